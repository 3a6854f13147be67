// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The net of isolines and gradient lines, one phase of `Quad_net_builder` (declared in
// quad_net_builder.h): the levels of the isolines: regular levels h apart (adaptively, by the
// median gradient norm), the spectacles' curves, extra levels near the boundary, in wide bands
// and between saddles that share a band.

#ifndef CGAL_SURFACE_DESIGN_INTERNAL_HARMONIC_QUAD_REMESHING_QUAD_NET_LEVELS_H
#define CGAL_SURFACE_DESIGN_INTERNAL_HARMONIC_QUAD_REMESHING_QUAD_NET_LEVELS_H

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

inline double Quad_net_builder::weighted_quantile(std::vector<std::pair<double, double>>& g, double q)
{
  if(g.empty())
    return 0.;
  std::sort(g.begin(), g.end());
  double total = 0.;
  for(const auto& x : g)
    total += x.second;
  double acc = 0.;
  for(const auto& x : g)
    if((acc += x.second) >= q * total)
      return x.first;
  return g.back().first;
}

inline double Quad_net_builder::median_gradient_at(double c) const
{
  std::vector<std::pair<double, double>> g; // (|grad u|, segment length)
  for(std::size_t f = 0; f < m_m.number_of_faces(); ++f)
  {
    const auto& t = m_m.tri[f];
    const double lo = (std::min)({m_u[t[0]], m_u[t[1]], m_u[t[2]]});
    const double hi = (std::max)({m_u[t[0]], m_u[t[1]], m_u[t[2]]});
    if(lo < c && c < hi)
    {
      const double gn = m_grad_norm[f];
      g.emplace_back(gn, std::sqrt(m_m.area[f])); // weight ~ the length of the level in f
    }
  }
  return weighted_quantile(g, 0.5);
}

inline std::vector<double> Quad_net_builder::regular_levels()
{
  compute_gradient_norms();
  std::vector<double> sorted(m_u);
  std::sort(sorted.begin(), sorted.end());
  const double lo = sorted.front(), hi = sorted.back(), range = hi - lo;
  const double gap = 1e-9 * range;
  const double h = m_opt.edge_length;
  std::vector<double> out;
  double c = lo;
  for(std::size_t guard = 0; guard < 100000; ++guard)
  {
    double g = median_gradient_at(avoid_vertex_values(c + gap, sorted, gap));
    if(!(g > 0.))
      break;
    const double mid = c + 0.5 * h * g; // midpoint rule: the gradient varies within a step
    const double gm = median_gradient_at(avoid_vertex_values(mid, sorted, gap));
    if(gm > 0.)
      g = gm;
    c = avoid_vertex_values(c + h * g, sorted, gap);
    if(c >= hi - gap)
      break;
    out.push_back(c);
  }
  return out;
}

inline void Quad_net_builder::include_spectacles(std::size_t k)
{
  const Net_spectacles& sp = m_opt.spectacles[k];
  auto curve = [&](const std::vector<std::size_t>& chain, bool closed, Curve_role role) {
    Isoline iso;
    iso.value = sp.value;
    iso.closed = closed;
    iso.role = role;
    const std::size_t n = chain.size();
    for(std::size_t j = 0; j < (closed ? n : n - 1); ++j)
    {
      const std::size_t a = chain[j], b = chain[(j + 1) % n];
      // the face on the higher side of a -> b (the one holding b -> a): lines leave from there
      std::size_t face = npos, any = npos;
      for(const auto& [f, i] : m_m.star[b])
        if(m_m.tri[f][(i + 1) % 3] == a || m_m.tri[f][(i + 2) % 3] == a)
        {
          any = f;
          if(m_m.tri[f][(i + 1) % 3] == a)
            face = f;
        }
      iso.faces.push_back(face != npos ? face : any);
      iso.point.push_back(m_m.point[a]);
      iso.point_edge.push_back(npos);
    }
    if(!closed)
    {
      iso.point.push_back(m_m.point[chain.back()]);
      iso.point_edge.push_back(npos);
    }
    iso.arc.assign(1, 0.);
    for(std::size_t j = 0; j < iso.segments(); ++j)
      iso.arc.push_back(iso.arc.back() + (iso.segment_end(j) - iso.point[j]).norm());
    const std::size_t id = m_iso.size();
    for(std::size_t j = 0; j < (closed ? n : n - 1); ++j)
      for(const auto& [f, i] : m_m.star[chain[j]])
        m_levels_in_face[f].push_back({sp.value, id, j});
    if(!closed)
      for(const auto& [f, i] : m_m.star[chain.back()])
        m_levels_in_face[f].push_back({sp.value, id, n - 2});
    m_iso.push_back(std::move(iso));
    return id;
  };
  Spectacles_curves c;
  c.frame[0] = curve(sp.frame[0], true, Curve_role::spectacles_frame);
  c.frame[1] = curve(sp.frame[1], true, Curve_role::spectacles_frame);
  c.bridge = curve(sp.bridge, false, Curve_role::spectacles_bridge);
  m_spectacles_curves.resize(m_opt.spectacles.size());
  m_spectacles_curves[k] = c;
}

inline void Quad_net_builder::choose_levels()
{
  compute_gradient_norms();
  std::vector<double> sorted(m_u);
  std::sort(sorted.begin(), sorted.end());
  const double lo = sorted.front(), hi = sorted.back(), range = hi - lo;
  const double gap = 1e-9 * range;
  m_on_spectacles.assign(m_m.number_of_vertices(), 0);
  for(const Net_spectacles& sp : m_opt.spectacles)
  {
    for(const auto& frame : sp.frame)
      for(std::size_t v : frame)
        m_on_spectacles[v] = 1;
    for(std::size_t v : sp.bridge)
      m_on_spectacles[v] = 1;
  }
  for(double c : m_opt.levels.empty() ? regular_levels() : m_opt.levels)
  {
    bool spectacles = false;
    for(const Net_spectacles& sp : m_opt.spectacles)
      spectacles = spectacles || sp.value == c;
    if(!spectacles)
    {
      add_level(avoid_vertex_values(c, sorted, gap));
      continue;
    }
    // the level's other pieces (away from the spectacles), then the spectacles
    for(Isoline& iso : extract_isolines(m_m, m_u, c))
    {
      // (a piece through a vertex of the spectacles is theirs: it crosses an edge at its end
      // held at the level, the vertex counting as above it; a piece that only passes through a
      // face next to them is another loop of the level, kept: dropping it left a band holding
      // a handle on the rounded genus-100 slab; the comparison is exact, since the solve
      // writes only the vertices that are not held)
      bool touches = false;
      for(std::size_t e : iso.point_edge)
      {
        const auto [f, i] = m_m.edge_side[e];
        for(const std::size_t v : {m_m.tri[f][i], m_m.tri[f][(i + 1) % 3]})
          touches = touches || (m_on_spectacles[v] && m_u[v] == c);
      }
      const bool ends_on_boundary =
        iso.closed || (is_boundary_edge(iso.point_edge.front()) && is_boundary_edge(iso.point_edge.back()));
      if(!touches && ends_on_boundary && worth_keeping(iso))
        include(std::move(iso));
    }
    ++m_stats.levels;
    for(std::size_t k = 0; k < m_opt.spectacles.size(); ++k)
      if(m_opt.spectacles[k].value == c)
        include_spectacles(k);
  }
  // bands far wider than h somewhere (a protrusion where u hardly varies) get local levels
  std::vector<double> values{lo};
  for(const Isoline& iso : m_iso)
    values.push_back(iso.value);
  values.push_back(hi);
  std::sort(values.begin(), values.end());
  values.erase(std::unique(values.begin(), values.end()), values.end());
  std::vector<std::size_t> all(m_m.number_of_faces());
  std::iota(all.begin(), all.end(), std::size_t(0));
  for(std::size_t k = 0; k + 1 < values.size(); ++k)
    refine_band(values[k], values[k + 1], all, sorted, gap, 0);
  separate_saddles(sorted, gap);
  // a boundary loop along which u varies but that no isoline meets gets one through its middle
  std::vector<char> touched(m_m.boundary_loop.size(), 0);
  for(const Isoline& iso : m_iso)
    if(!iso.closed && iso.role == Curve_role::level_set)
      touched[loop_of_edge(iso.point_edge.front())] = touched[loop_of_edge(iso.point_edge.back())] = 1;
  for(std::size_t l = 0; l < m_m.boundary_loop.size(); ++l)
  {
    double a = std::numeric_limits<double>::infinity(), b = -a;
    for(std::size_t v : m_m.boundary_loop[l])
    {
      a = (std::min)(a, m_u[v]);
      b = (std::max)(b, m_u[v]);
    }
    if(touched[l] || !(b - a > 1e3 * gap))
      continue;
    const double middle = avoid_vertex_values(0.5 * (a + b), sorted, gap);
    for(Isoline& iso : extract_isolines(m_m, m_u, middle))
      if(!iso.closed && worth_keeping(iso) &&
         (loop_of_edge(iso.point_edge.front()) == l || loop_of_edge(iso.point_edge.back()) == l))
      {
        include(std::move(iso));
        ++m_stats.extra_boundary_levels;
      }
  }
  m_stats.isolines = m_iso.size();
}

inline void Quad_net_builder::refine_band(double a, double b, const std::vector<std::size_t>& candidates, const std::vector<double>& sorted,
                 double gap, int depth)
{
  const double h = m_opt.edge_length;
  if(depth > 3)
    return;
  std::vector<std::size_t> band;
  for(std::size_t f : candidates)
  {
    const auto& t = m_m.tri[f];
    if((std::min)({m_u[t[0]], m_u[t[1]], m_u[t[2]]}) < b && (std::max)({m_u[t[0]], m_u[t[1]], m_u[t[2]]}) > a)
      band.push_back(f);
  }
  if(band.empty())
    return;
  std::map<std::size_t, std::size_t> local;
  for(std::size_t k = 0; k < band.size(); ++k)
    local[band[k]] = k;
  Union_find sets(band.size());
  for(std::size_t k = 0; k < band.size(); ++k)
    for(int i = 0; i < 3; ++i)
    {
      const auto it = local.find(m_m.neighbour[band[k]][std::size_t(i)]);
      if(it != local.end())
        sets.unite(k, it->second);
    }
  std::map<std::size_t, std::vector<std::size_t>> regions;
  for(std::size_t k = 0; k < band.size(); ++k)
    regions[sets.find(k)].push_back(band[k]);
  for(auto& [root, faces] : regions)
  {
    std::vector<std::pair<double, double>> g; // (|grad u|, area)
    for(std::size_t f : faces)
    {
      const auto& t = m_m.tri[f];
      // (faces at spectacles, where u leaves a level set held flat, do not set the width)
      if(!m_on_spectacles[t[0]] && !m_on_spectacles[t[1]] && !m_on_spectacles[t[2]])
        g.emplace_back(m_grad_norm[f], m_m.area[f]);
    }
    // the width where the region is widest: with the 10% quantile of |grad u| (by area), so
    // that the slow part of a band (around a saddle, on a protrusion) sets it
    const double slow = weighted_quantile(g, 0.1);
    const double width = slow > 0. ? (b - a) / slow : 0.;
    // the spacing where it is finest (the 10% quantile of the scale, by area)
    double here = h;
    if(!m_opt.spacing_scale.empty())
    {
      std::vector<std::pair<double, double>> scale;
      for(std::size_t f : faces)
        scale.emplace_back(m_opt.spacing_scale[f], m_m.area[f]);
      here = h * weighted_quantile(scale, 0.1);
    }
    if(!(width > 1.6 * here))
      continue;
    const std::size_t parts = (std::min<std::size_t>)(std::size_t(std::lround(width / here)), 64);
    std::vector<char> inside(m_m.number_of_faces(), 0);
    for(std::size_t f : faces)
      inside[f] = 1;
    std::vector<double> cuts{a};
    for(std::size_t j = 1; j < parts; ++j)
    {
      const double v = avoid_vertex_values(a + (b - a) * double(j) / double(parts), sorted, gap);
      if(!(v > cuts.back() && v < b))
        continue;
      cuts.push_back(v);
      for(Isoline& iso : extract_isolines(m_m, m_u, v))
        if(inside[iso.faces[0]] && worth_keeping(iso))
        {
          include(std::move(iso));
          ++m_stats.refined_levels;
        }
    }
    cuts.push_back(b);
    for(std::size_t j = 0; j + 1 < cuts.size(); ++j)
      refine_band(cuts[j], cuts[j + 1], faces, sorted, gap, depth + 1);
  }
}

inline void Quad_net_builder::separate_saddles(const std::vector<double>& sorted, double gap)
{
  const auto critical = critical_points(m_m, m_u).first;
  std::vector<std::size_t> saddles;
  for(const Critical_point& c : critical)
    if(c.kind == Critical_kind::saddle && !m_on_spectacles[c.vertex]) // (spectacles: one level already)
      saddles.push_back(c.vertex);
  std::sort(saddles.begin(), saddles.end(), [&](std::size_t a, std::size_t b) { return below(m_u, a, b); });
  std::vector<std::size_t> in_slab(m_m.number_of_faces(), 0), slab;
  for(std::size_t k = 0, next = 0; k + 1 < saddles.size(); ++k)
  {
    // the next saddle of a higher value: saddles of one value (mirror images on a symmetric
    // surface) are each separated from it (once, only the last of them was: the hole of the
    // first one kept its handle in one band)
    next = (std::max)(next, k + 1);
    while(next < saddles.size() && !(m_u[saddles[next]] - m_u[saddles[k]] > 4. * gap))
      ++next;
    if(next == saddles.size())
      break;
    const double a = m_u[saddles[k]], b = m_u[saddles[next]];
    const double c = avoid_vertex_values(0.5 * (a + b), sorted, (std::min)(gap, 0.1 * (b - a)));
    // the faces of the slab a <= u <= b connected to the lower saddle (marked with k + 1)
    slab.clear();
    for(const auto& [f, i] : m_m.star[saddles[k]])
      if(in_slab[f] != k + 1)
      {
        in_slab[f] = k + 1;
        slab.push_back(f);
      }
    for(std::size_t j = 0; j < slab.size(); ++j)
      for(const std::size_t g : m_m.neighbour[slab[j]])
      {
        if(g == npos || in_slab[g] == k + 1)
          continue;
        const auto& t = m_m.tri[g];
        const double lo = (std::min)({m_u[t[0]], m_u[t[1]], m_u[t[2]]});
        const double hi = (std::max)({m_u[t[0]], m_u[t[1]], m_u[t[2]]});
        if(hi >= a && lo <= b)
        {
          in_slab[g] = k + 1;
          slab.push_back(g);
        }
      }
    // Separated already where an isoline between them crosses the slab. (The test once asked
    // whether any isoline anywhere had a value between them: the levels added in one region
    // (wide bands, other saddles) then hid the saddles of a hole elsewhere, whose two saddles
    // stayed in one band, and the cell around the hole's wall held its handle: 6 of the 100
    // handles of the straight-walled slab at h = sqrt(area / 250). The slab is still a coarse
    // stand-in for the saddle's band: an isoline crossing a far part of a large slab counts
    // too; the topology check catches a net where that matters.)
    bool separated = false;
    for(std::size_t j = 0; j < slab.size() && !separated; ++j)
      for(const Face_level& l : m_levels_in_face[slab[j]])
        separated = separated || (l.value > a && l.value < b);
    if(separated)
      continue;
    for(Isoline& iso : extract_isolines(m_m, m_u, c, &slab))
      if(worth_keeping(iso)) // (a piece through a face of the slab stays in it)
      {
        include(std::move(iso));
        ++m_stats.saddle_levels;
      }
  }
}

} // namespace harmonic_quad
} // namespace internal
} // namespace Surface_design
} // namespace CGAL

#endif // CGAL_SURFACE_DESIGN_INTERNAL_HARMONIC_QUAD_REMESHING_QUAD_NET_LEVELS_H
