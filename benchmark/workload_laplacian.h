// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Workload `laplacian`: the linear-algebra core shared by most algorithms of the library. Build the
// cotangent Laplacian, factor it once, solve once.

#ifndef CGAL_SURFACE_DESIGN_BENCHMARK_WORKLOAD_LAPLACIAN_H
#define CGAL_SURFACE_DESIGN_BENCHMARK_WORKLOAD_LAPLACIAN_H

#include "harness.h"

#include <CGAL/Surface_design/internal/Solvers/Factored_system.h>
#include <CGAL/Surface_design/internal/Core/Mesh_indices.h>
#include <CGAL/Surface_design/internal/Core/dec.h>
#include <CGAL/Surface_design/internal/Core/geometry.h>
#include <CGAL/Surface_design/internal/Core/topology.h>

#include <Eigen/Core>
#include <Eigen/Sparse>

#include <cmath>
#include <cstddef>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace benchmark {

namespace laplacian_detail {

namespace SDI = CGAL::Surface_design::internal;

/// The system is A = L + eps M with eps = regularization * trace(L) / trace(M): positive definite
/// (L alone is semi-definite, its kernel the constants on each component), and for a right-hand
/// side of zero mean its solution differs from L's by a relative
/// ~ regularization * mean(L_ii) / lambda_2(L): the cost measured is that of the Laplacian solve.
constexpr double regularization = 1e-8;

/// A backward-stable factorization of A gives a relative residual near machine precision times a
/// modest factor; 1e-8 leaves room for the condition of the largest meshes.
constexpr double residual_bound = 1e-8;

/// A fixed pseudo-random right-hand side with zero mean on every connected component, so that it
/// is orthogonal to the kernel of L and the solution stays of the size of the data.
inline Eigen::VectorXd right_hand_side(const SDI::Mesh_indices<Mesh>& idx)
{
  const SDI::Components components = SDI::connected_components(idx, SDI::boundary_loops(idx));
  const std::size_t n = idx.number_of_vertices();
  Eigen::VectorXd b = Eigen::VectorXd::Zero(Eigen::Index(n));
  std::vector<double> sum(components.size(), 0.);
  for(std::size_t v = 0; v < n; ++v)
  {
    b[Eigen::Index(v)] = std::sin(0.7 * double(v) + 0.3);
    sum[components.vertex_component[v]] += b[Eigen::Index(v)];
  }
  for(std::size_t v = 0; v < n; ++v)
  {
    const std::size_t k = components.vertex_component[v];
    b[Eigen::Index(v)] -= sum[k] / double(components.info[k].vertices);
  }
  return b;
}

/// A = L + eps M (see `regularization`).
inline SDI::Sparse_matrix regularized_laplacian(const Mesh& mesh, const SDI::Mesh_indices<Mesh>& idx)
{
  const auto vpm = get(CGAL::vertex_point, mesh);
  const std::vector<double> weights = SDI::cotangent_weights(idx, SDI::halfedge_cotangents(idx, vpm));
  const SDI::Sparse_matrix l = SDI::weighted_laplacian(idx, weights);
  const std::vector<double> mass = SDI::vertex_areas(idx, SDI::face_areas(idx, vpm));
  double total_mass = 0.;
  for(double m : mass)
    total_mass += m;
  const double eps = regularization * l.diagonal().sum() / total_mass;
  return l + eps * SDI::diagonal_matrix(mass);
}

template <class SolverTraits>
void run_laplacian(const Mesh& mesh, Run& run)
{
  std::optional<SDI::Mesh_indices<Mesh>> idx;
  SDI::Sparse_matrix a;
  run.phase("assemble", [&] {
    idx.emplace(mesh);
    a = regularized_laplacian(mesh, *idx);
  });

  // untimed: the right-hand side, and a copy of A for the residual (factor() takes A over)
  const Eigen::VectorXd b = right_hand_side(*idx);
  SDI::Sparse_matrix a_copy;
  if(run.checks_enabled())
    a_copy = a;

  SDI::Factored_system<SolverTraits> factored(SolverTraits(), "regularized cotangent Laplacian");
  run.phase("factor", [&] { factored.factor(std::move(a)); });
  Eigen::VectorXd x;
  run.phase("solve", [&] { factored.solve(b, x); });

  if(run.checks_enabled())
    run.check("relative residual |Ax-b|/|b|", (a_copy * x - b).norm() / b.norm(), residual_bound);
}

} // namespace laplacian_detail

/// Phases: `assemble` (index maps, cotangent weights, Laplacian L, barycentric mass matrix M,
/// A = L + eps M), `factor` (`Factored_system::factor`), `solve` (one right-hand side).
/// Check: the relative residual of the solve.
inline void laplacian_workload(const Mesh& mesh, const std::string& solver, Run& run)
{
  with_solver_traits(solver, [&](auto tag) {
    laplacian_detail::run_laplacian<typename decltype(tag)::type>(mesh, run);
  });
}

} // namespace benchmark

#endif // CGAL_SURFACE_DESIGN_BENCHMARK_WORKLOAD_LAPLACIAN_H
