// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Boundary First Flattening in one call.

#ifndef CGAL_SURFACE_DESIGN_BOUNDARY_FIRST_FLATTENING_H
#define CGAL_SURFACE_DESIGN_BOUNDARY_FIRST_FLATTENING_H

#include <CGAL/Surface_design/Boundary_first_flattener.h>

#include <type_traits>

namespace CGAL {
namespace Surface_design {

/// \ingroup PkgFlatteningRef
///
/// Flattens a triangle mesh whose connected components are topological disks by Boundary First
/// Flattening (see `Boundary_first_flattener`) and writes the 2-D coordinates of every vertex.
///
/// \param tm the mesh (validated; every component a disk)
/// \param uv a writable vertex -> `Point_2` property map
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
///   \cgalParamNBegin{sparse_linear_solver}
///     \cgalParamDescription{the sparse solver that factors the cotangent Laplacian of the interior vertices
///                           (with `boundary_turning_angle_map`, a new object of the same type factors the
///                           shifted Laplacian of all vertices)}
///     \cgalParamType{a class model of `SparseLinearAlgebraWithFactorTraits_d`}
///     \cgalParamDefault{`Default_solver_traits` (`Size_switched_cholesky`: the simplicial LDLT below 20000
///                       unknowns, the supernodal Cholesky from there)}
///   \cgalParamNEnd
///   \cgalParamNBegin{boundary_scale_factor_map}
///     \cgalParamDescription{the log scale factors u_B at the boundary vertices (read there only): boundary
///                           edge ij is scaled by about exp((u_i + u_j) / 2)}
///     \cgalParamType{a class model of `ReadablePropertyMap` with
///                    `boost::graph_traits<TriangleMesh>::%vertex_descriptor` as key type and a value type
///                    convertible to `double`}
///     \cgalParamDefault{0 at every boundary vertex: the boundary keeps its lengths (the least area
///                       distortion)}
///     \cgalParamExtra{throws `Invalid_parameter` if a value is not finite or not in [-50, 50], or if
///                     `boundary_turning_angle_map` is given too}
///   \cgalParamNEnd
///   \cgalParamNBegin{boundary_turning_angle_map}
///     \cgalParamDescription{the turning angles k~_B at the boundary vertices (read there only), in radians,
///                           positive towards the piece, used instead of scale factors; u_B then solves the
///                           Neumann problem, its constant per piece chosen so that the boundary keeps its
///                           length}
///     \cgalParamType{a class model of `ReadablePropertyMap` with
///                    `boost::graph_traits<TriangleMesh>::%vertex_descriptor` as key type and a value type
///                    convertible to `double`}
///     \cgalParamDefault{not given: the boundary scale factors are used}
///     \cgalParamExtra{throws `Invalid_parameter` if an angle is not finite or not in (-pi, pi), if the
///                     angles of a boundary loop do not sum to 2 pi within 1e-6, or if
///                     `boundary_scale_factor_map` is given too}
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
/// \throws Invalid_mesh, Invalid_parameter (both maps given, or bad values),
///         Linear_solver_failure; `uv` is not written then
template <class TriangleMesh, class UVMap, class NamedParameters = CGAL::parameters::Default_named_parameters>
void boundary_first_flattening(const TriangleMesh& tm, UVMap uv,
                               const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::get_parameter;
  const auto scale = get_parameter(np, internal_np::boundary_scale_factor_map);
  const auto turning = get_parameter(np, internal_np::boundary_turning_angle_map);
  constexpr bool has_scale = !std::is_same<std::decay_t<decltype(scale)>, CGAL::internal_np::Param_not_found>::value;
  constexpr bool has_turning =
    !std::is_same<std::decay_t<decltype(turning)>, CGAL::internal_np::Param_not_found>::value;
  if constexpr(has_scale && has_turning)
    throw Invalid_parameter("boundary_turning_angle_map",
                            "give either boundary scale factors or boundary turning angles, not both");
  Boundary_first_flattener flattener(tm, np);
  if constexpr(has_scale)
    flattener.flatten_with_scale_factors(scale, uv);
  else if constexpr(has_turning)
    flattener.flatten_with_turning_angles(turning, uv);
  else
    flattener.flatten(uv);
}

} // namespace Surface_design
} // namespace CGAL

#endif // CGAL_SURFACE_DESIGN_BOUNDARY_FIRST_FLATTENING_H
