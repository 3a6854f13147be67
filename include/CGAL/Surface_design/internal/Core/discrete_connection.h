// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The discrete Levi-Civita connection between the angle-rescaled vertex frames, its face
// curvatures, and the indices of n-direction fields it transports.

#ifndef CGAL_SURFACE_DESIGN_INTERNAL_CORE_DISCRETE_CONNECTION_H
#define CGAL_SURFACE_DESIGN_INTERNAL_CORE_DISCRETE_CONNECTION_H

#include <CGAL/Surface_design/internal/Core/angles.h>
#include <CGAL/Surface_design/internal/Core/geometry.h>
#include <CGAL/Surface_design/internal/Core/vertex_frames.h>

#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Surface_design {
namespace internal {

/// Transport between vertex frames. A tangent direction of angle a at vertex i (in i's frame) is
/// carried along the edge to j as the direction of angle a + rho_ij in j's frame, where
/// rho_ij = phi_ji + pi - phi_ij and phi_ij is the angle of the edge i -> j in i's frame (the edge
/// direction at i becomes, reversed, the edge direction at j). Around a face the transport angles
/// sum, modulo 2 pi, to the face curvature K_f = (sum of the rescaled corner angles) - pi. On a
/// closed component the K_f sum to 2 pi chi; with boundary, to 2 pi chi minus the boundary turning
/// sum_v (pi - angle sum at v) over the boundary vertices (discrete Gauss-Bonnet).
struct Discrete_connection
{
  Vertex_frames frames;
  std::vector<double> rho;       ///< per edge index, along the edge's orientation (smaller -> larger vertex index), in [-pi, pi)
  std::vector<double> curvature; ///< K_f per face

  /// Transport angle along halfedge index h.
  template <class Indices>
  double transport(const Indices& idx, std::size_t h) const
  {
    const auto hd = idx.halfedge(h);
    return idx.orientation_sign(hd) * rho[idx.edge_index(hd)];
  }
};

template <class Indices, class VertexPointMap>
Discrete_connection levi_civita_connection(const Indices& idx, const VertexPointMap& vpm)
{
  const auto& tm = idx.mesh();
  const std::vector<double> corner = corner_angles(idx, vpm);
  Discrete_connection c;
  c.frames = vertex_frames(idx, vpm, corner);
  c.rho.resize(idx.number_of_edges());
  for_each_index(c.rho.size(), worth_parallel(c.rho.size()), [&](std::size_t e) {
    const auto h = idx.oriented_halfedge(e);
    c.rho[e] = wrap_angle(c.frames.angle[idx.index(opposite(h, tm))] + pi - c.frames.angle[idx.index(h)]);
  });
  c.curvature.assign(idx.number_of_faces(), -pi);
  for_each_index(c.curvature.size(), worth_parallel(c.curvature.size()), [&](std::size_t f) {
    for(auto h : halfedges_around_face(halfedge(idx.face(f), tm), tm))
      c.curvature[f] += c.frames.scale[idx.target_index(h)] * corner[idx.index(h)];
  });
  return c;
}

/// Singularity index of an n-direction field given by one angle per vertex (any of its n
/// directions, in the vertex frames), per face, as an integer numerator: the index is
/// numerator / n. Around face f, n times the field turns, relative to the transport, by
/// sum_h wrap(n (a_j - a_i - rho_ij)) (each term the smallest turn between the n-fold
/// directions), and the transport itself turns by n K_f:
/// index_f = (sum_h wrap(...) + n K_f) / (2 pi n).
template <class Indices>
std::vector<int> field_index_numerators(const Indices& idx, const Discrete_connection& c,
                                        const std::vector<double>& angle, int n)
{
  const auto& tm = idx.mesh();
  std::vector<int> k(idx.number_of_faces());
  for(std::size_t f = 0; f < k.size(); ++f)
  {
    double sum = n * c.curvature[f];
    for(auto h : halfedges_around_face(halfedge(idx.face(f), tm), tm))
      sum += wrap_angle(n * (angle[idx.target_index(h)] - angle[idx.source_index(h)] -
                             c.transport(idx, idx.index(h))));
    k[f] = int(std::lround(sum / two_pi));
  }
  return k;
}

} // namespace internal
} // namespace Surface_design
} // namespace CGAL

#endif // CGAL_SURFACE_DESIGN_INTERNAL_CORE_DISCRETE_CONNECTION_H
