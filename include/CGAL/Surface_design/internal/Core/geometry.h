// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Per-element geometric quantities of a triangle mesh, indexed by Mesh_indices.

#ifndef CGAL_SURFACE_DESIGN_INTERNAL_CORE_GEOMETRY_H
#define CGAL_SURFACE_DESIGN_INTERNAL_CORE_GEOMETRY_H

#include <CGAL/Surface_design/internal/Core/angles.h>
#include <CGAL/Surface_design/internal/Core/Mesh_indices.h>
#include <CGAL/Surface_design/internal/Solvers/parallel.h>

#include <CGAL/Kernel_traits.h>
#include <CGAL/Weights/utils.h>
#include <CGAL/number_utils.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <boost/property_map/property_map.hpp>

#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Surface_design {
namespace internal {

// Conventions (all vectors are indexed by the indices of `Mesh_indices`):
// - a *corner* is a non-border halfedge `h`: the corner of face(h) at vertex target(h), between
//   `h` and `next(h)`;
// - the angle *opposite* halfedge `h` is the corner angle of face(h) at target(next(h));
// - border halfedges have angle 0 and cotangent 0.
// Every function here requires a triangle mesh without degenerate faces (see validation.h);
// they never divide by a length or an area that validation did not bound away from zero.

/// Position of `v` as an Eigen vector of doubles.
template <class VertexPointMap, class Vertex>
Eigen::Vector3d position(const VertexPointMap& vpm, Vertex v)
{
  const auto& p = get(vpm, v);
  return Eigen::Vector3d(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
}

/// Positions of all vertices, by index. Read once, in order: the loops that run concurrently read
/// this vector, never the user's map (whose `get` need not be safe to call from several threads).
template <class Indices, class VertexPointMap>
std::vector<Eigen::Vector3d> vertex_positions(const Indices& idx, const VertexPointMap& vpm)
{
  std::vector<Eigen::Vector3d> x(idx.number_of_vertices());
  for(std::size_t v = 0; v < x.size(); ++v)
    x[v] = position(vpm, idx.vertex(v));
  return x;
}

/// Whether per-element loops over a mesh of `n` elements are worth running as concurrent tasks
/// (TBB): below, the tasks' start-up costs more than the loop (measured with the corner angles:
/// 2 threads gain from a few thousand halfedges on).
inline bool worth_parallel(std::size_t n) { return n >= 4096; }

/// The three vertex positions of the face of non-border halfedge `h`, starting at source(h).
template <class Indices, class VertexPointMap>
void triangle_of(const Indices& idx, const VertexPointMap& vpm,
                 typename Indices::halfedge_descriptor h,
                 Eigen::Vector3d& a, Eigen::Vector3d& b, Eigen::Vector3d& c)
{
  const auto& tm = idx.mesh();
  a = position(vpm, source(h, tm));
  b = position(vpm, target(h, tm));
  c = position(vpm, target(next(h, tm), tm));
}

/// Area of every face.
template <class Indices, class VertexPointMap>
std::vector<double> face_areas(const Indices& idx, const VertexPointMap& vpm)
{
  std::vector<double> area(idx.number_of_faces());
  for(std::size_t f = 0; f < area.size(); ++f)
  {
    Eigen::Vector3d a, b, c;
    triangle_of(idx, vpm, halfedge(idx.face(f), idx.mesh()), a, b, c);
    area[f] = 0.5 * (b - a).cross(c - a).norm();
  }
  return area;
}

/// Unit normal of every face (orientation of the face's halfedge cycle, right-hand rule).
template <class Indices, class VertexPointMap>
std::vector<Eigen::Vector3d> face_normals(const Indices& idx, const VertexPointMap& vpm)
{
  std::vector<Eigen::Vector3d> normal(idx.number_of_faces());
  for(std::size_t f = 0; f < normal.size(); ++f)
  {
    Eigen::Vector3d a, b, c;
    triangle_of(idx, vpm, halfedge(idx.face(f), idx.mesh()), a, b, c);
    normal[f] = (b - a).cross(c - a).normalized();
  }
  return normal;
}

/// Length of every edge.
template <class Indices, class VertexPointMap>
std::vector<double> edge_lengths(const Indices& idx, const VertexPointMap& vpm)
{
  std::vector<double> length(idx.number_of_edges());
  for(std::size_t e = 0; e < length.size(); ++e)
  {
    const auto h = halfedge(idx.edge(e), idx.mesh());
    length[e] = (position(vpm, target(h, idx.mesh())) - position(vpm, source(h, idx.mesh()))).norm();
  }
  return length;
}

/// Interior angle of every corner (per halfedge: the angle of face(h) at target(h); 0 on border
/// halfedges), computed as atan2(|u x v|, u . v), accurate for all angles in [0, pi].
template <class Indices, class VertexPointMap>
std::vector<double> corner_angles(const Indices& idx, const VertexPointMap& vpm)
{
  const std::vector<Eigen::Vector3d> x = vertex_positions(idx, vpm);
  const auto& tm = idx.mesh();
  std::vector<double> angle(idx.number_of_halfedges(), 0.);
  for_each_index(angle.size(), worth_parallel(angle.size()), [&](std::size_t i) {
    const auto h = idx.halfedge(i);
    if(idx.is_border(h))
      return;
    const Eigen::Vector3d& b = x[idx.target_index(h)];
    const Eigen::Vector3d u = x[idx.source_index(h)] - b, v = x[idx.target_index(next(h, tm))] - b;
    angle[i] = std::atan2(u.cross(v).norm(), u.dot(v));
  });
  return angle;
}

/// Sum of the corner angles around every vertex.
template <class Indices>
std::vector<double> vertex_angle_sums(const Indices& idx, const std::vector<double>& corner_angle)
{
  std::vector<double> sum(idx.number_of_vertices(), 0.);
  for(std::size_t i = 0; i < corner_angle.size(); ++i)
    if(!idx.is_border(idx.halfedge(i)))
      sum[idx.target_index(idx.halfedge(i))] += corner_angle[i];
  return sum;
}

/// Cotangent of the angle opposite every halfedge, in the face of that halfedge (0 on border
/// halfedges). Uses `CGAL::Weights::cotangent()` (dot product over cross-product norm): exact in
/// sign, negative for obtuse angles.
template <class Indices, class VertexPointMap>
std::vector<double> halfedge_cotangents(const Indices& idx, const VertexPointMap& vpm)
{
  using Point = typename boost::property_traits<VertexPointMap>::value_type;
  using Kernel = typename CGAL::Kernel_traits<Point>::Kernel;
  const Kernel traits;
  const auto& tm = idx.mesh();
  std::vector<double> cot(idx.number_of_halfedges(), 0.);
  for(std::size_t i = 0; i < cot.size(); ++i)
  {
    const auto h = idx.halfedge(i);
    if(idx.is_border(h))
      continue;
    // triangle (p, q, r) with q the corner opposite h
    const Point& p = get(vpm, source(h, tm));
    const Point& q = get(vpm, target(next(h, tm), tm));
    const Point& r = get(vpm, target(h, tm));
    cot[i] = CGAL::to_double(CGAL::Weights::cotangent(p, q, r, traits));
  }
  return cot;
}

/// Cotangent weight of every edge, w_ij = (cot a + cot b) / 2 with a, b the angles opposite the
/// edge (a single term on border edges). Negative on non-Delaunay edges.
template <class Indices>
std::vector<double> cotangent_weights(const Indices& idx, const std::vector<double>& halfedge_cot)
{
  const auto& tm = idx.mesh();
  std::vector<double> w(idx.number_of_edges());
  for(std::size_t e = 0; e < w.size(); ++e)
  {
    const auto h = halfedge(idx.edge(e), tm);
    w[e] = 0.5 * (halfedge_cot[idx.index(h)] + halfedge_cot[idx.index(opposite(h, tm))]);
  }
  return w;
}

/// Convenience overload computing the halfedge cotangents first.
template <class Indices, class VertexPointMap>
std::vector<double> cotangent_weights(const Indices& idx, const VertexPointMap& vpm)
{
  return cotangent_weights(idx, halfedge_cotangents(idx, vpm));
}

/// Barycentric vertex areas: a third of the area of every incident face. They sum to the total
/// area and are the diagonal of the lumped mass matrix.
template <class Indices>
std::vector<double> vertex_areas(const Indices& idx, const std::vector<double>& face_area)
{
  const auto& tm = idx.mesh();
  std::vector<double> area(idx.number_of_vertices(), 0.);
  for(std::size_t f = 0; f < face_area.size(); ++f)
    for(auto v : vertices_around_face(halfedge(idx.face(f), tm), tm))
      area[idx.index(v)] += face_area[f] / 3.;
  return area;
}

/// Angle-weighted unit vertex normals (Thürmer & Wüthrich): the sum of the incident face normals
/// weighted by the corner angles.
/// `angle` are the corner angles (corner_angles()), when the caller has them already.
template <class Indices, class VertexPointMap>
std::vector<Eigen::Vector3d> vertex_normals(const Indices& idx, const VertexPointMap& vpm,
                                            const std::vector<double>& angle)
{
  const std::vector<Eigen::Vector3d> fn = face_normals(idx, vpm);
  std::vector<Eigen::Vector3d> normal(idx.number_of_vertices(), Eigen::Vector3d::Zero());
  for(std::size_t i = 0; i < angle.size(); ++i)
  {
    const auto h = idx.halfedge(i);
    if(idx.is_border(h))
      continue;
    normal[idx.target_index(h)] += angle[i] * fn[idx.index(face(h, idx.mesh()))];
  }
  for(Eigen::Vector3d& n : normal)
    n.normalize();
  return normal;
}

/// Same, computing the corner angles.
template <class Indices, class VertexPointMap>
std::vector<Eigen::Vector3d> vertex_normals(const Indices& idx, const VertexPointMap& vpm)
{
  return vertex_normals(idx, vpm, corner_angles(idx, vpm));
}

} // namespace internal
} // namespace Surface_design
} // namespace CGAL

#endif // CGAL_SURFACE_DESIGN_INTERNAL_CORE_GEOMETRY_H
