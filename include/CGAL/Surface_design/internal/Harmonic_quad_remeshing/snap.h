// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Snapping the net's soup onto the input's vertices and creases that it passes far from
// (the snapping itself is the mesh core's, internal/Core/feature_snapping.h).

#ifndef CGAL_SURFACE_DESIGN_INTERNAL_HARMONIC_QUAD_REMESHING_SNAP_H
#define CGAL_SURFACE_DESIGN_INTERNAL_HARMONIC_QUAD_REMESHING_SNAP_H

#include <CGAL/Surface_design/internal/Core/feature_snapping.h>
#include <CGAL/Surface_design/internal/Harmonic_quad_remeshing/quad_net_builder.h>
#include <CGAL/Surface_design/internal/Harmonic_quad_remeshing/trace_mesh.h>

#include <Eigen/Core>

#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_design {
namespace internal {
namespace harmonic_quad {

/// The points that snapping may pull the soup onto (`internal::snap_targets()`): the input's
/// interior vertices, and points along its creases (interior edges whose faces' normals differ
/// by more than 30 degrees), at most `spacing` apart.
inline std::vector<Eigen::Vector3d> snap_targets(const Trace_mesh& m, double spacing)
{
  std::vector<Eigen::Vector3d> vertices;
  for(std::size_t v = 0; v < m.number_of_vertices(); ++v)
    if(!m.on_boundary[v] && !m.star[v].empty())
      vertices.push_back(m.point[v]);
  const double crease = std::cos(30. * 3.141592653589793 / 180.);
  std::vector<std::pair<Eigen::Vector3d, Eigen::Vector3d>> creases;
  for(std::size_t f = 0; f < m.number_of_faces(); ++f)
    for(std::size_t i = 0; i < 3; ++i)
    {
      const std::size_t g = m.neighbour[f][i];
      if(g != npos && g > f && m.normal[f].dot(m.normal[g]) < crease)
        creases.emplace_back(m.point[m.tri[f][i]], m.point[m.tri[f][(i + 1) % 3]]);
    }
  return internal::snap_targets(std::move(vertices), creases, spacing);
}

/// The net's soup snapped onto the input's vertices and creases farther than `tolerance` from
/// it (`internal::snap_to_far_points()`, the targets at most 2 `tolerance` apart).
inline Snap_statistics snap_to_far_vertices(Polygon_soup& soup, const Trace_mesh& m, double tolerance, double reach,
                                            bool parallel)
{
  return snap_to_far_points(soup.points, soup.faces, snap_targets(m, 2. * tolerance), tolerance, reach, parallel);
}

} // namespace harmonic_quad
} // namespace internal
} // namespace Surface_design
} // namespace CGAL

#endif // CGAL_SURFACE_DESIGN_INTERNAL_HARMONIC_QUAD_REMESHING_SNAP_H
