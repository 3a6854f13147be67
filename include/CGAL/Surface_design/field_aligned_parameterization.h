// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// One-call field-aligned parameterization, and singularity detection.

#ifndef CGAL_SURFACE_DESIGN_FIELD_ALIGNED_PARAMETERIZATION_H
#define CGAL_SURFACE_DESIGN_FIELD_ALIGNED_PARAMETERIZATION_H

#include <CGAL/Surface_design/Field_aligned_parameterizer.h>
#include <CGAL/Surface_design/internal/Core/angles.h>
#include <CGAL/Surface_design/internal/Core/Mesh_indices.h>
#include <CGAL/Surface_design/internal/Core/named_parameters.h>
#include <CGAL/Surface_design/parameters.h>

#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Named_function_parameters.h>

#include <cmath>
#include <map>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Surface_design {


/// \ingroup PkgFieldAlignedParameterizationRef
///
/// Computes a stripe function alpha (per vertex, in [-pi, pi)) whose differential follows the
/// vector field `field`, with a singularity of index `get(face_indices, f)` in every face `f`
/// where that is non-zero, and nowhere else. See `Field_aligned_parameterizer` for the
/// formulation; this function builds one, solves once and writes the outputs. The mesh is never
/// modified; on any exception no output map is written.
///
/// \param tm a triangle mesh (any number of connected components, with or without boundary)
/// \param field a readable vertex -> `Vector_3` map (projected to the tangent planes)
/// \param face_indices a readable face -> integer map; 0 in every face with an edge on the
///        boundary (such a face cannot hold a singularity: see `Field_aligned_parameterizer`)
/// \param alpha a writable vertex -> double map (output)
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
///     \cgalParamDescription{the sparse solver that factors the weighted Laplacian with one vertex pinned per
///                           connected component}
///     \cgalParamType{a class model of `SparseLinearAlgebraWithFactorTraits_d`}
///     \cgalParamDefault{`Default_solver_traits` (`Size_switched_cholesky`: the simplicial LDLT below 20000
///                       unknowns, the supernodal Cholesky from there)}
///   \cgalParamNEnd
///   \cgalParamNBegin{weighting}
///     \cgalParamDescription{the edge weights w_e of the least-squares energy}
///     \cgalParamType{`Edge_weighting`: `cotangent` or `uniform`}
///     \cgalParamDefault{`Edge_weighting::cotangent` (the paper's)}
///     \cgalParamExtra{throws `Invalid_parameter` for any other value (`mean_value`: the energy needs
///                     symmetric weights)}
///   \cgalParamNEnd
///   \cgalParamNBegin{stripes_per_unit_length}
///     \cgalParamDescription{when positive, the field is normalized and alpha advances by 2 pi times this per
///                           unit length along it; 0: the field is used as given (alpha advances by |X|
///                           radians per unit length)}
///     \cgalParamType{`double`}
///     \cgalParamDefault{`0`}
///     \cgalParamExtra{throws `Invalid_parameter` if it is negative or not finite, or, when it is positive,
///                     if the field has no tangential component at any vertex of a connected component}
///   \cgalParamNEnd
///   \cgalParamNBegin{one_form_convention}
///     \cgalParamDescription{how the target 1-form omega is computed from the field}
///     \cgalParamType{`One_form_convention`}
///     \cgalParamDefault{`One_form_convention::projected`}
///     \cgalParamExtra{throws `Invalid_parameter` for a value other than the two enumerators}
///   \cgalParamNEnd
///   \cgalParamNBegin{loop_windings}
///     \cgalParamDescription{the windings of the listed loops, loop number -> winding (the integral of dalpha
///                           along the loop is 2 pi times the winding); loops are numbered generators first,
///                           then boundary loops (`Field_aligned_parameterizer::loop()`); the loops not
///                           listed are automatic}
///     \cgalParamType{`std::map<std::size_t, int>`, or any range of (loop number, winding) pairs}
///     \cgalParamDefault{every winding automatic}
///     \cgalParamExtra{throws `Invalid_constraints` if a loop number does not exist}
///   \cgalParamNEnd
///   \cgalParamNBegin{edge_dalpha_map}
///     \cgalParamDescription{output: dalpha along `halfedge(e, tm)` for every edge `e`, unwrapped}
///     \cgalParamType{a class model of `WritablePropertyMap` with
///                    `boost::graph_traits<TriangleMesh>::%edge_descriptor` as key type and `double` as value
///                    type}
///     \cgalParamDefault{not written}
///     \cgalParamExtra{written only if the whole computation succeeds}
///   \cgalParamNEnd
///   \cgalParamNBegin{edge_omega_map}
///     \cgalParamDescription{output: the target 1-form omega along `halfedge(e, tm)` for every edge `e`}
///     \cgalParamType{a class model of `WritablePropertyMap` with
///                    `boost::graph_traits<TriangleMesh>::%edge_descriptor` as key type and `double` as value
///                    type}
///     \cgalParamDefault{not written}
///     \cgalParamExtra{written only if the whole computation succeeds}
///   \cgalParamNEnd
///   \cgalParamNBegin{corner_coordinate_map}
///     \cgalParamDescription{output: for every halfedge `h` that is not a border halfedge, the coordinate u
///                           at the corner of `face(h, tm)` at `target(h, tm)` (see
///                           `Field_aligned_parameterizer::corner_coordinates()`); border halfedges are not
///                           written}
///     \cgalParamType{a class model of `WritablePropertyMap` with
///                    `boost::graph_traits<TriangleMesh>::%halfedge_descriptor` as key type and `double` as
///                    value type}
///     \cgalParamDefault{not written}
///     \cgalParamExtra{written only if the whole computation succeeds}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_index_map}
///     \cgalParamDescription{a property map associating to each vertex of `tm` a unique index in
///                           `[0, num_vertices(tm))`: the numbering of the elements (faces addressed by
///                           index, loops, error messages)}
///     \cgalParamType{a class model of `ReadablePropertyMap` with
///                    `boost::graph_traits<TriangleMesh>::%vertex_descriptor` as key type and an integer as
///                    value type}
///     \cgalParamDefault{the mesh's own (`CGAL::get_initialized_vertex_index_map(tm)`)}
///     \cgalParamExtra{throws `Invalid_mesh` (`Mesh_defect::invalid_index_map`) if it is not a bijection onto
///                     `[0, num_vertices(tm))`}
///   \cgalParamNEnd
///   \cgalParamNBegin{halfedge_index_map}
///     \cgalParamDescription{a property map associating to each halfedge of `tm` a unique index in
///                           `[0, num_halfedges(tm))`: the numbering of the elements (faces addressed by
///                           index, loops, error messages)}
///     \cgalParamType{a class model of `ReadablePropertyMap` with
///                    `boost::graph_traits<TriangleMesh>::%halfedge_descriptor` as key type and an integer as
///                    value type}
///     \cgalParamDefault{the mesh's own (`CGAL::get_initialized_halfedge_index_map(tm)`)}
///     \cgalParamExtra{throws `Invalid_mesh` (`Mesh_defect::invalid_index_map`) if it is not a bijection onto
///                     `[0, num_halfedges(tm))`}
///   \cgalParamNEnd
///   \cgalParamNBegin{edge_index_map}
///     \cgalParamDescription{a property map associating to each edge of `tm` a unique index in
///                           `[0, num_edges(tm))`: the numbering of the elements (faces addressed by index,
///                           loops, error messages)}
///     \cgalParamType{a class model of `ReadablePropertyMap` with
///                    `boost::graph_traits<TriangleMesh>::%edge_descriptor` as key type and an integer as
///                    value type}
///     \cgalParamDefault{the order of `edges(tm)`}
///     \cgalParamExtra{throws `Invalid_mesh` (`Mesh_defect::invalid_index_map`) if it is not a bijection onto
///                     `[0, num_edges(tm))`}
///   \cgalParamNEnd
///   \cgalParamNBegin{face_index_map}
///     \cgalParamDescription{a property map associating to each face of `tm` a unique index in
///                           `[0, num_faces(tm))`: the numbering of the elements (faces addressed by index,
///                           loops, error messages)}
///     \cgalParamType{a class model of `ReadablePropertyMap` with
///                    `boost::graph_traits<TriangleMesh>::%face_descriptor` as key type and an integer as
///                    value type}
///     \cgalParamDefault{the mesh's own (`CGAL::get_initialized_face_index_map(tm)`)}
///     \cgalParamExtra{throws `Invalid_mesh` (`Mesh_defect::invalid_index_map`) if it is not a bijection onto
///                     `[0, num_faces(tm))`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \returns the energy sum_e w_e (dalpha_e - omega_e)^2 of the result
/// \throws Invalid_mesh, Invalid_parameter, Invalid_constraints, Linear_solver_failure (see
///         `Field_aligned_parameterizer`); nothing is written then
///
/// Complexity: one sparse factorization of size |V| and O(|E|) work.
template <class TriangleMesh, class VertexVectorMap, class FaceIndexMap, class VertexScalarMap,
          class NamedParameters = CGAL::parameters::Default_named_parameters>
double field_aligned_parameterization(const TriangleMesh& tm, const VertexVectorMap& field,
                                      const FaceIndexMap& face_indices, VertexScalarMap alpha,
                                      const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  const double stripes = choose_parameter(get_parameter(np, internal_np::stripes_per_unit_length), 0.);
  const One_form_convention convention =
    choose_parameter(get_parameter(np, internal_np::one_form_convention), One_form_convention::projected);

  Field_aligned_parameterizer<TriangleMesh, internal::Const_vertex_point_map_t<TriangleMesh, NamedParameters>,
                              internal::Solver_traits_t<NamedParameters>>
    fap(tm, np);
  fap.set_field(field, stripes, convention);
  fap.set_indices(face_indices);
  internal::if_given(
    np, internal_np::loop_windings, [&](const auto& windings) {
      for(const auto& [loop, winding] : windings)
        fap.set_loop_winding(loop, winding);
    });
  fap.solve();

  // outputs, written only after everything succeeded
  fap.alpha(alpha);
  internal::if_given(
    np, internal_np::edge_dalpha_map, [&](const auto& map) { fap.dalpha(map); });
  internal::if_given(
    np, internal_np::edge_omega_map, [&](const auto& map) {
      for(auto e : edges(tm))
        put(map, e, fap.omega(halfedge(e, tm)));
    });
  internal::if_given(
    np, internal_np::corner_coordinate_map, [&](const auto& map) { fap.corner_coordinates(map); });
  return fap.energy();
}

/// \ingroup PkgFieldAlignedParameterizationRef
/// Detects the singularities of a stripe function: for every face, the winding number of alpha
/// around it, (1 / 2 pi) times the sum over its edges of the difference of alpha wrapped to
/// [-pi, pi), written to `face_indices` (face -> int). This recovers the prescribed indices
/// wherever the mesh resolves the stripes (|dalpha| < pi on the face's edges). Since each wrapped
/// difference lies in [-pi, pi), a triangle can show at most |index| 1: a singularity of index
/// 2 or more appears spread over neighbouring faces (dalpha itself carries it exactly).
/// \returns the number of faces with a non-zero index
template <class PolygonMesh, class VertexScalarMap, class FaceIndexMap>
std::size_t stripe_singularities(const PolygonMesh& tm, const VertexScalarMap& alpha,
                                 FaceIndexMap face_indices)
{
  std::size_t count = 0;
  for(auto f : faces(tm))
  {
    double sum = 0.;
    for(auto h : halfedges_around_face(halfedge(f, tm), tm))
      sum += internal::wrap_angle(double(get(alpha, target(h, tm))) - double(get(alpha, source(h, tm))));
    const int k = int(std::lround(sum / internal::two_pi));
    put(face_indices, f, k);
    count += (k != 0);
  }
  return count;
}

/// \ingroup PkgFieldAlignedParameterizationRef
/// The singularities a 1-form asks for: for every face, the nearest integer to
/// (1 / 2 pi) times the integral of the form around the face (its discrete curl), written to
/// `face_indices`. `one_form` maps each edge `e` to the form's value along `halfedge(e, tm)`.
/// For the target form of a smooth field this is 0 almost everywhere; a vortex of the field
/// concentrated in a face shows as a non-zero index there.
/// \returns the number of faces with a non-zero index
template <class PolygonMesh, class EdgeScalarMap, class FaceIndexMap>
std::size_t one_form_singularities(const PolygonMesh& tm, const EdgeScalarMap& one_form,
                                   FaceIndexMap face_indices)
{
  // Accumulate edge by edge: the orientation of an edge must come from edges(tm), because on a
  // Surface_mesh and a Polyhedron_3 alike halfedge(edge(h, tm), tm) is h itself, whichever side
  // of the edge h is on.
  internal::Mesh_indices<PolygonMesh> idx(tm);
  std::vector<double> curl(idx.number_of_faces(), 0.);
  for(auto e : edges(tm))
  {
    const auto h = halfedge(e, tm);
    const double value = double(get(one_form, e));
    if(!is_border(h, tm))
      curl[idx.index(face(h, tm))] += value;
    if(!is_border(opposite(h, tm), tm))
      curl[idx.index(face(opposite(h, tm), tm))] -= value;
  }
  std::size_t count = 0;
  for(std::size_t f = 0; f < curl.size(); ++f)
  {
    const int k = int(std::lround(curl[f] / internal::two_pi));
    put(face_indices, idx.face(f), k);
    count += (k != 0);
  }
  return count;
}

} // namespace Surface_design
} // namespace CGAL

#endif // CGAL_SURFACE_DESIGN_FIELD_ALIGNED_PARAMETERIZATION_H
