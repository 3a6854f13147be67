// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Developability of triangle meshes (Stein, Grinspun & Crane 2018): the energies of vertex stars
// and the flow that drives a mesh towards a piecewise-developable shape.

#ifndef CGAL_SURFACE_DESIGN_DEVELOPABILITY_H
#define CGAL_SURFACE_DESIGN_DEVELOPABILITY_H

#include <CGAL/Surface_design/developability_energy.h>
#include <CGAL/Surface_design/exceptions.h>
#include <CGAL/Surface_design/internal/Solvers/Lbfgs_minimizer.h>
#include <CGAL/Surface_design/internal/Core/Mesh_indices.h>
#include <CGAL/Surface_design/internal/Core/named_parameters.h>
#include <CGAL/Surface_design/internal/Core/validation.h>
#include <CGAL/Surface_design/internal/Developability/flow.h>
#include <CGAL/Surface_design/internal/Developability/metrics.h>
#include <CGAL/Surface_design/internal/Developability/remeshing.h>
#include <CGAL/Surface_design/internal/Developability/star_energies.h>
#include <CGAL/Surface_design/internal/Developability/vertex_stars.h>
#include <CGAL/Surface_design/parameters.h>

#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Named_function_parameters.h>

#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <numeric>
#include <optional>
#include <string>
#include <tuple>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Surface_design {

/// \ingroup PkgDevelopabilityRef
/// The descent method of the developability flow.
enum class Developability_descent
{
  lbfgs,           ///< L-BFGS (memory 8) with the Lewis-Overton weak-Wolfe line search (the paper's choice, sec. 4.3)
  gradient_descent ///< gradient descent with Armijo backtracking
};

/// \ingroup PkgDevelopabilityRef
/// What the visitor of `make_piecewise_developable()` receives after every descent iteration.
struct Developability_iteration
{
  std::size_t level = 0;           ///< 0 before the first subdivision, then 1, 2, ...
  std::size_t iteration = 0;       ///< iterations so far, all levels together (1 for the first)
  std::size_t level_iteration = 0; ///< iterations so far in this level
  double energy = 0.;              ///< the energy after the iteration
  double gradient_norm = 0.;       ///< RMS of the gradient's coordinates times the mean edge length (dimensionless)
  double step = 0.;                ///< the accepted step length (0 if the line search failed)
  bool line_search_failed = false; ///< the iteration made no progress
  std::size_t flips = 0, collapses = 0; ///< small-angle operations after this iteration
  std::size_t vertices = 0, faces = 0;  ///< size of the mesh after the iteration
};

/// \ingroup PkgDevelopabilityRef
/// What `make_piecewise_developable()` did, per level and in total.
struct Developability_flow_result
{
  struct Level
  {
    std::size_t iterations = 0;
    double initial_energy = 0., final_energy = 0., final_gradient_norm = 0.;
    std::string end; ///< why the level ended: "converged", "target reached", "iteration limit", ...
    std::size_t vertices = 0, faces = 0;
    /// At the end of the level: the measured vertices (interior, valence >= 4) and those whose
    /// covariance lambda_i exceeds the target (`developability_target`)
    std::size_t measured_vertices = 0, vertices_above_target = 0;
  };
  std::vector<Level> levels;
  std::size_t iterations = 0, evaluations = 0, flips = 0, collapses = 0, subdivisions = 0;
  bool stopped_by_visitor = false;
  /// The last level converged, reached the target or found a zero gradient (it did not stop at
  /// the iteration limit, at a line-search failure or by the visitor).
  bool converged = false;
  /// Wall-clock seconds: energy and gradient evaluations (line searches included), small-angle
  /// handling, subdivisions, and everything together.
  double evaluation_seconds = 0., remeshing_seconds = 0., subdivision_seconds = 0., total_seconds = 0.;
};

namespace internal {

// The options of the flow from the named parameters, validated.
template <class NamedParameters>
Developability_flow_options developability_flow_options(const NamedParameters& np)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  internal::Developability_flow_options o;
  o.energy = choose_parameter(get_parameter(np, internal_np::developability_energy), Developability_energy::covariance);
  o.subdivisions = choose_parameter(get_parameter(np, internal_np::number_of_subdivisions), std::size_t(0));
  o.iterations_per_level = choose_parameter(get_parameter(np, CGAL::internal_np::number_of_iterations), o.iterations_per_level);
  o.gradient_tolerance = choose_parameter(get_parameter(np, internal_np::gradient_tolerance), o.gradient_tolerance);
  o.energy_tolerance = choose_parameter(get_parameter(np, internal_np::energy_tolerance), o.energy_tolerance);
  o.target = choose_parameter(get_parameter(np, internal_np::developability_target), o.target);
  o.stop_at_target = !std::is_same<std::decay_t<decltype(get_parameter(np, internal_np::developability_target))>,
                                   CGAL::internal_np::Param_not_found>::value;
  o.minimum_angle = choose_parameter(get_parameter(np, internal_np::minimum_angle), o.minimum_angle);
  o.omit_valence_three = choose_parameter(get_parameter(np, internal_np::omit_valence_three_vertices), true);
  o.include_boundary = choose_parameter(get_parameter(np, internal_np::include_boundary_vertices), false);
  o.parallel = choose_parameter(get_parameter(np, internal_np::parallel_evaluation), true);
  const Developability_descent d =
    choose_parameter(get_parameter(np, internal_np::descent_method), Developability_descent::lbfgs);

  switch(o.energy)
  {
    case Developability_energy::combinatorial: case Developability_energy::combinatorial_max:
    case Developability_energy::covariance: case Developability_energy::covariance_max:
    case Developability_energy::intrinsic: case Developability_energy::intrinsic_width:
    case Developability_energy::squared_angle_defect: case Developability_energy::absolute_angle_defect: break;
    default: throw Invalid_parameter("developability_energy", "not a Developability_energy enumerator");
  }
  if(d != Developability_descent::lbfgs && d != Developability_descent::gradient_descent)
    throw Invalid_parameter("descent_method", "not a Developability_descent enumerator");
  o.method = d == Developability_descent::lbfgs ? internal::Descent_method::lbfgs : internal::Descent_method::gradient_descent;
  if(o.subdivisions > 6)
    throw Invalid_parameter("number_of_subdivisions", "must be at most 6 (each multiplies the faces by 4), got " +
                                                        std::to_string(o.subdivisions));
  internal::require_nonnegative("gradient_tolerance", o.gradient_tolerance);
  internal::require_nonnegative("energy_tolerance", o.energy_tolerance);
  // lambda_i <= trace / 3 = (angle sum) / 3: 2 pi / 3 on an interior star
  internal::require_in_range("developability_target", o.target, 0., 2. * internal::pi / 3.);
  internal::require_in_range("minimum_angle", o.minimum_angle, 0., internal::pi / 6.);
  return o;
}

} // namespace internal

/// \ingroup PkgDevelopabilityRef
///
/// The developability energy of a triangle mesh: the sum over the vertex stars that carry energy
/// of the measure chosen by `developability_energy` (see `Developability_energy`), with, on
/// request, its value and its (sub)gradient per vertex.
///
/// \param tm a triangle mesh (validated)
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
///   \cgalParamNBegin{developability_energy}
///     \cgalParamDescription{the measure of non-developability of a vertex star (see
///                           `Developability_energy`)}
///     \cgalParamType{`Developability_energy`}
///     \cgalParamDefault{`Developability_energy::covariance` (E^lambda, eqs. 3-4)}
///     \cgalParamExtra{throws `Invalid_parameter` if it is not an enumerator of `Developability_energy`}
///   \cgalParamNEnd
///   \cgalParamNBegin{omit_valence_three_vertices}
///     \cgalParamDescription{`true`: the stars of valence less than 4 carry no energy (the paper omits its
///                           valence-3 vertices, the triple points of sec. 4.1.4)}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`true`}
///   \cgalParamNEnd
///   \cgalParamNBegin{include_boundary_vertices}
///     \cgalParamDescription{whether the stars of boundary vertices carry energy}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`false` (as the paper and its reference code)}
///   \cgalParamNEnd
///   \cgalParamNBegin{parallel_evaluation}
///     \cgalParamDescription{with TBB linked (`CGAL_LINKED_WITH_TBB`), the stars are evaluated in parallel,
///                           with results bitwise identical to the sequential ones}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`true`}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_energy_map}
///     \cgalParamDescription{output: the energy of each vertex's star (0 where it carries none)}
///     \cgalParamType{a class model of `WritablePropertyMap` with
///                    `boost::graph_traits<TriangleMesh>::%vertex_descriptor` as key type and `double` as
///                    value type}
///     \cgalParamDefault{not written}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_gradient_map}
///     \cgalParamDescription{output: the (sub)gradient of the total energy with respect to each vertex
///                           position}
///     \cgalParamType{a class model of `WritablePropertyMap` with
///                    `boost::graph_traits<TriangleMesh>::%vertex_descriptor` as key type and `%Vector_3` as
///                    value type}
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
/// The parameters of `make_piecewise_developable()` that this function does not use are checked all
/// the same: `number_of_subdivisions`, `gradient_tolerance`, `energy_tolerance`,
/// `developability_target`, `minimum_angle` or `descent_method` out of its range throws
/// `Invalid_parameter` here too.
///
/// \returns the total energy
/// \throws Invalid_mesh, Invalid_parameter; nothing is written then
///
/// Complexity: O(sum over stars of the star's cost): linear for the covariance energies, O(d^3)
/// per star of valence d for `combinatorial`, O(d^4) for `covariance_max`.
template <class TriangleMesh, class NamedParameters = CGAL::parameters::Default_named_parameters>
double developability_energy(const TriangleMesh& tm, const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  const internal::Developability_flow_options o = internal::developability_flow_options(np);
  const auto vpm = internal::const_vertex_point_map(tm, np);
  const internal::Mesh_indices<TriangleMesh> idx(tm, np);
  internal::validate_mesh(idx, vpm);
  const internal::Vertex_stars stars = internal::vertex_stars(idx, o.include_boundary, o.omit_valence_three ? 4 : 0);
  std::vector<Eigen::Vector3d> x = internal::vertex_positions(idx, vpm), gradient;
  std::vector<double> per_vertex;
  const double total = internal::developability_energy(stars, x, o.energy, &gradient, &per_vertex, o.parallel);
  internal::if_given(np, internal_np::vertex_energy_map, [&](const auto& map) {
    for(std::size_t v = 0; v < x.size(); ++v)
      put(map, idx.vertex(v), per_vertex[v]);
  });
  internal::if_given(np, internal_np::vertex_gradient_map, [&](const auto& map) {
    using Vector = typename boost::property_traits<std::decay_t<decltype(map)>>::value_type;
    for(std::size_t v = 0; v < x.size(); ++v)
      put(map, idx.vertex(v), Vector(gradient[v].x(), gradient[v].y(), gradient[v].z()));
  });
  return total;
}

/// \ingroup PkgDevelopabilityRef
///
/// Drives a triangle mesh towards a piecewise-developable shape (Stein, Grinspun & Crane 2018,
/// sec. 4): descends the chosen developability energy, with the vertex positions as unknowns,
/// removing small corner angles after every step, in levels separated by regular 4-1
/// subdivisions (sec. 4.2: start coarse, then refine to sharpen the seams). Curvature
/// concentrates on a sparse set of seam curves; elsewhere the vertex stars become hinges.
///
/// **A level** runs the descent until it has *converged*: every 50 iterations the flow counts the
/// measured vertices (interior, valence >= 4) whose covariance lambda_i (eq. 3, the measure of
/// `developability_metrics()`) exceeds the target (`developability_target`, by default the hinge
/// threshold 2 pi 1e-4), and the level has converged when, over the last 300 iterations, the
/// descent steps gained at most `energy_tolerance` of the energy (the jumps of flips and
/// collapses taken out) and that count fell by at most max(1, 0.5% of the measured vertices).
/// A level also ends when a target was given and every measured vertex is at most the target,
/// when the scaled gradient norm (RMS of the gradient's coordinates times the mean edge length,
/// dimensionless) is at most `gradient_tolerance`, when the line search failed twice in a row (at
/// a kink the descent cannot pass), or after `number_of_iterations` iterations (a safety cap;
/// `Developability_flow_result::converged` tells whether the last level stopped for a better
/// reason). Then the mesh is subdivided (if subdivisions remain) and the next level starts from
/// a reset optimizer.
///
/// **Small angles** (sec. 4.3, Fig. 18): after every step, a triangle with two corner angles
/// below `minimum_angle` has its longest edge flipped, a triangle with one has its shortest edge
/// collapsed (CGAL Euler operations; flips keep orientation, collapses respect the link
/// condition, keep boundary vertices and valences >= 3). The optimizer restarts after any change.
///
/// The mesh is modified in place: positions, and connectivity by subdivisions, flips and
/// collapses (a `Surface_mesh` has its garbage collected, so its indices are renumbered; property
/// maps of the input are not carried over to new elements). On an exception the mesh is untouched.
///
/// \param tm a triangle mesh, a model of `MutableFaceGraph` (validated: manifold, no degenerate
///        face, finite coordinates)
/// \param np an optional sequence of named parameters among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{a property map associating points to the vertices of `tm`: the positions are
///                           read from it and the new ones written to it}
///     \cgalParamType{a class model of `ReadWritePropertyMap` with
///                    `boost::graph_traits<TriangleMesh>::%vertex_descriptor` as key type and `%Point_3` as
///                    value type}
///     \cgalParamDefault{`boost::get(CGAL::vertex_point, tm)`}
///   \cgalParamNEnd
///   \cgalParamNBegin{developability_energy}
///     \cgalParamDescription{the measure of non-developability of a vertex star (see
///                           `Developability_energy`)}
///     \cgalParamType{`Developability_energy`}
///     \cgalParamDefault{`Developability_energy::covariance` (E^lambda, eqs. 3-4)}
///     \cgalParamExtra{throws `Invalid_parameter` if it is not an enumerator of `Developability_energy`}
///   \cgalParamNEnd
///   \cgalParamNBegin{number_of_subdivisions}
///     \cgalParamDescription{the number of regular 4-1 subdivisions, each after a level of descent}
///     \cgalParamType{`std::size_t`}
///     \cgalParamDefault{`0` (the paper uses 2 or 3 on a mesh of about 1k faces)}
///     \cgalParamExtra{throws `Invalid_parameter` if it is larger than 6 (each multiplies the faces by 4)}
///   \cgalParamNEnd
///   \cgalParamNBegin{number_of_iterations}
///     \cgalParamDescription{the largest number of descent iterations per level (a safety cap: levels end
///                           when they have converged)}
///     \cgalParamType{`std::size_t`}
///     \cgalParamDefault{`10000`}
///     \cgalParamExtra{not validated: 0 makes no iteration}
///   \cgalParamNEnd
///   \cgalParamNBegin{developability_target}
///     \cgalParamDescription{L: the lambda_i (covariance, eq. 3) at most which a vertex counts as developable.
///                           The convergence test counts the vertices above it; given, a level also ends as
///                           soon as every measured vertex is at most L (the vertices left above L at the end
///                           are the seams, which `compute_developable_cut()` with `cut_tolerance` L cuts)}
///     \cgalParamType{`double`}
///     \cgalParamDefault{2 pi 1e-4 (a hinge, as the metrics count them), without the early end}
///     \cgalParamExtra{throws `Invalid_parameter` if it is not in [0, 2 pi / 3] (lambda_i <= 2 pi / 3)}
///   \cgalParamNEnd
///   \cgalParamNBegin{gradient_tolerance}
///     \cgalParamDescription{a level ends when the scaled gradient norm (RMS of the gradient's coordinates
///                           times the mean edge length) is at most this}
///     \cgalParamType{`double`}
///     \cgalParamDefault{`1e-6`}
///     \cgalParamExtra{throws `Invalid_parameter` if it is negative or not finite}
///   \cgalParamNEnd
///   \cgalParamNBegin{energy_tolerance}
///     \cgalParamDescription{the convergence test: the largest relative gain of the descent steps over the last
///                           300 iterations (with the vertices above the target no longer falling); 0: only a
///                           descent that gained nothing at all has converged}
///     \cgalParamType{`double`}
///     \cgalParamDefault{`1e-2`}
///     \cgalParamExtra{throws `Invalid_parameter` if it is negative or not finite}
///   \cgalParamNEnd
///   \cgalParamNBegin{minimum_angle}
///     \cgalParamDescription{the corner angle, in radians, below which a triangle is treated by the
///                           small-angle handling (see **Small angles** above); 0 turns it off}
///     \cgalParamType{`double`}
///     \cgalParamDefault{`0.01` (the reference code's)}
///     \cgalParamExtra{throws `Invalid_parameter` if it is not in [0, pi/6]}
///   \cgalParamNEnd
///   \cgalParamNBegin{omit_valence_three_vertices}
///     \cgalParamDescription{`true`: the stars of valence less than 4 carry no energy (the paper omits its
///                           valence-3 vertices, the triple points of sec. 4.1.4)}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`true`}
///   \cgalParamNEnd
///   \cgalParamNBegin{include_boundary_vertices}
///     \cgalParamDescription{whether the stars of boundary vertices carry energy}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`false` (as the paper and its reference code)}
///   \cgalParamNEnd
///   \cgalParamNBegin{descent_method}
///     \cgalParamDescription{the descent method}
///     \cgalParamType{`Developability_descent`}
///     \cgalParamDefault{`Developability_descent::lbfgs`}
///     \cgalParamExtra{throws `Invalid_parameter` if it is not an enumerator of `Developability_descent`}
///   \cgalParamNEnd
///   \cgalParamNBegin{parallel_evaluation}
///     \cgalParamDescription{with TBB linked (`CGAL_LINKED_WITH_TBB`), the stars are evaluated in parallel,
///                           with results bitwise identical to the sequential ones}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`true`}
///   \cgalParamNEnd
///   \cgalParamNBegin{visitor}
///     \cgalParamDescription{a callable called after every iteration with its `Developability_iteration`;
///                           returning `false` stops the flow (the mesh keeps the current positions)}
///     \cgalParamType{a callable `bool(const Developability_iteration&)`}
///     \cgalParamDefault{none: the flow runs to its end}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_index_map}
///     \cgalParamDescription{a property map associating to each vertex of `tm` a unique index in
///                           `[0, num_vertices(tm))`: the numbering of the elements in the error messages of
///                           the validation of the input (the flow then numbers the mesh it modifies by the
///                           mesh's own maps)}
///     \cgalParamType{a class model of `ReadablePropertyMap` with
///                    `boost::graph_traits<TriangleMesh>::%vertex_descriptor` as key type and an integer as
///                    value type}
///     \cgalParamDefault{the mesh's own (`CGAL::get_initialized_vertex_index_map(tm)`)}
///     \cgalParamExtra{throws `Invalid_mesh` (`Mesh_defect::invalid_index_map`) if it is not a bijection onto
///                     `[0, num_vertices(tm))`}
///   \cgalParamNEnd
///   \cgalParamNBegin{halfedge_index_map}
///     \cgalParamDescription{a property map associating to each halfedge of `tm` a unique index in
///                           `[0, num_halfedges(tm))`: the numbering of the elements in the error messages of
///                           the validation of the input (the flow then numbers the mesh it modifies by the
///                           mesh's own maps)}
///     \cgalParamType{a class model of `ReadablePropertyMap` with
///                    `boost::graph_traits<TriangleMesh>::%halfedge_descriptor` as key type and an integer as
///                    value type}
///     \cgalParamDefault{the mesh's own (`CGAL::get_initialized_halfedge_index_map(tm)`)}
///     \cgalParamExtra{throws `Invalid_mesh` (`Mesh_defect::invalid_index_map`) if it is not a bijection onto
///                     `[0, num_halfedges(tm))`}
///   \cgalParamNEnd
///   \cgalParamNBegin{edge_index_map}
///     \cgalParamDescription{a property map associating to each edge of `tm` a unique index in
///                           `[0, num_edges(tm))`: the numbering of the elements in the error messages of the
///                           validation of the input (the flow then numbers the mesh it modifies by the
///                           mesh's own maps)}
///     \cgalParamType{a class model of `ReadablePropertyMap` with
///                    `boost::graph_traits<TriangleMesh>::%edge_descriptor` as key type and an integer as
///                    value type}
///     \cgalParamDefault{the order of `edges(tm)`}
///     \cgalParamExtra{throws `Invalid_mesh` (`Mesh_defect::invalid_index_map`) if it is not a bijection onto
///                     `[0, num_edges(tm))`}
///   \cgalParamNEnd
///   \cgalParamNBegin{face_index_map}
///     \cgalParamDescription{a property map associating to each face of `tm` a unique index in
///                           `[0, num_faces(tm))`: the numbering of the elements in the error messages of the
///                           validation of the input (the flow then numbers the mesh it modifies by the
///                           mesh's own maps)}
///     \cgalParamType{a class model of `ReadablePropertyMap` with
///                    `boost::graph_traits<TriangleMesh>::%face_descriptor` as key type and an integer as
///                    value type}
///     \cgalParamDefault{the mesh's own (`CGAL::get_initialized_face_index_map(tm)`)}
///     \cgalParamExtra{throws `Invalid_mesh` (`Mesh_defect::invalid_index_map`) if it is not a bijection onto
///                     `[0, num_faces(tm))`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \returns per level: iterations, energies, why it ended; in total: iterations, evaluations,
///          flips, collapses, subdivisions, and seconds per phase
/// \throws Invalid_mesh, Invalid_parameter (before anything is modified)
template <class TriangleMesh, class NamedParameters = CGAL::parameters::Default_named_parameters>
Developability_flow_result make_piecewise_developable(TriangleMesh& tm,
                                                      const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  using Vpm = internal::Vertex_point_map_t<TriangleMesh, NamedParameters>;
  const Vpm vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                   get_property_map(CGAL::vertex_point, tm));
  const internal::Developability_flow_options o = internal::developability_flow_options(np);
  {
    const internal::Mesh_indices<TriangleMesh> idx(tm, np);
    internal::validate_mesh(idx, vpm);
  }
  auto visitor = [&np](const Developability_iteration& it) {
    bool go_on = true;
    internal::if_given(np, CGAL::internal_np::visitor, [&](const auto& v) { go_on = bool(v(it)); });
    return go_on;
  };

  Developability_flow_result result;
  const internal::Phase_clock total;
  internal::Developability_state<TriangleMesh, Vpm> state(tm, vpm, o);
  internal::Lbfgs_options lo;
  lo.method = o.method;
  lo.unit_first_trial = true; // try the quasi-Newton step first: about half the evaluations
  for(std::size_t level = 0; level <= o.subdivisions && !result.stopped_by_visitor; ++level)
  {
    if(level > 0)
    {
      const internal::Phase_clock clock;
      internal::midpoint_subdivision(tm, vpm);
      state.rebuild();
      ++result.subdivisions;
      result.subdivision_seconds += clock.seconds();
    }
    internal::Lbfgs_minimizer minimizer(lo);
    Developability_flow_result::Level report;
    // Progress is measured by what the descent steps gained: a flip or a collapse changes the
    // energy too (up or down); those jumps are summed apart and taken out.
    struct Sample
    {
      std::size_t iteration;
      double energy, jumps;
      std::size_t above;
    };
    std::vector<Sample> samples; // every check_interval iterations
    double jumps = 0., last_energy = 0.;
    std::size_t failures_in_a_row = 0;
    report.end = to_string(internal::Developability_level_end::iteration_limit);
    for(std::size_t it = 0; it < o.iterations_per_level; ++it)
    {
      const internal::Phase_clock clock;
      const internal::Lbfgs_step_result s = minimizer.step(state, state.coordinates());
      result.evaluation_seconds += clock.seconds();
      if(it == 0)
        report.initial_energy = s.energy_before;
      else
        jumps += s.energy_before - last_energy; // nonzero only after a flip or collapse
      const bool accepted = s.status == internal::Lbfgs_step_status::accepted;
      failures_in_a_row = accepted ? 0 : failures_in_a_row + 1;

      Developability_iteration info;
      info.level = level;
      info.iteration = ++result.iterations;
      info.level_iteration = ++report.iterations;
      info.energy = accepted ? s.energy : s.energy_before;
      info.gradient_norm = minimizer.gradient_norm() * state.mean_edge_length();
      info.step = accepted ? s.step_length : 0.;
      info.line_search_failed = !accepted;

      if(accepted)
      {
        state.write_positions();
        if(o.minimum_angle > 0.)
        {
          const internal::Phase_clock remesh;
          const internal::Small_angle_report r = internal::remove_small_angles(tm, vpm, o.minimum_angle);
          if(r.flips + r.collapses > 0)
          {
            state.rebuild();
            minimizer.reset();
            info.flips = r.flips;
            info.collapses = r.collapses;
            result.flips += r.flips;
            result.collapses += r.collapses;
          }
          result.remeshing_seconds += remesh.seconds();
        }
      }
      info.vertices = num_vertices(tm);
      info.faces = num_faces(tm);
      report.final_energy = last_energy = info.energy;
      report.final_gradient_norm = info.gradient_norm;

      if(!visitor(info))
      {
        result.stopped_by_visitor = true;
        report.end = to_string(internal::Developability_level_end::visitor);
        break;
      }
      // a zero gradient (the minimizer reports a stationary point) or one below the tolerance,
      // whether or not a step was taken: nothing is left to descend
      if(s.status == internal::Lbfgs_step_status::stationary || info.gradient_norm <= o.gradient_tolerance)
      {
        report.end = to_string(internal::Developability_level_end::gradient_small);
        break;
      }
      if(failures_in_a_row >= 2) // the failed step reset the optimizer; its retry failed too
      {
        report.end = to_string(internal::Developability_level_end::line_search_failed);
        break;
      }
      if(report.iterations % o.check_interval == 0)
      {
        const auto [measured, above] = state.count_above(o.target);
        if(above == 0 && o.stop_at_target)
        {
          report.end = to_string(internal::Developability_level_end::target_reached);
          break;
        }
        samples.push_back({report.iterations, info.energy, jumps, above});
        // the latest sample at least a window ago
        auto old = std::find_if(samples.rbegin(), samples.rend(), [&](const Sample& x) {
          return x.iteration + o.convergence_window <= report.iterations;
        });
        if(old != samples.rend())
        {
          const double before = old->energy, now = info.energy, descent = before - now + (jumps - old->jumps);
          const double count_slack = (std::max)(1., o.count_tolerance * double(measured));
          if(descent <= o.energy_tolerance * (std::max)(std::abs(before), std::abs(now)) &&
             double(old->above) - double(above) <= count_slack)
          {
            report.end = to_string(internal::Developability_level_end::converged);
            break;
          }
        }
      }
    }
    report.vertices = num_vertices(tm);
    report.faces = num_faces(tm);
    std::tie(report.measured_vertices, report.vertices_above_target) = state.count_above(o.target);
    result.levels.push_back(report);
  }
  if(!result.levels.empty())
  {
    const std::string& end = result.levels.back().end;
    result.converged = end == to_string(internal::Developability_level_end::converged) ||
                       end == to_string(internal::Developability_level_end::target_reached) ||
                       end == to_string(internal::Developability_level_end::gradient_small);
  }
  result.evaluations = state.evaluations();
  result.total_seconds = total.seconds();
  return result;
}

/// \ingroup PkgDevelopabilityRef
/// The figures of a (piecewise-)developable design, as the field reports them (Stein et al. 2018;
/// Binninger et al. 2021), so that runs and methods can be compared. The per-vertex measure is
/// the covariance lambda_i (eq. 3) whatever energy was optimized; it equals 0 on hinges and flat
/// stars and is at most 2 pi / 3 (lambda_i <= trace / 3 = sum of the angles / 3).
/// *Measured* vertices are the interior vertices of valence >= 4 (those the energies act on).
struct Developability_metrics
{
  std::size_t vertices = 0, faces = 0, measured_vertices = 0;
  double energy = 0.;          ///< total of the energy named by `developability_energy` (default covariance)
  double lambda_max = 0., lambda_mean = 0., lambda_p95 = 0.; ///< lambda_i over the measured vertices
  /// share of the measured vertices that are hinges: lambda_i < 2 pi 1e-4 (1e-3)
  double hinge_share_1e4 = 0., hinge_share_1e3 = 0.;
  double angle_defect_max = 0., angle_defect_mean = 0.; ///< |Omega_i| over the interior vertices (radians)
  /// Seam vertices: the interior vertices that are not hinges, lambda_i >= 2 pi 1e-4 (valence 3
  /// included: triple points and cone points). Every measured vertex is a hinge or on a seam.
  /// The share of sum |Omega_i| (interior vertices) that the seam vertices carry: 1 when all the
  /// curvature sits on seams, about their share of the vertices when it is spread evenly. (The
  /// hinge threshold, not a larger one: on a refined mesh the stars along a curved seam bend
  /// less and less, and a larger threshold would lose the seams after subdivisions.)
  double seam_curvature_share = 0.;
  std::size_t seam_vertices = 0;
  /// Seam edges join two seam vertices; seam curves are the connected components of those edges.
  std::size_t seam_curves = 0;
  double seam_length = 0.;     ///< total length of the seam edges
  double minimum_angle = 0.;   ///< smallest corner angle, radians
  /// With a reference mesh: symmetric Hausdorff and mean distance between the two surfaces
  /// (sampled), divided by the reference's bounding-box diagonal; NaN without one.
  double hausdorff_distance = std::numeric_limits<double>::quiet_NaN();
  double mean_distance = std::numeric_limits<double>::quiet_NaN();
};

/// \ingroup PkgDevelopabilityRef
///
/// The metrics of a design (see `Developability_metrics`).
/// \param np an optional sequence of named parameters: exactly those of `developability_energy()`,
///        with the same types, defaults and checks. `energy` is `developability_energy(tm, np)`, so
///        `vertex_energy_map` and `vertex_gradient_map` are written if given; the point map, the
///        index maps and `parallel_evaluation` serve the other measures too, while
///        `developability_energy`, `omit_valence_three_vertices` and `include_boundary_vertices`
///        change only `energy`
/// \throws Invalid_mesh, Invalid_parameter
/// Complexity: linear in the mesh size (plus the star costs of the chosen energy).
template <class TriangleMesh, class NamedParameters = CGAL::parameters::Default_named_parameters>
Developability_metrics developability_metrics(const TriangleMesh& tm,
                                              const NamedParameters& np = CGAL::parameters::default_values())
{
  const internal::Developability_flow_options o = internal::developability_flow_options(np);
  Developability_metrics m;
  internal::measure_developability(m, tm, internal::const_vertex_point_map(tm, np), static_cast<const TriangleMesh*>(nullptr),
                                   np, o.parallel);
  m.energy = developability_energy(tm, np);
  return m;
}

/// \ingroup PkgDevelopabilityRef
/// Same, with the distances to `reference` (e.g. the input of the flow), relative to the
/// reference's bounding-box diagonal. `tm` is read through the point map of `np`, `reference`
/// through its own `CGAL::vertex_point` map.
/// \param np an optional sequence of named parameters: exactly those of `developability_energy()`,
///        as the overload without `reference`
template <class TriangleMesh, class NamedParameters = CGAL::parameters::Default_named_parameters>
Developability_metrics developability_metrics(const TriangleMesh& tm, const TriangleMesh& reference,
                                              const NamedParameters& np = CGAL::parameters::default_values())
{
  const internal::Developability_flow_options o = internal::developability_flow_options(np);
  Developability_metrics m;
  internal::measure_developability(m, tm, internal::const_vertex_point_map(tm, np), &reference, np, o.parallel);
  m.energy = developability_energy(tm, np);
  return m;
}

} // namespace Surface_design
} // namespace CGAL

#endif // CGAL_SURFACE_DESIGN_DEVELOPABILITY_H
