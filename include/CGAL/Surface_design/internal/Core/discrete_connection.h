// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The discrete Levi-Civita connection between the angle-rescaled vertex frames, and its face
// curvatures.

#ifndef CGAL_SURFACE_DESIGN_INTERNAL_CORE_DISCRETE_CONNECTION_H
#define CGAL_SURFACE_DESIGN_INTERNAL_CORE_DISCRETE_CONNECTION_H

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
  for(std::size_t e = 0; e < c.rho.size(); ++e)
  {
    const auto h = idx.oriented_halfedge(e);
    c.rho[e] = wrap_angle(c.frames.angle[idx.index(opposite(h, tm))] + pi - c.frames.angle[idx.index(h)]);
  }
  c.curvature.assign(idx.number_of_faces(), -pi);
  for(std::size_t f = 0; f < c.curvature.size(); ++f)
    for(auto h : halfedges_around_face(halfedge(idx.face(f), tm), tm))
      c.curvature[f] += c.frames.scale[idx.target_index(h)] * corner[idx.index(h)];
  return c;
}

} // namespace internal
} // namespace Surface_design
} // namespace CGAL

#endif // CGAL_SURFACE_DESIGN_INTERNAL_CORE_DISCRETE_CONNECTION_H
