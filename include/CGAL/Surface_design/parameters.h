// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Named parameters of the library, in the style of CGAL::parameters.

#ifndef CGAL_SURFACE_DESIGN_PARAMETERS_H
#define CGAL_SURFACE_DESIGN_PARAMETERS_H

#include <CGAL/Named_function_parameters.h>

namespace CGAL {
namespace Surface_design {

// Tags of the library's own named parameters. (Always qualify CGAL::internal_np:: for CGAL's.)
namespace internal_np {
enum stripes_per_unit_length_t { stripes_per_unit_length };
enum loop_windings_t { loop_windings };
enum one_form_convention_t { one_form_convention };
enum edge_dalpha_map_t { edge_dalpha_map };
enum edge_omega_map_t { edge_omega_map };
enum corner_coordinate_map_t { corner_coordinate_map };
enum weighting_t { weighting };
enum reference_point_map_t { reference_point_map };
enum area_tolerance_t { area_tolerance };
enum symmetry_order_t { symmetry_order };
enum curvature_alignment_weight_t { curvature_alignment_weight };
enum field_boundary_condition_t { field_boundary_condition };
enum boundary_smoothing_length_t { boundary_smoothing_length };
enum normalize_field_t { normalize_field };
enum unit_length_iterations_t { unit_length_iterations };
enum eigen_tolerance_t { eigen_tolerance };
enum developability_energy_t { developability_energy };
enum number_of_subdivisions_t { number_of_subdivisions };
enum gradient_tolerance_t { gradient_tolerance };
enum energy_tolerance_t { energy_tolerance };
enum developability_target_t { developability_target };
enum minimum_angle_t { minimum_angle };
enum omit_valence_three_vertices_t { omit_valence_three_vertices };
enum include_boundary_vertices_t { include_boundary_vertices };
enum parallel_evaluation_t { parallel_evaluation };
enum descent_method_t { descent_method };
enum vertex_energy_map_t { vertex_energy_map };
enum vertex_gradient_map_t { vertex_gradient_map };
enum cut_tolerance_t { cut_tolerance };
enum distortion_bound_t { distortion_bound };
enum crack_opening_bound_t { crack_opening_bound };
enum cut_edge_cost_t { cut_edge_cost };
enum ruling_alignment_weight_t { ruling_alignment_weight };
enum boundary_scale_factor_map_t { boundary_scale_factor_map };
enum boundary_turning_angle_map_t { boundary_turning_angle_map };
enum face_log_area_scale_map_t { face_log_area_scale_map };
enum sheet_size_t { sheet_size };
enum pattern_scale_t { pattern_scale };
enum sheet_margin_t { sheet_margin };
enum piece_spacing_t { piece_spacing };
enum seam_vertex_index_map_t { seam_vertex_index_map };
enum fold_angle_t { fold_angle };
enum glue_tab_width_t { glue_tab_width };
enum harmonic_constraints_t { harmonic_constraints };
enum harmonic_weights_t { harmonic_weights };
enum protrusion_maxima_t { protrusion_maxima };
enum target_edge_length_t { target_edge_length };
enum quad_poles_t { quad_poles };
enum hausdorff_error_bound_t { hausdorff_error_bound };
enum spectacles_t { spectacles };
enum all_quads_t { all_quads };
enum curvature_adaptation_t { curvature_adaptation };
enum feature_snapping_t { feature_snapping };
enum stiffening_rounds_t { stiffening_rounds };
enum edge_length_ratio_t { edge_length_ratio };
} // namespace internal_np

/// \ingroup PkgSurfaceDesignRef
/// Named parameters of `CGAL::Surface_design`. All of `CGAL::parameters` is available here too, so
/// one namespace serves: `CGAL::Surface_design::parameters::stripes_per_unit_length(4.).vertex_point_map(vpm)`.
/// A library parameter can be combined with an existing pack by passing the pack as second
/// argument: `stripes_per_unit_length(4., CGAL::parameters::vertex_point_map(vpm))`.
namespace parameters {

using namespace CGAL::parameters;

#define CGAL_SURFACE_DESIGN_ADD_NAMED_PARAMETER(NAME)                                              \
  template <typename K>                                                                            \
  CGAL::Named_function_parameters<K, internal_np::NAME##_t> NAME(const K& k)                       \
  {                                                                                                \
    return CGAL::Named_function_parameters<K, internal_np::NAME##_t>(k);                           \
  }                                                                                                \
  template <typename K, typename T, typename Tag, typename Base>                                   \
  CGAL::Named_function_parameters<K, internal_np::NAME##_t,                                        \
                                  CGAL::Named_function_parameters<T, Tag, Base>>                   \
  NAME(const K& k, const CGAL::Named_function_parameters<T, Tag, Base>& np)                        \
  {                                                                                                \
    return CGAL::Named_function_parameters<K, internal_np::NAME##_t,                               \
                                           CGAL::Named_function_parameters<T, Tag, Base>>(k, np);  \
  }

CGAL_SURFACE_DESIGN_ADD_NAMED_PARAMETER(stripes_per_unit_length)
CGAL_SURFACE_DESIGN_ADD_NAMED_PARAMETER(loop_windings)
CGAL_SURFACE_DESIGN_ADD_NAMED_PARAMETER(one_form_convention)
CGAL_SURFACE_DESIGN_ADD_NAMED_PARAMETER(edge_dalpha_map)
CGAL_SURFACE_DESIGN_ADD_NAMED_PARAMETER(edge_omega_map)
CGAL_SURFACE_DESIGN_ADD_NAMED_PARAMETER(corner_coordinate_map)
CGAL_SURFACE_DESIGN_ADD_NAMED_PARAMETER(weighting)
CGAL_SURFACE_DESIGN_ADD_NAMED_PARAMETER(reference_point_map)
CGAL_SURFACE_DESIGN_ADD_NAMED_PARAMETER(area_tolerance)
CGAL_SURFACE_DESIGN_ADD_NAMED_PARAMETER(symmetry_order)
CGAL_SURFACE_DESIGN_ADD_NAMED_PARAMETER(curvature_alignment_weight)
CGAL_SURFACE_DESIGN_ADD_NAMED_PARAMETER(field_boundary_condition)
CGAL_SURFACE_DESIGN_ADD_NAMED_PARAMETER(boundary_smoothing_length)
CGAL_SURFACE_DESIGN_ADD_NAMED_PARAMETER(normalize_field)
CGAL_SURFACE_DESIGN_ADD_NAMED_PARAMETER(unit_length_iterations)
CGAL_SURFACE_DESIGN_ADD_NAMED_PARAMETER(eigen_tolerance)
CGAL_SURFACE_DESIGN_ADD_NAMED_PARAMETER(developability_energy)
CGAL_SURFACE_DESIGN_ADD_NAMED_PARAMETER(number_of_subdivisions)
CGAL_SURFACE_DESIGN_ADD_NAMED_PARAMETER(gradient_tolerance)
CGAL_SURFACE_DESIGN_ADD_NAMED_PARAMETER(energy_tolerance)
CGAL_SURFACE_DESIGN_ADD_NAMED_PARAMETER(developability_target)
CGAL_SURFACE_DESIGN_ADD_NAMED_PARAMETER(minimum_angle)
CGAL_SURFACE_DESIGN_ADD_NAMED_PARAMETER(omit_valence_three_vertices)
CGAL_SURFACE_DESIGN_ADD_NAMED_PARAMETER(include_boundary_vertices)
CGAL_SURFACE_DESIGN_ADD_NAMED_PARAMETER(parallel_evaluation)
CGAL_SURFACE_DESIGN_ADD_NAMED_PARAMETER(descent_method)
CGAL_SURFACE_DESIGN_ADD_NAMED_PARAMETER(vertex_energy_map)
CGAL_SURFACE_DESIGN_ADD_NAMED_PARAMETER(vertex_gradient_map)
CGAL_SURFACE_DESIGN_ADD_NAMED_PARAMETER(cut_tolerance)
CGAL_SURFACE_DESIGN_ADD_NAMED_PARAMETER(distortion_bound)
CGAL_SURFACE_DESIGN_ADD_NAMED_PARAMETER(crack_opening_bound)
CGAL_SURFACE_DESIGN_ADD_NAMED_PARAMETER(cut_edge_cost)
CGAL_SURFACE_DESIGN_ADD_NAMED_PARAMETER(ruling_alignment_weight)
CGAL_SURFACE_DESIGN_ADD_NAMED_PARAMETER(boundary_scale_factor_map)
CGAL_SURFACE_DESIGN_ADD_NAMED_PARAMETER(boundary_turning_angle_map)
CGAL_SURFACE_DESIGN_ADD_NAMED_PARAMETER(face_log_area_scale_map)
CGAL_SURFACE_DESIGN_ADD_NAMED_PARAMETER(sheet_size)
CGAL_SURFACE_DESIGN_ADD_NAMED_PARAMETER(pattern_scale)
CGAL_SURFACE_DESIGN_ADD_NAMED_PARAMETER(sheet_margin)
CGAL_SURFACE_DESIGN_ADD_NAMED_PARAMETER(piece_spacing)
CGAL_SURFACE_DESIGN_ADD_NAMED_PARAMETER(seam_vertex_index_map)
CGAL_SURFACE_DESIGN_ADD_NAMED_PARAMETER(fold_angle)
CGAL_SURFACE_DESIGN_ADD_NAMED_PARAMETER(glue_tab_width)
CGAL_SURFACE_DESIGN_ADD_NAMED_PARAMETER(harmonic_constraints)
CGAL_SURFACE_DESIGN_ADD_NAMED_PARAMETER(harmonic_weights)
CGAL_SURFACE_DESIGN_ADD_NAMED_PARAMETER(protrusion_maxima)
CGAL_SURFACE_DESIGN_ADD_NAMED_PARAMETER(target_edge_length)
CGAL_SURFACE_DESIGN_ADD_NAMED_PARAMETER(quad_poles)
CGAL_SURFACE_DESIGN_ADD_NAMED_PARAMETER(hausdorff_error_bound)
CGAL_SURFACE_DESIGN_ADD_NAMED_PARAMETER(spectacles)
CGAL_SURFACE_DESIGN_ADD_NAMED_PARAMETER(all_quads)
CGAL_SURFACE_DESIGN_ADD_NAMED_PARAMETER(curvature_adaptation)
CGAL_SURFACE_DESIGN_ADD_NAMED_PARAMETER(feature_snapping)
CGAL_SURFACE_DESIGN_ADD_NAMED_PARAMETER(stiffening_rounds)
CGAL_SURFACE_DESIGN_ADD_NAMED_PARAMETER(edge_length_ratio)

#undef CGAL_SURFACE_DESIGN_ADD_NAMED_PARAMETER

} // namespace parameters
} // namespace Surface_design
} // namespace CGAL

#endif // CGAL_SURFACE_DESIGN_PARAMETERS_H
