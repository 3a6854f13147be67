// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Snapping the remeshed surface onto the input's vertices that it passes far from.

#ifndef CGAL_SURFACE_DESIGN_INTERNAL_HARMONIC_QUAD_REMESHING_SNAP_H
#define CGAL_SURFACE_DESIGN_INTERNAL_HARMONIC_QUAD_REMESHING_SNAP_H

#include <CGAL/Surface_design/internal/Solvers/parallel.h>
#include <CGAL/Surface_design/internal/Harmonic_quad_remeshing/quad_net.h>
#include <CGAL/Surface_design/internal/Harmonic_quad_remeshing/trace_mesh.h>

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Simple_cartesian.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_design {
namespace internal {
namespace harmonic_quad {

struct Snap_statistics
{
  std::size_t far_vertices = 0; ///< interior input vertices and crease points farther than the tolerance from the soup
  std::size_t snapped = 0;      ///< soup vertices moved onto one of them
  double largest_distance = 0.; ///< before snapping: the largest distance of such a point to the soup
};

/// The points that snapping may pull the soup onto: the input's interior vertices, and points
/// along its creases (interior edges whose faces' normals differ by more than 30 degrees), at
/// most `spacing` apart (each crease edge cut into equal pieces). A net whose cells span a crease
/// cuts it off between two of the input's vertices (the vertical edges of a slab's holes, many
/// spacings long on a coarse input).
inline std::vector<Eigen::Vector3d> snap_targets(const Trace_mesh& m, double spacing)
{
  std::vector<Eigen::Vector3d> out;
  for(std::size_t v = 0; v < m.number_of_vertices(); ++v)
    if(!m.on_boundary[v] && !m.star[v].empty())
      out.push_back(m.point[v]);
  const double crease = std::cos(30. * 3.141592653589793 / 180.);
  for(std::size_t f = 0; f < m.number_of_faces(); ++f)
    for(std::size_t i = 0; i < 3; ++i)
    {
      const std::size_t g = m.neighbour[f][i];
      if(g == npos || g < f || !(m.normal[f].dot(m.normal[g]) < crease))
        continue;
      const Eigen::Vector3d& a = m.point[m.tri[f][i]];
      const Eigen::Vector3d& b = m.point[m.tri[f][(i + 1) % 3]];
      const std::size_t pieces = std::size_t(std::ceil((b - a).norm() / spacing));
      for(std::size_t k = 1; k < pieces; ++k)
        out.push_back(a + (double(k) / double(pieces)) * (b - a));
    }
  return out;
}

/// The net passes over features narrower than its spacing: a pit or a spike, the apex of a cone,
/// a sharp crease. Input vertices (interior ones: the boundary follows the input's, see
/// `Quad_net_builder::boundary_detail`) and points along the input's creases (`snap_targets()`,
/// at most 2 `tolerance` apart) farther than `tolerance` from the soup's surface, farthest first, pull
/// the nearest corner of the soup face closest to them onto them, provided that
///  - that corner is not on the boundary and is at most `reach` away,
///  - no face around it turns over (its normal keeps a positive dot product with the old one),
///  - no face around it has moved already (the distances are those before any move: a corner
///    next to a moved one stays),
///  - the points closest to a face around it end up closer to the surface than the farthest of
///    them was (a pull into a narrow pit must not lift the surface off a ridge next to it).
/// The topology does not change; positions move onto points of the input, so the output still
/// interpolates the input there.
inline Snap_statistics snap_to_far_vertices(Polygon_soup& soup, const Trace_mesh& m, double tolerance, double reach,
                                            bool parallel)
{
  using K = CGAL::Simple_cartesian<double>;
  using Triangles = std::vector<K::Triangle_3>;
  using Primitive = CGAL::AABB_triangle_primitive<K, Triangles::const_iterator>;
  using Tree = CGAL::AABB_tree<CGAL::AABB_traits<K, Primitive>>;
  Snap_statistics stats;
  const auto point = [](const Eigen::Vector3d& p) { return K::Point_3(p.x(), p.y(), p.z()); };
  Triangles triangles;
  std::vector<std::size_t> face_of;
  for(std::size_t f = 0; f < soup.faces.size(); ++f)
  {
    const auto& c = soup.faces[f];
    for(std::size_t i = 1; i + 1 < c.size(); ++i)
    {
      triangles.emplace_back(point(soup.points[c[0]]), point(soup.points[c[i]]), point(soup.points[c[i + 1]]));
      face_of.push_back(f);
    }
  }
  if(triangles.empty())
    return stats;
  Tree tree(triangles.cbegin(), triangles.cend());
  tree.accelerate_distance_queries();
  const std::vector<Eigen::Vector3d> targets = snap_targets(m, 2. * tolerance);
  const std::size_t nv = targets.size();
  std::vector<double> distance(nv, 0.);
  std::vector<std::size_t> closest_face(nv, npos);
  (void)tree.closest_point(point(m.point[0])); // builds the search structure before the parallel queries
  for_each_index(nv, parallel, [&](std::size_t v) {
    const K::Point_3 p = point(targets[v]);
    const auto [q, id] = tree.closest_point_and_primitive(p);
    distance[v] = std::sqrt(CGAL::squared_distance(p, q));
    closest_face[v] = face_of[std::size_t(id - triangles.cbegin())];
  });
  std::vector<std::size_t> far;
  for(std::size_t v = 0; v < nv; ++v)
  {
    stats.largest_distance = (std::max)(stats.largest_distance, distance[v]);
    if(distance[v] > tolerance)
      far.push_back(v);
  }
  stats.far_vertices = far.size();
  if(far.empty())
    return stats;
  std::sort(far.begin(), far.end(), [&](std::size_t a, std::size_t b) {
    return distance[a] > distance[b] || (distance[a] == distance[b] && a < b);
  });
  std::vector<std::vector<std::size_t>> faces_around(soup.points.size());
  for(std::size_t f = 0; f < soup.faces.size(); ++f)
    for(std::size_t c : soup.faces[f])
      faces_around[c].push_back(f);
  // boundary corners: on an edge that only one face has
  std::vector<std::pair<std::size_t, std::size_t>> edges;
  for(const auto& c : soup.faces)
    for(std::size_t i = 0; i < c.size(); ++i)
      edges.emplace_back((std::min)(c[i], c[(i + 1) % c.size()]), (std::max)(c[i], c[(i + 1) % c.size()]));
  std::sort(edges.begin(), edges.end());
  std::vector<char> on_boundary(soup.points.size(), 0);
  for(std::size_t i = 0; i < edges.size(); ++i)
    if((i == 0 || edges[i - 1] != edges[i]) && (i + 1 == edges.size() || edges[i + 1] != edges[i]))
      on_boundary[edges[i].first] = on_boundary[edges[i].second] = 1;
  const auto newell_normal = [&](std::size_t f, std::size_t moved, const Eigen::Vector3d& to) {
    const auto& c = soup.faces[f];
    Eigen::Vector3d n = Eigen::Vector3d::Zero();
    for(std::size_t i = 0; i < c.size(); ++i)
    {
      const std::size_t j = (i + 1) % c.size();
      n += (c[i] == moved ? to : soup.points[c[i]]).cross(c[j] == moved ? to : soup.points[c[j]]);
    }
    return n;
  };
  std::vector<std::vector<std::size_t>> closest_to(soup.faces.size());
  for(std::size_t v = 0; v < nv; ++v)
    if(closest_face[v] != npos)
      closest_to[closest_face[v]].push_back(v);
  std::vector<char> face_moved(soup.faces.size(), 0);
  for(std::size_t v : far)
  {
    const std::size_t f = closest_face[v];
    if(face_moved[f])
      continue;
    const Eigen::Vector3d& target = targets[v];
    std::size_t corner = npos;
    for(std::size_t c : soup.faces[f])
      if(!on_boundary[c] && (corner == npos || (soup.points[c] - target).squaredNorm() <
                                                   (soup.points[corner] - target).squaredNorm()))
        corner = c;
    if(corner == npos || (soup.points[corner] - target).norm() > reach)
      continue;
    bool keeps_orientation = true;
    for(std::size_t g : faces_around[corner])
      keeps_orientation = keeps_orientation && !face_moved[g] &&
                          newell_normal(g, corner, target).dot(newell_normal(g, npos, target)) > 0.;
    if(!keeps_orientation)
      continue;
    // the points closest to a face around the corner may move away from it: their
    // distance to the faces around the corner and their neighbours (an upper bound of the new
    // distance) must stay below the largest old one (the others keep their closest face)
    std::vector<std::size_t> ring;
    for(std::size_t g : faces_around[corner])
      for(std::size_t c : soup.faces[g])
        ring.insert(ring.end(), faces_around[c].begin(), faces_around[c].end());
    std::sort(ring.begin(), ring.end());
    ring.erase(std::unique(ring.begin(), ring.end()), ring.end());
    const auto distance_to_ring = [&](const Eigen::Vector3d& x, const Eigen::Vector3d& corner_at) {
      double d2 = std::numeric_limits<double>::infinity();
      const K::Point_3 q = point(x);
      for(std::size_t g : ring)
      {
        const auto& c = soup.faces[g];
        const auto at = [&](std::size_t i) { return point(c[i] == corner ? corner_at : soup.points[c[i]]); };
        for(std::size_t i = 1; i + 1 < c.size(); ++i)
          d2 = (std::min)(d2, CGAL::squared_distance(q, K::Triangle_3(at(0), at(i), at(i + 1))));
      }
      return std::sqrt(d2);
    };
    double before = 0., after = 0.;
    for(std::size_t g : faces_around[corner])
      for(std::size_t w : closest_to[g])
      {
        before = (std::max)(before, distance[w]);
        after = (std::max)(after, distance_to_ring(targets[w], target));
      }
    if(!(after < before))
      continue;
    soup.points[corner] = target;
    for(std::size_t g : faces_around[corner])
      face_moved[g] = 1;
    ++stats.snapped;
  }
  return stats;
}

} // namespace harmonic_quad
} // namespace internal
} // namespace Surface_design
} // namespace CGAL

#endif // CGAL_SURFACE_DESIGN_INTERNAL_HARMONIC_QUAD_REMESHING_SNAP_H
