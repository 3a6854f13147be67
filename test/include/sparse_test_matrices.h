// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Sparse test matrices shared by the tests of the orderings and factorizations: graph Laplacians
// with a dominant diagonal, triangulated grids, screened cotangent Laplacians of meshes, a
// Hermitian magnetic Laplacian, deterministic right-hand sides.

#ifndef CGAL_SURFACE_DESIGN_TEST_SPARSE_TEST_MATRICES_H
#define CGAL_SURFACE_DESIGN_TEST_SPARSE_TEST_MATRICES_H

#include <CGAL/Surface_design/internal/Core/dec.h>
#include <CGAL/Surface_design/internal/Solvers/Hermitian_system.h>
#include <CGAL/Surface_design/internal/Core/geometry.h>
#include <CGAL/Surface_design/internal/Core/Mesh_indices.h>

#include <Eigen/SparseCore>

#include <catch2/catch.hpp>

#include <cmath>
#include <complex>
#include <utility>
#include <vector>

namespace test {

using Complex_matrix = Eigen::SparseMatrix<std::complex<double>>;

/// The symmetric pattern of a graph given by its edges, with a dominant diagonal (SPD).
inline Eigen::SparseMatrix<double> graph_matrix(int n, const std::vector<std::pair<int, int>>& edges)
{
  std::vector<Eigen::Triplet<double>> t;
  std::vector<double> degree(std::size_t(n), 0.);
  for(const auto& [i, j] : edges)
  {
    t.emplace_back(i, j, -1.);
    t.emplace_back(j, i, -1.);
    degree[std::size_t(i)] += 1.;
    degree[std::size_t(j)] += 1.;
  }
  for(int i = 0; i < n; ++i)
    t.emplace_back(i, i, degree[std::size_t(i)] + 1.);
  Eigen::SparseMatrix<double> a(n, n);
  a.setFromTriplets(t.begin(), t.end());
  return a;
}

/// A k x k grid of squares, each split into two triangles: the graph of a planar triangle mesh.
inline Eigen::SparseMatrix<double> triangulated_grid(int k)
{
  std::vector<std::pair<int, int>> edges;
  auto id = [k](int i, int j) { return i * k + j; };
  for(int i = 0; i < k; ++i)
    for(int j = 0; j < k; ++j)
    {
      if(j + 1 < k) edges.push_back({id(i, j), id(i, j + 1)});
      if(i + 1 < k) edges.push_back({id(i, j), id(i + 1, j)});
      if(i + 1 < k && j + 1 < k) edges.push_back({id(i, j), id(i + 1, j + 1)});
    }
  return graph_matrix(k * k, edges);
}

/// The cotangent Laplacian of a mesh plus `screening` times its lumped mass matrix (SPD).
template <class Mesh>
Eigen::SparseMatrix<double> screened_laplacian(const Mesh& mesh, double screening = 1e-2)
{
  namespace SDI = CGAL::Surface_design::internal;
  const auto vpm = get(CGAL::vertex_point, mesh);
  SDI::Mesh_indices<Mesh> idx(mesh);
  const SDI::Sparse_matrix L = SDI::weighted_laplacian(idx, SDI::cotangent_weights(idx, vpm));
  return L + screening * SDI::diagonal_matrix(SDI::vertex_areas(idx, SDI::face_areas(idx, vpm)));
}

/// A Hermitian positive definite matrix on the graph of `a`: a magnetic graph Laplacian
/// (off-diagonal -e^{+-0.3 i}) plus the identity, diagonally dominant.
inline Complex_matrix magnetic_laplacian(const Eigen::SparseMatrix<double>& a)
{
  std::vector<Eigen::Triplet<std::complex<double>>> t;
  std::vector<double> degree(std::size_t(a.rows()), 0.);
  for(int k = 0; k < a.outerSize(); ++k)
    for(Eigen::SparseMatrix<double>::InnerIterator it(a, k); it; ++it)
      if(it.row() != it.col())
      {
        t.emplace_back(it.row(), it.col(), -std::polar(1., it.row() < it.col() ? 0.3 : -0.3));
        degree[std::size_t(it.row())] += 1.;
      }
  for(Eigen::Index i = 0; i < a.rows(); ++i)
    t.emplace_back(i, i, degree[std::size_t(i)] + 1.);
  Complex_matrix h(a.rows(), a.cols());
  h.setFromTriplets(t.begin(), t.end());
  return h;
}

/// A fixed right-hand side with entries spread over [-1, 1].
inline Eigen::VectorXd test_vector(Eigen::Index n, unsigned seed)
{
  Eigen::VectorXd b(n);
  for(Eigen::Index i = 0; i < n; ++i)
    b[i] = std::sin(0.7 * double(i) + 1.3 * double(seed));
  return b;
}

/// A fixed complex right-hand side.
inline Eigen::VectorXcd complex_test_vector(Eigen::Index n, unsigned seed)
{
  const Eigen::VectorXd re = test_vector(n, seed), im = test_vector(n, seed + 1);
  Eigen::VectorXcd b(n);
  for(Eigen::Index i = 0; i < n; ++i)
    b[i] = {re[i], im[i]};
  return b;
}

/// Requires the library's Hermitian system with `SolverTraits` to take the complex path and to
/// solve `a y = b` (vectors interleaved as (Re, Im)) as the reference solution `x`, to 1e-10.
template <class SolverTraits>
void require_hermitian_system_solution(const Complex_matrix& a, const Eigen::VectorXcd& b, const Eigen::VectorXcd& x,
                                       SolverTraits traits = SolverTraits())
{
  namespace SDI = CGAL::Surface_design::internal;
  static_assert(SDI::Hermitian_system<SolverTraits>::uses_complex_arithmetic());
  SDI::Hermitian_system<SolverTraits> system(std::move(traits), "Hermitian test system");
  system.factor(Complex_matrix(a));
  Eigen::VectorXd interleaved(2 * b.size()), y;
  for(Eigen::Index i = 0; i < b.size(); ++i)
  {
    interleaved[2 * i] = b[i].real();
    interleaved[2 * i + 1] = b[i].imag();
  }
  system.solve(interleaved, y);
  for(Eigen::Index i = 0; i < b.size(); ++i)
    REQUIRE(std::abs(std::complex<double>(y[2 * i], y[2 * i + 1]) - x[i]) <= 1e-10 * x.norm());
}

} // namespace test

#endif // CGAL_SURFACE_DESIGN_TEST_SPARSE_TEST_MATRICES_H
