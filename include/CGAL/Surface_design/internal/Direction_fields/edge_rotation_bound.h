// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Bounding the edge rotations of a vertex field by vertex shifts (difference constraints solved
// by Bellman-Ford), or the closed path that shows it impossible: the adjustment step of
// `Trivial_connection`.

#ifndef CGAL_SURFACE_DESIGN_INTERNAL_DIRECTION_FIELDS_EDGE_ROTATION_BOUND_H
#define CGAL_SURFACE_DESIGN_INTERNAL_DIRECTION_FIELDS_EDGE_ROTATION_BOUND_H

#include <CGAL/Surface_design/internal/Core/Mesh_indices.h>

#include <algorithm>
#include <cstddef>
#include <deque>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_design {

namespace internal {

/// Vertex shifts that bound the edge rotations of a vertex field, see bound_edge_rotations().
struct Edge_rotation_bound
{
  std::vector<double> u;          ///< per vertex index: the shift (0 where nothing needs to move)
  std::vector<std::size_t> cycle; ///< empty if the bound is met; else the vertex indices of a closed
                                  ///< path of the mesh along which it cannot be
};

/// Finds vertex shifts u with |x_e + u_j - u_i| <= bound on every edge e = (i, j), i < j, or a
/// closed path along which no shifts can achieve it. These are difference constraints,
/// u_j - u_i <= bound - x_e and u_i - u_j <= bound + x_e: with an arc i -> j of length bound - x_e
/// and an arc j -> i of length bound + x_e, the shortest-path lengths u_v from a virtual source
/// joined to every vertex by an arc of length 0 satisfy all of them (Bellman-Ford, queue-based).
/// Only the arcs of edges with |x_e| > bound are negative, so u <= 0 is nonzero only around them.
/// Shifts exist iff there is no negative cycle: no closed path of L edges along which the oriented
/// x_e sum to more than L * bound in magnitude. A negative cycle shows as a cycle of the
/// predecessor graph, searched for after every |V| relaxations (O(|V|) per search).
template <class Indices>
Edge_rotation_bound bound_edge_rotations(const Indices& idx, const std::vector<double>& x, double bound)
{
  const std::size_t nv = idx.number_of_vertices(), ne = idx.number_of_edges();
  std::vector<std::size_t> begin(nv + 1, 0); // arcs in compressed rows by tail vertex
  for(std::size_t e = 0; e < ne; ++e)
  {
    const auto ij = idx.edge_vertices(e);
    ++begin[ij.first + 1];
    ++begin[ij.second + 1];
  }
  for(std::size_t v = 0; v < nv; ++v)
    begin[v + 1] += begin[v];
  std::vector<std::pair<std::size_t, double>> arc(2 * ne); // (head, length)
  std::vector<std::size_t> fill(begin.begin(), begin.end() - 1);
  for(std::size_t e = 0; e < ne; ++e)
  {
    const auto ij = idx.edge_vertices(e);
    arc[fill[ij.first]++] = {ij.second, bound - x[e]};
    arc[fill[ij.second]++] = {ij.first, bound + x[e]};
  }
  // a cycle of the predecessor graph (walks marked by their start), or nothing
  std::vector<std::size_t> pred(nv, npos), mark(nv, npos);
  auto predecessor_cycle = [&]() {
    std::fill(mark.begin(), mark.end(), npos);
    for(std::size_t s = 0; s < nv; ++s)
    {
      std::size_t v = s;
      while(v != npos && mark[v] == npos)
      {
        mark[v] = s;
        v = pred[v];
      }
      if(v != npos && mark[v] == s) // back on this walk: a cycle through v
      {
        std::vector<std::size_t> cycle{v};
        for(std::size_t w = pred[v]; w != v; w = pred[w])
          cycle.push_back(w);
        std::reverse(cycle.begin(), cycle.end()); // in the direction of the arcs
        return cycle;
      }
    }
    return std::vector<std::size_t>();
  };

  Edge_rotation_bound r;
  r.u.assign(nv, 0.);
  std::deque<std::size_t> queue;
  std::vector<bool> queued(nv, true);
  for(std::size_t v = 0; v < nv; ++v)
    queue.push_back(v);
  std::size_t relaxations = 0;
  while(!queue.empty())
  {
    const std::size_t v = queue.front();
    queue.pop_front();
    queued[v] = false;
    for(std::size_t a = begin[v]; a < begin[v + 1]; ++a)
    {
      const std::size_t w = arc[a].first;
      if(!(r.u[v] + arc[a].second < r.u[w]))
        continue;
      r.u[w] = r.u[v] + arc[a].second;
      pred[w] = v;
      if(!queued[w])
      {
        queued[w] = true;
        queue.push_back(w);
      }
      if(++relaxations % nv == 0 && !(r.cycle = predecessor_cycle()).empty())
        return r;
    }
  }
  return r;
}

} // namespace internal

} // namespace Surface_design
} // namespace CGAL

#endif // CGAL_SURFACE_DESIGN_INTERNAL_DIRECTION_FIELDS_EDGE_ROTATION_BOUND_H
