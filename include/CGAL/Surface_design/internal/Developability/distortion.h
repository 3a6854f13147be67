// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Distortion of a map from a triangle mesh to the plane: singular values per face, and
// intersections of boundary segments in the plane.

#ifndef CGAL_SURFACE_DESIGN_INTERNAL_DEVELOPABILITY_DISTORTION_H
#define CGAL_SURFACE_DESIGN_INTERNAL_DEVELOPABILITY_DISTORTION_H

#include <CGAL/Surface_design/exceptions.h>

#include <CGAL/number_utils.h>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_design {
namespace internal {

/// The 2-D coordinates of every vertex from a readable vertex -> `Point_2` map.
/// \throws Invalid_parameter a coordinate is not finite
template <class Indices, class UVMap>
std::vector<Eigen::Vector2d> plane_coordinates(const Indices& idx, const UVMap& uv)
{
  std::vector<Eigen::Vector2d> p(idx.number_of_vertices());
  for(std::size_t v = 0; v < p.size(); ++v)
  {
    const auto& q = get(uv, idx.vertex(v));
    p[v] = Eigen::Vector2d(CGAL::to_double(q.x()), CGAL::to_double(q.y()));
    if(!p[v].allFinite())
      throw Invalid_parameter("uv", "the 2-D coordinates of vertex " + std::to_string(v) + " are not finite");
  }
  return p;
}

/// Singular values s1 >= s2 >= 0 and the sign of the determinant of the linear map sending
/// triangle (a, b, c) in space to (p, q, r) in the plane.
struct Face_singular_values
{
  double s1 = 0., s2 = 0.;
  double determinant = 0.; ///< s1 s2 with the sign of the orientation (< 0: flipped)
};

inline Face_singular_values face_singular_values(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                                 const Eigen::Vector3d& c, const Eigen::Vector2d& p,
                                                 const Eigen::Vector2d& q, const Eigen::Vector2d& r)
{
  // the triangle in its own orthonormal frame: a at 0, b on the first axis
  const Eigen::Vector3d e1 = b - a, e2 = c - a;
  const double l1 = e1.norm();
  const Eigen::Vector3d x = e1 / l1;
  const Eigen::Vector3d y = (x.cross(e2)).cross(x).normalized();
  Eigen::Matrix2d P, Q;
  P << l1, e2.dot(x), 0., e2.dot(y);
  Q.col(0) = q - p;
  Q.col(1) = r - p;
  const Eigen::Matrix2d J = Q * P.inverse();
  // closed form: J = [E+F, G-H; G+H, E-F] -> s = sqrt(E^2+H^2) +- sqrt(F^2+G^2)
  const double E = 0.5 * (J(0, 0) + J(1, 1)), F = 0.5 * (J(0, 0) - J(1, 1));
  const double G = 0.5 * (J(1, 0) + J(0, 1)), H = 0.5 * (J(1, 0) - J(0, 1));
  const double conformal = std::hypot(E, H), anticonformal = std::hypot(F, G);
  Face_singular_values s;
  s.s1 = conformal + anticonformal;
  s.s2 = std::abs(conformal - anticonformal);
  s.determinant = J.determinant();
  return s;
}

/// Whether closed segment [a, b] properly or improperly intersects [c, d].
inline bool segments_intersect(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c,
                               const Eigen::Vector2d& d)
{
  auto orient = [](const Eigen::Vector2d& p, const Eigen::Vector2d& q, const Eigen::Vector2d& r) {
    const double v = (q - p).x() * (r - p).y() - (q - p).y() * (r - p).x();
    return (v > 0.) - (v < 0.);
  };
  auto on_segment = [](const Eigen::Vector2d& p, const Eigen::Vector2d& q, const Eigen::Vector2d& r) {
    return (std::min)(p.x(), q.x()) <= r.x() && r.x() <= (std::max)(p.x(), q.x()) &&
           (std::min)(p.y(), q.y()) <= r.y() && r.y() <= (std::max)(p.y(), q.y());
  };
  const int o1 = orient(a, b, c), o2 = orient(a, b, d), o3 = orient(c, d, a), o4 = orient(c, d, b);
  if(o1 != o2 && o3 != o4 && o1 * o2 <= 0 && o3 * o4 <= 0)
    return o1 != 0 || o2 != 0 || o3 != 0 || o4 != 0 || on_segment(a, b, c);
  if(o1 == 0 && on_segment(a, b, c))
    return true;
  if(o2 == 0 && on_segment(a, b, d))
    return true;
  if(o3 == 0 && on_segment(c, d, a))
    return true;
  if(o4 == 0 && on_segment(c, d, b))
    return true;
  return false;
}

/// Calls `visit(i, k)` (i < k) for every pair of edges of the closed polygon `loop` (edge i from
/// loop[i] to loop[i + 1]) that intersect and do not share a vertex of the loop, until `visit`
/// returns false. Uniform grid of the mean edge length: about linear for boundaries of evenly
/// sized edges. A pair may be visited more than once (once per grid cell both edges cross).
template <class Visitor>
void for_each_polygon_self_intersection(const std::vector<Eigen::Vector2d>& loop, Visitor visit)
{
  const std::size_t n = loop.size();
  if(n < 4)
    return;
  double mean = 0.;
  Eigen::Vector2d lo = loop[0], hi = loop[0];
  for(std::size_t i = 0; i < n; ++i)
  {
    mean += (loop[(i + 1) % n] - loop[i]).norm();
    lo = lo.cwiseMin(loop[i]);
    hi = hi.cwiseMax(loop[i]);
  }
  mean /= double(n);
  const double cell = mean > 0. ? mean : 1.;
  std::unordered_map<long long, std::vector<std::size_t>> grid;
  auto key = [&](long long i, long long j) { return i * 2000003LL + j; };
  for(std::size_t i = 0; i < n; ++i)
  {
    const Eigen::Vector2d a = loop[i], b = loop[(i + 1) % n];
    const long long i0 = (long long)std::floor(((std::min)(a.x(), b.x()) - lo.x()) / cell);
    const long long i1 = (long long)std::floor(((std::max)(a.x(), b.x()) - lo.x()) / cell);
    const long long j0 = (long long)std::floor(((std::min)(a.y(), b.y()) - lo.y()) / cell);
    const long long j1 = (long long)std::floor(((std::max)(a.y(), b.y()) - lo.y()) / cell);
    for(long long x = i0; x <= i1; ++x)
      for(long long y = j0; y <= j1; ++y)
      {
        std::vector<std::size_t>& bucket = grid[key(x, y)];
        for(std::size_t k : bucket)
        {
          // edges sharing a loop vertex are adjacent
          if(k == i || (k + 1) % n == i || (i + 1) % n == k)
            continue;
          if(segments_intersect(a, b, loop[k], loop[(k + 1) % n]) && !visit((std::min)(i, k), (std::max)(i, k)))
            return;
        }
        bucket.push_back(i);
      }
  }
}

/// Whether the closed polygon `loop` (vertices in order) intersects itself, i.e. whether two of
/// its edges that do not share a vertex of the loop intersect.
inline bool polygon_self_intersects(const std::vector<Eigen::Vector2d>& loop)
{
  bool found = false;
  for_each_polygon_self_intersection(loop, [&](std::size_t, std::size_t) {
    found = true;
    return false;
  });
  return found;
}

} // namespace internal
} // namespace Surface_design
} // namespace CGAL

#endif // CGAL_SURFACE_DESIGN_INTERNAL_DEVELOPABILITY_DISTORTION_H
