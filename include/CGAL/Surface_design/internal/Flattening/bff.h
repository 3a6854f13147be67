// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Boundary First Flattening (Sawhney & Crane 2017) of a union of topological disks: the data of
// the cotangent Laplacian split into interior (I) and boundary (B) blocks, the curvatures, the
// boundary loops in counter-clockwise order, and the closure of a boundary curve from target
// lengths and turning angles.

#ifndef CGAL_SURFACE_DESIGN_INTERNAL_FLATTENING_BFF_H
#define CGAL_SURFACE_DESIGN_INTERNAL_FLATTENING_BFF_H

#include <CGAL/Surface_design/exceptions.h>
#include <CGAL/Surface_design/internal/Core/Mesh_indices.h>
#include <CGAL/Surface_design/internal/Core/angles.h>
#include <CGAL/Surface_design/internal/Core/geometry.h>
#include <CGAL/Surface_design/internal/Core/topology.h>

#include <Eigen/Core>
#include <Eigen/Sparse>

#include <cmath>
#include <cstddef>
#include <sstream>
#include <string>
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

template <class Indices, class VertexPointMap>
Bff_system bff_system(const Indices& idx, const VertexPointMap& vpm, const Boundary_loops& loops)
{
  const auto& tm = idx.mesh();
  const std::size_t nv = idx.number_of_vertices();
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

  const std::vector<double> angle = corner_angles(idx, vpm);
  const std::vector<double> sum = vertex_angle_sums(idx, angle);
  s.K_I.resize(Eigen::Index(s.interior_vertices.size()));
  s.k_B.resize(Eigen::Index(s.boundary_vertices.size()));
  for(std::size_t v = 0; v < nv; ++v)
  {
    if(s.is_boundary[v])
      s.k_B[Eigen::Index(s.block_index[v])] = pi - sum[v];
    else
      s.K_I[Eigen::Index(s.block_index[v])] = two_pi - sum[v];
  }

  const std::vector<double> w = cotangent_weights(idx, vpm);
  using T = Eigen::Triplet<double>;
  std::vector<T> ii, ib, bb;
  auto add = [&](std::size_t a, std::size_t b, double value) {
    const Eigen::Index ra = Eigen::Index(s.block_index[a]), rb = Eigen::Index(s.block_index[b]);
    if(!s.is_boundary[a] && !s.is_boundary[b])
      ii.emplace_back(ra, rb, value);
    else if(!s.is_boundary[a])
      ib.emplace_back(ra, rb, value);
    else if(s.is_boundary[a] && s.is_boundary[b])
      bb.emplace_back(ra, rb, value);
  };
  for(std::size_t e = 0; e < w.size(); ++e)
  {
    const auto ij = idx.edge_vertices(e);
    add(ij.first, ij.first, w[e]);
    add(ij.second, ij.second, w[e]);
    add(ij.first, ij.second, -w[e]);
    add(ij.second, ij.first, -w[e]);
  }
  const Eigen::Index ni = Eigen::Index(s.interior_vertices.size()), nb = Eigen::Index(s.boundary_vertices.size());
  s.A_II.resize(ni, ni);
  s.A_II.setFromTriplets(ii.begin(), ii.end());
  s.A_IB.resize(ni, nb);
  s.A_IB.setFromTriplets(ib.begin(), ib.end());
  s.A_BB.resize(nb, nb);
  s.A_BB.setFromTriplets(bb.begin(), bb.end());
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

#endif // CGAL_SURFACE_DESIGN_INTERNAL_FLATTENING_BFF_H
