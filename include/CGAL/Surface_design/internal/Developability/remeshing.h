// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The two mesh operations of the developability flow (Stein, Grinspun & Crane 2018, sec. 4.2-4.3):
// regular 4-1 midpoint subdivision, and the removal of small corner angles by an edge flip (a
// triangle with two small angles) or an edge collapse (a triangle with one), with CGAL's Euler
// operations on any MutableFaceGraph.

#ifndef CGAL_SURFACE_DESIGN_INTERNAL_DEVELOPABILITY_REMESHING_H
#define CGAL_SURFACE_DESIGN_INTERNAL_DEVELOPABILITY_REMESHING_H

#include <CGAL/Surface_design/internal/Core/geometry.h>

#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/helpers.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <cmath>
#include <cstddef>
#include <type_traits>
#include <set>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_design {
namespace internal {

namespace remeshing_detail {

// Surface_mesh keeps removed elements as garbage, which breaks contiguous index maps: collect
// it when the mesh type can (a no-op for Polyhedron_3 and other meshes that free elements).
template <class Mesh, class = void>
struct Has_collect_garbage : std::false_type {};
template <class Mesh>
struct Has_collect_garbage<Mesh, std::void_t<decltype(std::declval<Mesh&>().collect_garbage())>> : std::true_type {};

template <class VertexPointMap>
void put_point(const VertexPointMap& vpm, typename boost::property_traits<VertexPointMap>::key_type v,
               const Eigen::Vector3d& p)
{
  using Point = typename boost::property_traits<VertexPointMap>::value_type;
  put(vpm, v, Point(p.x(), p.y(), p.z()));
}

} // namespace remeshing_detail

/// Frees the storage of removed elements if the mesh type keeps it (`Surface_mesh`), keeping the
/// positions of `vpm` with their vertices. `collect_garbage()` renumbers the vertices and permutes
/// the mesh's own property maps along, but not a map kept outside the mesh (a `std::map` keyed by
/// vertex index, say): the positions are carried across in a property of the mesh and written
/// back to `vpm` under the new indices.
template <class Mesh, class VertexPointMap>
void collect_garbage_if_any(Mesh& tm, const VertexPointMap& vpm)
{
  if constexpr(remeshing_detail::Has_collect_garbage<Mesh>::value)
  {
    if(!tm.has_garbage())
      return;
    using Point = typename boost::property_traits<VertexPointMap>::value_type;
    auto carried = get(CGAL::dynamic_vertex_property_t<Point>(), tm);
    for(auto v : vertices(tm))
      put(carried, v, get(vpm, v));
    tm.collect_garbage();
    for(auto v : vertices(tm))
      put(vpm, v, get(carried, v));
  }
  (void)tm;
  (void)vpm;
}

/// Regular 4-1 subdivision without smoothing (paper, sec. 4.2): every edge is split at its
/// midpoint and every triangle into four, the corners cut off by connecting the midpoints. The
/// geometry does not change (new vertices lie on the old edges); a developable design stays
/// developable. Vertices, edges and faces: V + E, 2E + 3F, 4F. \pre a triangle mesh
template <class Mesh, class VertexPointMap>
void midpoint_subdivision(Mesh& tm, const VertexPointMap& vpm)
{
  using GT = boost::graph_traits<Mesh>;
  using halfedge_descriptor = typename GT::halfedge_descriptor;
  using face_descriptor = typename GT::face_descriptor;
  const std::vector<typename GT::edge_descriptor> old_edges(edges(tm).begin(), edges(tm).end());
  const std::vector<face_descriptor> old_faces(faces(tm).begin(), faces(tm).end());

  // 1. split every edge at its midpoint; remember, per old face, a halfedge that ends at a
  // midpoint and starts at an old corner
  std::set<typename GT::vertex_descriptor> midpoints;
  for(auto e : old_edges)
  {
    const halfedge_descriptor h = halfedge(e, tm);
    const Eigen::Vector3d mid = 0.5 * (position(vpm, source(h, tm)) + position(vpm, target(h, tm)));
    const halfedge_descriptor to_mid = CGAL::Euler::split_edge(h, tm); // source(h) -> new vertex
    remeshing_detail::put_point(vpm, target(to_mid, tm), mid);
    midpoints.insert(target(to_mid, tm));
  }
  // 2. every old face is a hexagon corner, midpoint, corner, ...: cut its three corners off
  for(face_descriptor f : old_faces)
  {
    halfedge_descriptor a = halfedge(f, tm);
    if(midpoints.count(target(a, tm)) == 0) // make a run corner -> midpoint
      a = next(a, tm);
    // the cycle is a = (c0 -> m0), (m0 -> c1), (c1 -> m1), (m1 -> c2), (c2 -> m2), (m2 -> c0)
    const halfedge_descriptor h01 = CGAL::Euler::split_face(a, next(next(a, tm), tm), tm);     // m0 -> m1
    const halfedge_descriptor h12 = CGAL::Euler::split_face(h01, next(next(h01, tm), tm), tm); // m1 -> m2
    CGAL::Euler::split_face(h12, a, tm);                                                        // m2 -> m0
  }
}

/// What `remove_small_angles()` did.
struct Small_angle_report
{
  std::size_t flips = 0, collapses = 0;
};

/// Removes corner angles below `minimum_angle` (radians) as the paper's numerical safeguard
/// (sec. 4.3, Fig. 18): a triangle with two small angles is a cap whose longest edge is flipped;
/// a triangle with one small angle is a needle whose shortest edge is collapsed to its midpoint.
/// Operations keep the mesh a valid manifold: a flip only where the new edge does not exist yet
/// and the two new triangles keep the orientation of the old ones; a collapse only where CGAL's
/// link condition holds, neither endpoint is on the boundary, and the two vertices opposite the
/// edge keep a valence of at least 3. Boundary edges are never flipped or collapsed. Repeats
/// passes until nothing changes (at most `maximum_passes`). Collects Surface_mesh garbage.
template <class Mesh, class VertexPointMap>
Small_angle_report remove_small_angles(Mesh& tm, const VertexPointMap& vpm, double minimum_angle,
                                       std::size_t maximum_passes = 10)
{
  using GT = boost::graph_traits<Mesh>;
  using halfedge_descriptor = typename GT::halfedge_descriptor;
  using vertex_descriptor = typename GT::vertex_descriptor;
  Small_angle_report report;
  auto p = [&](vertex_descriptor v) { return position(vpm, v); };
  // corner angle at target(h) in face(h)
  auto corner = [&](halfedge_descriptor h) {
    const Eigen::Vector3d u = p(source(h, tm)) - p(target(h, tm)), w = p(target(next(h, tm), tm)) - p(target(h, tm));
    return std::atan2(u.cross(w).norm(), u.dot(w));
  };
  auto normal = [&](vertex_descriptor a, vertex_descriptor b, vertex_descriptor c) {
    return Eigen::Vector3d((p(b) - p(a)).cross(p(c) - p(a)));
  };
  auto interior_vertex = [&](vertex_descriptor v) { return !is_border(v, tm); };

  for(std::size_t pass = 0; pass < maximum_passes; ++pass)
  {
    bool changed = false;
    const std::vector<typename GT::face_descriptor> current(faces(tm).begin(), faces(tm).end());
    std::set<typename GT::face_descriptor> touched; // by value: no dereference of removed faces
    for(auto f : current)
    {
      if(touched.count(f))
        continue; // changed by an operation of this pass: look again in the next pass
      const halfedge_descriptor h0 = halfedge(f, tm);
      const halfedge_descriptor hs[3] = {h0, next(h0, tm), next(next(h0, tm), tm)};
      double angle[3];
      int small = 0;
      for(int i = 0; i < 3; ++i)
      {
        angle[i] = corner(hs[i]); // at target(hs[i]); the opposite edge is prev(hs[i]) = next(next(hs[i]))
        small += angle[i] < minimum_angle;
      }
      if(small == 0)
        continue;
      if(small >= 2)
      {
        // cap: flip the edge opposite the largest angle
        int big = 0;
        for(int i = 1; i < 3; ++i)
          if(angle[i] > angle[big])
            big = i;
        const halfedge_descriptor e = next(next(hs[big], tm), tm); // opposite target(hs[big])
        const halfedge_descriptor o = opposite(e, tm);
        if(is_border(o, tm))
          continue;
        const vertex_descriptor a = target(next(e, tm), tm), b = target(next(o, tm), tm);
        if(halfedge(a, b, tm).second)
          continue; // the flipped edge exists already
        const vertex_descriptor s = source(e, tm), t = target(e, tm);
        const Eigen::Vector3d n_old = normal(s, t, a) + normal(t, s, b);
        if(!(normal(a, b, t).dot(n_old) > 0. && normal(b, a, s).dot(n_old) > 0.))
          continue; // the quadrilateral is not convex enough: the flip would fold it
        touched.insert(face(e, tm));
        touched.insert(face(o, tm));
        CGAL::Euler::flip_edge(e, tm);
        ++report.flips;
        changed = true;
      }
      else
      {
        // needle: collapse the edge opposite the small angle, i.e. the shortest edge
        int tiny = 0;
        for(int i = 1; i < 3; ++i)
          if(angle[i] < angle[tiny])
            tiny = i;
        const halfedge_descriptor e = next(next(hs[tiny], tm), tm); // opposite the small angle
        const halfedge_descriptor o = opposite(e, tm);
        if(is_border(o, tm) || !interior_vertex(source(e, tm)) || !interior_vertex(target(e, tm)))
          continue;
        const vertex_descriptor apex1 = target(next(e, tm), tm), apex2 = target(next(o, tm), tm);
        if(degree(apex1, tm) <= 3 || degree(apex2, tm) <= 3)
          continue;
        if(!CGAL::Euler::does_satisfy_link_condition(edge(e, tm), tm))
          continue;
        const Eigen::Vector3d mid = 0.5 * (p(source(e, tm)) + p(target(e, tm)));
        for(auto g : faces_around_target(e, tm))
          touched.insert(g);
        for(auto g : faces_around_target(o, tm))
          touched.insert(g);
        const vertex_descriptor kept = CGAL::Euler::collapse_edge(edge(e, tm), tm);
        remeshing_detail::put_point(vpm, kept, mid);
        ++report.collapses;
        changed = true;
      }
    }
    if(!changed)
      break;
  }
  collect_garbage_if_any(tm, vpm);
  return report;
}

} // namespace internal
} // namespace Surface_design
} // namespace CGAL

#endif // CGAL_SURFACE_DESIGN_INTERNAL_DEVELOPABILITY_REMESHING_H
