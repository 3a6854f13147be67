// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The net of isolines and gradient lines, one phase of `Quad_net_builder` (declared in
// quad_net_builder.h): tracing the gradient lines from isoline to isoline, and the lines of
// spectacles (bridge and junction lines).

#ifndef CGAL_SURFACE_DESIGN_INTERNAL_HARMONIC_QUAD_REMESHING_QUAD_NET_TRACING_H
#define CGAL_SURFACE_DESIGN_INTERNAL_HARMONIC_QUAD_REMESHING_QUAD_NET_TRACING_H

#include <CGAL/Surface_design/internal/Harmonic_quad_remeshing/quad_net_builder.h>

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <map>
#include <numeric>
#include <optional>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_design {
namespace internal {
namespace harmonic_quad {

inline void Quad_net_builder::trace_lines()
{
  m_crossings.assign(m_iso.size(), {});
  Gradient_walker walker(m_m, m_u, m_levels_in_face, &m_iso);
  std::vector<std::size_t> order(m_iso.size());
  std::iota(order.begin(), order.end(), std::size_t(0));
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return m_iso[a].value < m_iso[b].value; });
  m_processed.assign(m_iso.size(), 0);
  for(std::size_t k = 0; k < m_spectacles_curves.size(); ++k)
    spectacles_lines(k, walker);
  for(std::size_t c : order)
  {
    if(m_iso[c].role == Curve_role::spectacles_bridge) // a bridge: its nodes and lines are made by spectacles_lines()
    {
      m_processed[c] = 1;
      continue;
    }
    space_crossings(c);
    // node ids fixed here; descending lines that land on this isoline later get theirs in
    // end_node()
    finalize_crossings(c);
    m_processed[c] = 1;
    const Isoline& iso = m_iso[c];
    const bool down = !m_trace_down.empty() && m_trace_down.back() == c;
    for(std::size_t k = 0; k < m_crossings[c].size(); ++k)
    {
      Crossing& x = m_crossings[c][k];
      const std::size_t seg = iso.at(x.s).second;
      const std::size_t node = x.node;
      const Eigen::Vector3d point = x.point;
      const bool up = x.up;
      if(down && x.down == npos)
      {
        // (end_node may add crossings to a lower isoline: `x` is not used after it)
        const std::size_t id = end_node(walker.from_face(iso.faces[seg], point, iso.value, -1), node);
        if(id != npos)
          m_line_edges.emplace_back(id, node);
        ++m_stats.gradient_lines;
      }
      if(up && !x.no_trace)
      {
        const std::size_t id = end_node(walker.from_face(iso.faces[seg], point, iso.value, +1), node);
        if(id != npos)
          m_line_edges.emplace_back(node, id);
        ++m_stats.gradient_lines;
      }
    }
  }
}

inline std::size_t Quad_net_builder::landing_from_above(const Trace_end& e)
{
  if(e.kind == Trace_end::isoline && m_iso[e.curve].role != Curve_role::spectacles_bridge)
  {
    Crossing c;
    c.s = m_iso[e.curve].nearest_arc_position(e.segment, e.point);
    c.point = e.point;
    c.up = c.fixed = c.no_trace = true;
    c.pending.push_back(m_pending_node.size());
    m_pending_node.push_back(npos);
    m_crossings[e.curve].push_back(c);
    return pending_bit | c.pending.back();
  }
  return node_for_end(e, npos);
}

inline void Quad_net_builder::spectacles_line(std::size_t from, double key, std::size_t f, const Eigen::Vector3d& p, double value, int sigma,
                     const Gradient_walker& walker)
{
  const Trace_end e = walker.from_face(f, p, value, sigma);
  ++m_stats.spectacles_lines;
  if(sigma > 0)
  {
    const bool onto_isoline = e.kind == Trace_end::isoline && m_iso[e.curve].role != Curve_role::spectacles_bridge;
    const std::size_t id = node_for_end(e, from);
    if(id == npos)
      return;
    if(onto_isoline)
      m_crossings[e.curve].back().keep = true;
    m_keyed_edges.push_back({from, id, Net_edge_kind::line, key, std::numeric_limits<double>::quiet_NaN()});
  }
  else
  {
    const std::size_t id = landing_from_above(e);
    if(id != npos)
      m_keyed_edges.push_back({id, from, Net_edge_kind::line, std::numeric_limits<double>::quiet_NaN(), key});
  }
}

inline std::optional<std::pair<std::size_t, Eigen::Vector3d>>
Quad_net_builder::sector_start(std::size_t v, const Vertex_sector& sector, double value, int sigma, double step) const
{
  // the faces of the sector by their distance from the bisector's face
  std::vector<std::size_t> order(sector.faces.size());
  std::iota(order.begin(), order.end(), std::size_t(0));
  std::stable_sort(order.begin(), order.end(), [&](std::size_t x, std::size_t y) {
    const auto dx = x > sector.middle ? x - sector.middle : sector.middle - x;
    const auto dy = y > sector.middle ? y - sector.middle : sector.middle - y;
    return dx < dy;
  });
  for(const std::size_t k : order)
  {
    const auto [f, corner] = sector.faces[k];
    const std::size_t a = m_m.tri[f][(corner + 1) % 3], b = m_m.tri[f][(corner + 2) % 3];
    const double sa = sigma * (m_u[a] - value), sb = sigma * (m_u[b] - value);
    if(sa < 0. || sb < 0. || !(sa > 0. || sb > 0.))
      continue; // not the side of the bridge (squeezed between the curves), or flat at the level
    const Eigen::Vector3d da = m_m.point[a] - m_m.point[v], db = m_m.point[b] - m_m.point[v];
    // the fraction of the angle from a towards b (counter-clockwise); off the bisector's face, its middle
    const double fraction = k == sector.middle ? sector.fraction : 0.5;
    const double t = sector.ccw ? fraction : 1. - fraction;
    const Eigen::Vector3d d = (1. - t) * da.normalized() + t * db.normalized();
    // Close to v: the net's edge is the chord from the junction to where the line lands, so the
    // start must lie before the first isoline beyond the spectacles (else the chord jumps over
    // isolines, the curves of the net cross and the net gains a handle: found on a coarse slab
    // whose faces are many h wide); inside f: less than half its shorter edge at v.
    double lambda = (std::min)(0.1 * m_opt.edge_length, 0.5 * (std::min)(da.norm(), db.norm()));
    const Eigen::Vector3d u_corners(m_u[m_m.tri[f][0]], m_u[m_m.tri[f][1]], m_u[m_m.tri[f][2]]);
    Eigen::Vector3d start = m_m.point[v] + lambda * d;
    for(int halving = 0; halving < 30 && step > 0. &&
                         std::abs(m_m.barycentric(f, start).dot(u_corners) - value) >= 0.25 * step;
        ++halving)
    {
      lambda *= 0.5;
      start = m_m.point[v] + lambda * d;
    }
    return std::make_pair(f, start);
  }
  return std::nullopt;
}

inline void Quad_net_builder::spectacles_lines(std::size_t k, const Gradient_walker& walker)
{
  const Net_spectacles& sp = m_opt.spectacles[k];
  const Spectacles_curves& sc = m_spectacles_curves[k];
  const double h = m_opt.edge_length;
  std::array<std::size_t, 2> junction_code;
  for(int j = 0; j < 2; ++j)
  {
    const auto& frame = sp.frame[std::size_t(j)];
    const std::size_t at = std::size_t(std::find(frame.begin(), frame.end(), sp.junction[std::size_t(j)]) - frame.begin());
    const Isoline& iso = m_iso[sc.frame[std::size_t(j)]];
    Crossing c;
    c.s = iso.arc[at];
    c.point = iso.point[at];
    c.up = c.fixed = true;
    c.no_trace = sp.sigma > 0; // above a valley junction: the bridge and the two sector lines
    c.pending.push_back(m_pending_node.size());
    m_pending_node.push_back(npos);
    m_crossings[sc.frame[std::size_t(j)]].push_back(c);
    junction_code[std::size_t(j)] = pending_bit | c.pending.back();
  }
  // bridge nodes
  const Isoline& bridge = m_iso[sc.bridge];
  // Bridge nodes at equal flux of grad u across the bridge (both sides averaged), as in the
  // (u, psi) net: the lines do not crowd where u hardly rises from the bridge (near the saddle).
  std::vector<double> flux{0.}; // cumulative, at every bridge vertex
  for(std::size_t j = 0; j + 1 < sp.bridge.size(); ++j)
  {
    const std::size_t a = sp.bridge[j], b = sp.bridge[j + 1];
    double g = 0.;
    int sides = 0;
    for(const auto& [f, i] : m_m.star[a])
      if(m_m.tri[f][(i + 1) % 3] == b || m_m.tri[f][(i + 2) % 3] == b)
      {
        g += m_grad_norm[f];
        ++sides;
      }
    flux.push_back(flux.back() + (sides > 0 ? g / sides : 0.) * (m_m.point[b] - m_m.point[a]).norm());
  }
  double step = 0.; // to the next level beyond the bridge
  for(double c : m_opt.levels)
    if(sp.sigma * (c - sp.value) > 0. && (step == 0. || std::abs(c - sp.value) < step))
      step = std::abs(c - sp.value);
  // (the count: the mean of the equal-flux count and the count at spacing h, which measured
  // best on eight, kitten, torus, double torus, fertility and bunny: fewer non-quads near the
  // saddles than either alone)
  const double by_length = bridge.length() / h;
  const double count = step > 0. ? 0.5 * (flux.back() / step + by_length) : by_length;
  const std::size_t parts = (std::max)(std::size_t(1), std::size_t(std::lround(count)));
  auto arc_at_flux = [&](double phi) { // the arc-length position where the flux reaches phi
    std::size_t j = std::size_t(std::upper_bound(flux.begin(), flux.end(), phi) - flux.begin());
    j = std::clamp<std::size_t>(j, 1, flux.size() - 1);
    const double t = flux[j] > flux[j - 1] ? (phi - flux[j - 1]) / (flux[j] - flux[j - 1]) : 0.5;
    return bridge.arc[j - 1] + t * (bridge.arc[j] - bridge.arc[j - 1]);
  };
  std::vector<std::size_t> chain{junction_code[0]};
  const double junction_key = sp.sigma > 0 ? 0. : 2.; // the bridge leaves a junction away from the frame's inside
  for(std::size_t j = 1; j < parts; ++j)
  {
    const auto [p, seg] = bridge.at(step > 0. ? arc_at_flux(flux.back() * double(j) / double(parts))
                                              : bridge.length() * double(j) / double(parts));
    Node n;
    n.point = p;
    n.kind = Net_point_kind::bridge;
    n.curve = sc.bridge;
    m_nodes.push_back(n);
    const std::size_t id = m_nodes.size() - 1;
    chain.push_back(id);
    // the faces on the right (key 0) and on the left (key 2) of the bridge segment
    const std::size_t a = sp.bridge[seg], b = sp.bridge[seg + 1];
    for(const auto& [f, i] : m_m.star[a])
    {
      const bool right = m_m.tri[f][(i + 2) % 3] == b; // holds b -> a
      const bool left = m_m.tri[f][(i + 1) % 3] == b;  // holds a -> b
      if(right || left)
        spectacles_line(id, right ? 0. : 2., f, p, sp.value, sp.sigma, walker);
    }
  }
  chain.push_back(junction_code[1]);
  for(std::size_t j = 0; j + 1 < chain.size(); ++j)
    m_keyed_edges.push_back({chain[j], chain[j + 1], Net_edge_kind::bridge, j == 0 ? junction_key : 1.,
                             j + 2 == chain.size() ? junction_key : 3.});
  // the lines into the two sectors at each junction, each along the sector's bisector
  for(int j = 0; j < 2; ++j)
  {
    const std::size_t v = sp.junction[std::size_t(j)];
    const auto& frame = sp.frame[std::size_t(j)];
    const std::size_t at = std::size_t(std::find(frame.begin(), frame.end(), v) - frame.begin());
    const std::size_t next = frame[(at + 1) % frame.size()], prev = frame[(at + frame.size() - 1) % frame.size()];
    const std::size_t along = j == 0 ? sp.bridge[1] : sp.bridge[sp.bridge.size() - 2];
    for(const bool ccw : {true, false})
    {
      // the sector between the bridge and the frame's first vertex met turning from it
      const Vertex_sector sector = vertex_sector(m_m, v, along, {next, prev}, ccw);
      const auto start = sector.end == npos ? std::nullopt : sector_start(v, sector, sp.value, sp.sigma, step);
      if(!start)
        continue;
      const auto [f, p] = *start;
      const auto& t = m_m.tri[f];
      const double start_value = m_m.barycentric(f, p).dot(Eigen::Vector3d(m_u[t[0]], m_u[t[1]], m_u[t[2]]));
      // rotation key at the junction: between the bridge and the frame's next (prev) direction
      const bool next_side = sector.end == next;
      const double key = sp.sigma > 0 ? (next_side ? 0.5 : 3.5) : (next_side ? 1.5 : 2.5);
      spectacles_line(junction_code[std::size_t(j)], key, f, p, start_value, sp.sigma, walker);
    }
  }
}

inline std::size_t Quad_net_builder::end_node(const Trace_end& e, std::size_t from)
{
  if(e.kind == Trace_end::isoline && m_processed[e.curve] && m_iso[e.curve].role != Curve_role::spectacles_bridge)
  {
    Crossing x;
    x.s = m_iso[e.curve].nearest_arc_position(e.segment, e.point);
    x.point = e.point;
    Node n;
    n.point = e.point;
    n.kind = Net_point_kind::crossing;
    n.curve = e.curve;
    n.s = x.s;
    m_nodes.push_back(n);
    x.node = m_nodes.size() - 1;
    m_crossings[e.curve].push_back(x);
    return x.node;
  }
  return node_for_end(e, from);
}

} // namespace harmonic_quad
} // namespace internal
} // namespace Surface_design
} // namespace CGAL

#endif // CGAL_SURFACE_DESIGN_INTERNAL_HARMONIC_QUAD_REMESHING_QUAD_NET_TRACING_H
