// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// From the quad-dominant net to quads only: the faces with an odd number of sides (the
// pentagons of T-junctions, triangles) are paired by paths in the dual graph, every edge a path
// crosses gets a vertex, and every face, now with an even number of sides, is split into quads.

#ifndef CGAL_SURFACE_DESIGN_INTERNAL_HARMONIC_QUAD_REMESHING_ODD_FACES_H
#define CGAL_SURFACE_DESIGN_INTERNAL_HARMONIC_QUAD_REMESHING_ODD_FACES_H

#include <CGAL/Surface_design/internal/Core/angles.h>
#include <CGAL/Surface_design/internal/Core/Mesh_indices.h>
#include <CGAL/Surface_design/internal/Harmonic_quad_remeshing/quad_net.h>

#include <CGAL/assertions.h>
#include <CGAL/use.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <queue>
#include <set>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_design {
namespace internal {
namespace harmonic_quad {

struct Odd_face_statistics
{
  std::size_t odd_faces = 0;      ///< faces with an odd number of sides before
  std::size_t paths = 0;          ///< dual paths between two of them
  std::size_t boundary_paths = 0; ///< dual paths from one of them to the boundary
  std::size_t split_edges = 0;    ///< edges that got a vertex
  std::size_t split_faces = 0;    ///< faces of more than four sides split into quads
  std::size_t merged_triangles = 0; ///< triangles at the end of a path merged with their neighbour
  std::size_t unpaired = 0;       ///< odd faces left (none on a valid mesh, but for unreachable ones)
};

/// Interior angle in [0, 2 pi) at corner b of a polygon ... a, b, c ... counter-clockwise about n.
inline double polygon_corner_angle(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                                   const Eigen::Vector3d& n)
{
  const Eigen::Vector3d next = c - b, previous = a - b;
  const double t = std::atan2(n.dot(next.cross(previous)), next.dot(previous));
  return t < 0. ? t + two_pi : t;
}

/// Newell's normal of a polygon (not normalized: its norm is twice the area of a planar polygon).
inline Eigen::Vector3d newell_normal(const std::vector<Eigen::Vector3d>& p)
{
  Eigen::Vector3d n = Eigen::Vector3d::Zero();
  for(std::size_t k = 0; k < p.size(); ++k)
    n += p[k].cross(p[(k + 1) % p.size()]);
  return n;
}

/// Splits polygons with an even number of sides into quads, minimizing the largest deviation of a
/// corner from 90 degrees (measured counter-clockwise about the polygon's normal, so that reflex
/// corners count as such). Candidates: diagonals (every choice up to 12 sides, greedy beyond; a
/// diagonal never duplicates an edge of `edges`, the mesh's edges, to which the chosen ones are
/// added) and, up to 8 sides, a new vertex joined to every other corner, at their mean. The centre
/// is taken only when it is better by `star_penalty` degrees, as it makes an irregular vertex in a
/// hexagon; it is what turns a corner well: a quad with vertices added on two adjacent sides
/// becomes three quads with corners of about 45 and 135 degrees instead of one flat corner.
class Even_polygon_splitter
{
public:
  Even_polygon_splitter(Polygon_soup& soup, std::set<std::pair<std::size_t, std::size_t>>& edges)
    : m_soup(soup), m_points(soup.points), m_edges(edges)
  {}

  /// The quads of `polygon` (its own orientation), or nothing when no split avoids duplicate
  /// edges. A centre vertex, when used, is added to the soup.
  std::vector<std::array<std::size_t, 4>> split(const std::vector<std::size_t>& polygon)
  {
    std::vector<Eigen::Vector3d> p;
    for(std::size_t v : polygon)
      p.push_back(m_points[v]);
    m_normal = newell_normal(p);
    const double norm = m_normal.norm();
    if(!(norm > 0.))
      return {};
    m_normal /= norm;
    Result r = best(polygon);
    if(polygon.size() <= 8)
    {
      // the centre: the mean of the corners it joins (the middle of a square whose sides got vertices)
      const std::size_t x = m_points.size(), n = polygon.size();
      m_points.emplace_back(Eigen::Vector3d::Zero());
      Result star;
      Eigen::Vector3d star_centre = Eigen::Vector3d::Zero();
      for(std::size_t parity = 0; parity < 2; ++parity)
      {
        Eigen::Vector3d c = Eigen::Vector3d::Zero();
        for(std::size_t i = parity; i < n; i += 2)
          c += m_points[polygon[i]];
        m_points[x] = c / double(n / 2);
        Result candidate;
        candidate.worst = candidate.sum = 0.;
        for(std::size_t i = parity; i < n; i += 2)
        {
          const std::array<std::size_t, 4> q{{polygon[i], polygon[(i + 1) % n], polygon[(i + 2) % n], x}};
          const double score = quad_score(q);
          candidate.worst = (std::max)(candidate.worst, score);
          candidate.sum += score;
          candidate.quads.push_back(q);
        }
        if(candidate.worst < star.worst)
        {
          star = std::move(candidate);
          star_centre = m_points[x];
        }
      }
      if(star.worst + star_penalty < r.worst)
      {
        m_points[x] = star_centre;
        m_soup.kind.push_back(Net_point_kind::crossing);
        return star.quads;
      }
      m_points.pop_back();
    }
    if(!std::isfinite(r.worst))
      return {};
    for(const auto& q : r.quads)
      m_edges.insert(key(q[0], q[3]));
    return r.quads;
  }

private:
  struct Result
  {
    double worst = std::numeric_limits<double>::infinity();
    double sum = std::numeric_limits<double>::infinity();
    std::vector<std::array<std::size_t, 4>> quads; // each cut by the diagonal q[3] - q[0]
  };

  static std::pair<std::size_t, std::size_t> key(std::size_t a, std::size_t b) { return {(std::min)(a, b), (std::max)(a, b)}; }

  double quad_score(const std::array<std::size_t, 4>& q) const
  {
    double worst = 0.;
    for(std::size_t k = 0; k < 4; ++k)
    {
      const double a = polygon_corner_angle(m_points[q[(k + 3) % 4]], m_points[q[k]], m_points[q[(k + 1) % 4]], m_normal);
      worst = (std::max)(worst, std::abs(a * 180. / pi - 90.));
    }
    return worst;
  }

  Result best(const std::vector<std::size_t>& poly) const
  {
    const std::size_t n = poly.size();
    Result out;
    if(n == 4)
    {
      const std::array<std::size_t, 4> q{{poly[0], poly[1], poly[2], poly[3]}};
      out.worst = out.sum = quad_score(q);
      out.quads = {q};
      return out;
    }
    // the quad cut off by the diagonal from corner i to corner i + 3, the rest recursively
    // (every cut up to 12 sides, only the best-shaped cut beyond)
    std::vector<std::pair<double, std::size_t>> cuts;
    for(std::size_t i = 0; i < n; ++i)
    {
      const std::size_t a = poly[i], b = poly[(i + 3) % n];
      if(a != b && m_edges.count(key(a, b)) == 0)
        cuts.emplace_back(quad_score({{a, poly[(i + 1) % n], poly[(i + 2) % n], b}}), i);
    }
    std::sort(cuts.begin(), cuts.end());
    if(n > 12 && cuts.size() > 1)
      cuts.resize(1);
    for(const auto& [s, i] : cuts)
    {
      if(s >= out.worst)
        break;
      const std::array<std::size_t, 4> q{{poly[i], poly[(i + 1) % n], poly[(i + 2) % n], poly[(i + 3) % n]}};
      std::vector<std::size_t> rest;
      for(std::size_t k = 3; k <= n; ++k)
        rest.push_back(poly[(i + k) % n]);
      const Result sub = best(rest);
      if(!std::isfinite(sub.worst))
        continue;
      const double worst = (std::max)(s, sub.worst), sum = s + sub.sum;
      if(worst < out.worst || (worst == out.worst && sum < out.sum))
      {
        out.worst = worst;
        out.sum = sum;
        out.quads = {q};
        out.quads.insert(out.quads.end(), sub.quads.begin(), sub.quads.end());
      }
    }
    return out;
  }

  static constexpr double star_penalty = 10.; // degrees

  Polygon_soup& m_soup;
  std::vector<Eigen::Vector3d>& m_points;
  std::set<std::pair<std::size_t, std::size_t>>& m_edges;
  Eigen::Vector3d m_normal = Eigen::Vector3d::UnitZ();
};

/// Pairs the odd faces of a valid polygon soup and splits it into quads (see the file comment).
/// Each odd face, in rounds of growing reach, is joined to the nearest unpaired odd face or to
/// the boundary by a shortest dual path whose cost is one per crossed edge plus a penalty for
/// turning (so that paths run straight across quads and leave a T-junction's pentagon opposite its
/// flat corner, i.e. they continue the line that ended there). The crossed edges (each as often
/// as paths cross it, mod 2) get a vertex at their middle, so that the surface of the polygon mesh
/// does not change (projecting it onto the input changed the Hausdorff distance by less than 0.01%
/// of the diagonal on eight, kitten, fertility and the camel head, for an AABB tree costing more than
/// the rest of this step); then every face has an even number of sides and is split into quads.
class Odd_face_pairing
{
public:
  explicit Odd_face_pairing(Polygon_soup& soup) : m_soup(soup) {}

  Odd_face_statistics run()
  {
    build_edges();
    Odd_face_statistics stats;
    m_odd.assign(m_faces, 0);
    std::vector<std::size_t> odd;
    for(std::size_t f = 0; f < m_faces; ++f)
      if(m_soup.faces[f].size() % 2 == 1)
      {
        m_odd[f] = 1;
        odd.push_back(f);
      }
    stats.odd_faces = odd.size();
    m_split.assign(m_edge_slots.size(), 0);
    const std::size_t nodes = 2 * m_slots + m_faces;
    m_dist.assign(nodes, std::numeric_limits<double>::infinity());
    m_previous.assign(nodes, npos);
    // nearest first: rounds of growing reach; a last round may cross next to flat corners
    for(double limit : {3., 8., 24., std::numeric_limits<double>::infinity(), -1.})
    {
      m_respect_blocking = limit >= 0.;
      for(std::size_t f : odd)
        if(m_odd[f] == 1)
        {
          const int result = pair_from(f, limit >= 0. ? limit : std::numeric_limits<double>::infinity());
          stats.paths += result == 1;
          stats.boundary_paths += result == 2;
        }
    }
    for(std::size_t f : odd)
      stats.unpaired += m_odd[f] == 1;
    split(stats);
    return stats;
  }

private:
  // face f's slot i is its edge from corner i to corner i + 1
  void build_edges()
  {
    m_faces = m_soup.faces.size();
    m_offset.assign(m_faces + 1, 0);
    for(std::size_t f = 0; f < m_faces; ++f)
      m_offset[f + 1] = m_offset[f] + m_soup.faces[f].size();
    m_slots = m_offset[m_faces];
    m_slot_face.resize(m_slots);
    std::vector<std::pair<std::pair<std::size_t, std::size_t>, std::size_t>> keyed;
    keyed.reserve(m_slots);
    for(std::size_t f = 0; f < m_faces; ++f)
    {
      const auto& face = m_soup.faces[f];
      for(std::size_t i = 0; i < face.size(); ++i)
      {
        const std::size_t a = face[i], b = face[(i + 1) % face.size()];
        keyed.push_back({{(std::min)(a, b), (std::max)(a, b)}, m_offset[f] + i});
        m_slot_face[m_offset[f] + i] = f;
      }
    }
    std::sort(keyed.begin(), keyed.end());
    m_slot_edge.assign(m_slots, npos);
    m_edge_slots.clear();
    m_edge_ends.clear();
    for(std::size_t k = 0; k < keyed.size();)
    {
      std::array<std::size_t, 2> slots{{keyed[k].second, npos}};
      std::size_t next = k + 1;
      if(next < keyed.size() && keyed[next].first == keyed[k].first)
        slots[1] = keyed[next++].second;
      for(std::size_t s : slots)
        if(s != npos)
          m_slot_edge[s] = m_edge_slots.size();
      m_edge_slots.push_back(slots);
      m_edge_ends.push_back({{keyed[k].first.first, keyed[k].first.second}});
      k = next;
    }
    // geometry of the search: edge midpoints, face centroids, the flattest corner of each face
    m_mid.resize(m_edge_slots.size());
    for(std::size_t e = 0; e < m_edge_slots.size(); ++e)
      m_mid[e] = 0.5 * (m_soup.points[m_edge_ends[e][0]] + m_soup.points[m_edge_ends[e][1]]);
    m_centroid.resize(m_faces);
    m_flat_corner.assign(m_faces, npos);
    m_blocked.assign(m_slots, 0);
    for(std::size_t f = 0; f < m_faces; ++f)
    {
      const auto& face = m_soup.faces[f];
      std::vector<Eigen::Vector3d> p;
      Eigen::Vector3d c = Eigen::Vector3d::Zero();
      for(std::size_t v : face)
      {
        p.push_back(m_soup.points[v]);
        c += m_soup.points[v];
      }
      m_centroid[f] = c / double(face.size());
      Eigen::Vector3d n = newell_normal(p);
      if(!(n.norm() > 0.))
        continue;
      n.normalize();
      double flattest = flat_corner_angle;
      for(std::size_t i = 0; i < face.size(); ++i)
      {
        const double a = polygon_corner_angle(p[(i + face.size() - 1) % face.size()], p[i], p[(i + 1) % face.size()], n);
        if(a > flat_corner_angle && a < two_pi - flat_corner_angle)
        {
          // a vertex added next to a flat corner would be a second one: no path crosses there
          m_blocked[m_offset[f] + i] = m_blocked[m_offset[f] + (i + face.size() - 1) % face.size()] = 1;
          if(a > flattest)
          {
            flattest = a;
            m_flat_corner[f] = face[i];
          }
        }
      }
    }
  }

  std::size_t other_slot(std::size_t s) const
  {
    const auto& e = m_edge_slots[m_slot_edge[s]];
    return e[0] == s ? e[1] : e[0];
  }

  static double turn_penalty(const Eigen::Vector3d& forward, const Eigen::Vector3d& step)
  {
    const double a = forward.norm(), b = step.norm();
    if(!(a > 0.) || !(b > 0.))
      return 0.;
    return turn_weight * (1. - forward.dot(step) / (a * b));
  }

  // Dijkstra over (face, entry slot) states from odd face `source`; nodes: [0, S) a state
  // entered through slot s, [S, 2S) leaving through boundary slot s, 2S + f ending in face f.
  // Returns 0 (nothing within `limit`), 1 (paired with a face) or 2 (with the boundary).
  int pair_from(std::size_t source, double limit)
  {
    using Entry = std::pair<double, std::size_t>;
    std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> heap;
    std::vector<std::size_t> touched;
    auto relax = [&](std::size_t node, double d, std::size_t from) {
      if(d < m_dist[node])
      {
        if(m_dist[node] == std::numeric_limits<double>::infinity())
          touched.push_back(node);
        m_dist[node] = d;
        m_previous[node] = from;
        heap.push({d, node});
      }
    };
    // leaving face f (entered at point `entry` heading `forward`) through each slot but `in`
    auto expand = [&](std::size_t f, std::size_t in, const Eigen::Vector3d& entry, const Eigen::Vector3d& forward,
                      double d, std::size_t from) {
      for(std::size_t s = m_offset[f]; s < m_offset[f + 1]; ++s)
      {
        if(s == in || (m_respect_blocking && (m_blocked[s] || (other_slot(s) != npos && m_blocked[other_slot(s)]))))
          continue;
        const double cost = d + 1. + turn_penalty(forward, m_mid[m_slot_edge[s]] - entry);
        const std::size_t across = other_slot(s);
        relax(across == npos ? m_slots + s : across, across == npos ? cost + boundary_cost : cost, from);
      }
    };
    const std::size_t t = m_flat_corner[source];
    if(t != npos)
      expand(source, npos, m_soup.points[t], m_centroid[source] - m_soup.points[t], 0., npos);
    else
      expand(source, npos, m_centroid[source], Eigen::Vector3d::Zero(), 0., npos);
    int result = 0;
    std::size_t end = npos;
    while(!heap.empty())
    {
      const auto [d, node] = heap.top();
      heap.pop();
      if(d > m_dist[node])
        continue;
      if(d > limit)
        break;
      if(node >= m_slots)
      {
        end = node;
        result = node >= 2 * m_slots ? 1 : 2;
        break;
      }
      const std::size_t f = m_slot_face[node];
      const Eigen::Vector3d entry = m_mid[m_slot_edge[node]], forward = m_centroid[f] - entry;
      if(m_odd[f] == 1 && f != source)
      {
        // end here, best entered opposite the flat corner of a T-junction
        const std::size_t c = m_flat_corner[f];
        relax(2 * m_slots + f, d + (c == npos ? 0. : turn_penalty(forward, m_soup.points[c] - entry)), node);
        continue;
      }
      expand(f, node, entry, forward, d, node);
    }
    if(result != 0)
    {
      if(result == 1)
        m_odd[end - 2 * m_slots] = 2;
      else
        m_split[m_slot_edge[end - m_slots]] ^= 1;
      for(std::size_t s = m_previous[end]; s != npos; s = m_previous[s])
        m_split[m_slot_edge[s]] ^= 1;
      m_odd[source] = 2;
    }
    for(std::size_t node : touched)
    {
      m_dist[node] = std::numeric_limits<double>::infinity();
      m_previous[node] = npos;
    }
    return result;
  }

  // A triangle crossed through one edge only would become a quad with a flat corner: it is
  // merged with the face across that edge instead (the edge removed rather than split; the
  // merged face has the same number of sides as that face with the vertex would have).
  std::vector<std::size_t> triangles_to_merge(Odd_face_statistics& stats)
  {
    std::vector<std::size_t> absorbed(m_faces, npos); // face -> the triangle merged into it
    std::vector<char> taken(m_faces, 0);
    for(std::size_t f = 0; f < m_faces; ++f)
    {
      if(m_soup.faces[f].size() != 3 || taken[f])
        continue;
      std::size_t crossed = npos, count = 0;
      for(std::size_t s = m_offset[f]; s < m_offset[f + 1]; ++s)
        if(m_split[m_slot_edge[s]])
        {
          crossed = s;
          ++count;
        }
      if(count != 1 || other_slot(crossed) == npos)
        continue;
      const std::size_t g = m_slot_face[other_slot(crossed)];
      const std::size_t apex = m_soup.faces[f][(crossed - m_offset[f] + 2) % 3];
      const auto& other = m_soup.faces[g];
      if(g == f || taken[g] || std::find(other.begin(), other.end(), apex) != other.end())
        continue;
      m_split[m_slot_edge[crossed]] = 0;
      absorbed[g] = f;
      taken[f] = taken[g] = 1;
      ++stats.merged_triangles;
    }
    return absorbed;
  }

  void split(Odd_face_statistics& stats)
  {
    const std::vector<std::size_t> absorbed = triangles_to_merge(stats);
    std::vector<char> removed(m_faces, 0);
    for(std::size_t t : absorbed)
      if(t != npos)
        removed[t] = 1;
    std::vector<std::size_t> new_vertex(m_edge_slots.size(), npos);
    for(std::size_t e = 0; e < m_edge_slots.size(); ++e)
      if(m_split[e])
      {
        new_vertex[e] = m_soup.points.size();
        m_soup.points.push_back(m_mid[e]);
        m_soup.kind.push_back(m_edge_slots[e][1] == npos ? Net_point_kind::boundary : Net_point_kind::crossing);
        ++stats.split_edges;
      }
    std::set<std::pair<std::size_t, std::size_t>> edges;
    for(std::size_t e = 0; e < m_edge_slots.size(); ++e)
      if(!m_split[e])
        edges.insert({m_edge_ends[e][0], m_edge_ends[e][1]});
      else
        for(std::size_t v : m_edge_ends[e])
          edges.insert({(std::min)(v, new_vertex[e]), (std::max)(v, new_vertex[e])});
    auto polygon_of = [&](std::size_t f) {
      std::vector<std::size_t> polygon;
      for(std::size_t s = m_offset[f]; s < m_offset[f + 1]; ++s)
      {
        polygon.push_back(m_soup.faces[f][s - m_offset[f]]);
        if(new_vertex[m_slot_edge[s]] != npos)
          polygon.push_back(new_vertex[m_slot_edge[s]]);
      }
      return polygon;
    };
    Even_polygon_splitter splitter(m_soup, edges);
    std::vector<std::vector<std::size_t>> faces;
    faces.reserve(m_faces + m_faces / 4);
    for(std::size_t f = 0; f < m_faces; ++f)
    {
      if(removed[f])
        continue;
      std::vector<std::size_t> polygon = polygon_of(f);
      if(absorbed[f] != npos)
      {
        // the triangle (a, b, c) across its edge a -> b, which is b -> a here: this face from a
        // round to b, then c
        const auto& t = m_soup.faces[absorbed[f]];
        std::size_t i = 0;
        for(; i < 3; ++i)
        {
          const std::size_t across = other_slot(m_offset[absorbed[f]] + i);
          if(across != npos && m_slot_face[across] == f)
            break;
        }
        const std::size_t a = t[i], b = t[(i + 1) % 3], c = t[(i + 2) % 3];
        const auto at = std::find(polygon.begin(), polygon.end(), a);
        std::rotate(polygon.begin(), at, polygon.end());
        CGAL_assertion(polygon.back() == b);
        CGAL_USE(b);
        polygon.push_back(c);
      }
      if(polygon.size() <= 4 || polygon.size() % 2 == 1)
      {
        faces.push_back(std::move(polygon));
        continue;
      }
      const auto quads = splitter.split(polygon);
      if(quads.empty())
      {
        faces.push_back(std::move(polygon));
        continue;
      }
      ++stats.split_faces;
      for(const auto& q : quads)
        faces.emplace_back(q.begin(), q.end());
    }
    m_soup.faces = std::move(faces);
  }

  // a step that leaves at angle a from the straight course costs 1 + 6 (1 - cos a) crossings:
  // 2.8 to a quad's side edge, 1 to its opposite edge (measured on eight, kitten, fertility and
  // the camel head: 3 to 10 give the same corners, fewer irregular vertices as it grows, more
  // vertices on edges)
  static constexpr double turn_weight = 6.;
  static constexpr double boundary_cost = 0.5; // an odd face rather than the boundary, at equal distance
  static constexpr double flat_corner_angle = 150. * pi / 180.; // corners flatter than this are T-junctions

  Polygon_soup& m_soup;
  std::size_t m_faces = 0, m_slots = 0;
  std::vector<std::size_t> m_offset, m_slot_face, m_slot_edge, m_flat_corner;
  std::vector<std::array<std::size_t, 2>> m_edge_slots, m_edge_ends;
  std::vector<Eigen::Vector3d> m_mid, m_centroid;
  std::vector<char> m_odd, m_split; // m_odd: 0 even, 1 odd and unpaired, 2 paired
  std::vector<char> m_blocked;      // slots next to a flat corner
  bool m_respect_blocking = true;
  std::vector<double> m_dist;
  std::vector<std::size_t> m_previous;
};

} // namespace harmonic_quad
} // namespace internal
} // namespace Surface_design
} // namespace CGAL

#endif // CGAL_SURFACE_DESIGN_INTERNAL_HARMONIC_QUAD_REMESHING_ODD_FACES_H
