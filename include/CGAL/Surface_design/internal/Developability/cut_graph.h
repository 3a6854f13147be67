// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The cut of a (piecewise-)developable design into developable disks (Stein, Grinspun & Crane
// 2018, sec. 4.4): a short tree through the vertices far from developable, joined to the
// boundary, plus generator loops on surfaces of higher genus.

#ifndef CGAL_SURFACE_DESIGN_INTERNAL_DEVELOPABILITY_CUT_GRAPH_H
#define CGAL_SURFACE_DESIGN_INTERNAL_DEVELOPABILITY_CUT_GRAPH_H

#include <CGAL/Surface_design/developability_energy.h>
#include <CGAL/Surface_design/exceptions.h>
#include <CGAL/Surface_design/internal/Core/Mesh_indices.h>
#include <CGAL/Surface_design/internal/Core/cut_mesh.h>
#include <CGAL/Surface_design/internal/Core/geometry.h>
#include <CGAL/Surface_design/internal/Core/topology.h>
#include <CGAL/Surface_design/internal/Developability/star_energies.h>
#include <CGAL/Surface_design/internal/Developability/vertex_stars.h>
#include <CGAL/Surface_design/internal/Solvers/Factored_system.h>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <algorithm>
#include <cstddef>
#include <functional>
#include <limits>
#include <numeric>
#include <queue>
#include <sstream>
#include <stdexcept>
#include <tuple>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_design {
namespace internal {

struct Cut_graph_options
{
  double tolerance = 1e-3;        ///< epsilon: interior vertices with lambda_i > epsilon are terminals
  double alignment_weight = 1.;   ///< w in the edge cost |e| (1 + w misalignment)
  Developable_cut_cost cost = Developable_cut_cost::ruling_alignment;
  bool parallel = true;
  std::vector<bool> forced_terminal; ///< per vertex (empty: none): interior vertices cut through whatever lambda_i
  /// > 0: cut again, through the worst distorted vertices, until the conformal flattening with the
  /// cut's lengths kept distorts no vertex's area by more than this (|log area scale| = 2 |u|)
  double distortion_bound = 0.;
  std::size_t max_distortion_rounds = 64;
};

struct Cut_graph
{
  std::vector<bool> edge_is_cut;
  std::vector<double> edge_cost;                 ///< per edge: the cost the tree minimized
  std::vector<double> lambda;                    ///< per vertex: covariance lambda_i (eq. 3)
  std::vector<Eigen::Vector3d> ruling;           ///< per vertex: unit ruling direction
  std::vector<std::size_t> terminals;            ///< interior vertices with lambda_i > epsilon (or forced), then the distortion peaks
  std::size_t generator_loops = 0;               ///< loops added for genus
  std::size_t boundary_loops = 0;
  std::size_t extra_edges = 0;                   ///< edges added so that a closed sphere opens into a disk
  std::size_t distortion_terminals = 0;          ///< terminals added for the distortion bound
  std::size_t distortion_rounds = 0;             ///< cuts computed again for the distortion bound
  double largest_log_area_scale = 0.;            ///< with a distortion bound: largest 2 |u_i| of the final cut
  Cut_corners corners;
  Cut_topology topology;
};

namespace cut_graph_detail {

struct Shortest_paths
{
  std::vector<double> distance;
  std::vector<std::size_t> source;          ///< id of the nearest source (npos if unreached)
  std::vector<std::size_t> parent_halfedge; ///< halfedge from the parent to the vertex (npos at sources)
};

// Dijkstra from several sources at once: `source_id[v]` != npos marks a source.
template <class Indices>
Shortest_paths multi_source_dijkstra(const Indices& idx, const std::vector<double>& edge_cost,
                                     const std::vector<std::size_t>& source_id)
{
  const auto& tm = idx.mesh();
  const std::size_t nv = idx.number_of_vertices();
  Shortest_paths p;
  p.distance.assign(nv, std::numeric_limits<double>::infinity());
  p.source.assign(nv, npos);
  p.parent_halfedge.assign(nv, npos);
  using Item = std::pair<double, std::size_t>;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> queue;
  for(std::size_t v = 0; v < nv; ++v)
    if(source_id[v] != npos)
    {
      p.distance[v] = 0.;
      p.source[v] = source_id[v];
      queue.emplace(0., v);
    }
  while(!queue.empty())
  {
    const auto [d, v] = queue.top();
    queue.pop();
    if(d > p.distance[v])
      continue;
    for(auto h : halfedges_around_source(idx.vertex(v), tm))
    {
      const std::size_t w = idx.target_index(h);
      const double dw = d + edge_cost[idx.edge_index(h)];
      if(dw < p.distance[w])
      {
        p.distance[w] = dw;
        p.source[w] = p.source[v];
        p.parent_halfedge[w] = idx.index(h);
        queue.emplace(dw, w);
      }
    }
  }
  return p;
}

// Marks the edges of the tree path from v to its source.
template <class Indices>
void cut_path_to_source(const Indices& idx, const Shortest_paths& p, std::size_t v, std::vector<bool>& edge_is_cut)
{
  while(p.parent_halfedge[v] != npos)
  {
    const auto h = idx.halfedge(p.parent_halfedge[v]);
    edge_is_cut[idx.edge_index(h)] = true;
    v = idx.source_index(h);
  }
}


// The corners and pieces of the cut; every piece must be a disk.
template <class Indices>
void finish_and_check(const Indices& idx, Cut_graph& g)
{
  g.corners = cut_corners(idx, g.edge_is_cut);
  g.topology = cut_topology(idx, g.edge_is_cut, g.corners);
  for(std::size_t k = 0; k < g.topology.pieces.size(); ++k)
  {
    const Component_info& piece = g.topology.pieces[k];
    if(piece.euler_characteristic() != 1 || piece.boundary_loops != 1)
    {
      std::ostringstream s;
      s << "the cut left piece " << k << " (face " << piece.root_face << ") with " << piece.boundary_loops
        << " boundary loops and Euler characteristic " << piece.euler_characteristic();
      throw Internal_error(s.str());
    }
  }
}

} // namespace cut_graph_detail

/// Computes the cut graph of a validated triangle mesh.
///
/// 1. Every vertex star gets lambda_i (the covariance measure, eq. 3) and its unit eigenvector
///    u_i, the ruling direction. Terminals: interior vertices with lambda_i > epsilon.
/// 2. Edge cost |e| (1 + w (|u_a x e^| + |u_b x e^|) / 2): short edges along the rulings are
///    cheap; or, `Developable_cut_cost::paper`, the paper's words taken literally (sec. 4.4:
///    length times the inner product of the edge direction with the small eigenvector at its
///    ends), |e| (|<u_a, e^>| + |<u_b, e^>|) / 2: edges across the rulings are cheap.
/// 3. A Steiner tree over the terminals and the boundary loops (each loop one zero-cost
///    super-terminal), by the metric-closure minimum spanning tree in Mehlhorn's form: one
///    Dijkstra from all terminals at once, Kruskal over the edges joining two Voronoi regions,
///    each kept edge expanded into its two shortest paths (a 2-approximation, as the
///    Erickson & Har-Peled cut the paper uses).
/// 4. Components of genus g > 0 (after capping their boundary loops) get 2g generator loops:
///    shortest paths from the cut so far, a dual spanning tree of maximal loop lengths through the
///    remaining edges, and the loop of every edge outside both (greedy system of loops,
///    Erickson & Whittlesey 2005).
/// 5. A closed component whose cut has fewer than two edges gets its cheapest edges at its
///    terminal (its vertex of largest lambda_i if none), because a sphere opens into a disk only
///    along a path of two edges or more.
/// The result is checked: every piece of the cut mesh is a disk.
template <class Indices, class VertexPointMap>
Cut_graph developable_cut_graph(const Indices& idx, const VertexPointMap& vpm, const Cut_graph_options& o)
{
  using namespace cut_graph_detail;
  const auto& tm = idx.mesh();
  const std::size_t nv = idx.number_of_vertices(), ne = idx.number_of_edges();
  Cut_graph g;
  g.edge_is_cut.assign(ne, false);

  // 1. lambda_i and rulings
  const Vertex_stars stars = vertex_stars(idx, false, 4);
  const std::vector<Eigen::Vector3d> x = vertex_positions(idx, vpm);
  g.lambda.assign(nv, 0.);
  g.ruling.assign(nv, Eigen::Vector3d::Zero());
  for_each_index(nv, o.parallel, [&](std::size_t v) {
    if(stars.number_of_faces(v) == 0)
      return;
    const Star_buffer<Eigen::Vector3d> ring = ring_positions(stars, x, v);
    const Star_geometry geometry(x[v], ring.data(), ring.size(), stars.closed[v]);
    g.lambda[v] = covariance_energy(geometry, nullptr, &g.ruling[v]);
  });
  const Boundary_loops loops = boundary_loops(idx);
  const Components comps = connected_components(idx, loops);
  g.boundary_loops = loops.size();
  std::vector<bool> on_boundary(nv, false);
  for(const auto& loop : loops.loops)
    for(std::size_t h : loop)
      on_boundary[idx.target_index(idx.halfedge(h))] = true;

  // 2. edge costs
  std::vector<double> cost(ne);
  for(std::size_t e = 0; e < ne; ++e)
  {
    const auto ab = idx.edge_vertices(e);
    Eigen::Vector3d d = x[ab.second] - x[ab.first];
    const double length = d.norm();
    d /= length;
    if(o.cost == Developable_cut_cost::paper)
    {
      cost[e] = length * 0.5 * (std::abs(g.ruling[ab.first].dot(d)) + std::abs(g.ruling[ab.second].dot(d)));
      continue;
    }
    const double misalignment = 0.5 * (g.ruling[ab.first].cross(d).norm() + g.ruling[ab.second].cross(d).norm());
    cost[e] = length * (1. + o.alignment_weight * misalignment);
  }

  // 3. Steiner tree over the terminals and the boundary loops
  std::vector<std::size_t> source_id(nv, npos);
  for(std::size_t v = 0; v < nv; ++v)
    if(stars.closed[v] && stars.number_of_faces(v) > 0 &&
       (g.lambda[v] > o.tolerance || (!o.forced_terminal.empty() && o.forced_terminal[v])))
    {
      source_id[v] = g.terminals.size();
      g.terminals.push_back(v);
    }
  for(std::size_t l = 0; l < loops.size(); ++l)
    for(std::size_t h : loops.loops[l])
      source_id[idx.target_index(idx.halfedge(h))] = g.terminals.size() + l;
  {
    const Shortest_paths p = multi_source_dijkstra(idx, cost, source_id);
    std::vector<std::tuple<double, std::size_t>> candidates;
    for(std::size_t e = 0; e < ne; ++e)
    {
      const auto ab = idx.edge_vertices(e);
      if(p.source[ab.first] != npos && p.source[ab.second] != npos && p.source[ab.first] != p.source[ab.second])
        candidates.emplace_back(p.distance[ab.first] + cost[e] + p.distance[ab.second], e);
    }
    std::sort(candidates.begin(), candidates.end());
    Union_find regions(g.terminals.size() + loops.size());
    for(const auto& [length, e] : candidates)
    {
      (void)length;
      const auto ab = idx.edge_vertices(e);
      if(!regions.unite(p.source[ab.first], p.source[ab.second]))
        continue;
      g.edge_is_cut[e] = true;
      cut_path_to_source(idx, p, ab.first, g.edge_is_cut);
      cut_path_to_source(idx, p, ab.second, g.edge_is_cut);
    }
  }

  // components without terminal nor boundary get their vertex of largest lambda as a root
  std::vector<std::size_t> root(comps.size(), npos);
  for(std::size_t v = 0; v < nv; ++v)
  {
    const std::size_t c = comps.vertex_component[v];
    if(source_id[v] != npos)
      root[c] = v; // has a terminal or a boundary
  }
  std::vector<std::size_t> fallback(comps.size(), npos);
  for(std::size_t v = 0; v < nv; ++v)
  {
    const std::size_t c = comps.vertex_component[v];
    if(root[c] == npos && (fallback[c] == npos || g.lambda[v] > g.lambda[fallback[c]]))
      fallback[c] = v;
  }

  // 4. generator loops
  bool higher_genus = false;
  for(const Component_info& c : comps.info)
    higher_genus = higher_genus || c.genus() > 0;
  if(higher_genus)
  {
    std::vector<std::size_t> sources(nv, npos);
    for(std::size_t v = 0; v < nv; ++v)
      if(source_id[v] != npos || fallback[comps.vertex_component[v]] == v)
        sources[v] = 0;
    for(std::size_t e = 0; e < ne; ++e)
      if(g.edge_is_cut[e])
      {
        const auto ab = idx.edge_vertices(e);
        sources[ab.first] = sources[ab.second] = 0;
      }
    const Shortest_paths p = multi_source_dijkstra(idx, cost, sources);
    std::vector<bool> in_tree(ne, false);
    for(std::size_t v = 0; v < nv; ++v)
      if(p.parent_halfedge[v] != npos)
        in_tree[idx.edge_index(idx.halfedge(p.parent_halfedge[v]))] = true;
    // dual spanning tree through the other interior edges, longest loops first
    std::vector<std::pair<double, std::size_t>> dual;
    for(std::size_t e = 0; e < ne; ++e)
    {
      const auto h = halfedge(idx.edge(e), tm);
      if(in_tree[e] || g.edge_is_cut[e] || idx.is_border(h) || idx.is_border(opposite(h, tm)))
        continue;
      const auto ab = idx.edge_vertices(e);
      dual.emplace_back(-(p.distance[ab.first] + cost[e] + p.distance[ab.second]), e);
    }
    std::sort(dual.begin(), dual.end());
    Union_find faces(idx.number_of_faces());
    std::vector<std::size_t> generators;
    for(const auto& [minus_length, e] : dual)
    {
      (void)minus_length;
      const auto h = halfedge(idx.edge(e), tm);
      if(!faces.unite(idx.index(face(h, tm)), idx.index(face(opposite(h, tm), tm))))
        generators.push_back(e);
    }
    for(std::size_t e : generators)
    {
      const auto ab = idx.edge_vertices(e);
      g.edge_is_cut[e] = true;
      cut_path_to_source(idx, p, ab.first, g.edge_is_cut);
      cut_path_to_source(idx, p, ab.second, g.edge_is_cut);
    }
    g.generator_loops = generators.size();
  }

  // 5. closed components need a cut of two edges at least
  std::vector<std::size_t> cut_count(comps.size(), 0);
  for(std::size_t e = 0; e < ne; ++e)
    if(g.edge_is_cut[e])
      ++cut_count[comps.vertex_component[idx.edge_vertices(e).first]];
  for(std::size_t c = 0; c < comps.size(); ++c)
  {
    if(!comps.info[c].is_closed() || cut_count[c] >= 2)
      continue;
    // grow from the terminal (or the fallback root), or from an end of the single cut edge
    std::size_t v = root[c] != npos ? root[c] : fallback[c];
    std::size_t avoid = npos;
    if(cut_count[c] == 1)
      for(std::size_t e = 0; e < ne; ++e)
        if(g.edge_is_cut[e] && comps.vertex_component[idx.edge_vertices(e).first] == c)
        {
          v = idx.edge_vertices(e).first;
          avoid = idx.edge_vertices(e).second;
        }
    std::vector<std::pair<double, std::size_t>> around;
    for(auto h : halfedges_around_source(idx.vertex(v), tm))
      if(!g.edge_is_cut[idx.edge_index(h)] && idx.target_index(h) != avoid)
        around.emplace_back(cost[idx.edge_index(h)], idx.edge_index(h));
    std::sort(around.begin(), around.end());
    for(std::size_t k = 0; k < around.size() && cut_count[c] < 2; ++k, ++cut_count[c], ++g.extra_edges)
      g.edge_is_cut[around[k].second] = true;
  }

  g.edge_cost = std::move(cost);
  cut_graph_detail::finish_and_check(idx, g);
  return g;
}

/// The log conformal scale factor u_i of every vertex in the flattening of the mesh cut along
/// `edge_is_cut` that keeps the lengths of the cut and of the boundary (Boundary First Flattening
/// with u_B = 0): A_II u_I = -K_I, A the cotangent Laplacian (positive semi-definite), K_I the
/// angle defects of the vertices off the cut and the boundary; u = 0 on the cut and the boundary.
/// Each vertex off the cut keeps its whole star in the cut mesh, so the system is set up on the
/// uncut mesh. The area of the flattening near vertex i is e^{2 u_i} times the area in space.
/// `weight` are the cotangent weights of the edges (cotangent_weights()), `angle_sum` the angle
/// sums of the vertices (vertex_angle_sums()).
template <class Indices, class SolverTraits>
std::vector<double> cut_scale_factors(const Indices& idx, const std::vector<double>& weight,
                                      const std::vector<double>& angle_sum, const std::vector<bool>& edge_is_cut,
                                      const SolverTraits& traits)
{
  const auto& tm = idx.mesh();
  const std::size_t nv = idx.number_of_vertices(), ne = idx.number_of_edges();
  std::vector<bool> fixed(nv, false);
  for(std::size_t e = 0; e < ne; ++e)
  {
    const auto h = halfedge(idx.edge(e), tm);
    if(edge_is_cut[e] || idx.is_border(h) || idx.is_border(opposite(h, tm)))
    {
      const auto ab = idx.edge_vertices(e);
      fixed[ab.first] = fixed[ab.second] = true;
    }
  }
  std::vector<std::size_t> unknown(nv, npos);
  std::size_t n = 0;
  for(std::size_t v = 0; v < nv; ++v)
    if(!fixed[v])
      unknown[v] = n++;
  std::vector<double> u(nv, 0.);
  if(n == 0)
    return u;
  std::vector<Eigen::Triplet<double>> entries;
  std::vector<double> diagonal(n, 0.);
  for(std::size_t e = 0; e < ne; ++e)
  {
    const auto ab = idx.edge_vertices(e);
    const std::size_t a = unknown[ab.first], b = unknown[ab.second];
    if(a != npos)
      diagonal[a] += weight[e];
    if(b != npos)
      diagonal[b] += weight[e];
    if(a != npos && b != npos)
      entries.emplace_back(Eigen::Index((std::max)(a, b)), Eigen::Index((std::min)(a, b)), -weight[e]);
  }
  for(std::size_t i = 0; i < n; ++i)
    entries.emplace_back(Eigen::Index(i), Eigen::Index(i), diagonal[i]);
  const Eigen::Index size = Eigen::Index(n);
  Eigen::SparseMatrix<double> a(size, size);
  a.setFromTriplets(entries.begin(), entries.end()); // lower triangle, the solvers read it
  Eigen::VectorXd rhs(size), x;
  for(std::size_t v = 0; v < nv; ++v)
    if(unknown[v] != npos)
      rhs[Eigen::Index(unknown[v])] = -(two_pi - angle_sum[v]);
  Factored_system<SolverTraits> system(traits, "Laplacian of the vertices off the cut");
  system.factor(std::move(a));
  system.solve(rhs, x);
  for(std::size_t v = 0; v < nv; ++v)
    if(unknown[v] != npos)
      u[v] = x[Eigen::Index(unknown[v])];
  return u;
}

template <class Indices, class VertexPointMap, class SolverTraits>
std::vector<double> cut_scale_factors(const Indices& idx, const VertexPointMap& vpm, const std::vector<bool>& edge_is_cut,
                                      const SolverTraits& traits)
{
  return cut_scale_factors(idx, cotangent_weights(idx, vpm), vertex_angle_sums(idx, corner_angles(idx, vpm)),
                           edge_is_cut, traits);
}

/// The cut graph of `developable_cut_graph()`, cut further until the flattening that keeps the
/// cut's lengths distorts no area by more than `o.distortion_bound` (|log area scale| = 2 |u_i|,
/// u from cut_scale_factors()). Each round takes the vertices off the cut where |u| is a local
/// maximum (no neighbour larger; ties to the lower index) with 2 |u| above the bound, and cuts
/// from each along the cheapest path (the tree's edge costs) to the cut or the boundary: the
/// cut only grows, its new branches are a forest hanging from it, so the pieces stay disks, and
/// the boundary of a flattening with u_B = 0 now passes where the curvature left spread under
/// epsilon had pushed u furthest. Stops after `o.max_distortion_rounds` rounds.
template <class Indices, class VertexPointMap, class SolverTraits>
Cut_graph distortion_bounded_cut_graph(const Indices& idx, const VertexPointMap& vpm, const Cut_graph_options& o,
                                       const SolverTraits& traits)
{
  using namespace cut_graph_detail;
  Cut_graph g = developable_cut_graph(idx, vpm, o);
  if(!(o.distortion_bound > 0.))
    return g;
  const auto& tm = idx.mesh();
  const std::size_t nv = idx.number_of_vertices(), ne = idx.number_of_edges();
  const std::vector<double> weight = cotangent_weights(idx, vpm);
  const std::vector<double> angle_sum = vertex_angle_sums(idx, corner_angles(idx, vpm));
  for(;; ++g.distortion_rounds)
  {
    const std::vector<double> u = cut_scale_factors(idx, weight, angle_sum, g.edge_is_cut, traits);
    std::vector<std::size_t> peaks;
    double largest = 0.;
    for(std::size_t v = 0; v < nv; ++v)
    {
      const double a = std::abs(u[v]);
      largest = (std::max)(largest, 2. * a);
      if(!(2. * a > o.distortion_bound))
        continue;
      bool peak = true;
      for(auto h : halfedges_around_source(idx.vertex(v), tm))
      {
        const std::size_t w = idx.target_index(h);
        const double b = std::abs(u[w]);
        peak = peak && (b < a || (b == a && v < w));
      }
      if(peak)
        peaks.push_back(v);
    }
    g.largest_log_area_scale = largest;
    if(peaks.empty() || g.distortion_rounds == o.max_distortion_rounds)
      break;
    // the cut and the boundary are the sources; every peak is joined to them
    std::vector<std::size_t> source(nv, npos);
    for(std::size_t e = 0; e < ne; ++e)
    {
      const auto h = halfedge(idx.edge(e), tm);
      if(g.edge_is_cut[e] || idx.is_border(h) || idx.is_border(opposite(h, tm)))
      {
        const auto ab = idx.edge_vertices(e);
        source[ab.first] = source[ab.second] = 0;
      }
    }
    const Shortest_paths p = multi_source_dijkstra(idx, g.edge_cost, source);
    for(std::size_t v : peaks)
    {
      cut_path_to_source(idx, p, v, g.edge_is_cut);
      g.terminals.push_back(v);
    }
    g.distortion_terminals += peaks.size();
  }
  if(g.distortion_rounds > 0) // else the tree's pieces, checked already
    finish_and_check(idx, g);
  return g;
}

} // namespace internal
} // namespace Surface_design
} // namespace CGAL

#endif // CGAL_SURFACE_DESIGN_INTERNAL_DEVELOPABILITY_CUT_GRAPH_H
