// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Contiguous indices for the vertices, halfedges, edges and faces of any FaceGraph.

#ifndef CGAL_SURFACE_DESIGN_INTERNAL_MESH_INDICES_H
#define CGAL_SURFACE_DESIGN_INTERNAL_MESH_INDICES_H

#include <CGAL/Surface_design/exceptions.h>

#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/Named_function_parameters.h>

#include <boost/graph/graph_traits.hpp>

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_design {
namespace internal {

/// Index maps for the four kinds of elements of a `FaceGraph`, plus the inverse maps
/// (index -> descriptor).
///
/// The maps come from `CGAL::get_initialized_*_index_map(tm, np)`: the map given in the named
/// parameters (`vertex_index_map`, `halfedge_index_map`, `face_index_map`) if any, else the mesh's internal map (initialized if it is writable and not yet
/// valid, as for `Polyhedron_3` with `Polyhedron_items_with_id_3`), else a dynamic map numbered in
/// iteration order. Every map is checked to be a bijection onto `[0, n)`; a `Surface_mesh` with
/// removed-but-not-collected elements fails that check with a clear `Invalid_mesh`.
/// Edges are numbered in the iteration order of `edges(tm)`.
///
/// **Edge orientation.** Every algorithm of the library orients edge `e` from its endpoint of
/// smaller vertex index to its endpoint of larger vertex index (the convention of the papers). It
/// does not depend on which halfedge the mesh data structure calls `halfedge(e)`, so a
/// `Surface_mesh` and a `Polyhedron_3` read from the same file give identical operators.
template <class TriangleMesh,
          class NamedParameters = CGAL::parameters::Default_named_parameters>
class Mesh_indices
{
  using GT = boost::graph_traits<TriangleMesh>;

public:
  using Mesh = TriangleMesh;
  using vertex_descriptor = typename GT::vertex_descriptor;
  using halfedge_descriptor = typename GT::halfedge_descriptor;
  using edge_descriptor = typename GT::edge_descriptor;
  using face_descriptor = typename GT::face_descriptor;

  using Vertex_index_map = decltype(CGAL::get_initialized_vertex_index_map(
    std::declval<const TriangleMesh&>(), std::declval<const NamedParameters&>()));
  using Halfedge_index_map = decltype(CGAL::get_initialized_halfedge_index_map(
    std::declval<const TriangleMesh&>(), std::declval<const NamedParameters&>()));
  using Face_index_map = decltype(CGAL::get_initialized_face_index_map(
    std::declval<const TriangleMesh&>(), std::declval<const NamedParameters&>()));

  /// Builds (or takes from the mesh) the index maps and checks them.
  /// \throws Invalid_mesh (`invalid_index_map`) if a map is not a bijection onto `[0, n)`.
  explicit Mesh_indices(const TriangleMesh& tm,
                        const NamedParameters& np = CGAL::parameters::default_values())
    : m_tm(&tm),
      m_vim(CGAL::get_initialized_vertex_index_map(tm, np)),
      m_him(CGAL::get_initialized_halfedge_index_map(tm, np)),
      m_fim(CGAL::get_initialized_face_index_map(tm, np))
  {
    fill_inverse(vertices(tm), num_vertices(tm), m_vim, m_vertices, "vertex");
    fill_inverse(halfedges(tm), num_halfedges(tm), m_him, m_halfedges, "halfedge");
    // Edge indices follow the iteration order of edges(tm), stored per halfedge: CGAL 5.5 has no
    // edge index map for Polyhedron_3 without ids, and this works for every HalfedgeGraph.
    m_edges.reserve(num_edges(tm));
    m_edge_of_halfedge.assign(m_halfedges.size(), std::size_t(-1));
    for(edge_descriptor e : edges(tm))
    {
      const halfedge_descriptor h = CGAL::halfedge(e, tm);
      m_edge_of_halfedge[index(h)] = m_edge_of_halfedge[index(opposite(h, tm))] = m_edges.size();
      m_edges.push_back(e);
    }
    if(m_edges.size() != num_edges(tm) || 2 * m_edges.size() != m_halfedges.size())
      throw Invalid_mesh(Mesh_defect::invalid_index_map, Invalid_mesh::no_element,
                         "the mesh has " + std::to_string(m_edges.size()) + " edges and " +
                           std::to_string(m_halfedges.size()) + " halfedges");
    fill_inverse(faces(tm), num_faces(tm), m_fim, m_faces, "face");
  }

  const TriangleMesh& mesh() const { return *m_tm; }

  std::size_t number_of_vertices() const { return m_vertices.size(); }
  std::size_t number_of_halfedges() const { return m_halfedges.size(); }
  std::size_t number_of_edges() const { return m_edges.size(); }
  std::size_t number_of_faces() const { return m_faces.size(); }

  std::size_t index(vertex_descriptor v) const { return static_cast<std::size_t>(get(m_vim, v)); }
  std::size_t index(halfedge_descriptor h) const { return static_cast<std::size_t>(get(m_him, h)); }
  std::size_t index(edge_descriptor e) const { return m_edge_of_halfedge[index(CGAL::halfedge(e, *m_tm))]; }
  std::size_t index(face_descriptor f) const { return static_cast<std::size_t>(get(m_fim, f)); }

  vertex_descriptor vertex(std::size_t i) const { return m_vertices[i]; }
  halfedge_descriptor halfedge(std::size_t i) const { return m_halfedges[i]; }
  edge_descriptor edge(std::size_t i) const { return m_edges[i]; }
  face_descriptor face(std::size_t i) const { return m_faces[i]; }

  std::size_t source_index(halfedge_descriptor h) const { return index(source(h, *m_tm)); }
  std::size_t target_index(halfedge_descriptor h) const { return index(target(h, *m_tm)); }
  std::size_t edge_index(halfedge_descriptor h) const { return m_edge_of_halfedge[index(h)]; }

  /// +1 if `h` runs along the orientation of its edge (from the smaller to the larger vertex
  /// index), -1 otherwise.
  int orientation_sign(halfedge_descriptor h) const
  {
    return source_index(h) < target_index(h) ? 1 : -1;
  }

  /// The halfedge of edge `e` oriented like `e` (from the smaller to the larger vertex index).
  halfedge_descriptor oriented_halfedge(std::size_t e) const
  {
    halfedge_descriptor h = CGAL::halfedge(m_edges[e], *m_tm);
    return orientation_sign(h) > 0 ? h : opposite(h, *m_tm);
  }

  /// Vertex indices (smaller, larger) of edge `e`.
  std::pair<std::size_t, std::size_t> edge_vertices(std::size_t e) const
  {
    halfedge_descriptor h = oriented_halfedge(e);
    return {source_index(h), target_index(h)};
  }

  bool is_border(halfedge_descriptor h) const
  {
    return CGAL::is_border(h, *m_tm);
  }

private:
  template <class Range, class Map, class Descriptor>
  static void fill_inverse(const Range& range, std::size_t n, const Map& map,
                           std::vector<Descriptor>& inverse, const char* what)
  {
    inverse.assign(n, Descriptor());
    std::vector<bool> seen(n, false);
    std::size_t count = 0;
    for(Descriptor d : range)
    {
      const std::size_t i = static_cast<std::size_t>(get(map, d));
      if(i >= n || seen[i])
        throw Invalid_mesh(Mesh_defect::invalid_index_map, Invalid_mesh::no_element,
                           std::string("the ") + what + " index map is not a bijection onto [0, " +
                             std::to_string(n) + ") (index " + std::to_string(i) +
                             (i >= n ? " out of range" : " repeated") +
                             "); a Surface_mesh with removed elements needs collect_garbage()");
      seen[i] = true;
      inverse[i] = d;
      ++count;
    }
    if(count != n)
      throw Invalid_mesh(Mesh_defect::invalid_index_map, Invalid_mesh::no_element,
                         std::string("the mesh iterates ") + std::to_string(count) + " " + what +
                           " descriptors but reports " + std::to_string(n) +
                           "; a Surface_mesh with removed elements needs collect_garbage()");
  }

  const TriangleMesh* m_tm;
  Vertex_index_map m_vim;
  Halfedge_index_map m_him;
  Face_index_map m_fim;
  std::vector<vertex_descriptor> m_vertices;
  std::vector<halfedge_descriptor> m_halfedges;
  std::vector<edge_descriptor> m_edges;
  std::vector<face_descriptor> m_faces;
  std::vector<std::size_t> m_edge_of_halfedge;
};

} // namespace internal
} // namespace Surface_design
} // namespace CGAL

#endif // CGAL_SURFACE_DESIGN_INTERNAL_MESH_INDICES_H
