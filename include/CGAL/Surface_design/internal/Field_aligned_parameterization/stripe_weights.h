// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The weights of the stripe energy on a direction field's cover (Branched_stripe_parameterizer):
// per edge, with the contributions of branch faces dropped, and per branch face the weights of
// the spokes from its corners to its branch point.

#ifndef CGAL_SURFACE_DESIGN_INTERNAL_FIELD_ALIGNED_PARAMETERIZATION_STRIPE_WEIGHTS_H
#define CGAL_SURFACE_DESIGN_INTERNAL_FIELD_ALIGNED_PARAMETERIZATION_STRIPE_WEIGHTS_H

#include <CGAL/Surface_design/internal/Core/direction_field_cover.h>
#include <CGAL/Surface_design/internal/Core/geometry.h>
#include <CGAL/Surface_design/internal/Field_aligned_parameterization/stripe_interpolation.h>

#include <boost/graph/graph_traits.hpp>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cstddef>
#include <functional>
#include <limits>
#include <queue>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_design {
namespace internal {

/// The stiffness per face (`Branched_stripe_parameterizer::stiffen()`) after multiplying by
/// `factor` that of `faces` (indices) and by `ring_factor` that of the other faces sharing a
/// vertex with one of them (the larger of the two where both apply), capped at 4^10; `stiffness`
/// empty: all 1 before.
template <class Indices>
std::vector<double> stiffened(const Indices& idx, std::vector<double> stiffness, const std::vector<std::size_t>& faces,
                              double factor, double ring_factor)
{
  const auto& tm = idx.mesh();
  if(stiffness.empty())
    stiffness.assign(idx.number_of_faces(), 1.);
  std::vector<double> times(idx.number_of_faces(), 1.);
  for(std::size_t f : faces)
    times[f] = factor;
  if(ring_factor != 1.)
    for(std::size_t f : faces)
      for(auto v : vertices_around_face(halfedge(idx.face(f), tm), tm))
        for(auto g : faces_around_target(halfedge(v, tm), tm))
          if(g != boost::graph_traits<typename Indices::Mesh>::null_face())
          {
            double& t = times[idx.index(g)];
            t = (std::max)(t, ring_factor);
          }
  for(std::size_t f = 0; f < times.size(); ++f)
    stiffness[f] = (std::min)(stiffness[f] * times[f], 1048576.);
  return stiffness;
}

/// The vertices (indices) of `faces` (indices) and those within `radius` of them along the edges
/// (Dijkstra's distances from the faces' corners).
template <class Indices, class VertexPointMap>
std::vector<std::size_t> vertices_near_faces(const Indices& idx, const VertexPointMap& vpm,
                                             const std::vector<std::size_t>& faces, double radius)
{
  const auto& tm = idx.mesh();
  std::vector<double> distance(idx.number_of_vertices(), std::numeric_limits<double>::infinity());
  using Entry = std::pair<double, std::size_t>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> queue;
  for(std::size_t f : faces)
    for(auto v : vertices_around_face(halfedge(idx.face(f), tm), tm))
      if(distance[idx.index(v)] > 0.)
      {
        distance[idx.index(v)] = 0.;
        queue.emplace(0., idx.index(v));
      }
  std::vector<std::size_t> out;
  while(!queue.empty())
  {
    const auto [d, v] = queue.top();
    queue.pop();
    if(d > distance[v])
      continue;
    out.push_back(v);
    const Eigen::Vector3d p = position(vpm, idx.vertex(v));
    for(auto w : vertices_around_target(halfedge(idx.vertex(v), tm), tm))
    {
      const double dw = d + (position(vpm, w) - p).norm();
      if(dw <= radius && dw < distance[idx.index(w)])
      {
        distance[idx.index(w)] = dw;
        queue.emplace(dw, idx.index(w));
      }
    }
  }
  return out;
}

/// The corners of face f, in the order source(h), target(h), target(next(h)) for h = halfedge(f)
/// (vertices_around_face() starts at target(h): not this order).
template <class Indices, class VertexPointMap>
std::array<Eigen::Vector3d, 3> face_corners(const Indices& idx, const VertexPointMap& vpm, std::size_t f)
{
  const auto& tm = idx.mesh();
  const auto h = halfedge(idx.face(f), tm);
  return {position(vpm, source(h, tm)), position(vpm, target(h, tm)), position(vpm, target(next(h, tm), tm))};
}

/// The branch point of face f (`branch_point_barycentric()` of its corners), in space.
template <class Indices, class VertexPointMap>
Eigen::Vector3d branch_point_position(const Indices& idx, const VertexPointMap& vpm, std::size_t f)
{
  const auto x = face_corners(idx, vpm, f);
  const auto o = branch_point_barycentric(x);
  return o[0] * x[0] + o[1] * x[1] + o[2] * x[2];
}

/// The cotangents in the triangle (source(h), target(h), o) of face f, o its branch point: at o,
/// at source(h), at target(h).
template <class Indices, class VertexPointMap, class Halfedge>
std::array<double, 3> sub_triangle_cotangents(const Indices& idx, const VertexPointMap& vpm, std::size_t f,
                                              Halfedge h)
{
  const auto& tm = idx.mesh();
  const Eigen::Vector3d o = branch_point_position(idx, vpm, f);
  const Eigen::Vector3d a = position(vpm, source(h, tm)), b = position(vpm, target(h, tm));
  auto cot = [](const Eigen::Vector3d& x, const Eigen::Vector3d& y) { return x.dot(y) / x.cross(y).norm(); };
  return {cot(a - o, b - o), cot(b - a, o - a), cot(a - b, o - b)};
}

/// Edge weights with the contributions of branch faces dropped: the cotangent weight (`cot`, per
/// halfedge) keeps the halves of its regular faces, the uniform weight 1 the share of its faces
/// that are regular; with lattice branch points and cotangent weights, a branch face contributes
/// the cotangent at its branch point of the triangle on the edge. `stiffness`: per face, or empty
/// (all 1).
template <class Indices, class VertexPointMap>
std::vector<double> stripe_edge_weights(const Indices& idx, const VertexPointMap& vpm, const Direction_field_cover& cover,
                                        const std::vector<double>& cot, const std::vector<double>& stiffness,
                                        bool lattice, bool uniform)
{
  const auto& tm = idx.mesh();
  auto stiff = [&](std::size_t f) { return stiffness.empty() ? 1. : stiffness[f]; };
  std::vector<double> w(idx.number_of_edges(), 0.);
  for(std::size_t e = 0; e < w.size(); ++e)
  {
    const auto h = idx.oriented_halfedge(e);
    int faces = 0;
    double regular = 0.; // the stiffness of the regular faces
    for(const auto g : {h, opposite(h, tm)})
      if(!idx.is_border(g))
      {
        ++faces;
        const std::size_t f = idx.index(face(g, tm));
        if(cover.regular[f])
        {
          regular += stiff(f);
          w[e] += 0.5 * stiff(f) * cot[idx.index(g)];
        }
        else if(lattice && !uniform)
          w[e] += 0.5 * stiff(f) * (std::max)(0., sub_triangle_cotangents(idx, vpm, f, g)[0]);
      }
    if(uniform)
      w[e] = regular / double(faces);
  }
  return w;
}

/// With branch points on the lattice: the weights of the spokes from the corners of every branch
/// face to its branch point o (the cotangent weights of the triangles (c_k, c_k+1, o): spoke k is
/// opposite corner k+1 in one of them and corner k-1 in the other; at least 0), in the order of
/// the corners (source(h), target(h), target(next(h)) for h = halfedge(f)); empty otherwise.
template <class Indices, class VertexPointMap>
std::vector<std::array<double, 3>> stripe_spoke_weights(const Indices& idx, const VertexPointMap& vpm,
                                                        const Direction_field_cover& cover,
                                                        const std::vector<double>& stiffness, bool lattice,
                                                        bool uniform)
{
  if(!lattice)
    return {};
  const auto& tm = idx.mesh();
  std::vector<std::array<double, 3>> w(idx.number_of_faces(), {0., 0., 0.});
  for(std::size_t f = 0; f < w.size(); ++f)
  {
    if(cover.regular[f])
      continue;
    int k = 0;
    for(auto h : halfedges_around_face(halfedge(idx.face(f), tm), tm))
    {
      // the triangle (c_k, c_k+1, o): its angle at c_k+1 is opposite spoke k, at c_k opposite spoke k+1
      const std::array<double, 3> c =
        uniform ? std::array<double, 3>{1., 1., 1.} : sub_triangle_cotangents(idx, vpm, f, h);
      w[f][std::size_t(k)] += 0.5 * c[2];
      w[f][std::size_t((k + 1) % 3)] += 0.5 * c[1];
      ++k;
    }
    for(double& x : w[f])
      x = (std::max)(0., x) * (stiffness.empty() ? 1. : stiffness[f]);
  }
  return w;
}

} // namespace internal
} // namespace Surface_design
} // namespace CGAL

#endif // CGAL_SURFACE_DESIGN_INTERNAL_FIELD_ALIGNED_PARAMETERIZATION_STRIPE_WEIGHTS_H
