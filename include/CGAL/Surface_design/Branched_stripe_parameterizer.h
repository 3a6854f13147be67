// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Stripe patterns on line fields and cross fields with exactly prescribed stripe singularities:
// the exact solver of Noma & Kawahara on the branched cover of the field, solved on the base mesh.

#ifndef CGAL_SURFACE_DESIGN_BRANCHED_STRIPE_PARAMETERIZER_H
#define CGAL_SURFACE_DESIGN_BRANCHED_STRIPE_PARAMETERIZER_H

#include <CGAL/Surface_design/edge_weighting.h>
#include <CGAL/Surface_design/exceptions.h>
#include <CGAL/Surface_design/Field_aligned_parameterizer.h>
#include <CGAL/Surface_design/internal/Core/angles.h>
#include <CGAL/Surface_design/internal/Core/boundary_smoothing.h>
#include <CGAL/Surface_design/internal/Core/Branched_one_form_solver.h>
#include <CGAL/Surface_design/internal/Core/direction_field_cover.h>
#include <CGAL/Surface_design/internal/Core/discrete_connection.h>
#include <CGAL/Surface_design/internal/Core/geometry.h>
#include <CGAL/Surface_design/internal/Core/Mesh_indices.h>
#include <CGAL/Surface_design/internal/Core/named_parameters.h>
#include <CGAL/Surface_design/internal/Core/topology.h>
#include <CGAL/Surface_design/internal/Core/validation.h>
#include <CGAL/Surface_design/internal/Field_aligned_parameterization/branched_target_one_form.h>
#include <CGAL/Surface_design/internal/Field_aligned_parameterization/stripe_interpolation.h>
#include <CGAL/Surface_design/internal/Field_aligned_parameterization/stripe_isolines.h>
#include <CGAL/Surface_design/internal/Field_aligned_parameterization/stripe_relaxation.h>
#include <CGAL/Surface_design/internal/Field_aligned_parameterization/stripe_weights.h>
#include <CGAL/Surface_design/parameters.h>
#include <CGAL/Surface_design/solver_traits.h>

#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Named_function_parameters.h>

#include <Eigen/Core>

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_design {

/// \ingroup PkgFieldAlignedParameterizationRef
///
/// Computes stripe patterns that follow an *n-direction field*, n = 1 (vector field), 2 (line
/// field) or 4 (cross field), with stripe singularities exactly at prescribed faces with
/// prescribed integer indices and nowhere else (or at the places the energy chooses,
/// `place_automatic_singularities()`). A line field's stripes, like geometry-central's stripe
/// patterns (Knöppel et al. 2015), branch at the field's ±1/2 singularities; a cross field carries
/// two coupled families of stripes, the second along the field turned by 90 degrees, which
/// exchange at its ±1/4 singularities.
///
/// **The cover.** The field's n directions at each vertex are its sheets; along each edge, sheet a
/// continues as sheet a + r_e (the matching r_e: the direction closest after transport by the
/// discrete Levi-Civita connection, the transport of the field's own indices). Around a face the
/// matchings add up to n times the field's index modulo n: the face is *regular* when they add up
/// to 0 and a *branch face* otherwise (an odd index numerator for a line field; ±1/4 or ±1/2 for a
/// cross field). Sheet a + n/2 carries the opposite direction and the opposite stripe angle, so
/// the pattern has d = n/2 unknown angles per vertex (one for n = 1).
///
/// **The problem.** Unknown: y, d values per edge, with y = d_P alpha (mod 2 pi), the difference
/// of the stripe angles along the edge read on the sheets the matching connects. Minimize
/// sum_e w_e |y_e - omega_e|^2 (omega_e: the field of each sheet integrated along e, as the vector
/// case's eq. 12), where the weights of the edges of branch faces are dropped (as Knöppel et al.),
/// subject to: around every regular face the walk of y returns to its start plus 2 pi k_f
/// (k_f the prescribed stripe indices, a pair for a cross field). Branch faces carry no
/// constraint: the value at the branch point is fixed by the sheets' symmetry (0 or pi for a line
/// field: the branch point lies on a stripe or midway between two). The windings of loops (around
/// handles, boundaries and pairs of branch points) are chosen to minimize the energy.
///
/// **How it is solved.** Exactly, as the vector case (`Field_aligned_parameterizer`): a particular
/// solution with the prescribed integers built by peeling a dual spanning forest rooted at the
/// branch faces and boundary loops, plus d_P f from one back-substitution with the twisted
/// Laplacian d_P^T W d_P (off-diagonal blocks -w_e P_e), factored once per field in `set_field()`;
/// the integer windings by one more back-substitution. Changing the singularities or the frequency
/// costs O(|E|) and at most two back-substitutions.
///
/// **Signs.** A stripe index (and the sheet of a family) is read on the face's *reference
/// direction*, `field_direction(f)`: flipping a line field's direction flips the stripe angle and
/// the sign of its singularities. The library chooses each vertex's representative so that the
/// field continues along a spanning tree; the face's is the one of the source of `halfedge(f)`.
///
/// **Not allowed.** A stripe singularity in a branch face (the stripe angle is not single-valued
/// around it), or in a face with an edge on the boundary (see `Field_aligned_parameterizer`): both
/// throw `Invalid_constraints`.
///
/// \tparam TriangleMesh a model of `FaceListGraph` and `HalfedgeListGraph`
/// \tparam VertexPointMap a readable property map from vertices to `Point_3` (default: the mesh's)
/// \tparam SolverTraits a model of `SparseLinearAlgebraWithFactorTraits_d` (default
///         `Default_solver_traits`)
template <class TriangleMesh,
          class VertexPointMap = typename boost::property_map<TriangleMesh, CGAL::vertex_point_t>::const_type,
          class SolverTraits = Default_solver_traits>
class Branched_stripe_parameterizer
{
  using GT = boost::graph_traits<TriangleMesh>;
  using Indices = internal::Mesh_indices<TriangleMesh>;
  using Solver = internal::Branched_one_form_solver<TriangleMesh, SolverTraits>;
  using Value = Eigen::Vector2d;

public:
  using vertex_descriptor = typename GT::vertex_descriptor;
  using halfedge_descriptor = typename GT::halfedge_descriptor;
  using face_descriptor = typename GT::face_descriptor;
  using Point_3 = typename boost::property_traits<VertexPointMap>::value_type;
  using Vector_3 = typename CGAL::Kernel_traits<Point_3>::Kernel::Vector_3;

  /// Validates the mesh and computes its topology, connection and weights. The field is given
  /// (and the system factored) by `set_field()`.
  ///
  /// \cgalNamedParamsBegin
  ///   \cgalParamNBegin{symmetry_order}
  ///     \cgalParamDescription{n: 1 (vector field), 2 (line field) or 4 (cross field)}
  ///     \cgalParamType{`int`}
  ///     \cgalParamDefault{2}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{vertex_point_map} as `Field_aligned_parameterizer` \cgalParamNEnd
  ///   \cgalParamNBegin{sparse_linear_solver}
  ///     \cgalParamDescription{the sparse solver that factors the twisted Laplacian (d |V| unknowns) and the
  ///                           relaxation of `place_automatic_singularities()` (2 d |V| unknowns)}
  ///     \cgalParamType{`SolverTraits`}
  ///     \cgalParamDefault{`SolverTraits()`}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{weighting}
  ///     \cgalParamDescription{the edge weights: `cotangent` (default) or `uniform`}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{vertex_index_map, halfedge_index_map, edge_index_map, face_index_map} as
  ///     `Field_aligned_parameterizer` \cgalParamNEnd
  /// \cgalNamedParamsEnd
  ///
  /// \throws Invalid_mesh (empty, non-triangle, non-manifold, degenerate face, non-finite point)
  /// \throws Invalid_parameter if `symmetry_order` is not 1, 2 or 4, or `weighting` is neither
  ///         `cotangent` nor `uniform`
  template <class NamedParameters = CGAL::parameters::Default_named_parameters>
  explicit Branched_stripe_parameterizer(const TriangleMesh& tm,
                                         const NamedParameters& np = CGAL::parameters::default_values())
    : m_tm(tm), m_vpm(internal::class_vertex_point_map<VertexPointMap>(tm, np)),
      m_traits(internal::class_solver_traits<SolverTraits>(np))
  {
    m_n = CGAL::parameters::choose_parameter(CGAL::parameters::get_parameter(np, internal_np::symmetry_order), 2);
    internal::check_cover_order(m_n, "symmetry_order");
    const Edge_weighting weighting = CGAL::parameters::choose_parameter(
      CGAL::parameters::get_parameter(np, internal_np::weighting), Edge_weighting::cotangent);
    if(weighting != Edge_weighting::cotangent && weighting != Edge_weighting::uniform)
      throw Invalid_parameter("weighting", std::string("the stripe energy needs symmetric edge weights (cotangent "
                                                       "or uniform), got ") + to_string(weighting));
    auto idx = std::make_shared<Indices>(tm, np);
    internal::validate_mesh(*idx, m_vpm);
    m_idx = idx;
    // the tree holds every boundary edge but one per loop: boundary loops on level lines need it
    m_topology = std::make_shared<internal::Topology>(internal::compute_topology(*m_idx, true));
    m_connection = internal::levi_civita_connection(*m_idx, m_vpm);
    m_cot = weighting == Edge_weighting::cotangent ? internal::halfedge_cotangents(*m_idx, m_vpm)
                                                   : std::vector<double>(m_idx->number_of_halfedges(), 1.);
    m_uniform = weighting == Edge_weighting::uniform;
    m_length = internal::edge_lengths(*m_idx, m_vpm);
    m_vertex_area = internal::vertex_areas(*m_idx, internal::face_areas(*m_idx, m_vpm));
    m_face_boundary = std::vector<bool>(m_idx->number_of_faces(), false);
    for(std::size_t h = 0; h < m_idx->number_of_halfedges(); ++h)
    {
      const auto hd = m_idx->halfedge(h);
      if(m_idx->is_border(hd))
        m_face_boundary[m_idx->index(face(opposite(hd, tm), tm))] = true;
    }
    m_index.assign(m_idx->number_of_faces(), Eigen::Vector2i::Zero());
  }

  const TriangleMesh& mesh() const { return m_tm; }
  /// The vertex positions it reads.
  const VertexPointMap& vertex_point_map() const { return m_vpm; }
  /// n: 1, 2 or 4.
  int symmetry_order() const { return m_n; }
  /// The number of stripe families: 2 for a cross field, 1 otherwise.
  int number_of_families() const { return internal::sheet_values(m_n); }

  /// \name The field
  /// @{

  /// Sets the field from one vector per vertex, any of the n directions (projected to the vertex
  /// tangent planes; only directions matter), and factors the system. The stripe angle advances by
  /// 2 pi `stripes_per_unit_length` per unit length along the field. Prescribed stripe
  /// singularities are kept; the stiffening of `stiffen()` is dropped (unless `keep_stiffening()`).
  /// \throws Invalid_parameter if a vector is not finite or has no tangential component, or
  ///         `stripes_per_unit_length` is not positive and finite
  /// \throws Invalid_constraints if a prescribed singularity lies in a branch face of the new field,
  ///         or if the field cannot carry stripes (see `internal::Branched_one_form_solver`)
  /// \throws Linear_solver_failure if the factorization fails. Nothing changes when it throws.
  template <class VertexVectorMap>
  void set_field(const VertexVectorMap& field, double stripes_per_unit_length,
                 One_form_convention convention = One_form_convention::projected)
  {
    check_frequency(stripes_per_unit_length);
    if(convention != One_form_convention::projected && convention != One_form_convention::angle_rescaled)
      throw Invalid_parameter("convention", "not a One_form_convention enumerator");
    std::vector<double> angle = internal::field_angles(*m_idx, m_connection.frames, field);
    internal::Direction_field_cover cover =
      internal::direction_field_cover(*m_idx, m_connection, m_topology->tree, std::move(angle), m_n);
    for(std::size_t f = 0; f < m_index.size(); ++f)
      if(!cover.regular[f] && !m_index[f].isZero())
        throw Invalid_constraints("face " + std::to_string(f) + " holds a stripe singularity and is a branch face of "
                                  "the new field (index " + std::to_string(cover.index_numerator[f]) + "/" +
                                  std::to_string(m_n) + "): move the singularity first");
    // a new field drops the analyses made for the old one's folds, and their stiffening unless kept
    if constexpr(internal::Has_solver_settings<SolverTraits>::value)
      if(m_own_analysis_cache)
      {
        m_traits.solver().set_analysis_cache(nullptr);
        m_own_analysis_cache = false;
      }
    std::vector<double> dropped = m_keep_stiffening ? std::vector<double>() : std::exchange(m_stiffness, {});
    std::unique_ptr<Solver> solver;
    try
    {
      // every system its own solver object (copies of Eigen's traits share one factorization)
      solver = std::make_unique<Solver>(m_idx, m_topology, cover, weights(cover), internal::new_solver_like(m_traits),
                                        "twisted Laplacian of the stripes", spoke_weights(cover), level_sheets(cover));
    }
    catch(...)
    {
      if(!dropped.empty())
        m_stiffness = std::move(dropped);
      throw;
    }
    solver->set_lattice_branch_points(m_lattice);
    m_solver = std::move(solver);
    ++m_factorizations;
    m_convention = convention;
    m_frequency = stripes_per_unit_length;
    m_solved = false;
    m_windings_valid = false;
    m_relaxation.reset();
    update_omega();
  }

  /// Changes the frequency only: no factorization.
  /// \throws Invalid_parameter if it is not positive and finite; Invalid_constraints before `set_field()`
  void set_frequency(double stripes_per_unit_length)
  {
    check_frequency(stripes_per_unit_length);
    require_field();
    m_frequency = stripes_per_unit_length;
    frequency_changed();
  }
  double frequency() const { return m_frequency; }

  /// Makes the frequency vary over the surface: at vertex v the stripe angle advances by
  /// 2 pi `frequency()` `scale[v]` per unit length, so that the spacing of the stripes there is
  /// 1 / (`frequency()` `scale[v]`) (the sizing of curvature-adapted quads:
  /// `field_aligned_quad_remeshing()` with `edge_length_ratio`). Along an edge the target integrates
  /// the scaled field by the trapezoid rule; from the corners of a branch face to its branch point
  /// the mean of the corners' scales applies. A scale that varies gives the target one-form a
  /// curl, which the least squares spreads: the spacing follows the scale where it varies slowly
  /// against the spacing. Kept by `set_field()` and `set_frequency()`. No factorization: O(|E|).
  /// \throws Invalid_parameter if a value is not positive and finite (nothing changes then)
  template <class VertexScalarMap>
  void set_frequency_scale(const VertexScalarMap& scale)
  {
    std::vector<double> s(m_idx->number_of_vertices());
    for(std::size_t v = 0; v < s.size(); ++v)
    {
      s[v] = double(get(scale, m_idx->vertex(v)));
      if(!std::isfinite(s[v]) || !(s[v] > 0.))
        throw Invalid_parameter("frequency scale", "must be positive and finite at every vertex, got " +
                                                     std::to_string(s[v]) + " at vertex " + std::to_string(v));
    }
    m_frequency_scale = std::move(s);
    frequency_changed();
  }
  /// Back to one frequency everywhere.
  void clear_frequency_scale()
  {
    m_frequency_scale.clear();
    frequency_changed();
  }
  /// The scale of `set_frequency_scale()` at v (1 without one).
  double frequency_scale(vertex_descriptor v) const
  {
    const std::size_t i = m_idx->find(v);
    if(i == internal::npos)
      throw Invalid_constraints("the vertex is not a vertex of this mesh");
    return m_frequency_scale.empty() ? 1. : m_frequency_scale[i];
  }

  bool has_field() const { return bool(m_solver); }
  /// Whether face f is a branch face of the field.
  bool is_branch_face(face_descriptor f) const { return !cover().regular[checked_face(f)]; }
  /// n times the field's index in face f.
  int field_index_numerator(face_descriptor f) const { return cover().index_numerator[checked_face(f)]; }
  /// The branch faces, by index.
  std::vector<std::size_t> branch_faces() const
  {
    std::vector<std::size_t> out;
    for(std::size_t f = 0; f < cover().regular.size(); ++f)
      if(!cover().regular[f])
        out.push_back(f);
    return out;
  }
  /// The face's reference direction (unit): the direction its stripe indices and values refer to.
  Vector_3 field_direction(face_descriptor f) const
  {
    const std::size_t v = reference_vertex(checked_face(f));
    const Eigen::Vector3d x = m_connection.frames.to_vector(v, cover().angle[v]);
    return Vector_3(x.x(), x.y(), x.z());
  }
  /// @}

  /// \name Stripe singularities
  /// @{

  /// The index of family `family` (0, or 1 for the second family of a cross field) prescribed in f.
  int index(face_descriptor f, int family = 0) const { return m_index[checked_face(f)][checked_family(family)]; }
  /// Prescribes index k of family `family` in face f (on the face's reference direction).
  /// \throws Invalid_constraints if f is a branch face or has an edge on the boundary and k != 0
  void set_index(face_descriptor f, int k, int family = 0) { set_index(checked_face(f), k, family); }
  /// Same, with the face given by its index.
  void set_index(std::size_t f, int k, int family = 0)
  {
    if(f >= m_index.size())
      throw Invalid_constraints("face " + std::to_string(f) + " does not exist (the mesh has " +
                                std::to_string(m_index.size()) + " faces)");
    const int a = checked_family(family);
    if(k != 0)
      require_singularity_allowed(f);
    if(k > max_index || k < -max_index)
      throw Invalid_constraints("stripe index " + std::to_string(k) + " at face " + std::to_string(f) +
                                " is out of range (at most " + std::to_string(max_index) + " in absolute value)");
    m_index[f][a] = k;
    m_solved = false;
    m_windings_valid = false;
  }
  /// The largest absolute stripe index accepted (far beyond what a mesh resolves; sums stay exact).
  static constexpr int max_index = 1 << 20;
  void clear_indices()
  {
    std::fill(m_index.begin(), m_index.end(), Eigen::Vector2i::Zero());
    m_solved = false;
    m_windings_valid = false;
  }
  /// Moves every index of face `from` to face `to` (added to the indices there).
  /// \throws Invalid_constraints if `to` cannot hold a singularity; nothing changes then
  void move_singularity(face_descriptor from, face_descriptor to)
  {
    const std::size_t a = checked_face(from), b = checked_face(to);
    if(a == b || m_index[a].isZero())
      return;
    require_singularity_allowed(b);
    const Eigen::Vector2i sum = m_index[b] + m_index[a];
    if(sum.cwiseAbs().maxCoeff() > max_index)
      throw Invalid_constraints("moving the singularity of face " + std::to_string(a) + " to face " + std::to_string(b) +
                                " would give an index beyond " + std::to_string(max_index));
    m_index[b] = sum;
    m_index[a].setZero();
    m_solved = false;
    m_windings_valid = false;
  }
  /// The faces with a non-zero prescribed index.
  std::vector<std::size_t> singular_faces() const
  {
    std::vector<std::size_t> out;
    for(std::size_t f = 0; f < m_index.size(); ++f)
      if(!m_index[f].isZero())
        out.push_back(f);
    return out;
  }

  /// Replaces the prescribed singularities by the ones the energy wants, and returns their number.
  /// 1. The candidates are the stripe singularities of the smallest eigenvector of the relaxed
  ///    problem (Knöppel et al. 2015: complex values whose phases are the stripe angles, with the
  ///    same weights, branch faces and sheets), read off as the integer turn of its phases around
  ///    every regular face with no edge on the boundary.
  /// 2. The relaxation lets the amplitude vanish where the exact pattern cannot, so some
  ///    candidates raise the exact energy (most of them on cross fields at low frequencies): each
  ///    candidate is dropped, in face order, when the exact energy without it is lower (one
  ///    solve per candidate; on a closed component without twist a single one cannot go, by
  ///    Stokes' theorem).
  /// 3. If no singularity at all gives a lower exact energy, none are placed.
  ///
  /// The relaxation (one factorization of size 2 d |V| and a shift-invert Lanczos run) is cached
  /// until the field or the frequency changes.
  /// \throws Invalid_constraints before `set_field()`
  std::size_t place_automatic_singularities()
  {
    require_field();
    if(!m_relaxation)
    {
      m_relaxation = internal::relaxed_stripe_indices(*m_idx, *m_solver, m_omega, m_vertex_area,
                                                      internal::new_solver_like(m_traits));
      ++m_factorizations;
    }
    const int d = number_of_families();
    auto exact_energy = [this](const std::vector<Eigen::Vector2i>& k) -> std::optional<double> {
      try
      {
        return m_solver->solve(m_omega, k).energy;
      }
      catch(const Invalid_constraints&)
      {
        return std::nullopt; // Stokes' theorem on a closed component without twist
      }
    };
    const std::vector<Eigen::Vector2i> none(m_index.size(), Eigen::Vector2i::Zero());
    std::vector<Eigen::Vector2i> k = none;
    for(std::size_t f = 0; f < k.size(); ++f)
      if(cover().regular[f] && !m_face_boundary[f])
        k[f] = (*m_relaxation)[f];
    std::optional<double> best = exact_energy(k);
    if(!best)
      k = none;
    else
      for(std::size_t f = 0; f < k.size(); ++f)
        for(int a = 0; a < d; ++a)
          if(k[f][a] != 0)
          {
            const int kept = k[f][a];
            k[f][a] = 0;
            const std::optional<double> e = exact_energy(k);
            if(e && *e < *best)
              best = e;
            else
              k[f][a] = kept;
          }
    const std::optional<double> without = exact_energy(none);
    if(best && without && *without <= *best)
      k = none;
    m_index = std::move(k);
    m_solved = false;
    m_windings_valid = false;
    return singular_faces().size();
  }
  /// @}

  /// \name Solving and results
  /// @{

  /// Computes the pattern for the current field, frequency and singularities.
  /// \throws Invalid_constraints before `set_field()`, or if the indices violate Stokes' theorem
  ///         on a closed component whose field has neither singularity nor twist
  void solve()
  {
    require_field();
    m_factorizations += m_solver->factorization_pending(); // (after stiffen_locally())
    typename Solver::Solution s = m_solver->solve(m_omega, m_index);
    m_solution = std::move(s);
    m_solved = true;
    m_windings_valid = true;
  }
  /// After `stiffen()`: solves again with the integers (the windings) of the last `solve()`, one
  /// back-substitution with the stiffened system, no new choice of windings. The map keeps its
  /// lattice branch points and its topology; the stiffening moves only its continuous part.
  /// \throws Invalid_constraints if the field, the singularities or the lattice setting changed
  ///         since the last `solve()` (or there was none): its windings do not apply
  void solve_keeping_windings()
  {
    require_field();
    if(!m_windings_valid)
      throw Invalid_constraints("solve_keeping_windings(): no solve() with the current field, singularities and "
                                "lattice setting to take the windings from");
    m_factorizations += m_solver->factorization_pending();
    typename Solver::Solution s = m_solver->solve_with_windings(m_omega, m_solution);
    m_solution = std::move(s);
    m_solved = true;
  }
  bool is_solved() const { return m_solved; }
  /// Whether every boundary loop lies on a level-0 line of the family normal to it (alpha = 0
  /// modulo 2 pi at its vertices, no stripe crossing it): the field must be normal to the
  /// boundary for some family (within 45 degrees) on every boundary edge. Factors again when a
  /// field is set. With `smoothing_length` L > 0 the family is read against the boundary's
  /// direction smoothed at L, as the field's `boundary_smoothing_length(L)` (give the same L).
  /// \throws Invalid_constraints where the field runs along the boundary, Invalid_parameter if L < 0
  void set_boundary_on_level_lines(bool on, double smoothing_length = 0.)
  {
    std::vector<double> old_offset = std::exchange(
      m_boundary_offset, internal::require_nonnegative("smoothing_length", smoothing_length) > 0. && on
                           ? internal::smoothed_boundary(*m_idx, m_vpm, m_topology->boundary, smoothing_length).offset
                           : std::vector<double>());
    const bool was = std::exchange(m_boundary_level, on);
    if(!has_field() || (was == on && old_offset == m_boundary_offset))
      return;
    try
    {
      refactor();
      m_windings_valid = false;
    }
    catch(...)
    {
      m_boundary_level = was;
      m_boundary_offset = std::move(old_offset);
      throw;
    }
  }
  bool boundary_on_level_lines() const { return m_boundary_level; }

  /// Whether `solve()` puts every branch point on the lattice of the stripes: every stripe angle
  /// 0 modulo 2 pi there, so that a line field's stripes run through its branch points and each
  /// cone of a cross field is a crossing of the two families (the condition for their level-0
  /// lines to form a quad mesh whose irregular vertices are the cones). The windings around pairs
  /// of branch points are then chosen, optimally, among those that meet the parity conditions
  /// this puts on them (`internal::Branched_one_form_solver`), and the energy also holds each
  /// branch face as the three triangles from its edges to its branch point (the spokes, with
  /// their cotangent weights clamped at 0), so that a winding cannot be moved for free across a
  /// branch face, which would fold the map around its cone. Off by default (the branch points at
  /// 0 or pi, whichever costs less; the branch faces' weights dropped, as Knöppel et al.).
  /// Switching it after `set_field()` factors the system again.
  /// \throws Invalid_constraints from `solve()` when no windings meet the conditions (these are
  ///         necessary for a quad mesh, not sufficient: the map may still fold)
  /// \throws Linear_solver_failure if the new factorization fails; nothing changes then
  void set_lattice_branch_points(bool on)
  {
    if(on == m_lattice)
      return;
    if(m_solver)
    {
      // the weights of the branch faces' edges change: a new factorization
      m_lattice = on;
      try
      {
        refactor();
      }
      catch(...)
      {
        m_lattice = !on;
        throw;
      }
    }
    m_lattice = on;
    m_solved = false;
    m_windings_valid = false;
  }
  bool lattice_branch_points() const { return m_lattice; }
  /// Local stiffening (as in Bommes et al.'s mixed-integer quadrangulation): multiplies by
  /// `factor` the energy's terms of the given faces (a regular face's share of its edges'
  /// weights; with lattice branch points, a branch face's spokes and share of its edges; a face's
  /// product at most 4^10, past which the factorization loses accuracy) and factors again. A
  /// fold of the map (a regular face whose two stripe angles turn clockwise, a cone whose three
  /// triangles around its branch point do not turn by 2 pi (1 - k / 4)) moves elsewhere: call
  /// `solve()` next.
  /// `ring_factor` multiplies the terms of the other faces that share a vertex with one of
  /// `faces` (default 1: none): a graded stiffening, which keeps the fold from moving next door
  /// (`extract_field_aligned_quads()` needs 4 rounds instead of 9 on the kitten with 4 and 2).
  /// \throws Invalid_parameter if `factor` or `ring_factor` is not finite and at least 1;
  ///         Invalid_constraints before `set_field()` or if a face is not one of the mesh;
  ///         Linear_solver_failure if the factorization fails (nothing changes when it throws)
  template <class FaceRange>
  void stiffen(const FaceRange& faces, double factor, double ring_factor = 1.)
  {
    std::vector<std::size_t> indices;
    std::vector<double> scaled = stiffness_after(faces, factor, ring_factor, indices);
    // the stiffened systems have one pattern: order and analyse it once (a cache of this object's
    // own, dropped with the next field, unless the traits have one)
    if constexpr(internal::Has_solver_settings<SolverTraits>::value)
      if(!m_traits.solver().analysis_cache())
      {
        m_traits.solver().set_analysis_cache(std::make_shared<Symbolic_analysis_cache>());
        m_own_analysis_cache = true;
      }
    std::swap(scaled, m_stiffness);
    try
    {
      // the same field and constraints: the solver keeps its forest and directions
      const internal::Direction_field_cover& cover = m_solver->cover();
      m_solver->set_weights(weights(cover), spoke_weights(cover));
    }
    catch(...)
    {
      std::swap(scaled, m_stiffness);
      throw;
    }
    ++m_factorizations;
    m_relaxation.reset();
    m_solved = false; // the windings stay valid: the same field and indices, other weights
  }
  /// `stiffen()` then `solve_keeping_windings()`, locally: the stripe angles are solved again
  /// only at the vertices within `radius` of `faces` along the edges, the others kept (their
  /// values the boundary values there), with a factorization of those vertices' block of the
  /// system; the whole system's waits for the next `solve()` or `solve_keeping_windings()`. The
  /// map keeps its windings, lattice branch points and topology.
  /// \throws as `stiffen()`; Invalid_parameter if `radius` is not finite and at least 0; Invalid_constraints
  ///         without a `solve()` for the current field, singularities and lattice setting
  template <class FaceRange>
  void stiffen_locally(const FaceRange& faces, double factor, double ring_factor, double radius)
  {
    std::vector<std::size_t> indices;
    std::vector<double> scaled = stiffness_after(faces, factor, ring_factor, indices);
    internal::require_nonnegative("radius", radius);
    if(!m_windings_valid || !m_solved)
      throw Invalid_constraints("stiffen_locally(): no solve() with the current field, singularities and lattice");
    std::swap(scaled, m_stiffness);
    const internal::Direction_field_cover& cover = m_solver->cover();
    const bool pending = m_solver->factorization_pending();
    m_solver->set_weights(weights(cover), spoke_weights(cover), false);
    try
    {
      m_solution = m_solver->solve_with_windings_near(m_omega, m_solution,
                                                      internal::vertices_near_faces(*m_idx, m_vpm, indices, radius));
    }
    catch(...)
    {
      std::swap(scaled, m_stiffness);
      m_solver->set_weights(weights(cover), spoke_weights(cover), !pending);
      throw;
    }
    m_relaxation.reset();
  }
  /// Whether `set_field()` keeps the stiffening of `stiffen()` (default: no). An editor moving a
  /// cone face by face keeps it: the new field's map mostly folds where the last one's did, and
  /// starts stiffened there (measured: 5 to 8 rounds instead of 28 over 10 steps on bunny_8k).
  void keep_stiffening(bool on) { m_keep_stiffening = on; }
  /// The sparse factorizations done so far: one per `set_field()`, one per relaxation of
  /// `place_automatic_singularities()`. Edits of the singularities and the frequency add none.
  std::size_t number_of_factorizations() const { return m_factorizations; }
  /// The energy sum_e w_e |y_e - omega_e|^2 of the last solve.
  double energy() const { return solution().energy; }
  /// The number of free integer windings (loops around handles, boundaries and pairs of branch
  /// points) and how many of them the last solve moved off their starting value.
  std::size_t number_of_free_windings() const { return solution().free_directions; }

  /// The stripe angles of family `family` at the corners of face f, in the order source(h),
  /// target(h), target(next(h)) for h = halfedge(f), on the face's reference direction, unwrapped
  /// along h and next(h): in a regular face without singularity they vary linearly inside the face
  /// and continuously across its edges.
  std::array<double, 3> corner_values(face_descriptor f, int family = 0) const
  {
    const auto beta = walk(checked_face(f));
    const int a = checked_family(family);
    return {beta[0][a], beta[1][a], beta[2][a]};
  }
  /// The stripe index of family `family` in face f read from the solution (round of the walk
  /// around the face over 2 pi; 0 in branch faces).
  int stripe_index(face_descriptor f, int family = 0) const
  {
    const std::size_t i = checked_face(f);
    const int a = checked_family(family);
    if(!cover().regular[i])
      return 0;
    return int(std::lround(m_solver->curl(solution().y, i)[a] / internal::two_pi));
  }
  /// The stripe angle of family `family` at barycentric coordinates b (of the corners in the order
  /// of `corner_values()`) in face f, with the interpolation of Knöppel et al.: linear in a regular
  /// face, plus a winding term in a face with a stripe singularity, and piecewise linear on three
  /// sub-triangles around the branch point (whose value is the fixed point of the sheets'
  /// exchange) in a branch face. Continuous across every edge.
  double value(face_descriptor f, const std::array<double, 3>& b, int family = 0) const
  {
    const std::size_t i = checked_face(f);
    const int a = checked_family(family);
    const auto beta = walk(i);
    if(cover().regular[i])
      return internal::regular_face_value({beta[0][a], beta[1][a], beta[2][a]}, stripe_index(f, a), b);
    return internal::branch_face_value({beta[0][a], beta[1][a], beta[2][a], beta[3][a]}, branch_value(i)[a],
                                       branch_point_coordinates(i), b);
  }
  /// The branch point of branch face f, the cone of the stripes there, in barycentric coordinates
  /// (of the corners in the order of `corner_values()`): the point from which the face's edges
  /// are seen under 120 degrees (its Fermat point, moved towards the centroid until every
  /// coordinate is at least 0.1), so that the three triangles from the edges to it stay apart in
  /// the parameter plane at a cone (150 degrees each at a -1/4 cone).
  std::array<double, 3> branch_point(face_descriptor f) const { return branch_point_coordinates(checked_face(f)); }
  /// The stripe angles at the branch point of branch face f (on the face's reference direction).
  std::array<double, 2> branch_point_value(face_descriptor f) const
  {
    const std::size_t i = checked_face(f);
    if(cover().regular[i])
      throw Invalid_constraints("face " + std::to_string(i) + " is not a branch face");
    const Value c = branch_value(i);
    return {c[0], c[1]};
  }

  /// The faces where the map of the two stripe angles (u, v) of a cross field (n = 4) is not
  /// locally injective (orientation-preserving): a regular face whose (u, v) triangle is not
  /// counterclockwise, or that holds a stripe singularity; a branch face of index k / 4 whose
  /// three triangles around the branch point (see `value()`) are not all counterclockwise or do
  /// not turn by 2 pi (1 - k / 4) together. The isolines of a map without such faces and with
  /// lattice branch points are a quad mesh (`field_aligned_quad_remeshing()`); `stiffen()` unfolds.
  /// \throws Invalid_constraints before `solve()` or if n is not 4
  std::vector<face_descriptor> folded_faces() const
  {
    solution();
    if(number_of_families() != 2)
      throw Invalid_constraints("folded_faces() reads the map of the two stripe families of a cross field (n = 4)");
    auto cross = [](const Eigen::Vector2d& a, const Eigen::Vector2d& b) { return a.x() * b.y() - a.y() * b.x(); };
    std::vector<face_descriptor> folded;
    for(std::size_t f = 0; f < m_idx->number_of_faces(); ++f)
    {
      const auto beta = walk(f);
      bool ok = true;
      if(cover().regular[f])
      {
        const Eigen::Vector2d a = beta[1] - beta[0], b = beta[2] - beta[0];
        ok = m_index[f].isZero() && cross(a, b) > 0.;
      }
      else
      {
        const Value c = branch_value(f);
        double turn = 0.;
        for(std::size_t k = 0; k < 3 && ok; ++k)
        {
          const Eigen::Vector2d a = beta[k] - c, b = beta[k + 1] - c;
          ok = cross(a, b) > 0.;
          turn += std::atan2(cross(a, b), a.dot(b));
        }
        const double expected = internal::two_pi * (1. - cover().index_numerator[f] / double(m_n));
        ok = ok && std::abs(turn - expected) < internal::pi;
      }
      if(!ok)
        folded.push_back(m_idx->face(f));
    }
    return folded;
  }

  /// The area of the map (u, v) of a cross field (n = 4) in lattice cells of (2 pi)^2: the signed
  /// areas of the faces' (u, v) triangles (the three around the branch point in a branch face).
  /// With lattice branch points an integer, and where the map does not fold its quad count.
  /// \throws Invalid_constraints before `solve()` or if n is not 4
  double map_area() const
  {
    if(number_of_families() != 2)
      throw Invalid_constraints("map_area() reads the map of the two stripe families of a cross field (n = 4)");
    double sum = 0.;
    for(std::size_t f = 0; f < m_idx->number_of_faces(); ++f)
    {
      const auto beta = walk(f); // (throws before solve())
      const bool regular = cover().regular[f];
      const Value c = regular ? beta[0] : branch_value(f); // the triangles' common corner
      for(std::size_t k = regular ? 1 : 0; k < (regular ? 2 : 3); ++k)
        sum += (beta[k] - c).x() * (beta[k + 1] - c).y() - (beta[k] - c).y() * (beta[k + 1] - c).x();
    }
    return 0.5 * sum / (internal::two_pi * internal::two_pi);
  }

  /// One isoline: `points` (a polyline on the surface, the first point not repeated when
  /// `closed`), `faces` (faces[i] is crossed from points[i] to the next point), `level` (0 or pi:
  /// the angle along the line modulo 2 pi) and `family` (of the face where the line starts: a line
  /// of a cross field follows its family where the two are exchanged).
  using Isoline = internal::Stripe_isoline<Point_3, face_descriptor>;

  /// The isolines of the stripe angles at 0 and pi (modulo 2 pi), of every family: the centre
  /// lines of the dark and of the light stripes of cos(angle), the lines a plotter, a laser or a
  /// quad extraction follows. They follow the interpolation of `value()`: straight in a regular
  /// face, through or around the branch point in a branch face, and on a grid of
  /// `singular_face_subdivision`² triangles in a face with a stripe singularity (where the
  /// angle is not linear: each small triangle is unwrapped and cut linearly, an approximation; a
  /// multiple of 3 puts the centroid, the singular point, on the grid). Lines end only on the boundary, at branch points and singularities,
  /// and where several lines meet (a mesh vertex exactly at a level).
  /// \throws Invalid_constraints before `solve()`; Invalid_parameter if
  ///         `singular_face_subdivision` is not in [1, 64]
  std::vector<Isoline> isolines(int singular_face_subdivision = 9) const
  {
    internal::check_isoline_subdivision(singular_face_subdivision);
    solution();
    internal::Stripe_isoline_builder builder(m_idx->number_of_vertices(), m_idx->number_of_edges());
    add_isolines(builder, singular_face_subdivision);
    return internal::stripe_isolines_of<Point_3>(builder, *m_idx);
  }
  /// @}

  /// \name Internal data, for tests and benchmarks (unstable)
  /// @{

  /// The isolines at level 0 alone, as the quad extraction reads them (points as `Eigen::Vector3d`,
  /// faces by their index): `isolines()` without its level-pi lines and conversions. With the
  /// boundary on level lines, the pieces along the boundary (and along chords between two of its
  /// vertices) are left out: the extraction adds the boundary loops.
  std::vector<internal::Stripe_isoline_polyline> level_zero_polylines() const
  {
    solution();
    internal::Stripe_isoline_builder builder(m_idx->number_of_vertices(), m_idx->number_of_edges(), 1e-9, true);
    if(m_boundary_level)
    {
      // the boundary is a level-0 line: the extraction adds its loops itself (a line along it
      // would run through ears and chords where the angle is constant)
      std::vector<bool> on(m_idx->number_of_vertices(), false);
      for(std::size_t h = 0; h < m_idx->number_of_halfedges(); ++h)
        if(m_idx->is_border(m_idx->halfedge(h)))
          on[m_idx->index(target(m_idx->halfedge(h), m_tm))] = true;
      builder.set_boundary_vertices(std::move(on));
    }
    add_isolines(builder, 9);
    return builder.polylines();
  }
  /// With the boundary on level lines: the boundary vertices (indices) where the family normal to
  /// the boundary switches (`internal::boundary_family_switches()`), where the level lines of
  /// both families meet the boundary: the corners of the quads; empty otherwise.
  std::vector<std::size_t> boundary_corners() const
  {
    if(!m_boundary_level)
      return {};
    return internal::boundary_family_switches(*m_idx, *m_topology, cover(), level_sheets(cover()));
  }
  const internal::Mesh_indices<TriangleMesh>& indices() const { return *m_idx; }
  const internal::Topology& topology() const { return *m_topology; }
  const internal::Direction_field_cover& cover() const { require_field(); return m_solver->cover(); }
  const Solver& solver() const { require_field(); return *m_solver; }
  /// y per edge index (d values), along the edge's orientation
  const std::vector<Value>& one_form() const { return solution().y; }
  const std::vector<Value>& target_one_form() const { require_field(); return m_omega; }
  /// per vertex: the stripe angles on the vertex's representative
  const std::vector<Value>& vertex_values() const { return solution().alpha; }
  /// @}

private:
  // the pieces of the isolines, face by face, family by family
  void add_isolines(internal::Stripe_isoline_builder& builder, int singular_face_subdivision) const
  {
    const auto& regular = cover().regular;
    const auto& y = solution().y;
    for(std::size_t f = 0; f < m_idx->number_of_faces(); ++f)
    {
      const auto face = internal::stripe_isoline_face(*m_idx, m_vpm, f);
      const auto beta = walk(f);
      const Value curl = regular[f] ? Value(m_solver->curl(y, f)) : Value::Zero();
      for(int a = 0; a < number_of_families(); ++a)
      {
        if(!regular[f])
          internal::add_branch_face_isolines(builder, face, a, {beta[0][a], beta[1][a], beta[2][a], beta[3][a]},
                                             branch_value(f)[a], branch_point_coordinates(f));
        else
          internal::add_regular_face_isolines(builder, face, a, {beta[0][a], beta[1][a], beta[2][a]},
                                              int(std::lround(curl[a] / internal::two_pi)), singular_face_subdivision);
      }
    }
  }
  // the target one-form changes (no factorization); before set_field() it is made there
  void frequency_changed()
  {
    if(!m_solver)
      return;
    m_relaxation.reset();
    m_solved = false;
    m_windings_valid = false;
    update_omega();
  }
  static void check_frequency(double s)
  {
    if(!std::isfinite(s) || !(s > 0.))
      throw Invalid_parameter("stripes_per_unit_length", "must be positive and finite, got " + std::to_string(s));
  }
  void require_field() const
  {
    if(!m_solver)
      throw Invalid_constraints("set_field() has not been called");
  }
  const typename Solver::Solution& solution() const
  {
    if(!m_solved)
      throw Invalid_constraints("solve() has not been called");
    return m_solution;
  }
  std::size_t checked_face(face_descriptor f) const
  {
    const std::size_t i = m_idx->find(f);
    if(i == internal::npos)
      throw Invalid_constraints("the face is not a face of this mesh");
    return i;
  }
  int checked_family(int family) const
  {
    if(family < 0 || family >= number_of_families())
      throw Invalid_constraints("stripe family " + std::to_string(family) + " does not exist (a " +
                                (m_n == 4 ? "cross field has families 0 and 1)" : "vector or line field has family 0)"));
    return family;
  }
  void require_singularity_allowed(std::size_t f) const
  {
    if(m_face_boundary[f])
      throw Invalid_constraints("face " + std::to_string(f) + " has an edge on the boundary: it cannot hold a stripe "
                                "singularity (the boundary's winding absorbs it); choose a face with no edge on the "
                                "boundary");
    if(m_solver && !cover().regular[f])
      throw Invalid_constraints("face " + std::to_string(f) + " is a branch face of the field (index " +
                                std::to_string(cover().index_numerator[f]) + "/" + std::to_string(m_n) +
                                "): the stripe angle is not single-valued around it, so it cannot hold a stripe "
                                "singularity; choose a neighbouring face");
  }
  std::size_t reference_vertex(std::size_t f) const { return m_idx->source_index(halfedge(m_idx->face(f), m_tm)); }

  double stiffness(std::size_t f) const { return m_stiffness.empty() ? 1. : m_stiffness[f]; }

  // The stiffness after stiffen(faces, factor, ring_factor), its arguments checked (the faces' indices)
  template <class FaceRange>
  std::vector<double> stiffness_after(const FaceRange& faces, double factor, double ring_factor,
                                      std::vector<std::size_t>& indices) const
  {
    require_field();
    if(!std::isfinite(factor) || !(factor >= 1.))
      throw Invalid_parameter("factor", "must be finite and at least 1, got " + std::to_string(factor));
    if(!std::isfinite(ring_factor) || !(ring_factor >= 1.))
      throw Invalid_parameter("ring_factor", "must be finite and at least 1, got " + std::to_string(ring_factor));
    for(face_descriptor f : faces)
      indices.push_back(checked_face(f));
    return internal::stiffened(*m_idx, m_stiffness, indices, factor, ring_factor);
  }

  // A new solver for the current field, after a change of its constraints (the lattice, the boundary).
  void refactor()
  {
    const internal::Direction_field_cover cover = m_solver->cover();
    auto solver = std::make_unique<Solver>(m_idx, m_topology, cover, weights(cover), internal::new_solver_like(m_traits),
                                           "twisted Laplacian of the stripes", spoke_weights(cover), level_sheets(cover));
    solver->set_lattice_branch_points(m_lattice);
    m_solver = std::move(solver);
    update_omega();
    ++m_factorizations;
    m_relaxation.reset();
    m_solved = false; // the windings stay valid: the same field and indices, other weights
  }

  // With boundary_on_level_lines(): the sheets normal to the boundary (cover_constraints.h)
  std::vector<std::uint8_t> level_sheets(const internal::Direction_field_cover& cover) const
  {
    return m_boundary_level
             ? internal::boundary_normal_sheets(*m_idx, *m_topology, m_connection.frames, cover, m_boundary_offset)
             : std::vector<std::uint8_t>();
  }

  // The stripes' weights (stripe_weights.h): per edge, and per branch face its spokes'
  std::vector<double> weights(const internal::Direction_field_cover& cover) const
  {
    return internal::stripe_edge_weights(*m_idx, m_vpm, cover, m_cot, m_stiffness, m_lattice, m_uniform);
  }
  std::vector<std::array<double, 3>> spoke_weights(const internal::Direction_field_cover& cover) const
  {
    return internal::stripe_spoke_weights(*m_idx, m_vpm, cover, m_stiffness, m_lattice, m_uniform);
  }
  std::array<Eigen::Vector3d, 3> corners(std::size_t f) const { return internal::face_corners(*m_idx, m_vpm, f); }
  std::array<double, 3> branch_point_coordinates(std::size_t f) const
  {
    return internal::branch_point_barycentric(corners(f));
  }
  Eigen::Vector3d branch_point_position(std::size_t f) const
  {
    return internal::branch_point_position(*m_idx, m_vpm, f);
  }

  // omega per edge and sheet, and the spokes' targets (branched_target_one_form.h)
  void update_omega()
  {
    const internal::Cover_sheet_field field{m_connection.frames, cover(), m_frequency_scale};
    m_omega = internal::branched_edge_targets(*m_idx, m_vpm, field, m_length, m_frequency,
                                              m_convention == One_form_convention::projected);
    if(m_solver->has_spokes())
      m_solver->set_spoke_targets(internal::branched_spoke_targets(
        *m_idx, m_vpm, field, m_frequency, [this](std::size_t h) { return m_solver->transition_along(h); }));
  }

  // The walk around face f and the value at its branch point (stripe_interpolation.h)
  auto walk(std::size_t f) const { return internal::face_walk(*m_idx, *m_solver, solution(), f, reference_vertex(f)); }
  Value branch_value(std::size_t f) const
  {
    return internal::branch_point_value(*m_idx, *m_solver, solution(), f, reference_vertex(f), cover().d);
  }

  const TriangleMesh& m_tm;
  VertexPointMap m_vpm;
  SolverTraits m_traits;
  int m_n = 2;
  bool m_uniform = false, m_lattice = false;
  bool m_windings_valid = false; // the last solve's windings hold for the current field and indices
  std::vector<double> m_stiffness; // per face (stiffen()), empty: all 1
  bool m_keep_stiffening = false;  // by set_field()
  bool m_boundary_level = false;    // boundary loops on level-0 lines
  std::vector<double> m_boundary_offset; // the smoothed boundary's offsets (empty: edge by edge)
  bool m_own_analysis_cache = false;
  std::shared_ptr<const Indices> m_idx;
  std::shared_ptr<const internal::Topology> m_topology;
  internal::Discrete_connection m_connection;
  std::vector<double> m_cot, m_length, m_vertex_area;
  std::vector<bool> m_face_boundary;

  std::unique_ptr<Solver> m_solver;
  One_form_convention m_convention = One_form_convention::projected;
  double m_frequency = 1.;
  std::vector<double> m_frequency_scale; // per vertex (set_frequency_scale()), empty: all 1
  std::vector<Value> m_omega;
  std::vector<Eigen::Vector2i> m_index;
  std::optional<std::vector<Eigen::Vector2i>> m_relaxation;

  std::size_t m_factorizations = 0;
  bool m_solved = false;
  typename Solver::Solution m_solution;
};

/// Deduces the point map and solver types from the named parameters.
template <class TriangleMesh, class NamedParameters>
Branched_stripe_parameterizer(const TriangleMesh&, const NamedParameters&)
  -> Branched_stripe_parameterizer<TriangleMesh, internal::Const_vertex_point_map_t<TriangleMesh, NamedParameters>,
                                   internal::Solver_traits_t<NamedParameters>>;
template <class TriangleMesh>
Branched_stripe_parameterizer(const TriangleMesh&) -> Branched_stripe_parameterizer<TriangleMesh>;

} // namespace Surface_design
} // namespace CGAL

#endif // CGAL_SURFACE_DESIGN_BRANCHED_STRIPE_PARAMETERIZER_H
