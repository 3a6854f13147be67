// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The boundary's direction smoothed at a length: what a field that follows the boundary follows
// where the boundary zigzags at a scale finer than the field's features (a cut through a
// triangulation, a staircase), its corners kept where it turns within that length.

#ifndef CGAL_SURFACE_DESIGN_INTERNAL_CORE_BOUNDARY_SMOOTHING_H
#define CGAL_SURFACE_DESIGN_INTERNAL_CORE_BOUNDARY_SMOOTHING_H

#include <CGAL/Surface_design/internal/Core/angles.h>
#include <CGAL/Surface_design/internal/Core/geometry.h>
#include <CGAL/Surface_design/internal/Core/topology.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <numeric>
#include <vector>

namespace CGAL {
namespace Surface_design {
namespace internal {

/// The boundary's direction smoothed at length L (`smoothed_boundary()`).
struct Smoothed_boundary
{
  /// per vertex: the angle from the boundary edge leaving it (the surface on its left: the
  /// reference of a boundary vertex's frame, `Vertex_frames`) to the smoothed direction,
  /// counterclockwise; 0 inside, and everywhere when L = 0
  std::vector<double> offset;
  /// per edge: how much the smoothed direction turns along a boundary edge, from its first
  /// vertex to its second in the boundary's direction (the surface on the left), against the
  /// transport along the boundary; 0 inside
  std::vector<double> turning;
  std::vector<bool> corner; ///< per vertex: a corner kept
  std::size_t corners = 0;
};

/// Along each boundary loop (the surface on its left) the boundary turns at vertex v by tau_v =
/// pi - (the angle sum of v's faces): its direction, unwrapped, is Theta_e on edge e, the sum of
/// the turns since the loop's first edge. At each vertex, the turn at scale L is the difference
/// of the length-weighted means of Theta over the edges within arc length L after it and within
/// L before it. A *corner* is kept where that turn is 3 pi / 8 or more in magnitude (there a
/// cross field turns by 22.5 degrees at most where it takes the boundary's turn as a quarter
/// turn), at a vertex that turns the same way itself, corners at least L apart (the largest
/// turns first, then the sharper vertex). Between corners (over the whole loop without any) the
/// smoothed direction at a vertex is the length-weighted mean of Theta over the edges of its
/// piece whose midpoints lie within L / 2 of it: a zigzag of period below L is straightened, a
/// turn of the piece spread over L. At a corner the direction is that of the piece that starts
/// there.
template <class Indices, class VertexPointMap>
Smoothed_boundary smoothed_boundary(const Indices& idx, const VertexPointMap& vpm, const Boundary_loops& loops,
                                    double length)
{
  const auto& tm = idx.mesh();
  Smoothed_boundary out;
  out.offset.assign(idx.number_of_vertices(), 0.);
  out.turning.assign(idx.number_of_edges(), 0.);
  out.corner.assign(idx.number_of_vertices(), false);
  if(loops.size() == 0)
    return out;
  const std::vector<double> angle_sum = vertex_angle_sums(idx, corner_angles(idx, vpm));
  const double half = 0.5 * length;
  for(const auto& loop : loops.loops)
  {
    // surface on the left: vertex k is the target of border halfedge m - 1 - k, edge k runs from
    // vertex k to vertex k + 1 (the opposite of that border halfedge)
    const std::size_t m = loop.size();
    std::vector<std::size_t> vertex(m), edge(m);
    std::vector<double> len(m), tau(m);
    for(std::size_t k = 0; k < m; ++k)
    {
      const auto h = idx.halfedge(loop[m - 1 - k]);
      vertex[k] = idx.target_index(h);
      edge[k] = idx.edge_index(h);
      len[k] = (position(vpm, target(h, tm)) - position(vpm, source(h, tm))).norm();
      tau[k] = pi - angle_sum[vertex[k]];
    }
    const double perimeter = std::accumulate(len.begin(), len.end(), 0.);
    const double total_turn = std::accumulate(tau.begin(), tau.end(), 0.);
    if(!(length > 0.))
    {
      for(std::size_t k = 0; k < m; ++k)
        out.turning[edge[k]] = tau[(k + 1) % m];
      continue;
    }
    // three copies of the loop, the middle one [m, 2m) the loop itself: arc positions of the
    // vertices and of the edges' midpoints, the edges' directions (Theta, periodic up to the
    // total turn), prefix sums
    const std::size_t M = 3 * m;
    std::vector<double> s(M), mid(M), theta(M);
    std::vector<double> sum_len(M + 1, 0.), sum_len_theta(M + 1, 0.);
    {
      std::vector<double> s0(m, 0.), theta0(m, 0.);
      for(std::size_t k = 1; k < m; ++k)
      {
        s0[k] = s0[k - 1] + len[k - 1];
        theta0[k] = theta0[k - 1] + tau[k];
      }
      for(std::size_t j = 0; j < M; ++j)
      {
        const std::size_t k = j % m;
        const double copy = double(j / m) - 1.;
        s[j] = s0[k] + copy * perimeter;
        mid[j] = s[j] + 0.5 * len[k];
        theta[j] = theta0[k] + copy * total_turn;
        sum_len[j + 1] = sum_len[j] + len[k];
        sum_len_theta[j + 1] = sum_len_theta[j] + len[k] * theta[j];
      }
    }
    // [lo, hi) of the positions `at` within `half` of x, at most m of them around `centre`
    auto window = [&](const std::vector<double>& at, double x, std::size_t centre) {
      std::size_t lo = std::size_t(std::lower_bound(at.begin(), at.end(), x - half) - at.begin());
      std::size_t hi = std::size_t(std::upper_bound(at.begin(), at.end(), x + half) - at.begin());
      lo = (std::max)(lo, centre - m / 2);
      hi = (std::min)(hi, lo + m);
      return std::make_pair(lo, (std::max)(lo, hi));
    };
    // the corners: the turn at each vertex between the mean directions of the edges within L
    // before it and within L after it (at least the edge on either side, at most half the loop)
    auto mean_theta = [&](std::size_t lo, std::size_t hi) {
      return (sum_len_theta[hi] - sum_len_theta[lo]) / (sum_len[hi] - sum_len[lo]);
    };
    std::vector<double> windowed(m);
    for(std::size_t k = 0; k < m; ++k)
    {
      const std::size_t c = m + k; // edge c leaves the vertex, edge c - 1 arrives at it
      const std::size_t before =
        std::size_t(std::lower_bound(mid.begin(), mid.end(), s[c] - length) - mid.begin());
      const std::size_t after =
        std::size_t(std::upper_bound(mid.begin(), mid.end(), s[c] + length) - mid.begin());
      const std::size_t lo = (std::min)(c - 1, (std::max)(before, c - (std::max)(m / 2, std::size_t(1))));
      const std::size_t hi = (std::max)(c + 1, (std::min)(after, c + (std::max)(m / 2, std::size_t(1))));
      windowed[k] = mean_theta(c, hi) - mean_theta(lo, c);
    }
    std::vector<std::size_t> order(m);
    std::iota(order.begin(), order.end(), std::size_t(0));
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
      if(std::abs(windowed[a]) != std::abs(windowed[b]))
        return std::abs(windowed[a]) > std::abs(windowed[b]);
      return std::abs(tau[a]) > std::abs(tau[b]);
    });
    std::vector<std::size_t> corners;
    auto arc_distance = [&](std::size_t a, std::size_t b) {
      const double d = std::abs(s[m + a] - s[m + b]);
      return (std::min)(d, perimeter - d);
    };
    for(std::size_t k : order)
    {
      if(std::abs(windowed[k]) < 3. * pi / 8.)
        break;
      if(!(tau[k] * windowed[k] > 0.))
        continue;
      bool apart = true;
      for(std::size_t c : corners)
        apart = apart && arc_distance(k, c) >= length;
      if(apart)
        corners.push_back(k);
    }
    std::sort(corners.begin(), corners.end());
    for(std::size_t c : corners)
      out.corner[vertex[c]] = true;
    out.corners += corners.size();
    // the smoothed direction at each vertex, over the piece of its edge
    for(std::size_t k = 0; k < m; ++k)
    {
      auto [lo, hi] = window(mid, s[m + k], m + k);
      if(!corners.empty())
      {
        // the piece [previous corner, next corner) of edge k, in the middle copy's numbering
        const auto next = std::upper_bound(corners.begin(), corners.end(), k);
        const std::size_t first = next == corners.begin() ? corners.back() : *(next - 1) + m;
        const std::size_t last = next == corners.end() ? corners.front() + 2 * m : *next + m;
        lo = (std::max)(lo, first);
        hi = (std::min)(hi, last);
      }
      out.offset[vertex[k]] = (hi > lo ? mean_theta(lo, hi) : theta[m + k]) - theta[m + k];
    }
    // the smoothed direction's turn along edge k (vertex k to k + 1), relative to the transport
    // along it, which turns by -tau there
    for(std::size_t k = 0; k < m; ++k)
    {
      const std::size_t next = (k + 1) % m;
      out.turning[edge[k]] = tau[next] + out.offset[vertex[next]] - out.offset[vertex[k]];
    }
  }
  return out;
}

} // namespace internal
} // namespace Surface_design
} // namespace CGAL

#endif // CGAL_SURFACE_DESIGN_INTERNAL_CORE_BOUNDARY_SMOOTHING_H
