// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The isolines of a stripe pattern at the levels 0 and pi (mod 2 pi) as polylines on the surface.
// Each face is cut into small triangles on which the stripe angle is linear (the face itself when
// it is regular without singularity, three triangles around the branch point in a branch face, a
// grid in a face with a stripe singularity), each small triangle is cut by marching triangles,
// and the pieces are chained into polylines through the points they share. A point on a mesh edge
// is found by its position along the edge, so that the two faces of the edge give the same point
// even when the stripe families or the signs of the angles differ between them (line and cross
// fields): the levels {0, pi} + 2 pi Z are the same for every sheet.

#ifndef CGAL_SURFACE_DESIGN_INTERNAL_FIELD_ALIGNED_PARAMETERIZATION_STRIPE_ISOLINES_H
#define CGAL_SURFACE_DESIGN_INTERNAL_FIELD_ALIGNED_PARAMETERIZATION_STRIPE_ISOLINES_H

#include <CGAL/Surface_design/exceptions.h>
#include <CGAL/Surface_design/internal/Core/angles.h>
#include <CGAL/Surface_design/internal/Field_aligned_parameterization/stripe_interpolation.h>

#include <CGAL/boost/graph/iterator.h>
#include <CGAL/number_utils.h>

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <map>
#include <set>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_design {
namespace internal {

/// One polyline: points on the surface, closed when it returns to its start (the first point is
/// then not repeated), at level 0 or pi, first met in a face of stripe family `family`; faces[i]
/// is the face of the piece from points[i] to the next point.
struct Stripe_isoline_polyline
{
  std::vector<Eigen::Vector3d> points;
  std::vector<std::size_t> faces;
  bool closed = false;
  double level = 0.;
  int family = 0;
  std::vector<std::size_t> crossings; ///< the points it shares with lines crossing it there (at a mesh vertex or on an edge)
};

/// A point of a face's subdivision, by barycentric coordinates, with the stripe angle there.
struct Stripe_isoline_sample
{
  std::array<double, 3> b;
  double value;
  std::size_t local; // its number within the face's subdivision
};

/// Collects the pieces face by face and chains them.
class Stripe_isoline_builder
{
public:
  /// The face being cut: its corners' mesh vertices and positions, and for corner k the mesh edge
  /// opposite it with the corner at that edge's first end (orientation).
  struct Face
  {
    std::size_t index;
    std::array<std::size_t, 3> vertex;
    std::array<Eigen::Vector3d, 3> position;
    std::array<std::size_t, 3> opposite_edge;
    std::array<int, 3> edge_first_corner; // the corner at the start of opposite_edge[k]
  };

  /// `level_zero_only`: the lines at level pi are not cut (the quad extraction reads level 0 alone)
  Stripe_isoline_builder(std::size_t number_of_vertices, std::size_t number_of_edges, double value_tolerance = 1e-9,
                         bool level_zero_only = false)
    : m_vertex_point(number_of_vertices, none), m_edge_points(number_of_edges), m_tolerance(value_tolerance),
      m_level_classes(level_zero_only ? 1 : 2)
  {}

  /// The mesh vertices on a boundary that lies on level lines (`on[v]`): the pieces of level
  /// lines running from one such vertex to another (along a boundary edge, or a chord between two
  /// boundary vertices) are not cut, the caller adding the boundary loops itself (the quad
  /// extraction); lines crossing the boundary still end on it.
  void set_boundary_vertices(std::vector<bool> on) { m_boundary_vertex = std::move(on); }

  /// Cuts one small triangle of face `face` (stripe family `family`) whose angle is linear
  /// between the samples, at every level 0 + 2 pi m and pi + 2 pi m it reaches. `unwrap`: the
  /// samples' values are known only up to multiples of 2 pi (samples of a face with a winding
  /// term, closer than half a stripe): each is first moved within pi of the first.
  void add_triangle(const Face& face, int family, std::array<Stripe_isoline_sample, 3> s, bool unwrap = false)
  {
    if(unwrap)
      for(int i = 1; i < 3; ++i)
        s[std::size_t(i)].value = s[0].value + wrapped(s[std::size_t(i)].value - s[0].value);
    double lo = s[0].value, hi = s[0].value;
    for(const auto& x : s)
      lo = (std::min)(lo, x.value), hi = (std::max)(hi, x.value);
    for(int c = 0; c < m_level_classes; ++c)
    {
      const double base = c * pi;
      const double m0 = std::ceil((lo - m_tolerance - base) / two_pi), m1 = std::floor((hi + m_tolerance - base) / two_pi);
      for(double m = m0; m <= m1; m += 1.)
        cut(face, family, c, s, base + two_pi * m);
    }
  }

  /// The polylines of all pieces added so far.
  std::vector<Stripe_isoline_polyline> polylines() const
  {
    // (a copy only where a segment runs along a mesh edge: an exact grid's lines)
    std::vector<Segment> split;
    const bool along_edges =
      std::any_of(m_segments.begin(), m_segments.end(), [](const Segment& s) { return s.edge != none; });
    if(along_edges)
      split = split_along_edges();
    const std::vector<Segment>& segments = along_edges ? split : m_segments;
    // the segments at each point, in one array (point p's in [first[p], first[p + 1]))
    std::vector<std::size_t> first(m_points.size() + 1, 0), at_point(2 * segments.size());
    for(const Segment& s : segments)
      ++first[s.a + 1], ++first[s.b + 1];
    for(std::size_t p = 0; p < m_points.size(); ++p)
      first[p + 1] += first[p];
    {
      std::vector<std::size_t> fill(first.begin(), first.end() - 1);
      for(std::size_t s = 0; s < segments.size(); ++s)
        at_point[fill[segments[s].a]++] = s, at_point[fill[segments[s].b]++] = s;
    }
    auto degree = [&](std::size_t p) { return first[p + 1] - first[p]; };
    auto other_end = [&](std::size_t s, std::size_t p) { return segments[s].a == p ? segments[s].b : segments[s].a; };
    // Where lines cross exactly at a mesh vertex or on a mesh edge (a grid whose lines run through
    // its vertices), they share that point: there each segment continues with the one most
    // nearly opposite it (of its level), so that each line runs through the crossing, which the
    // quad extraction then finds at the point the lines share. Elsewhere a point where other than
    // two segments meet ends them all (a branch point).
    std::vector<std::size_t> partner(at_point.size(), none);
    for(std::size_t p = 0; p < m_points.size(); ++p)
    {
      const bool on_mesh = (p < m_point_vertex.size() && m_point_vertex[p] != none) ||
                           (p < m_edge_point.size() && m_edge_point[p]);
      if(degree(p) < 4 || degree(p) % 2 != 0 || !on_mesh || on_boundary(p))
        continue; // (at the boundary the lines end: see set_boundary_vertices())
      std::vector<Eigen::Vector3d> direction;
      for(std::size_t k = first[p]; k < first[p + 1]; ++k)
        direction.push_back((m_points[other_end(at_point[k], p)] - m_points[p]).normalized());
      for(;;)
      {
        std::size_t best_i = none, best_j = none;
        double best = 0.; // pairs of segments at an obtuse angle only
        for(std::size_t i = 0; i < direction.size(); ++i)
          for(std::size_t j = i + 1; j < direction.size(); ++j)
          {
            const std::size_t ki = first[p] + i, kj = first[p] + j;
            if(partner[ki] != none || partner[kj] != none ||
               segments[at_point[ki]].level != segments[at_point[kj]].level)
              continue;
            if(const double d = direction[i].dot(direction[j]); d < best)
              best = d, best_i = i, best_j = j;
          }
        if(best_i == none)
          break;
        partner[first[p] + best_i] = at_point[first[p] + best_j];
        partner[first[p] + best_j] = at_point[first[p] + best_i];
      }
    }
    // the segment that continues the line of segment s at its end p (none: the line ends there)
    auto continuation = [&](std::size_t s, std::size_t p) {
      if(degree(p) == 2)
        return at_point[first[p]] == s ? at_point[first[p] + 1] : at_point[first[p]];
      for(std::size_t k = first[p]; k < first[p + 1]; ++k)
        if(at_point[k] == s)
          return partner[k];
      return none;
    };
    std::vector<bool> used(segments.size(), false);
    std::vector<Stripe_isoline_polyline> result;
    auto walk = [&](std::size_t start, std::size_t first_segment) {
      Stripe_isoline_polyline line;
      line.level = segments[first_segment].level == 0 ? 0. : pi;
      line.family = segments[first_segment].family;
      line.points.push_back(m_points[start]);
      std::size_t at = start, segment = first_segment;
      for(;;)
      {
        used[segment] = true;
        line.faces.push_back(segments[segment].face);
        const std::size_t next = other_end(segment, at);
        const std::size_t then = continuation(segment, next);
        if(next == start && then == first_segment)
        {
          line.closed = true;
          if(degree(start) != 2)
            line.crossings.push_back(0);
          break;
        }
        // (back at the point where it started, where other lines end too, a branch point on the
        // lattice: an open line with both ends there, not a loop)
        line.points.push_back(m_points[next]);
        if(then == none || used[then])
          break;
        if(degree(next) != 2)
          line.crossings.push_back(line.points.size() - 1);
        at = next;
        segment = then;
      }
      result.push_back(std::move(line));
    };
    // open chains start at the points where they end or branch, then the remaining loops
    for(std::size_t p = 0; p < m_points.size(); ++p)
      for(std::size_t k = first[p]; k < first[p + 1]; ++k)
        if(!used[at_point[k]] && continuation(at_point[k], p) == none)
          walk(p, at_point[k]);
    for(std::size_t s = 0; s < segments.size(); ++s)
      if(!used[s])
        walk(segments[s].a, s);
    return result;
  }

  std::size_t number_of_segments() const { return m_segments.size(); }

private:
  static constexpr std::size_t none = std::numeric_limits<std::size_t>::max();

  struct Carrier_point
  {
    double t;
    int level_class;
    std::size_t id;
  };

  struct Segment
  {
    std::size_t a, b;
    int level, family;
    std::size_t face;
    std::size_t edge = none; // the mesh edge it runs along, from a to b (a_first) or back
    bool a_first = true;
  };

  // The segments, those along a mesh edge cut at the points where other lines of their level
  // cross that edge: the lines cross there.
  std::vector<Segment> split_along_edges() const
  {
    std::vector<Segment> segments = m_segments;
    for(std::size_t s = 0, count = segments.size(); s < count; ++s)
    {
      if(segments[s].edge == none)
        continue;
      std::vector<std::pair<double, std::size_t>> inside;
      for(const Carrier_point& c : m_edge_points[segments[s].edge])
        if(c.level_class == segments[s].level)
          inside.emplace_back(c.t, c.id);
      std::sort(inside.begin(), inside.end());
      inside.erase(std::unique(inside.begin(), inside.end(),
                               [](const auto& x, const auto& y) { return x.second == y.second; }),
                   inside.end());
      if(inside.empty())
        continue;
      const Segment whole = segments[s];
      std::size_t from = whole.a_first ? whole.a : whole.b;
      const std::size_t to = whole.a_first ? whole.b : whole.a;
      segments[s].a = from;
      segments[s].b = inside.front().second;
      for(std::size_t i = 0; i < inside.size(); ++i)
      {
        from = inside[i].second;
        Segment piece = whole;
        piece.a = from;
        piece.b = i + 1 < inside.size() ? inside[i + 1].second : to;
        segments.push_back(piece);
      }
    }
    return segments;
  }

  static double wrapped(double x) { return x - two_pi * std::round(x / two_pi); }

  int sign(double value, double level) const
  {
    return value > level + m_tolerance ? 1 : (value < level - m_tolerance ? -1 : 0);
  }

  void cut(const Face& face, int family, int level_class, const std::array<Stripe_isoline_sample, 3>& s, double level)
  {
    m_class = level_class;
    std::array<int, 3> sg;
    int zeros = 0;
    for(int i = 0; i < 3; ++i)
      zeros += (sg[std::size_t(i)] = sign(s[std::size_t(i)].value, level)) == 0;
    std::size_t a = none, b = none;
    if(zeros == 3)
      return; // constant at the level: no line
    if(zeros == 2)
    {
      // the edge between the two corners at the level (met again from the face on its other side)
      const int k = sg[0] != 0 ? 0 : (sg[1] != 0 ? 1 : 2);
      a = sample_point(face, s[std::size_t((k + 1) % 3)]);
      b = sample_point(face, s[std::size_t((k + 2) % 3)]);
    }
    else if(zeros == 1)
    {
      const int z = sg[0] == 0 ? 0 : (sg[1] == 0 ? 1 : 2);
      const int i = (z + 1) % 3, j = (z + 2) % 3;
      if(sg[std::size_t(i)] * sg[std::size_t(j)] > 0)
        return; // touches the level at one corner
      a = sample_point(face, s[std::size_t(z)]);
      b = crossing(face, s[std::size_t(i)], s[std::size_t(j)], level);
    }
    else
    {
      if(sg[0] == sg[1] && sg[1] == sg[2])
        return;
      const int odd = sg[0] == sg[1] ? 2 : (sg[0] == sg[2] ? 1 : 0);
      a = crossing(face, s[std::size_t(odd)], s[std::size_t((odd + 1) % 3)], level);
      b = crossing(face, s[std::size_t(odd)], s[std::size_t((odd + 2) % 3)], level);
    }
    if(a == b)
      return;
    if(zeros == 2 && on_boundary(a) && on_boundary(b))
      return; // along the boundary (see set_boundary_vertices())
    // a segment between two corners at the level (a mesh edge, or an edge between two small
    // triangles) is met again from the other side: kept once
    if(zeros == 2 && !m_segment_keys.insert(std::make_pair((std::min)(a, b), (std::max)(a, b))).second)
      return;
    Segment segment{a, b, level_class, family, face.index};
    if(zeros == 2)
    {
      // along the mesh edge opposite corner k when both ends are on it
      const int k = sg[0] != 0 ? 0 : (sg[1] != 0 ? 1 : 2);
      const auto& p = s[std::size_t((k + 1) % 3)];
      const auto& q = s[std::size_t((k + 2) % 3)];
      if(p.b[std::size_t(k)] == 0. && q.b[std::size_t(k)] == 0. && a < m_point_vertex.size() &&
         m_point_vertex[a] != none)
      {
        segment.edge = face.opposite_edge[std::size_t(k)];
        segment.a_first = m_point_vertex[a] == face.vertex[std::size_t(face.edge_first_corner[std::size_t(k)])];
      }
    }
    m_segments.push_back(segment);
  }

  bool on_boundary(std::size_t point) const
  {
    return point < m_point_vertex.size() && m_point_vertex[point] != none && !m_boundary_vertex.empty() &&
           m_boundary_vertex[m_point_vertex[point]];
  }

  Eigen::Vector3d position(const Face& face, const std::array<double, 3>& b) const
  {
    return b[0] * face.position[0] + b[1] * face.position[1] + b[2] * face.position[2];
  }

  // the point at barycentric b on the segment between samples p and q (s in [0, 1] from p)
  std::size_t point_between(const Face& face, const Stripe_isoline_sample& p, const Stripe_isoline_sample& q, double s)
  {
    std::array<double, 3> b;
    for(int i = 0; i < 3; ++i)
      b[std::size_t(i)] = (1. - s) * p.b[std::size_t(i)] + s * q.b[std::size_t(i)];
    for(int k = 0; k < 3; ++k)
      if(p.b[std::size_t(k)] == 0. && q.b[std::size_t(k)] == 0.)
        return edge_point(face, k, b);
    // inside the face: on the segment between two of its samples
    const bool swap = p.local > q.local;
    const auto key = std::make_tuple(face.index, swap ? q.local : p.local, swap ? p.local : q.local);
    return find_or_add(m_local_points[key], swap ? 1. - s : s, position(face, b));
  }

  std::size_t crossing(const Face& face, const Stripe_isoline_sample& p, const Stripe_isoline_sample& q, double level)
  {
    const double s = (level - p.value) / (q.value - p.value);
    return point_between(face, p, q, (std::min)(1., (std::max)(0., s)));
  }

  std::size_t sample_point(const Face& face, const Stripe_isoline_sample& p)
  {
    int zeros = 0, nonzero = 0;
    for(int k = 0; k < 3; ++k)
      p.b[std::size_t(k)] == 0. ? ++zeros : (nonzero = k);
    if(zeros == 2)
    {
      std::size_t& id = m_vertex_point[face.vertex[std::size_t(nonzero)]];
      if(id == none)
      {
        id = m_points.size();
        m_points.push_back(face.position[std::size_t(nonzero)]);
        m_point_vertex.resize(m_points.size(), none);
        m_point_vertex[id] = face.vertex[std::size_t(nonzero)];
      }
      return id;
    }
    for(int k = 0; k < 3; ++k)
      if(p.b[std::size_t(k)] == 0.)
        return edge_point(face, k, p.b);
    const auto key = std::make_pair(face.index, p.local);
    const auto it = m_sample_points.find(key);
    if(it != m_sample_points.end())
      return it->second;
    m_sample_points.emplace(key, m_points.size());
    m_points.push_back(position(face, p.b));
    return m_points.size() - 1;
  }

  // the point at barycentric b on the mesh edge opposite corner k, found by its position along
  // the edge from the edge's first end
  std::size_t edge_point(const Face& face, int k, const std::array<double, 3>& b)
  {
    const int first = face.edge_first_corner[std::size_t(k)];
    const int second = 3 - k - first;
    const double t = b[std::size_t(second)] / (b[std::size_t(first)] + b[std::size_t(second)]);
    if(t <= 0. || t >= 1.)
      return sample_point(face, Stripe_isoline_sample{corner(t <= 0. ? first : second), 0., 0});
    const Eigen::Vector3d x = (1. - t) * face.position[std::size_t(first)] + t * face.position[std::size_t(second)];
    const std::size_t id = find_or_add(m_edge_points[face.opposite_edge[std::size_t(k)]], t, x);
    if(m_edge_point.size() <= id)
      m_edge_point.resize(id + 1, false);
    m_edge_point[id] = true;
    return id;
  }

  static std::array<double, 3> corner(int i)
  {
    std::array<double, 3> b{0., 0., 0.};
    b[std::size_t(i)] = 1.;
    return b;
  }

  // the point at t on a segment (a mesh edge or a segment inside a face), of the current level
  // class: a crossing of level 0 and one of level pi are never merged (the class is kept across
  // sheets and families: the angles change by x -> +-x + 2 pi k)
  std::size_t find_or_add(std::vector<Carrier_point>& on_carrier, double t, const Eigen::Vector3d& x)
  {
    for(const Carrier_point& c : on_carrier)
      if(c.level_class == m_class && std::abs(c.t - t) < 1e-9)
        return c.id;
    on_carrier.push_back({t, m_class, m_points.size()});
    m_points.push_back(x);
    return m_points.size() - 1;
  }

  std::vector<Eigen::Vector3d> m_points;
  std::vector<std::size_t> m_vertex_point;
  std::vector<std::size_t> m_point_vertex; // the mesh vertex a point is at, none elsewhere (may be short)
  std::vector<bool> m_boundary_vertex;     // see set_boundary_vertices()
  std::vector<bool> m_edge_point;          // whether a point is on a mesh edge (may be short)
  std::vector<std::vector<Carrier_point>> m_edge_points;
  std::map<std::tuple<std::size_t, std::size_t, std::size_t>, std::vector<Carrier_point>> m_local_points;
  int m_class = 0; // the level class being cut: 0 or 1 (pi)
  std::map<std::pair<std::size_t, std::size_t>, std::size_t> m_sample_points;
  std::vector<Segment> m_segments;
  std::set<std::pair<std::size_t, std::size_t>> m_segment_keys; // of the segments between two corners
  double m_tolerance;
  int m_level_classes;
};

/// One isoline of a stripe pattern, as the public classes return it: a polyline on the surface
/// (closed when it returns to its first point, which is then not repeated); faces[i] is the face
/// crossed from points[i] to the next point; level 0 or pi (the angle along the line, modulo
/// 2 pi); the stripe family of the face where the line starts (the families of a cross field are
/// exchanged across some edges, and a line follows its family across).
template <class Point_3, class FaceDescriptor>
struct Stripe_isoline
{
  std::vector<Point_3> points;
  std::vector<FaceDescriptor> faces;
  bool closed = false;
  double level = 0.;
  int family = 0;
};

/// \throws Invalid_parameter unless 1 <= n <= 64 (the grid of a face with a stripe singularity)
inline void check_isoline_subdivision(int n)
{
  if(n < 1 || n > 64)
    throw Invalid_parameter("singular_face_subdivision", "must lie in [1, 64], got " + std::to_string(n));
}

/// Face f of the mesh as the builder sees it, corners in the order source(h), target(h),
/// target(next(h)) for h = halfedge(f).
template <class Indices, class VertexPointMap>
Stripe_isoline_builder::Face stripe_isoline_face(const Indices& idx, const VertexPointMap& vpm, std::size_t f)
{
  const auto& tm = idx.mesh();
  Stripe_isoline_builder::Face face;
  face.index = f;
  const auto h = halfedge(idx.face(f), tm);
  const std::array<decltype(h), 3> opposite{next(h, tm), next(next(h, tm), tm), h};
  const std::array<decltype(source(h, tm)), 3> corner{source(h, tm), target(h, tm), target(next(h, tm), tm)};
  for(int k = 0; k < 3; ++k)
  {
    face.vertex[std::size_t(k)] = idx.index(corner[std::size_t(k)]);
    const auto p = get(vpm, corner[std::size_t(k)]);
    face.position[std::size_t(k)] = Eigen::Vector3d(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
    const auto g = opposite[std::size_t(k)]; // from corner k + 1 to corner k + 2
    face.edge_first_corner[std::size_t(k)] = idx.orientation_sign(g) > 0 ? (k + 1) % 3 : (k + 2) % 3;
    face.opposite_edge[std::size_t(k)] = idx.edge_index(g);
  }
  return face;
}

/// A regular face: linear between the corner values c (unwrapped along its first two edges)
/// without singularity; with stripe index k != 0, the interpolation of `regular_face_value()`
/// sampled on a grid of n^2 triangles.
inline void add_regular_face_isolines(Stripe_isoline_builder& builder, const Stripe_isoline_builder::Face& face,
                                      int family, const std::array<double, 3>& c, int k, int n)
{
  using Sample = Stripe_isoline_sample;
  if(k == 0)
  {
    builder.add_triangle(face, family, {Sample{{1., 0., 0.}, c[0], 0}, Sample{{0., 1., 0.}, c[1], 1},
                                        Sample{{0., 0., 1.}, c[2], 2}});
    return;
  }
  auto sample = [&](int i, int j) { // at b = (i, j, n - i - j) / n
    const std::array<double, 3> b{double(i) / n, double(j) / n, double(n - i - j) / n};
    return Sample{b, regular_face_value(c, k, b), std::size_t(i * (n + 1) + j)};
  };
  for(int i = 0; i < n; ++i)
    for(int j = 0; i + j < n; ++j)
    {
      builder.add_triangle(face, family, {sample(i, j), sample(i + 1, j), sample(i, j + 1)}, true);
      if(i + j + 2 <= n)
        builder.add_triangle(face, family, {sample(i + 1, j), sample(i + 1, j + 1), sample(i, j + 1)}, true);
    }
}

/// A branch face: linear on (0, 1, o), (1, 2, o), (2, 0', o) as in `branch_face_value()`, o the
/// branch point (barycentric coordinates).
inline void add_branch_face_isolines(Stripe_isoline_builder& builder, const Stripe_isoline_builder::Face& face,
                                     int family, const std::array<double, 4>& beta, double centre,
                                     const std::array<double, 3>& o)
{
  using Sample = Stripe_isoline_sample;
  const Sample middle{o, centre, 3};
  const std::array<Sample, 4> s{Sample{{1., 0., 0.}, beta[0], 0}, Sample{{0., 1., 0.}, beta[1], 1},
                                Sample{{0., 0., 1.}, beta[2], 2}, Sample{{1., 0., 0.}, beta[3], 0}};
  for(int i = 0; i < 3; ++i)
    builder.add_triangle(face, family, {s[std::size_t(i)], s[std::size_t(i + 1)], middle});
}

/// The builder's polylines with the mesh's points and faces.
template <class Point_3, class Indices>
std::vector<Stripe_isoline<Point_3, typename Indices::face_descriptor>>
stripe_isolines_of(const Stripe_isoline_builder& builder, const Indices& idx)
{
  std::vector<Stripe_isoline<Point_3, typename Indices::face_descriptor>> result;
  for(const auto& line : builder.polylines())
  {
    result.emplace_back();
    auto& out = result.back();
    out.closed = line.closed;
    out.level = line.level;
    out.family = line.family;
    for(const auto& x : line.points)
      out.points.push_back(Point_3(x.x(), x.y(), x.z()));
    for(std::size_t f : line.faces)
      out.faces.push_back(idx.face(f));
  }
  return result;
}

} // namespace internal
} // namespace Surface_design
} // namespace CGAL

#endif // CGAL_SURFACE_DESIGN_INTERNAL_FIELD_ALIGNED_PARAMETERIZATION_STRIPE_ISOLINES_H
