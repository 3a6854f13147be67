// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Workload of cutting and flattening: `flatten` cuts the mesh into disks (developable cut at
// epsilon = 1e-3, joined to every boundary loop), then flattens them by Boundary First
// Flattening (u_B = 0), as the CLI `flatten` does. Phases: cut (the cut graph and the cut mesh),
// factor (validation, Laplacian, one factorization), flatten (three solves and the boundary
// curves), full = factor + flatten; checks: distortion and flips.

#ifndef CGAL_SURFACE_DESIGN_BENCHMARK_WORKLOAD_FLATTENING_H
#define CGAL_SURFACE_DESIGN_BENCHMARK_WORKLOAD_FLATTENING_H

#include "harness.h"

#include <CGAL/Surface_design/Boundary_first_flattener.h>
#include <CGAL/Surface_design/developable_cutting.h>
#include <CGAL/Surface_design/flattening_distortion.h>

#include <optional>
#include <string>
#include <vector>

namespace benchmark {

template <class SolverTraits>
void run_flatten(const Mesh& mesh, Run& run)
{
  SolverTraits traits;
  namespace SD = CGAL::Surface_design;
  Mesh pieces;
  run.phase("cut", [&] {
    std::vector<Mesh::Edge_index> cut;
    SD::compute_developable_cut(mesh, std::back_inserter(cut), SD::parameters::cut_tolerance(1e-3));
    SD::cut_mesh_along_edges(mesh, cut, pieces);
  });
  auto uv = pieces.add_property_map<Mesh::Vertex_index, CGAL::Simple_cartesian<double>::Point_2>("v:uv").first;
  std::optional<SD::Boundary_first_flattener<Mesh, Mesh::Property_map<Mesh::Vertex_index, Mesh::Point>, SolverTraits>> bff;
  run.phase("factor", [&] { bff.emplace(pieces, CGAL::parameters::sparse_linear_solver(traits)); });
  run.phase("flatten", [&] { bff->flatten(uv); });
  run.sum_phase("full", {"factor", "flatten"});
  if(run.checks_enabled())
  {
    const SD::Flattening_distortion d = SD::flattening_distortion(pieces, uv);
    run.check("mean |log area scale|", d.area_log_mean, 1.);
    run.check("flipped faces", double(d.flipped_faces), 0.5);
    run.check("pieces", double(d.pieces), 1e9);
  }
}

inline void flatten_workload(const Mesh& mesh, const std::string& solver, Run& run)
{
  with_solver_traits(solver, [&](auto tag) { run_flatten<typename decltype(tag)::type>(mesh, run); });
}

} // namespace benchmark

#endif // CGAL_SURFACE_DESIGN_BENCHMARK_WORKLOAD_FLATTENING_H
