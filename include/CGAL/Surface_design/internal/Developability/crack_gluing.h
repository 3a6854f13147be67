// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Gluing the small cracks of a flattening back together (Stein, Grinspun & Crane 2018, sec. 4.4
// and Fig. 19, bottom): the dangling branches of a cut whose two sides barely open in the plane.

#ifndef CGAL_SURFACE_DESIGN_INTERNAL_DEVELOPABILITY_CRACK_GLUING_H
#define CGAL_SURFACE_DESIGN_INTERNAL_DEVELOPABILITY_CRACK_GLUING_H

#include <CGAL/Surface_design/exceptions.h>
#include <CGAL/Surface_design/internal/Core/Mesh_indices.h>
#include <CGAL/Surface_design/internal/Core/cut_mesh.h>
#include <CGAL/Surface_design/internal/Core/geometry.h>
#include <CGAL/Surface_design/internal/Core/topology.h>
#include <CGAL/Surface_design/internal/Developability/cut_graph.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <sstream>
#include <tuple>
#include <vector>

namespace CGAL {
namespace Surface_design {
namespace internal {

struct Crack_gluing_options
{
  double opening_bound = 0.;     ///< glue a crack only where its sides open by at most this angle (radians)
  double distortion_bound = 0.;  ///< > 0: keep 2 max |u| of the flattening at most this (or what it was)
  std::size_t max_rounds = 64;
};

struct Crack_gluing
{
  std::vector<bool> edge_is_cut;  ///< the cut after gluing
  std::size_t cracks = 0;         ///< connected parts of the glued edges (the cracks closed, whole or in part)
  std::size_t glued_edges = 0;
  std::size_t rounds = 0;         ///< rounds that glued something
  std::size_t reductions = 0;     ///< candidate sets halved because the distortion bound would break
  bool converged = true;          ///< false if the rounds ran out while cracks were still being glued
  double largest_log_area_scale_before = 0., largest_log_area_scale = 0.; ///< 2 max |u| of the flattenings
  Cut_topology topology;          ///< of the glued cut (same pieces, all of the input cut's topology)
};

namespace crack_gluing_detail {

struct Candidate
{
  double opening; // largest |opening angle| of the crack from its tip up to and including this edge
  std::size_t position, crack, edge;
};

inline double largest_scale(const std::vector<double>& u)
{
  double m = 0.;
  for(double x : u)
    m = (std::max)(m, 2. * std::abs(x));
  return m;
}

} // namespace crack_gluing_detail

/// Per vertex, delta_v = K_v + (A u)_v: the angle by which the angle sum of the flattening with log
/// scale factors `u` (cut_scale_factors()) misses 2 pi around v, all of v's corners together. 0
/// off the cut (the equations solved there); on the cut, the sum over a crack from its tip is how
/// far its two sides have turned apart. `weight`: cotangent weights, `angle_sum`: angle sums.
template <class Indices>
std::vector<double> crack_openings(const Indices& idx, const std::vector<double>& weight,
                                   const std::vector<double>& angle_sum, const std::vector<double>& u)
{
  std::vector<double> delta(idx.number_of_vertices());
  for(std::size_t v = 0; v < delta.size(); ++v)
    delta[v] = two_pi - angle_sum[v];
  for(std::size_t e = 0; e < idx.number_of_edges(); ++e)
  {
    const auto ab = idx.edge_vertices(e);
    const double flow = weight[e] * (u[ab.first] - u[ab.second]);
    delta[ab.first] += flow;
    delta[ab.second] -= flow;
  }
  return delta;
}

/// Glues the cracks of the flattening that keeps the cut's lengths (Boundary First Flattening
/// with u_B = 0, u from cut_scale_factors()).
///
/// A *crack* is a dangling branch of the cut: a path v_0 v_1 ... from a tip v_0 (one cut edge,
/// not on the border) through vertices with two cut edges, up to the first vertex with another
/// number, or on the border. In the flattening, the two sides of the crack leave v_0 at the angle
/// delta_0 and turn apart by delta_i at every v_i (crack_openings()): the crack opens at v_j by
/// Phi_j = delta_0 + ... + delta_j, and the gap between its sides grows by 2 |sin(Phi_j / 2)|
/// |v_j v_{j+1}| along the edge after v_j, which gluing that edge closes. The candidates are the
/// edges whose crack opens by at most `opening_bound` from the tip up to them, narrowest first
/// (a prefix of every crack); a connected part of the cut that does not reach the border keeps
/// two edges (a single edge would leave a free slit, nothing a closed surface opens along). With
/// a distortion bound, the candidates are glued only if the new flattening keeps 2 max |u| at
/// most max(bound, its value before the gluing): else the half with the widest openings is
/// dropped, until the rest passes or none is left. Every round solves again and glues the cracks'
/// new tips, until nothing is glued (or `max_rounds` rounds have: `converged` false). Gluing
/// dangling edges keeps every piece's topology (one vertex and one edge fewer in the cut mesh),
/// which is checked.
template <class Indices, class VertexPointMap, class SolverTraits>
Crack_gluing glue_cracks(const Indices& idx, const VertexPointMap& vpm, const std::vector<bool>& edge_is_cut,
                         const Crack_gluing_options& o, const SolverTraits& traits)
{
  using namespace crack_gluing_detail;
  const auto& tm = idx.mesh();
  const std::size_t nv = idx.number_of_vertices(), ne = idx.number_of_edges();
  const std::vector<double> weight = cotangent_weights(idx, vpm);
  const std::vector<double> angle_sum = vertex_angle_sums(idx, corner_angles(idx, vpm));
  std::vector<bool> on_border(nv, false);
  for(std::size_t e = 0; e < ne; ++e)
  {
    const auto h = halfedge(idx.edge(e), tm);
    if(idx.is_border(h) || idx.is_border(opposite(h, tm)))
    {
      const auto ab = idx.edge_vertices(e);
      on_border[ab.first] = on_border[ab.second] = true;
    }
  }

  Crack_gluing r;
  r.edge_is_cut = edge_is_cut;
  for(std::size_t e = 0; e < ne; ++e) // border edges are open already
  {
    const auto h = halfedge(idx.edge(e), tm);
    if(idx.is_border(h) || idx.is_border(opposite(h, tm)))
      r.edge_is_cut[e] = false;
  }
  const std::vector<bool> was_cut = r.edge_is_cut;
  const Cut_corners corners_before = cut_corners(idx, r.edge_is_cut);
  const Cut_topology before = cut_topology(idx, r.edge_is_cut, corners_before);

  std::vector<double> u = cut_scale_factors(idx, weight, angle_sum, r.edge_is_cut, traits);
  r.largest_log_area_scale_before = r.largest_log_area_scale = largest_scale(u);
  std::vector<std::size_t> degree(nv);
  std::vector<Candidate> candidates;
  for(std::size_t round = 0;; ++round)
  {
    std::fill(degree.begin(), degree.end(), std::size_t(0));
    for(std::size_t e = 0; e < ne; ++e)
      if(r.edge_is_cut[e])
      {
        const auto ab = idx.edge_vertices(e);
        ++degree[ab.first];
        ++degree[ab.second];
      }
    const std::vector<double> delta = crack_openings(idx, weight, angle_sum, u);
    // the connected parts of the cut: one off the border must keep two edges (a closed surface
    // opens into a disk only along two edges or more; one edge alone would be a free slit)
    Union_find parts(nv);
    for(std::size_t e = 0; e < ne; ++e)
      if(r.edge_is_cut[e])
      {
        const auto ab = idx.edge_vertices(e);
        parts.unite(ab.first, ab.second);
      }
    std::vector<std::size_t> budget(nv, 0);
    std::vector<bool> anchored(nv, false);
    for(std::size_t v = 0; v < nv; ++v)
      if(on_border[v] && degree[v] > 0)
        anchored[parts.find(v)] = true;
    for(std::size_t e = 0; e < ne; ++e)
      if(r.edge_is_cut[e])
        ++budget[parts.find(idx.edge_vertices(e).first)];
    for(std::size_t v = 0; v < nv; ++v)
      budget[v] = anchored[v] ? ne : (budget[v] >= 2 ? budget[v] - 2 : 0);
    // the cracks, walked from their tips (a part that is a single path is walked from both ends)
    candidates.clear();
    std::size_t crack = 0;
    for(std::size_t tip = 0; tip < nv; ++tip)
    {
      if(degree[tip] != 1 || on_border[tip])
        continue;
      double phi = 0., widest = 0.;
      std::size_t v = tip, previous_edge = npos;
      for(std::size_t position = 0;; ++position)
      {
        std::size_t next = npos;
        for(auto h : halfedges_around_source(idx.vertex(v), tm))
        {
          const std::size_t e = idx.edge_index(h);
          if(r.edge_is_cut[e] && e != previous_edge)
          {
            next = e;
            break;
          }
        }
        phi += delta[v];
        if(!(std::abs(phi) <= o.opening_bound)) // (NaN included)
          break;
        widest = (std::max)(widest, std::abs(phi));
        candidates.push_back({widest, position, crack, next});
        const auto ab = idx.edge_vertices(next);
        v = ab.first == v ? ab.second : ab.first;
        previous_edge = next;
        if(degree[v] != 2 || on_border[v])
          break;
      }
      ++crack;
    }
    if(candidates.empty())
      break;
    if(round == o.max_rounds)
    {
      r.converged = false; // candidates left
      break;
    }
    // narrowest openings first; within a crack from its tip (the openings grow along it), so that
    // every prefix of this order glues a prefix of every crack
    std::sort(candidates.begin(), candidates.end(), [](const Candidate& a, const Candidate& b) {
      return std::tie(a.opening, a.position, a.crack) < std::tie(b.opening, b.position, b.crack);
    });
    // the first `count` candidates, within the budgets; a crack stops at its first edge left out
    std::vector<bool> trial;
    auto select = [&](std::size_t count) {
      trial = r.edge_is_cut;
      std::vector<bool> blocked(crack, false);
      std::vector<std::size_t> left = budget;
      std::size_t glued = 0;
      for(std::size_t k = 0; k < count; ++k)
      {
        const Candidate& c = candidates[k];
        std::size_t& part = left[parts.find(idx.edge_vertices(c.edge).first)];
        if(blocked[c.crack] || !trial[c.edge] || part == 0)
        {
          blocked[c.crack] = true;
          continue;
        }
        --part;
        trial[c.edge] = false;
        ++glued;
      }
      return glued;
    };
    const double allowed = (std::max)(o.distortion_bound, r.largest_log_area_scale_before);
    std::size_t count = candidates.size(), glued = 0;
    std::vector<double> trial_u;
    for(; count > 0; count /= 2)
    {
      glued = select(count);
      if(glued == 0)
        continue;
      trial_u = cut_scale_factors(idx, weight, angle_sum, trial, traits);
      if(!(o.distortion_bound > 0.) || largest_scale(trial_u) <= allowed)
        break;
      ++r.reductions;
    }
    if(count == 0)
      break;
    r.glued_edges += glued;
    ++r.rounds;
    r.edge_is_cut = std::move(trial);
    u = std::move(trial_u);
    r.largest_log_area_scale = largest_scale(u);
  }

  // the cracks closed: connected parts of the glued edges
  {
    Union_find closed(nv);
    for(std::size_t e = 0; e < ne; ++e)
      if(was_cut[e] && !r.edge_is_cut[e])
        closed.unite(idx.edge_vertices(e).first, idx.edge_vertices(e).second);
    std::vector<std::size_t> roots;
    for(std::size_t e = 0; e < ne; ++e)
      if(was_cut[e] && !r.edge_is_cut[e])
        roots.push_back(closed.find(idx.edge_vertices(e).first));
    std::sort(roots.begin(), roots.end());
    r.cracks = std::size_t(std::unique(roots.begin(), roots.end()) - roots.begin());
  }
  const Cut_corners corners = cut_corners(idx, r.edge_is_cut);
  r.topology = cut_topology(idx, r.edge_is_cut, corners);
  bool same = r.topology.pieces.size() == before.pieces.size();
  for(std::size_t k = 0; same && k < before.pieces.size(); ++k)
    same = r.topology.pieces[k].euler_characteristic() == before.pieces[k].euler_characteristic() &&
           r.topology.pieces[k].boundary_loops == before.pieces[k].boundary_loops;
  if(!same)
  {
    std::ostringstream s;
    s << "gluing cracks changed the pieces of the cut (" << before.pieces.size() << " before, "
      << r.topology.pieces.size() << " after)";
    throw Internal_error(s.str());
  }
  return r;
}

} // namespace internal
} // namespace Surface_design
} // namespace CGAL

#endif // CGAL_SURFACE_DESIGN_INTERNAL_DEVELOPABILITY_CRACK_GLUING_H
