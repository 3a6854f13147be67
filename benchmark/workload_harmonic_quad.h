// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Workloads of the harmonic-function quad remeshing, as the CLI `quad_remesh` runs it (default
// constraints, about 3000 faces in the net). Phases as in Nagano & Imai's Table 2: harmonic
// (validation, Laplacian, factorization, solve), re-solve (spectacles), curves (isolines and
// gradient lines), meshing (the faces of the net, quads only, feature snapping, the output mesh); full = harmonic +
// re-solve + curves + meshing. Checks (untimed): the quality of the output against the input.

#ifndef CGAL_SURFACE_DESIGN_BENCHMARK_WORKLOAD_HARMONIC_QUAD_H
#define CGAL_SURFACE_DESIGN_BENCHMARK_WORKLOAD_HARMONIC_QUAD_H

#include "harness.h"

#include <CGAL/Surface_design/Harmonic_quad_remesher.h>
#include <CGAL/Surface_design/quad_mesh_quality.h>

#include <optional>
#include <string>
#include <vector>

namespace benchmark {

template <class SolverTraits>
void run_harmonic_quad(const Mesh& mesh, Run& run, CGAL::Surface_design::Harmonic_weights weights, bool spectacles,
                       bool all_quads, double curvature_adaptation = 0.)
{
  namespace SD = CGAL::Surface_design;
  SolverTraits traits;
  std::optional<SD::Harmonic_quad_remesher<Mesh, Mesh::Property_map<Mesh::Vertex_index, Mesh::Point>, SolverTraits>>
    remesher;
  run.phase("harmonic", [&] {
    remesher.emplace(mesh, SD::parameters::harmonic_weights(weights, CGAL::parameters::sparse_linear_solver(traits)));
    remesher->harmonic_function();
  });
  Mesh out;
  const SD::Harmonic_quad_remeshing_result r =
    remesher->remesh(out, SD::parameters::spectacles(
                            spectacles, SD::parameters::all_quads(
                                          all_quads, SD::parameters::curvature_adaptation(curvature_adaptation))));
  run.record("re-solve", 1e3 * r.spectacles_seconds); // the seed's 再計算: spectacles, insertion, re-solve
  run.record("curves", 1e3 * r.curves_seconds);
  run.record("meshing", 1e3 * r.meshing_seconds);
  run.record("quads only", 1e3 * r.all_quads_seconds); // part of meshing
  run.record("snapping", 1e3 * r.snapping_seconds);    // part of meshing
  run.sum_phase("full", {"harmonic", "re-solve", "curves", "meshing"});
  if(run.checks_enabled())
  {
    const SD::Quad_mesh_quality q = SD::quad_mesh_quality(out, mesh);
    run.check("faces (thousands)", double(q.faces) / 1e3, curvature_adaptation > 0. ? 60. : 10.);
    run.check("non-quad fraction", 1. - q.quad_fraction, 0.15);
    run.check("non-quad area fraction", 1. - q.quad_area_fraction, 0.25);
    run.check("irregular vertices per face", double(q.irregular_vertices) / double(q.faces), 0.2);
    run.check("T-junctions per face", double(q.t_junctions) / double(q.faces), 0.2);
    run.check("quad corner |angle - 90| mean (deg)", q.angle_deviation_mean, 10.);
    run.check("quad corner |angle - 90| rms (deg)", q.angle_deviation_rms, 15.);
    run.check("edge length variation", q.edge_length_variation, 0.5);
    run.check("Hausdorff / diagonal", q.relative_hausdorff_distance, 0.015);
    run.check("invalid or other topology", q.valid && q.same_topology ? 0. : 1., 0.5);
    const SD::Harmonic_critical_points cp = remesher->critical_points();
    run.check("saddles (multiplicity)", double(cp.saddle_multiplicity()), 1e9);
    run.check("saddles with spectacles", double(r.spectacles), 1e9);
    std::vector<Mesh::Point> saddles;
    for(const auto& [v, multiplicity] : cp.saddles)
      saddles.push_back(mesh.point(Mesh::Vertex_index(Mesh::size_type(v))));
    run.check("non-quads within 2h of the saddles",
              double(SD::count_non_quads_near(out, saddles, 2. * r.target_edge_length)), 1e9);
    run.check("spurious extrema", double(cp.spurious_extrema), 0.5);
    run.check("odd faces of the net", double(r.odd_faces), 1e9);
    run.check("boundary detail vertices", double(r.boundary_detail_vertices), 1e9);
    run.check("snapped vertices", double(r.snapped_vertices), 1e9);
  }
}

inline void harmonic_quad_workload(const Mesh& mesh, const std::string& solver, Run& run)
{
  with_solver_traits(solver, [&](auto tag) {
    run_harmonic_quad<typename decltype(tag)::type>(mesh, run, CGAL::Surface_design::Harmonic_weights::cotangent, true,
                                                    true);
  });
}

inline void harmonic_quad_net_workload(const Mesh& mesh, const std::string& solver, Run& run)
{
  with_solver_traits(solver, [&](auto tag) {
    run_harmonic_quad<typename decltype(tag)::type>(mesh, run, CGAL::Surface_design::Harmonic_weights::cotangent, true,
                                                    false);
  });
}

inline void harmonic_quad_no_spectacles_workload(const Mesh& mesh, const std::string& solver, Run& run)
{
  with_solver_traits(solver, [&](auto tag) {
    run_harmonic_quad<typename decltype(tag)::type>(mesh, run, CGAL::Surface_design::Harmonic_weights::cotangent, false,
                                                    false);
  });
}

inline void harmonic_quad_curvature_workload(const Mesh& mesh, const std::string& solver, Run& run)
{
  with_solver_traits(solver, [&](auto tag) {
    run_harmonic_quad<typename decltype(tag)::type>(mesh, run, CGAL::Surface_design::Harmonic_weights::cotangent, true,
                                                    true, 1.);
  });
}

inline void harmonic_quad_delaunay_workload(const Mesh& mesh, const std::string& solver, Run& run)
{
  with_solver_traits(solver, [&](auto tag) {
    run_harmonic_quad<typename decltype(tag)::type>(mesh, run, CGAL::Surface_design::Harmonic_weights::intrinsic_delaunay,
                                                    true, true);
  });
}

} // namespace benchmark

#endif // CGAL_SURFACE_DESIGN_BENCHMARK_WORKLOAD_HARMONIC_QUAD_H
