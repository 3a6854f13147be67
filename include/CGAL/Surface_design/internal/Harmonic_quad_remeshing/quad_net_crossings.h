// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The net of isolines and gradient lines, one phase of `Quad_net_builder` (declared in
// quad_net_builder.h): where the gradient lines cross an isoline, and their spacing: nodes for the
// ends of traced lines, the fences along an isoline, lines stopped where they crowd and started
// in wide gaps, merged into spectacles lines, untangled so that they keep their order.

#ifndef CGAL_SURFACE_DESIGN_INTERNAL_HARMONIC_QUAD_REMESHING_QUAD_NET_CROSSINGS_H
#define CGAL_SURFACE_DESIGN_INTERNAL_HARMONIC_QUAD_REMESHING_QUAD_NET_CROSSINGS_H

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

inline std::size_t Quad_net_builder::node_for_end(const Trace_end& e, std::size_t from_node)
{
  if(e.kind == Trace_end::isoline && m_iso[e.curve].role == Curve_role::spectacles_bridge)
  {
    ++m_stats.merged_lines; // a line that reaches a bridge ends one isoline early
    return npos;
  }
  switch(e.kind)
  {
  case Trace_end::isoline: {
    Crossing c;
    c.s = m_iso[e.curve].nearest_arc_position(e.segment, e.point);
    c.point = e.point;
    c.down = from_node;
    c.pending.push_back(m_pending_node.size());
    m_pending_node.push_back(npos);
    m_crossings[e.curve].push_back(c);
    return pending_bit | c.pending.back();
  }
  case Trace_end::pole: {
    auto it = m_pole_node.find(e.vertex);
    if(it != m_pole_node.end())
      return it->second;
    Node n;
    n.point = e.point;
    n.kind = Net_point_kind::pole;
    n.vertex = e.vertex;
    if(m_m.on_boundary[e.vertex])
    {
      n.loop = m_m.boundary_position[e.vertex].first;
      n.loop_position = double(m_m.boundary_position[e.vertex].second);
    }
    m_nodes.push_back(n);
    m_pole_node[e.vertex] = m_nodes.size() - 1;
    return m_nodes.size() - 1;
  }
  case Trace_end::boundary: {
    Node n;
    n.point = e.point;
    n.kind = Net_point_kind::boundary;
    n.loop = e.loop;
    n.loop_position = e.loop_position;
    m_nodes.push_back(n);
    return m_nodes.size() - 1;
  }
  default:
    ++m_stats.lost_lines;
    return npos;
  }
}

inline Quad_net_builder::Fences Quad_net_builder::fences(const Isoline& iso, const std::vector<Crossing>& cr) const
{
  Fences f;
  f.length = iso.length();
  f.closed = iso.closed;
  if(!iso.closed)
  {
    f.pos.push_back(0.);
    f.who.push_back(npos);
  }
  for(std::size_t k = 0; k < cr.size(); ++k)
    if(cr[k].up)
    {
      f.pos.push_back(cr[k].s);
      f.who.push_back(k);
    }
  if(!iso.closed)
  {
    f.pos.push_back(iso.length());
    f.who.push_back(npos);
  }
  // crossings added by add_crossing() come last: sort by position
  std::vector<std::size_t> order(f.pos.size());
  std::iota(order.begin(), order.end(), std::size_t(0));
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return f.pos[a] < f.pos[b]; });
  Fences sorted = f;
  for(std::size_t k = 0; k < order.size(); ++k)
  {
    sorted.pos[k] = f.pos[order[k]];
    sorted.who[k] = f.who[order[k]];
  }
  return sorted;
}

inline void Quad_net_builder::add_crossing(std::size_t c, double s)
{
  const Isoline& iso = m_iso[c];
  auto& cr = m_crossings[c];
  const double h = m_opt.edge_length;
  if(iso.closed)
    s = std::fmod(s, iso.length());
  for(Crossing& x : cr) // revive a stopped crossing near the spot rather than adding one
    if(!x.up && std::abs(wrapped(x.s - s, iso.length(), iso.closed)) < 0.25 * h)
    {
      x.up = true;
      --m_stats.stopped_lines;
      return;
    }
  Crossing x;
  x.s = s;
  x.point = iso.at(s).first;
  x.up = true;
  cr.push_back(x);
  ++m_stats.started_lines;
}

inline void Quad_net_builder::space_crossings(std::size_t c)
{
  const Isoline& iso = m_iso[c];
  auto& cr = m_crossings[c];
  const double L = iso.length();
  if(cr.empty())
  {
    // a first isoline (around a minimum or above a boundary): evenly spaced lines, traced both
    // ways; an even number on a loop, so that the fan at the pole below becomes quads
    // (at equal steps of the number of cells, the integral of ds / local h, when the spacing varies)
    std::vector<double> cells(iso.segments() + 1, 0.);
    for(std::size_t j = 0; j < iso.segments(); ++j)
      cells[j + 1] = cells[j] + (iso.arc[j + 1] - iso.arc[j]) / local_h_on_segment(iso, j);
    const double total = cells.back();
    std::size_t n = std::size_t(std::lround(total));
    if(iso.closed)
      n = (std::max)(n + n % 2, std::size_t(4));
    for(std::size_t k = iso.closed ? 0 : 1; k < n; ++k)
    {
      if(!(total > 0.) || iso.segments() == 0)
      {
        add_crossing(c, double(k) * L / double(n));
        continue;
      }
      const double target = double(k) * total / double(n);
      std::size_t j = std::size_t(std::upper_bound(cells.begin(), cells.end(), target) - cells.begin());
      j = j == 0 ? 0 : (std::min)(j - 1, iso.segments() - 1);
      const double span = cells[j + 1] - cells[j];
      const double t = span > 0. ? std::clamp((target - cells[j]) / span, 0., 1.) : 0.;
      add_crossing(c, iso.arc[j] + t * (iso.arc[j + 1] - iso.arc[j]));
    }
    m_trace_down.push_back(c);
    return;
  }
  bool arrivals = false;
  for(Crossing& x : cr)
  {
    x.up = true;
    arrivals = arrivals || x.down != npos;
  }
  if(!arrivals) // only lines from spectacles above: a first isoline, traced downwards too
    m_trace_down.push_back(c);
  untangle_arrivals(c);
  merge_into_spectacles_lines(c);
  // a loop reached by fewer than two lines (one side of a splitting saddle) would hang on a
  // single line, a slit inside one face: its new lines are traced downwards as well
  if(iso.closed && cr.size() < 2)
    m_trace_down.push_back(c);
  std::stable_sort(cr.begin(), cr.end(), [](const Crossing& a, const Crossing& b) { return a.s < b.s; });
  // stop lines that come too close to a neighbour (or to the boundary): at the smallest gap,
  // the line whose other gap is the smaller one
  for(;;)
  {
    const Fences f = fences(iso, cr);
    const std::size_t live = iso.closed ? f.size() : f.size() - 2;
    if(live == 0 || (iso.closed && live <= 3))
      break;
    // the smallest gap with a line that may stop at one of its ends (not the boundary, not
    // a spectacles line)
    auto movable = [&](std::size_t k) { return f.who[k] != npos && !cr[f.who[k]].fixed; };
    std::size_t k = npos;
    for(std::size_t j = 0; j < f.gaps(); ++j)
      if((movable(j) || movable((j + 1) % f.size())) && (k == npos || f.gap(j) < f.gap(k)))
        k = j;
    if(k == npos || !(f.gap(k) < m_opt.min_spacing * local_h_at(iso, f.pos[k] + 0.5 * f.gap(k))))
      break;
    const std::size_t left = k, right = (k + 1) % f.size();
    const std::size_t left_other = iso.closed ? (k + f.gaps() - 1) % f.gaps() : k - 1; // gap before `left`
    const std::size_t right_other = iso.closed ? (k + 1) % f.gaps() : k + 1;             // gap after `right`
    std::size_t victim;
    if(!movable(left))
      victim = f.who[right];
    else if(!movable(right))
      victim = f.who[left];
    else
      victim = f.gap(left_other) < f.gap(right_other) ? f.who[left] : f.who[right];
    cr[victim].up = false;
    ++m_stats.stopped_lines;
  }
  // start lines in gaps that are too wide
  const Fences f = fences(iso, cr);
  for(std::size_t k = 0; k < f.gaps(); ++k)
  {
    const double g = f.gap(k), here = local_h_at(iso, f.pos[k] + 0.5 * g);
    if(!(g > m_opt.max_spacing * here))
      continue;
    const std::size_t parts = (std::max)(std::size_t(2), std::size_t(std::lround(g / here)));
    for(std::size_t j = 1; j < parts; ++j)
      add_crossing(c, f.pos[k] + double(j) * g / double(parts));
  }
  // at least three lines around a loop
  for(;;)
  {
    const Fences g = fences(iso, cr);
    if(!iso.closed || g.size() >= 3)
      break;
    std::size_t k = 0;
    for(std::size_t j = 1; j < g.gaps(); ++j)
      if(g.gap(j) > g.gap(k))
        k = j;
    add_crossing(c, g.pos[k] + 0.5 * g.gap(k));
  }
}

inline void Quad_net_builder::merge_into_spectacles_lines(std::size_t c)
{
  auto& cr = m_crossings[c];
  const Isoline& iso = m_iso[c];
  const std::size_t n = cr.size();
  std::vector<char> gone(n, 0);
  // (`cr` is sorted along the isoline) the line may only join a neighbour along the isoline,
  // the first crossing on either side that has not joined another: a farther one would cross
  // the lines between them (found on the triceratops: two lines from below, each joined to the
  // spectacles line nearer the other one's, crossed and gave the net a handle)
  auto neighbour = [&](std::size_t k, bool forward) {
    for(std::size_t step = 1; step < n; ++step)
    {
      if(!iso.closed && (forward ? k + step >= n : step > k))
        return npos;
      const std::size_t j = forward ? (k + step) % n : (k + n - step) % n;
      if(!gone[j])
        return j;
    }
    return npos;
  };
  for(std::size_t i = 0; i < n; ++i)
  {
    Crossing& x = cr[i];
    if(!x.fixed || !x.no_trace || x.down != npos)
      continue;
    std::size_t best = npos;
    double distance = 0.5 * m_opt.edge_length;
    for(const bool forward : {false, true})
    {
      const std::size_t k = neighbour(i, forward);
      if(k == npos)
        continue;
      const double d = std::abs(wrapped(cr[k].s - x.s, iso.length(), iso.closed));
      if(!cr[k].fixed && cr[k].down != npos && d < distance)
      {
        distance = d;
        best = k;
      }
    }
    if(best == npos)
      continue;
    x.down = cr[best].down;
    x.pending.insert(x.pending.end(), cr[best].pending.begin(), cr[best].pending.end());
    gone[best] = 1;
  }
  std::vector<Crossing> kept;
  for(std::size_t k = 0; k < cr.size(); ++k)
    if(!gone[k])
      kept.push_back(cr[k]);
  cr.swap(kept);
}

inline void Quad_net_builder::finalize_crossings(std::size_t c)
{
  auto& cr = m_crossings[c];
  std::stable_sort(cr.begin(), cr.end(), [](const Crossing& a, const Crossing& b) { return a.s < b.s; });
  for(Crossing& x : cr)
  {
    Node n;
    n.point = x.point;
    n.kind = Net_point_kind::crossing;
    n.curve = c;
    n.s = x.s;
    m_nodes.push_back(n);
    x.node = m_nodes.size() - 1;
    for(std::size_t p : x.pending)
      m_pending_node[p] = x.node;
  }
}

inline void Quad_net_builder::untangle_arrivals(std::size_t c)
{
  const Isoline& iso = m_iso[c];
  auto& cr = m_crossings[c];
  const double L = iso.length();
  std::map<std::size_t, std::vector<std::size_t>> by_source;
  for(std::size_t k = 0; k < cr.size(); ++k)
    if(!cr[k].keep && !cr[k].fixed && cr[k].down != npos && !(cr[k].down & pending_bit) &&
       m_nodes[cr[k].down].kind == Net_point_kind::crossing)
      by_source[m_nodes[cr[k].down].curve].push_back(k);
  for(auto& entry : by_source)
  {
    std::vector<std::size_t>& lines = entry.second;
    const std::size_t n = lines.size();
    if(n < 2)
      continue;
    std::vector<double> landing;
    for(std::size_t k : lines)
      landing.push_back(cr[k].s);
    std::sort(landing.begin(), landing.end());
    std::sort(lines.begin(), lines.end(), [&](std::size_t a, std::size_t b) {
      return m_nodes[cr[a].down].s < m_nodes[cr[b].down].s;
    });
    std::size_t best_shift = 0;
    double best = std::numeric_limits<double>::infinity();
    // a loop has no first line: when the source or the target is a loop, the order holds up to
    // a cyclic shift; between two paths it is the order itself
    const bool cyclic = iso.closed || m_iso[entry.first].closed;
    for(std::size_t shift = 0; shift < (cyclic ? n : 1); ++shift)
    {
      double cost = 0.;
      for(std::size_t j = 0; j < n; ++j)
        cost += std::abs(wrapped(landing[(j + shift) % n] - cr[lines[j]].s, L, iso.closed));
      if(cost < best)
      {
        best = cost;
        best_shift = shift;
      }
    }
    for(std::size_t j = 0; j < n; ++j)
    {
      const double t = landing[(j + best_shift) % n];
      if(t != cr[lines[j]].s)
      {
        cr[lines[j]].s = t;
        cr[lines[j]].point = iso.at(t).first;
        ++m_stats.reordered_lines;
      }
    }
  }
  std::stable_sort(cr.begin(), cr.end(), [](const Crossing& a, const Crossing& b) { return a.s < b.s; });
  // a line that lands where another one landed (they met at a vertex or along an edge) ends
  // one isoline earlier: its source becomes a T-junction
  const double tie = 1e-3 * m_opt.edge_length;
  std::vector<Crossing> kept;
  for(const Crossing& x : cr)
    if(kept.empty() || x.s - kept.back().s >= tie)
      kept.push_back(x);
    else
    {
      if(x.fixed && !kept.back().fixed)
        kept.back() = x; // spectacles first
      ++m_stats.merged_lines;
    }
  if(iso.closed && kept.size() > 1 && kept.front().s + L - kept.back().s < tie) // across the seam
  {
    if(kept.back().fixed && !kept.front().fixed)
      kept.front() = kept.back();
    kept.pop_back();
    ++m_stats.merged_lines;
  }
  cr.swap(kept);
}

} // namespace harmonic_quad
} // namespace internal
} // namespace Surface_design
} // namespace CGAL

#endif // CGAL_SURFACE_DESIGN_INTERNAL_HARMONIC_QUAD_REMESHING_QUAD_NET_CROSSINGS_H
