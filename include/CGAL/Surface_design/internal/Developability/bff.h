// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Boundary First Flattening (Sawhney & Crane 2017) of a union of topological disks: the data of
// the cotangent Laplacian split into interior (I) and boundary (B) blocks, the curvatures, the
// boundary loops in counter-clockwise order, and the closure of a boundary curve from target
// lengths and turning angles.

#ifndef CGAL_SURFACE_DESIGN_INTERNAL_DEVELOPABILITY_BFF_H
#define CGAL_SURFACE_DESIGN_INTERNAL_DEVELOPABILITY_BFF_H

#include <CGAL/Surface_design/exceptions.h>
#include <CGAL/Surface_design/internal/Core/Mesh_indices.h>
#include <CGAL/Surface_design/internal/Core/angles.h>
#include <CGAL/Surface_design/internal/Core/geometry.h>
#include <CGAL/Surface_design/internal/Solvers/parallel.h>
#include <CGAL/Surface_design/internal/Core/topology.h>

#include <Eigen/Core>
#include <Eigen/Sparse>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_design {
namespace internal {

/// Throws `Invalid_mesh` (`not_a_disk`) naming the first connected component that is not a
/// topological disk (Euler characteristic 1 and exactly one boundary loop).
inline void require_disks(const Components& comps)
{
  for(std::size_t c = 0; c < comps.size(); ++c)
  {
    const Component_info& info = comps.info[c];
    if(info.euler_characteristic() == 1 && info.boundary_loops == 1)
      continue;
    std::ostringstream s;
    s << "connected component " << c << " (" << info.vertices << " vertices, " << info.faces
      << " faces, containing vertex " << info.root_vertex << ") is not a topological disk: "
      << info.boundary_loops << " boundary loop" << (info.boundary_loops == 1 ? "" : "s")
      << ", Euler characteristic " << info.euler_characteristic();
    if(info.boundary_loops == 0)
      s << " (a closed surface)";
    else if(info.euler_characteristic() <= 1 && info.boundary_loops >= 1)
      s << " (genus " << info.genus() << ")";
    s << "; cut it into disks first (e.g. CGAL::Surface_design::compute_developable_cut() and "
         "cut_mesh_along_edges())";
    throw Invalid_mesh(Mesh_defect::not_a_disk, info.root_vertex, s.str());
  }
}

/// What BFF needs of a mesh whose components are all disks.
struct Bff_system
{
  std::vector<std::size_t> interior_vertices, boundary_vertices; ///< vertex indices
  std::vector<std::size_t> block_index; ///< per vertex: position in interior_vertices or boundary_vertices
  std::vector<bool> is_boundary;        ///< per vertex
  /// Boundary loops as vertex indices in counter-clockwise order (the faces on the left, as the
  /// faces' own orientation), with the 3-D length of the edge from loop[m] to loop[m + 1].
  std::vector<std::vector<std::size_t>> loops;
  std::vector<std::vector<double>> loop_edge_length;
  Eigen::SparseMatrix<double> A_II, A_IB, A_BB; ///< blocks of the cotangent Laplacian (positive semi-definite)
  Eigen::VectorXd K_I; ///< angle defects 2 pi - sum of angles at interior vertices
  Eigen::VectorXd k_B; ///< turning angles pi - sum of angles at boundary vertices
};

namespace bff_detail {

// The cotangent Laplacian restricted to rows in one block and columns in another, in compressed
// column form, built column by column (in parallel: each column only writes its own entries) from
// the edges around every vertex: -w_e at the row of the other end of edge e when that end is in the
// row block, and on the diagonal (square blocks) the sum of the weights of all edges at the vertex.
// Edges with the same ends (possible in a halfedge mesh that is not a simplicial complex) are summed.
struct Laplacian_blocks
{
  const std::vector<std::size_t>& edge_offset; // CSR: the edges at vertex v are edge_at[edge_offset[v] ..]
  const std::vector<std::size_t>& edge_at;
  const std::vector<std::pair<std::size_t, std::size_t>>& ends;
  const std::vector<double>& weight;
  const std::vector<std::size_t>& block_index;
  const std::vector<bool>& is_boundary;

  // entries of column `v` in the rows of the block (boundary or not), sorted by row, merged
  void column(std::size_t v, bool rows_on_boundary, bool with_diagonal,
              std::vector<std::pair<Eigen::Index, double>>& out) const
  {
    out.clear();
    double diagonal = 0.;
    for(std::size_t k = edge_offset[v]; k < edge_offset[v + 1]; ++k)
    {
      const std::size_t e = edge_at[k];
      const std::size_t u = ends[e].first == v ? ends[e].second : ends[e].first;
      diagonal += weight[e];
      if(is_boundary[u] == rows_on_boundary)
        out.emplace_back(Eigen::Index(block_index[u]), -weight[e]);
    }
    if(with_diagonal)
      out.emplace_back(Eigen::Index(block_index[v]), diagonal);
    std::sort(out.begin(), out.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    std::size_t kept = 0;
    for(std::size_t k = 0; k < out.size(); ++k)
    {
      if(kept > 0 && out[kept - 1].first == out[k].first)
        out[kept - 1].second += out[k].second;
      else
        out[kept++] = out[k];
    }
    out.resize(kept);
  }

  // rows: the vertices of the row block; columns: the vertices of the column block. Each column is
  // gathered once, into room for all its edges and the diagonal, then the gaps are closed.
  Eigen::SparseMatrix<double> block(Eigen::Index rows, const std::vector<std::size_t>& column_vertices,
                                    bool rows_on_boundary, bool with_diagonal) const
  {
    const std::size_t n = column_vertices.size();
    Eigen::SparseMatrix<double> m(rows, Eigen::Index(n));
    if(n == 0) // no columns (a piece whose vertices all lie on its boundary): nothing to reserve,
      return m; // and Eigen's makeCompressed() of a reserved 0-column matrix reads past its end
    Eigen::VectorXi room = Eigen::VectorXi::Zero(Eigen::Index(n));
    for(std::size_t j = 0; j < n; ++j)
    {
      const std::size_t v = column_vertices[j];
      room[Eigen::Index(j)] = int(edge_offset[v + 1] - edge_offset[v]) + 1;
    }
    m.reserve(room); // uncompressed: column j has room[j] places from outerIndexPtr()[j]
    for_each_index(n, n > 20000, [&](std::size_t j) {
      thread_local std::vector<std::pair<Eigen::Index, double>> entries;
      column(column_vertices[j], rows_on_boundary, with_diagonal, entries);
      const int start = m.outerIndexPtr()[j];
      for(std::size_t k = 0; k < entries.size(); ++k)
      {
        m.innerIndexPtr()[start + int(k)] = int(entries[k].first);
        m.valuePtr()[start + int(k)] = entries[k].second;
      }
      m.innerNonZeroPtr()[j] = int(entries.size());
    });
    m.makeCompressed();
    return m;
  }
};

} // namespace bff_detail

/// Everything BFF needs of `idx`'s mesh (`loops`: its boundary loops), in O(|V| + |F|): the
/// per-face work (corner angles and cotangents) and the assembly of the blocks run in parallel
/// with TBB on large meshes.
template <class Indices, class VertexPointMap>
Bff_system bff_system(const Indices& idx, const VertexPointMap& vpm, const Boundary_loops& loops)
{
  const auto& tm = idx.mesh();
  const std::size_t nv = idx.number_of_vertices(), nf = idx.number_of_faces(), ne = idx.number_of_edges();
  const bool parallel = nf > 20000;
  Bff_system s;
  s.is_boundary.assign(nv, false);
  for(const auto& loop : loops.loops)
    for(std::size_t h : loop)
      s.is_boundary[idx.target_index(idx.halfedge(h))] = true;
  s.block_index.assign(nv, npos);
  for(std::size_t v = 0; v < nv; ++v)
  {
    std::vector<std::size_t>& block = s.is_boundary[v] ? s.boundary_vertices : s.interior_vertices;
    s.block_index[v] = block.size();
    block.push_back(v);
  }

  // loops: the border halfedges run clockwise around the faces; reverse them
  for(const auto& loop : loops.loops)
  {
    std::vector<std::size_t> vertices;
    std::vector<double> lengths;
    for(auto it = loop.rbegin(); it != loop.rend(); ++it)
    {
      const auto h = idx.halfedge(*it); // border halfedge; its opposite runs target -> source
      vertices.push_back(idx.target_index(h));
      lengths.push_back((position(vpm, target(h, tm)) - position(vpm, source(h, tm))).norm());
    }
    s.loops.push_back(std::move(vertices));
    s.loop_edge_length.push_back(std::move(lengths));
  }

  // the corners of every face as plain indices (the mesh's maps are read here only, sequentially)
  const std::vector<Eigen::Vector3d> point = vertex_positions(idx, vpm);
  std::vector<std::size_t> corner_vertex(3 * nf), corner_edge(3 * nf); // edge k: corners k -> k + 1
  for(std::size_t f = 0; f < nf; ++f)
  {
    auto h = halfedge(idx.face(f), tm);
    for(std::size_t k = 0; k < 3; ++k, h = next(h, tm))
    {
      corner_vertex[3 * f + k] = idx.source_index(h);
      corner_edge[3 * f + k] = idx.edge_index(h);
    }
  }
  // per corner: its angle (atan2 of |cross| and dot) and cotangent (dot / |cross|); one cross
  // product per face, twice its area
  std::vector<double> corner_angle(3 * nf), corner_cot(3 * nf);
  for_each_index(nf, parallel, [&](std::size_t f) {
    const Eigen::Vector3d* p[3] = {&point[corner_vertex[3 * f]], &point[corner_vertex[3 * f + 1]],
                                   &point[corner_vertex[3 * f + 2]]};
    const double twice_area = (*p[1] - *p[0]).cross(*p[2] - *p[0]).norm();
    for(std::size_t k = 0; k < 3; ++k)
    {
      const double dot = (*p[(k + 1) % 3] - *p[k]).dot(*p[(k + 2) % 3] - *p[k]);
      corner_angle[3 * f + k] = std::atan2(twice_area, dot);
      corner_cot[3 * f + k] = dot / twice_area; // validation refused degenerate faces
    }
  });

  std::vector<double> angle_sum(nv, 0.), weight(ne, 0.);
  for(std::size_t c = 0; c < 3 * nf; ++c)
  {
    angle_sum[corner_vertex[c]] += corner_angle[c];
    // the edge opposite corner k of a face is its edge k + 1 (from corner k + 1 to corner k + 2)
    const std::size_t f = c / 3, k = c % 3;
    weight[corner_edge[3 * f + (k + 1) % 3]] += 0.5 * corner_cot[c];
  }
  s.K_I.resize(Eigen::Index(s.interior_vertices.size()));
  s.k_B.resize(Eigen::Index(s.boundary_vertices.size()));
  for(std::size_t v = 0; v < nv; ++v)
  {
    if(s.is_boundary[v])
      s.k_B[Eigen::Index(s.block_index[v])] = pi - angle_sum[v];
    else
      s.K_I[Eigen::Index(s.block_index[v])] = two_pi - angle_sum[v];
  }

  // the edges around every vertex (CSR)
  std::vector<std::pair<std::size_t, std::size_t>> ends(ne);
  std::vector<std::size_t> edge_offset(nv + 1, 0), edge_at(2 * ne);
  for(std::size_t e = 0; e < ne; ++e)
  {
    ends[e] = idx.edge_vertices(e);
    ++edge_offset[ends[e].first + 1];
    ++edge_offset[ends[e].second + 1];
  }
  for(std::size_t v = 0; v < nv; ++v)
    edge_offset[v + 1] += edge_offset[v];
  {
    std::vector<std::size_t> fill(edge_offset.begin(), edge_offset.end() - 1);
    for(std::size_t e = 0; e < ne; ++e)
    {
      edge_at[fill[ends[e].first]++] = e;
      edge_at[fill[ends[e].second]++] = e;
    }
  }
  const bff_detail::Laplacian_blocks laplacian{edge_offset, edge_at, ends, weight, s.block_index, s.is_boundary};
  const Eigen::Index ni = Eigen::Index(s.interior_vertices.size()), nb = Eigen::Index(s.boundary_vertices.size());
  s.A_II = laplacian.block(ni, s.interior_vertices, false, true);
  s.A_IB = laplacian.block(ni, s.boundary_vertices, false, false);
  s.A_BB = laplacian.block(nb, s.boundary_vertices, true, true);
  return s;
}

/// The closed polygon of one boundary loop (Sawhney & Crane 2017, sec. 4.3): edge m runs from
/// vertex m to vertex m + 1 with tangent angle phi_m = turning[1] + ... + turning[m] (so the
/// polygon turns by `turning[m]` at vertex m) and length l~_m, where l~ is the closest vector to
/// the target lengths l* in the norm sum (l~_m - l*_m)^2 / l*_m under the closure constraint
/// sum l~_m T_m = 0:  l~ = l* - L T^t (T L T^t)^{-1} T l*,  L = diag(l*).
/// Returns the n vertices, the first at the origin, the first edge along +x.
/// Throws `Invalid_constraints` if the tangents do not span the plane (no closed curve exists).
inline std::vector<Eigen::Vector2d> close_boundary_curve(const std::vector<double>& target_length,
                                                         const std::vector<double>& turning)
{
  const std::size_t n = target_length.size();
  Eigen::Matrix2Xd T(2, Eigen::Index(n));
  double phi = 0.;
  for(std::size_t m = 0; m < n; ++m)
  {
    if(m > 0)
      phi += turning[m];
    T.col(Eigen::Index(m)) = Eigen::Vector2d(std::cos(phi), std::sin(phi));
  }
  Eigen::VectorXd l = Eigen::Map<const Eigen::VectorXd>(target_length.data(), Eigen::Index(n));
  const Eigen::Matrix2d M = T * l.asDiagonal() * T.transpose();
  const Eigen::Vector2d gap = T * l;
  const double det = M.determinant();
  if(!(std::abs(det) > 1e-14 * M.squaredNorm()))
    throw Invalid_constraints("the boundary loop of " + std::to_string(n) +
                              " edges cannot be closed: all its target tangents are parallel");
  const Eigen::VectorXd closed = l - l.asDiagonal() * (T.transpose() * M.inverse() * gap);
  std::vector<Eigen::Vector2d> points(n);
  Eigen::Vector2d p = Eigen::Vector2d::Zero();
  for(std::size_t m = 0; m < n; ++m)
  {
    points[m] = p;
    p += closed[Eigen::Index(m)] * T.col(Eigen::Index(m));
  }
  return points;
}

} // namespace internal
} // namespace Surface_design
} // namespace CGAL

#endif // CGAL_SURFACE_DESIGN_INTERNAL_DEVELOPABILITY_BFF_H
