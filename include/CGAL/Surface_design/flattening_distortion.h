// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// How much a flattening stretches: area and angle distortion, flips, boundary lengths, overlaps.

#ifndef CGAL_SURFACE_DESIGN_FLATTENING_DISTORTION_H
#define CGAL_SURFACE_DESIGN_FLATTENING_DISTORTION_H

#include <CGAL/Surface_design/internal/Core/Mesh_indices.h>
#include <CGAL/Surface_design/internal/Core/geometry.h>
#include <CGAL/Surface_design/internal/Core/named_parameters.h>
#include <CGAL/Surface_design/internal/Core/topology.h>
#include <CGAL/Surface_design/internal/Core/validation.h>
#include <CGAL/Surface_design/internal/Developability/distortion.h>
#include <CGAL/Surface_design/parameters.h>

#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Named_function_parameters.h>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <string>
#include <vector>

namespace CGAL {
namespace Surface_design {

/// \ingroup PkgFlatteningRef
/// The distortion of a map from a triangle mesh to the plane, from the singular values
/// s1 >= s2 of its linear map on every face (weights: the faces' areas in space).
struct Flattening_distortion
{
  std::size_t faces = 0, pieces = 0;
  std::size_t flipped_faces = 0;        ///< faces whose orientation is reversed (or zero area) in the plane
  double area_log_mean = 0.;            ///< area-weighted mean of |log(s1 s2)| (area scale)
  double area_log_max = 0.;             ///< largest |log(s1 s2)|
  double conformal_log_mean = 0.;       ///< area-weighted mean of log(s1 / s2) (angle distortion; 0 for a similarity)
  double conformal_log_max = 0.;        ///< largest log(s1 / s2)
  double stretch_max = 1.;              ///< largest max(s1, 1 / s2): 1 for an isometry
  double area_ratio = 1.;               ///< total area in the plane over total area in space
  double boundary_length_error = 0.;    ///< sum over boundary edges of |l_2d - l_3d| over the sum of l_3d
  double boundary_length_error_max = 0.; ///< largest |l_2d / l_3d - 1| over the boundary edges
  std::size_t self_overlapping_pieces = 0; ///< pieces whose boundary crosses itself in the plane
};

/// \ingroup PkgFlatteningRef
///
/// Measures a flattening `uv` of `tm` (2-D coordinates per vertex; a cut mesh carries per-corner
/// coordinates as per-vertex ones).
///
/// \param tm a triangle mesh (validated)
/// \param uv a readable vertex -> `Point_2` map
/// \param np an optional sequence of named parameters among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{a property map associating points to the vertices of `tm`}
///     \cgalParamType{a class model of `ReadablePropertyMap` with
///                    `boost::graph_traits<TriangleMesh>::%vertex_descriptor` as key type and `%Point_3` as
///                    value type}
///     \cgalParamDefault{`boost::get(CGAL::vertex_point, tm)`}
///   \cgalParamNEnd
///   \cgalParamNBegin{face_log_area_scale_map}
///     \cgalParamDescription{output: log(s1 s2), the log of the ratio of the face's areas in the plane and in
///                           space (-inf for a face collapsed to zero area; the orientation is not in it:
///                           flipped faces are counted in `flipped_faces`)}
///     \cgalParamType{a class model of `WritablePropertyMap` with
///                    `boost::graph_traits<TriangleMesh>::%face_descriptor` as key type and `double` as value
///                    type}
///     \cgalParamDefault{not written}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_index_map}
///     \cgalParamDescription{a property map associating to each vertex of `tm` a unique index in
///                           `[0, num_vertices(tm))`: the numbering of the elements in error messages}
///     \cgalParamType{a class model of `ReadablePropertyMap` with
///                    `boost::graph_traits<TriangleMesh>::%vertex_descriptor` as key type and an integer as
///                    value type}
///     \cgalParamDefault{the mesh's own (`CGAL::get_initialized_vertex_index_map(tm)`)}
///     \cgalParamExtra{throws `Invalid_mesh` (`Mesh_defect::invalid_index_map`) if it is not a bijection onto
///                     `[0, num_vertices(tm))`}
///   \cgalParamNEnd
///   \cgalParamNBegin{halfedge_index_map}
///     \cgalParamDescription{a property map associating to each halfedge of `tm` a unique index in
///                           `[0, num_halfedges(tm))`: the numbering of the elements in error messages}
///     \cgalParamType{a class model of `ReadablePropertyMap` with
///                    `boost::graph_traits<TriangleMesh>::%halfedge_descriptor` as key type and an integer as
///                    value type}
///     \cgalParamDefault{the mesh's own (`CGAL::get_initialized_halfedge_index_map(tm)`)}
///     \cgalParamExtra{throws `Invalid_mesh` (`Mesh_defect::invalid_index_map`) if it is not a bijection onto
///                     `[0, num_halfedges(tm))`}
///   \cgalParamNEnd
///   \cgalParamNBegin{edge_index_map}
///     \cgalParamDescription{a property map associating to each edge of `tm` a unique index in
///                           `[0, num_edges(tm))`: the numbering of the elements in error messages}
///     \cgalParamType{a class model of `ReadablePropertyMap` with
///                    `boost::graph_traits<TriangleMesh>::%edge_descriptor` as key type and an integer as
///                    value type}
///     \cgalParamDefault{the order of `edges(tm)`}
///     \cgalParamExtra{throws `Invalid_mesh` (`Mesh_defect::invalid_index_map`) if it is not a bijection onto
///                     `[0, num_edges(tm))`}
///   \cgalParamNEnd
///   \cgalParamNBegin{face_index_map}
///     \cgalParamDescription{a property map associating to each face of `tm` a unique index in
///                           `[0, num_faces(tm))`: the numbering of the elements in error messages}
///     \cgalParamType{a class model of `ReadablePropertyMap` with
///                    `boost::graph_traits<TriangleMesh>::%face_descriptor` as key type and an integer as
///                    value type}
///     \cgalParamDefault{the mesh's own (`CGAL::get_initialized_face_index_map(tm)`)}
///     \cgalParamExtra{throws `Invalid_mesh` (`Mesh_defect::invalid_index_map`) if it is not a bijection onto
///                     `[0, num_faces(tm))`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \throws Invalid_mesh the mesh is invalid, Invalid_parameter a coordinate of `uv` is not finite
template <class TriangleMesh, class UVMap, class NamedParameters = CGAL::parameters::Default_named_parameters>
Flattening_distortion flattening_distortion(const TriangleMesh& tm, const UVMap& uv,
                                            const NamedParameters& np = CGAL::parameters::default_values())
{
  const auto vpm = internal::const_vertex_point_map(tm, np);
  const internal::Mesh_indices<TriangleMesh> idx(tm, np);
  internal::validate_mesh(idx, vpm);
  const std::vector<Eigen::Vector2d> p = internal::plane_coordinates(idx, uv);
  const auto& mesh = idx.mesh();
  Flattening_distortion d;
  d.faces = idx.number_of_faces();
  std::vector<double> log_area(d.faces, 0.);
  double area_3d = 0., area_2d = 0.;
  for(std::size_t f = 0; f < d.faces; ++f)
  {
    const auto h = halfedge(idx.face(f), mesh);
    Eigen::Vector3d a, b, c;
    internal::triangle_of(idx, vpm, h, a, b, c);
    const std::size_t ia = idx.source_index(h), ib = idx.target_index(h), ic = idx.target_index(next(h, mesh));
    const internal::Face_singular_values s = internal::face_singular_values(a, b, c, p[ia], p[ib], p[ic]);
    const double area = 0.5 * (b - a).cross(c - a).norm();
    area_3d += area;
    area_2d += s.determinant * area; // the determinant is the signed area ratio
    if(!(s.determinant > 0.))
      ++d.flipped_faces;
    const double la = s.s1 * s.s2 > 0. ? std::abs(std::log(s.s1 * s.s2)) : std::numeric_limits<double>::infinity();
    const double lc = s.s2 > 0. ? std::log(s.s1 / s.s2) : std::numeric_limits<double>::infinity();
    log_area[f] = s.s1 * s.s2 > 0. ? std::log(s.s1 * s.s2) : -std::numeric_limits<double>::infinity();
    d.area_log_mean += area * la;
    d.conformal_log_mean += area * lc;
    d.area_log_max = (std::max)(d.area_log_max, la);
    d.conformal_log_max = (std::max)(d.conformal_log_max, lc);
    d.stretch_max = (std::max)({d.stretch_max, s.s1, s.s2 > 0. ? 1. / s.s2 : std::numeric_limits<double>::infinity()});
  }
  d.area_log_mean /= area_3d;
  d.conformal_log_mean /= area_3d;
  d.area_ratio = area_2d / area_3d;

  const internal::Boundary_loops loops = internal::boundary_loops(idx);
  const internal::Components comps = internal::connected_components(idx, loops);
  d.pieces = comps.size();
  double boundary_3d = 0., boundary_error = 0.;
  std::vector<bool> overlapping(comps.size(), false);
  for(const auto& loop : loops.loops)
  {
    std::vector<Eigen::Vector2d> polygon;
    for(std::size_t i : loop)
    {
      const auto h = idx.halfedge(i);
      const std::size_t s = idx.source_index(h), t = idx.target_index(h);
      const double l3 = (internal::position(vpm, idx.vertex(s)) - internal::position(vpm, idx.vertex(t))).norm();
      const double l2 = (p[s] - p[t]).norm();
      boundary_3d += l3;
      boundary_error += std::abs(l2 - l3);
      d.boundary_length_error_max = (std::max)(d.boundary_length_error_max, std::abs(l2 / l3 - 1.));
      polygon.push_back(p[t]);
    }
    if(internal::polygon_self_intersects(polygon))
      overlapping[comps.vertex_component[idx.target_index(idx.halfedge(loop.front()))]] = true;
  }
  d.boundary_length_error = boundary_3d > 0. ? boundary_error / boundary_3d : 0.;
  d.self_overlapping_pieces = std::size_t(std::count(overlapping.begin(), overlapping.end(), true));
  internal::if_given(np, internal_np::face_log_area_scale_map, [&](auto map) {
    for(std::size_t f = 0; f < d.faces; ++f)
      put(map, idx.face(f), log_area[f]);
  });
  return d;
}

} // namespace Surface_design
} // namespace CGAL

#endif // CGAL_SURFACE_DESIGN_FLATTENING_DISTORTION_H
