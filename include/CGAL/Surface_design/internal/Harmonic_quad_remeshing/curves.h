// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Isolines (marching triangles) and gradient lines (face to face) of a piecewise-linear function.

#ifndef CGAL_SURFACE_DESIGN_INTERNAL_HARMONIC_QUAD_REMESHING_CURVES_H
#define CGAL_SURFACE_DESIGN_INTERNAL_HARMONIC_QUAD_REMESHING_CURVES_H

#include <CGAL/Surface_design/internal/Harmonic_quad_remeshing/harmonic_function.h>
#include <CGAL/Surface_design/internal/Harmonic_quad_remeshing/trace_mesh.h>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Surface_design {
namespace internal {
namespace harmonic_quad {

/// What a curve of the net is: a piece of a level set, or a frame or the bridge of spectacles
/// (curves along mesh edges at the value of a saddle, see spectacles.h).
enum class Curve_role { level_set, spectacles_frame, spectacles_bridge };

/// One connected piece of the level set u = value: a closed loop, or an open path from boundary
/// to boundary. Segment k lies in face faces[k] and runs from point[k] to point[k + 1] (index
/// taken mod the number of segments on a loop), in the direction n x grad u (higher values on
/// the right). Every point lies inside a mesh edge (levels avoid vertex values).
struct Isoline
{
  double value = 0.;
  bool closed = false;
  std::vector<std::size_t> faces;
  std::vector<Eigen::Vector3d> point;
  std::vector<std::size_t> point_edge; ///< mesh edge of each point
  std::vector<double> arc;             ///< arc length at each point (and the total at the end for loops)

  Curve_role role = Curve_role::level_set;

  std::size_t segments() const { return faces.size(); }
  double length() const { return arc.back(); }
  const Eigen::Vector3d& segment_end(std::size_t k) const { return point[closed ? (k + 1) % point.size() : k + 1]; }

  /// Arc-length position of a point lying on segment k.
  double arc_position(std::size_t k, const Eigen::Vector3d& p) const
  {
    const Eigen::Vector3d& a = point[k];
    const Eigen::Vector3d d = segment_end(k) - a;
    const double len2 = d.squaredNorm();
    const double t = len2 > 0. ? std::clamp((p - a).dot(d) / len2, 0., 1.) : 0.;
    return arc[k] + t * (arc[k + 1] - arc[k]);
  }

  /// Arc-length position of a point lying on segment k or on one of its two neighbours.
  double nearest_arc_position(std::size_t k, const Eigen::Vector3d& p) const
  {
    const std::size_t n = segments();
    double best = arc_position(k, p), distance = (at(best).first - p).squaredNorm();
    for(std::size_t j : {closed ? (k + n - 1) % n : (k == 0 ? k : k - 1), closed ? (k + 1) % n : (std::min)(k + 1, n - 1)})
    {
      const double s = arc_position(j, p), d = (at(s).first - p).squaredNorm();
      if(d < distance)
      {
        distance = d;
        best = s;
      }
    }
    return best;
  }

  /// Point and segment at arc-length position s (wrapped on loops).
  std::pair<Eigen::Vector3d, std::size_t> at(double s) const
  {
    if(closed)
    {
      s = std::fmod(s, length());
      if(s < 0.)
        s += length();
    }
    const std::size_t n = segments();
    std::size_t k = std::size_t(std::upper_bound(arc.begin(), arc.begin() + std::ptrdiff_t(n), s) - arc.begin());
    k = k == 0 ? 0 : (std::min)(k - 1, n - 1);
    const double len = arc[k + 1] - arc[k];
    const double t = len > 0. ? std::clamp((s - arc[k]) / len, 0., 1.) : 0.;
    return {(1. - t) * point[k] + t * segment_end(k), k};
  }
};

/// A value whose level set passes through no vertex: `c` moved up by small steps while it is
/// within `gap` of a vertex value (`sorted` holds the vertex values in increasing order).
inline double avoid_vertex_values(double c, const std::vector<double>& sorted, double gap)
{
  for(int guard = 0; guard < 64; ++guard)
  {
    const auto it = std::lower_bound(sorted.begin(), sorted.end(), c - gap);
    if(it == sorted.end() || *it > c + gap)
      return c;
    c = *it + 2. * gap;
  }
  return c;
}

/// Every connected piece of the level set u = c (c equal to no vertex value); with `seeds`, only
/// the pieces through one of those faces (then only the faces they cross are examined, besides
/// clearing two arrays of a byte or two per face).
inline std::vector<Isoline> extract_isolines(const Trace_mesh& m, const std::vector<double>& u, double c,
                                             const std::vector<std::size_t>* seeds = nullptr)
{
  const std::size_t nf = m.number_of_faces();
  // entry (rising) and exit (falling) local edges of every crossed face, found when first asked
  // for; a vertex valued c exactly counts as above (a symbolic perturbation of c downwards), so
  // that a face is crossed on two edges or on none (with a strict test, a level through a vertex
  // met its faces on one edge only: the walks below read past the cut table and ended paths
  // inside the surface)
  std::vector<std::pair<signed char, signed char>> cut_table(nf, {-2, -2});
  auto cut = [&](std::size_t f) -> const std::pair<signed char, signed char>& {
    auto& entry = cut_table[f];
    if(entry.first == -2)
    {
      entry = {-1, -1};
      const auto& t = m.tri[f];
      for(int i = 0; i < 3; ++i)
      {
        const bool a = u[t[i]] >= c, b = u[t[(i + 1) % 3]] >= c;
        if(!a && b)
          entry.first = static_cast<signed char>(i);
        else if(a && !b)
          entry.second = static_cast<signed char>(i);
      }
    }
    return entry;
  };
  auto edge_point = [&](std::size_t f, int i) {
    const std::size_t a = m.tri[f][i], b = m.tri[f][(i + 1) % 3];
    const double t = (c - u[a]) / (u[b] - u[a]);
    return Eigen::Vector3d((1. - t) * m.point[a] + t * m.point[b]);
  };
  std::vector<char> done(nf, 0);
  std::vector<Isoline> out;
  for(std::size_t seed = 0; seed < (seeds != nullptr ? seeds->size() : nf); ++seed)
  {
    const std::size_t f0 = seeds != nullptr ? (*seeds)[seed] : seed;
    // (a face meets the level on two edges, or on none when no vertex value equals it)
    if(done[f0] || cut(f0).first < 0 || cut(f0).second < 0)
      continue;
    // walk back to the start of an open path (or once around a loop)
    std::size_t start = f0;
    bool closed = false;
    for(std::size_t guard = 0; guard <= nf; ++guard)
    {
      const std::size_t prev = m.neighbour[start][std::size_t(cut(start).first)];
      if(prev == npos)
        break;
      if(prev == f0)
      {
        closed = true;
        break;
      }
      start = prev;
    }
    if(closed)
      start = f0;
    Isoline iso;
    iso.value = c;
    iso.closed = closed;
    std::size_t f = start;
    for(std::size_t guard = 0; guard <= nf; ++guard)
    {
      done[f] = 1;
      iso.faces.push_back(f);
      iso.point.push_back(edge_point(f, cut(f).first));
      iso.point_edge.push_back(m.edge[f][std::size_t(cut(f).first)]);
      const std::size_t next = m.neighbour[f][std::size_t(cut(f).second)];
      // (`next` is crossed too, and unvisited but for the start of a loop, on a manifold mesh)
      if(next == npos || (done[next] && next != start))
      {
        iso.point.push_back(edge_point(f, cut(f).second));
        iso.point_edge.push_back(m.edge[f][std::size_t(cut(f).second)]);
        break;
      }
      if(next == start && closed)
        break;
      f = next;
    }
    iso.arc.assign(1, 0.);
    for(std::size_t k = 0; k < iso.segments(); ++k)
      iso.arc.push_back(iso.arc.back() + (iso.segment_end(k) - iso.point[k]).norm());
    out.push_back(std::move(iso));
  }
  return out;
}

/// Where a gradient line ended.
struct Trace_end
{
  enum Kind
  {
    isoline,  ///< on an included isoline: `curve`, `segment`, `point`
    pole,     ///< at a local extremum: `vertex`
    boundary, ///< on the mesh boundary: `loop`, `loop_position`, `point`
    lost      ///< the walk did not end (should not happen)
  } kind = lost;
  std::size_t curve = npos, segment = npos, vertex = npos, loop = npos;
  double loop_position = 0.;
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
};

/// A point of the surface: a mesh vertex, a point inside a mesh edge, or a point inside a face.
struct Surface_point
{
  enum Kind
  {
    vertex, ///< vertex `a`
    edge,   ///< (1 - t) a + t b on the edge between vertices a and b
    face    ///< inside face `a`
  } kind = vertex;
  std::size_t a = npos, b = npos;
  double t = 0.;
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
};

/// An isoline segment registered in a face, for the gradient walk.
struct Face_level
{
  double value;
  std::size_t curve, segment;
};

/// Walks a gradient line of u (`direction` +1: ascending, -1: descending) from a point of a face
/// or from a vertex until it meets a registered isoline, an extremum of u, or the boundary.
/// Straight inside each face; through a vertex into the steepest face whose gradient leaves it
/// (else along the steepest edge); along an edge when both faces' gradients point into it.
class Gradient_walker
{
public:
  /// With `curves` (the isolines that `levels` refer to), a line that reaches a level held by
  /// two curves in one face (a frame and the bridge of spectacles around their junction) lands
  /// on the one nearer to where it reaches the level; else on the first registered.
  Gradient_walker(const Trace_mesh& m, const std::vector<double>& u,
                  const std::vector<std::vector<Face_level>>& levels, const std::vector<Isoline>* curves = nullptr)
    : m_m(m), m_u(u), m_levels(levels), m_curves(curves), m_grad(m.number_of_faces())
  {
    for(std::size_t f = 0; f < m.number_of_faces(); ++f)
      m_grad[f] = m.gradient(f, u);
  }

  const Eigen::Vector3d& gradient(std::size_t f) const { return m_grad[f]; }

  /// From point p of face f, where u = value (the isoline there is not met again). With `path`,
  /// the points where the line enters faces, vertices and edges are appended to it (the start,
  /// every vertex and edge crossing, the end).
  Trace_end from_face(std::size_t f, const Eigen::Vector3d& p, double value, int direction,
                      std::vector<Surface_point>* path = nullptr) const
  {
    Eigen::Vector3d bary = m_m.barycentric(f, p);
    return walk(f, bary, npos, value, direction, path);
  }

  Trace_end from_vertex(std::size_t v, int direction, std::vector<Surface_point>* path = nullptr) const
  {
    return walk(npos, {}, v, m_u[v], direction, path);
  }

private:
  // first registered level strictly between `from` and `to` (in the walking direction) in face f
  const Face_level* level_between(std::size_t f, double from, double to, int direction, bool inclusive) const
  {
    const Face_level* best = nullptr;
    for(const Face_level& l : m_levels[f])
    {
      const bool inside = direction > 0 ? (l.value > from && l.value <= to) : (l.value < from && l.value >= to);
      // a level met exactly where the walk crossed into this face (rounding may have missed it
      // in the face before), but never the level the line started on
      const bool at_entry = inclusive && l.value == from;
      if(!inside && !at_entry)
        continue;
      if(best == nullptr || (direction > 0 ? l.value < best->value : l.value > best->value))
        best = &l;
    }
    return best;
  }

  // p: where the line reaches level l in face f
  Trace_end landed(const Face_level& l, const Eigen::Vector3d& p, std::size_t f) const
  {
    Trace_end e;
    e.kind = Trace_end::isoline;
    e.curve = l.curve;
    e.segment = l.segment;
    e.point = p;
    // (`l` is an element of m_levels[f]: every caller found it there)
    const auto other_at_level = [&](const Face_level& k) { return k.value == l.value && &k != &l; };
    const bool tie = m_curves != nullptr && std::any_of(m_levels[f].begin(), m_levels[f].end(), other_at_level);
    if(!tie)
      return e;
    auto distance = [&](const Face_level& k) {
      const Isoline& iso = (*m_curves)[k.curve];
      return (iso.at(iso.nearest_arc_position(k.segment, p)).first - p).squaredNorm();
    };
    double best = distance(l);
    for(const Face_level& k : m_levels[f])
      if(other_at_level(k))
      {
        const double d = distance(k);
        if(d < best)
        {
          best = d;
          e.curve = k.curve;
          e.segment = k.segment;
        }
      }
    return e;
  }

  Trace_end on_boundary(std::size_t a, std::size_t b, double t) const
  {
    // edge a -> b runs counter-clockwise in its face: along the boundary loop, b follows a
    Trace_end e;
    e.kind = Trace_end::boundary;
    e.loop = m_m.boundary_position[a].first;
    e.loop_position = double(m_m.boundary_position[a].second) + t;
    e.point = (1. - t) * m_m.point[a] + t * m_m.point[b];
    return e;
  }

  Trace_end walk(std::size_t f, Eigen::Vector3d bary, std::size_t v, double value, int direction,
                 std::vector<Surface_point>* path) const
  {
    const double s = direction > 0 ? 1. : -1.;
    // a line never lands at or behind its starting level, even where rounding moves it back a
    // little (snapping to a vertex next to the start)
    const double start = value;
    auto level_between = [&](std::size_t face, double from, double to, int dir) {
      const bool beyond = dir > 0 ? from > start : from < start;
      return this->level_between(face, beyond ? from : start, to, dir, beyond);
    };
    auto record = [&](Surface_point::Kind kind, std::size_t a, std::size_t b, double t, const Eigen::Vector3d& p) {
      if(path == nullptr)
        return;
      Surface_point q;
      q.kind = kind;
      q.a = a;
      q.b = b;
      q.t = t;
      q.point = p;
      path->push_back(q);
    };
    if(v != npos)
      record(Surface_point::vertex, v, npos, 0., m_m.point[v]);
    else
      record(Surface_point::face, f, npos, 0., m_m.at(f, bary));
    auto higher = [&](std::size_t a, std::size_t b) { return direction > 0 ? below(m_u, b, a) : below(m_u, a, b); };
    const std::size_t guard = 20 * m_m.number_of_faces() + 1000;
    for(std::size_t step = 0; step < guard; ++step)
    {
      if(v != npos) // at a vertex
      {
        value = m_u[v];
        if(path != nullptr && !(path->back().kind == Surface_point::vertex && path->back().a == v))
          record(Surface_point::vertex, v, npos, 0., m_m.point[v]);
        std::size_t best_face = npos;
        double best = 0.;
        for(const auto& [g, i] : m_m.star[v])
        {
          const Eigen::Vector3d d = s * m_grad[g];
          if(m_m.grad_lambda[g][(i + 1) % 3].dot(d) >= 0. && m_m.grad_lambda[g][(i + 2) % 3].dot(d) >= 0. &&
             d.squaredNorm() > best)
          {
            best = d.squaredNorm();
            best_face = g;
          }
        }
        if(best_face != npos)
        {
          f = best_face;
          bary = Eigen::Vector3d::Zero();
          for(const auto& [g, i] : m_m.star[v])
            if(g == f)
              bary[i] = 1.;
          v = npos;
          continue;
        }
        // steepest edge upwards (strictly: a tie would let the line crawl along a plateau, such
        // as a boundary rim held at one value); none: an extremum, the line's pole (shared by
        // every line that ends there, also on the boundary)
        std::size_t w_best = npos, edge_face = npos;
        double slope = 0.;
        for(const auto& [g, i] : m_m.star[v])
          for(int k = 1; k < 3; ++k)
          {
            const std::size_t w = m_m.tri[g][(i + k) % 3];
            if(!(s * (m_u[w] - m_u[v]) > 0.))
              continue;
            const double sl = s * (m_u[w] - m_u[v]) / (m_m.point[w] - m_m.point[v]).norm();
            if(w_best == npos || sl > slope)
            {
              slope = sl;
              w_best = w;
              edge_face = g;
            }
          }
        if(w_best == npos)
        {
          Trace_end e;
          e.kind = Trace_end::pole;
          e.vertex = v;
          e.point = m_m.point[v];
          return e;
        }
        if(const Face_level* l = level_between(edge_face, value, m_u[w_best], direction))
        {
          const double t = (l->value - m_u[v]) / (m_u[w_best] - m_u[v]);
          record(Surface_point::edge, v, w_best, t, (1. - t) * m_m.point[v] + t * m_m.point[w_best]);
          return landed(*l, (1. - t) * m_m.point[v] + t * m_m.point[w_best], edge_face);
        }
        v = w_best;
        continue;
      }
      // inside face f at barycentric coordinates `bary`
      const Eigen::Vector3d d = s * m_grad[f];
      const double speed = d.squaredNorm(); // |du/dt| along d
      if(!(speed > 0.))
      {
        std::size_t top = m_m.tri[f][0];
        for(int i = 1; i < 3; ++i)
          if(higher(m_m.tri[f][std::size_t(i)], top))
            top = m_m.tri[f][std::size_t(i)];
        v = top;
        continue;
      }
      double t_exit = std::numeric_limits<double>::infinity();
      int exit_corner = -1;
      for(int i = 0; i < 3; ++i)
      {
        const double rate = m_m.grad_lambda[f][std::size_t(i)].dot(d);
        if(rate < 0.)
        {
          const double t = (std::max)(0., bary[i]) / -rate;
          if(t < t_exit)
          {
            t_exit = t;
            exit_corner = i;
          }
        }
      }
      if(exit_corner < 0) // no edge ahead (a numerically flat face): continue from its top vertex
      {
        std::size_t top = m_m.tri[f][0];
        for(int i = 1; i < 3; ++i)
          if(higher(m_m.tri[f][std::size_t(i)], top))
            top = m_m.tri[f][std::size_t(i)];
        v = top;
        continue;
      }
      const double exit_value = value + s * t_exit * speed;
      if(const Face_level* l = level_between(f, value, exit_value, direction))
      {
        const double t = s * (l->value - value) / speed;
        record(Surface_point::face, f, npos, 0., m_m.at(f, bary) + t * d);
        return landed(*l, m_m.at(f, bary) + t * d, f);
      }
      // exit through the edge opposite exit_corner: local edge (exit_corner + 1)
      for(int i = 0; i < 3; ++i)
        bary[i] += t_exit * m_m.grad_lambda[f][std::size_t(i)].dot(d);
      const int e = (exit_corner + 1) % 3, j = e, k = (e + 1) % 3;
      bary[exit_corner] = 0.;
      const double wj = (std::max)(0., bary[j]), wk = (std::max)(0., bary[k]);
      const double t = wj + wk > 0. ? wk / (wj + wk) : 0.5; // from corner j to corner k
      const std::size_t a = m_m.tri[f][std::size_t(j)], b = m_m.tri[f][std::size_t(k)];
      value = m_u[a] + t * (m_u[b] - m_u[a]); // exactly their value on an edge whose ends share one
      const std::size_t g = m_m.neighbour[f][std::size_t(e)];
      if(g == npos) // the boundary, even at one of its vertices
      {
        record(Surface_point::edge, a, b, t, (1. - t) * m_m.point[a] + t * m_m.point[b]);
        return on_boundary(a, b, t);
      }
      constexpr double snap = 1e-9;
      if(t < snap || t > 1. - snap)
      {
        v = t < snap ? a : b;
        continue;
      }
      const int eg = m_m.neighbour_edge[f][std::size_t(e)]; // runs b -> a in g
      const Eigen::Vector3d dg = s * m_grad[g];
      if(m_m.grad_lambda[g][std::size_t((eg + 2) % 3)].dot(dg) <= 0.)
      {
        // both gradients point into the edge: slide along it to its higher end
        const std::size_t top = higher(a, b) ? a : b;
        record(Surface_point::edge, a, b, t, (1. - t) * m_m.point[a] + t * m_m.point[b]);
        if(const Face_level* l = level_between(f, value, m_u[top], direction))
        {
          const double tl = (l->value - m_u[a]) / (m_u[b] - m_u[a]);
          record(Surface_point::edge, a, b, tl, (1. - tl) * m_m.point[a] + tl * m_m.point[b]);
          return landed(*l, (1. - tl) * m_m.point[a] + tl * m_m.point[b], f);
        }
        v = top;
        continue;
      }
      record(Surface_point::edge, a, b, t, (1. - t) * m_m.point[a] + t * m_m.point[b]);
      f = g;
      bary = Eigen::Vector3d::Zero();
      bary[eg] = t;           // corner eg is vertex b
      bary[(eg + 1) % 3] = 1. - t; // corner eg + 1 is vertex a
    }
    return Trace_end();
  }

  const Trace_mesh& m_m;
  const std::vector<double>& m_u;
  const std::vector<std::vector<Face_level>>& m_levels;
  const std::vector<Isoline>* m_curves;
  std::vector<Eigen::Vector3d> m_grad;
};

} // namespace harmonic_quad
} // namespace internal
} // namespace Surface_design
} // namespace CGAL

#endif // CGAL_SURFACE_DESIGN_INTERNAL_HARMONIC_QUAD_REMESHING_CURVES_H
