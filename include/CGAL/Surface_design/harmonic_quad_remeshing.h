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
/// \param np an optional sequence of named parameters among the ones listed below: those of the
///        `Harmonic_quad_remesher` constructor and of its `remesh()`, but the point map of `out`,
///        which is its internal one
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
///     \cgalParamDescription{the sparse solver that factors the Laplacian (of `harmonic_weights`) restricted
///                           to the unconstrained vertices (the Laplacians of the mesh refined along
///                           spectacles and of the intrinsic Delaunay fall-back of `remesh()` are factored by
///                           new objects of the same type)}
///     \cgalParamType{a class model of `SparseLinearAlgebraWithFactorTraits_d`}
///     \cgalParamDefault{`Default_solver_traits` (`Size_switched_cholesky`: the simplicial LDLT below 20000
///                       unknowns, the supernodal Cholesky from there)}
///   \cgalParamNEnd
///   \cgalParamNBegin{harmonic_weights}
///     \cgalParamDescription{the weights of the Laplacian whose harmonic function drives the remeshing}
///     \cgalParamType{`Harmonic_weights`}
///     \cgalParamDefault{`Harmonic_weights::cotangent`}
///     \cgalParamExtra{throws `Invalid_parameter` for a value other than the two enumerators}
///   \cgalParamNEnd
///   \cgalParamNBegin{harmonic_constraints}
///     \cgalParamDescription{the constrained vertices and their values, u(c) = value (see
///                           `set_constraints()`)}
///     \cgalParamType{a range of (`vertex_descriptor`, value convertible to `double`) pairs}
///     \cgalParamDefault{the default constraints (`set_default_constraints()`)}
///     \cgalParamExtra{throws `Invalid_constraints` if a vertex is not a vertex of `tm` or is constrained
///                     twice, if a value is not finite, or if a connected component does not get at least two
///                     different values}
///   \cgalParamNEnd
///   \cgalParamNBegin{protrusion_maxima}
///     \cgalParamDescription{with the default constraints, whether there is also a maximum at every tip of
///                           the shape (see `set_default_constraints()`)}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`true`}
///     \cgalParamExtra{ignored when `harmonic_constraints` is given}
///   \cgalParamNEnd
///   \cgalParamNBegin{target_edge_length}
///     \cgalParamDescription{the spacing h of both families of curves}
///     \cgalParamType{`double`}
///     \cgalParamDefault{sqrt(area / 3000), with the area of `tm`: about 3000 faces}
///     \cgalParamExtra{throws `Invalid_parameter` if it is not finite and positive, or if area / h^2 > 1e7
///                     (about 10 million faces)}
///   \cgalParamNEnd
///   \cgalParamNBegin{quad_poles}
///     \cgalParamDescription{fans of quads at the extrema (every other line ends there); `false`: fans of
///                           triangles}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`true`}
///   \cgalParamNEnd
///   \cgalParamNBegin{spectacles}
///     \cgalParamDescription{Nagano & Imai's spectacles around every simple interior saddle (two gradient
///                           lines from the saddle down, or up, to the next level of the net and the isolines
///                           where they end), inserted into a copy of the mesh, held at one value while the
///                           function is re-solved, and built into the net as one isoline graph (lines leave
///                           the bridge on both sides and each junction along the bisectors of its two
///                           corners). Saddles whose spectacles cannot be built (on the boundary, of
///                           multiplicity > 1, both wedges reaching one isoline, crossing other spectacles)
///                           are listed in `skipped_saddles` with the reason; when the net with spectacles is
///                           not a valid polygon mesh with the input's topology, the net is built without
///                           them and all are listed there}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`true`}
///   \cgalParamNEnd
///   \cgalParamNBegin{all_quads}
///     \cgalParamDescription{quads only. The net's faces with an odd number of sides (the pentagons where a
///                           line ends on an isoline, triangles) are paired by short, straight paths across
///                           the net (or led to the boundary); every edge a path crosses gets a vertex at its
///                           middle and every face is split into quads by the diagonals that keep its corners
///                           closest to 90 degrees. A path continues the line that ended at a T-junction
///                           until it meets another one, so T-junctions become regular vertices. `false`: the
///                           quad-dominant net as it is}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`true`}
///   \cgalParamNEnd
///   \cgalParamNBegin{curvature_adaptation}
///     \cgalParamDescription{curvature-adapted spacing a: the spacing of both families of curves becomes h /
///                           (1 + a h kappa), at least h / 4, with kappa the (smoothed) normal curvature
///                           across the input's edges: finer where the surface bends. 0: uniform spacing h}
///     \cgalParamType{`double`}
///     \cgalParamDefault{`0`}
///     \cgalParamExtra{throws `Invalid_parameter` if it is negative or not finite}
///   \cgalParamNEnd
///   \cgalParamNBegin{feature_snapping}
///     \cgalParamDescription{the curves pass over features narrower than their spacing (a pit, a spike, the
///                           apex of a cone, a sharp crease). Interior input vertices farther than h / 4 from
///                           the result, farthest first, pull the nearest corner of the face closest to them
///                           onto them (a corner not on the boundary, at most 2h away, no face around it
///                           turned over or moved before). The boundary needs no snapping: where the input's
///                           boundary leaves the chord between two vertices of the net by more than h / 4 (a
///                           serrated or sharply bent boundary), its vertices become vertices of the net (an
///                           even number per edge, see `boundary_detail_vertices`)}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`true`}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_index_map}
///     \cgalParamDescription{a property map associating to each vertex of `tm` a unique index in
///                           `[0, num_vertices(tm))`: the numbering of the elements (vertex indices in the
///                           results and in error messages)}
///     \cgalParamType{a class model of `ReadablePropertyMap` with
///                    `boost::graph_traits<TriangleMesh>::%vertex_descriptor` as key type and an integer as
///                    value type}
///     \cgalParamDefault{the mesh's own (`CGAL::get_initialized_vertex_index_map(tm)`)}
///     \cgalParamExtra{throws `Invalid_mesh` (`Mesh_defect::invalid_index_map`) if it is not a bijection onto
///                     `[0, num_vertices(tm))`}
///   \cgalParamNEnd
///   \cgalParamNBegin{halfedge_index_map}
///     \cgalParamDescription{a property map associating to each halfedge of `tm` a unique index in
///                           `[0, num_halfedges(tm))`: the numbering of the elements (vertex indices in the
///                           results and in error messages)}
///     \cgalParamType{a class model of `ReadablePropertyMap` with
///                    `boost::graph_traits<TriangleMesh>::%halfedge_descriptor` as key type and an integer as
///                    value type}
///     \cgalParamDefault{the mesh's own (`CGAL::get_initialized_halfedge_index_map(tm)`)}
///     \cgalParamExtra{throws `Invalid_mesh` (`Mesh_defect::invalid_index_map`) if it is not a bijection onto
///                     `[0, num_halfedges(tm))`}
///   \cgalParamNEnd
///   \cgalParamNBegin{edge_index_map}
///     \cgalParamDescription{a property map associating to each edge of `tm` a unique index in
///                           `[0, num_edges(tm))`: the numbering of the elements (vertex indices in the
///                           results and in error messages)}
///     \cgalParamType{a class model of `ReadablePropertyMap` with
///                    `boost::graph_traits<TriangleMesh>::%edge_descriptor` as key type and an integer as
///                    value type}
///     \cgalParamDefault{the order of `edges(tm)`}
///     \cgalParamExtra{throws `Invalid_mesh` (`Mesh_defect::invalid_index_map`) if it is not a bijection onto
///                     `[0, num_edges(tm))`}
///   \cgalParamNEnd
///   \cgalParamNBegin{face_index_map}
///     \cgalParamDescription{a property map associating to each face of `tm` a unique index in
///                           `[0, num_faces(tm))`: the numbering of the elements (vertex indices in the
///                           results and in error messages)}
///     \cgalParamType{a class model of `ReadablePropertyMap` with
///                    `boost::graph_traits<TriangleMesh>::%face_descriptor` as key type and an integer as
///                    value type}
///     \cgalParamDefault{the mesh's own (`CGAL::get_initialized_face_index_map(tm)`)}
///     \cgalParamExtra{throws `Invalid_mesh` (`Mesh_defect::invalid_index_map`) if it is not a bijection onto
///                     `[0, num_faces(tm))`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \returns the report of `remesh()`; `report.harmonic_seconds` includes building the Laplacian
/// \throws Invalid_mesh, Invalid_constraints, Invalid_parameter, Linear_solver_failure,
///         Remeshing_failure (no net with the input's topology, see `Harmonic_quad_remesher::remesh()`);
///         `out` is not modified then
template <class TriangleMesh, class PolygonMesh, class NamedParameters = CGAL::parameters::Default_named_parameters>
Harmonic_quad_remeshing_result harmonic_quad_remeshing(const TriangleMesh& tm, PolygonMesh& out,
                                                       const NamedParameters& np = CGAL::parameters::default_values())
{
  Harmonic_quad_remesher<TriangleMesh, internal::Const_vertex_point_map_t<TriangleMesh, NamedParameters>,
                         internal::Solver_traits_t<NamedParameters>>
    remesher(tm, np);
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
