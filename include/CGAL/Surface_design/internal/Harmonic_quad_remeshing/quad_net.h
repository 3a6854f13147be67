// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The net of isolines and gradient lines of a harmonic function, and its faces.

#ifndef CGAL_SURFACE_DESIGN_INTERNAL_HARMONIC_QUAD_REMESHING_QUAD_NET_H
#define CGAL_SURFACE_DESIGN_INTERNAL_HARMONIC_QUAD_REMESHING_QUAD_NET_H

#include <CGAL/Surface_design/internal/Harmonic_quad_remeshing/curves.h>
#include <CGAL/Surface_design/internal/Harmonic_quad_remeshing/harmonic_function.h>
#include <CGAL/Surface_design/internal/Harmonic_quad_remeshing/trace_mesh.h>

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <map>
#include <numeric>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_design {
namespace internal {
namespace harmonic_quad {

/// Spectacles inserted into the mesh, for the net: frames and bridge run along mesh edges, their
/// vertices hold `value`.
struct Net_spectacles
{
  double value = 0.;
  int sigma = 1;                                 ///< +1: frames around lower regions, the bridge a valley
  std::array<std::vector<std::size_t>, 2> frame; ///< vertex loops, higher values on their right
  std::array<std::size_t, 2> junction{{npos, npos}}; ///< where the bridge meets each frame
  std::vector<std::size_t> bridge;               ///< vertex path from junction[0] to junction[1]
};

struct Net_options
{
  double edge_length = 1.;       ///< target spacing h of both families of curves
  double min_spacing = 0.7071;   ///< a gradient line stops where its neighbour is closer than this * h
  double max_spacing = 1.4142;   ///< a gradient line starts in gaps wider than this * h
  bool quad_poles = true;        ///< every other line ends at an extremum: a fan of quads (else triangles)
  std::vector<double> levels;    ///< the levels (else chosen by `regular_levels()`); spectacles values among them
  /// per face of the mesh: the local spacing is edge_length times this (empty: uniform; see
  /// `curvature_spacing_scale()`)
  std::vector<double> spacing_scale;
  std::vector<Net_spectacles> spectacles;
};

struct Net_statistics
{
  std::size_t levels = 0, isolines = 0, gradient_lines = 0, stopped_lines = 0, started_lines = 0;
  std::size_t lost_lines = 0, removed_dangling_edges = 0, extra_boundary_levels = 0, saddle_levels = 0;
  std::size_t reordered_lines = 0, merged_lines = 0, refined_levels = 0, attached_loops = 0;
  std::size_t spectacles_lines = 0; ///< lines from bridges and junctions
  std::size_t boundary_detail_nodes = 0; ///< nodes at the input's boundary vertices where it leaves the chords
};

/// A spacing scale per face for curvature-adapted spacing: h(f) = h / (1 + adaptation h kappa(f)),
/// at least h / 4, with kappa the normal curvature across the face's edges (dihedral angle over
/// the distance between the two face centroids, the largest of the three), smoothed by three
/// area-weighted averages with the neighbours so that a noisy scan does not scatter it.
inline std::vector<double> curvature_spacing_scale(const Trace_mesh& m, double h, double adaptation)
{
  const std::size_t nf = m.number_of_faces();
  std::vector<Eigen::Vector3d> centroid(nf);
  for(std::size_t f = 0; f < nf; ++f)
    centroid[f] = (m.point[m.tri[f][0]] + m.point[m.tri[f][1]] + m.point[m.tri[f][2]]) / 3.;
  std::vector<double> kappa(nf, 0.);
  for(std::size_t f = 0; f < nf; ++f)
    for(std::size_t i = 0; i < 3; ++i)
    {
      const std::size_t g = m.neighbour[f][i];
      if(g == npos)
        continue;
      const double angle = std::atan2(m.normal[f].cross(m.normal[g]).norm(), m.normal[f].dot(m.normal[g]));
      const double d = (centroid[f] - centroid[g]).norm();
      if(d > 0.)
        kappa[f] = (std::max)(kappa[f], angle / d);
    }
  for(int pass = 0; pass < 3; ++pass)
  {
    std::vector<double> next(nf);
    for(std::size_t f = 0; f < nf; ++f)
    {
      double sum = m.area[f] * kappa[f], weight = m.area[f];
      for(std::size_t g : m.neighbour[f])
        if(g != npos)
        {
          sum += m.area[g] * kappa[g];
          weight += m.area[g];
        }
      next[f] = weight > 0. ? sum / weight : kappa[f];
    }
    kappa.swap(next);
  }
  std::vector<double> scale(nf);
  for(std::size_t f = 0; f < nf; ++f)
    scale[f] = (std::max)(0.25, 1. / (1. + adaptation * h * kappa[f]));
  return scale;
}

/// The output polygon mesh as a soup: vertex positions and counter-clockwise faces.
struct Polygon_soup
{
  std::vector<Eigen::Vector3d> points;
  std::vector<std::vector<std::size_t>> faces;
  std::vector<int> kind; ///< per point: 0 isoline x gradient line, 1 extremum (pole), 2 on the boundary, 3 on a bridge
};

/// Builds the net of Dong et al.: isolines at levels spaced by h (adaptively: the next level is
/// h times the median gradient norm further), gradient lines traced upwards from isoline to
/// isoline with spacing kept in [min_spacing, max_spacing] * h along every isoline (a line stops
/// or starts there otherwise), lines ending at extrema (poles) and at the boundary; then the faces
/// of the embedded graph by its rotation system.
class Quad_net_builder
{
public:
  Quad_net_builder(const Trace_mesh& m, const std::vector<double>& u, const Net_options& options)
    : m_m(m), m_u(u), m_opt(options), m_levels_in_face(m.number_of_faces())
  {}

  const Net_statistics& statistics() const { return m_stats; }
  const std::vector<Isoline>& isolines() const { return m_iso; }

  Polygon_soup build()
  {
    choose_levels();
    trace_lines();
    return assemble();
  }

private:
  // ---- levels -------------------------------------------------------------------------------
  // The q-quantile of the values of (value, weight) pairs by weight; 0 for no pair.
  static double weighted_quantile(std::vector<std::pair<double, double>>& g, double q)
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

  double median_gradient_at(double c) const
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

  bool is_boundary_edge(std::size_t e) const
  {
    const auto [f, i] = m_m.edge_side[e];
    return m_m.neighbour[f][i] == npos;
  }

  std::size_t loop_of_edge(std::size_t e) const
  {
    const auto [f, i] = m_m.edge_side[e];
    return m_m.boundary_position[m_m.tri[f][i]].first;
  }

  // A loop shorter than h would carry fewer than three crossings, and a path shorter than 2 h from
  // a boundary loop back to it would cut off a sliver next to a small hole: such isolines are
  // left out.
  bool worth_keeping(const Isoline& iso) const
  {
    if(iso.closed)
      return iso.length() >= m_opt.edge_length;
    return iso.length() >= 2. * m_opt.edge_length ||
           loop_of_edge(iso.point_edge.front()) != loop_of_edge(iso.point_edge.back());
  }

  void include(Isoline&& iso)
  {
    const std::size_t id = m_iso.size();
    for(std::size_t k = 0; k < iso.segments(); ++k)
      m_levels_in_face[iso.faces[k]].push_back({iso.value, id, k});
    m_iso.push_back(std::move(iso));
  }

  void add_level(double c)
  {
    for(Isoline& iso : extract_isolines(m_m, m_u, c))
      if(worth_keeping(iso))
        include(std::move(iso));
    ++m_stats.levels;
  }

public:
  /// The levels h apart: from the minimum value up, the next level is h times the median of
  /// |grad u| around the middle of the step further.
  std::vector<double> regular_levels()
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

private:
  void compute_gradient_norms()
  {
    m_grad_norm.resize(m_m.number_of_faces());
    for(std::size_t f = 0; f < m_m.number_of_faces(); ++f)
      m_grad_norm[f] = m_m.gradient(f, m_u).norm();
  }

  // Frames and bridge as curves of the net at their value, registered in every face around
  // their vertices (a line may reach them at a vertex); frames first, so that a line reaching a
  // junction lands on its frame.
  void include_spectacles(std::size_t k)
  {
    const Net_spectacles& sp = m_opt.spectacles[k];
    auto curve = [&](const std::vector<std::size_t>& chain, bool closed, int role) {
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
    c.frame[0] = curve(sp.frame[0], true, 1);
    c.frame[1] = curve(sp.frame[1], true, 1);
    c.bridge = curve(sp.bridge, false, 2);
    m_spectacles_curves.resize(m_opt.spectacles.size());
    m_spectacles_curves[k] = c;
  }

  void choose_levels()
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
        bool touches = false;
        for(std::size_t f : iso.faces)
          for(std::size_t v : m_m.tri[f])
            touches = touches || m_on_spectacles[v];
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
      if(!iso.closed && iso.role == 0)
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

  // The connected regions of the faces in `candidates` whose values meet (a, b) (a band between two
  // levels): where a region is wider than 1.6 h across the levels (measured with the 10% quantile
  // of its gradient norm), isolines at intermediate values are added inside that region only,
  // recursively.
  void refine_band(double a, double b, const std::vector<std::size_t>& candidates, const std::vector<double>& sorted,
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

  // Two saddles between the same two levels leave a band that the gradient lines may fail to cut
  // into disks (all lines of one lower loop reaching the same upper loop): between them, an
  // extra isoline is added in the region of the slab of values between the two saddles.
  void separate_saddles(const std::vector<double>& sorted, double gap)
  {
    const auto critical = critical_points(m_m, m_u).first;
    std::vector<std::size_t> saddles;
    for(const Critical_point& c : critical)
      if(c.kind == Critical_kind::saddle && !m_on_spectacles[c.vertex]) // (spectacles: one level already)
        saddles.push_back(c.vertex);
    std::sort(saddles.begin(), saddles.end(), [&](std::size_t a, std::size_t b) { return below(m_u, a, b); });
    std::vector<double> level_values;
    for(const Isoline& iso : m_iso)
      level_values.push_back(iso.value);
    std::sort(level_values.begin(), level_values.end());
    auto band = [&](double x) { return std::lower_bound(level_values.begin(), level_values.end(), x) - level_values.begin(); };
    for(std::size_t k = 0; k + 1 < saddles.size(); ++k)
    {
      const double a = m_u[saddles[k]], b = m_u[saddles[k + 1]];
      if(band(a) != band(b) || !(b - a > 4. * gap))
        continue;
      const double c = avoid_vertex_values(0.5 * (a + b), sorted, (std::min)(gap, 0.1 * (b - a)));
      // the faces of the slab a <= u <= b connected to the lower saddle
      std::vector<char> in_slab(m_m.number_of_faces(), 0);
      std::vector<std::size_t> stack;
      for(const auto& [f, i] : m_m.star[saddles[k]])
      {
        in_slab[f] = 1;
        stack.push_back(f);
      }
      while(!stack.empty())
      {
        const std::size_t f = stack.back();
        stack.pop_back();
        for(int i = 0; i < 3; ++i)
        {
          const std::size_t g = m_m.neighbour[f][std::size_t(i)];
          if(g == npos || in_slab[g])
            continue;
          const auto& t = m_m.tri[g];
          const double lo = (std::min)({m_u[t[0]], m_u[t[1]], m_u[t[2]]});
          const double hi = (std::max)({m_u[t[0]], m_u[t[1]], m_u[t[2]]});
          if(hi >= a && lo <= b)
          {
            in_slab[g] = 1;
            stack.push_back(g);
          }
        }
      }
      for(Isoline& iso : extract_isolines(m_m, m_u, c))
        if(in_slab[iso.faces[0]] && worth_keeping(iso))
        {
          include(std::move(iso));
          ++m_stats.saddle_levels;
        }
    }
  }

  // ---- gradient lines ------------------------------------------------------------------------
  struct Crossing
  {
    double s;                 // arc-length position on its isoline
    Eigen::Vector3d point;
    std::size_t down = npos;    // the node below, when a line arrived from there
    bool up = false;            // a line continues upwards from here
    std::size_t node = npos;    // net node id
    std::vector<std::size_t> pending; // pending codes of the lines that landed here
    bool fixed = false;         // part of spectacles: never stopped, moved or merged away
    bool no_trace = false;      // its upward edge exists already (spectacles)
    bool keep = false;          // reached by a spectacles line: not reordered
  };

  struct Spectacles_curves
  {
    std::array<std::size_t, 2> frame;
    std::size_t bridge;
  };

  // an edge of the net with the directions of its ends in the rotation system, where the
  // generic rule (up, along, down, back) does not apply
  struct Keyed_edge
  {
    std::size_t a, b; // codes (pending allowed)
    int kind;         // 0 line (a below b), 3 bridge
    double key_a, key_b; // NaN: the generic rule
  };

  // a net node: crossing (isoline, index), pole (mesh vertex) or boundary point
  struct Node
  {
    Eigen::Vector3d point;
    int kind; // 0 crossing, 1 pole, 2 boundary point, 3 bridge node (spectacles)
    std::size_t curve = npos, vertex = npos, loop = npos;
    double loop_position = 0.;
    double s = 0.; // arc-length position on `curve`
  };

  std::size_t node_for_end(const Trace_end& e, std::size_t from_node)
  {
    if(e.kind == Trace_end::isoline && m_iso[e.curve].role == 2)
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
      n.kind = 1;
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
      n.kind = 2;
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

  // crossings get their node ids when their isoline is finalized; until then a line that lands
  // on one refers to it by a pending code
  static constexpr std::size_t pending_bit = std::size_t(1) << (sizeof(std::size_t) * 8 - 1);
  std::size_t resolve(std::size_t id) const
  {
    if(id == npos || !(id & pending_bit))
      return id;
    return m_pending_node[id & ~pending_bit];
  }

  // Fences along an isoline: the continuing crossings (and the boundary ends of a path), with
  // the gaps between consecutive ones.
  struct Fences
  {
    std::vector<double> pos;
    std::vector<std::size_t> who; // crossing index, npos for a boundary end
    double length;
    bool closed;
    std::size_t size() const { return pos.size(); }
    std::size_t gaps() const { return closed ? pos.size() : (pos.empty() ? 0 : pos.size() - 1); }
    double gap(std::size_t k) const
    {
      return k + 1 < pos.size() ? pos[k + 1] - pos[k] : pos[0] + length - pos[k];
    }
  };

  Fences fences(const Isoline& iso, const std::vector<Crossing>& cr) const
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

  void add_crossing(std::size_t c, double s)
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

  void space_crossings(std::size_t c)
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

  // A line arriving from below next to a spectacles line that landed here from above (a bridge
  // or junction line of spectacles above, which has no line below it) joins it: one line through.
  void merge_into_spectacles_lines(std::size_t c)
  {
    auto& cr = m_crossings[c];
    const Isoline& iso = m_iso[c];
    std::vector<char> gone(cr.size(), 0);
    for(Crossing& x : cr)
    {
      if(!x.fixed || !x.no_trace || x.down != npos)
        continue;
      std::size_t best = npos;
      double distance = 0.5 * m_opt.edge_length;
      for(std::size_t k = 0; k < cr.size(); ++k)
      {
        const double d = std::abs(wrapped(cr[k].s - x.s, iso.length(), iso.closed));
        if(!gone[k] && !cr[k].fixed && cr[k].down != npos && d < distance)
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

  void finalize_crossings(std::size_t c)
  {
    auto& cr = m_crossings[c];
    std::stable_sort(cr.begin(), cr.end(), [](const Crossing& a, const Crossing& b) { return a.s < b.s; });
    for(Crossing& x : cr)
    {
      Node n;
      n.point = x.point;
      n.kind = 0;
      n.curve = c;
      n.s = x.s;
      m_nodes.push_back(n);
      x.node = m_nodes.size() - 1;
      for(std::size_t p : x.pending)
        m_pending_node[p] = x.node;
    }
  }

  static double wrapped(double d, double length, bool closed)
  {
    if(!closed)
      return d;
    d = std::fmod(d, length);
    if(d > 0.5 * length)
      d -= length;
    else if(d <= -0.5 * length)
      d += length;
    return d;
  }

  // Discrete gradient lines may cross or merge (through vertices, along sink edges), which would
  // make the net non-planar. The lines from one isoline keep their order on the next one: their
  // landing points are given back to them in the order of their sources (the cyclic shift that
  // moves them least); of two lines landing on the same point, one stops.
  void untangle_arrivals(std::size_t c)
  {
    const Isoline& iso = m_iso[c];
    auto& cr = m_crossings[c];
    const double L = iso.length();
    std::map<std::size_t, std::vector<std::size_t>> by_source;
    for(std::size_t k = 0; k < cr.size(); ++k)
      if(!cr[k].keep && !cr[k].fixed && cr[k].down != npos && !(cr[k].down & pending_bit) &&
         m_nodes[cr[k].down].kind == 0)
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

  void trace_lines()
  {
    m_crossings.assign(m_iso.size(), {});
    Gradient_walker walker(m_m, m_u, m_levels_in_face);
    std::vector<std::size_t> order(m_iso.size());
    std::iota(order.begin(), order.end(), std::size_t(0));
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return m_iso[a].value < m_iso[b].value; });
    m_processed.assign(m_iso.size(), 0);
    for(std::size_t k = 0; k < m_spectacles_curves.size(); ++k)
      spectacles_lines(k, walker);
    for(std::size_t c : order)
    {
      if(m_iso[c].role == 2) // a bridge: its nodes and lines are made by spectacles_lines()
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

  // Where a line traced downwards from spectacles ends: on an isoline below (processed later), a
  // crossing whose upward edge is that line; else a pole or boundary node.
  std::size_t landing_from_above(const Trace_end& e)
  {
    if(e.kind == Trace_end::isoline && m_iso[e.curve].role != 2)
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

  // A line of spectacles from node `from` (a code), started in face f at p, towards the side
  // of sigma, with rotation key `key` at `from`.
  void spectacles_line(std::size_t from, double key, std::size_t f, const Eigen::Vector3d& p, double value, int sigma,
                       const Gradient_walker& walker)
  {
    const Trace_end e = walker.from_face(f, p, value, sigma);
    ++m_stats.spectacles_lines;
    if(sigma > 0)
    {
      const bool onto_isoline = e.kind == Trace_end::isoline && m_iso[e.curve].role != 2;
      const std::size_t id = node_for_end(e, from);
      if(id == npos)
        return;
      if(onto_isoline)
        m_crossings[e.curve].back().keep = true;
      m_keyed_edges.push_back({from, id, 0, key, std::numeric_limits<double>::quiet_NaN()});
    }
    else
    {
      const std::size_t id = landing_from_above(e);
      if(id != npos)
        m_keyed_edges.push_back({id, from, 0, std::numeric_limits<double>::quiet_NaN(), key});
    }
  }

  // The nodes and lines of spectacles k, before any isoline is processed: a junction on each
  // frame (a crossing that is never stopped), bridge nodes about h apart with one line on each
  // side (up from a valley, down from a ridge), and from each junction one line into each of
  // the two sectors between its frame and the bridge (the corner of the level set there is a
  // right angle, which the (u, psi) net opens to a straight one: the line along its bisector
  // keeps the cells there quadrilateral).
  void spectacles_lines(std::size_t k, const Gradient_walker& walker)
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
      n.kind = 3;
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
      m_keyed_edges.push_back({chain[j], chain[j + 1], 3, j == 0 ? junction_key : 1.,
                               j + 2 == chain.size() ? junction_key : 3.});
    // the lines into the two sectors at each junction
    for(int j = 0; j < 2; ++j)
    {
      const std::size_t v = sp.junction[std::size_t(j)];
      const auto& frame = sp.frame[std::size_t(j)];
      const std::size_t at = std::size_t(std::find(frame.begin(), frame.end(), v) - frame.begin());
      const std::size_t next = frame[(at + 1) % frame.size()], prev = frame[(at + frame.size() - 1) % frame.size()];
      const std::size_t along = j == 0 ? sp.bridge[1] : sp.bridge[sp.bridge.size() - 2];
      const Eigen::Vector3d n = vertex_normal(v);
      auto tangent = [&](std::size_t w) { return tangent_of(m_m.point[w] - m_m.point[v], n); };
      const Eigen::Vector3d db = tangent(along), dn = tangent(next), dp = tangent(prev);
      for(int next_side = 1; next_side >= 0; --next_side)
      {
        const Eigen::Vector3d& df = next_side ? dn : dp;
        const Eigen::Vector3d bisector = (db + df).normalized();
        const double side = n.dot(db.cross(df));
        // the face around v on the bridge's side of the frame closest to the bisector
        std::size_t best = npos;
        double best_dot = -2.;
        for(const auto& [f, i] : m_m.star[v])
        {
          const std::size_t a = m_m.tri[f][(i + 1) % 3], b = m_m.tri[f][(i + 2) % 3];
          if(sp.sigma * (m_u[a] - sp.value) < 0. || sp.sigma * (m_u[b] - sp.value) < 0.)
            continue; // inside the frame
          const Eigen::Vector3d centroid = (m_m.point[a] + m_m.point[b] + m_m.point[v]) / 3.;
          const Eigen::Vector3d dc = tangent_of(centroid - m_m.point[v], n);
          if(side * n.dot(db.cross(dc)) <= 0.)
            continue; // the other sector
          if(dc.dot(bisector) > best_dot)
          {
            best_dot = dc.dot(bisector);
            best = f;
          }
        }
        if(best == npos)
          continue;
        const auto& t = m_m.tri[best];
        const Eigen::Vector3d start = 0.5 * m_m.point[v] + 0.25 * (m_m.point[t[0]] + m_m.point[t[1]] + m_m.point[t[2]] - m_m.point[v]);
        // rotation key at the junction: between the bridge and the frame's next (prev) direction
        const double key = sp.sigma > 0 ? (next_side ? 0.5 : 3.5) : (next_side ? 1.5 : 2.5);
        spectacles_line(junction_code[std::size_t(j)], key, best, start, m_m.barycentric(best, start).dot(Eigen::Vector3d(m_u[t[0]], m_u[t[1]], m_u[t[2]])), sp.sigma, walker);
      }
    }
  }

  // the spacing at arc length s of an isoline (on segment j for the second form)
  double local_h_at(const Isoline& iso, double s) const
  {
    return m_opt.spacing_scale.empty() ? m_opt.edge_length : local_h_on_segment(iso, iso.at(s).second);
  }

  double local_h_on_segment(const Isoline& iso, std::size_t j) const
  {
    if(m_opt.spacing_scale.empty() || j >= iso.faces.size() || iso.faces[j] >= m_opt.spacing_scale.size())
      return m_opt.edge_length;
    return m_opt.edge_length * m_opt.spacing_scale[iso.faces[j]];
  }

  static Eigen::Vector3d tangent_of(const Eigen::Vector3d& d, const Eigen::Vector3d& n)
  {
    const Eigen::Vector3d t = d - d.dot(n) * n;
    return t.norm() > 0. ? Eigen::Vector3d(t.normalized()) : t;
  }

  // The node where a traced line ends, or npos if it got lost. On an isoline not processed yet
  // (ascending lines) a pending code, resolved when that isoline is; on one already processed
  // (descending lines) a new crossing there with its node at once.
  std::size_t end_node(const Trace_end& e, std::size_t from)
  {
    if(e.kind == Trace_end::isoline && m_processed[e.curve] && m_iso[e.curve].role != 2)
    {
      Crossing x;
      x.s = m_iso[e.curve].nearest_arc_position(e.segment, e.point);
      x.point = e.point;
      Node n;
      n.point = e.point;
      n.kind = 0;
      n.curve = e.curve;
      n.s = x.s;
      m_nodes.push_back(n);
      x.node = m_nodes.size() - 1;
      m_crossings[e.curve].push_back(x);
      return x.node;
    }
    return node_for_end(e, from);
  }

  // ---- assembly ------------------------------------------------------------------------------
  // A boundary loop that no line reaches and no isoline with lines on it touches (a small hole
  // inside one cell) would leave the cell an annulus: it gets a gradient line upwards from its
  // highest vertex and one downwards from its lowest, which end on the net.
  void attach_floating_loops()
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
      if(!m_iso[c].closed && m_iso[c].role == 0 && !m_crossings[c].empty())
      {
        attached[loop_of_edge(m_iso[c].point_edge.front())] = 1;
        attached[loop_of_edge(m_iso[c].point_edge.back())] = 1;
      }
    for(bool changed = true; changed;)
    {
      changed = false;
      for(std::size_t c = 0; c < m_iso.size(); ++c)
        if(!m_iso[c].closed && m_iso[c].role == 0)
        {
          const std::size_t a = loop_of_edge(m_iso[c].point_edge.front()), b = loop_of_edge(m_iso[c].point_edge.back());
          if(attached[a] != attached[b])
          {
            attached[a] = attached[b] = 1;
            changed = true;
          }
        }
    }
    Gradient_walker walker(m_m, m_u, m_levels_in_face);
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
        n.kind = 2;
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

  Polygon_soup assemble()
  {
    attach_floating_loops();
    // edges: (a, b, kind) with kind 0 line (a below b), 1 isoline (a before b), 2 boundary
    const double nan = std::numeric_limits<double>::quiet_NaN();
    struct Edge
    {
      std::size_t a, b;
      int kind;
      double key_a, key_b; // explicit rotation keys (spectacles), NaN otherwise
    };
    std::vector<Edge> edges;
    for(auto [a, b] : m_line_edges)
    {
      // npos: a lost line, or one that stopped where it met another (its pending code unresolved)
      const std::size_t ra = resolve(a), rb = resolve(b);
      if(ra != npos && rb != npos)
        edges.push_back({ra, rb, 0, nan, nan});
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
      if(m_nodes[edges[k].b].kind == 1)
        into_pole[edges[k].b].push_back(k);
      else if(m_nodes[edges[k].a].kind == 1)
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
    for(std::size_t c = 0; c < m_iso.size(); ++c)
    {
      auto& cr = m_crossings[c];
      std::stable_sort(cr.begin(), cr.end(), [](const Crossing& a, const Crossing& b) { return a.s < b.s; });
      std::vector<std::size_t> chain;
      const Isoline& iso = m_iso[c];
      if(iso.role == 2) // a bridge: its edges are keyed edges
        continue;
      if(!iso.closed)
        chain.push_back(boundary_node(iso.point_edge.front(), iso.point.front()));
      for(const Crossing& x : cr)
        chain.push_back(x.node);
      if(!iso.closed)
        chain.push_back(boundary_node(iso.point_edge.back(), iso.point.back()));
      for(std::size_t k = 0; k + 1 < chain.size(); ++k)
        edges.push_back({chain[k], chain[k + 1], 1, nan, nan});
      if(iso.closed && chain.size() >= 2)
        edges.push_back({chain.back(), chain.front(), 1, nan, nan});
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
        n.kind = 2;
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
          n.kind = 2;
          n.loop = l;
          n.loop_position = std::fmod(t, double(loop.size()));
          n.point = loop_point(l, n.loop_position);
          m_nodes.push_back(n);
          edges.push_back({from, m_nodes.size() - 1, 2, nan, nan});
          from = m_nodes.size() - 1;
          ++m_stats.boundary_detail_nodes;
        }
        edges.push_back({from, q[(k + 1) % q.size()].second, 2, nan, nan});
      }
    }
    return faces_of(edges);
  }

  // the point at `position` (vertex index + fraction of the next edge) along boundary loop `l`
  Eigen::Vector3d loop_point(std::size_t l, double position) const
  {
    const auto& loop = m_m.boundary_loop[l];
    const std::size_t n = loop.size();
    const double w = std::fmod(position, double(n));
    const std::size_t i = (std::min)(std::size_t(w), n - 1);
    const double f = w - double(i);
    return (1. - f) * m_m.point[loop[i]] + f * m_m.point[loop[(i + 1) % n]];
  }

  // Douglas-Peucker on boundary loop `l` between loop positions `begin` < `end` (`end` may
  // exceed the loop's size: it wraps): the positions (increasing, between them) of the loop's
  // vertices to keep so that the boundary between consecutive kept points stays within h / 4 of
  // their chord; vertices closer than h / 8 to a kept point are not taken. An even number, so
  // that the face along it keeps the parity of its sides: an odd count gets the next farthest
  // vertex, or the middle of the longest piece when no vertex is left.
  std::vector<double> boundary_detail(std::size_t l, double begin, double end) const
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

  std::size_t boundary_node(std::size_t mesh_edge, const Eigen::Vector3d& p)
  {
    const auto [f, i] = m_m.edge_side[mesh_edge];
    const std::size_t a = m_m.tri[f][i], b = m_m.tri[f][(i + 1) % 3];
    const double len = (m_m.point[b] - m_m.point[a]).norm();
    const double t = len > 0. ? std::clamp((p - m_m.point[a]).norm() / len, 0., 1.) : 0.;
    Node n;
    n.point = p;
    n.kind = 2;
    n.loop = m_m.boundary_position[a].first;
    n.loop_position = double(m_m.boundary_position[a].second) + t;
    m_nodes.push_back(n);
    return m_nodes.size() - 1;
  }

  Eigen::Vector3d vertex_normal(std::size_t v) const
  {
    Eigen::Vector3d n = Eigen::Vector3d::Zero();
    for(const auto& [f, i] : m_m.star[v])
      n += m_m.area[f] * m_m.normal[f];
    return n.norm() > 0. ? n.normalized() : m_m.normal[m_m.star[v].front().first];
  }

  template <class Edges>
  void sort_around(std::size_t p, std::vector<std::size_t>& in, const Edges& edges) const
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
      one_loop = one_loop && o.kind == 0 && o.curve == f.curve && m_iso[o.curve].closed;
    }
    if(one_loop) // lines from one loop: their order along it (see faces_of)
      for(std::size_t k = 0; k < in.size(); ++k)
        a[k].first = (edges[in[k]].a == p ? 1. : -1.) * m_nodes[edges[in[k]].a == p ? edges[in[k]].b : edges[in[k]].a].s;
    std::sort(a.begin(), a.end());
    for(std::size_t k = 0; k < in.size(); ++k)
      in[k] = a[k].second;
  }

  template <class Edges>
  Polygon_soup faces_of(Edges edges)
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
    auto direction_key = [&](std::size_t from, std::size_t to, int kind, bool forward) -> double {
      const Node& n = m_nodes[from];
      if(n.kind == 0)
      {
        // crossing: up (line, forward), next along the isoline, down, previous: 0, 1, 2, 3
        if(kind == 0)
          return forward ? 0. : 2.;
        return forward ? 1. : 3.;
      }
      // poles and boundary points: the angle of the chord in the tangent plane; on the boundary
      // measured from the direction along the loop (interior on the left)
      Eigen::Vector3d normal, x;
      if(n.kind == 1 && n.loop == npos)
      {
        normal = vertex_normal(n.vertex);
        x = normal.unitOrthogonal();
      }
      else
      {
        if(kind == 2)
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
      if(node.kind == 1 && node.loop == npos && !r.empty())
      {
        bool one_loop = true;
        const Node& first = m_nodes[other_end(r[0].second)];
        for(const auto& [key, h] : r)
        {
          const Node& o = m_nodes[other_end(h)];
          one_loop = one_loop && o.kind == 0 && o.curve == first.curve && m_iso[o.curve].closed;
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
      if(edges[h / 2].kind == 2 && h % 2 == 1)
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

  Eigen::Vector3d boundary_normal(const Node& n) const
  {
    const auto& loop = m_m.boundary_loop[n.loop];
    const std::size_t a = loop[std::size_t(n.loop_position) % loop.size()];
    return vertex_normal(a);
  }

  Eigen::Vector3d boundary_tangent(const Node& n) const
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

  const Trace_mesh& m_m;
  const std::vector<double>& m_u;
  Net_options m_opt;
  std::vector<double> m_grad_norm;
  std::vector<std::vector<Face_level>> m_levels_in_face;
  std::vector<Isoline> m_iso;
  std::vector<std::vector<Crossing>> m_crossings;
  std::vector<std::size_t> m_pending_node; // node of every pending code
  std::vector<std::size_t> m_trace_down;
  std::vector<char> m_processed;
  std::vector<Node> m_nodes;
  std::map<std::size_t, std::size_t> m_pole_node;
  std::vector<Spectacles_curves> m_spectacles_curves;
  std::vector<char> m_on_spectacles;
  std::vector<Keyed_edge> m_keyed_edges;
  std::vector<std::pair<std::size_t, std::size_t>> m_line_edges; // (lower node, upper node), pending codes allowed
  Net_statistics m_stats;
};

} // namespace harmonic_quad
} // namespace internal
} // namespace Surface_design
} // namespace CGAL

#endif // CGAL_SURFACE_DESIGN_INTERNAL_HARMONIC_QUAD_REMESHING_QUAD_NET_H
