// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Spectacles around saddles (Nagano & Imai): a bridge of two gradient lines through the saddle
// and the isolines at its ends (the frames), inserted into the mesh so that they can be held at
// one value.

#ifndef CGAL_SURFACE_DESIGN_INTERNAL_HARMONIC_QUAD_REMESHING_SPECTACLES_H
#define CGAL_SURFACE_DESIGN_INTERNAL_HARMONIC_QUAD_REMESHING_SPECTACLES_H

#include <CGAL/Surface_design/internal/Harmonic_quad_remeshing/curves.h>
#include <CGAL/Surface_design/internal/Harmonic_quad_remeshing/harmonic_function.h>
#include <CGAL/Surface_design/internal/Harmonic_quad_remeshing/trace_mesh.h>

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_design {
namespace internal {
namespace harmonic_quad {

/// The spectacles of one saddle, on the input mesh. With `sigma` = +1 the frames are isolines
/// below the saddle (each around one of the two lower regions that meet there) and the bridge
/// descends from the saddle into both; with -1 everything is mirrored (frames above).
struct Spectacles_plan
{
  std::size_t saddle = npos;
  int sigma = 1;
  double value = 0.;
  std::array<std::vector<Surface_point>, 2> frame; ///< closed, oriented with higher values on the right
  std::array<std::size_t, 2> junction{{npos, npos}}; ///< index in frame[k] where the bridge meets it
  std::vector<Surface_point> bridge;                 ///< from frame[0]'s junction through the saddle to frame[1]'s
};

struct Skipped_saddle
{
  std::size_t vertex;
  std::string reason;
};

inline double path_length(const std::vector<Surface_point>& path)
{
  double l = 0.;
  for(std::size_t k = 1; k < path.size(); ++k)
    l += (path[k].point - path[k - 1].point).norm();
  return l;
}

/// Finds the spectacles of the saddles of u: for each simple interior saddle, the two gradient
/// lines leaving it into its two lower wedges (or upper wedges) down to a level of the net
/// (`levels`, increasing), the first level at which both lines are at least 0.6 h long and land
/// on two different closed isolines. A saddle whose wedges lead to one isoline on both sides, to
/// the boundary, or whose curves would touch the faces of spectacles already placed is skipped
/// with a reason (two close saddles: Nagano & Imai's open problem).
class Spectacles_planner
{
public:
  Spectacles_planner(const Trace_mesh& m, const std::vector<double>& u, std::vector<double> levels, double h)
    : m_m(m), m_u(u), m_levels(std::move(levels)), m_h(h), m_in_face(m.number_of_faces()),
      m_walker(m, u, m_in_face), m_owner(m.number_of_faces(), npos)
  {}

  void plan(const std::vector<Critical_point>& critical)
  {
    for(const Critical_point& c : critical)
    {
      if(c.kind != Critical_kind::saddle)
        continue;
      if(c.on_boundary)
      {
        m_skipped.push_back({c.vertex, "the saddle is on the boundary"});
        continue;
      }
      if(c.multiplicity > 1)
      {
        m_skipped.push_back({c.vertex, "a saddle of multiplicity " + std::to_string(c.multiplicity) +
                                         " (the spectacles are defined for simple saddles)"});
        continue;
      }
      std::string below_why, above_why;
      Spectacles_plan p;
      if(plan_one(c.vertex, +1, p, below_why) || plan_one(c.vertex, -1, p, above_why))
      {
        // the faces its curves touch are taken
        for(std::size_t f : touched_faces(p))
          m_owner[f] = c.vertex;
        m_plans.push_back(std::move(p));
      }
      else
        m_skipped.push_back({c.vertex, "downwards, " + below_why + "; upwards, " + above_why});
    }
  }

  const std::vector<Spectacles_plan>& plans() const { return m_plans; }
  const std::vector<Skipped_saddle>& skipped() const { return m_skipped; }

  /// Faces that the curves of `p` pass through or touch.
  std::vector<std::size_t> touched_faces(const Spectacles_plan& p) const
  {
    std::vector<std::size_t> out;
    auto add = [&](const Surface_point& q) {
      switch(q.kind)
      {
      case Surface_point::vertex:
        for(const auto& [f, i] : m_m.star[q.a])
          out.push_back(f);
        break;
      case Surface_point::edge:
        for(const auto& [f, i] : m_m.star[q.a])
          for(int k = 1; k < 3; ++k)
            if(m_m.tri[f][(i + k) % 3] == q.b)
              out.push_back(f);
        break;
      case Surface_point::face:
        out.push_back(q.a);
        break;
      }
    };
    for(const auto& frame : p.frame)
      for(const auto& q : frame)
        add(q);
    for(const auto& q : p.bridge)
      add(q);
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
  }

private:
  // The wedges of v on the side `sigma` (+1: below v), each as the cyclic run of its link
  // vertices in counter-clockwise order.
  std::vector<std::vector<std::size_t>> wedges(std::size_t v, int sigma) const
  {
    std::map<std::size_t, std::size_t> next;
    for(const auto& [f, i] : m_m.star[v])
      next[m_m.tri[f][(i + 1) % 3]] = m_m.tri[f][(i + 2) % 3];
    std::vector<std::size_t> cycle{next.begin()->first};
    for(std::size_t guard = 0; guard < next.size(); ++guard)
    {
      const auto it = next.find(cycle.back());
      if(it == next.end() || it->second == cycle.front())
        break;
      cycle.push_back(it->second);
    }
    auto on_side = [&](std::size_t w) { return sigma > 0 ? below(m_u, w, v) : below(m_u, v, w); };
    const std::size_t n = cycle.size();
    std::size_t first = npos; // a link vertex that starts a run
    for(std::size_t k = 0; k < n && first == npos; ++k)
      if(on_side(cycle[k]) && !on_side(cycle[(k + n - 1) % n]))
        first = k;
    std::vector<std::vector<std::size_t>> out;
    if(first == npos)
      return out;
    for(std::size_t j = 0; j < n; ++j)
    {
      const std::size_t w = cycle[(first + j) % n];
      if(!on_side(w))
        continue;
      if(out.empty() || !on_side(cycle[(first + j + n - 1) % n]))
        out.emplace_back();
      out.back().push_back(w);
    }
    return out;
  }

  // The gradient line from saddle v into one wedge (walking direction -sigma).
  Trace_end trace_wedge(std::size_t v, const std::vector<std::size_t>& wedge, int sigma,
                        std::vector<Surface_point>& path) const
  {
    const int direction = -sigma;
    // the steepest face of the wedge that the line enters from v
    std::size_t best_face = npos;
    double best = 0.;
    for(const auto& [f, i] : m_m.star[v])
    {
      const std::size_t a = m_m.tri[f][(i + 1) % 3], b = m_m.tri[f][(i + 2) % 3];
      if(std::find(wedge.begin(), wedge.end(), a) == wedge.end() ||
         std::find(wedge.begin(), wedge.end(), b) == wedge.end())
        continue;
      const Eigen::Vector3d d = double(direction) * m_walker.gradient(f);
      if(m_m.grad_lambda[f][(i + 1) % 3].dot(d) >= 0. && m_m.grad_lambda[f][(i + 2) % 3].dot(d) >= 0. &&
         d.squaredNorm() > best)
      {
        best = d.squaredNorm();
        best_face = f;
      }
    }
    path.clear();
    if(best_face != npos)
    {
      const Trace_end e = m_walker.from_face(best_face, m_m.point[v], m_u[v], direction, &path);
      path.front().kind = Surface_point::vertex; // it starts at the saddle itself
      path.front().a = v;
      path.front().point = m_m.point[v];
      return e;
    }
    // no face of the wedge is entered: along the edge to its farthest vertex
    std::size_t w = wedge.front();
    for(std::size_t x : wedge)
      if(direction > 0 ? below(m_u, w, x) : below(m_u, x, w))
        w = x;
    Surface_point start;
    start.kind = Surface_point::vertex;
    start.a = v;
    start.point = m_m.point[v];
    path.push_back(start);
    // a level met on that edge: the line ends there (in either face of the edge, the level has
    // one segment)
    for(const auto& [f, i] : m_m.star[v])
      for(int k = 1; k < 3; ++k)
        if(m_m.tri[f][(i + k) % 3] == w)
          for(const Face_level& l : m_in_face[f])
            if((l.value - m_u[v]) * (l.value - m_u[w]) < 0.)
            {
              Surface_point q;
              q.kind = Surface_point::edge;
              q.a = v;
              q.b = w;
              q.t = (l.value - m_u[v]) / (m_u[w] - m_u[v]);
              q.point = (1. - q.t) * m_m.point[v] + q.t * m_m.point[w];
              path.push_back(q);
              Trace_end e;
              e.kind = Trace_end::isoline;
              e.curve = l.curve;
              e.segment = l.segment;
              e.point = q.point;
              return e;
            }
    return m_walker.from_vertex(w, direction, &path);
  }

  bool plan_one(std::size_t s, int sigma, Spectacles_plan& plan, std::string& why)
  {
    const auto wedge = wedges(s, sigma);
    if(wedge.size() != 2)
    {
      why = "the saddle has " + std::to_string(wedge.size()) + " wedges on that side";
      return false;
    }
    // candidate levels beyond the saddle, nearest first
    std::vector<double> candidates;
    for(double c : m_levels)
      if(sigma > 0 ? c < m_u[s] : c > m_u[s])
        candidates.push_back(c);
    if(sigma > 0)
      std::reverse(candidates.begin(), candidates.end());
    if(candidates.size() > 4)
      candidates.resize(4);
    if(candidates.empty())
    {
      why = "no level of the net lies beyond the saddle";
      return false;
    }
    for(double c : candidates)
    {
      for(auto& l : m_in_face)
        l.clear();
      std::vector<Isoline> iso = extract_isolines(m_m, m_u, c);
      for(std::size_t k = 0; k < iso.size(); ++k)
        for(std::size_t j = 0; j < iso[k].segments(); ++j)
          m_in_face[iso[k].faces[j]].push_back({c, k, j});
      std::array<std::vector<Surface_point>, 2> path;
      std::array<Trace_end, 2> end;
      for(int k = 0; k < 2; ++k)
        end[k] = trace_wedge(s, wedge[std::size_t(k)], sigma, path[std::size_t(k)]);
      if(end[0].kind != Trace_end::isoline || end[1].kind != Trace_end::isoline)
      {
        why = "a gradient line from the saddle ends at an extremum or at the boundary before the next level";
        return false;
      }
      if(end[0].curve == end[1].curve)
      {
        why = "both wedges lead to one isoline";
        return false; // (on this side; the caller tries the other one)
      }
      if(!iso[end[0].curve].closed || !iso[end[1].curve].closed)
      {
        why = "a frame would reach the boundary";
        return false;
      }
      // a frame shorter than 2 h would carry too few lines (the net drops loops shorter than h),
      // a bridge shorter than 0.6 h would leave slivers: the next level
      if((std::min)(iso[end[0].curve].length(), iso[end[1].curve].length()) < 2. * m_h)
      {
        why = "a frame would be shorter than 2 h up to the last level tried";
        continue;
      }
      if((std::min)(path_length(path[0]), path_length(path[1])) < 0.6 * m_h)
      {
        why = "the gradient lines are shorter than 0.6 h up to the last level tried";
        continue;
      }
      plan = Spectacles_plan();
      plan.saddle = s;
      plan.sigma = sigma;
      plan.value = c;
      for(int k = 0; k < 2; ++k)
      {
        const Isoline& loop = iso[end[std::size_t(k)].curve];
        auto& frame = plan.frame[std::size_t(k)];
        for(std::size_t j = 0; j < loop.segments(); ++j)
        {
          const auto [f, i] = m_m.edge_side[loop.point_edge[j]];
          Surface_point q;
          q.kind = Surface_point::edge;
          q.a = m_m.tri[f][i];
          q.b = m_m.tri[f][(i + 1) % 3];
          q.t = (c - m_u[q.a]) / (m_u[q.b] - m_u[q.a]);
          q.point = loop.point[j];
          frame.push_back(q);
          if(j == end[std::size_t(k)].segment)
          {
            Surface_point a;
            a.kind = Surface_point::face;
            a.a = loop.faces[j];
            a.point = end[std::size_t(k)].point;
            plan.junction[std::size_t(k)] = frame.size();
            frame.push_back(a);
          }
        }
        // the line's own end is the junction
        path[std::size_t(k)].back() = frame[plan.junction[std::size_t(k)]];
      }
      plan.bridge.assign(path[0].rbegin(), path[0].rend());
      plan.bridge.insert(plan.bridge.end(), path[1].begin() + 1, path[1].end());
      for(std::size_t f : touched_faces(plan))
        if(m_owner[f] != npos)
        {
          why = "the spectacles would cross those of the saddle at vertex " + std::to_string(m_owner[f]);
          return false;
        }
      return true;
    }
    return false; // (`why` says what failed at the last level tried)
  }

  const Trace_mesh& m_m;
  const std::vector<double>& m_u;
  std::vector<double> m_levels;
  double m_h;
  std::vector<std::vector<Face_level>> m_in_face;
  Gradient_walker m_walker;
  std::vector<std::size_t> m_owner;
  std::vector<Spectacles_plan> m_plans;
  std::vector<Skipped_saddle> m_skipped;
};

/// A triangle mesh refined so that given polylines run along its edges.
struct Refined_mesh
{
  std::vector<Eigen::Vector3d> points; ///< the input's vertices first, with their indices
  std::vector<std::array<std::size_t, 3>> triangles;
  std::vector<std::vector<std::size_t>> chains; ///< per polyline, its vertices (a closed one not repeated)
};

/// Inserts polylines of surface points (consecutive points on a common face) into a trace mesh:
/// their points become vertices (points within `snap` (relative) of a vertex or an edge are
/// moved onto it, so that no sliver appears), every face they cross is re-triangulated with the
/// pieces as constraints (a constrained Delaunay triangulation in the plane of the face).
class Polyline_inserter
{
public:
  explicit Polyline_inserter(const Trace_mesh& m, double snap = 0.02) : m_m(m), m_snap(snap)
  {
    m_points = m.point;
  }

  /// Registers a polyline; returns its vertex chain (consecutive duplicates removed).
  std::vector<std::size_t> add(const std::vector<Surface_point>& polyline, bool closed)
  {
    std::vector<std::size_t> chain;
    for(const Surface_point& q : polyline)
    {
      const std::size_t id = point_id(q);
      if(chain.empty() || chain.back() != id)
        chain.push_back(id);
    }
    while(closed && chain.size() > 1 && chain.front() == chain.back())
      chain.pop_back();
    m_chains.emplace_back(chain, closed);
    return chain;
  }

  /// The refined mesh; false (with a reason) when a polyline leaves its faces.
  bool build(Refined_mesh& out, std::string& error)
  {
    // chords inside faces, and chains completed with the points they pass on shared edges
    std::map<std::size_t, std::vector<std::pair<std::size_t, std::size_t>>> chords;
    out.chains.clear();
    for(const auto& [chain, closed] : m_chains)
    {
      std::vector<std::size_t> full;
      const std::size_t n = chain.size();
      for(std::size_t k = 0; k < (closed ? n : n - 1) && n > 1; ++k)
      {
        const std::size_t p = chain[k], q = chain[(k + 1) % n];
        full.push_back(p);
        const auto common = common_faces(p, q);
        if(common.empty())
        {
          error = "a spectacles curve jumps between faces that do not touch";
          return false;
        }
        std::pair<std::size_t, std::size_t> e;
        if(on_common_edge(p, q, e))
        {
          // along an edge: the points inserted on it in between
          const double tp = edge_parameter(p, e), tq = edge_parameter(q, e);
          std::vector<std::pair<double, std::size_t>> between;
          for(const auto& [t, id] : m_on_edge[e])
            if((t - tp) * (t - tq) < 0.)
              between.emplace_back(tq > tp ? t : -t, id);
          std::sort(between.begin(), between.end());
          for(const auto& x : between)
            full.push_back(x.second);
        }
        else
          chords[common.front()].emplace_back(p, q);
      }
      if(!closed && n > 0)
        full.push_back(chain.back());
      out.chains.push_back(std::move(full));
    }
    std::set<std::size_t> affected;
    for(const auto& [f, c] : chords)
      affected.insert(f);
    for(const auto& [f, pts] : m_in_face)
      affected.insert(f);
    for(const auto& [e, pts] : m_on_edge)
      if(!pts.empty())
        for(std::size_t f : faces_of_edge(e.first, e.second))
          affected.insert(f);
    out.points = m_points;
    out.triangles.clear();
    for(std::size_t f = 0; f < m_m.number_of_faces(); ++f)
      if(!affected.count(f))
        out.triangles.push_back(m_m.tri[f]);
    for(std::size_t f : affected)
      if(!triangulate(f, chords[f], out.triangles, error))
        return false;
    // an edge between two curve points that is not a piece of a curve would be flat once they
    // are held at one value (across the corner between a frame and the bridge, where the
    // function rises): it is split at its middle by a free vertex
    std::vector<char> on_curve(out.points.size(), 0);
    std::set<Edge_key> pieces;
    for(std::size_t k = 0; k < out.chains.size(); ++k)
    {
      const auto& chain = out.chains[k];
      for(std::size_t v : chain)
        on_curve[v] = 1;
      const bool closed = m_chains[k].second;
      for(std::size_t j = 0; j + 1 < chain.size() + (closed ? 1 : 0) && chain.size() > 1; ++j)
      {
        const std::size_t a = chain[j], b = chain[(j + 1) % chain.size()];
        pieces.insert({(std::min)(a, b), (std::max)(a, b)});
      }
    }
    std::map<Edge_key, std::size_t> middle;
    auto split = [&](std::size_t a, std::size_t b) -> std::size_t {
      const Edge_key e{(std::min)(a, b), (std::max)(a, b)};
      if(!on_curve[a] || !on_curve[b] || pieces.count(e))
        return npos;
      const auto it = middle.find(e);
      if(it != middle.end())
        return it->second;
      out.points.push_back(0.5 * (out.points[a] + out.points[b]));
      return middle[e] = out.points.size() - 1;
    };
    std::vector<std::array<std::size_t, 3>> triangles;
    for(const auto& t : out.triangles)
    {
      std::array<std::size_t, 3> m;
      int n = 0;
      for(int i = 0; i < 3; ++i)
        n += (m[std::size_t(i)] = split(t[std::size_t(i)], t[std::size_t((i + 1) % 3)])) != npos;
      if(n == 0)
      {
        triangles.push_back(t);
        continue;
      }
      // rotate so that edge 0 (t0 t1) is split, and with two splits, edge 1 too
      int r = 0;
      while(m[std::size_t(r)] == npos || (n == 2 && m[std::size_t((r + 1) % 3)] == npos))
        ++r;
      const std::size_t a = t[std::size_t(r)], b = t[std::size_t((r + 1) % 3)], c = t[std::size_t((r + 2) % 3)];
      const std::size_t ab = m[std::size_t(r)], bc = m[std::size_t((r + 1) % 3)], ca = m[std::size_t((r + 2) % 3)];
      if(n == 1)
      {
        triangles.push_back({a, ab, c});
        triangles.push_back({ab, b, c});
      }
      else if(n == 2)
      {
        triangles.push_back({ab, b, bc});
        triangles.push_back({a, ab, bc});
        triangles.push_back({a, bc, c});
      }
      else
      {
        triangles.push_back({a, ab, ca});
        triangles.push_back({ab, b, bc});
        triangles.push_back({ca, bc, c});
        triangles.push_back({ab, bc, ca});
      }
    }
    out.triangles.swap(triangles);
    return true;
  }

private:
  struct Location
  {
    Surface_point::Kind kind;
    std::size_t a, b; // vertex a; edge (a < b); face a
  };

  using Edge_key = std::pair<std::size_t, std::size_t>;

  std::vector<std::size_t> faces_of_edge(std::size_t a, std::size_t b) const
  {
    std::vector<std::size_t> out;
    for(const auto& [f, i] : m_m.star[a])
      for(int k = 1; k < 3; ++k)
        if(m_m.tri[f][(i + k) % 3] == b)
          out.push_back(f);
    return out;
  }

  Location location(std::size_t id) const
  {
    if(id < m_m.number_of_vertices())
      return {Surface_point::vertex, id, npos};
    return m_location[id - m_m.number_of_vertices()];
  }

  std::vector<std::size_t> faces_of(std::size_t id) const
  {
    const Location l = location(id);
    std::vector<std::size_t> out;
    if(l.kind == Surface_point::vertex)
      for(const auto& [f, i] : m_m.star[l.a])
        out.push_back(f);
    else if(l.kind == Surface_point::edge)
      out = faces_of_edge(l.a, l.b);
    else
      out.push_back(l.a);
    std::sort(out.begin(), out.end());
    return out;
  }

  std::vector<std::size_t> common_faces(std::size_t p, std::size_t q) const
  {
    const auto a = faces_of(p), b = faces_of(q);
    std::vector<std::size_t> out;
    std::set_intersection(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(out));
    return out;
  }

  // p and q on one mesh edge (vertices at its ends, or points inside it)
  bool on_common_edge(std::size_t p, std::size_t q, Edge_key& e) const
  {
    const Location a = location(p), b = location(q);
    if(a.kind == Surface_point::face || b.kind == Surface_point::face)
      return false;
    if(a.kind == Surface_point::edge)
      e = {a.a, a.b};
    else if(b.kind == Surface_point::edge)
      e = {b.a, b.b};
    else
      e = {(std::min)(a.a, b.a), (std::max)(a.a, b.a)};
    auto on = [&](const Location& l) {
      return l.kind == Surface_point::edge ? (l.a == e.first && l.b == e.second) : (l.a == e.first || l.a == e.second);
    };
    return on(a) && on(b) && !faces_of_edge(e.first, e.second).empty();
  }

  double edge_parameter(std::size_t id, const Edge_key& e) const
  {
    const Location l = location(id);
    if(l.kind == Surface_point::vertex)
      return l.a == e.first ? 0. : 1.;
    for(const auto& [t, x] : m_on_edge.at(e))
      if(x == id)
        return t;
    return 0.;
  }

  std::size_t new_point(const Location& l, const Eigen::Vector3d& p)
  {
    m_location.push_back(l);
    m_points.push_back(p);
    return m_points.size() - 1;
  }

  std::size_t edge_point(std::size_t a, std::size_t b, double t)
  {
    if(a > b)
    {
      std::swap(a, b);
      t = 1. - t;
    }
    if(!(t >= m_snap))
      return a;
    if(!(t <= 1. - m_snap))
      return b;
    auto& list = m_on_edge[{a, b}];
    for(const auto& [s, id] : list)
      if(std::abs(s - t) < m_snap)
        return id;
    const std::size_t id = new_point({Surface_point::edge, a, b}, (1. - t) * m_m.point[a] + t * m_m.point[b]);
    list.emplace_back(t, id);
    return id;
  }

  std::size_t point_id(const Surface_point& q)
  {
    switch(q.kind)
    {
    case Surface_point::vertex:
      return q.a;
    case Surface_point::edge:
      return edge_point(q.a, q.b, q.t);
    case Surface_point::face:
    default: {
      const std::size_t f = q.a;
      const Eigen::Vector3d b = m_m.barycentric(f, q.point);
      int big = 0, small = 0;
      for(int i = 1; i < 3; ++i)
      {
        if(b[i] > b[big])
          big = i;
        if(b[i] < b[small])
          small = i;
      }
      const auto& t = m_m.tri[f];
      if(b[big] > 1. - m_snap)
        return t[std::size_t(big)];
      if(b[small] < m_snap)
      {
        const int i = (small + 1) % 3, j = (small + 2) % 3;
        return edge_point(t[std::size_t(i)], t[std::size_t(j)], b[j] / (b[i] + b[j]));
      }
      auto& list = m_in_face[f];
      for(const auto& [c, id] : list)
        if((c - b).cwiseAbs().maxCoeff() < m_snap)
          return id;
      const std::size_t id = new_point({Surface_point::face, f, npos}, m_m.at(f, b));
      list.emplace_back(b, id);
      return id;
    }
    }
  }

  bool triangulate(std::size_t f, const std::vector<std::pair<std::size_t, std::size_t>>& chords,
                   std::vector<std::array<std::size_t, 3>>& out, std::string& error) const
  {
    using K = CGAL::Exact_predicates_inexact_constructions_kernel;
    using Vb = CGAL::Triangulation_vertex_base_with_info_2<std::size_t, K>;
    using Fb = CGAL::Constrained_triangulation_face_base_2<K>;
    using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
    using Cdt = CGAL::Constrained_Delaunay_triangulation_2<K, Tds, CGAL::Exact_predicates_tag>;
    const auto& t = m_m.tri[f];
    // plane coordinates: corner 0 at the origin, corner 1 on the x axis
    const Eigen::Vector3d x = (m_m.point[t[1]] - m_m.point[t[0]]).normalized();
    const Eigen::Vector3d y = m_m.normal[f].cross(x);
    std::array<K::Point_2, 3> corner;
    for(int i = 0; i < 3; ++i)
    {
      const Eigen::Vector3d d = m_m.point[t[std::size_t(i)]] - m_m.point[t[0]];
      corner[std::size_t(i)] = K::Point_2(d.dot(x), d.dot(y));
    }
    auto mix = [](const K::Point_2& a, const K::Point_2& b, double s) {
      return K::Point_2((1. - s) * a.x() + s * b.x(), (1. - s) * a.y() + s * b.y());
    };
    Cdt cdt;
    std::map<std::size_t, Cdt::Vertex_handle> handle;
    std::size_t inserted = 0;
    auto insert = [&](std::size_t id, const K::Point_2& p) {
      if(handle.count(id))
        return true;
      const auto v = cdt.insert(p);
      if(cdt.number_of_vertices() == inserted) // a point at the place of another one
        return false;
      ++inserted;
      v->info() = id;
      handle[id] = v;
      return true;
    };
    std::vector<std::size_t> boundary;
    for(int i = 0; i < 3; ++i)
    {
      const std::size_t a = t[std::size_t(i)], b = t[std::size_t((i + 1) % 3)];
      boundary.push_back(a);
      if(!insert(a, corner[std::size_t(i)]))
        break;
      const auto it = m_on_edge.find({(std::min)(a, b), (std::max)(a, b)});
      if(it == m_on_edge.end())
        continue;
      std::vector<std::pair<double, std::size_t>> pts; // parameter from a to b
      for(const auto& [s, id] : it->second)
        pts.emplace_back(a < b ? s : 1. - s, id);
      std::sort(pts.begin(), pts.end());
      for(const auto& [s, id] : pts)
      {
        boundary.push_back(id);
        if(!insert(id, mix(corner[std::size_t(i)], corner[std::size_t((i + 1) % 3)], s)))
          break;
      }
    }
    const auto in = m_in_face.find(f);
    if(in != m_in_face.end())
      for(const auto& [b, id] : in->second)
        insert(id, K::Point_2(b[1] * corner[1].x() + b[2] * corner[2].x(), b[1] * corner[1].y() + b[2] * corner[2].y()));
    std::size_t expected = boundary.size() + (in != m_in_face.end() ? in->second.size() : 0);
    if(inserted != expected)
    {
      error = "two spectacles points fall on one place in face " + std::to_string(f);
      return false;
    }
    for(std::size_t k = 0; k < boundary.size(); ++k)
      cdt.insert_constraint(handle[boundary[k]], handle[boundary[(k + 1) % boundary.size()]]);
    for(const auto& [p, q] : chords)
      if(handle.count(p) && handle.count(q))
        cdt.insert_constraint(handle[p], handle[q]);
    if(cdt.number_of_vertices() != inserted)
    {
      error = "spectacles curves cross inside face " + std::to_string(f);
      return false;
    }
    // the faces outside the constrained boundary (slivers between it and the convex hull)
    std::set<Cdt::Face_handle> outside;
    std::vector<Cdt::Face_handle> stack{cdt.infinite_face()};
    outside.insert(cdt.infinite_face());
    while(!stack.empty())
    {
      const auto g = stack.back();
      stack.pop_back();
      for(int i = 0; i < 3; ++i)
      {
        const auto n = g->neighbor(i);
        if(!outside.count(n) && !cdt.is_constrained(Cdt::Edge(g, i)))
        {
          outside.insert(n);
          stack.push_back(n);
        }
      }
    }
    for(auto g = cdt.finite_faces_begin(); g != cdt.finite_faces_end(); ++g)
      if(!outside.count(g))
        out.push_back({g->vertex(0)->info(), g->vertex(1)->info(), g->vertex(2)->info()});
    return true;
  }

  const Trace_mesh& m_m;
  double m_snap;
  std::vector<Eigen::Vector3d> m_points;
  std::vector<Location> m_location; // of the new points
  std::map<Edge_key, std::vector<std::pair<double, std::size_t>>> m_on_edge; // parameter from the smaller index
  std::map<std::size_t, std::vector<std::pair<Eigen::Vector3d, std::size_t>>> m_in_face; // barycentric
  std::vector<std::pair<std::vector<std::size_t>, bool>> m_chains;
};

} // namespace harmonic_quad
} // namespace internal
} // namespace Surface_design
} // namespace CGAL

#endif // CGAL_SURFACE_DESIGN_INTERNAL_HARMONIC_QUAD_REMESHING_SPECTACLES_H
