// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Contiguous indices for the vertices, halfedges, edges and faces of any FaceGraph.

#ifndef CGAL_SURFACE_DESIGN_INTERNAL_CORE_MESH_INDICES_H
#define CGAL_SURFACE_DESIGN_INTERNAL_CORE_MESH_INDICES_H

#include <CGAL/Surface_design/exceptions.h>

#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/Named_function_parameters.h>

#include <boost/graph/graph_traits.hpp>

#include <cstddef>
#include <limits>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_design {
namespace internal {

/// "No element": an index that names nothing.
constexpr std::size_t npos = (std::numeric_limits<std::size_t>::max)();

namespace mesh_indices_detail {
// Unqualified calls, found by argument-dependent lookup when instantiated: this header works
// whether or not the graph's own header (Surface_mesh, Polyhedron_3) was included before it.
template <class Edge, class Graph>
auto halfedge_of_edge(Edge e, const Graph& g)
{
  return halfedge(e, g);
}

template <class Halfedge, class Graph>
bool is_border_halfedge(Halfedge h, const Graph& g)
{
  return is_border(h, g);
}
} // namespace mesh_indices_detail

/// Index maps for the four kinds of elements of a `FaceGraph`, plus the inverse maps
/// (index -> descriptor).
///
/// **Which numbering.** A map given in the named parameters (`vertex_index_map`,
/// `halfedge_index_map`, `edge_index_map`, `face_index_map`) is honoured: element `i` is the one
/// the user's map sends to `i`. Without one, the mesh's own map is used
/// (`CGAL::get_initialized_*_index_map`: the built-in indices of a `Surface_mesh`, the ids of a
/// `Polyhedron_3` with ids, initialized if they are not yet valid, else a dynamic map numbered in
/// iteration order), and edges are numbered in the iteration order of `edges(tm)`. Every map is
/// checked to be a bijection onto `[0, n)`; a `Surface_mesh` with removed but not collected
/// elements fails that check with a clear `Invalid_mesh`.
///
/// The type does not depend on the named parameters, so classes can hold one: a user map is read
/// once, in the constructor, into a permutation of the mesh's own numbering.
///
/// **Edge orientation.** Every algorithm of the library orients edge `e` from its endpoint of
/// smaller vertex index to its endpoint of larger vertex index (the convention of the papers). It
/// does not depend on which halfedge the mesh data structure calls `halfedge(e)`, so a
/// `Surface_mesh` and a `Polyhedron_3` read from the same file give identical operators.
template <class TriangleMesh>
class Mesh_indices
{
  using GT = boost::graph_traits<TriangleMesh>;
  using Defaults = CGAL::parameters::Default_named_parameters;

public:
  using Mesh = TriangleMesh;
  using vertex_descriptor = typename GT::vertex_descriptor;
  using halfedge_descriptor = typename GT::halfedge_descriptor;
  using edge_descriptor = typename GT::edge_descriptor;
  using face_descriptor = typename GT::face_descriptor;

  using Vertex_index_map = decltype(CGAL::get_initialized_vertex_index_map(
    std::declval<const TriangleMesh&>(), std::declval<const Defaults&>()));
  using Halfedge_index_map = decltype(CGAL::get_initialized_halfedge_index_map(
    std::declval<const TriangleMesh&>(), std::declval<const Defaults&>()));
  using Face_index_map = decltype(CGAL::get_initialized_face_index_map(
    std::declval<const TriangleMesh&>(), std::declval<const Defaults&>()));

  /// Builds (or takes from the mesh or the named parameters) the index maps and checks them.
  /// \throws Invalid_mesh (`invalid_index_map`) if a map is not a bijection onto `[0, n)`.
  template <class NamedParameters = Defaults>
  explicit Mesh_indices(const TriangleMesh& tm, const NamedParameters& np = CGAL::parameters::default_values())
    : m_tm(&tm),
      m_vim(CGAL::get_initialized_vertex_index_map(tm, CGAL::parameters::default_values())),
      m_him(CGAL::get_initialized_halfedge_index_map(tm, CGAL::parameters::default_values())),
      m_fim(CGAL::get_initialized_face_index_map(tm, CGAL::parameters::default_values()))
  {
    using CGAL::parameters::get_parameter;
    number(vertices(tm), num_vertices(tm), m_vim, get_parameter(np, CGAL::internal_np::vertex_index), m_vertices,
           m_vertex_permutation, "vertex");
    number(halfedges(tm), num_halfedges(tm), m_him, get_parameter(np, CGAL::internal_np::halfedge_index),
           m_halfedges, m_halfedge_permutation, "halfedge");
    number(faces(tm), num_faces(tm), m_fim, get_parameter(np, CGAL::internal_np::face_index), m_faces,
           m_face_permutation, "face");

    // Edge indices are stored per halfedge: CGAL 5.5 has no edge index map for Polyhedron_3
    // without ids, and this works for every HalfedgeGraph.
    const auto user_edge_map = get_parameter(np, CGAL::internal_np::edge_index);
    constexpr bool user_edges =
      !std::is_same<std::decay_t<decltype(user_edge_map)>, CGAL::internal_np::Param_not_found>::value;
    const std::size_t ne = num_edges(tm);
    m_edges.assign(ne, edge_descriptor());
    m_edge_of_halfedge.assign(m_halfedges.size(), npos);
    std::vector<bool> seen(ne, false);
    std::size_t count = 0;
    for(edge_descriptor e : edges(tm))
    {
      std::size_t i = count;
      if constexpr(user_edges)
        i = static_cast<std::size_t>(get(user_edge_map, e));
      if(i >= ne || seen[i])
        throw_not_bijective("edge", i, ne);
      seen[i] = true;
      const halfedge_descriptor h = mesh_indices_detail::halfedge_of_edge(e, tm);
      m_edge_of_halfedge[index(h)] = m_edge_of_halfedge[index(opposite(h, tm))] = i;
      m_edges[i] = e;
      ++count;
    }
    if(count != ne || 2 * ne != m_halfedges.size())
      throw Invalid_mesh(Mesh_defect::invalid_index_map, Invalid_mesh::no_element,
                         "the mesh has " + std::to_string(count) + " edges and " +
                           std::to_string(m_halfedges.size()) + " halfedges");
  }

  const TriangleMesh& mesh() const { return *m_tm; }

  std::size_t number_of_vertices() const { return m_vertices.size(); }
  std::size_t number_of_halfedges() const { return m_halfedges.size(); }
  std::size_t number_of_edges() const { return m_edges.size(); }
  std::size_t number_of_faces() const { return m_faces.size(); }

  /// Index of an element of the mesh. \pre the descriptor is an element of the mesh (see `find`).
  std::size_t index(vertex_descriptor v) const { return permuted(m_vertex_permutation, get(m_vim, v)); }
  std::size_t index(halfedge_descriptor h) const { return permuted(m_halfedge_permutation, get(m_him, h)); }
  std::size_t index(edge_descriptor e) const { return m_edge_of_halfedge[index(mesh_indices_detail::halfedge_of_edge(e, *m_tm))]; }
  std::size_t index(face_descriptor f) const { return permuted(m_face_permutation, get(m_fim, f)); }

  /// Index of `f` if it is a face of the mesh, else `npos` (e.g. a descriptor of another mesh or
  /// `null_face()`). Same for vertices.
  std::size_t find(face_descriptor f) const { return checked(f, m_faces, m_fim, m_face_permutation); }
  std::size_t find(vertex_descriptor v) const { return checked(v, m_vertices, m_vim, m_vertex_permutation); }

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
    halfedge_descriptor h = mesh_indices_detail::halfedge_of_edge(m_edges[e], *m_tm);
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
    return mesh_indices_detail::is_border_halfedge(h, *m_tm);
  }

private:
  static std::size_t permuted(const std::vector<std::size_t>& permutation, std::size_t i)
  {
    return permutation.empty() ? i : permutation[i];
  }

  template <class Descriptor, class Map>
  static std::size_t checked(Descriptor d, const std::vector<Descriptor>& inverse, const Map& map,
                             const std::vector<std::size_t>& permutation)
  {
    std::size_t i = static_cast<std::size_t>(get(map, d));
    if(i >= inverse.size())
      return npos;
    i = permuted(permutation, i);
    return inverse[i] == d ? i : npos;
  }

  [[noreturn]] static void throw_not_bijective(const char* what, std::size_t i, std::size_t n)
  {
    throw Invalid_mesh(Mesh_defect::invalid_index_map, Invalid_mesh::no_element,
                       std::string("the ") + what + " index map is not a bijection onto [0, " +
                         std::to_string(n) + ") (index " + std::to_string(i) +
                         (i >= n ? " out of range" : " repeated") +
                         "); a Surface_mesh with removed elements needs collect_garbage()");
  }

  // Fills `inverse` (index -> descriptor) from the mesh's own map, or from the user's map if one
  // was given; then `permutation` sends the mesh's index to the user's.
  template <class Range, class Map, class UserMap, class Descriptor>
  static void number(const Range& range, std::size_t n, const Map& map, const UserMap& user_map,
                     std::vector<Descriptor>& inverse, std::vector<std::size_t>& permutation, const char* what)
  {
    constexpr bool user = !std::is_same<UserMap, CGAL::internal_np::Param_not_found>::value;
    inverse.assign(n, Descriptor());
    std::vector<bool> seen(n, false);
    std::size_t count = 0;
    for(Descriptor d : range)
    {
      const std::size_t own = static_cast<std::size_t>(get(map, d));
      if(own >= n || seen[own])
        throw_not_bijective(what, own, n);
      seen[own] = true;
      inverse[own] = d;
      ++count;
    }
    if(count != n)
      throw Invalid_mesh(Mesh_defect::invalid_index_map, Invalid_mesh::no_element,
                         std::string("the mesh iterates ") + std::to_string(count) + " " + what +
                           " descriptors but reports " + std::to_string(n) +
                           "; a Surface_mesh with removed elements needs collect_garbage()");
    if constexpr(user)
    {
      permutation.assign(n, npos);
      std::vector<Descriptor> by_user(n, Descriptor());
      std::fill(seen.begin(), seen.end(), false);
      for(std::size_t own = 0; own < n; ++own)
      {
        const std::size_t i = static_cast<std::size_t>(get(user_map, inverse[own]));
        if(i >= n || seen[i])
          throw_not_bijective(what, i, n);
        seen[i] = true;
        permutation[own] = i;
        by_user[i] = inverse[own];
      }
      inverse = std::move(by_user);
    }
  }

  const TriangleMesh* m_tm;
  Vertex_index_map m_vim;
  Halfedge_index_map m_him;
  Face_index_map m_fim;
  std::vector<vertex_descriptor> m_vertices;
  std::vector<halfedge_descriptor> m_halfedges;
  std::vector<edge_descriptor> m_edges;
  std::vector<face_descriptor> m_faces;
  std::vector<std::size_t> m_vertex_permutation, m_halfedge_permutation, m_face_permutation;
  std::vector<std::size_t> m_edge_of_halfedge;
};

} // namespace internal
} // namespace Surface_design
} // namespace CGAL

#endif // CGAL_SURFACE_DESIGN_INTERNAL_CORE_MESH_INDICES_H
