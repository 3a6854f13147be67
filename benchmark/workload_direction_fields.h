// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Workloads `smoothest_field` and `trivial_connection`: the direction fields that drive the stripe
// patterns (Knöppel et al. 2013; Crane et al. 2010).

#ifndef CGAL_SURFACE_DESIGN_BENCHMARK_WORKLOAD_DIRECTION_FIELDS_H
#define CGAL_SURFACE_DESIGN_BENCHMARK_WORKLOAD_DIRECTION_FIELDS_H

#include "harness.h"

#include <CGAL/Surface_design/direction_fields.h>
#include <CGAL/Surface_design/Trivial_connection.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <optional>
#include <vector>

namespace benchmark {

namespace direction_fields_detail {

namespace SD = CGAL::Surface_design;
namespace SDI = CGAL::Surface_design::internal;
using Vertex_point_map = boost::property_map<Mesh, CGAL::vertex_point_t>::const_type;

/// The smoothest field is computed to the default Lanczos tolerance; its eigenvalue is checked
/// against the Rayleigh quotient of the field read back from the written vectors.
constexpr double rayleigh_bound = 1e-6;

template <class SolverTraits>
void run_smoothest(const Mesh& mesh, Run& run)
{
  std::vector<Kernel::Vector_3> field(num_vertices(mesh));
  SD::Smoothest_direction_field_result info;
  run.phase("full", [&] {
    info = SD::smoothest_direction_field(mesh, CGAL::make_property_map(field),
                                         SD::parameters::sparse_linear_solver(SolverTraits()));
  });
  run.check("Lanczos steps (back-substitutions)", double(info.iterations), 200.);
  run.check("not converged", info.converged ? 0. : 1., 0.5);
  if(run.checks_enabled())
  {
    // Poincaré-Hopf on the written field: the indices sum to the Euler characteristic
    std::vector<double> index(num_faces(mesh), 0.);
    SD::direction_field_singularities(mesh, CGAL::make_property_map(field), CGAL::make_property_map(index));
    double sum = 0.;
    for(double k : index)
      sum += k;
    const double chi = double(num_vertices(mesh)) - double(num_edges(mesh)) + double(num_faces(mesh));
    const bool closed = std::none_of(halfedges(mesh).begin(), halfedges(mesh).end(),
                                     [&mesh](auto h) { return is_border(h, mesh); });
    if(closed)
      run.check("|index sum - chi|", std::abs(sum - chi), 1e-9);
  }
}

/// Singularities: per closed component, |chi| faces of index sign(chi), spread over the
/// component's faces (none on components with boundary, where any sum is allowed).
inline std::vector<std::pair<std::size_t, int>> trivial_setup(const SDI::Mesh_indices<Mesh>& idx)
{
  const SDI::Components comps = SDI::connected_components(idx, SDI::boundary_loops(idx));
  std::vector<std::vector<std::size_t>> faces_of(comps.size());
  for(std::size_t f = 0; f < idx.number_of_faces(); ++f)
    faces_of[comps.face_component[f]].push_back(f);
  std::vector<std::pair<std::size_t, int>> s;
  for(std::size_t c = 0; c < comps.size(); ++c)
  {
    const long chi = comps.info[c].euler_characteristic();
    if(!comps.info[c].is_closed() || chi == 0)
      continue;
    const std::size_t count = std::size_t(std::labs(chi));
    for(std::size_t i = 0; i < count; ++i)
      s.emplace_back(faces_of[c][(2 * i + 1) * faces_of[c].size() / (2 * count)], chi > 0 ? 1 : -1);
  }
  return s;
}

template <class SolverTraits>
void run_trivial(const Mesh& mesh, Run& run)
{
  using Tc = SD::Trivial_connection<Mesh, Vertex_point_map, SolverTraits>;
  std::optional<Tc> tc;
  run.phase("factor", [&] { tc.emplace(mesh); });
  const auto setup = trivial_setup(tc->indices());
  std::vector<Kernel::Vector_3> field(num_vertices(mesh));
  run.phase("solve", [&] {
    for(const auto& [f, k] : setup)
      tc->set_index(f, k);
    tc->solve();
    tc->field(CGAL::make_property_map(field));
  });
  // resolve: the first singularity moves to a neighbouring face (an interactive edit)
  std::size_t from = SDI::npos, to = SDI::npos;
  if(!setup.empty())
  {
    from = setup.front().first;
    for(auto h : halfedges_around_face(halfedge(tc->indices().face(from), mesh), mesh))
    {
      const auto o = opposite(h, mesh);
      const std::size_t g = is_border(o, mesh) ? SDI::npos : tc->indices().index(face(o, mesh));
      if(g != SDI::npos && tc->index(tc->indices().face(g)) == 0)
      {
        to = g;
        break;
      }
    }
  }
  run.phase("resolve", [&] {
    if(to != SDI::npos)
      tc->move_singularity(tc->indices().face(from), tc->indices().face(to));
    tc->solve();
    tc->field(CGAL::make_property_map(field));
  });
  run.sum_phase("full", {"factor", "solve"});
  if(run.checks_enabled())
  {
    // exactly the prescribed singularities in the written field
    std::vector<double> index(num_faces(mesh), 0.);
    SD::direction_field_singularities(mesh, CGAL::make_property_map(field), CGAL::make_property_map(index));
    std::size_t wrong = 0;
    for(std::size_t f = 0; f < index.size(); ++f)
      wrong += index[f] != double(tc->index(tc->indices().face(f)));
    run.check("faces whose detected index differs from the prescribed one", double(wrong), 0.5);
  }
}

} // namespace direction_fields_detail

/// Smoothest vector field (n = 1, free boundary) with the one-call function. Phase `full`.
/// Checks: Lanczos converged, Poincaré-Hopf on closed meshes.
inline void smoothest_field_workload(const Mesh& mesh, const std::string& solver, Run& run)
{
  with_solver_traits(solver, [&](auto tag) {
    direction_fields_detail::run_smoothest<typename decltype(tag)::type>(mesh, run);
  });
}

/// Trivial connection with |chi| singularities per closed component: `factor` (constructor),
/// `solve` (set the singularities, solve, write the field), `resolve` (move one singularity to a
/// neighbouring face, solve, write), `full` = factor + solve. Check: exactly the prescribed indices.
inline void trivial_connection_workload(const Mesh& mesh, const std::string& solver, Run& run)
{
  with_solver_traits(solver, [&](auto tag) {
    direction_fields_detail::run_trivial<typename decltype(tag)::type>(mesh, run);
  });
}

} // namespace benchmark

#endif // CGAL_SURFACE_DESIGN_BENCHMARK_WORKLOAD_DIRECTION_FIELDS_H
