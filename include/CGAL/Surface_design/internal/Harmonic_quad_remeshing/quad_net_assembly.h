// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The net of isolines and gradient lines, one phase of `Quad_net_builder` (declared in
// quad_net_builder.h): the faces of the net: floating boundary loops attached, the edges (lines,
// isolines, boundary with its detail), every other line into a pole kept, the rotation system and
// its faces.

#ifndef CGAL_SURFACE_DESIGN_INTERNAL_HARMONIC_QUAD_REMESHING_QUAD_NET_ASSEMBLY_H
#define CGAL_SURFACE_DESIGN_INTERNAL_HARMONIC_QUAD_REMESHING_QUAD_NET_ASSEMBLY_H

#include <CGAL/Surface_design/internal/Harmonic_quad_remeshing/quad_net_builder.h>

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <map>
#include <numeric>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_design {
namespace internal {
namespace harmonic_quad {

inline void Quad_net_builder::attach_floating_loops()
{
  const std::size_t nl = m_m.boundary_loop.size();
  if(nl == 0)
    return;
  std::vector<char> attached(nl, 0);
  for(const auto& [a, b] : m_line_edges)
    for(std::size_t id : {resolve(a), resolve(b)})
      if(id != npos && m_nodes[id].loop != npos)
        attached[m_nodes[id].loop] = 1;
  for(const Keyed_edge& e : m_keyed_edges)
    for(std::size_t id : {resolve(e.a), resolve(e.b)})
      if(id != npos && m_nodes[id].loop != npos)
        attached[m_nodes[id].loop] = 1;
  for(std::size_t c = 0; c < m_iso.size(); ++c)
    if(!m_iso[c].closed && m_iso[c].role == Curve_role::level_set && !m_crossings[c].empty())
    {
      attached[loop_of_edge(m_iso[c].point_edge.front())] = 1;
      attached[loop_of_edge(m_iso[c].point_edge.back())] = 1;
    }
  for(bool changed = true; changed;)
  {
    changed = false;
    for(std::size_t c = 0; c < m_iso.size(); ++c)
      if(!m_iso[c].closed && m_iso[c].role == Curve_role::level_set)
      {
        const std::size_t a = loop_of_edge(m_iso[c].point_edge.front()), b = loop_of_edge(m_iso[c].point_edge.back());
        if(attached[a] != attached[b])
        {
          attached[a] = attached[b] = 1;
          changed = true;
        }
      }
  }
  Gradient_walker walker(m_m, m_u, m_levels_in_face, &m_iso);
  for(std::size_t l = 0; l < nl; ++l)
  {
    if(attached[l])
      continue;
    const auto& loop = m_m.boundary_loop[l];
    std::size_t top = loop[0], bottom = loop[0];
    for(std::size_t v : loop)
    {
      if(below(m_u, top, v))
        top = v;
      if(below(m_u, v, bottom))
        bottom = v;
    }
    for(int direction : {+1, -1})
    {
      const std::size_t v = direction > 0 ? top : bottom;
      const Trace_end e = walker.from_vertex(v, direction);
      if(e.kind == Trace_end::lost || (e.kind == Trace_end::pole && e.vertex == v))
        continue;
      Node n;
      n.point = m_m.point[v];
      n.kind = Net_point_kind::boundary;
      n.loop = l;
      n.loop_position = double(m_m.boundary_position[v].second);
      m_nodes.push_back(n);
      const std::size_t node = m_nodes.size() - 1;
      const std::size_t end = end_node(e, node);
      if(end != npos)
        m_line_edges.emplace_back(direction > 0 ? node : end, direction > 0 ? end : node);
      ++m_stats.attached_loops;
    }
  }
}

inline Polygon_soup Quad_net_builder::assemble()
{
  attach_floating_loops();
  // edges: (a, b, kind): a line (a below b), an isoline (a before b), the boundary, a bridge
  const double nan = std::numeric_limits<double>::quiet_NaN();
  struct Edge
  {
    std::size_t a, b;
    Net_edge_kind kind;
    double key_a, key_b; // explicit rotation keys (spectacles), NaN otherwise
  };
  std::vector<Edge> edges;
  for(auto [a, b] : m_line_edges)
  {
    // npos: a lost line, or one that stopped where it met another (its pending code unresolved)
    const std::size_t ra = resolve(a), rb = resolve(b);
    if(ra != npos && rb != npos)
      edges.push_back({ra, rb, Net_edge_kind::line, nan, nan});
  }
  for(const Keyed_edge& e : m_keyed_edges)
  {
    const std::size_t ra = resolve(e.a), rb = resolve(e.b);
    if(ra != npos && rb != npos)
      edges.push_back({ra, rb, e.kind, e.key_a, e.key_b});
  }
  // lines ending at a pole: keep every other one (a fan of quads)
  std::vector<std::vector<std::size_t>> into_pole(m_nodes.size());
  for(std::size_t k = 0; k < edges.size(); ++k)
  {
    if(m_nodes[edges[k].b].kind == Net_point_kind::pole)
      into_pole[edges[k].b].push_back(k);
    else if(m_nodes[edges[k].a].kind == Net_point_kind::pole)
      into_pole[edges[k].a].push_back(k);
  }
  std::vector<char> drop(edges.size(), 0);
  for(std::size_t p = 0; p < m_nodes.size(); ++p)
  {
    auto& in = into_pole[p];
    if(in.size() < 3)
    {
      for(std::size_t k : in)
        drop[k] = 1; // fewer than three lines: no pole
      continue;
    }
    if(!m_opt.quad_poles || in.size() < 6 || m_nodes[p].loop != npos)
      continue;
    sort_around(p, in, edges);
    for(std::size_t k = 1; k < in.size(); k += 2)
      if(!(in.size() % 2 == 1 && k + 1 == in.size()))
        drop[in[k]] = 1;
  }
  std::vector<Edge> kept;
  for(std::size_t k = 0; k < edges.size(); ++k)
    if(!drop[k])
      kept.push_back(edges[k]);
  edges.swap(kept);
  // isoline edges
  std::map<std::size_t, bool> path_ends; // crossings made boundary nodes (below): at the path's start?
  for(std::size_t c = 0; c < m_iso.size(); ++c)
  {
    auto& cr = m_crossings[c];
    std::stable_sort(cr.begin(), cr.end(), [](const Crossing& a, const Crossing& b) { return a.s < b.s; });
    std::vector<std::size_t> chain;
    const Isoline& iso = m_iso[c];
    if(iso.role == Curve_role::spectacles_bridge) // a bridge: its edges are keyed edges
      continue;
    // A path's ends get boundary nodes. A line that came up along the boundary lands on the path
    // at its end (found on blobby_3cc and the elephant with holes): that crossing becomes the
    // boundary node, rather than a second node at the same point joined to it by an isoline edge
    // of length 0 (a degenerate face on either side of it).
    std::size_t first = 0, last = cr.size(); // the crossings [first, last) between the ends
    auto boundary_end = [&](bool front) {
      const std::size_t b = front ? boundary_node(iso.point_edge.front(), iso.point.front())
                                  : boundary_node(iso.point_edge.back(), iso.point.back());
      if(first == last)
        return b;
      const Crossing& x = front ? cr[first] : cr[last - 1];
      if(x.fixed || !((front ? x.s : iso.length() - x.s) < 1e-3 * m_opt.edge_length))
        return b;
      Node& n = m_nodes[x.node];
      n.point = m_nodes[b].point;
      n.kind = Net_point_kind::boundary;
      n.loop = m_nodes[b].loop;
      n.loop_position = m_nodes[b].loop_position;
      m_nodes.pop_back(); // b
      if(front)
        ++first;
      else
        --last;
      path_ends[x.node] = front;
      return x.node;
    };
    if(!iso.closed)
      chain.push_back(boundary_end(true));
    const std::size_t back = iso.closed ? npos : boundary_end(false);
    for(std::size_t k = first; k < last; ++k)
      chain.push_back(cr[k].node);
    if(!iso.closed)
      chain.push_back(back);
    for(std::size_t k = 0; k + 1 < chain.size(); ++k)
      edges.push_back({chain[k], chain[k + 1], Net_edge_kind::isoline, nan, nan});
    if(iso.closed && chain.size() >= 2)
      edges.push_back({chain.back(), chain.front(), Net_edge_kind::isoline, nan, nan});
  }
  // boundary edges between consecutive boundary nodes of every loop
  std::vector<std::vector<std::pair<double, std::size_t>>> on_loop(m_m.boundary_loop.size());
  for(std::size_t n = 0; n < m_nodes.size(); ++n)
    if(m_nodes[n].loop != npos)
      on_loop[m_nodes[n].loop].emplace_back(m_nodes[n].loop_position, n);
  for(std::size_t l = 0; l < on_loop.size(); ++l)
  {
    auto& q = on_loop[l];
    std::sort(q.begin(), q.end());
    // a loop that curves reach fewer than three times gets nodes at boundary vertices, so that
    // it stays a loop of the output
    const auto& loop = m_m.boundary_loop[l];
    for(std::size_t k = 0; q.size() < 3 && k < 3; ++k)
    {
      const std::size_t at = (k * loop.size()) / 3 + (q.empty() ? 0 : std::size_t(q[0].first) + loop.size() / 6);
      Node n;
      n.point = m_m.point[loop[at % loop.size()]];
      n.kind = Net_point_kind::boundary;
      n.loop = l;
      n.loop_position = double(at % loop.size());
      bool taken = false;
      for(const auto& x : q)
        taken = taken || std::abs(x.first - n.loop_position) < 0.5;
      if(taken)
        continue;
      m_nodes.push_back(n);
      q.emplace_back(n.loop_position, m_nodes.size() - 1);
      std::sort(q.begin(), q.end());
    }
    for(std::size_t k = 0; k < q.size(); ++k)
    {
      // the input's boundary between two nodes, where it leaves the chord by more than h / 4
      // (a serrated or sharply bent boundary), gets nodes at its vertices
      std::size_t from = q[k].second;
      const double end = k + 1 < q.size() ? q[k + 1].first : q[0].first + double(loop.size());
      for(double t : boundary_detail(l, q[k].first, end))
      {
        Node n;
        n.kind = Net_point_kind::boundary;
        n.loop = l;
        n.loop_position = std::fmod(t, double(loop.size()));
        n.point = loop_point(l, n.loop_position);
        m_nodes.push_back(n);
        edges.push_back({from, m_nodes.size() - 1, Net_edge_kind::boundary, nan, nan});
        from = m_nodes.size() - 1;
        ++m_stats.boundary_detail_nodes;
      }
      edges.push_back({from, q[(k + 1) % q.size()].second, Net_edge_kind::boundary, nan, nan});
    }
  }
  // At such an end, the crossing's order (up, along the isoline, down: see faces_of) between the
  // loop's next direction (key 0) and its previous one (key 10), not the angles of the chords
  // (a line along the boundary leaves no room for them): lower values lie on the left of an
  // isoline, so that from the loop's next direction come the lines up, the isoline, the lines
  // down at a path's start, and the other way round at its end.
  for(Edge& e : edges)
    for(const bool at_a : {true, false})
    {
      const auto it = path_ends.find(at_a ? e.a : e.b);
      if(it == path_ends.end() || e.kind == Net_edge_kind::boundary)
        continue;
      double key = 2.; // the isoline
      if(e.kind != Net_edge_kind::isoline) // a line (a below b)
        key = at_a == it->second ? 1. : 3.;
      (at_a ? e.key_a : e.key_b) = key;
    }
  return faces_of(edges);
}

inline std::vector<double> Quad_net_builder::boundary_detail(std::size_t l, double begin, double end) const
{
  const double h = m_opt.edge_length;
  std::vector<double> position{begin}; // the loop's vertices strictly inside (begin, end)
  for(double i = std::floor(begin) + 1.; i < end - 1e-9; i += 1.)
    if(i > begin + 1e-9)
      position.push_back(i);
  position.push_back(end);
  if(position.size() == 2)
    return {};
  std::vector<Eigen::Vector3d> p;
  for(double t : position)
    p.push_back(loop_point(l, t));
  const auto distance_to_chord = [&](std::size_t i, std::size_t a, std::size_t b) {
    const Eigen::Vector3d d = p[b] - p[a];
    const double t = d.squaredNorm() > 0. ? std::clamp((p[i] - p[a]).dot(d) / d.squaredNorm(), 0., 1.) : 0.;
    return (p[i] - p[a] - t * d).norm();
  };
  // split the piece (a, b) at its farthest point while that is beyond the tolerance
  std::vector<char> kept(p.size(), 0);
  kept.front() = kept.back() = 1;
  std::size_t count = 0;
  double best_left = 0.;
  std::size_t best_left_at = npos;
  std::vector<std::pair<std::size_t, std::size_t>> pieces{{0, p.size() - 1}};
  while(!pieces.empty())
  {
    const auto [a, b] = pieces.back();
    pieces.pop_back();
    double far = -1.;
    std::size_t at = npos;
    for(std::size_t i = a + 1; i < b; ++i)
    {
      if((p[i] - p[a]).norm() < h / 8. || (p[i] - p[b]).norm() < h / 8.)
        continue;
      const double d = distance_to_chord(i, a, b);
      if(d > far)
      {
        far = d;
        at = i;
      }
    }
    if(at == npos)
      continue;
    if(far > h / 4.)
    {
      kept[at] = 1;
      ++count;
      pieces.emplace_back(a, at);
      pieces.emplace_back(at, b);
    }
    else if(far > best_left)
    {
      best_left = far;
      best_left_at = at;
    }
  }
  std::vector<double> out;
  if(count % 2 == 1 && best_left_at != npos)
    kept[best_left_at] = 1;
  double longest = -1., middle = 0.;
  for(std::size_t i = 1, last = 0; i < p.size(); ++i)
    if(kept[i])
    {
      if(i + 1 < p.size())
        out.push_back(position[i]);
      if((p[i] - p[last]).norm() > longest)
      {
        longest = (p[i] - p[last]).norm();
        middle = 0.5 * (position[i] + position[last]);
      }
      last = i;
    }
  if(out.size() % 2 == 1)
  {
    out.push_back(middle);
    std::sort(out.begin(), out.end());
  }
  return out;
}

inline std::size_t Quad_net_builder::boundary_node(std::size_t mesh_edge, const Eigen::Vector3d& p)
{
  const auto [f, i] = m_m.edge_side[mesh_edge];
  const std::size_t a = m_m.tri[f][i], b = m_m.tri[f][(i + 1) % 3];
  const double len = (m_m.point[b] - m_m.point[a]).norm();
  const double t = len > 0. ? std::clamp((p - m_m.point[a]).norm() / len, 0., 1.) : 0.;
  Node n;
  n.point = p;
  n.kind = Net_point_kind::boundary;
  n.loop = m_m.boundary_position[a].first;
  n.loop_position = double(m_m.boundary_position[a].second) + t;
  m_nodes.push_back(n);
  return m_nodes.size() - 1;
}

template <class Edges>
void Quad_net_builder::sort_around(std::size_t p, std::vector<std::size_t>& in, const Edges& edges) const
{
  const Eigen::Vector3d n = vertex_normal(m_nodes[p].vertex);
  Eigen::Vector3d x = n.unitOrthogonal(), y = n.cross(x);
  std::vector<std::pair<double, std::size_t>> a;
  for(std::size_t k : in)
  {
    const std::size_t o = edges[k].a == p ? edges[k].b : edges[k].a;
    const Eigen::Vector3d d = m_nodes[o].point - m_nodes[p].point;
    a.emplace_back(std::atan2(d.dot(y), d.dot(x)), k);
  }
  bool one_loop = true;
  for(std::size_t k : in)
  {
    const Node& o = m_nodes[edges[k].a == p ? edges[k].b : edges[k].a];
    const Node& f = m_nodes[edges[in[0]].a == p ? edges[in[0]].b : edges[in[0]].a];
    one_loop = one_loop && o.kind == Net_point_kind::crossing && o.curve == f.curve && m_iso[o.curve].closed;
  }
  if(one_loop) // lines from one loop: their order along it (see faces_of)
    for(std::size_t k = 0; k < in.size(); ++k)
      a[k].first = (edges[in[k]].a == p ? 1. : -1.) * m_nodes[edges[in[k]].a == p ? edges[in[k]].b : edges[in[k]].a].s;
  std::sort(a.begin(), a.end());
  for(std::size_t k = 0; k < in.size(); ++k)
    in[k] = a[k].second;
}

template <class Edges>
Polygon_soup Quad_net_builder::faces_of(Edges edges)
{
  const std::size_t nn = m_nodes.size();
  // remove dangling edges (a node of degree one) repeatedly
  for(;;)
  {
    std::vector<std::size_t> degree(nn, 0);
    for(const auto& e : edges)
      ++degree[e.a], ++degree[e.b];
    Edges kept;
    for(const auto& e : edges)
      if(e.a != e.b && degree[e.a] > 1 && degree[e.b] > 1)
        kept.push_back(e);
    if(kept.size() == edges.size())
      break;
    m_stats.removed_dangling_edges += edges.size() - kept.size();
    edges.swap(kept);
  }
  // rotation system: outgoing halfedges (2 e: a -> b, 2 e + 1: b -> a) sorted counter-clockwise
  std::vector<std::vector<std::pair<double, std::size_t>>> around(nn);
  auto direction_key = [&](std::size_t from, std::size_t to, Net_edge_kind kind, bool forward) -> double {
    const Node& n = m_nodes[from];
    if(n.kind == Net_point_kind::crossing)
    {
      // crossing: up (line, forward), next along the isoline, down, previous: 0, 1, 2, 3
      if(kind == Net_edge_kind::line)
        return forward ? 0. : 2.;
      return forward ? 1. : 3.;
    }
    // poles and boundary points: the angle of the chord in the tangent plane; on the boundary
    // measured from the direction along the loop (interior on the left)
    Eigen::Vector3d normal, x;
    if(n.kind == Net_point_kind::pole && n.loop == npos)
    {
      normal = vertex_normal(n.vertex);
      x = normal.unitOrthogonal();
    }
    else
    {
      if(kind == Net_edge_kind::boundary)
        return forward ? 0. : 10.; // next along the loop first, previous last
      normal = boundary_normal(n);
      x = boundary_tangent(n);
    }
    const Eigen::Vector3d y = normal.cross(x);
    const Eigen::Vector3d d = m_nodes[to].point - n.point;
    double a = std::atan2(d.dot(y), d.dot(x));
    if(!std::isfinite(a))
      a = 0.;
    if(n.loop != npos) // interior directions lie between the two loop directions (keys 0 and 10);
      a = std::clamp(a, 1e-3, 3.) + 1e-6 * a; // chords leaving a concave boundary keep their order
    else if(a < 0.)
      a += 2. * 3.141592653589793;
    return a;
  };
  for(std::size_t e = 0; e < edges.size(); ++e)
  {
    const double ka = edges[e].key_a, kb = edges[e].key_b;
    around[edges[e].a].emplace_back(ka == ka ? ka : direction_key(edges[e].a, edges[e].b, edges[e].kind, true), 2 * e);
    around[edges[e].b].emplace_back(kb == kb ? kb : direction_key(edges[e].b, edges[e].a, edges[e].kind, false), 2 * e + 1);
  }
  // the lines into a pole from one loop come in the order of their sources along that loop
  // (more reliable than the angles of the chords)
  auto other_end = [&](std::size_t h) { return h % 2 == 0 ? edges[h / 2].b : edges[h / 2].a; };
  for(std::size_t n = 0; n < nn; ++n)
  {
    auto& r = around[n];
    const Node& node = m_nodes[n];
    if(node.kind == Net_point_kind::pole && node.loop == npos && !r.empty())
    {
      bool one_loop = true;
      const Node& first = m_nodes[other_end(r[0].second)];
      for(const auto& [key, h] : r)
      {
        const Node& o = m_nodes[other_end(h)];
        one_loop = one_loop && o.kind == Net_point_kind::crossing && o.curve == first.curve && m_iso[o.curve].closed;
      }
      // a loop runs counter-clockwise around a minimum (lower values on its left), clockwise
      // around a maximum; halfedge 2e leaves the lower end of a line
      if(one_loop)
        for(auto& [key, h] : r)
          key = (h % 2 == 0 ? 1. : -1.) * m_nodes[other_end(h)].s;
    }
  }
  std::vector<std::size_t> position(2 * edges.size());
  for(auto& r : around)
  {
    std::sort(r.begin(), r.end());
    for(std::size_t k = 0; k < r.size(); ++k)
      position[r[k].second] = k;
  }
  auto source = [&](std::size_t h) { return h % 2 == 0 ? edges[h / 2].a : edges[h / 2].b; };
  auto target = [&](std::size_t h) { return h % 2 == 0 ? edges[h / 2].b : edges[h / 2].a; };
  auto next = [&](std::size_t h) {
    const std::size_t t = h ^ 1, b = target(h);
    const auto& r = around[b];
    return r[(position[t] + r.size() - 1) % r.size()].second;
  };
  // renumber the nodes that are used
  std::vector<std::size_t> new_id(nn, npos);
  Polygon_soup soup;
  std::vector<char> visited(2 * edges.size(), 0);
  for(std::size_t h = 0; h < 2 * edges.size(); ++h)
  {
    // the outside of a boundary edge (b -> a for a loop edge a -> b) bounds no face
    if(edges[h / 2].kind == Net_edge_kind::boundary && h % 2 == 1)
      visited[h] = 1;
  }
  for(std::size_t h0 = 0; h0 < 2 * edges.size(); ++h0)
  {
    if(visited[h0])
      continue;
    std::vector<std::size_t> face;
    std::size_t h = h0;
    bool outside = false;
    for(std::size_t guard = 0; guard <= 2 * edges.size(); ++guard)
    {
      if(visited[h])
      {
        outside = outside || h != h0;
        break;
      }
      visited[h] = 1;
      face.push_back(source(h));
      h = next(h);
    }
    if(outside || face.size() < 3)
    {
      ++m_stats.lost_lines;
      continue;
    }
    for(std::size_t& v : face)
    {
      if(new_id[v] == npos)
      {
        new_id[v] = soup.points.size();
        soup.points.push_back(m_nodes[v].point);
        soup.kind.push_back(m_nodes[v].kind);
      }
      v = new_id[v];
    }
    soup.faces.push_back(std::move(face));
  }
  return soup;
}

inline Eigen::Vector3d Quad_net_builder::boundary_tangent(const Node& n) const
{
  const auto& loop = m_m.boundary_loop[n.loop];
  const std::size_t k = std::size_t(n.loop_position) % loop.size();
  const double frac = n.loop_position - std::floor(n.loop_position);
  const std::size_t a = loop[k], b = loop[(k + 1) % loop.size()];
  Eigen::Vector3d t = m_m.point[b] - m_m.point[a];
  if(frac < 1e-12) // at a vertex: the mean of the two boundary edges
    t = t.normalized() + (m_m.point[a] - m_m.point[loop[(k + loop.size() - 1) % loop.size()]]).normalized();
  const Eigen::Vector3d nn = boundary_normal(n);
  const Eigen::Vector3d tangent = t - t.dot(nn) * nn;
  return tangent.norm() > 0. ? tangent.normalized() : nn.unitOrthogonal();
}

} // namespace harmonic_quad
} // namespace internal
} // namespace Surface_design
} // namespace CGAL

#endif // CGAL_SURFACE_DESIGN_INTERNAL_HARMONIC_QUAD_REMESHING_QUAD_NET_ASSEMBLY_H
