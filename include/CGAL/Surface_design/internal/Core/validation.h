// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Input validation shared by every algorithm: read-only, throws Invalid_mesh.

#ifndef CGAL_SURFACE_DESIGN_INTERNAL_CORE_VALIDATION_H
#define CGAL_SURFACE_DESIGN_INTERNAL_CORE_VALIDATION_H

#include <CGAL/Surface_design/exceptions.h>
#include <CGAL/Surface_design/internal/Core/geometry.h>
#include <CGAL/Surface_design/internal/Core/Mesh_indices.h>

#include <cmath>
#include <cstddef>
#include <sstream>
#include <string>
#include <vector>

namespace CGAL {
namespace Surface_design {
namespace internal {

/// What an algorithm requires of its input mesh.
struct Validation_options
{
  bool require_triangles = true; ///< reject faces that are not triangles
  bool reject_degenerate_faces = true; ///< reject (numerically) zero-area triangles
  /// A triangle is degenerate when twice its area is at most
  /// `degenerate_tolerance * (longest edge)^2`. That ratio is sin(a) sin(b) / sin(c) for the
  /// angles a, b and the largest angle c: about the sine of the smallest angle, scale invariant.
  /// 1e-12 accepts slivers with angles down to about 1e-10 degrees.
  double degenerate_tolerance = 1e-12;
};

namespace validation_detail {

template <class Indices>
std::string describe_face(const Indices& idx, std::size_t f)
{
  const auto& tm = idx.mesh();
  std::ostringstream s;
  s << "face " << f << " (vertices";
  for(auto v : vertices_around_face(halfedge(idx.face(f), tm), tm))
    s << ' ' << idx.index(v);
  s << ')';
  return s.str();
}

} // namespace validation_detail

/// Checks, in this order, and throws `Invalid_mesh` naming the first offending element:
/// the mesh has at least one face; every vertex has finite coordinates; no vertex is isolated;
/// every face is a triangle (if required); every vertex is manifold (its incident faces form one
/// fan); no triangle is degenerate (if required). Reads only: the mesh is never modified.
/// (Index-map validity is checked by the Mesh_indices constructor.)
template <class Indices, class VertexPointMap>
void validate_mesh(const Indices& idx, const VertexPointMap& vpm,
                   const Validation_options& options = Validation_options())
{
  using validation_detail::describe_face;
  const auto& tm = idx.mesh();

  if(idx.number_of_faces() == 0)
    throw Invalid_mesh(Mesh_defect::empty, Invalid_mesh::no_element,
                       "the mesh has no face (" + std::to_string(idx.number_of_vertices()) +
                         " vertices)");

  for(std::size_t v = 0; v < idx.number_of_vertices(); ++v)
  {
    const Eigen::Vector3d p = position(vpm, idx.vertex(v));
    // coordinates beyond 1e150 overflow the squared lengths every algorithm computes
    if(!p.allFinite() || p.cwiseAbs().maxCoeff() > 1e150)
    {
      std::ostringstream s;
      s << "vertex " << v << " has coordinates (" << p.x() << ", " << p.y() << ", " << p.z() << ")"
        << (p.allFinite() ? ", too large for double precision (at most 1e150: squared lengths overflow)" : "");
      throw Invalid_mesh(Mesh_defect::non_finite_coordinates, v, s.str());
    }
  }

  // Number of halfedges pointing to each vertex; a manifold vertex sees all of them in the one
  // cycle halfedges_around_target(halfedge(v)).
  std::vector<std::size_t> incoming(idx.number_of_vertices(), 0);
  for(std::size_t h = 0; h < idx.number_of_halfedges(); ++h)
    ++incoming[idx.target_index(idx.halfedge(h))];
  for(std::size_t v = 0; v < idx.number_of_vertices(); ++v)
  {
    const auto vd = idx.vertex(v);
    const auto h0 = halfedge(vd, tm);
    if(h0 == boost::graph_traits<typename Indices::Mesh>::null_halfedge() || incoming[v] == 0)
      throw Invalid_mesh(Mesh_defect::isolated_vertex, v,
                         "vertex " + std::to_string(v) + " has no incident face");
  }

  if(options.require_triangles)
    for(std::size_t f = 0; f < idx.number_of_faces(); ++f)
    {
      const std::size_t degree = halfedges_around_face(halfedge(idx.face(f), tm), tm).size();
      if(degree != 3)
        throw Invalid_mesh(Mesh_defect::not_triangle, f,
                           describe_face(idx, f) + " has " + std::to_string(degree) +
                             " sides; triangulate the mesh first (e.g. "
                             "CGAL::Polygon_mesh_processing::triangulate_faces())");
    }

  for(std::size_t v = 0; v < idx.number_of_vertices(); ++v)
  {
    std::size_t fan = 0, border_halfedges = 0;
    for(auto h : halfedges_around_target(halfedge(idx.vertex(v), tm), tm))
    {
      ++fan;
      if(idx.is_border(h))
        ++border_halfedges;
    }
    if(fan != incoming[v] || border_halfedges > 1)
      throw Invalid_mesh(Mesh_defect::non_manifold_vertex, v,
                         "vertex " + std::to_string(v) + " joins " +
                           (fan != incoming[v] ? "several fans of faces (" + std::to_string(fan) +
                                                   " of its " + std::to_string(incoming[v]) +
                                                   " incident edges around one fan)"
                                               : std::string("several boundary gaps")) +
                           "; split it (e.g. CGAL::Polygon_mesh_processing::"
                           "duplicate_non_manifold_vertices())");
  }

  if(options.require_triangles && options.reject_degenerate_faces)
    for(std::size_t f = 0; f < idx.number_of_faces(); ++f)
    {
      Eigen::Vector3d a, b, c;
      triangle_of(idx, vpm, halfedge(idx.face(f), tm), a, b, c);
      const double longest2 =
        (std::max)({(b - a).squaredNorm(), (c - b).squaredNorm(), (a - c).squaredNorm()});
      const double double_area = (b - a).cross(c - a).norm();
      if(!(double_area > options.degenerate_tolerance * longest2))
      {
        std::ostringstream s;
        s << describe_face(idx, f) << " has area " << 0.5 * double_area
          << (longest2 == 0. ? " (all its vertices coincide)" : "")
          << "; remove degenerate faces first (e.g. "
             "CGAL::Polygon_mesh_processing::remove_degenerate_faces())";
        throw Invalid_mesh(Mesh_defect::degenerate_face, f, s.str());
      }
    }
}

} // namespace internal
} // namespace Surface_design
} // namespace CGAL

#endif // CGAL_SURFACE_DESIGN_INTERNAL_CORE_VALIDATION_H
