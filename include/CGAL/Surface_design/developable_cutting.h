// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Cutting a (piecewise-)developable design into disks that flatten with little distortion
// (Stein, Grinspun & Crane 2018, sec. 4.4), and cutting any triangle mesh along edges.

#ifndef CGAL_SURFACE_DESIGN_DEVELOPABLE_CUTTING_H
#define CGAL_SURFACE_DESIGN_DEVELOPABLE_CUTTING_H

#include <CGAL/Surface_design/exceptions.h>
#include <CGAL/Surface_design/internal/Core/Mesh_indices.h>
#include <CGAL/Surface_design/internal/Core/cut_mesh.h>
#include <CGAL/Surface_design/internal/Core/named_parameters.h>
#include <CGAL/Surface_design/internal/Core/validation.h>
#include <CGAL/Surface_design/internal/Developability/crack_gluing.h>
#include <CGAL/Surface_design/internal/Developability/cut_graph.h>
#include <CGAL/Surface_design/parameters.h>

#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Named_function_parameters.h>

#include <array>
#include <cstddef>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_design {

namespace internal {

// Writes the edges flagged in `edge_is_cut` to `out` and adds their number and total length.
template <class Indices, class VertexPointMap, class EdgeOutputIterator>
void write_cut(const Indices& idx, const VertexPointMap& vpm, const std::vector<bool>& edge_is_cut,
               EdgeOutputIterator out, std::size_t& count, double& length)
{
  for(std::size_t e = 0; e < idx.number_of_edges(); ++e)
    if(edge_is_cut[e])
    {
      ++count;
      const auto ab = idx.edge_vertices(e);
      length += (position(vpm, idx.vertex(ab.first)) - position(vpm, idx.vertex(ab.second))).norm();
      *out++ = idx.edge(e);
    }
}

} // namespace internal

/// \ingroup PkgDevelopabilityRef
/// What `compute_developable_cut()` found.
struct Developable_cut_result
{
  std::size_t terminals = 0;       ///< interior vertices with lambda_i > epsilon, and the `distortion_terminals`
  std::size_t boundary_loops = 0;  ///< boundary loops of the input (each joined to the cut)
  std::size_t generator_loops = 0; ///< loops added because of genus (2g per component of genus g)
  std::size_t cut_edges = 0;       ///< edges of the cut
  double cut_length = 0.;          ///< total length of the cut edges
  std::size_t pieces = 0;          ///< disks the cut leaves
  double lambda_max = 0.;          ///< largest lambda_i over the interior vertices
  /// With `distortion_bound`: the terminals added to meet it, the rounds of cutting again, and the
  /// largest |log area scale| of the conformal flattening that keeps the cut's lengths (at most
  /// the bound unless the rounds ran out)
  std::size_t distortion_terminals = 0, distortion_rounds = 0;
  double largest_log_area_scale = 0.;
};

/// \ingroup PkgDevelopabilityRef
///
/// Computes a cut along which a (piecewise-)developable design opens into topological disks that
/// flatten with little distortion (Stein, Grinspun & Crane 2018, sec. 4.4).
///
/// **What is cut.** The *terminals* are the interior vertices whose covariance measure lambda_i
/// (eq. 3: the smallest eigenvalue of the angle-weighted covariance of the face normals of the
/// star; 0 on hinges and flat stars) exceeds `cut_tolerance` epsilon: the vertices a stiff sheet
/// cannot follow without cutting. The cut is a short tree through all of them, joined to every
/// boundary loop (a Steiner tree by Mehlhorn's metric-closure minimum spanning tree, each
/// boundary loop one zero-cost super-terminal), plus 2g generator loops on a component of genus
/// g (greedy system of loops through the shortest paths from the tree), plus, on a closed
/// component whose tree has fewer than two edges, its cheapest edges at its terminal (a sphere
/// opens into a disk only along two edges or more). Edge cost: |e| (1 + w (|u_a x e^| +
/// |u_b x e^|) / 2), u the unit eigenvector of lambda at each end (the ruling direction), so that
/// cuts follow rulings (paper: length times alignment). Every piece is checked to be a disk
/// (one boundary loop, Euler characteristic 1). Smaller epsilon: more cuts, less distortion.
///
/// **Distortion.** The vertices under epsilon may still carry curvature, which adds up over a
/// piece and distorts its flattening (a sphere of evenly spread curvature has no vertex above a
/// large epsilon at all). With `distortion_bound` the cut grows, from the peaks of the log
/// conformal factor of the flattening, until that factor is bounded everywhere.
///
/// \param tm a triangle mesh (validated: manifold, no degenerate face, finite coordinates), any
///        genus, boundaries and number of components
/// \param cut_edges output iterator receiving the `edge_descriptor`s of the cut
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
///   \cgalParamNBegin{cut_tolerance}
///     \cgalParamDescription{epsilon: the interior vertices with lambda_i > epsilon are the terminals of the
///                           cut (smaller: more cuts, less distortion)}
///     \cgalParamType{`double`}
///     \cgalParamDefault{`1e-3` (the paper's Fig. 20 uses .01 to .001)}
///     \cgalParamExtra{throws `Invalid_parameter` if it is negative or not finite}
///   \cgalParamNEnd
///   \cgalParamNBegin{ruling_alignment_weight}
///     \cgalParamDescription{w in the edge cost |e| (1 + w (|u_a x e^| + |u_b x e^|) / 2); 0: shortest cuts}
///     \cgalParamType{`double`}
///     \cgalParamDefault{`1`}
///     \cgalParamExtra{throws `Invalid_parameter` if it is negative or not finite}
///   \cgalParamNEnd
///   \cgalParamNBegin{cut_edge_cost}
///     \cgalParamDescription{the edge cost of the tree (see `Developable_cut_cost`): along the rulings, or the
///                           paper's words taken literally (across them)}
///     \cgalParamType{`Developable_cut_cost`}
///     \cgalParamDefault{`Developable_cut_cost::ruling_alignment`}
///     \cgalParamExtra{throws `Invalid_parameter` if it is not an enumerator of `Developable_cut_cost`}
///   \cgalParamNEnd
///   \cgalParamNBegin{distortion_bound}
///     \cgalParamDescription{B > 0: after the tree, cut further until the conformal flattening that keeps the
///                           cut's lengths (Boundary First Flattening with u_B = 0) has |log area scale| = 2 |u_i|
///                           at most B at every vertex. The curvature the flow left spread under epsilon is what
///                           distorts a piece; each round solves A_II u = -K_I on the mesh (one factorization)
///                           and cuts from every local maximum of |u| above the bound along the cheapest path
///                           to the cut (at most 64 rounds; `largest_log_area_scale` in the result says whether
///                           the bound was met). 0: cut only through the vertices above epsilon}
///     \cgalParamType{`double`}
///     \cgalParamDefault{`0` (the CLI `flatten`: 10 epsilon)}
///     \cgalParamExtra{throws `Invalid_parameter` if it is negative or not finite}
///   \cgalParamNEnd
///   \cgalParamNBegin{sparse_linear_solver}
///     \cgalParamDescription{the solver of the distortion rounds (symmetric positive definite systems)}
///     \cgalParamType{a model of `SparseLinearAlgebraWithFactorTraits_d`}
///     \cgalParamDefault{`Default_solver_traits`}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_energy_map}
///     \cgalParamDescription{output: lambda_i of every vertex}
///     \cgalParamType{a class model of `WritablePropertyMap` with
///                    `boost::graph_traits<TriangleMesh>::%vertex_descriptor` as key type and `double` as
///                    value type}
///     \cgalParamDefault{not written}
///   \cgalParamNEnd
///   \cgalParamNBegin{parallel_evaluation}
///     \cgalParamDescription{with TBB linked (`CGAL_LINKED_WITH_TBB`), the lambda_i are computed in parallel}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`true`}
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
/// \returns what was cut
/// \throws Invalid_mesh, Invalid_parameter (nothing written then), Linear_solver_failure (with a
///         distortion bound)
/// Complexity: O(|E| log |V|) (two Dijkstra searches and two Kruskal passes); with a distortion
/// bound, per round one factorization of the Laplacian of the vertices off the cut and one
/// Dijkstra search.
template <class TriangleMesh, class EdgeOutputIterator,
          class NamedParameters = CGAL::parameters::Default_named_parameters>
Developable_cut_result compute_developable_cut(const TriangleMesh& tm, EdgeOutputIterator cut_edges,
                                               const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  internal::Cut_graph_options o;
  o.tolerance = internal::require_nonnegative(
    "cut_tolerance", choose_parameter(get_parameter(np, internal_np::cut_tolerance), o.tolerance));
  o.alignment_weight = internal::require_nonnegative(
    "ruling_alignment_weight", choose_parameter(get_parameter(np, internal_np::ruling_alignment_weight), 1.));
  o.parallel = choose_parameter(get_parameter(np, internal_np::parallel_evaluation), true);
  o.cost = choose_parameter(get_parameter(np, internal_np::cut_edge_cost), Developable_cut_cost::ruling_alignment);
  if(o.cost != Developable_cut_cost::ruling_alignment && o.cost != Developable_cut_cost::paper)
    throw Invalid_parameter("cut_edge_cost", "not a Developable_cut_cost enumerator");
  o.distortion_bound = internal::require_nonnegative(
    "distortion_bound", choose_parameter(get_parameter(np, internal_np::distortion_bound), 0.));
  const auto vpm = internal::const_vertex_point_map(tm, np);
  const internal::Mesh_indices<TriangleMesh> idx(tm, np);
  internal::validate_mesh(idx, vpm);

  const internal::Cut_graph g = internal::distortion_bounded_cut_graph(idx, vpm, o, internal::solver_traits(np));
  Developable_cut_result r;
  r.terminals = g.terminals.size();
  r.distortion_terminals = g.distortion_terminals;
  r.distortion_rounds = g.distortion_rounds;
  r.largest_log_area_scale = g.largest_log_area_scale;
  r.boundary_loops = g.boundary_loops;
  r.generator_loops = g.generator_loops;
  r.pieces = g.topology.pieces.size();
  for(std::size_t v = 0; v < idx.number_of_vertices(); ++v)
    if(!is_border(idx.vertex(v), tm))
      r.lambda_max = (std::max)(r.lambda_max, g.lambda[v]);
  internal::if_given(np, internal_np::vertex_energy_map, [&](auto map) {
    for(std::size_t v = 0; v < idx.number_of_vertices(); ++v)
      put(map, idx.vertex(v), g.lambda[v]);
  });
  internal::write_cut(idx, vpm, g.edge_is_cut, cut_edges, r.cut_edges, r.cut_length);
  return r;
}

/// \ingroup PkgDevelopabilityRef
/// What `glue_flattening_cracks()` glued.
struct Crack_gluing_result
{
  std::size_t cracks = 0;      ///< cracks closed, whole or in part: connected parts of the glued edges
  std::size_t glued_edges = 0; ///< cut edges glued (border edges given in the cut count in neither number)
  std::size_t rounds = 0;      ///< rounds of flattening again that glued something
  std::size_t reductions = 0;  ///< candidate sets halved to keep the distortion bound
  bool converged = true;       ///< false if the 64 rounds ran out with candidates left
  std::size_t cut_edges = 0;   ///< edges of the glued cut
  double cut_length = 0.;      ///< total length of the glued cut
  /// largest |log area scale| 2 |u_i| of the conformal flattening keeping the cut's lengths, with
  /// the cut given and with the glued cut
  double largest_log_area_scale_before = 0., largest_log_area_scale = 0.;
};

/// \ingroup PkgDevelopabilityRef
///
/// Glues the small cracks of a flattening and flattens again, until none is left (Stein,
/// Grinspun & Crane 2018, sec. 4.4 and Fig. 19, bottom): a shorter cut whose pieces lay out with
/// fewer, longer seams.
///
/// **Cracks.** A cut through every vertex far from developable also passes through vertices
/// whose curvature is small, for example along the seams between developable patches (where
/// lambda_i is large but the angle defect is not): there its two sides barely open in the plane.
/// A crack is a dangling branch of the cut, from its tip (a vertex with one cut edge, off the
/// border) along vertices with two cut edges. In the conformal flattening that keeps the cut's
/// lengths (u_i the log scale factor, u = 0 on the cut: Boundary First Flattening with u_B = 0),
/// the sides of a crack leave its tip v_0 at the angle delta_0 and turn apart by delta_i at each
/// v_i, delta_i = K_i + (A u)_i (the angle defect, plus the cotangent Laplacian of u: what the
/// flattening's angle sum at v_i lacks of 2 pi). The crack opens at v_j by Phi_j = delta_0 + ... +
/// delta_j, and its edges from the tip up to where |Phi| first exceeds `crack_opening_bound` are
/// glued (removed from the cut). With `distortion_bound` B, the glue must keep the largest
/// |log area scale| 2 |u_i| of the new flattening at most max(B, its value before): else the half
/// of the edges with the widest openings is left, until the rest passes. Then the flattening is
/// computed again and the cracks' new tips are glued, until a round glues nothing (at most 64
/// rounds: `converged` says whether that was reached). Only
/// dangling edges are glued, so every piece keeps its topology (a disk stays a disk); a
/// connected part of the cut that does not reach the border keeps two edges.
///
/// \param tm a triangle mesh (validated: manifold, no degenerate face, finite coordinates)
/// \param cut a range of `edge_descriptor`s of `tm` (normally from `compute_developable_cut()`;
///        border edges are ignored)
/// \param glued_cut output iterator receiving the `edge_descriptor`s of the glued cut
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
///   \cgalParamNBegin{crack_opening_bound}
///     \cgalParamDescription{the largest angle (radians) by which the two sides of a crack may open in the
///                           flattening where it is glued}
///     \cgalParamType{`double`}
///     \cgalParamDefault{`0.02` (about 1 degree)}
///     \cgalParamExtra{throws `Invalid_parameter` if it is negative or not finite}
///   \cgalParamNEnd
///   \cgalParamNBegin{distortion_bound}
///     \cgalParamDescription{B > 0: glue only as long as the flattening distorts no area by more than
///                           max(B, what the cut given distorts) (|log area scale| = 2 |u_i|); 0: no bound}
///     \cgalParamType{`double`}
///     \cgalParamDefault{`0`}
///     \cgalParamExtra{throws `Invalid_parameter` if it is negative or not finite}
///   \cgalParamNEnd
///   \cgalParamNBegin{sparse_linear_solver}
///     \cgalParamDescription{the solver of the flattenings (symmetric positive definite systems)}
///     \cgalParamType{a model of `SparseLinearAlgebraWithFactorTraits_d`}
///     \cgalParamDefault{`Default_solver_traits`}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_index_map}
///     \cgalParamDescription{as in `compute_developable_cut()`}
///     \cgalParamType{as in `compute_developable_cut()`}
///     \cgalParamDefault{the mesh's own}
///   \cgalParamNEnd
///   \cgalParamNBegin{halfedge_index_map}
///     \cgalParamDescription{as in `compute_developable_cut()`}
///     \cgalParamType{as in `compute_developable_cut()`}
///     \cgalParamDefault{the mesh's own}
///   \cgalParamNEnd
///   \cgalParamNBegin{edge_index_map}
///     \cgalParamDescription{as in `compute_developable_cut()`}
///     \cgalParamType{as in `compute_developable_cut()`}
///     \cgalParamDefault{the order of `edges(tm)`}
///   \cgalParamNEnd
///   \cgalParamNBegin{face_index_map}
///     \cgalParamDescription{as in `compute_developable_cut()`}
///     \cgalParamType{as in `compute_developable_cut()`}
///     \cgalParamDefault{the mesh's own}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \returns what was glued
/// \throws Invalid_mesh, Invalid_parameter, Invalid_constraints (an edge of `cut` is not an edge of
///         `tm`), Linear_solver_failure, Internal_error (the pieces' topology changed: a bug);
///         nothing is written then
/// Complexity: per round, one factorization of the Laplacian of the vertices off the cut, and
/// one more each time the candidates are halved.
template <class TriangleMesh, class EdgeRange, class EdgeOutputIterator,
          class NamedParameters = CGAL::parameters::Default_named_parameters>
Crack_gluing_result glue_flattening_cracks(const TriangleMesh& tm, const EdgeRange& cut, EdgeOutputIterator glued_cut,
                                           const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  internal::Crack_gluing_options o;
  o.opening_bound = internal::require_nonnegative(
    "crack_opening_bound", choose_parameter(get_parameter(np, internal_np::crack_opening_bound), 0.02));
  o.distortion_bound = internal::require_nonnegative(
    "distortion_bound", choose_parameter(get_parameter(np, internal_np::distortion_bound), 0.));
  const auto vpm = internal::const_vertex_point_map(tm, np);
  const internal::Mesh_indices<TriangleMesh> idx(tm, np);
  internal::validate_mesh(idx, vpm);
  const internal::Crack_gluing g =
    internal::glue_cracks(idx, vpm, internal::edge_flags(idx, cut), o, internal::solver_traits(np));
  Crack_gluing_result r;
  r.cracks = g.cracks;
  r.glued_edges = g.glued_edges;
  r.rounds = g.rounds;
  r.reductions = g.reductions;
  r.converged = g.converged;
  r.largest_log_area_scale_before = g.largest_log_area_scale_before;
  r.largest_log_area_scale = g.largest_log_area_scale;
  internal::write_cut(idx, vpm, g.edge_is_cut, glued_cut, r.cut_edges, r.cut_length);
  return r;
}

/// \ingroup PkgDevelopabilityRef
///
/// Copies `tm` into `out` cut open along `edges`: every vertex becomes one vertex per fan of its
/// faces between cut or border edges, so each cut edge becomes two boundary edges. An uncut mesh
/// is copied with the same vertex and face order. Edges on the border are already open and are
/// ignored.
///
/// \param tm a triangle mesh (validated: manifold, no degenerate face)
/// \param edges a range of `edge_descriptor`s of `tm`
/// \param out the mesh that receives the cut copy (a `MutableFaceGraph`; normally empty: the
///        copy is added to what it holds)
/// \param np_in an optional sequence of named parameters of `tm` among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{a property map associating points to the vertices of `tm`}
///     \cgalParamType{a class model of `ReadablePropertyMap` with
///                    `boost::graph_traits<TriangleMesh>::%vertex_descriptor` as key type and `%Point_3` as
///                    value type}
///     \cgalParamDefault{`boost::get(CGAL::vertex_point, tm)`}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_to_vertex_output_iterator}
///     \cgalParamDescription{receives a pair (vertex of `tm`, vertex of `out`) for every vertex of `out`
///                           (several per cut vertex of `tm`)}
///     \cgalParamType{a model of `OutputIterator` accepting `std::pair`s of a
///                    `boost::graph_traits<TriangleMesh>::%vertex_descriptor` and a
///                    `boost::graph_traits<OutputMesh>::%vertex_descriptor`}
///     \cgalParamDefault{unused}
///   \cgalParamNEnd
///   \cgalParamNBegin{face_to_face_output_iterator}
///     \cgalParamDescription{receives a pair (face of `tm`, face of `out`) for every face}
///     \cgalParamType{a model of `OutputIterator` accepting `std::pair`s of a
///                    `boost::graph_traits<TriangleMesh>::%face_descriptor` and a
///                    `boost::graph_traits<OutputMesh>::%face_descriptor`}
///     \cgalParamDefault{unused}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_index_map}
///     \cgalParamDescription{a property map associating to each vertex of `tm` a unique index in
///                           `[0, num_vertices(tm))`: the numbering of the elements in error messages; the
///                           copies of the vertices are added to `out` in this order}
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
///                           `[0, num_faces(tm))`: the numbering of the elements in error messages; the faces
///                           are added to `out` in this order}
///     \cgalParamType{a class model of `ReadablePropertyMap` with
///                    `boost::graph_traits<TriangleMesh>::%face_descriptor` as key type and an integer as
///                    value type}
///     \cgalParamDefault{the mesh's own (`CGAL::get_initialized_face_index_map(tm)`)}
///     \cgalParamExtra{throws `Invalid_mesh` (`Mesh_defect::invalid_index_map`) if it is not a bijection onto
///                     `[0, num_faces(tm))`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \param np_out an optional sequence of named parameters of `out` among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{a property map through which the points of the new vertices of `out` are
///                           written}
///     \cgalParamType{a class model of `WritablePropertyMap` with
///                    `boost::graph_traits<OutputMesh>::%vertex_descriptor` as key type and `%Point_3` as
///                    value type}
///     \cgalParamDefault{`boost::get(CGAL::vertex_point, out)`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \returns the number of connected components (pieces) of the cut mesh
/// \throws Invalid_mesh (`tm`), Invalid_constraints (an edge is not an edge of `tm`); `out` is
///         not modified then
template <class TriangleMesh, class EdgeRange, class OutputMesh,
          class NamedParametersIn = CGAL::parameters::Default_named_parameters,
          class NamedParametersOut = CGAL::parameters::Default_named_parameters>
std::size_t cut_mesh_along_edges(const TriangleMesh& tm, const EdgeRange& edges, OutputMesh& out,
                                 const NamedParametersIn& np_in = CGAL::parameters::default_values(),
                                 const NamedParametersOut& np_out = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  const auto vpm = internal::const_vertex_point_map(tm, np_in);
  const internal::Mesh_indices<TriangleMesh> idx(tm, np_in);
  internal::validate_mesh(idx, vpm);
  const std::vector<bool> edge_is_cut = internal::edge_flags(idx, edges);
  const internal::Cut_corners corners = internal::cut_corners(idx, edge_is_cut);
  const internal::Cut_topology topology = internal::cut_topology(idx, edge_is_cut, corners);
  const std::vector<std::array<std::size_t, 3>> faces = internal::cut_faces(idx, corners);

  using Out_vertex = typename boost::graph_traits<OutputMesh>::vertex_descriptor;
  auto out_vpm = choose_parameter(get_parameter(np_out, CGAL::internal_np::vertex_point),
                                  get_property_map(CGAL::vertex_point, out));
  std::vector<Out_vertex> copies(corners.number_of_copies());
  auto vertex_pairs = get_parameter(np_in, CGAL::internal_np::vertex_to_vertex_output_iterator);
  auto face_pairs = get_parameter(np_in, CGAL::internal_np::face_to_face_output_iterator);
  constexpr bool output_vertices =
    !std::is_same<std::decay_t<decltype(vertex_pairs)>, CGAL::internal_np::Param_not_found>::value;
  constexpr bool output_faces =
    !std::is_same<std::decay_t<decltype(face_pairs)>, CGAL::internal_np::Param_not_found>::value;
  for(std::size_t c = 0; c < copies.size(); ++c)
  {
    copies[c] = add_vertex(out);
    const auto v = idx.vertex(corners.original_vertex[c]);
    put(out_vpm, copies[c], get(vpm, v));
    if constexpr(output_vertices)
      *vertex_pairs++ = std::make_pair(v, copies[c]);
  }
  for(std::size_t f = 0; f < faces.size(); ++f)
  {
    const std::array<Out_vertex, 3> triangle = {copies[faces[f][0]], copies[faces[f][1]], copies[faces[f][2]]};
    const auto new_face = CGAL::Euler::add_face(triangle, out);
    if constexpr(output_faces)
      *face_pairs++ = std::make_pair(idx.face(f), new_face);
    else
      (void)new_face;
  }
  return topology.pieces.size();
}

} // namespace Surface_design
} // namespace CGAL

#endif // CGAL_SURFACE_DESIGN_DEVELOPABLE_CUTTING_H
