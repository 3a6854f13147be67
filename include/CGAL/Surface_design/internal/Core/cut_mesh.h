// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Cutting a triangle mesh along a set of edges, at the level of indices: every vertex is split
// into one copy per fan of corners between cut (or border) edges, and the topology of the result
// (components, boundary loops, Euler characteristics) is computed without building it.

#ifndef CGAL_SURFACE_DESIGN_INTERNAL_CORE_CUT_MESH_H
#define CGAL_SURFACE_DESIGN_INTERNAL_CORE_CUT_MESH_H

#include <CGAL/Surface_design/exceptions.h>
#include <CGAL/Surface_design/internal/Core/Mesh_indices.h>
#include <CGAL/Surface_design/internal/Core/topology.h>

#include <array>
#include <cstddef>
#include <numeric>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_design {
namespace internal {

/// Per edge index: whether it is in `edges` (a range of edge descriptors of the mesh, found by
/// their end vertices, so that an edge of another mesh is refused).
template <class Indices, class EdgeRange>
std::vector<bool> edge_flags(const Indices& idx, const EdgeRange& edges)
{
  const auto& tm = idx.mesh();
  std::vector<bool> flag(idx.number_of_edges(), false);
  for(const auto& e : edges)
  {
    const auto h = CGAL::halfedge(e, tm);
    const auto s = source(h, tm), t = target(h, tm);
    const auto found = idx.find(s) != npos && idx.find(t) != npos ? CGAL::halfedge(s, t, tm) : std::make_pair(h, false);
    if(!found.second)
      throw Invalid_constraints("an edge to cut is not an edge of the mesh");
    flag[idx.edge_index(found.first)] = true;
  }
  return flag;
}

/// The corners of a mesh cut along edges.
struct Cut_corners
{
  /// Per halfedge h (not border): the copy of target(h) that the corner of face(h) at target(h)
  /// belongs to; npos on border halfedges.
  std::vector<std::size_t> corner_copy;
  std::vector<std::size_t> original_vertex; ///< per copy: the vertex it copies
  std::size_t number_of_copies() const { return original_vertex.size(); }
};

/// Splits every vertex into its fans of corners. Walking around vertex v, the corner of face(h)
/// (h pointing to v) starts a new fan when the edge of h is cut or on the border. Copies are
/// numbered by vertex, then in walking order: an uncut mesh keeps its vertex numbering.
template <class Indices>
Cut_corners cut_corners(const Indices& idx, const std::vector<bool>& edge_is_cut)
{
  const auto& tm = idx.mesh();
  Cut_corners c;
  c.corner_copy.assign(idx.number_of_halfedges(), npos);
  std::vector<std::size_t> corners;
  for(std::size_t v = 0; v < idx.number_of_vertices(); ++v)
  {
    corners.clear();
    for(auto h : halfedges_around_target(halfedge(idx.vertex(v), tm), tm))
      if(!idx.is_border(h))
        corners.push_back(idx.index(h));
    const auto starts = [&](std::size_t h) {
      const auto hd = idx.halfedge(h);
      return edge_is_cut[idx.edge_index(hd)] || idx.is_border(opposite(hd, tm));
    };
    std::size_t first = 0;
    while(first < corners.size() && !starts(corners[first]))
      ++first;
    if(first == corners.size()) // no break: one copy
      first = 0;
    const std::size_t n = corners.size();
    for(std::size_t k = 0; k < n; ++k)
    {
      const std::size_t h = corners[(first + k) % n];
      if(k == 0 || starts(h))
        c.original_vertex.push_back(v);
      c.corner_copy[h] = c.original_vertex.size() - 1;
    }
  }
  return c;
}

/// The three corner copies of every face, in the face's order (starting at target(halfedge(f))).
template <class Indices>
std::vector<std::array<std::size_t, 3>> cut_faces(const Indices& idx, const Cut_corners& c)
{
  const auto& tm = idx.mesh();
  std::vector<std::array<std::size_t, 3>> faces(idx.number_of_faces());
  for(std::size_t f = 0; f < faces.size(); ++f)
  {
    auto h = halfedge(idx.face(f), tm);
    for(std::size_t k = 0; k < 3; ++k, h = next(h, tm))
      faces[f][k] = c.corner_copy[idx.index(h)];
  }
  return faces;
}

/// Topology of the cut mesh, per connected component of its faces.
struct Cut_topology
{
  std::vector<std::size_t> face_piece; ///< per face: its piece
  std::vector<Component_info> pieces;  ///< counts per piece (root_vertex: an original vertex)
  /// true when every piece is a topological disk (one boundary loop, Euler characteristic 1)
  bool all_disks() const
  {
    for(const Component_info& p : pieces)
      if(p.euler_characteristic() != 1 || p.boundary_loops != 1)
        return false;
    return true;
  }
};

template <class Indices>
Cut_topology cut_topology(const Indices& idx, const std::vector<bool>& edge_is_cut, const Cut_corners& c)
{
  const auto& tm = idx.mesh();
  const std::size_t nf = idx.number_of_faces();
  Union_find pieces(nf);
  for(std::size_t e = 0; e < idx.number_of_edges(); ++e)
  {
    const auto h = halfedge(idx.edge(e), tm);
    const auto o = opposite(h, tm);
    if(edge_is_cut[e] || idx.is_border(h) || idx.is_border(o))
      continue;
    pieces.unite(idx.index(face(h, tm)), idx.index(face(o, tm)));
  }
  Cut_topology t;
  t.face_piece.assign(nf, npos);
  std::vector<std::size_t> piece_of_root(nf, npos);
  for(std::size_t f = 0; f < nf; ++f)
  {
    const std::size_t r = pieces.find(f);
    if(piece_of_root[r] == npos)
    {
      piece_of_root[r] = t.pieces.size();
      t.pieces.emplace_back();
      t.pieces.back().root_face = f;
      t.pieces.back().root_vertex = idx.target_index(halfedge(idx.face(f), tm));
    }
    t.face_piece[f] = piece_of_root[r];
    ++t.pieces[t.face_piece[f]].faces;
  }
  // vertices: every copy belongs to the piece of its corners
  std::vector<std::size_t> copy_piece(c.number_of_copies(), npos);
  // boundary of the cut mesh: from each boundary corner's copy to the next copy along the
  // boundary; the successor map is a permutation of the boundary copies whose cycles are loops
  std::vector<std::size_t> successor(c.number_of_copies(), npos);
  for(std::size_t i = 0; i < idx.number_of_halfedges(); ++i)
  {
    const auto h = idx.halfedge(i);
    if(idx.is_border(h))
      continue;
    const std::size_t piece = t.face_piece[idx.index(face(h, tm))];
    const std::size_t copy = c.corner_copy[i];
    if(copy_piece[copy] == npos)
    {
      copy_piece[copy] = piece;
      ++t.pieces[piece].vertices;
    }
    const auto o = opposite(h, tm);
    const std::size_t e = idx.edge_index(h);
    if(idx.is_border(o) || edge_is_cut[e])
    {
      ++t.pieces[piece].edges; // one side of a cut edge, or a border edge
      // the boundary runs against h: from target(h) to source(h)
      const std::size_t from = copy;
      const std::size_t to = c.corner_copy[idx.index(prev(h, tm))];
      successor[from] = to;
    }
    else if(i < idx.index(o))
      ++t.pieces[piece].edges;
  }
  std::vector<bool> visited(c.number_of_copies(), false);
  for(std::size_t copy = 0; copy < successor.size(); ++copy)
  {
    if(successor[copy] == npos || visited[copy])
      continue;
    for(std::size_t x = copy; x != npos && !visited[x]; x = successor[x])
      visited[x] = true;
    ++t.pieces[copy_piece[copy]].boundary_loops;
  }
  return t;
}

} // namespace internal
} // namespace Surface_design
} // namespace CGAL

#endif // CGAL_SURFACE_DESIGN_INTERNAL_CORE_CUT_MESH_H
