// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Boundary First Flattening: factor once, flatten with any boundary data.

#ifndef CGAL_SURFACE_DESIGN_BOUNDARY_FIRST_FLATTENER_H
#define CGAL_SURFACE_DESIGN_BOUNDARY_FIRST_FLATTENER_H

#include <CGAL/Surface_design/exceptions.h>
#include <CGAL/Surface_design/internal/Solvers/Factored_system.h>
#include <CGAL/Surface_design/internal/Core/Mesh_indices.h>
#include <CGAL/Surface_design/internal/Core/named_parameters.h>
#include <CGAL/Surface_design/internal/Core/topology.h>
#include <CGAL/Surface_design/internal/Core/validation.h>
#include <CGAL/Surface_design/internal/Developability/bff.h>
#include <CGAL/Surface_design/parameters.h>
#include <CGAL/Surface_design/solver_traits.h>

#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Named_function_parameters.h>

#include <Eigen/Core>
#include <Eigen/Sparse>

#include <boost/property_map/property_map.hpp>

#include <cmath>
#include <cstddef>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

namespace CGAL {
namespace Surface_design {

/// \ingroup PkgFlatteningRef
///
/// Flattens a triangle mesh whose connected components are topological disks into the plane by
/// Boundary First Flattening (Sawhney & Crane 2017): a conformal map determined by its boundary
/// data, computed with one sparse factorization and a few back-substitutions.
///
/// **The method.** A conformal flattening rescales the metric by e^{2u}. With A the (positive
/// semi-definite) cotangent Laplacian, K_i = 2 pi - sum of angles at interior vertex i and
/// k_j = pi - sum of angles at boundary vertex j, the discrete Yamabe equation
///   A_II u_I = -K_I - A_IB u_B
/// makes every interior vertex flat, and the boundary then turns by
///   k~_B = k_B + A_BI u_I + A_BB u_B   (the Dirichlet-to-Neumann map; sum over a loop: 2 pi).
/// Every boundary loop becomes the closed polygon with these turning angles whose edge lengths
/// l~ are closest to the targets e^{(u_i + u_j)/2} l_ij (a 2 x 2 solve per loop), and the
/// interior is the harmonic extension of that polygon (two solves with the same A_II).
///
/// Three kinds of boundary data:
/// - `flatten()`: u_B = 0, the boundary keeps its lengths; the flattening with the least area
///   distortion (the paper's choice for fabrication: a developable piece maps isometrically);
/// - `flatten_with_scale_factors()`: given u_B (log of the length scale along the boundary);
/// - `flatten_with_turning_angles()`: given k~_B (e.g. pi/2 at four corners and 0 elsewhere
///   for a rectangle); u_B follows from the Neumann problem A u = [-K_I; k~_B - k_B] (factored
///   on first use), its constant fixed so that every loop keeps its length.
///
/// **Seams.** Coordinates are per vertex: flatten a mesh cut into disks
/// (`cut_mesh_along_edges()`), whose vertices are the corners of the original mesh.
///
/// \tparam TriangleMesh a model of `FaceListGraph` and `HalfedgeListGraph`, triangles only
/// \tparam VertexPointMap a readable vertex -> `Point_3` property map
/// \tparam SolverTraits a model of `SparseLinearAlgebraWithFactorTraits_d` for symmetric positive
///         definite systems
template <class TriangleMesh,
          class VertexPointMap = typename boost::property_map<TriangleMesh, CGAL::vertex_point_t>::const_type,
          class SolverTraits = Default_solver_traits>
class Boundary_first_flattener
{
  using GT = boost::graph_traits<TriangleMesh>;
  using Indices = internal::Mesh_indices<TriangleMesh>;

public:
  using vertex_descriptor = typename GT::vertex_descriptor;

  /// Validates the mesh, checks that every connected component is a disk, builds the Laplacian
  /// and factors its interior block.
  ///
  /// \param tm the mesh; its connectivity and positions must not change while the object is used
  /// \param np an optional sequence of named parameters among the ones listed below
  ///
  /// \cgalNamedParamsBegin
  ///   \cgalParamNBegin{vertex_point_map}
  ///     \cgalParamDescription{a property map associating points to the vertices of `tm`}
  ///     \cgalParamType{a class model of `ReadablePropertyMap` with
  ///                    `boost::graph_traits<TriangleMesh>::%vertex_descriptor` as key type and `%Point_3` as
  ///                    value type, convertible to `VertexPointMap`}
  ///     \cgalParamDefault{`boost::get(CGAL::vertex_point, tm)`}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{sparse_linear_solver}
  ///     \cgalParamDescription{the sparse solver that factors the cotangent Laplacian of the interior vertices
  ///                           (on the first `flatten_with_turning_angles()`, a new object of the same type
  ///                           factors the shifted Laplacian of all vertices)}
  ///     \cgalParamType{`SolverTraits`, a model of `SparseLinearAlgebraWithFactorTraits_d` (class template
  ///                    argument deduction takes the class's `SolverTraits` from this parameter)}
  ///     \cgalParamDefault{`SolverTraits()`}
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
  /// \throws Invalid_mesh the mesh is empty, not a triangle mesh, not manifold, has degenerate
  ///         faces or non-finite coordinates, or a component is not a disk (`not_a_disk`)
  /// \throws Linear_solver_failure the factorization fails
  /// Complexity: O(|V|) plus one sparse factorization of size #interior vertices.
  template <class NamedParameters = CGAL::parameters::Default_named_parameters>
  explicit Boundary_first_flattener(const TriangleMesh& tm, const NamedParameters& np = CGAL::parameters::default_values())
    : m_idx(tm, np),
      m_vpm(internal::class_vertex_point_map<VertexPointMap, false>(tm, np)),
      m_dirichlet(internal::class_solver_traits<SolverTraits>(np), "Laplacian of the interior vertices (BFF)"),
      m_neumann(internal::new_solver_like(m_dirichlet.traits()), "shifted Laplacian of all vertices (BFF, Neumann problem)")
  {
    internal::validate_mesh(m_idx, m_vpm);
    const internal::Boundary_loops loops = internal::boundary_loops(m_idx);
    const internal::Components comps = internal::connected_components(m_idx, loops);
    internal::require_disks(comps);
    m_system = internal::bff_system(m_idx, m_vpm, loops);
    m_number_of_pieces = comps.size();
    if(m_system.interior_vertices.size() > 0)
      m_dirichlet.factor(Eigen::SparseMatrix<double>(m_system.A_II));
  }

  /// Number of connected components (pieces), each a disk.
  std::size_t number_of_pieces() const { return m_number_of_pieces; }
  std::size_t number_of_interior_vertices() const { return m_system.interior_vertices.size(); }
  std::size_t number_of_boundary_vertices() const { return m_system.boundary_vertices.size(); }

  /// Flattens with u_B = 0 (boundary lengths kept: least area distortion) and writes the 2-D
  /// coordinates of every vertex to `uv` (a writable vertex -> `Point_2` map). Every piece has
  /// its first boundary vertex at the origin; pieces overlap until laid out
  /// (`lay_out_flattened_pieces()`). Faces keep their orientation (counter-clockwise).
  /// \throws Linear_solver_failure only if a solve fails
  template <class UVMap>
  void flatten(UVMap uv)
  {
    solve_and_write(Eigen::VectorXd::Zero(Eigen::Index(m_system.boundary_vertices.size())), uv);
  }

  /// Flattens with given log scale factors u_B at the boundary vertices (`scale` is a readable
  /// vertex -> double map, read at boundary vertices only): boundary edge ij is scaled by about
  /// e^{(u_i + u_j)/2}.
  /// \throws Invalid_parameter (`boundary_scale_factor_map`) a value is not finite or beyond
  ///         +-50; nothing is written then
  template <class ScaleMap, class UVMap>
  void flatten_with_scale_factors(const ScaleMap& scale, UVMap uv)
  {
    Eigen::VectorXd u_B(Eigen::Index(m_system.boundary_vertices.size()));
    for(std::size_t j = 0; j < m_system.boundary_vertices.size(); ++j)
    {
      const std::size_t v = m_system.boundary_vertices[j];
      const double value = double(get(scale, m_idx.vertex(v)));
      if(!std::isfinite(value) || std::abs(value) > 50.)
        throw Invalid_parameter("boundary_scale_factor_map",
                                "the log scale factor of boundary vertex " + std::to_string(v) + " is " +
                                  internal::to_text(value) + "; it must be finite and in [-50, 50]");
      u_B[Eigen::Index(j)] = value;
    }
    solve_and_write(u_B, uv);
  }

  /// Flattens with given turning angles k~ at the boundary vertices (`turning` is a readable
  /// vertex -> double map in radians, read at boundary vertices; positive turns towards the
  /// piece). Every loop's angles must sum to 2 pi (within 1e-6) and lie in (-pi, pi).
  /// The scale factors are the solution of the Neumann problem, with the constant of each piece
  /// chosen so that its boundary keeps its length.
  /// \throws Invalid_parameter (`boundary_turning_angle_map`) an angle is not finite or out of
  ///         range, or a loop's angles do not sum to 2 pi; nothing is written then
  template <class AngleMap, class UVMap>
  void flatten_with_turning_angles(const AngleMap& turning, UVMap uv)
  {
    const Eigen::Index nb = Eigen::Index(m_system.boundary_vertices.size());
    const Eigen::Index ni = Eigen::Index(m_system.interior_vertices.size());
    Eigen::VectorXd target(nb);
    for(std::size_t l = 0; l < m_system.loops.size(); ++l)
    {
      double sum = 0.;
      for(std::size_t v : m_system.loops[l])
      {
        const double k = double(get(turning, m_idx.vertex(v)));
        if(!std::isfinite(k) || !(std::abs(k) < internal::pi))
          throw Invalid_parameter("boundary_turning_angle_map",
                                  "the turning angle of boundary vertex " + std::to_string(v) + " is " +
                                    internal::to_text(k) + "; it must be in (-pi, pi)");
        target[Eigen::Index(m_system.block_index[v])] = k;
        sum += k;
      }
      if(!(std::abs(sum - internal::two_pi) <= 1e-6))
        throw Invalid_parameter("boundary_turning_angle_map",
                                "the turning angles of boundary loop " + std::to_string(l) + " (through vertex " +
                                  std::to_string(m_system.loops[l].front()) + ") sum to " + internal::to_text(sum) +
                                  ", not 2 pi: the loop could not close");
    }
    if(!m_neumann.is_factored())
      factor_neumann();
    // A u = [-K_I; k~_B - k_B], A ordered [I; B]
    Eigen::VectorXd rhs(ni + nb);
    rhs.head(ni) = -m_system.K_I;
    rhs.tail(nb) = target - m_system.k_B;
    const Eigen::VectorXd u = m_neumann.solve(rhs);
    Eigen::VectorXd u_B = u.tail(nb);
    // per piece, the constant that keeps the boundary length
    for(std::size_t l = 0; l < m_system.loops.size(); ++l)
    {
      const auto& loop = m_system.loops[l];
      double before = 0., after = 0.;
      for(std::size_t m = 0; m < loop.size(); ++m)
      {
        const double a = u_B[Eigen::Index(m_system.block_index[loop[m]])];
        const double b = u_B[Eigen::Index(m_system.block_index[loop[(m + 1) % loop.size()]])];
        before += m_system.loop_edge_length[l][m];
        after += std::exp(0.5 * (a + b)) * m_system.loop_edge_length[l][m];
      }
      const double c = std::log(before / after);
      for(std::size_t v : loop)
        u_B[Eigen::Index(m_system.block_index[v])] += c;
    }
    solve_and_write(u_B, uv, &target);
  }

  /// The log scale factors u of the last flattening, written to a writable vertex -> double map
  /// (at interior vertices the solution of the Yamabe equation; 0 everywhere before any).
  template <class ScaleMap>
  void scale_factors(ScaleMap out) const
  {
    for(std::size_t v = 0; v < m_idx.number_of_vertices(); ++v)
    {
      const Eigen::Index j = Eigen::Index(m_system.block_index[v]);
      double value = 0.;
      if(m_last_u_B.size() > 0)
        value = m_system.is_boundary[v] ? m_last_u_B[j] : m_last_u_I[j];
      put(out, m_idx.vertex(v), value);
    }
  }

private:
  void factor_neumann()
  {
    const Eigen::Index ni = Eigen::Index(m_system.interior_vertices.size());
    const Eigen::Index nb = Eigen::Index(m_system.boundary_vertices.size());
    std::vector<Eigen::Triplet<double>> t;
    auto append = [&t](const Eigen::SparseMatrix<double>& m, Eigen::Index r0, Eigen::Index c0, bool transpose) {
      for(int k = 0; k < m.outerSize(); ++k)
        for(Eigen::SparseMatrix<double>::InnerIterator it(m, k); it; ++it)
          t.emplace_back(transpose ? c0 + it.col() : r0 + it.row(), transpose ? r0 + it.row() : c0 + it.col(),
                         it.value());
    };
    append(m_system.A_II, 0, 0, false);
    append(m_system.A_IB, 0, ni, false);
    append(m_system.A_IB, 0, ni, true);
    append(m_system.A_BB, ni, ni, false);
    Eigen::SparseMatrix<double> a(ni + nb, ni + nb);
    a.setFromTriplets(t.begin(), t.end());
    // the Laplacian's kernel (constants per piece) is lifted by a shift far below its spectrum
    double mean_diagonal = 0.;
    for(Eigen::Index i = 0; i < a.rows(); ++i)
      mean_diagonal += a.coeff(i, i);
    mean_diagonal /= double(a.rows());
    for(Eigen::Index i = 0; i < a.rows(); ++i)
      a.coeffRef(i, i) += 1e-8 * mean_diagonal;
    m_neumann.factor(std::move(a));
  }

  template <class UVMap>
  void solve_and_write(const Eigen::VectorXd& u_B, UVMap uv, const Eigen::VectorXd* given_turning = nullptr)
  {
    const Eigen::Index ni = Eigen::Index(m_system.interior_vertices.size());
    const Eigen::Index nb = Eigen::Index(m_system.boundary_vertices.size());
    Eigen::VectorXd u_I = Eigen::VectorXd::Zero(ni);
    if(ni > 0)
      u_I = m_dirichlet.solve(-m_system.K_I - m_system.A_IB * u_B);
    // the Dirichlet-to-Neumann map gives the turning angles (given ones are used as they are)
    const Eigen::VectorXd turning =
      given_turning ? *given_turning
                    : Eigen::VectorXd(m_system.k_B + m_system.A_IB.transpose() * u_I + m_system.A_BB * u_B);

    Eigen::VectorXd x_B(nb), y_B(nb);
    for(std::size_t l = 0; l < m_system.loops.size(); ++l)
    {
      const auto& loop = m_system.loops[l];
      std::vector<double> target(loop.size()), k(loop.size());
      for(std::size_t m = 0; m < loop.size(); ++m)
      {
        const double a = u_B[Eigen::Index(m_system.block_index[loop[m]])];
        const double b = u_B[Eigen::Index(m_system.block_index[loop[(m + 1) % loop.size()]])];
        target[m] = std::exp(0.5 * (a + b)) * m_system.loop_edge_length[l][m];
        k[m] = turning[Eigen::Index(m_system.block_index[loop[m]])];
      }
      const std::vector<Eigen::Vector2d> curve = internal::close_boundary_curve(target, k);
      for(std::size_t m = 0; m < loop.size(); ++m)
      {
        x_B[Eigen::Index(m_system.block_index[loop[m]])] = curve[m].x();
        y_B[Eigen::Index(m_system.block_index[loop[m]])] = curve[m].y();
      }
    }
    Eigen::VectorXd x_I(ni), y_I(ni);
    if(ni > 0)
    {
      x_I = m_dirichlet.solve(-(m_system.A_IB * x_B));
      y_I = m_dirichlet.solve(-(m_system.A_IB * y_B));
    }
    using Point_2 = typename boost::property_traits<UVMap>::value_type;
    for(std::size_t v = 0; v < m_idx.number_of_vertices(); ++v)
    {
      const Eigen::Index j = Eigen::Index(m_system.block_index[v]);
      if(m_system.is_boundary[v])
        put(uv, m_idx.vertex(v), Point_2(x_B[j], y_B[j]));
      else
        put(uv, m_idx.vertex(v), Point_2(x_I[j], y_I[j]));
    }
    m_last_u_B = u_B;
    m_last_u_I = u_I;
  }

  Indices m_idx;
  VertexPointMap m_vpm;
  internal::Bff_system m_system;
  std::size_t m_number_of_pieces = 0;
  internal::Factored_system<SolverTraits> m_dirichlet, m_neumann;
  Eigen::VectorXd m_last_u_B, m_last_u_I;
};

/// Deduces the point map and solver types from the named parameters.
template <class TriangleMesh, class NamedParameters>
Boundary_first_flattener(const TriangleMesh&, const NamedParameters&)
  -> Boundary_first_flattener<TriangleMesh, internal::Const_vertex_point_map_t<TriangleMesh, NamedParameters>,
                              internal::Solver_traits_t<NamedParameters>>;
template <class TriangleMesh>
Boundary_first_flattener(const TriangleMesh&) -> Boundary_first_flattener<TriangleMesh>;

} // namespace Surface_design
} // namespace CGAL

#endif // CGAL_SURFACE_DESIGN_BOUNDARY_FIRST_FLATTENER_H
