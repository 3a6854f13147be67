// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Non-iterative "nice" (barycentric) embedding with fixed vertices (Imafuji & Ochiai): every free
// vertex at the (weighted) barycentre of its neighbours, by one sparse factorization reused for
// every later position of the fixed vertices.

#ifndef CGAL_SURFACE_DESIGN_BARYCENTRIC_EMBEDDER_H
#define CGAL_SURFACE_DESIGN_BARYCENTRIC_EMBEDDER_H

#include <CGAL/Surface_design/edge_weighting.h>
#include <CGAL/Surface_design/exceptions.h>
#include <CGAL/Surface_design/internal/Barycentric_embedding/barycentric_stencil.h>
#include <CGAL/Surface_design/internal/Core/dec.h>
#include <CGAL/Surface_design/internal/Solvers/Factored_system.h>
#include <CGAL/Surface_design/internal/Core/geometry.h>
#include <CGAL/Surface_design/internal/Core/Mesh_indices.h>
#include <CGAL/Surface_design/internal/Core/named_parameters.h>
#include <CGAL/Surface_design/parameters.h>
#include <CGAL/Surface_design/solver_traits.h>

#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Named_function_parameters.h>

#include <Eigen/Core>
#include <Eigen/Sparse>

#include <boost/property_map/property_map.hpp>

#include <cstddef>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_design {

/// \ingroup PkgBarycentricEmbeddingRef
///
/// Places every free vertex of a polygon mesh at the weighted barycentre of its neighbours, the
/// fixed vertices staying where they are (Imafuji & Ochiai, "nice embedding"): factors the system
/// once for a connectivity, a fixed set and weights, then `update()` re-solves by
/// back-substitution whenever the fixed vertices move.
///
/// **The problem** (paper, sec. 2). With x_i the position of vertex i and w_ij the weight of
/// neighbour j at i, every free vertex i satisfies
///   sum_j w_ij (x_i - x_j) = 0,   i.e.   x_i = sum_j w_ij x_j / sum_j w_ij.
/// Splitting the unknowns into free (f) and fixed (c) vertices gives, per coordinate,
///   L_ff x_f = -L_fc x_c = C x_c,
/// with L the weighted graph Laplacian (L_ii = sum_j w_ij, L_ij = -w_ij). This is the paper's
/// eq. (2), (E - A) C_I = B C_O, multiplied row by row by the degree: the limit of its
/// iteration C <- F C (method 2) obtained in one solve (method 1). The fixed positions only
/// enter the right-hand side, so moving them costs three back-substitutions.
///
/// **Which solver.** Uniform weights (the paper's, the default) and cotangent weights give a
/// symmetric L_ff, factored by `SolverTraits` (an LDLT or Cholesky factorization). It is positive
/// definite as soon as every connected component with a free vertex has a fixed vertex (which
/// the constructor checks): L_ff is a principal submatrix of a positive semi-definite matrix
/// whose kernel is the constants per component. For cotangent weights this holds even with
/// negative weights, because the cotangent Laplacian is the P1 stiffness matrix, but then a free
/// vertex may leave the convex hull of its neighbours (no Tutte guarantee). Should a
/// factorization still find a non-positive pivot (a numerically singular system), the
/// constructor throws `Linear_solver_failure` naming the pivot. Mean-value weights are positive
/// but not symmetric (w_ij != w_ji): that system is factored by a sparse LU
/// (`Sparse_lu_solver_traits`) whatever `SolverTraits` is, and solved exactly as posed: no
/// symmetrization, so every free vertex is exactly the mean-value barycentre of its neighbours.
///
/// Weights of a reference geometry (cotangent, mean value) are computed once, in the constructor,
/// from `reference_point_map` (default: the vertex point map at that moment): moving the fixed
/// vertices later does not change them.
///
/// \tparam PolygonMesh a model of `FaceListGraph` and `HalfedgeListGraph` (any polygon faces;
///         triangles for cotangent weights)
/// \tparam VertexPointMap a readable and writable property map from vertices to `Point_3`
/// \tparam SolverTraits a model of `SparseLinearAlgebraWithFactorTraits_d` for symmetric positive
///         definite systems. Copies of a `CGAL::Eigen_solver_traits` share one factorization:
///         give every object its own solver (the default does).
template <class PolygonMesh,
          class VertexPointMap = typename boost::property_map<PolygonMesh, CGAL::vertex_point_t>::type,
          class SolverTraits = Default_solver_traits>
class Barycentric_embedder
{
  using GT = boost::graph_traits<PolygonMesh>;
  using Indices = internal::Mesh_indices<PolygonMesh>;
  using Point = typename boost::property_traits<VertexPointMap>::value_type;

public:
  using vertex_descriptor = typename GT::vertex_descriptor;

  /// Validates the input, computes the weights and factors the system of the free vertices.
  /// The connectivity, the fixed set and the weights are final; the fixed positions are read by
  /// `update()`. The mesh's connectivity must not change while this object is used.
  ///
  /// \param pm the mesh
  /// \param fixed_vertices either a readable vertex -> bool property map (true: fixed) or a
  ///        range of the fixed vertex descriptors
  /// \param np an optional sequence of named parameters among the ones listed below
  ///
  /// \cgalNamedParamsBegin
  ///   \cgalParamNBegin{vertex_point_map}
  ///     \cgalParamDescription{a property map associating points to the vertices of `pm`: the positions of the
  ///                           fixed vertices are read from it, those of the free vertices written to it by
  ///                           `update()`}
  ///     \cgalParamType{a class model of `ReadWritePropertyMap` with
  ///                    `boost::graph_traits<PolygonMesh>::%vertex_descriptor` as key type and `%Point_3` as
  ///                    value type, convertible to `VertexPointMap`}
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
  ///     \cgalParamDefault{the vertex point map, read once, in the constructor: moving the fixed vertices later
  ///                       does not change the weights}
  ///     \cgalParamExtra{read only with `cotangent` or `mean_value` weights, and validated like the vertex
  ///                     point map: throws `Invalid_mesh` if a coordinate is not finite, or, there, a triangle
  ///                     (cotangent weights) or an edge (mean-value weights) is degenerate}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{sparse_linear_solver}
  ///     \cgalParamDescription{the sparse solver that factors the symmetric system of the free vertices
  ///                           (uniform and cotangent weights)}
  ///     \cgalParamType{`SolverTraits`, a model of `SparseLinearAlgebraWithFactorTraits_d` (class template
  ///                    argument deduction takes the class's `SolverTraits` from this parameter)}
  ///     \cgalParamDefault{`SolverTraits()`}
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
  /// \throws Invalid_mesh the mesh is empty, not manifold, has non-finite coordinates, or (for
  ///         weights of a reference geometry) degenerate faces or edges there; cotangent weights
  ///         also need triangles
  /// \throws Invalid_constraints a connected component with free vertices has no fixed vertex
  /// \throws Invalid_parameter `weighting` is not an `Edge_weighting` enumerator
  ///         (the system would be singular), or a vertex of the range is not in the mesh
  /// \throws Linear_solver_failure the factorization fails
  /// Nothing is written on failure (nor on success: positions are written by `update()`).
  /// Complexity: O(|V| + |E|) plus one sparse factorization of size #free vertices.
  template <class FixedVertices, class NamedParameters = CGAL::parameters::Default_named_parameters>
  Barycentric_embedder(PolygonMesh& pm, const FixedVertices& fixed_vertices,
                       const NamedParameters& np = CGAL::parameters::default_values())
    : m_pm(pm),
      m_vpm(internal::class_vertex_point_map<VertexPointMap, true>(pm, np)),
      m_idx(pm, np),
      m_weighting(CGAL::parameters::choose_parameter(
        CGAL::parameters::get_parameter(np, internal_np::weighting), Edge_weighting::uniform)),
      m_symmetric(internal::class_solver_traits<SolverTraits>(np),
                  std::string("barycentric system of the free vertices (") + to_string(m_weighting) +
                    " weights)"),
      m_lu(Sparse_lu_solver_traits(), "barycentric system of the free vertices (mean-value weights)")
  {
    internal::check_edge_weighting(m_weighting);
    const auto reference = CGAL::parameters::choose_parameter(
      CGAL::parameters::get_parameter(np, internal_np::reference_point_map), m_vpm);
    std::vector<bool> is_fixed = internal::fixed_flags(m_idx, fixed_vertices);
    internal::validate_barycentric_input(m_idx, m_vpm, reference, m_weighting, is_fixed);
    m_stencil = internal::barycentric_stencil(m_idx, reference, m_weighting, std::move(is_fixed));
    factor();
  }

  /// Re-solves for the current positions of the fixed vertices (read from the vertex point map)
  /// and writes the positions of the free vertices: three back-substitutions, no factorization.
  /// \throws Invalid_mesh (`non_finite_coordinates`) if a fixed vertex has a non-finite
  ///         coordinate; nothing is written then
  void update()
  {
    solve_and_write(fixed_positions(m_vpm, true), false);
  }

  /// Moves the fixed vertices to `new_fixed_positions` (a readable vertex -> `Point_3` map, read
  /// at the fixed vertices only), re-solves and writes the positions of all vertices.
  /// \throws Invalid_constraints if a new fixed position is not finite; nothing is written then
  template <class FixedPointMap>
  void update(const FixedPointMap& new_fixed_positions)
  {
    solve_and_write(fixed_positions(new_fixed_positions, false), true);
  }

  /// \name Information
  /// @{
  const PolygonMesh& mesh() const { return m_pm; }
  std::size_t number_of_free_vertices() const { return m_stencil.number_of_free_vertices(); }
  std::size_t number_of_fixed_vertices() const { return m_stencil.number_of_fixed_vertices(); }
  bool is_fixed(vertex_descriptor v) const { return m_stencil.is_fixed[m_idx.index(v)]; }
  Edge_weighting weighting() const { return m_weighting; }
  /// The fixed vertices, in the order of their columns in the system.
  std::vector<vertex_descriptor> fixed_vertices() const
  {
    std::vector<vertex_descriptor> v;
    v.reserve(number_of_fixed_vertices());
    for(std::size_t i : m_stencil.fixed_vertices)
      v.push_back(m_idx.vertex(i));
    return v;
  }
  /// Largest distance between a free vertex and the weighted barycentre of its neighbours, at the
  /// current positions: 0 up to rounding after `update()`.
  double barycentre_residual() const
  {
    double worst = 0.;
    for(std::size_t r = 0; r < m_stencil.free_vertices.size(); ++r)
    {
      Eigen::Vector3d sum = Eigen::Vector3d::Zero();
      double total = 0.;
      for(std::size_t k = m_stencil.row_start[r]; k < m_stencil.row_start[r + 1]; ++k)
      {
        sum += m_stencil.weight[k] * internal::position(m_vpm, m_idx.vertex(m_stencil.neighbour[k]));
        total += m_stencil.weight[k];
      }
      const Eigen::Vector3d p = internal::position(m_vpm, m_idx.vertex(m_stencil.free_vertices[r]));
      worst = (std::max)(worst, (p - sum / total).norm());
    }
    return worst;
  }
  /// @}

private:
  bool uses_lu() const { return m_weighting == Edge_weighting::mean_value; }

  // L_ff (free x free) and C (free x fixed, rhs = C x_c) from the stencil, and the factorization
  void factor()
  {
    const std::size_t nf = number_of_free_vertices();
    if(nf == 0)
      return; // every vertex is fixed: nothing to solve
    // weight of neighbour target(h) at source(h), per halfedge leaving a free vertex
    std::vector<double> halfedge_weight(m_idx.number_of_halfedges(), 0.);
    std::vector<double> diagonal(m_idx.number_of_vertices(), 0.);
    std::vector<internal::Triplet> c;
    for(std::size_t r = 0; r < nf; ++r)
      for(std::size_t k = m_stencil.row_start[r]; k < m_stencil.row_start[r + 1]; ++k)
      {
        const std::size_t j = m_stencil.neighbour[k];
        const double w = m_stencil.weight[k];
        halfedge_weight[m_stencil.halfedge[k]] += w;
        diagonal[m_stencil.free_vertices[r]] += w;
        if(m_stencil.is_fixed[j])
          c.emplace_back(int(r), int(m_stencil.slot[j]), w);
      }
    // the free rows and columns only: slot of a free vertex, npos for a fixed one
    std::vector<std::size_t> free_slot(m_idx.number_of_vertices(), internal::npos);
    for(std::size_t r = 0; r < nf; ++r)
      free_slot[m_stencil.free_vertices[r]] = r;
    internal::Sparse_matrix A = internal::assemble_vertex_matrix<double>(
      m_idx, [&](std::size_t h) { return -halfedge_weight[h]; }, [&](std::size_t v) { return diagonal[v]; },
      free_slot);
    m_coupling.resize(int(nf), int(number_of_fixed_vertices()));
    m_coupling.setFromTriplets(c.begin(), c.end());
    if(uses_lu())
      m_lu.factor(std::move(A), false);
    else
      m_symmetric.factor(std::move(A), true);
  }

  // positions of the fixed vertices (#fixed x 3), checked finite
  template <class PointMap>
  Eigen::MatrixXd fixed_positions(const PointMap& map, bool from_mesh) const
  {
    Eigen::MatrixXd x(Eigen::Index(number_of_fixed_vertices()), 3);
    for(std::size_t k = 0; k < number_of_fixed_vertices(); ++k)
    {
      const std::size_t v = m_stencil.fixed_vertices[k];
      const Eigen::Vector3d p = internal::position(map, m_idx.vertex(v));
      if(!p.allFinite())
      {
        std::ostringstream s;
        s << "fixed vertex " << v << " has coordinates (" << p.x() << ", " << p.y() << ", " << p.z()
          << ")";
        if(from_mesh)
          throw Invalid_mesh(Mesh_defect::non_finite_coordinates, v, s.str());
        throw Invalid_constraints("the new position of " + s.str());
      }
      x.row(Eigen::Index(k)) = p.transpose();
    }
    return x;
  }

  void solve_and_write(const Eigen::MatrixXd& fixed, bool write_fixed)
  {
    const std::size_t nf = number_of_free_vertices();
    Eigen::MatrixXd free(Eigen::Index(nf), 3);
    if(nf > 0)
    {
      const Eigen::MatrixXd rhs = m_coupling * fixed;
      Eigen::VectorXd x;
      for(int d = 0; d < 3; ++d)
      {
        if(uses_lu())
          m_lu.solve(rhs.col(d), x);
        else
          m_symmetric.solve(rhs.col(d), x);
        free.col(d) = x;
      }
    }
    // everything succeeded: write
    if(write_fixed)
      for(std::size_t k = 0; k < number_of_fixed_vertices(); ++k)
        put(m_vpm, m_idx.vertex(m_stencil.fixed_vertices[k]),
            Point(fixed(Eigen::Index(k), 0), fixed(Eigen::Index(k), 1), fixed(Eigen::Index(k), 2)));
    for(std::size_t r = 0; r < nf; ++r)
      put(m_vpm, m_idx.vertex(m_stencil.free_vertices[r]),
          Point(free(Eigen::Index(r), 0), free(Eigen::Index(r), 1), free(Eigen::Index(r), 2)));
  }

  PolygonMesh& m_pm;
  VertexPointMap m_vpm;
  Indices m_idx;
  Edge_weighting m_weighting;
  internal::Barycentric_stencil m_stencil;
  internal::Sparse_matrix m_coupling;
  internal::Factored_system<SolverTraits> m_symmetric;
  internal::Factored_system<Sparse_lu_solver_traits> m_lu;
};

/// Deduces the point map and solver types from the named parameters.
template <class PolygonMesh, class FixedVertices, class NamedParameters>
Barycentric_embedder(PolygonMesh&, const FixedVertices&, const NamedParameters&)
  -> Barycentric_embedder<PolygonMesh, internal::Vertex_point_map_t<PolygonMesh, NamedParameters>,
                          internal::Solver_traits_t<NamedParameters>>;
template <class PolygonMesh, class FixedVertices>
Barycentric_embedder(PolygonMesh&, const FixedVertices&) -> Barycentric_embedder<PolygonMesh>;

} // namespace Surface_design
} // namespace CGAL

#endif // CGAL_SURFACE_DESIGN_BARYCENTRIC_EMBEDDER_H
