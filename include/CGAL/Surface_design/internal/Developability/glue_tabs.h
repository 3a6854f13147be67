// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Glue tabs for a paper pattern: a strip along one side of a seam, outside its piece, that is
// folded under and glued to the other side. The outline of a tab, and the test that it overlaps
// no piece and no tab placed before it.

#ifndef CGAL_SURFACE_DESIGN_INTERNAL_DEVELOPABILITY_GLUE_TABS_H
#define CGAL_SURFACE_DESIGN_INTERNAL_DEVELOPABILITY_GLUE_TABS_H

#include <CGAL/Surface_design/internal/Developability/distortion.h>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Surface_design {
namespace internal {

/// Whether x lies strictly inside the closed polygon (even-odd rule; on the boundary: either).
inline bool inside_polygon(const std::vector<Eigen::Vector2d>& polygon, const Eigen::Vector2d& x)
{
  bool in = false;
  for(std::size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++)
  {
    const Eigen::Vector2d& a = polygon[i];
    const Eigen::Vector2d& b = polygon[j];
    if((a.y() > x.y()) != (b.y() > x.y()) && x.x() < (b.x() - a.x()) * (x.y() - a.y()) / (b.y() - a.y()) + a.x())
      in = !in;
  }
  return in;
}

/// A glue tab on the base polyline p_0 .. p_m (a side of a seam, in the order of its piece's
/// boundary: the piece on the left, y up): the outer points q_0 .. q_m at `width` outside, along
/// the vertex normals (the mean of the two edges' outward normals: no mitre, so that no outer
/// point is farther than `width` from its base point), the ends pulled in along the base by
/// `width` (or a third of the base's length, if shorter) so that the tab tapers at 45 degrees.
/// The tab is the polygon p_0 .. p_m, q_m .. q_0.
inline std::vector<Eigen::Vector2d> glue_tab_outer(const std::vector<Eigen::Vector2d>& p, double width)
{
  const std::size_t m = p.size() - 1;
  std::vector<Eigen::Vector2d> normal(m), q(m + 1);
  double length = 0.;
  for(std::size_t i = 0; i < m; ++i)
  {
    const Eigen::Vector2d t = (p[i + 1] - p[i]).normalized();
    normal[i] = Eigen::Vector2d(t.y(), -t.x()); // right of the walk: outside the piece
    length += (p[i + 1] - p[i]).norm();
  }
  for(std::size_t i = 0; i <= m; ++i)
  {
    Eigen::Vector2d n = i == 0 ? normal[0] : i == m ? normal[m - 1] : normal[i - 1] + normal[i];
    const double c = n.norm();
    n = c > 0. ? Eigen::Vector2d(n / c) : normal[(std::min)(i, m - 1)];
    q[i] = p[i] + width * n;
  }
  const double taper = (std::min)(width, length / 3.);
  q[0] += taper * (p[1] - p[0]).normalized();
  q[m] -= taper * (p[m] - p[m - 1]).normalized();
  return q;
}

/// The segments of a tab that are cut (not its base): p_0 -> q_0, q_0 -> ... -> q_m, q_m -> p_m,
/// the two ends started a hair away from the base so that they do not touch it.
inline std::vector<std::pair<Eigen::Vector2d, Eigen::Vector2d>>
glue_tab_cut_segments(const std::vector<Eigen::Vector2d>& p, const std::vector<Eigen::Vector2d>& q)
{
  const std::size_t m = p.size() - 1;
  std::vector<std::pair<Eigen::Vector2d, Eigen::Vector2d>> s;
  s.emplace_back(p[0] + 1e-6 * (q[0] - p[0]), q[0]);
  for(std::size_t i = 0; i < m; ++i)
    s.emplace_back(q[i], q[i + 1]);
  s.emplace_back(q[m], p[m] + 1e-6 * (q[m] - p[m]));
  return s;
}

/// Whether a tab (base p, outer q) is a simple polygon that meets no piece boundary segment
/// (`pieces`: closed boundary polygons) except along its base, contains no piece vertex and has
/// no outer point on a piece (a piece that overlaps itself may cover it), and meets no tab of
/// `placed` (each a polygon p .. q reversed) nor contains one or lies in one.
inline bool glue_tab_fits(const std::vector<Eigen::Vector2d>& p, const std::vector<Eigen::Vector2d>& q,
                          const std::vector<std::vector<Eigen::Vector2d>>& pieces,
                          const std::vector<std::vector<Eigen::Vector2d>>& placed)
{
  const std::size_t m = p.size() - 1;
  std::vector<Eigen::Vector2d> polygon(p);
  polygon.insert(polygon.end(), q.rbegin(), q.rend());
  Eigen::Vector2d lo = polygon[0], hi = polygon[0];
  for(const Eigen::Vector2d& x : polygon)
  {
    lo = lo.cwiseMin(x);
    hi = hi.cwiseMax(x);
  }
  auto near = [&](const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    return (std::max)(a.x(), b.x()) >= lo.x() && (std::min)(a.x(), b.x()) <= hi.x() &&
           (std::max)(a.y(), b.y()) >= lo.y() && (std::min)(a.y(), b.y()) <= hi.y();
  };
  const auto cut = glue_tab_cut_segments(p, q);
  // simple: the cut segments meet neither each other (but neighbours) nor the base
  for(std::size_t i = 0; i < cut.size(); ++i)
  {
    for(std::size_t j = i + 2; j < cut.size(); ++j)
      if(segments_intersect(cut[i].first, cut[i].second, cut[j].first, cut[j].second))
        return false;
    for(std::size_t k = 0; k < m; ++k)
      if(segments_intersect(cut[i].first, cut[i].second, p[k], p[k + 1]))
        return false;
  }
  auto is_base = [&](const Eigen::Vector2d& x) { return std::find(p.begin(), p.end(), x) != p.end(); };
  // a closed polygon (a piece's outline, a tab placed before) against this tab: one of its
  // vertices inside the tab, or one of its edges meeting a cut segment of the tab (the base, and
  // chords of it, excepted when `skip_base`)
  auto meets = [&](const std::vector<Eigen::Vector2d>& other, bool skip_base) {
    for(std::size_t i = 0; i < other.size(); ++i)
    {
      const Eigen::Vector2d& a = other[i];
      const Eigen::Vector2d& b = other[(i + 1) % other.size()];
      if(!near(a, b))
        continue;
      if(!is_base(a) && inside_polygon(polygon, a))
        return true;
      if(skip_base && is_base(a) && is_base(b))
        continue;
      for(const auto& s : cut)
        if(segments_intersect(s.first, s.second, a, b))
          return true;
    }
    return false;
  };
  for(const auto& piece : pieces)
  {
    // a tab lying on a piece without meeting its boundary (on a piece that overlaps itself)
    Eigen::Vector2d piece_lo = piece[0], piece_hi = piece[0];
    for(const Eigen::Vector2d& x : piece)
    {
      piece_lo = piece_lo.cwiseMin(x);
      piece_hi = piece_hi.cwiseMax(x);
    }
    if(near(piece_lo, piece_hi))
      for(const Eigen::Vector2d& x : q)
        if(inside_polygon(piece, x))
          return false;
    if(meets(piece, true))
      return false;
  }
  for(const auto& other : placed)
    if(meets(other, false) || inside_polygon(other, 0.5 * (q[m / 2] + p[m / 2])))
      return false;
  return true;
}

} // namespace internal
} // namespace Surface_design
} // namespace CGAL

#endif // CGAL_SURFACE_DESIGN_INTERNAL_DEVELOPABILITY_GLUE_TABS_H
