// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SURFACE_DESIGN_INTERNAL_CORE_HAUSDORFF_DISTANCE_H
#define CGAL_SURFACE_DESIGN_INTERNAL_CORE_HAUSDORFF_DISTANCE_H

// The two-sided Hausdorff distance between two triangulated surfaces, certified: a lower bound (the
// largest distance found at a point of one surface) and an upper bound no more than a given error
// above it.
//
// One side, from A to B: d(p) = distance from p to B. Over a triangle T of A, d is bounded above
// in two ways:
//  - d is 1-Lipschitz: d(p) <= d(v) + |p - v| for a corner v of T, so max_T d <= d(v) + (the
//    longest edge of T at v);
//  - the distance to one triangle t of B is convex, so over T it is largest at a corner:
//    max_T d <= max_T dist(., t) = max over the corners of dist(corner, t); the candidates t are the
//    triangles of B closest to the corners.
// The triangles of A wait in a queue ordered by their upper bound; the one with the largest is
// split in four (the distances at the edge midpoints raise the lower bound) until the largest upper
// bound is within the error of the largest distance found. The Lipschitz bound shrinks with the
// edges, so this ends.

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/boost/graph/iterator.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <map>
#include <queue>
#include <vector>

namespace CGAL {
namespace Surface_design {
namespace internal {

/// Points and triangles (indices into the points).
struct Triangle_soup
{
  using Point = CGAL::Exact_predicates_inexact_constructions_kernel::Point_3;
  std::vector<Point> points;
  std::vector<std::array<std::size_t, 3>> triangles;
};

/// The faces of `pm` fanned into triangles from their first corner, with `vpm`'s points in double
/// precision.
template <class PolygonMesh, class VertexPointMap>
Triangle_soup fanned_triangle_soup(const PolygonMesh& pm, const VertexPointMap& vpm)
{
  Triangle_soup soup;
  std::map<typename boost::graph_traits<PolygonMesh>::vertex_descriptor, std::size_t> index;
  for(auto v : vertices(pm))
  {
    const auto& p = get(vpm, v);
    index.emplace(v, soup.points.size());
    soup.points.emplace_back(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
  }
  std::vector<std::size_t> corners;
  for(auto f : faces(pm))
  {
    corners.clear();
    for(auto v : vertices_around_face(halfedge(f, pm), pm))
      corners.push_back(index.at(v));
    for(std::size_t k = 1; k + 1 < corners.size(); ++k)
      soup.triangles.push_back({corners[0], corners[k], corners[k + 1]});
  }
  return soup;
}

/// The exact Hausdorff distance lies in [lower, upper].
struct Hausdorff_bounds
{
  double lower = 0.;
  double upper = 0.;
};

namespace hausdorff_internal {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Triangle = Kernel::Triangle_3;

// The distances from the points of one surface to another triangle soup, and the refinement of
// the first surface's triangles.
class One_side
{
  using Primitive = CGAL::AABB_triangle_primitive<Kernel, std::vector<Triangle>::const_iterator>;
  using Tree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive>>;

  struct Piece
  {
    double upper;
    std::array<Point, 3> p;
    std::array<double, 3> distance;
    std::array<std::size_t, 3> closest; // the triangle of the other surface closest to each corner
    bool operator<(const Piece& other) const { return upper < other.upper; }
  };

public:
  explicit One_side(const Triangle_soup& to)
  {
    targets_.reserve(to.triangles.size());
    for(const auto& t : to.triangles)
      targets_.emplace_back(to.points[t[0]], to.points[t[1]], to.points[t[2]]);
    tree_.insert(targets_.cbegin(), targets_.cend());
    tree_.accelerate_distance_queries();
  }

  // the triangles of `from`, with the distances at their corners (the lower bound rises to the
  // largest; points of no triangle are not on the surface and are left out)
  void add(const Triangle_soup& from, double& lower)
  {
    std::vector<double> distance(from.points.size());
    std::vector<std::size_t> closest(from.points.size());
    std::vector<char> used(from.points.size(), 0);
    for(const auto& t : from.triangles)
      used[t[0]] = used[t[1]] = used[t[2]] = 1;
    for(std::size_t v = 0; v < from.points.size(); ++v)
      if(used[v])
      {
        query(from.points[v], distance[v], closest[v]);
        lower = (std::max)(lower, distance[v]);
      }
    for(const auto& t : from.triangles)
      queue_.push(piece({from.points[t[0]], from.points[t[1]], from.points[t[2]]},
                        {distance[t[0]], distance[t[1]], distance[t[2]]},
                        {closest[t[0]], closest[t[1]], closest[t[2]]}));
  }

  // splits pieces until no upper bound exceeds `lower + error`; returns the largest upper bound
  double refine(double& lower, double error)
  {
    while(!queue_.empty() && queue_.top().upper > lower + error)
    {
      const Piece t = queue_.top();
      queue_.pop();
      std::array<Point, 3> m;
      std::array<double, 3> dm;
      std::array<std::size_t, 3> cm;
      for(int i = 0; i < 3; ++i) // m[i] halves the edge from corner i to corner i + 1
      {
        m[i] = CGAL::midpoint(t.p[i], t.p[(i + 1) % 3]);
        query(m[i], dm[i], cm[i]);
        lower = (std::max)(lower, dm[i]);
      }
      queue_.push(piece({t.p[0], m[0], m[2]}, {t.distance[0], dm[0], dm[2]}, {t.closest[0], cm[0], cm[2]}));
      queue_.push(piece({m[0], t.p[1], m[1]}, {dm[0], t.distance[1], dm[1]}, {cm[0], t.closest[1], cm[1]}));
      queue_.push(piece({m[2], m[1], t.p[2]}, {dm[2], dm[1], t.distance[2]}, {cm[2], cm[1], t.closest[2]}));
      queue_.push(piece(m, dm, cm));
    }
    return queue_.empty() ? 0. : queue_.top().upper;
  }

private:
  void query(const Point& p, double& distance, std::size_t& closest) const
  {
    const auto found = tree_.closest_point_and_primitive(p);
    distance = std::sqrt(CGAL::squared_distance(p, found.first));
    closest = std::size_t(found.second - targets_.cbegin());
  }

  Piece piece(const std::array<Point, 3>& p, const std::array<double, 3>& distance,
              const std::array<std::size_t, 3>& closest) const
  {
    double upper = std::numeric_limits<double>::infinity();
    for(int i = 0; i < 3; ++i) // Lipschitz
    {
      const double reach = (std::max)(CGAL::squared_distance(p[i], p[(i + 1) % 3]),
                                      CGAL::squared_distance(p[i], p[(i + 2) % 3]));
      upper = (std::min)(upper, distance[i] + std::sqrt(reach));
    }
    for(int k = 0; k < 3; ++k) // convexity of the distance to one triangle
    {
      double largest = 0.;
      for(int i = 0; i < 3 && largest < upper; ++i)
        largest = (std::max)(largest, i == k ? distance[i] : std::sqrt(CGAL::squared_distance(p[i], targets_[closest[k]])));
      upper = (std::min)(upper, largest);
    }
    return Piece{upper, p, distance, closest};
  }

  std::vector<Triangle> targets_;
  Tree tree_;
  std::priority_queue<Piece> queue_;
};

} // namespace hausdorff_internal

/// Two-sided Hausdorff distance between the surfaces of `a` and `b` (each with at least one
/// triangle), certified: `upper - lower <= error` (`error > 0`). An error below what the
/// coordinates can resolve (1e-12 times the largest coordinate) is raised to that, so that the
/// refinement ends.
inline Hausdorff_bounds bounded_hausdorff_distance(const Triangle_soup& a, const Triangle_soup& b, double error)
{
  double largest = 0.;
  for(const Triangle_soup* soup : {&a, &b})
    for(const auto& p : soup->points)
      largest = (std::max)({largest, std::abs(p.x()), std::abs(p.y()), std::abs(p.z())});
  error = (std::max)(error, 1e-12 * largest);
  hausdorff_internal::One_side a_to_b(b), b_to_a(a);
  Hausdorff_bounds h;
  a_to_b.add(a, h.lower);
  b_to_a.add(b, h.lower);
  // the larger lower bound of the two sides serves both: a side whose pieces all stay below it
  // need not be refined
  const double upper_ab = a_to_b.refine(h.lower, error);
  const double upper_ba = b_to_a.refine(h.lower, error);
  h.upper = (std::max)({h.lower, upper_ab, upper_ba});
  return h;
}

} // namespace internal
} // namespace Surface_design
} // namespace CGAL

#endif // CGAL_SURFACE_DESIGN_INTERNAL_CORE_HAUSDORFF_DISTANCE_H
