// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Discrete exterior calculus operators on a FaceGraph.

#ifndef CGAL_SURFACE_DESIGN_INTERNAL_DEC_H
#define CGAL_SURFACE_DESIGN_INTERNAL_DEC_H

#include <CGAL/Surface_design/internal/Mesh_indices.h>

#include <Eigen/Sparse>

#include <cstddef>
#include <algorithm>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_design {
namespace internal {

using Sparse_matrix = Eigen::SparseMatrix<double>;
using Triplet = Eigen::Triplet<double>;

// Orientation conventions (see Mesh_indices): edge e runs from its endpoint of smaller vertex
// index to the larger one; face f is oriented by its halfedge cycle (next()), i.e.
// counter-clockwise seen from the side of its normal. Hence
//   (d0 u)_e = u_j - u_i            for e = (i -> j),
//   (d1 y)_f = sum_{h in f} s(h) y_{edge(h)},   s(h) = +1 if h runs along its edge, -1 otherwise,
// and d1 * d0 = 0 exactly (every term cancels in integer arithmetic). Both work on polygon faces.

/// Exterior derivative on 0-forms, |E| x |V|.
template <class Indices>
Sparse_matrix d0(const Indices& idx)
{
  std::vector<Triplet> t;
  t.reserve(2 * idx.number_of_edges());
  for(std::size_t e = 0; e < idx.number_of_edges(); ++e)
  {
    const auto ij = idx.edge_vertices(e);
    t.emplace_back(int(e), int(ij.first), -1.);
    t.emplace_back(int(e), int(ij.second), 1.);
  }
  Sparse_matrix m(int(idx.number_of_edges()), int(idx.number_of_vertices()));
  m.setFromTriplets(t.begin(), t.end());
  return m;
}

/// Exterior derivative on 1-forms, |F| x |E|.
template <class Indices>
Sparse_matrix d1(const Indices& idx)
{
  const auto& tm = idx.mesh();
  std::vector<Triplet> t;
  t.reserve(idx.number_of_halfedges());
  for(std::size_t f = 0; f < idx.number_of_faces(); ++f)
    for(auto h : halfedges_around_face(halfedge(idx.face(f), tm), tm))
      t.emplace_back(int(f), int(idx.edge_index(h)), double(idx.orientation_sign(h)));
  Sparse_matrix m(int(idx.number_of_faces()), int(idx.number_of_edges()));
  m.setFromTriplets(t.begin(), t.end());
  return m;
}

/// Diagonal sparse matrix from a vector (Hodge stars, lumped mass matrix).
inline Sparse_matrix diagonal_matrix(const std::vector<double>& d)
{
  Sparse_matrix m(int(d.size()), int(d.size()));
  m.reserve(Eigen::VectorXi::Constant(int(d.size()), 1));
  for(std::size_t i = 0; i < d.size(); ++i)
    m.insert(int(i), int(i)) = d[i];
  m.makeCompressed();
  return m;
}

/// The weighted graph Laplacian L = d0^T W d0 (|V| x |V|, symmetric), with W = diag(edge_weight).
/// With cotangent weights it is the cotangent Laplacian, positive semi-definite on every triangle
/// mesh (it is the P1 finite-element stiffness matrix) with the constants per connected component
/// as kernel. Sign convention: L_ii = sum_j w_ij >= 0 (for positive weights), L_ij = -w_ij.
/// Assembled row by row straight into compressed storage (no triplets, no d0): row i holds the
/// diagonal and one entry per edge at i, column indices sorted.
template <class Indices>
Sparse_matrix weighted_laplacian(const Indices& idx, const std::vector<double>& edge_weight)
{
  const auto& tm = idx.mesh();
  const std::size_t nv = idx.number_of_vertices();
  Sparse_matrix m(static_cast<Eigen::Index>(nv), static_cast<Eigen::Index>(nv));
  Eigen::VectorXi row_size = Eigen::VectorXi::Zero(static_cast<Eigen::Index>(nv));
  for(std::size_t v = 0; v < nv; ++v)
    row_size[Eigen::Index(v)] = int(degree(idx.vertex(v), tm)) + 1;
  m.reserve(row_size);
  // the matrix is symmetric: fill column v (= row v) with its neighbours, sorted
  std::vector<std::pair<int, double>> column;
  for(std::size_t v = 0; v < nv; ++v)
  {
    column.clear();
    double diagonal = 0.;
    for(auto h : halfedges_around_source(idx.vertex(v), tm))
    {
      const double w = edge_weight[idx.edge_index(h)];
      column.emplace_back(int(idx.target_index(h)), -w);
      diagonal += w;
    }
    column.emplace_back(int(v), diagonal);
    std::sort(column.begin(), column.end(),
              [](const std::pair<int, double>& a, const std::pair<int, double>& b) { return a.first < b.first; });
    for(std::size_t k = 0; k < column.size(); ++k)
    {
      double value = column[k].second;
      while(k + 1 < column.size() && column[k + 1].first == column[k].first) // two edges, same ends
        value += column[++k].second;
      m.insert(Eigen::Index(column[k].first), Eigen::Index(v)) = value;
    }
  }
  m.makeCompressed();
  return m;
}

} // namespace internal
} // namespace Surface_design
} // namespace CGAL

#endif // CGAL_SURFACE_DESIGN_INTERNAL_DEC_H
