// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Discrete exterior calculus operators on a FaceGraph.

#ifndef CGAL_SURFACE_DESIGN_INTERNAL_CORE_DEC_H
#define CGAL_SURFACE_DESIGN_INTERNAL_CORE_DEC_H

#include <CGAL/assertions.h>
#include <CGAL/Surface_design/internal/Core/Mesh_indices.h>
#include <CGAL/Surface_design/internal/Solvers/sparse_types.h>

#include <Eigen/Sparse>

#include <cstddef>
#include <algorithm>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_design {
namespace internal {

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

/// Assembles a sparse matrix on the vertices with the sparsity of a vertex Laplacian: entry
/// (source(h), target(h)) = `off_diagonal(h)` for every halfedge h (so both (i, j) and (j, i)
/// for every edge, from its two halfedges; two edges joining the same vertices add up), and
/// entry (v, v) = `diagonal(v)`. Every Laplacian-like operator of the library is assembled here:
/// the weighted (e.g. cotangent) Laplacian, the Hermitian connection Laplacian of direction
/// fields, the barycentric systems.
///
/// `slot` optionally restricts and renumbers: row/column `slot[v]` for vertex `v`, and vertices
/// with `slot[v] == npos` are left out with every entry in their row or column. Empty: all
/// vertices in index order. Assembled column by column straight into compressed storage (no
/// triplets), row indices sorted; the pattern depends on the connectivity (and `slot`) only.
/// \tparam Scalar `double` or `std::complex<double>`
template <class Scalar, class Indices, class OffDiagonal, class Diagonal>
Eigen::SparseMatrix<Scalar> assemble_vertex_matrix(const Indices& idx, const OffDiagonal& off_diagonal,
                                                   const Diagonal& diagonal,
                                                   const std::vector<std::size_t>& slot = {})
{
  const auto& tm = idx.mesh();
  const std::size_t nv = idx.number_of_vertices();
  auto slot_of = [&slot](std::size_t v) { return slot.empty() ? v : slot[v]; };
  std::size_t size = 0;
  for(std::size_t v = 0; v < nv; ++v)
    size += slot_of(v) != npos;
  Eigen::SparseMatrix<Scalar> m(static_cast<Eigen::Index>(size), static_cast<Eigen::Index>(size));
  Eigen::VectorXi column_size = Eigen::VectorXi::Zero(static_cast<Eigen::Index>(size));
  for(std::size_t v = 0; v < nv; ++v)
    if(slot_of(v) != npos)
      column_size[Eigen::Index(slot_of(v))] = int(degree(idx.vertex(v), tm)) + 1;
  m.reserve(column_size);
  std::vector<std::pair<std::size_t, Scalar>> column;
  for(std::size_t v = 0; v < nv; ++v)
  {
    const std::size_t c = slot_of(v);
    if(c == npos)
      continue;
    column.clear();
    for(auto h : halfedges_around_target(idx.vertex(v), tm)) // entries (source(h), v)
    {
      const std::size_t r = slot_of(idx.source_index(h));
      if(r != npos)
        column.emplace_back(r, off_diagonal(idx.index(h)));
    }
    column.emplace_back(c, diagonal(v));
    std::sort(column.begin(), column.end(),
              [](const auto& a, const auto& b) { return a.first < b.first; });
    for(std::size_t k = 0; k < column.size(); ++k)
    {
      Scalar value = column[k].second;
      while(k + 1 < column.size() && column[k + 1].first == column[k].first) // two edges, same ends
        value += column[++k].second;
      m.insert(Eigen::Index(column[k].first), Eigen::Index(c)) = value;
    }
  }
  m.makeCompressed();
  return m;
}

/// The pattern of a matrix on `d` values per vertex (d = 1 or 2), and where each of its blocks
/// lies: row/column `v d + a` is value `a` of vertex `v`, and every block of
/// `assemble_vertex_matrix()`'s pattern is a full d x d block. Built once, it fills matrices of
/// that pattern with other values without sorting anything again (a system whose weights change):
/// written straight into compressed storage, the rows of every column sorted, the pattern depending
/// on the connectivity and d only, whatever the values (zeros stay).
class Vertex_block_pattern
{
public:
  Vertex_block_pattern() = default;

  template <class Indices>
  Vertex_block_pattern(const Indices& idx, int d) : m_d(std::size_t(d))
  {
    CGAL_precondition(d == 1 || d == 2);
    const auto& tm = idx.mesh();
    const std::size_t nv = idx.number_of_vertices(), ud = m_d;
    // per vertex v, (row vertex, halfedge into v) sorted by row vertex, with (v, npos) for block
    // (v, v); `blocks` counts the distinct row vertices (prefix sums)
    std::vector<std::pair<std::size_t, std::size_t>> incoming;
    incoming.reserve(idx.number_of_halfedges() + nv);
    std::vector<std::size_t> begin(nv + 1, 0), blocks(nv + 1, 0);
    for(std::size_t v = 0; v < nv; ++v)
    {
      const std::size_t start = incoming.size();
      incoming.emplace_back(v, npos);
      for(auto h : halfedges_around_target(idx.vertex(v), tm))
        incoming.emplace_back(idx.source_index(h), idx.index(h));
      std::sort(incoming.begin() + std::ptrdiff_t(start), incoming.end());
      std::size_t distinct = 0;
      for(std::size_t k = start; k < incoming.size(); ++k)
        distinct += k == start || incoming[k].first != incoming[k - 1].first;
      begin[v + 1] = incoming.size();
      blocks[v + 1] = blocks[v] + distinct;
    }
    const std::size_t n = nv * ud;
    m_pattern = Sparse_matrix(Eigen::Index(n), Eigen::Index(n));
    m_pattern.resizeNonZeros(Eigen::Index(blocks[nv] * ud * ud));
    int* outer = m_pattern.outerIndexPtr();
    int* inner = m_pattern.innerIndexPtr();
    std::fill_n(m_pattern.valuePtr(), blocks[nv] * ud * ud, 0.); // (nonZeros() reads outer: not yet)
    for(std::size_t v = 0; v < nv; ++v)
      for(std::size_t b = 0; b < ud; ++b) // column v d + b holds d rows per row vertex
        outer[v * ud + b] = int((blocks[v] * ud + b * (blocks[v + 1] - blocks[v])) * ud);
    outer[n] = int(blocks[nv] * ud * ud);
    m_halfedge.assign(idx.number_of_halfedges(), {0, 0});
    m_vertex.assign(nv, 0);
    for(std::size_t v = 0; v < nv; ++v)
    {
      std::size_t slot = 0; // the row vertex's position in the column
      for(std::size_t k = begin[v]; k < begin[v + 1]; ++k)
      {
        const auto [u, h] = incoming[k];
        slot += k > begin[v] && u != incoming[k - 1].first; // the same slot for a second edge (u, v)
        const std::size_t position = std::size_t(outer[v * ud]) + slot * ud;
        (h == npos ? m_vertex[v] : m_halfedge[h].first) = position;
        if(h != npos)
          m_halfedge[h].second = v;
        for(std::size_t b = 0; b < ud; ++b)
          for(std::size_t a = 0; a < ud; ++a)
            inner[std::size_t(outer[v * ud + b]) + slot * ud + a] = int(u * ud + a);
      }
    }
  }

  bool empty() const { return m_d == 0; }

  /// The matrix of this pattern with block (source(h), target(h)) = the top-left d x d part of
  /// `off_diagonal(h)` for every halfedge index h (two edges joining the same vertices add up) and
  /// block (v, v) = that of `diagonal(v)`, both returning a 2 x 2 matrix. Zeros stay in the pattern.
  template <class OffDiagonal, class Diagonal>
  Sparse_matrix fill(const OffDiagonal& off_diagonal, const Diagonal& diagonal) const
  {
    Sparse_matrix m = m_pattern;
    double* value = m.valuePtr();
    const int* outer = m.outerIndexPtr();
    auto add = [&](std::size_t position, std::size_t column_vertex, const Eigen::Matrix2d& block) {
      // column v d + 1 (d = 2) holds the same rows as column v d, `stride` entries further
      const std::size_t first = column_vertex * m_d;
      const std::size_t stride = m_d == 1 ? 0 : std::size_t(outer[first + 1] - outer[first]);
      for(std::size_t b = 0; b < m_d; ++b)
        for(std::size_t a = 0; a < m_d; ++a)
          value[position + b * stride + a] += block(Eigen::Index(a), Eigen::Index(b));
    };
    for(std::size_t v = 0; v < m_vertex.size(); ++v)
      add(m_vertex[v], v, Eigen::Matrix2d(diagonal(v)));
    for(std::size_t h = 0; h < m_halfedge.size(); ++h)
      add(m_halfedge[h].first, m_halfedge[h].second, Eigen::Matrix2d(off_diagonal(h)));
    return m;
  }

private:
  std::size_t m_d = 0;
  Sparse_matrix m_pattern;                                // the values all 0
  std::vector<std::pair<std::size_t, std::size_t>> m_halfedge; // per halfedge: (first entry of its block, column vertex)
  std::vector<std::size_t> m_vertex;                       // per vertex: first entry of its diagonal block
};

/// The weighted graph Laplacian L = d0^T W d0 (|V| x |V|, symmetric), with W = diag(edge_weight).
/// With cotangent weights it is the cotangent Laplacian, positive semi-definite on every triangle
/// mesh (it is the P1 finite-element stiffness matrix) with the constants per connected component
/// as kernel. Sign convention: L_ii = sum_j w_ij >= 0 (for positive weights), L_ij = -w_ij.
template <class Indices>
Sparse_matrix weighted_laplacian(const Indices& idx, const std::vector<double>& edge_weight)
{
  std::vector<double> diagonal(idx.number_of_vertices(), 0.);
  for(std::size_t e = 0; e < edge_weight.size(); ++e)
  {
    const auto ij = idx.edge_vertices(e);
    diagonal[ij.first] += edge_weight[e];
    diagonal[ij.second] += edge_weight[e];
  }
  return assemble_vertex_matrix<double>(
    idx, [&](std::size_t h) { return -edge_weight[idx.edge_index(idx.halfedge(h))]; },
    [&](std::size_t v) { return diagonal[v]; });
}

} // namespace internal
} // namespace Surface_design
} // namespace CGAL

#endif // CGAL_SURFACE_DESIGN_INTERNAL_CORE_DEC_H
