// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// One-call barycentric ("nice") embedding with fixed vertices, and the paper's iterative method
// as a reference.

#ifndef CGAL_SURFACE_DESIGN_BARYCENTRIC_EMBEDDING_H
#define CGAL_SURFACE_DESIGN_BARYCENTRIC_EMBEDDING_H

#include <CGAL/Surface_design/Barycentric_embedder.h>
#include <CGAL/Surface_design/internal/Barycentric_embedding/barycentric_stencil.h>
#include <CGAL/Surface_design/internal/Core/named_parameters.h>
#include <CGAL/Surface_design/parameters.h>

#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Named_function_parameters.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

namespace CGAL {
namespace Surface_design {

/// \ingroup PkgBarycentricEmbeddingRef
///
/// Moves every free vertex of `pm` to the weighted barycentre of its neighbours, the fixed
/// vertices staying in place (Imafuji & Ochiai's non-iterative "nice embedding", method 1): one
/// sparse factorization and three back-substitutions. To move the fixed vertices repeatedly,
/// build a `Barycentric_embedder` once and call its `update()`.
///
/// \param pm a polygon mesh (any faces; only its connectivity matters for uniform weights)
/// \param fixed_vertices a readable vertex -> bool property map (true: fixed), or a range of the
///        fixed vertex descriptors
/// \param np an optional sequence of named parameters among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{a property map associating points to the vertices of `pm`: read at the fixed
///                           vertices, written at the free vertices}
///     \cgalParamType{a class model of `ReadWritePropertyMap` with
///                    `boost::graph_traits<PolygonMesh>::%vertex_descriptor` as key type and `%Point_3` as
///                    value type}
///     \cgalParamDefault{`boost::get(CGAL::vertex_point, pm)`}
///   \cgalParamNEnd
///   \cgalParamNBegin{weighting}
///     \cgalParamDescription{the weights w_ij of the barycentres}
///     \cgalParamType{`Edge_weighting`: `uniform`, `cotangent` (triangle meshes only) or `mean_value`}
///     \cgalParamDefault{`Edge_weighting::uniform` (the paper's)}
///     \cgalParamExtra{throws `Invalid_parameter` if it is not an enumerator of `Edge_weighting`}
///   \cgalParamNEnd
///   \cgalParamNBegin{reference_point_map}
///     \cgalParamDescription{the geometry the cotangent or mean-value weights are computed from}
///     \cgalParamType{a class model of `ReadablePropertyMap` with
///                    `boost::graph_traits<PolygonMesh>::%vertex_descriptor` as key type and `%Point_3` as
///                    value type}
///     \cgalParamDefault{the vertex point map before the call}
///     \cgalParamExtra{read only with `cotangent` or `mean_value` weights, and validated like the vertex
///                     point map: throws `Invalid_mesh` if a coordinate is not finite, or, there, a triangle
///                     (cotangent weights) or an edge (mean-value weights) is degenerate}
///   \cgalParamNEnd
///   \cgalParamNBegin{sparse_linear_solver}
///     \cgalParamDescription{the sparse solver that factors the symmetric system of the free vertices
///                           (uniform and cotangent weights)}
///     \cgalParamType{a class model of `SparseLinearAlgebraWithFactorTraits_d`}
///     \cgalParamDefault{`Default_solver_traits` (`Size_switched_cholesky`: the simplicial LDLT below 20000
///                       unknowns, the supernodal Cholesky from there)}
///     \cgalParamExtra{not used with mean-value weights: that system is not symmetric and is always factored
///                     by `Sparse_lu_solver_traits`}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_index_map}
///     \cgalParamDescription{a property map associating to each vertex of `pm` a unique index in
///                           `[0, num_vertices(pm))`: the numbering of the elements in error messages}
///     \cgalParamType{a class model of `ReadablePropertyMap` with
///                    `boost::graph_traits<PolygonMesh>::%vertex_descriptor` as key type and an integer as
///                    value type}
///     \cgalParamDefault{the mesh's own (`CGAL::get_initialized_vertex_index_map(pm)`)}
///     \cgalParamExtra{throws `Invalid_mesh` (`Mesh_defect::invalid_index_map`) if it is not a bijection onto
///                     `[0, num_vertices(pm))`}
///   \cgalParamNEnd
///   \cgalParamNBegin{halfedge_index_map}
///     \cgalParamDescription{a property map associating to each halfedge of `pm` a unique index in
///                           `[0, num_halfedges(pm))`: the numbering of the elements in error messages}
///     \cgalParamType{a class model of `ReadablePropertyMap` with
///                    `boost::graph_traits<PolygonMesh>::%halfedge_descriptor` as key type and an integer as
///                    value type}
///     \cgalParamDefault{the mesh's own (`CGAL::get_initialized_halfedge_index_map(pm)`)}
///     \cgalParamExtra{throws `Invalid_mesh` (`Mesh_defect::invalid_index_map`) if it is not a bijection onto
///                     `[0, num_halfedges(pm))`}
///   \cgalParamNEnd
///   \cgalParamNBegin{edge_index_map}
///     \cgalParamDescription{a property map associating to each edge of `pm` a unique index in
///                           `[0, num_edges(pm))`: the numbering of the elements in error messages}
///     \cgalParamType{a class model of `ReadablePropertyMap` with
///                    `boost::graph_traits<PolygonMesh>::%edge_descriptor` as key type and an integer as
///                    value type}
///     \cgalParamDefault{the order of `edges(pm)`}
///     \cgalParamExtra{throws `Invalid_mesh` (`Mesh_defect::invalid_index_map`) if it is not a bijection onto
///                     `[0, num_edges(pm))`}
///   \cgalParamNEnd
///   \cgalParamNBegin{face_index_map}
///     \cgalParamDescription{a property map associating to each face of `pm` a unique index in
///                           `[0, num_faces(pm))`: the numbering of the elements in error messages}
///     \cgalParamType{a class model of `ReadablePropertyMap` with
///                    `boost::graph_traits<PolygonMesh>::%face_descriptor` as key type and an integer as
///                    value type}
///     \cgalParamDefault{the mesh's own (`CGAL::get_initialized_face_index_map(pm)`)}
///     \cgalParamExtra{throws `Invalid_mesh` (`Mesh_defect::invalid_index_map`) if it is not a bijection onto
///                     `[0, num_faces(pm))`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \returns the number of free vertices moved
/// \throws Invalid_mesh, Invalid_constraints, Invalid_parameter, Linear_solver_failure, as
///         `Barycentric_embedder`'s constructor and `update()`; the mesh is unchanged then
/// Complexity: one sparse factorization of size #free vertices.
template <class PolygonMesh, class FixedVertices,
          class NamedParameters = CGAL::parameters::Default_named_parameters>
std::size_t barycentric_embedding(PolygonMesh& pm, const FixedVertices& fixed_vertices,
                                  const NamedParameters& np = CGAL::parameters::default_values())
{
  Barycentric_embedder<PolygonMesh, internal::Vertex_point_map_t<PolygonMesh, NamedParameters>,
                       internal::Solver_traits_t<NamedParameters>>
    embedder(pm, fixed_vertices, np);
  embedder.update();
  return embedder.number_of_free_vertices();
}

/// \ingroup PkgBarycentricEmbeddingRef
/// What `barycentric_embedding_iterative()` did.
struct Iterative_embedding_result
{
  std::size_t iterations = 0; ///< number of steps C <- F C made
  double area = 0.;           ///< surface area after the last step
  bool converged = false;     ///< the area changed by less than the tolerance in the last step
};

namespace internal {

// Area of a polygon mesh given its vertex positions: the norm of each face's vector area
// (1/2 sum p_k x p_{k+1}), exact for planar faces and for triangles.
inline double polygon_mesh_area(const std::vector<std::size_t>& face_start,
                           const std::vector<std::size_t>& face_vertex,
                           const std::vector<Eigen::Vector3d>& x)
{
  double area = 0.;
  for(std::size_t f = 0; f + 1 < face_start.size(); ++f)
  {
    Eigen::Vector3d vector_area = Eigen::Vector3d::Zero();
    const std::size_t b = face_start[f], e = face_start[f + 1];
    for(std::size_t k = b; k < e; ++k)
      vector_area += x[face_vertex[k]].cross(x[face_vertex[k + 1 < e ? k + 1 : b]]);
    area += 0.5 * vector_area.norm();
  }
  return area;
}

} // namespace internal

/// \ingroup PkgBarycentricEmbeddingRef
///
/// The paper's iterative method (method 2), kept as a reference: starting from the current
/// positions, repeats C <- F C, i.e. moves every free vertex to the weighted barycentre of its
/// neighbours' *previous* positions (a Jacobi iteration), until the surface area changes by less
/// than `area_tolerance` in one step (the paper's criterion, sec. 4.2) or
/// `number_of_iterations` steps were made. Then writes the free vertices' positions. Its
/// limit is the solution of `barycentric_embedding()`, which gets it in one solve; the number of
/// steps grows like the square of the mesh's diameter in edges. It converges for uniform and
/// mean-value weights (positive weights, every free component with a fixed vertex); with
/// negative cotangent weights it may not.
///
/// \param np an optional sequence of named parameters among the ones listed below (those of
///        `barycentric_embedding()` but `sparse_linear_solver`, plus `area_tolerance` and
///        `number_of_iterations`)
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{a property map associating points to the vertices of `pm`: the starting
///                           positions, and the positions of the free vertices after the last step are
///                           written to it}
///     \cgalParamType{a class model of `ReadWritePropertyMap` with
///                    `boost::graph_traits<PolygonMesh>::%vertex_descriptor` as key type and `%Point_3` as
///                    value type}
///     \cgalParamDefault{`boost::get(CGAL::vertex_point, pm)`}
///   \cgalParamNEnd
///   \cgalParamNBegin{weighting}
///     \cgalParamDescription{the weights w_ij of the barycentres}
///     \cgalParamType{`Edge_weighting`: `uniform`, `cotangent` (triangle meshes only) or `mean_value`}
///     \cgalParamDefault{`Edge_weighting::uniform` (the paper's)}
///     \cgalParamExtra{throws `Invalid_parameter` if it is not an enumerator of `Edge_weighting`}
///   \cgalParamNEnd
///   \cgalParamNBegin{reference_point_map}
///     \cgalParamDescription{the geometry the cotangent or mean-value weights are computed from}
///     \cgalParamType{a class model of `ReadablePropertyMap` with
///                    `boost::graph_traits<PolygonMesh>::%vertex_descriptor` as key type and `%Point_3` as
///                    value type}
///     \cgalParamDefault{the vertex point map before the call}
///     \cgalParamExtra{read only with `cotangent` or `mean_value` weights, and validated like the vertex
///                     point map: throws `Invalid_mesh` if a coordinate is not finite, or, there, a triangle
///                     (cotangent weights) or an edge (mean-value weights) is degenerate}
///   \cgalParamNEnd
///   \cgalParamNBegin{area_tolerance}
///     \cgalParamDescription{the absolute change of the surface area in one step below which the iteration
///                           stops}
///     \cgalParamType{`double`}
///     \cgalParamDefault{`1e-6` (the paper's)}
///     \cgalParamExtra{throws `Invalid_parameter` if it is not finite and positive}
///   \cgalParamNEnd
///   \cgalParamNBegin{number_of_iterations}
///     \cgalParamDescription{the largest number of steps C <- F C}
///     \cgalParamType{`std::size_t`}
///     \cgalParamDefault{`1000000`}
///     \cgalParamExtra{not validated: 0 makes no step (and writes the current positions)}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_index_map}
///     \cgalParamDescription{a property map associating to each vertex of `pm` a unique index in
///                           `[0, num_vertices(pm))`: the numbering of the elements in error messages}
///     \cgalParamType{a class model of `ReadablePropertyMap` with
///                    `boost::graph_traits<PolygonMesh>::%vertex_descriptor` as key type and an integer as
///                    value type}
///     \cgalParamDefault{the mesh's own (`CGAL::get_initialized_vertex_index_map(pm)`)}
///     \cgalParamExtra{throws `Invalid_mesh` (`Mesh_defect::invalid_index_map`) if it is not a bijection onto
///                     `[0, num_vertices(pm))`}
///   \cgalParamNEnd
///   \cgalParamNBegin{halfedge_index_map}
///     \cgalParamDescription{a property map associating to each halfedge of `pm` a unique index in
///                           `[0, num_halfedges(pm))`: the numbering of the elements in error messages}
///     \cgalParamType{a class model of `ReadablePropertyMap` with
///                    `boost::graph_traits<PolygonMesh>::%halfedge_descriptor` as key type and an integer as
///                    value type}
///     \cgalParamDefault{the mesh's own (`CGAL::get_initialized_halfedge_index_map(pm)`)}
///     \cgalParamExtra{throws `Invalid_mesh` (`Mesh_defect::invalid_index_map`) if it is not a bijection onto
///                     `[0, num_halfedges(pm))`}
///   \cgalParamNEnd
///   \cgalParamNBegin{edge_index_map}
///     \cgalParamDescription{a property map associating to each edge of `pm` a unique index in
///                           `[0, num_edges(pm))`: the numbering of the elements in error messages}
///     \cgalParamType{a class model of `ReadablePropertyMap` with
///                    `boost::graph_traits<PolygonMesh>::%edge_descriptor` as key type and an integer as
///                    value type}
///     \cgalParamDefault{the order of `edges(pm)`}
///     \cgalParamExtra{throws `Invalid_mesh` (`Mesh_defect::invalid_index_map`) if it is not a bijection onto
///                     `[0, num_edges(pm))`}
///   \cgalParamNEnd
///   \cgalParamNBegin{face_index_map}
///     \cgalParamDescription{a property map associating to each face of `pm` a unique index in
///                           `[0, num_faces(pm))`: the numbering of the elements in error messages}
///     \cgalParamType{a class model of `ReadablePropertyMap` with
///                    `boost::graph_traits<PolygonMesh>::%face_descriptor` as key type and an integer as
///                    value type}
///     \cgalParamDefault{the mesh's own (`CGAL::get_initialized_face_index_map(pm)`)}
///     \cgalParamExtra{throws `Invalid_mesh` (`Mesh_defect::invalid_index_map`) if it is not a bijection onto
///                     `[0, num_faces(pm))`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \returns the number of steps, the final area and whether the tolerance was met. The positions
///          of the last step are written in either case.
/// \throws Invalid_mesh, Invalid_constraints (as `barycentric_embedding()`), Invalid_parameter
///         (`area_tolerance` not finite and positive, `weighting` not an enumerator), Linear_solver_failure
///         if the iteration diverges (possible with negative cotangent weights); nothing is
///         written then
/// Complexity: O(|E| + |F|) per step.
template <class PolygonMesh, class FixedVertices,
          class NamedParameters = CGAL::parameters::Default_named_parameters>
Iterative_embedding_result
barycentric_embedding_iterative(PolygonMesh& pm, const FixedVertices& fixed_vertices,
                                const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  using Vpm = internal::Vertex_point_map_t<PolygonMesh, NamedParameters>;
  using Point = typename boost::property_traits<Vpm>::value_type;

  const Vpm vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                   get_property_map(CGAL::vertex_point, pm));
  const auto reference = choose_parameter(get_parameter(np, internal_np::reference_point_map), vpm);
  const Edge_weighting weighting =
    choose_parameter(get_parameter(np, internal_np::weighting), Edge_weighting::uniform);
  const double tolerance =
    internal::require_positive("area_tolerance", choose_parameter(get_parameter(np, internal_np::area_tolerance), 1e-6));
  const std::size_t max_iterations =
    choose_parameter(get_parameter(np, CGAL::internal_np::number_of_iterations), std::size_t(1000000));
  internal::check_edge_weighting(weighting);

  internal::Mesh_indices<PolygonMesh> idx(pm, np);
  std::vector<bool> is_fixed = internal::fixed_flags(idx, fixed_vertices);
  internal::validate_barycentric_input(idx, vpm, reference, weighting, is_fixed);
  const internal::Barycentric_stencil s =
    internal::barycentric_stencil(idx, reference, weighting, std::move(is_fixed));

  std::vector<std::size_t> face_start{0}, face_vertex;
  for(std::size_t f = 0; f < idx.number_of_faces(); ++f)
  {
    for(auto v : vertices_around_face(halfedge(idx.face(f), pm), pm))
      face_vertex.push_back(idx.index(v));
    face_start.push_back(face_vertex.size());
  }
  std::vector<Eigen::Vector3d> x = internal::vertex_positions(idx, vpm), next;

  Iterative_embedding_result result;
  result.area = internal::polygon_mesh_area(face_start, face_vertex, x);
  next = x;
  while(result.iterations < max_iterations && !s.free_vertices.empty())
  {
    // C^{k+1} = F C^k (paper, eq. 1): fixed rows are the identity, free rows the barycentre
    for(std::size_t r = 0; r < s.free_vertices.size(); ++r)
    {
      Eigen::Vector3d sum = Eigen::Vector3d::Zero();
      double total = 0.;
      for(std::size_t k = s.row_start[r]; k < s.row_start[r + 1]; ++k)
      {
        sum += s.weight[k] * x[s.neighbour[k]];
        total += s.weight[k];
      }
      next[s.free_vertices[r]] = sum / total;
    }
    std::swap(x, next);
    ++result.iterations;
    const double area = internal::polygon_mesh_area(face_start, face_vertex, x);
    if(!std::isfinite(area))
      throw Linear_solver_failure("the iteration C <- F C diverged after " +
                                  std::to_string(result.iterations) + " steps (" +
                                  to_string(weighting) + " weights); nothing was written");
    const double change = std::abs(area - result.area);
    result.area = area;
    if(change < tolerance)
    {
      result.converged = true;
      break;
    }
  }
  if(s.free_vertices.empty())
    result.converged = true;
  for(std::size_t v : s.free_vertices)
    put(vpm, idx.vertex(v), Point(x[v].x(), x[v].y(), x[v].z()));
  return result;
}

} // namespace Surface_design
} // namespace CGAL

#endif // CGAL_SURFACE_DESIGN_BARYCENTRIC_EMBEDDING_H
