// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The barycentric stencil of a polygon mesh with fixed vertices: which vertices are free, and the
// weighted neighbour list of every free vertex (uniform, cotangent or mean-value weights). Shared
// by the direct solver (Barycentric_embedding) and the paper's iterative reference.

#ifndef CGAL_SURFACE_DESIGN_INTERNAL_BARYCENTRIC_EMBEDDING_BARYCENTRIC_STENCIL_H
#define CGAL_SURFACE_DESIGN_INTERNAL_BARYCENTRIC_EMBEDDING_BARYCENTRIC_STENCIL_H

#include <CGAL/Surface_design/edge_weighting.h>
#include <CGAL/Surface_design/exceptions.h>
#include <CGAL/Surface_design/internal/Core/geometry.h>
#include <CGAL/Surface_design/internal/Core/Mesh_indices.h>
#include <CGAL/Surface_design/internal/Core/topology.h>
#include <CGAL/Surface_design/internal/Core/validation.h>

#include <CGAL/Weights/tangent_weights.h>

#include <boost/property_map/property_map.hpp>

#include <cmath>
#include <cstddef>
#include <iterator>
#include <sstream>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_design {

namespace internal {

/// \throws Invalid_parameter if `w` is not an enumerator of `Edge_weighting`
inline void check_edge_weighting(Edge_weighting w)
{
  if(w != Edge_weighting::uniform && w != Edge_weighting::cotangent && w != Edge_weighting::mean_value)
    throw Invalid_parameter("weighting", "not an Edge_weighting enumerator (" + std::to_string(int(w)) + ")");
}

namespace stencil_detail {

// A range of vertices (as opposed to a vertex -> bool property map): `*begin(r)` converts to a
// vertex descriptor. (A property map's values are bools, which do not convert to a descriptor.)
template <class T, class Vertex, class = void>
struct Is_vertex_range : std::false_type {};
template <class T, class Vertex>
struct Is_vertex_range<T, Vertex, std::void_t<decltype(*std::begin(std::declval<const T&>()))>>
  : std::is_convertible<decltype(*std::begin(std::declval<const T&>())), Vertex> {};

} // namespace stencil_detail

/// `true` when `FixedVertices` is a range of vertex descriptors, `false` when it is a vertex ->
/// bool property map.
template <class FixedVertices, class Vertex>
constexpr bool is_vertex_range_v = stencil_detail::Is_vertex_range<FixedVertices, Vertex>::value;

/// Per vertex index: true if fixed. `fixed` is either a readable vertex -> bool property map or a
/// range of vertex descriptors.
/// \throws Invalid_constraints if a vertex of the range is not a vertex of the mesh
template <class Indices, class FixedVertices>
std::vector<bool> fixed_flags(const Indices& idx, const FixedVertices& fixed)
{
  std::vector<bool> flag(idx.number_of_vertices(), false);
  if constexpr(is_vertex_range_v<FixedVertices, typename Indices::vertex_descriptor>)
  {
    for(const auto& v : fixed)
    {
      const std::size_t i = idx.index(typename Indices::vertex_descriptor(v));
      if(i >= flag.size() || idx.vertex(i) != typename Indices::vertex_descriptor(v))
        throw Invalid_constraints("a fixed vertex (index " + std::to_string(i) +
                                  ") is not a vertex of the mesh (" +
                                  std::to_string(flag.size()) + " vertices)");
      flag[i] = true;
    }
  }
  else
  {
    for(std::size_t i = 0; i < flag.size(); ++i)
      flag[i] = bool(get(fixed, idx.vertex(i)));
  }
  return flag;
}

/// Free and fixed vertices, and the weighted neighbour list of every free vertex, in compressed
/// rows: free vertex `free_vertices[r]` has neighbours `neighbour[k]` with weights `weight[k]` for
/// `k` in `[row_start[r], row_start[r + 1])` (one entry per halfedge leaving it, so a neighbour
/// joined by two edges appears twice). `slot[v]` is the position of vertex `v` in `free_vertices`
/// or in `fixed_vertices`. `halfedge[k]` is the halfedge index of entry k (from the free vertex
/// to its neighbour).
struct Barycentric_stencil
{
  std::vector<bool> is_fixed;
  std::vector<std::size_t> free_vertices, fixed_vertices, slot;
  std::vector<std::size_t> row_start, neighbour, halfedge;
  std::vector<double> weight;

  std::size_t number_of_free_vertices() const { return free_vertices.size(); }
  std::size_t number_of_fixed_vertices() const { return fixed_vertices.size(); }
};

/// Checks what the barycentric embedding requires and throws before anything is computed:
/// - the mesh (validate_mesh; triangles and non-degenerate faces for cotangent weights);
/// - with weights of a reference geometry, finite reference positions, and edges of non-zero
///   length for mean-value weights (`Invalid_mesh`);
/// - every connected component with a free vertex has a fixed vertex, else the linear system is
///   singular: a free component floats (`Invalid_constraints`, naming the component).
template <class Indices, class VertexPointMap, class ReferencePointMap>
void validate_barycentric_input(const Indices& idx, const VertexPointMap& vpm,
                                const ReferencePointMap& reference, Edge_weighting weighting,
                                const std::vector<bool>& is_fixed)
{
  Validation_options options;
  options.require_triangles = weighting == Edge_weighting::cotangent;
  options.reject_degenerate_faces = weighting == Edge_weighting::cotangent;
  validate_mesh(idx, vpm, options);
  if(weighting != Edge_weighting::uniform)
    validate_mesh(idx, reference, options); // the geometry the weights come from
  if(weighting == Edge_weighting::mean_value)
    for(std::size_t e = 0; e < idx.number_of_edges(); ++e)
    {
      const auto ij = idx.edge_vertices(e);
      if(!((position(reference, idx.vertex(ij.first)) - position(reference, idx.vertex(ij.second)))
             .squaredNorm() > 0.))
        throw Invalid_mesh(Mesh_defect::degenerate_face, Invalid_mesh::no_element,
                           "edge " + std::to_string(e) + " (vertices " + std::to_string(ij.first) +
                             " and " + std::to_string(ij.second) +
                             ") has length 0 in the reference geometry of the mean-value weights");
    }

  const Components comps = connected_components(idx, boundary_loops(idx));
  std::vector<bool> has_fixed(comps.size(), false), has_free(comps.size(), false);
  std::vector<std::size_t> some_free(comps.size(), npos);
  for(std::size_t v = 0; v < idx.number_of_vertices(); ++v)
  {
    const std::size_t c = comps.vertex_component[v];
    if(is_fixed[v])
      has_fixed[c] = true;
    else if(!has_free[c])
    {
      has_free[c] = true;
      some_free[c] = v;
    }
  }
  for(std::size_t c = 0; c < comps.size(); ++c)
    if(has_free[c] && !has_fixed[c])
    {
      std::ostringstream s;
      s << "connected component " << c << " (" << comps.info[c].vertices << " vertices, e.g. vertex "
        << some_free[c] << ") has no fixed vertex: the positions of its free vertices are not "
        << "determined (the barycentric system is singular); fix at least one of its vertices";
      throw Invalid_constraints(s.str());
    }
}

/// Tangent of half the angle between the vectors u and v (0 <= angle < pi), by
/// `CGAL::Weights::tangent_half_angle`: 2A / (|u| |v| + u.v), with A the area of the triangle
/// they span. \pre u, v non-zero and not opposite.
inline double tangent_half_angle(const Eigen::Vector3d& u, const Eigen::Vector3d& v)
{
  return CGAL::Weights::tangent_half_angle(u.norm(), v.norm(), 0.5 * u.cross(v).norm(), u.dot(v));
}

/// Builds the stencil. Weights of the reference geometry `reference` (ignored for uniform ones).
/// \pre validate_barycentric_input() passed
/// \throws Invalid_mesh (`degenerate_face`) if a mean-value weight is not finite (two edges of a
/// face at a free vertex point in opposite directions)
template <class Indices, class ReferencePointMap>
Barycentric_stencil barycentric_stencil(const Indices& idx, const ReferencePointMap& reference,
                                        Edge_weighting weighting, std::vector<bool> is_fixed)
{
  const auto& tm = idx.mesh();
  Barycentric_stencil s;
  s.is_fixed = std::move(is_fixed);
  s.slot.assign(idx.number_of_vertices(), npos);
  for(std::size_t v = 0; v < idx.number_of_vertices(); ++v)
  {
    std::vector<std::size_t>& list = s.is_fixed[v] ? s.fixed_vertices : s.free_vertices;
    s.slot[v] = list.size();
    list.push_back(v);
  }

  std::vector<double> edge_weight; // cotangent weights, per edge
  if(weighting == Edge_weighting::cotangent)
    edge_weight = cotangent_weights(idx, reference);

  s.row_start.reserve(s.free_vertices.size() + 1);
  s.row_start.push_back(0);
  for(std::size_t v : s.free_vertices)
  {
    const Eigen::Vector3d p = weighting == Edge_weighting::mean_value
                                ? position(reference, idx.vertex(v))
                                : Eigen::Vector3d::Zero();
    for(auto h : halfedges_around_source(idx.vertex(v), tm))
    {
      const std::size_t j = idx.target_index(h);
      double w = 1.;
      if(weighting == Edge_weighting::cotangent)
        w = edge_weight[idx.edge_index(h)];
      else if(weighting == Edge_weighting::mean_value)
      {
        // h runs v -> j; the neighbouring edges at v are prev(h) in face(h) and
        // next(opposite(h)) in the face on the other side (one term on a border edge)
        const Eigen::Vector3d e = position(reference, idx.vertex(j)) - p;
        double tangents = 0.;
        if(!idx.is_border(h))
          tangents += tangent_half_angle(e, position(reference, source(prev(h, tm), tm)) - p);
        const auto o = opposite(h, tm);
        if(!idx.is_border(o))
          tangents += tangent_half_angle(e, position(reference, target(next(o, tm), tm)) - p);
        w = tangents / e.norm();
        if(!std::isfinite(w))
          throw Invalid_mesh(Mesh_defect::degenerate_face, Invalid_mesh::no_element,
                             "the mean-value weight of vertex " + std::to_string(j) +
                               " at vertex " + std::to_string(v) +
                               " is not finite (a corner of 180 degrees at vertex " +
                               std::to_string(v) + " in the reference geometry)");
      }
      s.neighbour.push_back(j);
      s.halfedge.push_back(idx.index(h));
      s.weight.push_back(w);
    }
    s.row_start.push_back(s.neighbour.size());
  }
  return s;
}

} // namespace internal
} // namespace Surface_design
} // namespace CGAL

#endif // CGAL_SURFACE_DESIGN_INTERNAL_BARYCENTRIC_EMBEDDING_BARYCENTRIC_STENCIL_H
