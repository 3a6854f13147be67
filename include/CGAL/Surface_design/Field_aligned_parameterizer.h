// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Field-aligned parameterization with prescribed singularities (Noma & Kawahara), solved exactly
// in vertex space: one factorization of the cotangent Laplacian, then one back-substitution per
// change of the field, of the singularities or of the loop windings.

#ifndef CGAL_SURFACE_DESIGN_FIELD_ALIGNED_PARAMETERIZER_H
#define CGAL_SURFACE_DESIGN_FIELD_ALIGNED_PARAMETERIZER_H

#include <CGAL/Surface_design/edge_weighting.h>
#include <CGAL/Surface_design/exceptions.h>
#include <CGAL/Surface_design/internal/Core/angles.h>
#include <CGAL/Surface_design/internal/Core/geometry.h>
#include <CGAL/Surface_design/internal/Core/Mesh_indices.h>
#include <CGAL/Surface_design/internal/Core/named_parameters.h>
#include <CGAL/Surface_design/internal/Core/Periodic_one_form_solver.h>
#include <CGAL/Surface_design/internal/Core/topology.h>
#include <CGAL/Surface_design/internal/Core/validation.h>
#include <CGAL/Surface_design/internal/Field_aligned_parameterization/stripe_isolines.h>
#include <CGAL/Surface_design/internal/Field_aligned_parameterization/target_one_form.h>
#include <CGAL/Surface_design/parameters.h>
#include <CGAL/Surface_design/solver_traits.h>

#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Named_function_parameters.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_design {

/// \ingroup PkgFieldAlignedParameterizationRef
/// How the target 1-form omega is computed from a per-vertex field X. Both integrate X along each
/// edge e = (i, j), X_i ruling the half of the edge next to i (paper, eq. 12):
/// omega_ij = 1/2 (integral contribution of X_i + that of X_j).
enum class One_form_convention
{
  /// X_i is projected to the tangent plane of vertex i (angle-weighted vertex normal) and
  /// omega_ij = 1/2 <X_i + X_j, p_j - p_i>. Extrinsic, simple, exact on planar meshes.
  projected,
  /// The paper's convention (sec. 4.1, after Knöppel et al. 2015): angles around vertex i are
  /// rescaled by s_i = 2 pi / (angle sum at i) (s_i = 1 on the boundary) so that the vertex star
  /// is flat; with theta_i the rescaled angle of X_i and phi_ij that of the edge leaving i towards
  /// j, omega_ij = l_ij / 2 (|X_i| cos(theta_i - phi_ij) - |X_j| cos(theta_j - phi_ji)): X_j is
  /// integrated along i -> j, i.e. against the direction phi_ji of the edge leaving j. (The paper's
  /// eq. 12 prints "+"; with phi_ji read as the direction j -> i that sign would make the integral
  /// of a constant planar field vanish, so the consistent sign is used.)
  /// A 3D vector is converted to a rescaled angle by locating it, after projection to the
  /// tangent plane, in the wedge of one corner and interpolating linearly inside that corner.
  angle_rescaled
};

/// \ingroup PkgFieldAlignedParameterizationRef
///
/// Computes a circle-valued *stripe function* alpha (one angle per vertex) whose differential
/// follows a target 1-form omega (from a tangent vector field) in the weighted least-squares
/// sense, with singularities exactly at prescribed faces with prescribed integer indices and
/// nowhere else, and with prescribed (or automatically chosen) windings along the
/// non-contractible loops of the surface (Noma & Kawahara). Factor once in the constructor, then
/// change the field, the singularities and the windings and `solve()` as often as needed.
///
/// **The problem** (paper, eq. 15-16). Unknown: a 1-form y = dalpha on the edges.
/// Minimize sum_e w_e (y_e - omega_e)^2, w_e the cotangent weights (or 1, named parameter
/// `weighting`), subject to
/// - (d1 y)_f = 2 pi k_f on every face (k_f = prescribed index, 0 almost everywhere),
/// - the integral of y along each homology generator loop = 2 pi h (its winding), and along each
///   boundary loop (oriented with the surface on its left) = 2 pi W (its winding).
///
/// **How it is solved.** Exactly, in vertex space (`internal::Periodic_one_form_solver`, shared
/// with `Trivial_connection`): y = y* + d0 f with a particular solution y* built in O(|E|) on a
/// tree-cotree decomposition, and L f = d0^T W (omega - y*) with L the weighted Laplacian with one
/// vertex pinned per component, positive definite on every mesh, negative cotangent weights
/// included (it is the P1 stiffness matrix). L is factored once in the constructor; every
/// `solve()` afterwards costs O(|E|) plus one back-substitution. alpha is integrated along the
/// primal spanning tree.
///
/// **Windings.** Loops are numbered generators first (2g per component of genus g, from the
/// tree-cotree decomposition), then boundary loops. A loop's winding is either set with
/// `set_loop_winding()` or *automatic* (the default): automatic windings minimize the energy over
/// the integers (one extra back-substitution per automatic loop, once per mesh).
///
/// **Consistency.** By Stokes' theorem, on each connected component the indices must sum to the
/// sum of its boundary windings (to 0 on a closed component). With automatic boundary windings
/// the sum is met by construction; otherwise `solve()` throws `Invalid_constraints` with the sums.
///
/// **No singularity in a face with an edge on the boundary.** Such a face f shares its border
/// edge e with the virtual face of the boundary loop L. Index k in f with winding W of L is the
/// same problem as index 0 in f with winding W - k and the target omega shifted by 2 pi k on e
/// alone: adding -2 pi k to dalpha on e maps one feasible set onto the other with the same
/// energy, and leaves alpha, known modulo 2 pi, unchanged. So the index is no property of the
/// stripe function, only a phase jump of the target at one point of the boundary, and the
/// optimum absorbs most of it there: it leaves about 2/3 of the 2 pi k on e (a vortex at the
/// centroid of an equilateral boundary triangle and its mirror image across the free boundary
/// send (2/pi) atan(sqrt 3) = 2/3 of its circulation along e in the continuum; 0.59-0.75 measured
/// on well-shaped meshes), more than pi, so the wrapped alpha shows no singularity in f and
/// winding W - k on L. A non-zero index in such a face is therefore refused
/// (`Invalid_constraints`, by every setter): prescribe the winding of L instead. A face with
/// vertices on the boundary but no edge there is accepted: the cheapest way to undo its index
/// crosses an interior edge, so its index is a genuine vortex, and it reads back exactly wherever
/// its edges carry |dalpha| < pi, like any face (with a smaller margin: on a regular mesh about
/// 0.42 of the 2 pi runs along one of its edges, against 0.36 in the interior).
///
/// \tparam TriangleMesh a model of `FaceListGraph` and `HalfedgeListGraph`
/// \tparam VertexPointMap a readable property map from vertices to `Point_3` (default: the mesh's)
/// \tparam SolverTraits a model of `SparseLinearAlgebraWithFactorTraits_d` (default
///         `Default_solver_traits`). Copies of a `CGAL::Eigen_solver_traits` share one
///         factorization: give every object its own solver (the default does).
///
/// With class template argument deduction, `Field_aligned_parameterizer fap(mesh, np)` takes both
/// types from the named parameters.
template <class TriangleMesh,
          class VertexPointMap = typename boost::property_map<TriangleMesh, CGAL::vertex_point_t>::const_type,
          class SolverTraits = Default_solver_traits>
class Field_aligned_parameterizer
{
  using GT = boost::graph_traits<TriangleMesh>;
  using Solver = internal::Periodic_one_form_solver<TriangleMesh, SolverTraits>;
  using Indices = internal::Mesh_indices<TriangleMesh>;

public:
  using vertex_descriptor = typename GT::vertex_descriptor;
  using halfedge_descriptor = typename GT::halfedge_descriptor;
  using edge_descriptor = typename GT::edge_descriptor;
  using face_descriptor = typename GT::face_descriptor;

  /// Validates the mesh, computes the edge weights and the topology, and factors the Laplacian.
  /// The mesh must not change while this object is used.
  ///
  /// \param tm a triangle mesh (any number of connected components, with or without boundary)
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
  ///     \cgalParamDescription{the sparse solver that factors the weighted Laplacian with one vertex pinned per
  ///                           connected component}
  ///     \cgalParamType{`SolverTraits`, a model of `SparseLinearAlgebraWithFactorTraits_d` (class template
  ///                    argument deduction takes the class's `SolverTraits` from this parameter)}
  ///     \cgalParamDefault{`SolverTraits()`}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{weighting}
  ///     \cgalParamDescription{the edge weights w_e of the least-squares energy}
  ///     \cgalParamType{`Edge_weighting`: `cotangent` or `uniform`}
  ///     \cgalParamDefault{`Edge_weighting::cotangent` (the paper's)}
  ///     \cgalParamExtra{throws `Invalid_parameter` for any other value (`mean_value`: the energy needs
  ///                     symmetric weights)}
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
  /// \throws Invalid_mesh (empty, non-triangle, non-manifold, degenerate face, non-finite point)
  /// \throws Invalid_parameter if `weighting` is `mean_value` (the energy needs symmetric weights)
  /// \throws Linear_solver_failure if the factorization fails
  ///
  /// Complexity: O(|E|) plus one sparse factorization of size |V|.
  template <class NamedParameters = CGAL::parameters::Default_named_parameters>
  explicit Field_aligned_parameterizer(const TriangleMesh& tm,
                                       const NamedParameters& np = CGAL::parameters::default_values())
    : m_tm(tm), m_vpm(internal::class_vertex_point_map<VertexPointMap>(tm, np)), m_solver(make_solver(tm, m_vpm, np))
  {
    const auto& loops = topology().boundary;
    m_face_boundary_loop.assign(indices().number_of_faces(), internal::npos);
    for(std::size_t h = 0; h < indices().number_of_halfedges(); ++h)
      if(loops.loop_of_halfedge[h] != internal::npos) // a border halfedge: its opposite's face
        m_face_boundary_loop[indices().index(face(opposite(indices().halfedge(h), m_tm), m_tm))] =
          number_of_generator_loops() + loops.loop_of_halfedge[h];
    m_omega.assign(indices().number_of_edges(), 0.);
    m_index.assign(indices().number_of_faces(), 0);
    m_winding.assign(number_of_loops(), std::nullopt);
  }

  const TriangleMesh& mesh() const { return m_tm; }

  /// \name The target field
  /// @{

  /// Sets the target 1-form from a per-vertex vector field (any vectors: they are projected to
  /// the vertex tangent planes). If `stripes_per_unit_length > 0` the field is normalized and
  /// alpha advances by 2 pi * stripes_per_unit_length per unit length along it; otherwise
  /// (`stripes_per_unit_length == 0`) the field is used as given (alpha advances by |X| radians
  /// per unit length).
  /// \throws Invalid_parameter if `stripes_per_unit_length` is negative or not finite, if a field
  ///         vector is not finite, or if the field is to be normalized and has no tangential
  ///         component anywhere on a connected component, or if `convention` is not a
  ///         `One_form_convention` enumerator. Nothing changes then.
  template <class VertexVectorMap>
  void set_field(const VertexVectorMap& field, double stripes_per_unit_length = 0.,
                 One_form_convention convention = One_form_convention::projected)
  {
    internal::require_nonnegative("stripes_per_unit_length", stripes_per_unit_length);
    if(convention != One_form_convention::projected && convention != One_form_convention::angle_rescaled)
      throw Invalid_parameter("one_form_convention", "not a One_form_convention enumerator");
    const auto x = internal::tangent_field(indices(), m_vpm, field, internal::two_pi * stripes_per_unit_length,
                                           topology().components);
    m_omega = convention == One_form_convention::projected
                ? internal::projected_one_form(indices(), m_vpm, x)
                : internal::angle_rescaled_one_form(indices(), m_vpm, x);
  }

  /// Sets the target 1-form directly: `omega(h)` for the halfedge `h = halfedge(e, tm)` of
  /// every edge (the value along h).
  /// \throws Invalid_parameter if a value is not finite; nothing changes then
  template <class EdgeScalarMap>
  void set_target_one_form(const EdgeScalarMap& omega)
  {
    std::vector<double> values(indices().number_of_edges());
    for(std::size_t e = 0; e < values.size(); ++e)
    {
      const edge_descriptor ed = indices().edge(e);
      values[e] = indices().orientation_sign(halfedge(ed, m_tm)) * double(get(omega, ed));
    }
    set_target_one_form_by_edge_index(std::move(values));
  }

  /// Target 1-form along halfedge `h`.
  double omega(halfedge_descriptor h) const
  {
    return indices().orientation_sign(h) * m_omega[indices().edge_index(h)];
  }
  /// @}

  /// \name Singularities
  /// An index k is an integer: alpha turns by 2 pi k around the face (the library's convention for
  /// stripes, n = 1; see the foundation manual).
  /// @{

  /// Index of the singularity prescribed in face `f` (0: no singularity).
  int index(face_descriptor f) const { return m_index[checked_face(f)]; }
  /// Prescribes index `k` in face `f`.
  /// \throws Invalid_constraints if `f` is not a face of the mesh, or if `k != 0` and `f` has an
  ///         edge on the boundary (see the class documentation); the index is left unchanged then
  void set_index(face_descriptor f, int k)
  {
    const std::size_t i = checked_face(f);
    require_singularity_allowed(i, k);
    m_index[i] = k;
  }
  /// Same, with the face given by its index (the face index map's; for meshes read from a file,
  /// the input order).
  void set_index(std::size_t face_index, int k)
  {
    const std::size_t i = checked_face_index(face_index);
    require_singularity_allowed(i, k);
    m_index[i] = k;
  }
  /// Reads all indices from a face -> integer map.
  /// \throws Invalid_constraints if a face with an edge on the boundary gets a non-zero index
  ///         (then no index is changed)
  template <class FaceIndexMap>
  void set_indices(const FaceIndexMap& k)
  {
    std::vector<int> index(indices().number_of_faces());
    for(std::size_t f = 0; f < index.size(); ++f)
    {
      index[f] = int(get(k, indices().face(f)));
      require_singularity_allowed(f, index[f]);
    }
    m_index = std::move(index);
  }
  /// Whether face `f` has an edge on the boundary, i.e. cannot hold a singularity.
  bool has_boundary_edge(face_descriptor f) const { return m_face_boundary_loop[checked_face(f)] != internal::npos; }
  /// Removes every singularity.
  void clear_indices() { std::fill(m_index.begin(), m_index.end(), 0); }
  /// Moves the singularity of face `from` to face `to` (adding its index to that of `to`).
  /// \throws Invalid_constraints if the faces are not faces of the mesh, lie on different
  ///         connected components, or `to` has an edge on the boundary; nothing changes then
  void move_singularity(face_descriptor from, face_descriptor to)
  {
    const std::size_t a = checked_face(from), b = checked_face(to);
    if(a == b)
      return;
    if(topology().components.face_component[a] != topology().components.face_component[b])
      throw Invalid_constraints("cannot move a singularity from face " + std::to_string(a) +
                                " to face " + std::to_string(b) + " of another connected component");
    require_singularity_allowed(b, long(m_index[b]) + m_index[a]);
    m_index[b] += m_index[a];
    m_index[a] = 0;
  }
  /// Annihilates a +k/-k pair: both faces lose their singularity.
  /// \throws Invalid_constraints if `a` and `b` do not hold non-zero opposite indices
  void annihilate(face_descriptor a, face_descriptor b)
  {
    const std::size_t i = checked_face(a), j = checked_face(b);
    if(i == j || m_index[i] == 0 || m_index[i] + m_index[j] != 0)
      throw Invalid_constraints("faces " + std::to_string(i) + " and " + std::to_string(j) +
                                " do not hold opposite singularities (indices " +
                                std::to_string(m_index[i]) + " and " + std::to_string(m_index[j]) + ")");
    m_index[i] = m_index[j] = 0;
  }
  /// @}

  /// \name Topology, loops and their windings
  /// @{
  std::size_t number_of_connected_components() const { return topology().components.size(); }
  /// Genus of connected component `c` (components are numbered by their smallest vertex index).
  long genus(std::size_t c) const { return topology().components.info.at(c).genus(); }
  std::size_t number_of_generator_loops() const { return m_solver.number_of_generator_loops(); }
  std::size_t number_of_boundary_loops() const { return m_solver.number_of_boundary_loops(); }
  std::size_t number_of_loops() const { return m_solver.number_of_loops(); }
  bool is_boundary_loop(std::size_t loop) const { return m_solver.is_boundary_loop(checked_loop(loop)); }

  /// The halfedges of a loop, in order, oriented as its winding is measured: generator loops as
  /// built by the tree-cotree decomposition, boundary loops with the surface on their left.
  std::vector<halfedge_descriptor> loop(std::size_t l) const
  {
    std::vector<halfedge_descriptor> out;
    for(std::size_t h : m_solver.oriented_loop(checked_loop(l)))
      out.push_back(indices().halfedge(h));
    return out;
  }

  /// Prescribes the winding of loop `l` (the integral of dalpha along it is 2 pi * winding).
  void set_loop_winding(std::size_t l, int winding) { m_winding[checked_loop(l)] = winding; }
  /// Lets solve() choose the winding of loop `l` (the default).
  void set_automatic_winding(std::size_t l) { m_winding[checked_loop(l)] = std::nullopt; }
  void set_all_windings_automatic() { std::fill(m_winding.begin(), m_winding.end(), std::nullopt); }
  /// Winding of loop `l` in the last solve().
  int loop_winding(std::size_t l) const
  {
    require_solved();
    return m_solution.windings[checked_loop(l)];
  }
  /// @}

  /// \name Solving
  /// @{

  /// Computes dalpha and alpha for the current field, indices and windings. O(|E|) plus one
  /// back-substitution (and, the first time automatic windings are used, one per automatic loop).
  /// \throws Invalid_constraints if the indices and explicit windings violate Stokes' theorem;
  ///         the previous solution is kept then
  void solve()
  {
    typename Solver::Solution s = m_solver.solve(m_omega, m_index, m_winding);
    std::vector<double> alpha = m_solver.integrate(s.y);
    for(double& a : alpha)
      a = internal::wrap_angle(a);
    m_solution = std::move(s);
    m_alpha = std::move(alpha);
    m_solved = true;
  }

  bool is_solved() const { return m_solved; }

  /// alpha at vertex `v`, in [-pi, pi).
  double alpha(vertex_descriptor v) const
  {
    require_solved();
    return m_alpha[indices().index(v)];
  }

  /// Writes alpha (in [-pi, pi)) to a vertex -> double map.
  template <class VertexScalarMap>
  void alpha(VertexScalarMap out) const
  {
    require_solved();
    for(std::size_t v = 0; v < m_alpha.size(); ++v)
      put(out, indices().vertex(v), m_alpha[v]);
  }

  /// dalpha along halfedge `h`, unwrapped: alpha(target) = alpha(source) + dalpha (mod 2 pi).
  double dalpha(halfedge_descriptor h) const
  {
    require_solved();
    return indices().orientation_sign(h) * m_solution.y[indices().edge_index(h)];
  }

  /// Writes dalpha along `halfedge(e, tm)` for every edge `e` to an edge -> double map.
  template <class EdgeScalarMap>
  void dalpha(EdgeScalarMap out) const
  {
    require_solved();
    for(std::size_t e = 0; e < indices().number_of_edges(); ++e)
      put(out, indices().edge(e), dalpha(halfedge(indices().edge(e), m_tm)));
  }

  /// Writes a per-corner coordinate u to a halfedge -> double map: for a non-border halfedge h,
  /// the value at the corner of face(h) at target(h). Within each face the three values are
  /// alpha unwrapped (u(target) - u(source) = dalpha along each of its first two halfedges), so
  /// cos(u) interpolates without seams; u / (2 pi) is a texture coordinate with one stripe per
  /// unit. Border halfedges are not written.
  template <class HalfedgeScalarMap>
  void corner_coordinates(HalfedgeScalarMap out) const
  {
    require_solved();
    for(std::size_t f = 0; f < indices().number_of_faces(); ++f)
    {
      const halfedge_descriptor h0 = halfedge(indices().face(f), m_tm);
      double u = m_alpha[indices().source_index(h0)];
      put(out, prev(h0, m_tm), u);
      u += dalpha(h0);
      put(out, h0, u);
      u += dalpha(next(h0, m_tm));
      put(out, next(h0, m_tm), u);
    }
  }

  /// One isoline: `points` (a polyline on the surface, the first point not repeated when
  /// `closed`), `faces` (faces[i] is crossed from points[i] to the next point), `level` (0 or pi:
  /// alpha along the line modulo 2 pi), `family` (always 0 here).
  using Isoline = internal::Stripe_isoline<typename boost::property_traits<VertexPointMap>::value_type, face_descriptor>;

  /// The isolines of alpha at 0 and pi (modulo 2 pi): the centre lines of the dark and of the
  /// light stripes of cos(alpha), as polylines for plotters, lasers and vector graphics. Straight
  /// in every face without singularity (alpha is linear there); in a face with index k != 0,
  /// alpha is interpolated with a winding term about the centroid (Knöppel et al. 2015, sec. 6)
  /// sampled on a grid of `singular_face_subdivision`² triangles (a multiple of 3 puts the
  /// centroid, the singular point, on the grid). Lines end only on the
  /// boundary, in singular faces, and where several lines meet (a vertex exactly at a level).
  /// \throws Invalid_constraints before `solve()`; Invalid_parameter if
  ///         `singular_face_subdivision` is not in [1, 64]
  std::vector<Isoline> isolines(int singular_face_subdivision = 9) const
  {
    internal::check_isoline_subdivision(singular_face_subdivision);
    require_solved();
    internal::Stripe_isoline_builder builder(indices().number_of_vertices(), indices().number_of_edges());
    for(std::size_t f = 0; f < indices().number_of_faces(); ++f)
    {
      const halfedge_descriptor h = halfedge(indices().face(f), m_tm);
      const double c0 = m_alpha[indices().source_index(h)], c1 = c0 + dalpha(h), c2 = c1 + dalpha(next(h, m_tm));
      const double turn = c2 + dalpha(next(next(h, m_tm), m_tm)) - c0;
      internal::add_regular_face_isolines(builder, internal::stripe_isoline_face(indices(), m_vpm, f), 0, {c0, c1, c2},
                                          int(std::lround(turn / internal::two_pi)), singular_face_subdivision);
    }
    return internal::stripe_isolines_of<typename boost::property_traits<VertexPointMap>::value_type>(builder, indices());
  }

  /// The energy sum_e w_e (dalpha_e - omega_e)^2 of the last solve (with the field of that
  /// solve). With negative cotangent weights it can be negative: the energy is convex on the
  /// feasible set, not positive on every 1-form.
  double energy() const
  {
    require_solved();
    return m_solution.energy;
  }

  /// The energy of the optimal dalpha for the current field and indices with the given windings
  /// of all loops (no refactorization; one back-substitution). Used to compare winding choices.
  /// \throws Invalid_constraints if `windings` does not have one entry per loop or violates Stokes
  double energy_with_windings(const std::vector<int>& windings) const
  {
    if(windings.size() != number_of_loops())
      throw Invalid_constraints("expected " + std::to_string(number_of_loops()) + " windings, got " +
                                std::to_string(windings.size()));
    return m_solver.energy_with_windings(m_omega, m_index, windings);
  }
  /// @}

  /// \name Internal data, for tests and benchmarks (unstable: may change without notice)
  /// @{
  const internal::Mesh_indices<TriangleMesh>& indices() const { return m_solver.indices(); }
  const internal::Topology& topology() const { return m_solver.topology(); }
  const std::vector<double>& edge_weights() const { return m_solver.weights(); } ///< per edge index
  /// dalpha per edge index, oriented from the smaller to the larger vertex index
  const std::vector<double>& one_form() const { require_solved(); return m_solution.y; }
  /// omega per edge index, same orientation
  const std::vector<double>& target_one_form() const { return m_omega; }
  /// Sets omega per edge index, same orientation.
  /// \throws Invalid_parameter on a size mismatch or a non-finite value
  void set_target_one_form_by_edge_index(std::vector<double> omega)
  {
    if(omega.size() != indices().number_of_edges())
      throw Invalid_parameter("omega", "has " + std::to_string(omega.size()) + " values but the mesh has " +
                                         std::to_string(indices().number_of_edges()) + " edges");
    for(std::size_t e = 0; e < omega.size(); ++e)
      if(!std::isfinite(omega[e]))
        throw Invalid_parameter("omega", "the value on edge " + std::to_string(e) + " is " + internal::to_text(omega[e]));
    m_omega = std::move(omega);
  }
  const std::vector<int>& indices_per_face() const { return m_index; }
  /// every loop as halfedge indices, oriented as its winding is measured
  std::vector<std::vector<std::size_t>> loops_as_indices() const
  {
    std::vector<std::vector<std::size_t>> out;
    for(std::size_t l = 0; l < number_of_loops(); ++l)
      out.push_back(m_solver.oriented_loop(l));
    return out;
  }
  /// @}

private:
  template <class NamedParameters>
  static Solver make_solver(const TriangleMesh& tm, const VertexPointMap& vpm, const NamedParameters& np)
  {
    const Edge_weighting weighting = CGAL::parameters::choose_parameter(
      CGAL::parameters::get_parameter(np, internal_np::weighting), Edge_weighting::cotangent);
    if(weighting != Edge_weighting::cotangent && weighting != Edge_weighting::uniform)
      throw Invalid_parameter("weighting", std::string("the stripe energy needs symmetric edge weights (cotangent "
                                                       "or uniform), got ") + to_string(weighting));
    Indices idx(tm, np);
    internal::validate_mesh(idx, vpm);
    std::vector<double> weight = weighting == Edge_weighting::cotangent
                                   ? internal::cotangent_weights(idx, vpm)
                                   : std::vector<double>(idx.number_of_edges(), 1.);
    return Solver(std::move(idx), std::move(weight), internal::class_solver_traits<SolverTraits>(np),
                  std::string("pinned ") + to_string(weighting) + " Laplacian",
                  "; unlike a vector field, a stripe function's indices do not sum to the Euler characteristic");
  }

  std::size_t checked_face(face_descriptor f) const
  {
    const std::size_t i = indices().find(f);
    if(i == internal::npos)
      throw Invalid_constraints("the face is not a face of this mesh");
    return i;
  }

  std::size_t checked_face_index(std::size_t f) const
  {
    if(f >= indices().number_of_faces())
      throw Invalid_constraints("face " + std::to_string(f) + " does not exist (the mesh has " +
                                std::to_string(indices().number_of_faces()) + " faces)");
    return f;
  }

  // A face with an edge on the boundary cannot hold a singularity (see the class documentation).
  void require_singularity_allowed(std::size_t f, long k) const
  {
    const std::size_t l = m_face_boundary_loop[f];
    if(k == 0 || l == internal::npos)
      return;
    const std::string ls = std::to_string(l), n = std::to_string(k < 0 ? -k : k);
    throw Invalid_constraints(
      "face " + std::to_string(f) + " has an edge on boundary loop " + ls + ": it cannot hold a singularity. "
      "Index " + std::to_string(k) + " there differs from index 0 with the winding of loop " + ls +
      (k > 0 ? " lower" : " higher") + " by " + n + " only by 2 pi" + (n == "1" ? "" : " * " + n) +
      " of dalpha on that boundary edge, which alpha, known modulo 2 pi, cannot show; the optimum leaves "
      "about 2/3 of it on that edge, more than pi, so alpha would show no singularity in the face. "
      "Prescribe the winding of loop " + ls + " instead, or choose a face with no edge on the boundary "
      "(vertices on the boundary are fine)");
  }

  std::size_t checked_loop(std::size_t l) const
  {
    if(l >= number_of_loops())
      throw Invalid_constraints("loop " + std::to_string(l) + " does not exist (the mesh has " +
                                std::to_string(number_of_generator_loops()) + " generator loops and " +
                                std::to_string(number_of_boundary_loops()) + " boundary loops)");
    return l;
  }

  void require_solved() const
  {
    if(!m_solved)
      throw Invalid_constraints("solve() has not been called");
  }

  const TriangleMesh& m_tm;
  VertexPointMap m_vpm;
  Solver m_solver;

  std::vector<std::size_t> m_face_boundary_loop; // per face: the loop of one of its border edges, or npos
  std::vector<double> m_omega;
  std::vector<int> m_index;
  std::vector<std::optional<int>> m_winding;

  bool m_solved = false;
  typename Solver::Solution m_solution;
  std::vector<double> m_alpha;
};

/// Deduces the point map and solver types from the named parameters.
template <class TriangleMesh, class NamedParameters>
Field_aligned_parameterizer(const TriangleMesh&, const NamedParameters&)
  -> Field_aligned_parameterizer<TriangleMesh, internal::Const_vertex_point_map_t<TriangleMesh, NamedParameters>,
                                 internal::Solver_traits_t<NamedParameters>>;
template <class TriangleMesh>
Field_aligned_parameterizer(const TriangleMesh&) -> Field_aligned_parameterizer<TriangleMesh>;

} // namespace Surface_design
} // namespace CGAL

#endif // CGAL_SURFACE_DESIGN_FIELD_ALIGNED_PARAMETERIZER_H
