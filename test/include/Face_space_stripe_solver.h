// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The paper's own face-space formulation of the field-aligned parameterization (Noma & Kawahara,
// sec. 5.2), done correctly. A reference for tests and benchmarks, not the library's solver.

#ifndef CGAL_SURFACE_DESIGN_TEST_FACE_SPACE_STRIPE_SOLVER_H
#define CGAL_SURFACE_DESIGN_TEST_FACE_SPACE_STRIPE_SOLVER_H

#include <CGAL/Surface_design/exceptions.h>
#include <CGAL/Surface_design/internal/Core/dec.h>
#include <CGAL/Surface_design/internal/Solvers/Factored_system.h>
#include <CGAL/Surface_design/internal/Core/topology.h>

#include <cmath>
#include <string>
#include <vector>

namespace CGAL {
namespace Surface_design {
namespace internal {

/// Minimizes x^T W x subject to A x = c - A omega, x = y - omega, where the rows of A are
/// - the face rows of d1, except one face per connected component (the rows of each component
///   sum to its boundary-loop rows, so one is dependent; the paper keeps them all and its
///   A W^-1 A^T is singular),
/// - one row per homology generator loop and one per boundary loop (surface orientation),
/// and c = 2 pi (k; h; W). The minimizer is x = W^-1 A^T (A W^-1 A^T)^-1 (c - A omega) — the
/// paper's sec. 5.2 writes (A^T A)^-1 A^T, which is singular for a wide A. Requires every
/// cotangent weight to be positive (W^-1, and A W^-1 A^T positive definite): on meshes with
/// non-Delaunay edges it throws, which is why the library solves in vertex space instead.
template <class SolverTraits>
class Face_space_stripe_solver
{
public:
  /// `loops`: halfedge-index loops in the order of the windings passed to solve() (generator
  /// loops first, then boundary loops, as Field_aligned_parameterizer numbers them).
  template <class Indices>
  Face_space_stripe_solver(const Indices& idx, const Topology& topo, const std::vector<double>& weight,
                           const std::vector<std::vector<std::size_t>>& loops)
    : m_system(SolverTraits(), "face-space system A W^-1 A^T")
  {
    for(std::size_t e = 0; e < weight.size(); ++e)
      if(!(weight[e] > 0.))
        throw Linear_solver_failure("the face-space formulation needs positive cotangent weights, "
                                    "but edge " + std::to_string(e) + " has weight " +
                                    std::to_string(weight[e]) + " (a non-Delaunay edge)");
    const auto& tm = idx.mesh();
    std::vector<bool> dropped(idx.number_of_faces(), false);
    for(const auto& c : topo.components.info)
      dropped[c.root_face] = true;
    std::vector<Triplet> t;
    int row = 0;
    for(std::size_t f = 0; f < idx.number_of_faces(); ++f)
    {
      if(dropped[f])
        continue;
      m_face_of_row.push_back(f);
      for(auto h : halfedges_around_face(halfedge(idx.face(f), tm), tm))
        t.emplace_back(row, int(idx.edge_index(h)), double(idx.orientation_sign(h)));
      ++row;
    }
    m_first_loop_row = row;
    for(const auto& loop : loops)
    {
      for(std::size_t h : loop)
      {
        const auto hd = idx.halfedge(h);
        t.emplace_back(row, int(idx.edge_index(hd)), double(idx.orientation_sign(hd)));
      }
      ++row;
    }
    m_A.resize(row, int(idx.number_of_edges()));
    m_A.setFromTriplets(t.begin(), t.end());
    m_inverse_weight.resize(Eigen::Index(weight.size()));
    for(std::size_t e = 0; e < weight.size(); ++e)
      m_inverse_weight[Eigen::Index(e)] = 1. / weight[e];
    Sparse_matrix AWinv = m_A * m_inverse_weight.asDiagonal();
    m_system.factor(Sparse_matrix(AWinv * m_A.transpose()));
  }

  /// dalpha per edge for the given target form, face indices and loop windings.
  std::vector<double> solve(const std::vector<double>& omega, const std::vector<int>& k,
                            const std::vector<int>& windings)
  {
    const Eigen::Map<const Eigen::VectorXd> om(omega.data(), Eigen::Index(omega.size()));
    Eigen::VectorXd c(m_A.rows());
    for(std::size_t r = 0; r < m_face_of_row.size(); ++r)
      c[Eigen::Index(r)] = two_pi * k[m_face_of_row[r]];
    for(std::size_t l = 0; l < windings.size(); ++l)
      c[Eigen::Index(m_first_loop_row + int(l))] = two_pi * windings[l];
    const Eigen::VectorXd lambda = m_system.solve(c - m_A * om);
    const Eigen::VectorXd x = m_inverse_weight.asDiagonal() * (m_A.transpose() * lambda);
    std::vector<double> y(omega.size());
    for(std::size_t e = 0; e < y.size(); ++e)
      y[e] = x[Eigen::Index(e)] + omega[e];
    return y;
  }

  Eigen::Index number_of_rows() const { return m_A.rows(); }

private:
  Sparse_matrix m_A;
  Eigen::VectorXd m_inverse_weight;
  std::vector<std::size_t> m_face_of_row;
  int m_first_loop_row = 0;
  Factored_system<SolverTraits> m_system;
};

} // namespace internal
} // namespace Surface_design
} // namespace CGAL

#endif // CGAL_SURFACE_DESIGN_TEST_FACE_SPACE_STRIPE_SOLVER_H
