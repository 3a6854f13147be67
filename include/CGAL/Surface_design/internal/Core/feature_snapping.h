// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Snapping a remeshed surface (a polygon soup) onto the points of the input that it passes far
// from: its vertices, and points along its creases (both remeshers: the harmonic nets and the
// field-aligned quads).

#ifndef CGAL_SURFACE_DESIGN_INTERNAL_CORE_FEATURE_SNAPPING_H
#define CGAL_SURFACE_DESIGN_INTERNAL_CORE_FEATURE_SNAPPING_H

#include <CGAL/Surface_design/internal/Core/geometry.h>
#include <CGAL/Surface_design/internal/Solvers/parallel.h>

#include <CGAL/AABB_segment_primitive.h>
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

struct Snap_statistics
{
  std::size_t far_vertices = 0; ///< targets farther than the tolerance from the soup
  std::size_t snapped = 0;      ///< soup vertices moved onto one of them
  double largest_distance = 0.; ///< before snapping: the largest distance of a target to the soup
};

/// The points that snapping may pull a soup onto: `points` (the input's interior vertices), then
/// points along the crease segments, at most `spacing` apart (each segment cut into equal
/// pieces, its ends left out: they are vertices). A remeshed surface whose cells span a crease
/// cuts it off between two of the input's vertices (the vertical edges of a slab's holes, many
/// spacings long on a coarse input).
inline std::vector<Eigen::Vector3d>
snap_targets(std::vector<Eigen::Vector3d> points,
             const std::vector<std::pair<Eigen::Vector3d, Eigen::Vector3d>>& creases, double spacing)
{
  for(const auto& [a, b] : creases)
  {
    const std::size_t pieces = std::size_t(std::ceil((b - a).norm() / spacing));
    for(std::size_t k = 1; k < pieces; ++k)
      points.push_back(a + (double(k) / double(pieces)) * (b - a));
  }
  return points;
}

/// Per edge index: whether the edge is a crease, an interior edge whose faces' normals differ by
/// more than `angle` (radians).
template <class Indices, class VertexPointMap>
std::vector<bool> dihedral_creases(const Indices& idx, const VertexPointMap& vpm, double angle)
{
  const auto& tm = idx.mesh();
  const auto normal = [&](auto hd) {
    const Eigen::Vector3d a = position(vpm, source(hd, tm)), b = position(vpm, target(hd, tm)),
                          c = position(vpm, target(next(hd, tm), tm));
    return Eigen::Vector3d((b - a).cross(c - a).normalized());
  };
  const double cosine = std::cos(angle);
  std::vector<bool> crease(idx.number_of_edges(), false);
  for(auto e : edges(tm))
    if(!is_border(e, tm))
    {
      const auto hd = halfedge(e, tm);
      crease[idx.index(e)] = normal(hd).dot(normal(opposite(hd, tm))) < cosine;
    }
  return crease;
}

/// The snap targets of a triangle mesh: its interior vertices, and points along `crease` edges
/// (per edge index; interior ones only), at most `spacing` apart (`snap_targets()`).
template <class Indices, class VertexPointMap>
std::vector<Eigen::Vector3d> mesh_snap_targets(const Indices& idx, const VertexPointMap& vpm,
                                               const std::vector<bool>& crease, double spacing)
{
  std::vector<bool> on_boundary(idx.number_of_vertices(), false);
  std::vector<std::pair<Eigen::Vector3d, Eigen::Vector3d>> segments;
  const auto& tm = idx.mesh();
  for(auto e : edges(tm))
  {
    const auto hd = halfedge(e, tm);
    const std::size_t i = idx.index(source(hd, tm)), j = idx.index(target(hd, tm));
    if(is_border(e, tm))
      on_boundary[i] = on_boundary[j] = true;
    else if(crease[idx.index(e)])
      segments.emplace_back(position(vpm, source(hd, tm)), position(vpm, target(hd, tm)));
  }
  std::vector<Eigen::Vector3d> points;
  for(std::size_t v = 0; v < idx.number_of_vertices(); ++v)
    if(!on_boundary[v])
      points.push_back(position(vpm, idx.vertex(v)));
  return snap_targets(std::move(points), segments, spacing);
}

/// The faces around every vertex of a polygon soup, its edges (each once, as sorted pairs) and
/// its boundary vertices (on an edge that only one face has).
struct Soup_adjacency
{
  std::vector<std::vector<std::size_t>> faces_around;
  std::vector<std::pair<std::size_t, std::size_t>> edges;
  std::vector<char> on_boundary;
};

inline Soup_adjacency soup_adjacency(std::size_t vertices, const std::vector<std::vector<std::size_t>>& soup_faces)
{
  Soup_adjacency a;
  a.faces_around.resize(vertices);
  a.on_boundary.assign(vertices, 0);
  for(std::size_t f = 0; f < soup_faces.size(); ++f)
    for(std::size_t i = 0; i < soup_faces[f].size(); ++i)
    {
      const std::size_t u = soup_faces[f][i], w = soup_faces[f][(i + 1) % soup_faces[f].size()];
      a.edges.emplace_back((std::min)(u, w), (std::max)(u, w));
      a.faces_around[u].push_back(f);
    }
  std::sort(a.edges.begin(), a.edges.end());
  for(std::size_t i = 0; i < a.edges.size(); ++i)
    if((i == 0 || a.edges[i - 1] != a.edges[i]) && (i + 1 == a.edges.size() || a.edges[i + 1] != a.edges[i]))
      a.on_boundary[a.edges[i].first] = a.on_boundary[a.edges[i].second] = 1;
  a.edges.erase(std::unique(a.edges.begin(), a.edges.end()), a.edges.end());
  return a;
}

/// Newell's normal of a face of a soup (twice its vector area) with its vertex `moved` at `to`
/// (none when `moved` is npos).
inline Eigen::Vector3d newell_normal(const std::vector<Eigen::Vector3d>& soup_points, const std::vector<std::size_t>& face,
                                     std::size_t moved, const Eigen::Vector3d& to)
{
  Eigen::Vector3d n = Eigen::Vector3d::Zero();
  for(std::size_t i = 0; i < face.size(); ++i)
  {
    const std::size_t j = (i + 1) % face.size();
    n += (face[i] == moved ? to : soup_points[face[i]]).cross(face[j] == moved ? to : soup_points[face[j]]);
  }
  return n;
}

/// Whether moving vertex v of a soup to `to` keeps every face around it facing the same way: its
/// normal keeps a positive dot product with the one it has with the `reference` positions (the
/// soup's before any move, so that moves one after the other cannot turn a face by steps; the
/// current positions when null).
inline bool keeps_orientation(const std::vector<Eigen::Vector3d>& soup_points,
                              const std::vector<std::vector<std::size_t>>& soup_faces,
                              const std::vector<std::size_t>& faces_around, std::size_t v, const Eigen::Vector3d& to,
                              const std::vector<Eigen::Vector3d>* reference = nullptr)
{
  const std::vector<Eigen::Vector3d>& before = reference ? *reference : soup_points;
  for(std::size_t f : faces_around)
    if(!(newell_normal(soup_points, soup_faces[f], v, to).dot(newell_normal(before, soup_faces[f], npos, to)) > 0.))
      return false;
  return true;
}

/// Whether `to` lies farther than `epsilon` from every other vertex of the faces around v (a
/// move there would not make two vertices one point).
inline bool lands_apart(const std::vector<Eigen::Vector3d>& soup_points,
                        const std::vector<std::vector<std::size_t>>& soup_faces,
                        const std::vector<std::size_t>& faces_around, std::size_t v, const Eigen::Vector3d& to,
                        double epsilon)
{
  for(std::size_t f : faces_around)
    for(std::size_t w : soup_faces[f])
      if(w != v && (soup_points[w] - to).norm() <= epsilon)
        return false;
  return true;
}

/// The remeshed surface passes over features narrower than its spacing: a pit or a spike, the
/// apex of a cone, a sharp crease. The `targets` (`snap_targets()`, at most 2 `tolerance` apart)
/// farther than `tolerance` from the soup's surface, farthest first, pull the nearest corner of
/// the soup face closest to them onto them, provided that
///  - that corner is not on the boundary nor `fixed` (per soup vertex; empty: none) and is at
///    most `reach` away,
///  - no face around it turns over (its normal keeps a positive dot product with the old one, or
///    with the one it has with the `reference` positions when given),
///  - no face around it has moved already (the distances are those before any move: a corner
///    next to a moved one stays),
///  - the targets closest to a face around it end up closer to the surface than the farthest of
///    them was (a pull into a narrow pit must not lift the surface off a ridge next to it).
/// The topology does not change; positions move onto points of the input, so the output still
/// interpolates the input there.
inline Snap_statistics snap_to_far_points(std::vector<Eigen::Vector3d>& soup_points,
                                          const std::vector<std::vector<std::size_t>>& soup_faces,
                                          const std::vector<Eigen::Vector3d>& targets, double tolerance, double reach,
                                          bool parallel, const std::vector<char>& fixed = {},
                                          const std::vector<Eigen::Vector3d>* reference = nullptr)
{
  using K = CGAL::Simple_cartesian<double>;
  using Triangles = std::vector<K::Triangle_3>;
  using Primitive = CGAL::AABB_triangle_primitive<K, Triangles::const_iterator>;
  using Tree = CGAL::AABB_tree<CGAL::AABB_traits<K, Primitive>>;
  Snap_statistics stats;
  const auto point = [](const Eigen::Vector3d& p) { return K::Point_3(p.x(), p.y(), p.z()); };
  Triangles triangles;
  std::vector<std::size_t> face_of;
  for(std::size_t f = 0; f < soup_faces.size(); ++f)
  {
    const auto& c = soup_faces[f];
    for(std::size_t i = 1; i + 1 < c.size(); ++i)
    {
      triangles.emplace_back(point(soup_points[c[0]]), point(soup_points[c[i]]), point(soup_points[c[i + 1]]));
      face_of.push_back(f);
    }
  }
  if(triangles.empty() || targets.empty())
    return stats;
  Tree tree(triangles.cbegin(), triangles.cend());
  tree.accelerate_distance_queries();
  const std::size_t nv = targets.size();
  std::vector<double> distance(nv, 0.);
  std::vector<std::size_t> closest_face(nv, npos);
  (void)tree.closest_point(point(targets[0])); // builds the search structure before the parallel queries
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
  const Soup_adjacency adjacency = soup_adjacency(soup_points.size(), soup_faces);
  const auto& faces_around = adjacency.faces_around;
  const auto& on_boundary = adjacency.on_boundary;
  std::vector<std::vector<std::size_t>> closest_to(soup_faces.size());
  for(std::size_t v = 0; v < nv; ++v)
    if(closest_face[v] != npos)
      closest_to[closest_face[v]].push_back(v);
  std::vector<char> face_moved(soup_faces.size(), 0);
  for(std::size_t v : far)
  {
    const std::size_t f = closest_face[v];
    if(face_moved[f])
      continue;
    const Eigen::Vector3d& target = targets[v];
    std::size_t corner = npos;
    for(std::size_t c : soup_faces[f])
      if(!on_boundary[c] && (fixed.empty() || !fixed[c]) &&
         (corner == npos || (soup_points[c] - target).squaredNorm() < (soup_points[corner] - target).squaredNorm()))
        corner = c;
    if(corner == npos || (soup_points[corner] - target).norm() > reach)
      continue;
    bool any_moved = false;
    for(std::size_t g : faces_around[corner])
      any_moved = any_moved || face_moved[g];
    if(any_moved || !keeps_orientation(soup_points, soup_faces, faces_around[corner], corner, target, reference))
      continue;
    // the targets closest to a face around the corner may move away from it: their
    // distance to the faces around the corner and their neighbours (an upper bound of the new
    // distance) must stay below the largest old one (the others keep their closest face)
    std::vector<std::size_t> ring;
    for(std::size_t g : faces_around[corner])
      for(std::size_t c : soup_faces[g])
        ring.insert(ring.end(), faces_around[c].begin(), faces_around[c].end());
    std::sort(ring.begin(), ring.end());
    ring.erase(std::unique(ring.begin(), ring.end()), ring.end());
    const auto distance_to_ring = [&](const Eigen::Vector3d& x, const Eigen::Vector3d& corner_at) {
      double d2 = std::numeric_limits<double>::infinity();
      const K::Point_3 q = point(x);
      for(std::size_t g : ring)
      {
        const auto& c = soup_faces[g];
        const auto at = [&](std::size_t i) { return point(c[i] == corner ? corner_at : soup_points[c[i]]); };
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
    soup_points[corner] = target;
    for(std::size_t g : faces_around[corner])
      face_moved[g] = 1;
    ++stats.snapped;
  }
  return stats;
}

/// A crease edge of the input (`crease_segments()`): its ends and `side`, the difference of the
/// perpendiculars of its two faces that point into them: near a point c of the crease, a point p
/// of the surface lies on the first face's side where (p - c) . side > 0, on the other's where it
/// is negative (at any dihedral angle: the perpendiculars differ unless the faces fold flat).
struct Crease_segment
{
  Eigen::Vector3d a, b, side;
};

/// The `crease` edges (per edge index) that are not on the boundary, as `Crease_segment`s.
template <class Indices, class VertexPointMap>
std::vector<Crease_segment> crease_segments(const Indices& idx, const VertexPointMap& vpm, const std::vector<bool>& crease)
{
  const auto& tm = idx.mesh();
  // the perpendicular of the face of hd to its edge, pointing into the face (counterclockwise:
  // to the left of the edge's direction)
  const auto inward = [&](auto hd) {
    const Eigen::Vector3d p = position(vpm, source(hd, tm)), q = position(vpm, target(hd, tm)),
                          r = position(vpm, target(next(hd, tm), tm));
    return Eigen::Vector3d((q - p).cross(r - p).normalized().cross((q - p).normalized()));
  };
  std::vector<Crease_segment> out;
  for(auto e : edges(tm))
    if(!is_border(e, tm) && crease[idx.index(e)])
    {
      const auto hd = halfedge(e, tm);
      out.push_back({position(vpm, source(hd, tm)), position(vpm, target(hd, tm)), inward(hd) - inward(opposite(hd, tm))});
    }
  return out;
}

/// The vertices of a polygon soup (a quad mesh) along the creases, moved onto them, so that its
/// edges follow the creases instead of cutting across them. Every edge of the soup that crosses
/// a crease (its two ends on the two sides of the crease segment nearest the end closer to it,
/// `Crease_segment::side`) marks that closer end, if it lies within `reach` of the creases, not
/// on the soup's boundary and not `fixed` (per soup vertex; empty: none); the marked vertices
/// move onto their nearest points of the creases, closest first, each unless a face around it
/// would turn over (`keeps_orientation()`, against `reference` when given) or the point is
/// another vertex's of those faces. On a quad mesh whose lines run along the creases (a
/// field that follows them) the closer ends are the row of vertices next to each crease: the row
/// moves onto it. Returns the number of vertices moved; the topology does not change.
inline std::size_t snap_rows_onto_creases(std::vector<Eigen::Vector3d>& soup_points,
                                          const std::vector<std::vector<std::size_t>>& soup_faces,
                                          const std::vector<Crease_segment>& creases, double reach, bool parallel,
                                          const std::vector<char>& fixed = {},
                                          const std::vector<Eigen::Vector3d>* reference = nullptr)
{
  using K = CGAL::Simple_cartesian<double>;
  using Segments = std::vector<K::Segment_3>;
  using Primitive = CGAL::AABB_segment_primitive<K, Segments::const_iterator>;
  using Tree = CGAL::AABB_tree<CGAL::AABB_traits<K, Primitive>>;
  const std::size_t nv = soup_points.size();
  if(creases.empty() || nv == 0)
    return 0;
  const auto point = [](const Eigen::Vector3d& p) { return K::Point_3(p.x(), p.y(), p.z()); };
  Segments segments;
  for(const Crease_segment& c : creases)
    segments.emplace_back(point(c.a), point(c.b));
  Tree tree(segments.cbegin(), segments.cend());
  tree.accelerate_distance_queries();
  std::vector<Eigen::Vector3d> nearest(nv);
  std::vector<std::size_t> segment(nv);
  std::vector<double> distance(nv);
  (void)tree.closest_point(point(soup_points[0])); // builds the search structure before the parallel queries
  for_each_index(nv, parallel, [&](std::size_t v) {
    const auto [q, id] = tree.closest_point_and_primitive(point(soup_points[v]));
    nearest[v] = Eigen::Vector3d(q.x(), q.y(), q.z());
    segment[v] = std::size_t(id - segments.cbegin());
    distance[v] = (soup_points[v] - nearest[v]).norm();
  });
  const Soup_adjacency adjacency = soup_adjacency(nv, soup_faces);
  std::vector<char> marked(nv, 0);
  for(const auto& [v, w] : adjacency.edges)
  {
    const std::size_t closer = distance[v] <= distance[w] ? v : w, other = closer == v ? w : v;
    if(!(distance[closer] > 0.) || distance[closer] > reach)
      continue; // on a crease already, or far from them
    const Crease_segment& c = creases[segment[closer]];
    // the other end's side of the same segment (from its nearest point on it)
    const Eigen::Vector3d ab = c.b - c.a;
    if(!(ab.squaredNorm() > 0.))
      continue;
    const double t = std::clamp((soup_points[other] - c.a).dot(ab) / ab.squaredNorm(), 0., 1.);
    const double side = (soup_points[closer] - nearest[closer]).dot(c.side),
                 other_side = (soup_points[other] - (c.a + t * ab)).dot(c.side);
    if(side * other_side < 0.)
      marked[closer] = 1;
  }
  std::vector<std::size_t> order;
  for(std::size_t v = 0; v < nv; ++v)
    if(marked[v] && !adjacency.on_boundary[v] && (fixed.empty() || !fixed[v]))
      order.push_back(v);
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return distance[a] < distance[b] || (distance[a] == distance[b] && a < b); });
  std::size_t moved = 0;
  for(std::size_t v : order)
  {
    if(!keeps_orientation(soup_points, soup_faces, adjacency.faces_around[v], v, nearest[v], reference) ||
       !lands_apart(soup_points, soup_faces, adjacency.faces_around[v], v, nearest[v], 1e-9 * reach))
      continue;
    soup_points[v] = nearest[v];
    ++moved;
  }
  return moved;
}

} // namespace internal
} // namespace Surface_design
} // namespace CGAL

#endif // CGAL_SURFACE_DESIGN_INTERNAL_CORE_FEATURE_SNAPPING_H
