// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The harmonic function of Dong et al.: default constraints, the Dirichlet solve, critical points.

#ifndef CGAL_SURFACE_DESIGN_INTERNAL_HARMONIC_QUAD_REMESHING_HARMONIC_FUNCTION_H
#define CGAL_SURFACE_DESIGN_INTERNAL_HARMONIC_QUAD_REMESHING_HARMONIC_FUNCTION_H

#include <CGAL/Surface_design/exceptions.h>
#include <CGAL/Surface_design/internal/Solvers/Factored_system.h>
#include <CGAL/Surface_design/internal/Core/intrinsic_delaunay.h>
#include <CGAL/Surface_design/internal/Core/named_parameters.h>
#include <CGAL/Surface_design/internal/Harmonic_quad_remeshing/trace_mesh.h>

#include <Eigen/Sparse>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <functional>
#include <limits>
#include <map>
#include <queue>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_design {
namespace internal {
namespace harmonic_quad {

/// Simulation of simplicity: a is below b if u_a < u_b, or u_a == u_b and a < b.
inline bool below(const std::vector<double>& u, std::size_t a, std::size_t b)
{
  return u[a] < u[b] || (u[a] == u[b] && a < b);
}

/// Face-connected components of a trace mesh (vertex -> component, number of components).
inline std::pair<std::vector<std::size_t>, std::size_t> vertex_components(const Trace_mesh& m)
{
  Union_find sets(m.number_of_vertices());
  for(const auto& t : m.tri)
  {
    sets.unite(t[0], t[1]);
    sets.unite(t[0], t[2]);
  }
  std::vector<std::size_t> comp(m.number_of_vertices(), npos), root_comp(m.number_of_vertices(), npos);
  std::size_t n = 0;
  for(std::size_t v = 0; v < m.number_of_vertices(); ++v)
  {
    const std::size_t r = sets.find(v);
    if(root_comp[r] == npos)
      root_comp[r] = n++;
    comp[v] = root_comp[r];
  }
  return {comp, n};
}

/// Dijkstra distances along mesh edges from `sources`, optionally stopping beyond `radius`.
inline std::vector<double> edge_distances(const Trace_mesh& m, const std::vector<std::size_t>& sources,
                                          double radius = std::numeric_limits<double>::infinity())
{
  std::vector<double> d(m.number_of_vertices(), std::numeric_limits<double>::infinity());
  using Item = std::pair<double, std::size_t>;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> queue;
  for(std::size_t s : sources)
  {
    d[s] = 0.;
    queue.emplace(0., s);
  }
  while(!queue.empty())
  {
    const auto [dv, v] = queue.top();
    queue.pop();
    if(dv > d[v] || dv > radius)
      continue;
    for(const auto& [f, i] : m.star[v])
      for(int k = 1; k < 3; ++k)
      {
        const std::size_t w = m.tri[f][(i + k) % 3];
        const double dw = dv + (m.point[w] - m.point[v]).norm();
        if(dw < d[w])
        {
          d[w] = dw;
          queue.emplace(dw, w);
        }
      }
  }
  return d;
}

/// The default constraints (documented in the manual):
/// per connected component, a minimum (value 0) and a maximum (value 1) at the two ends of an
/// approximate geodesic diameter (two Dijkstra sweeps along the edges: a = farthest vertex from the
/// component's first vertex, b = farthest from a). With `protrusions`, every tip t of the shape
/// also becomes a maximum, with value d(a, t) / d(a, b): a tip is a vertex whose distance from a
/// is largest within the geodesic ball of radius `tip_radius_ratio` * d(a, b) around it.
/// Without them, a protrusion the diameter misses has an almost constant function (Dong et
/// al.'s harmonic field avoids it) and is covered by a few large cells.
inline std::vector<std::pair<std::size_t, double>>
default_constraints(const Trace_mesh& m, bool protrusions, double tip_radius_ratio = 0.25)
{
  const auto components = vertex_components(m);
  const auto& comp = components.first; // a reference, not a structured binding: the lambdas capture it
  const std::size_t ncomp = components.second;
  std::vector<std::pair<std::size_t, double>> out;
  std::vector<std::size_t> first(ncomp, npos);
  for(std::size_t v = 0; v < m.number_of_vertices(); ++v)
    if(first[comp[v]] == npos)
      first[comp[v]] = v;
  for(std::size_t c = 0; c < ncomp; ++c)
  {
    auto farthest = [&](const std::vector<double>& d) {
      std::size_t best = first[c];
      for(std::size_t v = 0; v < m.number_of_vertices(); ++v)
        if(comp[v] == c && d[v] > d[best])
          best = v;
      return best;
    };
    const std::size_t a = farthest(edge_distances(m, {first[c]}));
    const std::vector<double> da = edge_distances(m, {a});
    const std::size_t b = farthest(da);
    const double diameter = da[b];
    out.emplace_back(a, 0.);
    out.emplace_back(b, 1.);
    if(!protrusions || !(diameter > 0.))
      continue;
    std::vector<double> dist(m.number_of_vertices(), std::numeric_limits<double>::infinity());
    std::vector<std::size_t> ball;
    for(std::size_t t = 0; t < m.number_of_vertices(); ++t)
    {
      if(comp[t] != c || t == b || da[t] < 0.3 * diameter)
        continue;
      bool local = true;
      for(const auto& [f, i] : m.star[t])
        for(int k = 1; k < 3 && local; ++k)
          local = !below(da, t, m.tri[f][(i + k) % 3]);
      if(!local)
        continue;
      // the ball around t, grown until a vertex farther from a shows up
      const double radius = tip_radius_ratio * diameter;
      bool tip = true;
      for(std::size_t v : ball)
        dist[v] = std::numeric_limits<double>::infinity();
      ball.clear();
      using Item = std::pair<double, std::size_t>;
      std::priority_queue<Item, std::vector<Item>, std::greater<Item>> queue;
      dist[t] = 0.;
      ball.push_back(t);
      queue.emplace(0., t);
      while(!queue.empty() && tip)
      {
        const auto [dv, v] = queue.top();
        queue.pop();
        if(dv > dist[v])
          continue;
        if(below(da, t, v) || v == b)
          tip = false;
        for(const auto& [f, i] : m.star[v])
          for(int k = 1; k < 3; ++k)
          {
            const std::size_t w = m.tri[f][(i + k) % 3];
            const double dw = dv + (m.point[w] - m.point[v]).norm();
            if(dw < dist[w] && dw <= radius)
            {
              if(!std::isfinite(dist[w]))
                ball.push_back(w);
              dist[w] = dw;
              queue.emplace(dw, w);
            }
          }
      }
      if(tip)
        out.emplace_back(t, da[t] / diameter);
    }
  }
  return out;
}

/// The harmonic function with Dirichlet constraints u_c = value and natural (zero-flux) boundary
/// elsewhere: L_FF u_F = -L_FC u_C for the Laplacian L = sum_e w_e (e_i - e_j)(e_i - e_j)^T.
template <class SolverTraits>
class Harmonic_solver
{
public:
  Harmonic_solver(std::size_t nv, std::vector<Weighted_edge> weights, SolverTraits traits)
    : m_nv(nv), m_weights(std::move(weights)), m_system(std::move(traits), "harmonic (Dirichlet) system")
  {}

  const std::vector<Weighted_edge>& weights() const { return m_weights; }
  SolverTraits& traits() { return m_system.traits(); }

  /// Factors L_FF for the constrained vertex set (a no-op if it is the one already factored).
  void factor(const std::vector<char>& constrained)
  {
    if(m_system.is_factored() && constrained == m_constrained)
      return;
    m_constrained = constrained;
    m_slot.assign(m_nv, npos);
    std::size_t n = 0;
    for(std::size_t v = 0; v < m_nv; ++v)
      if(!constrained[v])
        m_slot[v] = n++;
    if(n == 0)
      return;
    std::vector<Eigen::Triplet<double>> entries;
    entries.reserve(4 * m_weights.size());
    std::vector<double> diagonal(n, 0.);
    for(const Weighted_edge& e : m_weights)
    {
      const std::size_t si = m_slot[e.i], sj = m_slot[e.j];
      if(si != npos)
        diagonal[si] += e.w;
      if(sj != npos)
        diagonal[sj] += e.w;
      if(si != npos && sj != npos)
      {
        entries.emplace_back(Eigen::Index(si), Eigen::Index(sj), -e.w);
        entries.emplace_back(Eigen::Index(sj), Eigen::Index(si), -e.w);
      }
    }
    for(std::size_t k = 0; k < n; ++k)
      entries.emplace_back(Eigen::Index(k), Eigen::Index(k), diagonal[k]);
    const Eigen::Index size = static_cast<Eigen::Index>(n);
    Eigen::SparseMatrix<double> a(size, size);
    a.setFromTriplets(entries.begin(), entries.end());
    m_system.factor(std::move(a));
  }

  /// Solves for every vertex value; `u` holds the constrained values on input.
  void solve(std::vector<double>& u)
  {
    std::size_t n = 0;
    for(std::size_t v = 0; v < m_nv; ++v)
      n += m_slot[v] != npos;
    if(n == 0)
      return;
    Eigen::VectorXd b = Eigen::VectorXd::Zero(Eigen::Index(n));
    for(const Weighted_edge& e : m_weights)
    {
      const std::size_t si = m_slot[e.i], sj = m_slot[e.j];
      if(si != npos && sj == npos)
        b[Eigen::Index(si)] += e.w * u[e.j];
      if(sj != npos && si == npos)
        b[Eigen::Index(sj)] += e.w * u[e.i];
    }
    const Eigen::VectorXd x = m_system.solve(b);
    for(std::size_t v = 0; v < m_nv; ++v)
      if(m_slot[v] != npos)
        u[v] = x[Eigen::Index(m_slot[v])];
  }

private:
  std::size_t m_nv;
  std::vector<Weighted_edge> m_weights;
  Factored_system<SolverTraits> m_system;
  std::vector<char> m_constrained;
  std::vector<std::size_t> m_slot;
};

/// Checks user constraints: vertices in range and distinct, finite values, and on every
/// connected component at least two different values (else the function is constant there).
inline void check_constraints(const Trace_mesh& m, const std::vector<std::pair<std::size_t, double>>& c)
{
  const auto [comp, ncomp] = vertex_components(m);
  std::vector<double> lo(ncomp, std::numeric_limits<double>::infinity()), hi(ncomp, -lo[0]);
  std::vector<char> seen(m.number_of_vertices(), 0);
  for(const auto& [v, value] : c)
  {
    if(v >= m.number_of_vertices())
      throw Invalid_constraints("constraint vertex " + std::to_string(v) + " is out of range (the mesh has " +
                                std::to_string(m.number_of_vertices()) + " vertices)");
    if(!std::isfinite(value))
      throw Invalid_constraints("the value of vertex " + std::to_string(v) + " is " + to_text(value));
    if(seen[v])
      throw Invalid_constraints("vertex " + std::to_string(v) + " is constrained twice");
    seen[v] = 1;
    lo[comp[v]] = (std::min)(lo[comp[v]], value);
    hi[comp[v]] = (std::max)(hi[comp[v]], value);
  }
  for(std::size_t k = 0; k < ncomp; ++k)
    if(!(hi[k] > lo[k]))
      throw Invalid_constraints(
        "connected component " + std::to_string(k) +
        (std::isfinite(lo[k]) ? " has constraints on one value only (" + to_text(lo[k]) +
                                  "): give at least one minimum and one maximum"
                              : " has no constraint: give at least one minimum and one maximum there"));
}

/// Kind of a vertex of a piecewise-linear function (Edelsbrunner, Harer & Zomorodian 2003).
enum class Critical_kind
{
  regular,
  minimum,
  maximum,
  saddle
};

struct Critical_point
{
  std::size_t vertex;
  Critical_kind kind;
  int multiplicity; ///< 1 for extrema; k - 1 for a saddle whose lower link has k pieces
  bool on_boundary;
};

/// Every critical vertex, and the sum of the indices 1 - chi(lower link), which equals the
/// Euler characteristic of the mesh.
inline std::pair<std::vector<Critical_point>, long> critical_points(const Trace_mesh& m, const std::vector<double>& u)
{
  std::vector<Critical_point> out;
  long index_sum = 0;
  std::vector<std::size_t> link;
  for(std::size_t v = 0; v < m.number_of_vertices(); ++v)
  {
    link.clear();
    long lower_edges = 0;
    for(const auto& [f, i] : m.star[v])
    {
      const std::size_t a = m.tri[f][(i + 1) % 3], b = m.tri[f][(i + 2) % 3];
      link.push_back(a);
      link.push_back(b);
      lower_edges += below(u, a, v) && below(u, b, v);
    }
    std::sort(link.begin(), link.end());
    link.erase(std::unique(link.begin(), link.end()), link.end());
    long lower = 0, upper = 0;
    for(std::size_t w : link)
      (below(u, w, v) ? lower : upper) += 1;
    const long index = 1 - (lower - lower_edges);
    index_sum += index;
    const bool boundary = m.on_boundary[v] != 0;
    if(lower == 0)
      out.push_back({v, Critical_kind::minimum, 1, boundary});
    else if(upper == 0)
      out.push_back({v, Critical_kind::maximum, 1, boundary});
    else if(index < 0)
      out.push_back({v, Critical_kind::saddle, int(-index), boundary});
  }
  return {out, index_sum};
}

} // namespace harmonic_quad
} // namespace internal
} // namespace Surface_design
} // namespace CGAL

#endif // CGAL_SURFACE_DESIGN_INTERNAL_HARMONIC_QUAD_REMESHING_HARMONIC_FUNCTION_H
