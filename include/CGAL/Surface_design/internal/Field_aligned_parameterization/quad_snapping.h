// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The extracted quads snapped onto the input's features: cones onto the corners of its creases,
// the rows next to the creases onto them, then its vertices and crease points that the quads
// pass far from (the mesh core's feature snapping).

#ifndef CGAL_SURFACE_DESIGN_INTERNAL_FIELD_ALIGNED_PARAMETERIZATION_QUAD_SNAPPING_H
#define CGAL_SURFACE_DESIGN_INTERNAL_FIELD_ALIGNED_PARAMETERIZATION_QUAD_SNAPPING_H

#include <CGAL/Surface_design/internal/Core/feature_snapping.h>
#include <CGAL/Surface_design/internal/Core/geometry.h>
#include <CGAL/Surface_design/internal/Field_aligned_parameterization/quad_extraction.h>

#include <Eigen/Core>

#include <cmath>
#include <cstddef>
#include <optional>
#include <vector>

namespace CGAL {
namespace Surface_design {
namespace internal {

struct Quad_snapping
{
  std::size_t cones_on_corners = 0, crease_vertices = 0;
  Snap_statistics far; ///< of the snapping onto the input's vertices and crease points
};

/// Snaps the quads `q` (spacing h) onto the input's features, the cones' vertices
/// (`q.cone_vertex`, in the faces `cone_faces`) fixed but for the corners:
///  - with `given_creases` (per edge index; none: the edges whose faces' normals differ by more
///    than 30 degrees, and the first two steps are skipped), a cone in a face with a corner of
///    the creases (an interior vertex with three crease edges or more) within 2h (the reach of
///    the last step) moves onto it, one cone per corner;
///  - the rows next to the given creases move onto them (`snap_rows_onto_creases()`, within
///    3h / 4);
///  - the input's interior vertices and points along the creases farther than h / 4 from the
///    quads pull the nearest vertex onto them (`snap_to_far_points()`, reach 2h).
/// No move turns a quad over against its orientation before the first.
template <class Indices, class VertexPointMap>
Quad_snapping snap_quads_to_features(Quad_extraction& q, const Indices& idx, const VertexPointMap& vpm,
                                     const std::vector<std::size_t>& cone_faces,
                                     const std::optional<std::vector<bool>>& given_creases, double h)
{
  Quad_snapping out;
  const std::vector<Eigen::Vector3d> before = q.points;
  std::vector<char> fixed(q.points.size(), 0);
  for(std::size_t v : q.cone_vertex)
    fixed[v] = 1;
  const auto& tm = idx.mesh();
  if(given_creases)
  {
    const std::vector<bool>& crease = *given_creases;
    std::vector<int> crease_edges_at(idx.number_of_vertices(), 0);
    std::vector<bool> used(idx.number_of_vertices(), false);
    for(auto e : edges(tm))
    {
      const auto hd = halfedge(e, tm);
      if(is_border(e, tm)) // (a boundary vertex is no corner: the boundary's vertices stay)
        used[idx.index(source(hd, tm))] = used[idx.index(target(hd, tm))] = true;
      else if(crease[idx.index(e)])
      {
        ++crease_edges_at[idx.index(source(hd, tm))];
        ++crease_edges_at[idx.index(target(hd, tm))];
      }
    }
    const Soup_adjacency adjacency = soup_adjacency(q.points.size(), q.faces);
    for(std::size_t i = 0; i < cone_faces.size(); ++i)
    {
      const std::size_t c = q.cone_vertex[i];
      std::size_t corner = npos;
      for(auto v : vertices_around_face(halfedge(idx.face(cone_faces[i]), tm), tm))
      {
        const std::size_t w = idx.index(v);
        if(crease_edges_at[w] >= 3 && !used[w] && (position(vpm, v) - q.points[c]).norm() <= 2. * h &&
           (corner == npos || (position(vpm, v) - q.points[c]).norm() <
                                (position(vpm, idx.vertex(corner)) - q.points[c]).norm()))
          corner = w;
      }
      if(corner == npos)
        continue;
      const Eigen::Vector3d x = position(vpm, idx.vertex(corner));
      if(keeps_orientation(q.points, q.faces, adjacency.faces_around[c], c, x, &before) &&
         lands_apart(q.points, q.faces, adjacency.faces_around[c], c, x, 1e-9 * h))
      {
        q.points[c] = x;
        used[corner] = true;
        ++out.cones_on_corners;
      }
    }
    out.crease_vertices =
      snap_rows_onto_creases(q.points, q.faces, crease_segments(idx, vpm, crease), 0.75 * h, true, fixed, &before);
  }
  const std::vector<bool> crease = given_creases ? *given_creases : dihedral_creases(idx, vpm, CGAL_PI / 6.);
  out.far = snap_to_far_points(q.points, q.faces, mesh_snap_targets(idx, vpm, crease, h / 2.), h / 4., 2. * h, true,
                               fixed, &before);
  return out;
}

} // namespace internal
} // namespace Surface_design
} // namespace CGAL

#endif // CGAL_SURFACE_DESIGN_INTERNAL_FIELD_ALIGNED_PARAMETERIZATION_QUAD_SNAPPING_H
