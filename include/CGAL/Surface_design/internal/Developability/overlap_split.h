// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Cuts that split flattened pieces whose boundary crosses itself in the plane.

#ifndef CGAL_SURFACE_DESIGN_INTERNAL_DEVELOPABILITY_OVERLAP_SPLIT_H
#define CGAL_SURFACE_DESIGN_INTERNAL_DEVELOPABILITY_OVERLAP_SPLIT_H

#include <CGAL/Surface_design/internal/Core/cut_mesh.h>
#include <CGAL/Surface_design/internal/Core/geometry.h>
#include <CGAL/Surface_design/internal/Core/topology.h>
#include <CGAL/Surface_design/internal/Developability/distortion.h>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <functional>
#include <limits>
#include <queue>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_design {
namespace internal {

struct Overlap_split
{
  std::vector<bool> edge_is_cut;  ///< per edge: cut to split an overlapping piece
  std::size_t overlapping = 0;    ///< pieces whose boundary crosses itself in the plane
  std::size_t split = 0;          ///< of these, the pieces split into disks
};

/// For every boundary loop whose image `uv` (per vertex) crosses itself: the two crossing
/// boundary edges i, k farthest apart along the loop (3-D arc length, the shorter way round)
/// are what overlaps globally; the piece is cut where the faces become closer (graph distance
/// along the edges, in space) to k than to i, so i and k end up in different parts. Face regions
/// are made connected (an island of one label inside the other joins it), and the parts must be
/// disks (Euler characteristic 1, one boundary loop); otherwise that piece is left whole.
template <class Indices, class VertexPointMap>
Overlap_split overlap_splitting_cut(const Indices& idx, const VertexPointMap& vpm, const std::vector<Eigen::Vector2d>& uv)
{
  const auto& tm = idx.mesh();
  const std::size_t nv = idx.number_of_vertices(), ne = idx.number_of_edges(), nf = idx.number_of_faces();
  Overlap_split result;
  result.edge_is_cut.assign(ne, false);
  const Boundary_loops loops = boundary_loops(idx);
  const Components components = connected_components(idx, loops);

  const std::vector<Eigen::Vector3d> x = vertex_positions(idx, vpm);
  std::vector<char> on_boundary(nv, 0);
  for(const std::vector<std::size_t>& loop : loops.loops)
    for(std::size_t h : loop)
      on_boundary[idx.target_index(idx.halfedge(h))] = 1;
  std::vector<std::vector<std::pair<std::size_t, double>>> adjacency;
  // shortest paths from {a, b}; `through(w)`: whether a path may pass through w (to w when false)
  const auto distances_from = [&](std::size_t a, std::size_t b, std::vector<std::size_t>* parent, auto through) {
    if(adjacency.empty())
    {
      adjacency.resize(nv);
      for(std::size_t e = 0; e < ne; ++e)
      {
        const auto ij = idx.edge_vertices(e);
        const double l = (x[ij.first] - x[ij.second]).norm();
        adjacency[ij.first].emplace_back(ij.second, l);
        adjacency[ij.second].emplace_back(ij.first, l);
      }
    }
    std::vector<double> d(nv, std::numeric_limits<double>::infinity());
    using Entry = std::pair<double, std::size_t>;
    std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> queue;
    if(parent)
      parent->assign(nv, npos);
    d[a] = d[b] = 0.;
    queue.emplace(0., a);
    queue.emplace(0., b);
    while(!queue.empty())
    {
      const auto [dv, v] = queue.top();
      queue.pop();
      if(dv > d[v] || (v != a && v != b && !through(v)))
        continue;
      for(const auto& [w, l] : adjacency[v])
        if(dv + l < d[w])
        {
          d[w] = dv + l;
          if(parent)
            (*parent)[w] = v;
          queue.emplace(d[w], w);
        }
    }
    return d;
  };

  for(const std::vector<std::size_t>& loop : loops.loops)
  {
    const std::size_t n = loop.size();
    std::vector<Eigen::Vector2d> polygon(n);
    std::vector<double> arc(n + 1, 0.); // 3-D arc length at the start of every boundary edge
    for(std::size_t j = 0; j < n; ++j)
    {
      const auto h = idx.halfedge(loop[j]);
      polygon[j] = uv[idx.source_index(h)];
      arc[j + 1] = arc[j] + (x[idx.source_index(h)] - x[idx.target_index(h)]).norm();
    }
    std::size_t best_i = npos, best_k = npos;
    double best_separation = -1.;
    for_each_polygon_self_intersection(polygon, [&](std::size_t i, std::size_t k) {
      const double along = arc[k] - arc[i];
      const double separation = (std::min)(along, arc[n] - along);
      if(separation > best_separation)
      {
        best_separation = separation;
        best_i = i;
        best_k = k;
      }
      return true;
    });
    if(best_i == npos)
      continue;
    ++result.overlapping;

    const auto hi = idx.halfedge(loop[best_i]), hk = idx.halfedge(loop[best_k]);
    const auto anywhere = [](std::size_t) { return true; };
    const std::vector<double> di = distances_from(idx.source_index(hi), idx.target_index(hi), nullptr, anywhere);
    const std::vector<double> dk = distances_from(idx.source_index(hk), idx.target_index(hk), nullptr, anywhere);
    const std::size_t piece = components.vertex_component[idx.source_index(hi)];
    // label 0: closer to i, 1: closer to k; -1: another piece
    std::vector<int> label(nf, -1);
    for(std::size_t f = 0; f < nf; ++f)
    {
      if(components.face_component[f] != piece)
        continue;
      double si = 0., sk = 0.;
      auto h = halfedge(idx.face(f), tm);
      for(int c = 0; c < 3; ++c, h = next(h, tm))
      {
        si += di[idx.target_index(h)];
        sk += dk[idx.target_index(h)];
      }
      label[f] = sk < si ? 1 : 0;
    }
    const std::size_t seed_i = idx.index(face(opposite(hi, tm), tm)), seed_k = idx.index(face(opposite(hk, tm), tm));
    if(label[seed_i] != 0 || label[seed_k] != 1)
      continue;
    // the faces of `wanted` reached from `seed` across edges keep it, the others take the other label
    const auto keep_connected = [&](std::size_t seed, int wanted) {
      std::vector<char> reached(nf, 0);
      std::vector<std::size_t> stack{seed};
      reached[seed] = 1;
      while(!stack.empty())
      {
        const std::size_t f = stack.back();
        stack.pop_back();
        for(auto h : halfedges_around_face(halfedge(idx.face(f), tm), tm))
        {
          const auto o = opposite(h, tm);
          if(idx.is_border(o))
            continue;
          const std::size_t g = idx.index(face(o, tm));
          if(!reached[g] && label[g] == wanted)
          {
            reached[g] = 1;
            stack.push_back(g);
          }
        }
      }
      for(std::size_t f = 0; f < nf; ++f)
        if(label[f] == wanted && !reached[f])
          label[f] = 1 - wanted;
    };
    keep_connected(seed_i, 0);
    keep_connected(seed_k, 1);
    std::vector<bool> cut(ne, false);
    for(std::size_t e = 0; e < ne; ++e)
    {
      const auto h = halfedge(idx.edge(e), tm);
      const auto o = opposite(h, tm);
      if(idx.is_border(h) || idx.is_border(o))
        continue;
      const int a = label[idx.index(face(h, tm))], b = label[idx.index(face(o, tm))];
      cut[e] = a >= 0 && b >= 0 && a != b;
    }
    // whether cutting the piece along `c` leaves two disks
    const auto splits_into_two_disks = [&](const std::vector<bool>& c) {
      const Cut_corners corners = cut_corners(idx, c);
      const Cut_topology parts = cut_topology(idx, c, corners);
      std::size_t count = 0;
      bool disks = true;
      for(const Component_info& p : parts.pieces)
        if(components.face_component[p.root_face] == piece)
        {
          ++count;
          disks = disks && p.euler_characteristic() == 1 && p.boundary_loops == 1;
        }
      return count == 2 && disks;
    };
    if(!splits_into_two_disks(cut))
      continue;
    // The border between the labels zigzags along the edges; when it is one chord from boundary
    // vertex a to boundary vertex b, the shortest path from a to b through interior vertices
    // splits the boundary at the same places (i and k stay apart) and is straighter.
    std::vector<std::size_t> ends;
    for(std::size_t e = 0; e < ne; ++e)
      if(cut[e])
        for(std::size_t v : {idx.edge_vertices(e).first, idx.edge_vertices(e).second})
          if(on_boundary[v] && std::find(ends.begin(), ends.end(), v) == ends.end())
            ends.push_back(v);
    if(ends.size() == 2)
    {
      std::vector<std::size_t> parent;
      const std::vector<double> d =
        distances_from(ends[0], ends[0], &parent, [&](std::size_t v) { return !on_boundary[v]; });
      std::vector<bool> path(ne, false);
      bool interior = std::isfinite(d[ends[1]]);
      for(std::size_t v = ends[1]; interior && v != ends[0]; v = parent[v])
      {
        const auto h = halfedge(idx.vertex(parent[v]), idx.vertex(v), tm).first;
        interior = !idx.is_border(h) && !idx.is_border(opposite(h, tm));
        path[idx.edge_index(h)] = true;
      }
      if(interior && splits_into_two_disks(path))
        cut = std::move(path);
    }
    for(std::size_t e = 0; e < ne; ++e)
      if(cut[e])
        result.edge_is_cut[e] = true;
    ++result.split;
  }
  return result;
}

} // namespace internal
} // namespace Surface_design
} // namespace CGAL

#endif // CGAL_SURFACE_DESIGN_INTERNAL_DEVELOPABILITY_OVERLAP_SPLIT_H
