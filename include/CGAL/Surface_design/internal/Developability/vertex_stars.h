// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The vertex stars of a triangle mesh as index arrays: every vertex's one-ring in counter-clockwise
// order, which stars carry developability energy, and the gather lists that sum per-star gradient
// blocks into per-vertex gradients in a fixed order.

#ifndef CGAL_SURFACE_DESIGN_INTERNAL_DEVELOPABILITY_VERTEX_STARS_H
#define CGAL_SURFACE_DESIGN_INTERNAL_DEVELOPABILITY_VERTEX_STARS_H

#include <CGAL/Surface_design/internal/Core/Mesh_indices.h>

#include <boost/graph/graph_traits.hpp>

#include <algorithm>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Surface_design {
namespace internal {

/// The star of every vertex, in compressed rows (indices of `Mesh_indices`).
///
/// **Rings.** The one-ring of vertex v is `ring[ring_begin[v]]`, ..., `ring[ring_begin[v + 1] - 1]`,
/// r_0, ..., r_{d-1} with d the valence, in counter-clockwise order: the star's faces are the
/// triangles (v, r_k, r_{k+1}), oriented like the mesh's faces. A *closed* star (interior vertex)
/// has the d faces k = 0, ..., d - 1 (indices mod d) and starts at its smallest vertex index, so
/// that it does not depend on the mesh data structure; an *open* star (boundary vertex) has the
/// d - 1 faces k = 0, ..., d - 2: edges (v, r_0) and (v, r_{d-1}) are boundary edges.
///
/// **Active stars** carry energy: valence >= `minimum_valence`, and interior unless boundary
/// vertices are included. A star with no face (isolated vertex) is never active.
///
/// **Gradient blocks.** The energy of star v depends on the positions of v and its ring; its
/// gradient is the block of d + 1 vectors (centre first, then the ring in order) stored in the
/// slots `block_begin(v)`, ..., `block_begin(v) + d` of an array of `number_of_slots()` vectors.
/// `gather_slot[gather_begin[p]]`, ..., `gather_slot[gather_begin[p + 1] - 1]` are the slots, of
/// active stars only, that hold a derivative with respect to vertex p, in increasing order: the
/// gradient of the sum of the stars is, for every p, the sum of those slots in that order, which
/// makes it independent of how the blocks were computed (sequentially or by any number of threads).
struct Vertex_stars
{
  std::vector<std::size_t> ring_begin{0}; ///< |V| + 1 offsets into `ring`
  std::vector<std::size_t> ring;          ///< the one-rings, counter-clockwise
  std::vector<bool> closed;               ///< per vertex: interior (closed ring) or boundary (open fan)
  std::vector<bool> active;               ///< per vertex: the star carries energy
  std::vector<std::size_t> active_vertices; ///< the vertices with `active[v]`, increasing
  std::vector<std::size_t> gather_begin{0}; ///< |V| + 1 offsets into `gather_slot`
  std::vector<std::size_t> gather_slot;     ///< per vertex, the slots that hold its derivatives

  std::size_t number_of_vertices() const { return ring_begin.size() - 1; }
  /// Valence: number of ring vertices.
  std::size_t degree(std::size_t v) const { return ring_begin[v + 1] - ring_begin[v]; }
  /// Faces of the star: d when closed, d - 1 when open (0 for an isolated vertex).
  std::size_t number_of_faces(std::size_t v) const
  {
    const std::size_t d = degree(v);
    return closed[v] || d == 0 ? d : d - 1;
  }
  const std::size_t* ring_of(std::size_t v) const { return ring.data() + ring_begin[v]; }
  /// First slot of the gradient block of star v (its centre); the ring follows.
  std::size_t block_begin(std::size_t v) const { return ring_begin[v] + v; }
  /// Size of the array of gradient blocks: one slot per star centre and per ring entry.
  std::size_t number_of_slots() const { return ring.size() + number_of_vertices(); }
};

/// Builds the stars of a triangle mesh.
/// \param idx the indices of a validated mesh (triangles, manifold vertices: see validation.h)
/// \param include_boundary_vertices whether boundary stars (open fans) carry energy
/// \param minimum_valence the smallest valence of a star that carries energy; the paper omits
///        valence-3 vertices (section 4.1.4: a valence-3 hinge is flat, Prop. A.3), i.e. 4
///
/// Complexity: linear in the number of halfedges.
template <class Indices>
Vertex_stars vertex_stars(const Indices& idx, bool include_boundary_vertices, std::size_t minimum_valence)
{
  using Mesh = typename Indices::Mesh;
  using GT = boost::graph_traits<Mesh>;
  const Mesh& tm = idx.mesh();
  const std::size_t nv = idx.number_of_vertices();
  // a walk around one vertex cannot be longer than this on a valid mesh
  const std::size_t walk_limit = idx.number_of_halfedges();

  Vertex_stars stars;
  stars.ring_begin.assign(nv + 1, 0);
  stars.closed.assign(nv, false);
  stars.active.assign(nv, false);
  stars.ring.reserve(idx.number_of_halfedges());
  for(std::size_t v = 0; v < nv; ++v)
  {
    stars.ring_begin[v] = stars.ring.size();
    const auto vd = idx.vertex(v);
    const auto incoming = halfedge(vd, tm);
    if(incoming == GT::null_halfedge())
      continue;

    // Start at the outgoing halfedge whose opposite is a border halfedge (the first edge of an
    // open fan), or anywhere on a closed star.
    auto start = opposite(incoming, tm);
    bool boundary = false;
    for(auto h : halfedges_around_source(vd, tm))
      if(idx.is_border(opposite(h, tm)))
      {
        start = h;
        boundary = true;
        break;
      }

    // Outgoing halfedge h = (v, r_k) lies in face (v, r_k, r_{k+1}); the next outgoing halfedge
    // counter-clockwise is opposite(prev(h)) = (v, r_{k+1}).
    const std::size_t first = stars.ring.size();
    auto h = start;
    for(std::size_t step = 0; step < walk_limit; ++step)
    {
      stars.ring.push_back(idx.target_index(h));
      if(idx.is_border(h))
        break; // the last edge of an open fan
      h = opposite(prev(h, tm), tm);
      if(h == start)
        break; // around a closed star
    }
    if(!boundary)
      std::rotate(stars.ring.begin() + first,
                  std::min_element(stars.ring.begin() + first, stars.ring.end()), stars.ring.end());

    const std::size_t valence = stars.ring.size() - first;
    const std::size_t faces = boundary ? valence - 1 : valence;
    stars.closed[v] = !boundary;
    stars.active[v] = (!boundary || include_boundary_vertices) && valence >= minimum_valence && faces > 0;
  }
  stars.ring_begin[nv] = stars.ring.size();

  for(std::size_t v = 0; v < nv; ++v)
    if(stars.active[v])
      stars.active_vertices.push_back(v);

  // Gather lists by counting sort over the slots in increasing order.
  stars.gather_begin.assign(nv + 1, 0);
  auto for_each_slot = [&stars](auto&& f) {
    for(std::size_t v : stars.active_vertices)
    {
      const std::size_t b = stars.block_begin(v);
      f(b, v);
      const std::size_t* r = stars.ring_of(v);
      for(std::size_t k = 0; k < stars.degree(v); ++k)
        f(b + 1 + k, r[k]);
    }
  };
  for_each_slot([&stars](std::size_t, std::size_t p) { ++stars.gather_begin[p + 1]; });
  for(std::size_t p = 0; p < nv; ++p)
    stars.gather_begin[p + 1] += stars.gather_begin[p];
  stars.gather_slot.resize(stars.gather_begin[nv]);
  std::vector<std::size_t> fill(stars.gather_begin.begin(), stars.gather_begin.end() - 1);
  for_each_slot([&stars, &fill](std::size_t slot, std::size_t p) { stars.gather_slot[fill[p]++] = slot; });
  return stars;
}

} // namespace internal
} // namespace Surface_design
} // namespace CGAL

#endif // CGAL_SURFACE_DESIGN_INTERNAL_DEVELOPABILITY_VERTEX_STARS_H
