// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Harmonic-function quad remeshing in one call.

#ifndef CGAL_SURFACE_DESIGN_HARMONIC_QUAD_REMESHING_H
#define CGAL_SURFACE_DESIGN_HARMONIC_QUAD_REMESHING_H

#include <CGAL/Surface_design/Harmonic_quad_remesher.h>

#include <type_traits>

namespace CGAL {
namespace Surface_design {

/// \ingroup PkgHarmonicQuadRemeshingRef
///
/// Remeshes the triangle mesh `tm` into a quad mesh with its topology (with `all_quads(false)`:
/// the quad-dominant net) added to `out`, from the isolines and gradient lines of a harmonic function (see
/// `Harmonic_quad_remesher`).
///
/// \param np optional named parameters: those of the `Harmonic_quad_remesher` constructor
///        (`vertex_point_map`, `sparse_linear_solver`, `harmonic_weights`,
///        `harmonic_constraints`, `protrusion_maxima`, index maps) and of its `remesh()`
///        (`target_edge_length`, `quad_poles`, `spectacles`, `all_quads`, `curvature_adaptation`,
///        `feature_snapping`);
///        `out`'s point map is its internal one
/// \returns the report of `remesh()`; `report.harmonic_seconds` includes building the Laplacian
/// \throws Invalid_mesh, Invalid_constraints, Invalid_parameter, Linear_solver_failure,
///         Remeshing_failure (no net with the input's topology, see `Harmonic_quad_remesher::remesh()`);
///         `out` is not modified then
template <class TriangleMesh, class PolygonMesh, class NamedParameters = CGAL::parameters::Default_named_parameters>
Harmonic_quad_remeshing_report harmonic_quad_remeshing(const TriangleMesh& tm, PolygonMesh& out,
                                                       const NamedParameters& np = CGAL::parameters::default_values())
{
  using VPM = typename CGAL::GetVertexPointMap<TriangleMesh, NamedParameters>::const_type;
  using Traits = std::decay_t<decltype(internal::solver_traits(np))>;
  Harmonic_quad_remesher<TriangleMesh, VPM, Traits> remesher(tm, np);
  // the remaining parameters go to remesh() without the input's point map
  const bool poles = CGAL::parameters::choose_parameter(CGAL::parameters::get_parameter(np, internal_np::quad_poles), true);
  const bool spectacles =
    CGAL::parameters::choose_parameter(CGAL::parameters::get_parameter(np, internal_np::spectacles), true);
  const bool all_quads =
    CGAL::parameters::choose_parameter(CGAL::parameters::get_parameter(np, internal_np::all_quads), true);
  const double adaptation =
    CGAL::parameters::choose_parameter(CGAL::parameters::get_parameter(np, internal_np::curvature_adaptation), 0.);
  const bool snapping =
    CGAL::parameters::choose_parameter(CGAL::parameters::get_parameter(np, internal_np::feature_snapping), true);
  const auto rest = parameters::quad_poles(
    poles, parameters::spectacles(
             spectacles, parameters::all_quads(all_quads, parameters::curvature_adaptation(
                                                            adaptation, parameters::feature_snapping(snapping)))));
  const auto h = CGAL::parameters::get_parameter(np, internal_np::target_edge_length);
  if constexpr(std::is_same<std::decay_t<decltype(h)>, CGAL::internal_np::Param_not_found>::value)
    return remesher.remesh(out, rest);
  else
    return remesher.remesh(out, parameters::target_edge_length(double(h), rest));
}

} // namespace Surface_design
} // namespace CGAL

#endif // CGAL_SURFACE_DESIGN_HARMONIC_QUAD_REMESHING_H
