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
/// \param np optional named parameters among:
/// - `vertex_point_map`, `sparse_linear_solver`, index maps
/// - `boundary_scale_factor_map` (readable vertex -> double): log scale factors u_B at the
///   boundary; default 0 everywhere (boundary lengths kept: least area distortion)
/// - `boundary_turning_angle_map` (readable vertex -> double): target turning angles at the
///   boundary (radians, summing to 2 pi per loop) instead of scale factors
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
