// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Smoothest vertex-based n-direction fields (Knöppel, Crane, Pinkall & Schröder 2013) and the
// singularity index of a direction field in every face.

#ifndef CGAL_SURFACE_DESIGN_DIRECTION_FIELDS_H
#define CGAL_SURFACE_DESIGN_DIRECTION_FIELDS_H

#include <CGAL/Surface_design/exceptions.h>
#include <CGAL/Surface_design/internal/Core/angles.h>
#include <CGAL/Surface_design/internal/Core/boundary_smoothing.h>
#include <CGAL/Surface_design/internal/Core/dec.h>
#include <CGAL/Surface_design/internal/Core/discrete_connection.h>
#include <CGAL/Surface_design/internal/Core/geometry.h>
#include <CGAL/Surface_design/internal/Solvers/Hermitian_system.h>
#include <CGAL/Surface_design/internal/Core/Mesh_indices.h>
#include <CGAL/Surface_design/internal/Core/named_parameters.h>
#include <CGAL/Surface_design/internal/Solvers/shift_invert_lanczos.h>
#include <CGAL/Surface_design/internal/Core/topology.h>
#include <CGAL/Surface_design/internal/Core/validation.h>
#include <CGAL/Surface_design/internal/Direction_fields/direction_field_operators.h>
#include <CGAL/Surface_design/parameters.h>
#include <CGAL/Surface_design/solver_traits.h>

#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Named_function_parameters.h>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <random>
#include <string>
#include <vector>

namespace CGAL {
namespace Surface_design {

/// \ingroup PkgDirectionFieldsRef
/// What a smoothest direction field does at the boundary.
enum class Direction_field_boundary
{
  free,    ///< no condition (natural boundary): the eigenproblem on the whole component
  tangent, ///< one direction along the boundary (boundary oriented with the surface on its left)
  normal   ///< one direction along the inward boundary normal
};

/// \ingroup PkgDirectionFieldsRef
/// What `smoothest_direction_field()` computed.
struct Smoothest_direction_field_result
{
  /// Per connected component: the smallest eigenvalue lambda of A u = lambda M u (the normalized
  /// connection energy E(u) / <u, M u> of the returned field) for components solved as an
  /// eigenproblem; NaN for components with a boundary condition or with curvature alignment,
  /// which are solved as one linear system.
  std::vector<double> eigenvalues;
  /// Lanczos steps (back-substitutions), 0 when no eigenproblem was solved.
  std::size_t iterations = 0;
  /// False if the eigensolver stopped at the iteration limit before reaching the tolerance.
  bool converged = true;
  /// True if the cotangent connection Laplacian was indefinite (possible for n = 4 on meshes with
  /// obtuse triangles) and the field was computed with its negative edge weights set to 0.
  bool weights_clamped = false;
  /// Vertices whose direction the feature edges (`edge_is_constrained_map`) fixed.
  std::size_t feature_vertices = 0;
};


/// \ingroup PkgDirectionFieldsRef
///
/// Computes the smoothest vertex-based n-direction field of a triangle mesh (Knöppel et al.
/// 2013) and writes one of its n directions per vertex to `field` (the others are its rotations
/// by multiples of 2 pi / n in the vertex tangent plane, in the rescaled angles of the frames).
///
/// **Representation.** At vertex v the field is the complex number u_v = |u_v| exp(i n theta_v)
/// in the angle-rescaled vertex frame (corner angles scaled to sum to 2 pi at interior vertices,
/// kept at boundary vertices); theta_v is the angle of the direction. The Levi-Civita transport rotates by rho_ij
/// along each edge (see the manual).
///
/// **Energy.** E(u) = sum_edges w_ij |u_j - exp(i n rho_ij) u_i|^2 with cotangent weights, the
/// Hermitian connection Laplacian A; M the lumped (barycentric) mass matrix. The library's own
/// solver traits factor A in complex arithmetic; any other traits factor its real symmetric form
/// of size 2|V| (`internal::Hermitian_system`).
///  - No boundary condition, no alignment: u is the eigenvector of the smallest eigenvalue of
///    A u = lambda M u, computed per connected component by shift-invert Lanczos (M inner
///    product, full reorthogonalization) on one factorization of A + eps M (eps = 1e-8 trace(A) /
///    trace(M), which keeps the matrix positive definite when lambda = 0 and does not change the
///    eigenvectors), from a fixed pseudo-random start, until the Lanczos residual is below
///    `eigen_tolerance` relative to the eigenvalue (the eigenvalue is then accurate to about its
///    square). Typically 10 to 20 back-substitutions, where plain inverse iteration needs 40 to
///    several hundred (near-degenerate eigenvalues, e.g. on a round sphere).
///  - `field_boundary_condition(Direction_field_boundary::tangent or normal)`: on components with
///    boundary, u is fixed at the boundary vertices to the boundary tangent (or inward normal) and
///    the interior minimizes E: one linear solve (Knöppel et al., sec. 6.1). Its zeros cluster
///    where the boundary data must wind (a disk: all n of them at the centre, |u| ~ r^n), and
///    `unit_length_iterations(k)` moves them apart: k steps of the implicit flow
///    (A + s M) u' = s M u / |u| (boundary values kept, s = 100 / the component's area), whose
///    rest points minimize E(u) + s sum_v m_v |u_v - u_v / |u_v||^2, a Ginzburg-Landau-like
///    penalty with a core about a tenth of the component's size: the singularities of a unit
///    field, kept apart by their interaction energy (the hemisphere: four +1/n cones around the
///    pole instead of a cluster at it).
///  - `curvature_alignment_weight(t) > 0` (n even): minimizes E(u) + t sum_v m~_v |u_v - q_v|^2
///    where q is the principal curvature direction field (n = 2: the larger principal curvature
///    direction; n = 4: both), with magnitude |kappa_1 - kappa_2| scaled to area-weighted RMS 1,
///    and m~ the vertex areas scaled to average 1: one linear solve of (A + t M~) u = t M~ q.
///    This is Knöppel et al.'s alignment family (their (A - lambda_t M) u = M q with
///    lambda_t = -t); t is dimensionless, about the strength of one edge's coupling per vertex.
///
/// \param tm a triangle mesh (validated: no degenerate, non-manifold or non-triangle face)
/// \param field a writable vertex -> `Vector_3` property map; receives unit tangent vectors
///        (tangent to the angle-weighted vertex normal), or vectors of length |u_v| with
///        `normalize_field(false)` (u scaled on each connected component to sum_v m_v |u_v|^2 = the
///        component's area; |u| falls to 0 near singularities); written only if the computation
///        succeeds.
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
///     \cgalParamDescription{the sparse solver that factors the (shifted) Hermitian connection Laplacian: the
///                           library's own solver traits in complex arithmetic, any other in its real
///                           symmetric form of size 2|V|}
///     \cgalParamType{a class model of `SparseLinearAlgebraWithFactorTraits_d`}
///     \cgalParamDefault{`Default_solver_traits` (`Size_switched_cholesky`: the simplicial LDLT below 20000
///                       unknowns, the supernodal Cholesky from there)}
///   \cgalParamNEnd
///   \cgalParamNBegin{symmetry_order}
///     \cgalParamDescription{the symmetry order n of the field: 1 vector field, 2 line field, 4 cross field,
///                           ...}
///     \cgalParamType{`int`}
///     \cgalParamDefault{`1` (vector field)}
///     \cgalParamExtra{throws `Invalid_parameter` if n < 1}
///   \cgalParamNEnd
///   \cgalParamNBegin{field_boundary_condition}
///     \cgalParamDescription{what the field does at the boundary of the components that have one: `free` (no
///                           condition), `tangent` or `normal` (fixed at the boundary vertices, the interior
///                           by one linear solve)}
///     \cgalParamType{`Direction_field_boundary`}
///     \cgalParamDefault{`Direction_field_boundary::free`}
///     \cgalParamExtra{throws `Invalid_parameter` if it is not an enumerator of `Direction_field_boundary`}
///   \cgalParamNEnd
///   \cgalParamNBegin{boundary_smoothing_length}
///     \cgalParamDescription{with `tangent` or `normal`: the length L at which the boundary's direction is
///                           smoothed before the field follows it. 0 follows every boundary edge; L > 0
///                           straightens what zigzags at a scale below L (a cut through a triangulation, a
///                           staircase) and keeps the corners where the boundary turns by 67.5 degrees or more
///                           within L (see `Trivial_connection`, which takes the same parameter; the quads of
///                           `field_aligned_quad_remeshing()` want the same L as their field, about their edge
///                           length)}
///     \cgalParamType{`double`}
///     \cgalParamDefault{`0`}
///     \cgalParamExtra{throws `Invalid_parameter` if it is negative or not finite}
///   \cgalParamNEnd
///   \cgalParamNBegin{edge_is_constrained_map}
///     \cgalParamDescription{the feature edges (creases, e.g. from
///                           `CGAL::Polygon_mesh_processing::detect_sharp_edges()`): at a vertex inside a line of
///                           interior feature edges (two of them) or at its end (one), one direction of the field
///                           lies along them: u is fixed there to the normalized mean of exp(i n theta) over the
///                           edges' rescaled angles theta, as at a boundary with `tangent`, where the two agree
///                           (|mean| at least half their count: for n = 4 a line that turns by at most 30
///                           degrees there). Corners (three feature edges or more) and sharper turns stay free:
///                           the field's singularities may sit there (a -1/4 cone next to a saddle-like corner).
///                           Boundary edges are left to `field_boundary_condition`. A component with such
///                           vertices is solved as with a boundary condition (one linear solve, then
///                           `unit_length_iterations`)}
///     \cgalParamType{a class model of `ReadablePropertyMap` with
///                    `boost::graph_traits<TriangleMesh>::%edge_descriptor` as key type and `bool` as value type}
///     \cgalParamDefault{none: no feature edge}
///   \cgalParamNEnd
///   \cgalParamNBegin{curvature_alignment_weight}
///     \cgalParamDescription{the weight t of the alignment with the principal curvature directions; 0: no
///                           alignment}
///     \cgalParamType{`double`}
///     \cgalParamDefault{`0`}
///     \cgalParamExtra{throws `Invalid_parameter` if it is negative or not finite, or if it is positive and
///                     `symmetry_order` is odd or the curvature tensor of the mesh vanishes everywhere}
///   \cgalParamNEnd
///   \cgalParamNBegin{unit_length_iterations}
///     \cgalParamDescription{steps of the normalized flow after the linear solve on components with a boundary
///                           condition (above); ignored with curvature alignment and on components without one}
///     \cgalParamType{`int`, in [0, 1000]}
///     \cgalParamDefault{`0`}
///     \cgalParamExtra{throws `Invalid_parameter` if out of range}
///   \cgalParamNEnd
///   \cgalParamNBegin{normalize_field}
///     \cgalParamDescription{`true`: unit tangent vectors; `false`: vectors of length |u_v|, u scaled per
///                           connected component to sum_v m_v |u_v|^2 = the component's area}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`true`}
///   \cgalParamNEnd
///   \cgalParamNBegin{eigen_tolerance}
///     \cgalParamDescription{the Lanczos residual, relative to the eigenvalue, at which the eigensolver
///                           stops}
///     \cgalParamType{`double`}
///     \cgalParamDefault{`1e-6`}
///     \cgalParamExtra{throws `Invalid_parameter` if it is not in (0, 1)}
///   \cgalParamNEnd
///   \cgalParamNBegin{number_of_iterations}
///     \cgalParamDescription{the largest number of Lanczos steps (back-substitutions); `converged` is false
///                           in the result if the eigensolver stopped there}
///     \cgalParamType{`std::size_t`}
///     \cgalParamDefault{`200`}
///     \cgalParamExtra{throws `Invalid_parameter` if it is 0}
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
/// \returns the eigenvalue per component, the number of Lanczos steps and whether they converged
/// \throws Invalid_mesh on bad input (the mesh is never modified)
/// \throws Invalid_parameter if n < 1, t < 0 or not finite, the tolerance is not in (0, 1), the
///         iteration limit is 0, or curvature alignment is asked for with an odd n or on a
///         surface whose curvature tensor vanishes everywhere (a plane has no principal directions)
/// \throws Linear_solver_failure if the connection Laplacian is not positive definite (possible
///         with many negative cotangent weights) or the solver fails
///
/// Complexity: one sparse Hermitian factorization of size |V| and, for the eigenproblem, one
/// back-substitution per Lanczos step (typically 10 to 20).
namespace internal {

// `steps` steps of (A + s M) u' = s M u / |u| on the components of the Dirichlet vertices `fixed`
// (their values kept, and the other components'), s = 100 / the component's area; x: u, (Re, Im)
// interleaved. Where A + s M is not positive definite on the free vertices (obtuse triangles'
// negative cotangent weights), the field is left as the linear solve made it.
template <class Solver, class NamedParameters>
void unit_length_flow(const Complex_sparse_matrix& a_energy, const std::vector<double>& mass, const std::vector<bool>& fixed,
                      const Components& comps, int steps, const NamedParameters& np, Eigen::VectorXd& x)
{
  const std::size_t nv = mass.size();
  std::vector<double> area(comps.info.size(), 0.);
  std::vector<bool> with_boundary(comps.info.size(), false);
  for(std::size_t v = 0; v < nv; ++v)
  {
    area[comps.vertex_component[v]] += mass[v];
    if(fixed[v])
      with_boundary[comps.vertex_component[v]] = true;
  }
  // the vertices kept: the Dirichlet ones and those of components without boundary condition
  std::vector<bool> kept(nv);
  std::vector<double> s(nv, 0.);
  Eigen::VectorXcd u_kept = Eigen::VectorXcd::Zero(Eigen::Index(nv));
  for(std::size_t v = 0; v < nv; ++v)
  {
    const std::size_t c = comps.vertex_component[v];
    kept[v] = fixed[v] || !with_boundary[c];
    s[v] = with_boundary[c] ? 100. / area[c] : 0.;
    if(kept[v])
      u_kept[Eigen::Index(v)] = {x[Eigen::Index(2 * v)], x[Eigen::Index(2 * v + 1)]};
  }
  Complex_sparse_matrix a = a_energy;
  const Eigen::VectorXcd coupling = a * u_kept;
  a.prune([&kept](Eigen::Index i, Eigen::Index j, const std::complex<double>&) {
    return !kept[std::size_t(i)] && !kept[std::size_t(j)];
  });
  for(std::size_t v = 0; v < nv; ++v)
    a.coeffRef(Eigen::Index(v), Eigen::Index(v)) += kept[v] ? 1. : s[v] * mass[v];
  a.makeCompressed();
  Hermitian_system<Solver> flow(solver_traits(np), "normalized flow");
  try
  {
    flow.factor(std::move(a));
  }
  catch(const Linear_solver_failure&)
  {
    return;
  }
  Eigen::VectorXd rhs(Eigen::Index(2 * nv)), y(Eigen::Index(2 * nv));
  for(int step = 0; step < steps; ++step)
  {
    for(std::size_t v = 0; v < nv; ++v)
    {
      const Eigen::Index r = Eigen::Index(v);
      const std::complex<double> u(x[2 * r], x[2 * r + 1]);
      const std::complex<double> b =
        kept[v] ? u : s[v] * mass[v] * (std::abs(u) > 0. ? u / std::abs(u) : u) - coupling[r];
      rhs[2 * r] = b.real(), rhs[2 * r + 1] = b.imag();
    }
    flow.solve(rhs, y);
    x = y;
  }
}

} // namespace internal

template <class TriangleMesh, class VertexVectorMap,
          class NamedParameters = CGAL::parameters::Default_named_parameters>
Smoothest_direction_field_result smoothest_direction_field(const TriangleMesh& tm, VertexVectorMap field,
                                                         const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  using Solver = internal::Solver_traits_t<NamedParameters>;
  const auto vpm = internal::const_vertex_point_map(tm, np);
  const int n = choose_parameter(get_parameter(np, internal_np::symmetry_order), 1);
  const Direction_field_boundary boundary =
    choose_parameter(get_parameter(np, internal_np::field_boundary_condition), Direction_field_boundary::free);
  const double alignment = choose_parameter(get_parameter(np, internal_np::curvature_alignment_weight), 0.);
  const bool normalize = choose_parameter(get_parameter(np, internal_np::normalize_field), true);
  const double smoothing = choose_parameter(get_parameter(np, internal_np::boundary_smoothing_length), 0.);
  const int flow_steps = choose_parameter(get_parameter(np, internal_np::unit_length_iterations), 0);
  const double tolerance = choose_parameter(get_parameter(np, internal_np::eigen_tolerance), 1e-6);
  const std::size_t max_iterations =
    choose_parameter(get_parameter(np, CGAL::internal_np::number_of_iterations), std::size_t(200));

  internal::check_symmetry_order(n);
  internal::require_nonnegative("curvature_alignment_weight", alignment);
  internal::require_nonnegative("boundary_smoothing_length", smoothing);
  internal::require_in_range("eigen_tolerance", tolerance, 0., 1., true, true);
  internal::require_at_least("number_of_iterations", max_iterations, std::size_t(1));
  if(flow_steps < 0 || flow_steps > 1000)
    throw Invalid_parameter("unit_length_iterations", "must lie in [0, 1000], got " + std::to_string(flow_steps));
  if(boundary != Direction_field_boundary::free && boundary != Direction_field_boundary::tangent &&
     boundary != Direction_field_boundary::normal)
    throw Invalid_parameter("field_boundary_condition", "not a Direction_field_boundary enumerator");
  if(alignment > 0. && n % 2 != 0)
    throw Invalid_parameter("curvature_alignment_weight",
                            "curvature alignment needs an even symmetry order (n = 2: line field, "
                            "n = 4: cross field): principal directions have no orientation");

  const internal::Mesh_indices<TriangleMesh> idx(tm, np);
  internal::validate_mesh(idx, vpm);
  const std::size_t nv = idx.number_of_vertices();
  const internal::Discrete_connection conn = internal::levi_civita_connection(idx, vpm);
  std::vector<double> weight = internal::cotangent_weights(idx, vpm);
  const std::vector<double> mass = internal::vertex_areas(idx, internal::face_areas(idx, vpm));
  const internal::Boundary_loops loops = internal::boundary_loops(idx);
  const internal::Components comps = internal::connected_components(idx, loops);
  const std::size_t nc = comps.info.size();

  // Which components are an eigenproblem, and which vertices carry a Dirichlet value.
  std::vector<bool> eigen_component(nc, alignment == 0.);
  std::vector<bool> fixed(nv, false);
  Eigen::VectorXd fixed_value = Eigen::VectorXd::Zero(Eigen::Index(2 * nv));
  if(boundary != Direction_field_boundary::free)
  {
    const double direction = boundary == Direction_field_boundary::tangent ? 0. : internal::pi / 2.;
    // the boundary's direction, smoothed at `boundary_smoothing_length` (0: edge by edge)
    const std::vector<double> offset = smoothing > 0. ? internal::smoothed_boundary(idx, vpm, loops, smoothing).offset
                                                      : std::vector<double>(nv, 0.);
    for(const auto& loop : loops.loops)
      for(std::size_t h : loop)
      {
        // the border halfedge h runs against the boundary orientation; its target's outgoing
        // boundary halfedge has rescaled angle 0, so the tangent is angle 0, the inward normal pi/2
        const std::size_t v = idx.target_index(idx.halfedge(h));
        fixed[v] = true;
        eigen_component[comps.vertex_component[v]] = false;
        fixed_value[Eigen::Index(2 * v)] = std::cos(n * (direction + offset[v]));
        fixed_value[Eigen::Index(2 * v + 1)] = std::sin(n * (direction + offset[v]));
      }
  }
  // feature edges: one direction along them at their vertices (see `edge_is_constrained_map`)
  std::size_t feature_vertices = 0;
  internal::if_given(np, CGAL::internal_np::edge_is_constrained, [&](const auto& ecm) {
    std::vector<std::complex<double>> sum(nv, 0.);
    std::vector<int> count(nv, 0);
    for(std::size_t h = 0; h < idx.number_of_halfedges(); ++h)
    {
      const auto hd = idx.halfedge(h);
      if(idx.is_border(hd) || idx.is_border(opposite(hd, tm)) || !get(ecm, edge(hd, tm)))
        continue;
      const std::size_t v = idx.source_index(hd);
      sum[v] += std::polar(1., n * conn.frames.angle[h]);
      ++count[v];
    }
    for(std::size_t v = 0; v < nv; ++v)
      if((count[v] == 1 || count[v] == 2) && !fixed[v] && std::abs(sum[v]) >= 0.5 * count[v])
      {
        fixed[v] = true;
        eigen_component[comps.vertex_component[v]] = false;
        const std::complex<double> u = sum[v] / std::abs(sum[v]);
        fixed_value[Eigen::Index(2 * v)] = u.real();
        fixed_value[Eigen::Index(2 * v + 1)] = u.imag();
        ++feature_vertices;
      }
  });
  const bool any_fixed = std::find(fixed.begin(), fixed.end(), true) != fixed.end();
  const bool any_eigen = std::find(eigen_component.begin(), eigen_component.end(), true) != eigen_component.end();

  // The system matrix: A + s M with s = eps (eigenproblem) or t * V / area (alignment);
  // Dirichlet rows and columns replaced by the identity. Vectors are complex, stored with
  // (Re, Im) interleaved in real vectors.
  // With cotangent weights, obtuse triangles can make A indefinite, the more so as n grows (for
  // n = 4: kitten and camelhead among the shared meshes): its smallest eigenvector would then be
  // a field of negative energy. The factorization detects it
  // (a negative pivot), and the system is rebuilt with the negative weights set to 0.
  auto as_complex = [nv](Eigen::VectorXd& u) {
    return Eigen::Map<Eigen::VectorXcd>(reinterpret_cast<std::complex<double>*>(u.data()), Eigen::Index(nv));
  };
  internal::Complex_sparse_matrix a_energy;
  Eigen::VectorXd rhs_fixed;
  internal::Hermitian_system<Solver> system(internal::solver_traits(np), "connection Laplacian");
  bool weights_clamped = false;
  for(;;)
  {
    internal::Complex_sparse_matrix a = internal::complex_connection_laplacian(idx, conn, weight, n);
    a_energy = a;
    double total_mass = 0.;
    for(double m : mass)
      total_mass += m;
    const double eps_shift = 1e-8 * a.diagonal().real().sum() / total_mass;
    const double mass_scale = double(nv) / total_mass; // m~ = mass_scale * m
    std::vector<double> shift(nv);
    for(std::size_t v = 0; v < nv; ++v)
      shift[v] = (eigen_component[comps.vertex_component[v]] ? eps_shift : alignment * mass_scale) * mass[v];

    rhs_fixed = Eigen::VectorXd::Zero(Eigen::Index(2 * nv)); // constant part of the rhs
    if(alignment > 0.)
    {
      std::vector<std::complex<double>> q = internal::principal_curvature_directions(idx, vpm, conn);
      for(auto& z : q)
        z = n == 2 ? z : (std::abs(z) > 0. ? std::pow(z, n / 2) / std::pow(std::abs(z), n / 2 - 1) : 0.);
      double rms = 0.;
      for(std::size_t v = 0; v < nv; ++v)
        rms += mass[v] * std::norm(q[v]);
      rms = std::sqrt(rms / total_mass);
      if(!(rms > 0.))
        throw Invalid_parameter("curvature_alignment_weight", "curvature alignment is undefined on this mesh: its curvature tensor "
                                  "vanishes everywhere (a planar surface has no principal directions)");
      for(std::size_t v = 0; v < nv; ++v)
        as_complex(rhs_fixed)[Eigen::Index(v)] = shift[v] * q[v] / rms;
    }
    if(any_fixed)
    {
      const Eigen::VectorXcd coupling = a * as_complex(fixed_value);
      for(std::size_t v = 0; v < nv; ++v)
      {
        const Eigen::Index r = Eigen::Index(v);
        as_complex(rhs_fixed)[r] = fixed[v] ? as_complex(fixed_value)[r] : as_complex(rhs_fixed)[r] - coupling[r];
      }
      a.prune([&fixed](Eigen::Index i, Eigen::Index j, const std::complex<double>&) {
        return !fixed[std::size_t(i)] && !fixed[std::size_t(j)];
      });
    }
    for(std::size_t v = 0; v < nv; ++v)
      a.coeffRef(Eigen::Index(v), Eigen::Index(v)) += fixed[v] ? 1. : shift[v];
    a.makeCompressed();
    try
    {
      system.factor(std::move(a));
      break;
    }
    catch(const Linear_solver_failure&)
    {
      if(weights_clamped || *std::min_element(weight.begin(), weight.end()) >= 0.)
        throw;
      for(double& w : weight)
        w = (std::max)(w, 0.);
      weights_clamped = true;
    }
  }

  Smoothest_direction_field_result info;
  info.weights_clamped = weights_clamped;
  info.feature_vertices = feature_vertices;
  info.eigenvalues.assign(nc, std::numeric_limits<double>::quiet_NaN());
  Eigen::VectorXd x = Eigen::VectorXd::Zero(Eigen::Index(2 * nv));
  if(!std::all_of(eigen_component.begin(), eigen_component.end(), [](bool b) { return b; }))
    system.solve(rhs_fixed, x); // boundary conditions and alignment: one linear solve
  if(flow_steps > 0 && alignment == 0. && any_fixed)
    internal::unit_length_flow<Solver>(a_energy, mass, fixed, comps, flow_steps, np, x);
  if(any_eigen)
  {
    // the smallest eigenvector of every remaining component: shift-invert Lanczos on A + eps M,
    // from a fixed pseudo-random start (reproducible results)
    std::vector<std::size_t> group(std::size_t(2 * nv));
    Eigen::VectorXd mass2(Eigen::Index(2 * nv)), start(Eigen::Index(2 * nv));
    std::mt19937 random(20130721u);
    for(std::size_t r = 0; r < group.size(); ++r)
    {
      group[r] = comps.vertex_component[r / 2];
      mass2[Eigen::Index(r)] = mass[r / 2];
      start[Eigen::Index(r)] = eigen_component[group[r]] ? 2. * (double(random()) / 4294967296.) - 1. : 0.;
    }
    const internal::Lanczos_result eig = internal::largest_eigenvectors_by_group(
      [&system](const Eigen::VectorXd& b, Eigen::VectorXd& y) { system.solve(b, y); }, mass2, group,
      eigen_component, start, tolerance, max_iterations);
    info.iterations = eig.solves;
    info.converged = eig.converged;
    for(Eigen::Index r = 0; r < x.size(); ++r)
      if(eigen_component[group[std::size_t(r)]])
        x[r] = eig.x[r];
    // the normalized energy of the result, from A itself
    const Eigen::VectorXcd ax = a_energy * as_complex(x);
    std::vector<double> num(nc, 0.), den(nc, 0.);
    for(std::size_t v = 0; v < nv; ++v)
    {
      const std::complex<double> u = as_complex(x)[Eigen::Index(v)];
      num[comps.vertex_component[v]] += (std::conj(u) * ax[Eigen::Index(v)]).real();
      den[comps.vertex_component[v]] += mass[v] * std::norm(u);
    }
    for(std::size_t c = 0; c < nc; ++c)
      if(eigen_component[c])
        info.eigenvalues[c] = num[c] / den[c];
  }

  // Output: direction arg(u) / n; magnitude |u| scaled to sum m |u|^2 = area per component.
  std::vector<double> comp_area(nc, 0.), comp_norm2(nc, 0.);
  for(std::size_t v = 0; v < nv; ++v)
  {
    const std::size_t c = comps.vertex_component[v];
    comp_area[c] += mass[v];
    comp_norm2[c] += mass[v] * (x[Eigen::Index(2 * v)] * x[Eigen::Index(2 * v)] +
                                x[Eigen::Index(2 * v + 1)] * x[Eigen::Index(2 * v + 1)]);
  }
  std::vector<double> angle(nv), magnitude;
  if(!normalize)
    magnitude.resize(nv);
  for(std::size_t v = 0; v < nv; ++v)
  {
    const std::complex<double> u(x[Eigen::Index(2 * v)], x[Eigen::Index(2 * v + 1)]);
    angle[v] = std::arg(u) / n;
    if(!normalize)
    {
      const std::size_t c = comps.vertex_component[v];
      magnitude[v] = comp_norm2[c] > 0. ? std::abs(u) * std::sqrt(comp_area[c] / comp_norm2[c]) : 0.;
    }
  }
  internal::write_field(idx, conn.frames, angle, magnitude, field);
  return info;
}

/// \ingroup PkgDirectionFieldsRef
///
/// Computes the singularity index of a vertex-based n-direction field in every face and writes
/// it to `face_index` as an integer k, the index in units of 1/n (the library's convention:
/// k = 1 is a +1/4 singularity of a cross field, a +1 singularity of a vector field).
///
/// The field is given by one of its n directions per vertex (vectors are projected to the vertex
/// tangent planes; their length is ignored). Around a face, each edge contributes the smallest
/// turn of the n-fold direction relative to the Levi-Civita transport along the edge, and the
/// transport contributes the face curvature; the total, divided by 2 pi, is k. Boundary
/// faces get indices like any other face (their boundary edges included), so that on every
/// closed surface the indices sum to n times the Euler characteristic (Poincaré-Hopf), and on a
/// surface with boundary to n chi plus the turning of the field along the boundary relative to it.
///
/// \param tm a triangle mesh
/// \param field a readable vertex -> `Vector_3` map
/// \param face_index a writable face -> integer map (output), written only on success
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
///   \cgalParamNBegin{symmetry_order}
///     \cgalParamDescription{the symmetry order n of the field: 1 vector field, 2 line field, 4 cross field,
///                           ...}
///     \cgalParamType{`int`}
///     \cgalParamDefault{`1` (vector field)}
///     \cgalParamExtra{throws `Invalid_parameter` if n < 1}
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
/// \returns the number of faces with a non-zero index
/// \throws Invalid_mesh on bad input; Invalid_parameter if n < 1, or if a field vector is zero,
///         normal to the surface or not finite (its direction, and the index of the faces around
///         it, are undefined)
///
/// Complexity: O(|E|).
template <class TriangleMesh, class VertexVectorMap, class FaceIndexMap,
          class NamedParameters = CGAL::parameters::Default_named_parameters>
std::size_t direction_field_singularities(const TriangleMesh& tm, const VertexVectorMap& field,
                                          FaceIndexMap face_index,
                                          const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  const auto vpm = internal::const_vertex_point_map(tm, np);
  const int n = choose_parameter(get_parameter(np, internal_np::symmetry_order), 1);
  internal::check_symmetry_order(n);
  const internal::Mesh_indices<TriangleMesh> idx(tm, np);
  internal::validate_mesh(idx, vpm);
  const internal::Discrete_connection conn = internal::levi_civita_connection(idx, vpm);
  const std::vector<double> angle = internal::field_angles(idx, conn.frames, field);
  const std::vector<int> k = internal::field_index_numerators(idx, conn, angle, n);
  std::size_t count = 0;
  for(std::size_t f = 0; f < k.size(); ++f)
  {
    put(face_index, idx.face(f), k[f]);
    count += (k[f] != 0);
  }
  return count;
}

} // namespace Surface_design
} // namespace CGAL

#endif // CGAL_SURFACE_DESIGN_DIRECTION_FIELDS_H
