// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The closest periodic 1-form on the branched cover of an n-direction field, solved on the base
// mesh: the stripe problem of Noma & Kawahara on line fields (n = 2) and cross fields (n = 4).

#ifndef CGAL_SURFACE_DESIGN_INTERNAL_CORE_BRANCHED_ONE_FORM_SOLVER_H
#define CGAL_SURFACE_DESIGN_INTERNAL_CORE_BRANCHED_ONE_FORM_SOLVER_H

#include <CGAL/Surface_design/exceptions.h>
#include <CGAL/assertions.h>
#include <CGAL/Surface_design/internal/Core/angles.h>
#include <CGAL/Surface_design/internal/Core/cover_constraints.h>
#include <CGAL/Surface_design/internal/Core/dec.h>
#include <CGAL/Surface_design/internal/Core/direction_field_cover.h>
#include <CGAL/Surface_design/internal/Core/dual_forest_peeling.h>
#include <CGAL/Surface_design/internal/Core/Mesh_indices.h>
#include <CGAL/Surface_design/internal/Core/sparse_one_forms.h>
#include <CGAL/Surface_design/internal/Core/topology.h>
#include <CGAL/Surface_design/internal/Solvers/Factored_system.h>
#include <CGAL/Surface_design/internal/Solvers/integer_quadratic.h>
#include <CGAL/Surface_design/internal/Solvers/parallel.h>
#include <CGAL/Surface_design/internal/Solvers/sparse_types.h>

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_design {
namespace internal {

/// Solves the stripe problem on the cover of an n-direction field (n = 1, 2, 4), with d values
/// per vertex (the sheets 0 .. d-1; sheet a + n/2 is the negation of sheet a):
///
///   minimize sum_e w_e |y_e - omega_e|^2 over y in (R^d)^E
///   subject to: y = d_P alpha + 2 pi m for some alpha in (R^d)^V and m in (Z^d)^E, and the
///   twisted curl of y is 2 pi k_f in every regular face f,
///
/// where (d_P alpha)_e = P_e alpha_j - alpha_i along e = (i -> j), P_e the signed permutation of
/// the sheets along e (`sheet_transition`). The twisted curl of a face starts at the source v0 of
/// its first halfedge on the face's reference sheets (those of v0's representative):
/// y(h0) + M1 y(h1) + M2 y(h2), M1 = P(h0), M2 = P(h0) P(h1), and y(h) = -P_e^T y_e on a halfedge
/// against its edge. Branch faces (the product of the transitions around them is not the
/// identity) carry no constraint: whatever y does there, the walk around the face returns to
/// another sheet, and the value at the branch point is fixed by the sheets' symmetry (0 or pi for
/// a line field).
///
/// **How.** With m = 0 on the primal spanning tree (the gauge of the cover makes P = I there), the
/// feasible y are y* + d_P f + (integer combinations of free directions). y* = 2 pi m* is built
/// by peeling a dual spanning forest whose roots are the unconstrained nodes (branch faces and
/// boundary loops); the edges in neither the tree nor the forest are the free integer
/// directions eta_j (one per edge and sheet), whose windings are chosen to minimize the energy.
/// f solves L f = d_P^T W (omega - y*) with the twisted Laplacian L = d_P^T W d_P, factored once;
/// L is definite on a component whose monodromy is non-trivial (no sheet value is invariant), and
/// is pinned at the root elsewhere (where the problem is the vector field's, with Stokes' theorem).
/// The weights of branch faces' edges are expected to be dropped by the caller (the energy of a
/// regular face is then that of a P1 function in a local gauge: L is semi-definite for cotangent
/// weights too).
///
/// **Windings.** g_j = <eta_j, y - omega>_W and Q_jk = <eta_j, xi_k>_W (xi_k = eta_k - d_P phi_k
/// the harmonic part: y - omega and xi_k are W-orthogonal to d_P of anything), so that the
/// integer step c minimizes 2 g^T c + c^T Q c; the corrected y is one more back-substitution with
/// y* + 2 pi sum c_j eta_j. Directions whose harmonic part depends on the earlier ones (the global
/// shift of alpha by pi makes one of them redundant on a twisted component) are left out.
///
/// **Branch points on the lattice** (`set_lattice_branch_points()`). Around a branch face f the
/// walk of y returns as x -> M x + 2 pi t (M the product of the transitions, t the integer curl of
/// y* + 2 pi sum c_j eta_j), so the branch point carries the fixed point p = 2 pi (I - M)^-1 t,
/// and q = 2 (I - M)^-1 t = K t is an integer vector (K = the adjugate of I - M for a quarter
/// turn, I for a half turn). p is 0 modulo 2 pi (a cone of a cross field on a lattice point, the
/// condition for a quad mesh; a line field's branch point on a stripe) when q is even; the global
/// shift of alpha by pi (1, 1), which keeps y, adds (1, 1) to every q of a component. The
/// windings c are therefore chosen among those with K_f t_f = s (1, 1) (mod 2) at every branch
/// face, s in {0, 1} per component: the coset offset + B z of a sublattice
/// (`parity_coset()`), minimized over z exactly as before with the form B^T Q B; then alpha is
/// shifted by pi where s = 1.
///
/// **Spokes.** Alone, these conditions are met for free by a jump of 2 pi across an edge of the
/// branch face, where the map then folds around a branch point far from its corners' values. With
/// spoke weights, the energy also holds the segments from the corners c_k of every branch face to
/// its branch point o: sum_k w_k |(p - beta_k) - b_k|^2, with beta_k the corner values on the
/// face's reference sheets (the walk), p - beta_k = (I - M)^-1 S_3 - S_k linear in y (S_k the walk
/// of y to corner k), and targets b_k (`set_spoke_targets()`: the field integrated from c_k to o).
/// This is the energy of the three triangles (c_k, c_k+1, o) on their spokes; W is then no longer
/// diagonal: it couples the three edges of every branch face.
template <class TriangleMesh, class SolverTraits>
class Branched_one_form_solver
{
public:
  using Indices = Mesh_indices<TriangleMesh>;
  using Value = Eigen::Vector2d; ///< the sheet values of an edge or vertex (second one unused for d = 1)
  using Face_index = Eigen::Vector2i;

  struct Solution
  {
    std::vector<Value> y;     ///< per edge, along its orientation
    std::vector<Value> alpha; ///< per vertex: y = d_P alpha + 2 pi (integers) on every edge
    double energy = 0.;
    std::size_t free_directions = 0, winding_changes = 0;
    std::vector<Value> windings; ///< per edge: the particular solution with the chosen windings (2 pi integers)
    Eigen::VectorXd potential;   ///< per value (v d + a): f with y = windings + d_P f, before the lattice offsets
  };

  /// \param weight per edge, with the contributions of branch faces already removed
  /// \param spoke_weight per face, empty or the weights of the three spokes from the corners of a
  ///        branch face to its branch point (see the class documentation); 0 in regular faces
  /// \param level_sheets per edge, empty or a bit mask of the sheets (in the frame of the edge's
  ///        source) on which the edge lies on a level-0 line: alpha = 0 (mod 2 pi) at its ends and
  ///        y = 0 on it (boundary edges only; a loop with one such edge must have them all, and
  ///        the tree must hold all its edges but one: `compute_topology(idx, true)`)
  Branched_one_form_solver(std::shared_ptr<const Indices> idx, std::shared_ptr<const Topology> topology,
                           const Direction_field_cover& cover, std::vector<double> weight, SolverTraits traits,
                           const std::string& name, const std::vector<std::array<double, 3>>& spoke_weight = {},
                           std::vector<std::uint8_t> level_sheets = {})
    : m_idx_ptr(std::move(idx)), m_topology_ptr(std::move(topology)), m_idx(*m_idx_ptr), m_topology(*m_topology_ptr), m_cover(cover), m_weight(std::move(weight)), m_system(std::move(traits), name), m_level_sheets(std::move(level_sheets))
  {
    const std::size_t ne = m_idx.number_of_edges();
    m_P.resize(ne);
    m_ends.resize(ne);
    for(std::size_t e = 0; e < ne; ++e)
    {
      m_P[e] = sheet_transition(m_cover.n, m_cover.matching[e]);
      m_ends[e] = m_idx.edge_vertices(e);
    }
    m_twisted = twisted_components(m_idx, m_topology, m_P, m_ends); // cover_constraints.h
    collect_branch_faces(spoke_weight);
    collect_level_constraints();
    build_forest();
    factor();
  }

  /// New weights, as in the constructor (the spokes' given if and only if they were): factors
  /// again and keeps the rest (the forest, the free directions and the constraints do not depend
  /// on the weights); the windings of earlier solutions stay valid for `solve_with_windings()`.
  /// \throws Linear_solver_failure if the factorization fails; the old weights are then kept
  ///         (and factored again)
  /// With `factor_now` false the factorization waits for the next `solve()` or
  /// `solve_with_windings()` (`solve_with_windings_near()` needs none).
  void set_weights(std::vector<double> weight, const std::vector<std::array<double, 3>>& spoke_weight,
                   bool factor_now = true)
  {
    CGAL_precondition(weight.size() == m_weight.size() && spoke_weight.empty() != m_spokes);
    auto swap_weights = [&](std::vector<double>& w, std::vector<std::array<double, 3>>& spokes) {
      std::swap(w, m_weight);
      for(std::size_t b = 0; m_spokes && b < m_branch.size(); ++b)
        std::swap(spokes[m_branch[b].face], m_branch[b].spoke_weight);
    };
    std::vector<std::array<double, 3>> spokes = spoke_weight;
    swap_weights(weight, spokes);
    m_basis_ready = m_lattice_ready = false;
    m_potential_basis.resize(0, 0);
    if((m_stale = !factor_now)) // factored by the next solve
      return;
    try
    {
      factor();
    }
    catch(...)
    {
      swap_weights(weight, spokes);
      factor();
      throw;
    }
  }
  int values_per_vertex() const { return m_cover.d; }
  const Direction_field_cover& cover() const { return m_cover; }
  const std::vector<double>& weights() const { return m_weight; }
  const Eigen::Matrix2d& transition(std::size_t e) const { return m_P[e]; }
  /// Whether connected component c has a non-trivial monodromy (then no Stokes condition holds).
  bool is_twisted(std::size_t c) const { return m_twisted[c]; }
  std::size_t number_of_free_directions() const { return m_free.size(); }
  /// The integer directions of the windings: the free edges' and one per chain of values on a
  /// level-0 boundary line (its offset, 2 pi times an integer).
  std::size_t number_of_directions() const { return m_free.size() + m_chain_eta.size(); }
  /// Whether vertex v's values are pinned to 0 (one per piece of the weighted graph whose
  /// transport is trivial): the optimality condition d_P^T W (y - omega) = 0 holds elsewhere.
  bool is_pinned(std::size_t v) const
  {
    return m_fixed[v * std::size_t(m_cover.d)] && (m_cover.d == 1 || m_fixed[v * std::size_t(m_cover.d) + 1]);
  }
  /// Whether value a of vertex v is fixed (a pin, or a vertex on a level-0 boundary line).
  bool is_fixed(std::size_t v, int a) const { return m_fixed[v * std::size_t(m_cover.d) + std::size_t(a)]; }

  /// The targets b_k of the spokes, per face (read in branch faces only), on the face's reference
  /// sheets; 0 until set.
  void set_spoke_targets(const std::vector<std::array<Value, 3>>& target)
  {
    for(Branch& b : m_branch)
      b.target = target[b.face];
  }
  bool has_spokes() const { return m_spokes; }

  /// Whether `solve()` puts every branch point at 0 modulo 2 pi (see the class documentation).
  void set_lattice_branch_points(bool on) { m_lattice = on; }
  bool lattice_branch_points() const { return m_lattice; }

  /// The minimizer for `omega` (per edge) and the integer indices `k` (per face, read in regular
  /// faces only; the faces' reference sheets as in the class documentation).
  /// \throws Invalid_constraints if, on an untwisted closed component, the indices of a sheet do
  ///         not sum to 0 (Stokes' theorem)
  Solution solve(const std::vector<Value>& omega, const std::vector<Face_index>& k)
  {
    check_stokes_sums(m_topology.components, m_cover.regular, m_stokes_component, m_cover.d, k); // cover_constraints.h
    ensure_factored();
    Solution s;
    std::vector<Value> ystar = particular_solution(k);
    s.y = optimal_one_form(ystar, omega, &s.alpha);
    s.free_directions = number_of_directions();
    const bool lattice = m_lattice && !m_branch.empty();
    if(number_of_directions() > 0)
    {
      ensure_harmonic_basis();
      const std::size_t m = m_kept.size();
      Eigen::VectorXd g = Eigen::VectorXd::Zero(Eigen::Index(m));
      const std::vector<Value> gradient = weighted_residual(s.y, &omega);
      for(std::size_t j = 0; j < m; ++j)
        g[Eigen::Index(j)] = sparse_dot(m_eta[m_kept[j]], gradient);
      const Eigen::VectorXi c = lattice ? lattice_windings(g, ystar) : closest_integer_point(m_reduced, g);
      bool changed = false;
      for(std::size_t j = 0; j < m; ++j)
        if(c[Eigen::Index(j)] != 0)
        {
          changed = true;
          ++s.winding_changes;
          for(const auto& [e, v] : m_eta[m_kept[j]])
            ystar[e] += double(c[Eigen::Index(j)]) * v;
        }
      if(changed && m_potential_basis.cols() > 0)
      {
        // the potential is affine in ystar: add those of the moved directions instead of a second
        // back-substitution (median edits at 60k faces: line fields 8.3 -> 5.4 ms, cross 31.9 -> 26.5)
        const std::size_t d = std::size_t(m_cover.d);
        Eigen::VectorXd f = m_potential_basis * c.cast<double>();
        for(std::size_t v = 0; v < s.alpha.size(); ++v)
          for(std::size_t a = 0; a < d; ++a)
            f[Eigen::Index(v * d + a)] += s.alpha[v][Eigen::Index(a)];
        s.y = one_form_of_potential(ystar, f, &s.alpha);
      }
      else if(changed)
        s.y = optimal_one_form(ystar, omega, &s.alpha);
    }
    s.potential = potential_vector(s.alpha);
    finish_lattice(ystar, s.alpha); // ystar holds the windings now
    s.energy = energy(s.y, omega);
    s.windings = std::move(ystar);
    return s;
  }

  /// The optimal solution with the integers of `previous` (of a system with this cover and these
  /// indices, other weights: a stiffening): one back-substitution, no windings chosen.
  Solution solve_with_windings(const std::vector<Value>& omega, const Solution& previous)
  {
    ensure_factored();
    return with_potential(omega, previous, m_system.solve(potential_rhs(previous.windings, &omega)));
  }

  /// As `solve_with_windings()`, but the potential of `previous` is kept at all vertices but
  /// `vertices` (indices), the boundary values of its minimizer there: a local relaxation (after
  /// a stiffening of the faces around them). One sparse factorization of their block of L, not
  /// of L (whose factorization may wait: `set_weights()`); the minimizer of the whole energy with
  /// these windings when `vertices` holds them all.
  /// \throws Linear_solver_failure if that factorization fails
  Solution solve_with_windings_near(const std::vector<Value>& omega, const Solution& previous,
                                    const std::vector<std::size_t>& vertices)
  {
    CGAL_precondition(previous.potential.size() == Eigen::Index(m_fixed.size()));
    const std::size_t d = std::size_t(m_cover.d);
    const Sparse_matrix L = assemble(); // (the current weights: the same pins)
    const Eigen::VectorXd b = potential_rhs(previous.windings, &omega);
    Eigen::VectorXd f = previous.potential;
    std::vector<Eigen::Index> relaxed; // the values of those vertices that are not pinned
    for(std::size_t v : vertices)
      for(std::size_t a = 0; a < d; ++a)
        if(!m_fixed[v * d + a])
          relaxed.push_back(Eigen::Index(v * d + a));
    solve_on_subset<SolverTraits>(L, b, f, relaxed, "twisted Laplacian of the relaxed vertices");
    return with_potential(omega, previous, std::move(f));
  }

  /// Whether the weights changed without a factorization since (`set_weights()`).
  bool factorization_pending() const { return m_stale; }

  double energy(const std::vector<Value>& y, const std::vector<Value>& omega) const
  {
    double sum = 0.;
    for(std::size_t e = 0; e < y.size(); ++e)
      sum += m_weight[e] * (y[e] - omega[e]).head(m_cover.d).squaredNorm();
    if(m_spokes)
      for(const Branch& b : m_branch)
        for(int k = 0; k < 3; ++k)
        {
          // the second values of a line field's spokes and targets are 0
          const Value r = spoke(b, k, y) - b.target[std::size_t(k)];
          sum += b.spoke_weight[std::size_t(k)] * r.squaredNorm();
        }
    return sum;
  }

  /// The value of y along halfedge index h (from its source's sheets): y_e along the edge,
  /// -P_e^T y_e against it.
  Value along(const std::vector<Value>& y, std::size_t h) const
  {
    const auto hd = m_idx.halfedge(h);
    const std::size_t e = m_idx.edge_index(hd);
    return m_idx.orientation_sign(hd) > 0 ? y[e] : Value(-(m_P[e].transpose() * y[e]));
  }
  /// The transition along halfedge index h.
  Eigen::Matrix2d transition_along(std::size_t h) const
  {
    const auto hd = m_idx.halfedge(h);
    const std::size_t e = m_idx.edge_index(hd);
    return m_idx.orientation_sign(hd) > 0 ? m_P[e] : Eigen::Matrix2d(m_P[e].transpose());
  }

  /// The twisted curl of y around face f, on its reference sheets.
  Value curl(const std::vector<Value>& y, std::size_t f) const
  {
    Value sum = Value::Zero();
    Eigen::Matrix2d M = Eigen::Matrix2d::Identity();
    for(auto h : halfedges_around_face(halfedge(m_idx.face(f), m_idx.mesh()), m_idx.mesh()))
    {
      const std::size_t hi = m_idx.index(h);
      sum += M * along(y, hi);
      M = M * transition_along(hi);
    }
    return sum;
  }

private:
  struct Branch;
  // --- branch points on the lattice

  // The branch faces, with K = 2 (I - M)^-1 (integer) of their monodromy M on the reference
  // sheets, and their spokes: r_k = p - beta_k = sum_i R[k][i] y_(e_i) over the face's edges e_i.
  void collect_branch_faces(const std::vector<std::array<double, 3>>& spoke_weight)
  {
    const int d = m_cover.d;
    m_spokes = !spoke_weight.empty();
    for(std::size_t f = 0; f < m_idx.number_of_faces(); ++f)
    {
      if(m_cover.regular[f])
        continue;
      Branch b;
      // C_i: the coefficient of y_(e_i) in the walk (the peeling's), M_i the transport before it
      std::array<Eigen::Matrix2d, 3> C;
      Eigen::Matrix2d M = Eigen::Matrix2d::Identity();
      int i = 0;
      for(auto h : halfedges_around_face(halfedge(m_idx.face(f), m_idx.mesh()), m_idx.mesh()))
      {
        const std::size_t hi = m_idx.index(h), e = m_idx.edge_index(h);
        b.edge[std::size_t(i)] = e;
        C[std::size_t(i)] = m_idx.orientation_sign(h) > 0 ? M : Eigen::Matrix2d(-M * m_P[e].transpose());
        M = M * transition_along(hi);
        ++i;
      }
      Eigen::Matrix2d A = Eigen::Matrix2d::Identity() - M;
      if(d == 1)
        A(1, 1) = 1.; // the unused second value
      const Eigen::Matrix2d Ainv = A.inverse();
      const Eigen::Matrix2d K = 2. * Ainv;
      b.face = f;
      b.component = m_topology.components.face_component[f];
      b.K.setZero();
      for(int r = 0; r < d; ++r)
        for(int c = 0; c < d; ++c)
          b.K(r, c) = int(std::lround(K(r, c)));
      for(std::size_t k = 0; k < 3; ++k)
        for(std::size_t j = 0; j < 3; ++j)
        {
          b.R[k][j] = Ainv * C[j];
          if(j < k)
            b.R[k][j] -= C[j];
          if(d == 1)
            b.R[k][j].row(1).setZero(), b.R[k][j].col(1).setZero();
        }
      if(m_spokes)
        b.spoke_weight = spoke_weight[f];
      m_branch.push_back(b);
    }
  }

  // r_k of branch b for the one-form y
  Value spoke(const Branch& b, int k, const std::vector<Value>& y) const
  {
    Value r = Value::Zero();
    for(std::size_t j = 0; j < 3; ++j)
      r += b.R[std::size_t(k)][j] * y[b.edge[j]];
    return r;
  }

  // W y - c, with c the linear term of the targets (W (y - omega) without spokes); y alone when
  // omega is null (W y)
  std::vector<Value> weighted_residual(const std::vector<Value>& y, const std::vector<Value>* omega) const
  {
    std::vector<Value> out(y.size());
    for(std::size_t e = 0; e < y.size(); ++e)
      out[e] = m_weight[e] * (omega ? Value(y[e] - (*omega)[e]) : y[e]);
    if(m_spokes)
      for(const Branch& b : m_branch)
        for(int k = 0; k < 3; ++k)
        {
          Value r = spoke(b, k, y);
          if(omega)
            r -= b.target[std::size_t(k)];
          r *= b.spoke_weight[std::size_t(k)];
          for(std::size_t j = 0; j < 3; ++j)
            out[b.edge[j]] += b.R[std::size_t(k)][j].transpose() * r;
        }
    return out;
  }

  // The integer curl t_f of a 2 pi-integer form at every branch face.
  std::vector<Face_index> branch_curls(const std::vector<Value>& y) const
  {
    std::vector<Face_index> t(m_branch.size());
    for(std::size_t b = 0; b < m_branch.size(); ++b)
    {
      const Value c = curl(y, m_branch[b].face) / two_pi;
      t[b] = Face_index(int(std::lround(c[0])), int(std::lround(c[1])));
    }
    return t;
  }

  // q = K t modulo 2 (per sheet value) at branch b
  Face_index branch_parity(std::size_t b, const Face_index& t) const
  {
    Face_index q = m_branch[b].K * t;
    for(int a = 0; a < 2; ++a)
      q[a] = ((q[a] % 2) + 2) % 2;
    return q;
  }

  // The windings c (in the kept directions) minimizing 2 g^T c + c^T Q c among those that put
  // every branch point at 0 or every branch point of a component at pi (1, 1) (the global shift
  // of alpha then moves them all to 0).
  Eigen::VectorXi lattice_windings(const Eigen::VectorXd& g, const std::vector<Value>& ystar)
  {
    const std::size_t m = m_kept.size(), d = std::size_t(m_cover.d);
    std::vector<std::size_t> aux(m_topology.components.size(), npos);
    std::size_t n_aux = 0;
    for(const Branch& b : m_branch)
      if(aux[b.component] == npos && !m_level_component[b.component]) // no global shift by pi there
        aux[b.component] = n_aux++;
    const std::vector<Face_index> t0 = branch_curls(ystar);
    std::vector<std::vector<std::uint8_t>> rows;
    std::vector<std::uint8_t> rhs;
    for(std::size_t b = 0; b < m_branch.size(); ++b)
    {
      const Face_index q0 = branch_parity(b, t0[b]);
      for(std::size_t a = 0; a < d; ++a)
      {
        std::vector<std::uint8_t> row(m + n_aux, 0);
        for(std::size_t j = 0; j < m; ++j)
          row[j] = std::uint8_t(branch_parity(b, m_direction_curl[m_kept[j]][b])[Eigen::Index(a)]);
        if(aux[m_branch[b].component] != npos)
          row[m + aux[m_branch[b].component]] = 1;
        rows.push_back(std::move(row));
        rhs.push_back(std::uint8_t(q0[Eigen::Index(a)]));
      }
    }
    const Parity_coset coset = parity_coset(rows, rhs, m, n_aux);
    if(!coset.feasible)
      throw Invalid_constraints(
        "the branch points of the field cannot all lie on the lattice of the stripes (every stripe angle 0 modulo "
        "2 pi there): no choice of the windings meets the parity conditions of its " +
        std::to_string(m_branch.size()) + " branch faces; move or add singularities");
    if(!m_lattice_ready)
    {
      const Eigen::MatrixXd B = coset.basis.cast<double>();
      m_lattice_basis = B;
      m_lattice_reduced = reduce_integer_quadratic(B.transpose() * m_Q * B);
      m_lattice_ready = true;
    }
    const Eigen::VectorXd c0 = coset.offset.cast<double>();
    const Eigen::VectorXd g_lattice = m_lattice_basis.transpose() * (g + m_Q * c0);
    const Eigen::VectorXi z = closest_integer_point(m_lattice_reduced, g_lattice);
    return coset.offset + (m_lattice_basis * z.cast<double>()).array().round().cast<int>().matrix();
  }

  // With lattice branch points: theirs to 0, the pieces pinned at 0 to a generic offset
  void finish_lattice(const std::vector<Value>& windings, std::vector<Value>& alpha) const
  {
    if(m_lattice && !m_branch.empty())
      shift_to_lattice(windings, alpha);
    for(std::size_t v = 0; m_lattice && v < alpha.size(); ++v)
      alpha[v] += m_free_offset[v];
  }

  // After the windings: every branch point of a component is at 0, or all at pi (1, 1), shifted
  // to 0 here (y is unchanged: (P_e - I) pi (1, 1) is a multiple of 2 pi). ystar with the
  // windings (2 pi integers) gives t exactly.
  void shift_to_lattice(const std::vector<Value>& ystar, std::vector<Value>& alpha) const
  {
    const std::vector<Face_index> t = branch_curls(ystar);
    std::vector<int> shift(m_topology.components.size(), -1);
    for(std::size_t b = 0; b < m_branch.size(); ++b)
    {
      const Face_index q = branch_parity(b, t[b]);
      int& s = shift[m_branch[b].component];
      const bool uniform = m_cover.d == 1 || q[0] == q[1];
      if(m_level_component[m_branch[b].component])
        s = 0; // the boundary's level lines fix the shift
      if(s == -1 && uniform)
        s = q[0];
      if(!uniform || q[0] != s)
        throw Invalid_constraints("the branch points of the field cannot all lie on the lattice of the stripes: the "
                                  "windings found leave branch face " + std::to_string(m_branch[b].face) +
                                  " off it; move or add singularities");
    }
    const double half = 0.5 * two_pi;
    for(std::size_t v = 0; v < alpha.size(); ++v)
      if(shift[m_topology.components.vertex_component[v]] == 1)
        for(int a = 0; a < m_cover.d; ++a)
          alpha[v][a] += half;
  }

  // --- boundary loops on level-0 lines (cover_constraints.h)
  void collect_level_constraints()
  {
    Boundary_level_lines l = boundary_level_lines(m_idx, m_topology, m_P, m_ends, m_level_sheets, m_cover.d);
    m_level_loop = std::move(l.loop);
    m_level_component = std::move(l.component);
    m_level_values = std::move(l.values);
    m_chain_eta = std::move(l.chain_eta);
  }

  // The dual forest: roots are the branch faces and the boundary loops (no closure to meet), and
  // one face on each closed component without branch faces (its closure follows from the others
  // by Stokes' theorem when the component is not twisted).
  void build_forest()
  {
    const auto& tm = m_idx.mesh();
    const Tree_cotree& t = m_topology.tree;
    const Boundary_loops& loops = m_topology.boundary;
    const std::size_t nf = m_idx.number_of_faces(), nd = nf + loops.size();
    std::vector<std::size_t> parent_edge_of(nd, npos);
    std::vector<bool> reached(nd, false), in_forest(m_idx.number_of_edges(), false);
    std::vector<bool> stokes_fixed(m_idx.number_of_edges(), false); // no free winding alone (below)
    std::vector<std::pair<std::size_t, std::size_t>> stokes_loops; // (root face, loop edge)
    std::vector<std::size_t> order;
    order.reserve(nd);
    auto dual_node = [&](std::size_t h) {
      const auto hd = m_idx.halfedge(h);
      return m_idx.is_border(hd) ? nf + loops.loop_of_halfedge[h] : m_idx.index(face(hd, tm));
    };
    auto grow = [&](std::size_t head) {
      while(head < order.size())
      {
        const std::size_t node = order[head++];
        auto visit = [&](std::size_t h) {
          const std::size_t e = m_idx.edge_index(m_idx.halfedge(h));
          if(t.edge_in_tree[e] || in_forest[e])
            return;
          const std::size_t other = dual_node(m_idx.index(opposite(m_idx.halfedge(h), tm)));
          if(reached[other] || (other >= nf && m_level_loop[other - nf]))
            return; // a loop on level lines is no node: its one edge off the tree is fixed (or free)
          reached[other] = true;
          in_forest[e] = true;
          parent_edge_of[other] = e;
          order.push_back(other);
        };
        if(node < nf)
          for(auto h : halfedges_around_face(halfedge(m_idx.face(node), tm), tm))
            visit(m_idx.index(h));
        else
          for(std::size_t h : loops.loops[node - nf])
            visit(h);
      }
    };
    for(std::size_t f = 0; f < nf; ++f)
      if(!m_cover.regular[f])
      {
        reached[f] = true;
        order.push_back(f);
      }
    for(std::size_t l = 0; l < loops.size(); ++l)
      if(!m_level_loop[l])
      {
        reached[nf + l] = true;
        order.push_back(nf + l);
      }
    grow(0);
    m_stokes_component.assign(m_topology.components.size(), false);
    for(std::size_t f = 0; f < nf; ++f)
      if(!reached[f])
      {
        const std::size_t c = m_topology.components.face_component[f];
        if(m_twisted[c])
          throw Invalid_constraints(
            "connected component " + std::to_string(c) + " has no free boundary, its field has no singularity, and "
            "its sheets are exchanged around a loop (a twisted field on a torus): stripes on such a field are not "
            "supported; give the field a pair of singularities");
        if(m_cover.d == 2 && m_level_component[c])
          for(std::size_t e : stokes_loop_edges(m_idx, m_topology, c)) // (cover_constraints.h)
          {
            stokes_fixed[e] = true;
            stokes_loops.emplace_back(f, e);
          }
        m_stokes_component[c] = true;
        reached[f] = true;
        const std::size_t head = order.size();
        order.push_back(f);
        grow(head);
      }

    m_peeling = Dual_forest_peeling(m_idx, m_P, order, parent_edge_of, [&](std::size_t h) { return transition_along(h); });
    std::vector<bool> off(in_forest.size()); // the edges in neither the tree nor the forest, nor fixed by Stokes
    for(std::size_t e = 0; e < off.size(); ++e)
      off[e] = !t.edge_in_tree[e] && !in_forest[e] && !stokes_fixed[e];
    const std::vector<std::size_t> free_edges = free_winding_edges(m_topology.components, m_ends, m_cover, off);
    auto free_sheet = [&](std::size_t e, int a) { return m_level_sheets.empty() || !((m_level_sheets[e] >> a) & 1); };
    for(std::size_t e : free_edges)
      for(int a = 0; a < m_cover.d; ++a)
        if(free_sheet(e, a)) // a level sheet stays 0
          m_free.push_back({e, a});
    // the loops of a component whose root face closes by Stokes: their windings free in pairs
    // that keep the root's curl (cover_constraints.h)
    for(const auto& x : stokes_loop_directions(stokes_loops, m_cover.d, free_sheet, [&](std::size_t f, std::size_t e, int a) {
          std::vector<Value> y(m_idx.number_of_edges(), Value::Zero());
          y[e][a] = two_pi;
          return Eigen::Vector2d(curl(peel(std::move(y), nullptr), f));
        }))
      m_free.push_back({x.edge, x.sheet, x.partner, x.partner_sheet, x.sign});
  }

  // L = d_P^T W d_P on d values per vertex. Its kernel is the f with P_e f_j = f_i on every edge of
  // non-zero weight: on each connected piece of the graph of such edges (the weights of branch
  // faces are dropped, so adjacent branch faces can cut a component), constant sheet values
  // transported without twist. Pinned: one vertex of every piece whose transport around its
  // loops is trivial (a single vertex whose faces all branch is such a piece).
  void factor()
  {
    m_system.factor(assemble());
    m_stale = false;
  }
  void ensure_factored()
  {
    if(m_stale)
      factor();
  }
  // The solution with the windings of `previous` and the potential f (`Solution::potential`)
  Solution with_potential(const std::vector<Value>& omega, const Solution& previous, Eigen::VectorXd f) const
  {
    Solution s;
    s.windings = previous.windings;
    s.y = one_form_of_potential(s.windings, f, &s.alpha);
    s.free_directions = number_of_directions();
    s.potential = std::move(f);
    finish_lattice(s.windings, s.alpha);
    s.energy = energy(s.y, omega);
    return s;
  }
  Eigen::VectorXd potential_vector(const std::vector<Value>& alpha) const
  {
    const std::size_t d = std::size_t(m_cover.d);
    Eigen::VectorXd f(Eigen::Index(alpha.size() * d));
    for(std::size_t v = 0; v < alpha.size(); ++v)
      for(std::size_t a = 0; a < d; ++a)
        f[Eigen::Index(v * d + a)] = alpha[v][Eigen::Index(a)];
    return f;
  }
  // L with the current weights (and m_fixed, the pins, for them)
  Sparse_matrix assemble()
  {
    const auto& tm = m_idx.mesh();
    const int d = m_cover.d;
    const std::size_t nv = m_idx.number_of_vertices();
    m_fixed.assign(nv * std::size_t(d), false);
    for(const auto& [v, a] : m_level_values)
      m_fixed[v * std::size_t(d) + std::size_t(a)] = true;
    m_free_offset = pin_untwisted_pieces(m_weight, m_P, m_ends, d, m_fixed); // cover_constraints.h

    // L's blocks: (i, i), (j, j) += w I, (i, j) -= w P_e, (j, i) -= w P_e^T per edge e = (i, j); and per
    // spoke w_k G_u^T G_v at (u, v), r_k = sum_j R[k][j] (P_e alpha_second - alpha_first) = sum_v G_v alpha_v
    std::vector<Eigen::Matrix2d> diagonal(nv, Eigen::Matrix2d::Zero());
    for(std::size_t e = 0; e < m_weight.size(); ++e)
      for(std::size_t v : {m_ends[e].first, m_ends[e].second})
        diagonal[v].diagonal().array() += m_weight[e];
    std::map<std::size_t, Eigen::Matrix2d> spoke_blocks; // per halfedge from u to v, their sum
    for(std::size_t b = 0; m_spokes && b < m_branch.size(); ++b)
      for(std::size_t k = 0; k < 3; ++k)
      {
        const Branch& br = m_branch[b];
        std::array<std::pair<std::size_t, Eigen::Matrix2d>, 6> G;
        for(std::size_t j = 0; j < 3; ++j)
        {
          const std::size_t e = br.edge[j];
          G[2 * j] = {m_ends[e].second, br.R[k][j] * m_P[e]};
          G[2 * j + 1] = {m_ends[e].first, -br.R[k][j]};
        }
        for(const auto& [u, Gu] : G)
          for(const auto& [v, Gv] : G)
          {
            const Eigen::Matrix2d block = br.spoke_weight[k] * Gu.transpose() * Gv;
            if(u == v)
              diagonal[u] += block;
            for(auto h : halfedges_around_face(halfedge(m_idx.face(br.face), tm), tm))
              for(auto g : {h, opposite(h, tm)})
                if(u != v && m_idx.source_index(g) == u && m_idx.target_index(g) == v)
                  spoke_blocks.emplace(m_idx.index(g), Eigen::Matrix2d::Zero()).first->second += block;
          }
      }
    if(m_block_pattern.empty()) // (dec.h) built once: set_weights() refills it
      m_block_pattern = Vertex_block_pattern(m_idx, d);
    Sparse_matrix L = m_block_pattern.fill(
      [&](std::size_t h) {
        const Eigen::Matrix2d block = -m_weight[m_idx.edge_index(m_idx.halfedge(h))] * transition_along(h);
        const auto it = spoke_blocks.find(h);
        return it == spoke_blocks.end() ? block : Eigen::Matrix2d(block + it->second);
      },
      [&](std::size_t v) { return diagonal[v]; });
    for(Eigen::Index c = 0; c < L.outerSize(); ++c) // a pinned value: its row and column the identity's
      for(Sparse_matrix::InnerIterator it(L, c); it; ++it)
        if(m_fixed[std::size_t(it.row())] || m_fixed[std::size_t(c)])
          it.valueRef() = it.row() == c ? 1. : 0.;
    return L;
  }

  // y* = 2 pi m*: the free edges at `free_values` (zero elsewhere off the forest), the forest
  // edges peeled so that every constrained face gets its curl 2 pi k_f.
  std::vector<Value> peel(std::vector<Value> y, const std::vector<Face_index>* k) const
  {
    return m_peeling.peel(std::move(y), k, m_cover.d);
  }

  std::vector<Value> particular_solution(const std::vector<Face_index>& k) const
  {
    return peel(std::vector<Value>(m_idx.number_of_edges(), Value::Zero()), &k);
  }

  // y = ystar + d_P f, L f = d_P^T W (omega - ystar), f = 0 at pinned vertices. Since ystar is
  // 2 pi times integers, f is the stripe angle: y = d_P f (mod 2 pi) on every edge (integrating y
  // along a tree from 0 would not do on a twisted component, where the root's value matters).
  std::vector<Value> optimal_one_form(const std::vector<Value>& ystar, const std::vector<Value>& omega,
                                      std::vector<Value>* potential = nullptr) const
  {
    const Eigen::VectorXd f = m_system.solve(potential_rhs(ystar, &omega));
    return one_form_of_potential(ystar, f, potential);
  }

  // d_P^T W (omega - ystar) (omega = 0 when null), 0 at pinned vertices
  Eigen::VectorXd potential_rhs(const std::vector<Value>& ystar, const std::vector<Value>* omega) const
  {
    Eigen::VectorXd b = Eigen::VectorXd::Zero(Eigen::Index(m_fixed.size()));
    const std::vector<Value> residual = weighted_residual(ystar, omega);
    for(std::size_t e = 0; e < residual.size(); ++e)
      subtract_codifferential(e, residual[e], b);
    zero_fixed_rows(b);
    return b;
  }

  // b -= d_P^T x for x on edge e alone
  template <class Vector>
  void subtract_codifferential(std::size_t e, const Value& x, Vector&& b) const
  {
    const std::size_t d = std::size_t(m_cover.d);
    const Value xj = m_P[e].transpose() * x;
    for(std::size_t a = 0; a < d; ++a)
    {
      b[Eigen::Index(m_ends[e].first * d + a)] += x[Eigen::Index(a)];
      b[Eigen::Index(m_ends[e].second * d + a)] -= xj[Eigen::Index(a)];
    }
  }
  template <class Vector>
  void zero_fixed_rows(Vector&& b) const
  {
    for(std::size_t i = 0; i < m_fixed.size(); ++i)
      if(m_fixed[i])
        b[Eigen::Index(i)] = 0.;
  }

  // the values of the potential f (d per vertex) at vertex v, 0 on unused sheets
  template <class Potential>
  Value potential_value(const Potential& f, std::size_t v) const
  {
    const std::size_t d = std::size_t(m_cover.d);
    Value x = Value::Zero();
    for(std::size_t a = 0; a < d; ++a)
      x[Eigen::Index(a)] = f[Eigen::Index(v * d + a)];
    return x;
  }
  // (d_P f) on edge e
  template <class Potential>
  Value differential(const Potential& f, std::size_t e) const
  {
    return m_P[e] * potential_value(f, m_ends[e].second) - potential_value(f, m_ends[e].first);
  }

  // y = ystar + d_P f, and f per vertex in `potential`
  template <class Potential>
  std::vector<Value> one_form_of_potential(const std::vector<Value>& ystar, const Potential& f,
                                           std::vector<Value>* potential) const
  {
    std::vector<Value> y(ystar.size());
    for(std::size_t e = 0; e < y.size(); ++e)
      y[e] = ystar[e] + m_P[e] * potential_value(f, m_ends[e].second) - potential_value(f, m_ends[e].first);
    if(potential)
    {
      potential->resize(m_idx.number_of_vertices());
      for(std::size_t v = 0; v < potential->size(); ++v)
        (*potential)[v] = potential_value(f, v);
    }
    return y;
  }

  using Sparse_form = Sparse_one_form; // sparse_one_forms.h

  // W y of a sparse form y, sparse: its support and the edges of the branch faces whose spokes it
  // reaches (as weighted_residual(), omega null)
  Sparse_form weighted_sparse(const Sparse_form& y) const
  {
    Sparse_form out;
    out.reserve(y.size());
    for(const auto& [e, v] : y)
      out.emplace_back(e, m_weight[e] * v);
    for(std::size_t i = 0; m_spokes && i < m_branch.size(); ++i)
    {
      const Branch& b = m_branch[i];
      const std::array<Value, 3> yb{sparse_value(y, b.edge[0]), sparse_value(y, b.edge[1]), sparse_value(y, b.edge[2])};
      if(yb[0].isZero() && yb[1].isZero() && yb[2].isZero())
        continue;
      for(std::size_t k = 0; k < 3; ++k)
      {
        const Value r = b.spoke_weight[k] * (b.R[k][0] * yb[0] + b.R[k][1] * yb[1] + b.R[k][2] * yb[2]);
        for(std::size_t j = 0; j < 3; ++j)
          out.emplace_back(b.edge[j], b.R[k][j].transpose() * r);
      }
    }
    if(out.size() > y.size())
      sort_and_merge(out);
    return out;
  }

  // The free directions eta_j (sparse), their Gram matrix through the harmonic parts, and the
  // subset whose harmonic parts are independent (incremental Cholesky with a relative threshold).
  void ensure_harmonic_basis()
  {
    if(m_basis_ready)
      return;
    // built in locals and committed at the end: a failing back-substitution leaves no half basis
    // Every direction and every potential is independent of the others: concurrent tasks (TBB).
    const std::size_t m = number_of_directions(), ne = m_idx.number_of_edges();
    std::vector<Sparse_form> eta(m);
    std::vector<std::vector<Face_index>> curls(m);
    for_each_index(2, true, [&](std::size_t half) { // one one-form per half, reused
      std::vector<Value> y(ne);
      for(std::size_t j = half * m / 2; j < (half + 1) * m / 2; ++j)
      {
        std::fill(y.begin(), y.end(), Value::Zero());
        if(j < m_free.size())
        {
          y[m_free[j].edge][m_free[j].sheet] = two_pi;
          if(m_free[j].partner != npos) // a loop's winding and its Stokes partner's
            y[m_free[j].partner][m_free[j].partner_sheet] = m_free[j].partner_sign * two_pi;
          y = peel(std::move(y), nullptr);
        }
        else // exact: no face to meet
          for(const auto& [e, x] : m_chain_eta[j - m_free.size()])
            y[e] = x;
        curls[j] = branch_curls(y);
        for(std::size_t e = 0; e < ne; ++e)
          if(!y[e].isZero())
            eta[j].emplace_back(e, y[e]);
      }
    });
    Eigen::MatrixXd full = Eigen::MatrixXd::Zero(Eigen::Index(m), Eigen::Index(m));
    // the potentials of the directions (the responses to them), kept for the kept directions when
    // they fit in the memory budget: a solve whose windings move adds them instead of solving again
    const std::size_t d = std::size_t(m_cover.d), nv = m_idx.number_of_vertices();
    const bool keep_potentials = m * nv * d <= potential_budget;
    Eigen::MatrixXd all_potentials(keep_potentials ? Eigen::Index(nv * d) : 0, keep_potentials ? Eigen::Index(m) : 0);
    // Potentials solved by blocks of right-hand sides (a supernodal factor is read once per block).
    // The directions are sparse (dual forest paths, chains), and so is W eta_j: with the potential
    // f_k of direction k (L f_k = -d_P^T W eta_k), its harmonic part is xi_k = eta_k + d_P f_k and
    // the Gram entry <eta_j, W xi_k> = <W eta_j, eta_k + d_P f_k>, a sum over the support of W eta_j;
    // the right-hand sides are scattered from it too.
    std::vector<Sparse_form> w_eta(m);
    for_each_index(m, true, [&](std::size_t j) { w_eta[j] = weighted_sparse(eta[j]); });
    Eigen::MatrixXd block; // a block of right-hand sides, solved in place (one block: all_potentials)
    for(std::size_t k0 = 0; k0 < m; k0 += solve_block)
    {
      const std::size_t width = (std::min)(solve_block, m - k0);
      Eigen::MatrixXd& solved = width == m && keep_potentials ? all_potentials : block;
      solved.setZero(Eigen::Index(nv * d), Eigen::Index(width));
      for_each_index(width, true, [&](std::size_t c) {
        auto b = solved.col(Eigen::Index(c)); // -d_P^T (W eta)
        for(const auto& [e, x] : w_eta[k0 + c])
          subtract_codifferential(e, x, b);
        zero_fixed_rows(b);
      });
      m_system.solve_many(solved, solved);
      if(keep_potentials && width < m)
        all_potentials.middleCols(Eigen::Index(k0), Eigen::Index(width)) = block;
      for_each_index(width, true, [&](std::size_t c) {
        const std::size_t k = k0 + c;
        const auto f = solved.col(Eigen::Index(c));
        for(std::size_t j = 0; j < m; ++j)
        {
          double sum = sparse_dot(w_eta[j], eta[k]);
          for(const auto& [e, x] : w_eta[j]) // <W eta_j, d_P f_k>
            sum += x.dot(differential(f, e));
          full(Eigen::Index(j), Eigen::Index(k)) = sum;
        }
      });
    }
    full = 0.5 * (full + full.transpose()).eval();
    // keep j when its harmonic part is not (numerically) in the span of the kept ones
    std::vector<std::size_t> kept = independent_gram_columns(full);
    const Eigen::Index mk = Eigen::Index(kept.size());
    Eigen::MatrixXd Q(mk, mk);
    for(Eigen::Index i = 0; i < mk; ++i)
      for(Eigen::Index j = 0; j < mk; ++j)
        Q(i, j) = full(Eigen::Index(kept[std::size_t(i)]), Eigen::Index(kept[std::size_t(j)]));
    m_reduced = reduce_integer_quadratic(Q);
    m_Q = std::move(Q);
    m_eta = std::move(eta);
    m_direction_curl = std::move(curls);
    for(std::size_t j = 0; keep_potentials && j < kept.size(); ++j) // kept[j] >= j: in place
      all_potentials.col(Eigen::Index(j)) = all_potentials.col(Eigen::Index(kept[j]));
    all_potentials.conservativeResize(Eigen::NoChange, keep_potentials ? Eigen::Index(kept.size()) : 0);
    m_potential_basis = std::move(all_potentials);
    m_kept = std::move(kept);
    m_basis_ready = true;
  }

  struct Free_direction
  {
    std::size_t edge;
    int sheet;
    std::size_t partner = npos; // with partner_sign times 2 pi on (partner, partner_sheet) too
    int partner_sheet = 0;
    double partner_sign = 0.;
  };
  static constexpr std::size_t potential_budget = std::size_t(1) << 24; // doubles (128 MB)
  static constexpr std::size_t solve_block = 32;                        // right-hand sides per solve

  std::shared_ptr<const Indices> m_idx_ptr;
  std::shared_ptr<const Topology> m_topology_ptr;
  const Indices& m_idx;
  const Topology& m_topology;
  Direction_field_cover m_cover;
  std::vector<double> m_weight;
  mutable Factored_system<SolverTraits> m_system;
  std::vector<Eigen::Matrix2d> m_P;
  std::vector<std::pair<std::size_t, std::size_t>> m_ends;
  std::vector<bool> m_twisted, m_stokes_component;
  std::vector<bool> m_fixed; // per value (v d + a): a pin or a value on a level-0 boundary line
  // level-0 boundary lines: the sheets per edge, the loops and components they constrain, the
  // values they fix, and the sparse integer directions 2 pi d_P(1_chain) of their chains
  std::vector<std::uint8_t> m_level_sheets;
  std::vector<bool> m_level_loop, m_level_component;
  std::vector<std::pair<std::size_t, int>> m_level_values;
  std::vector<Sparse_form> m_chain_eta;
  std::vector<Value> m_free_offset; // per vertex of an untwisted piece: its generic lattice offset
  Dual_forest_peeling m_peeling;
  std::vector<Free_direction> m_free;
  Vertex_block_pattern m_block_pattern; // of L
  bool m_basis_ready = false;
  bool m_stale = false; // set_weights() without a factorization
  std::vector<Sparse_form> m_eta;
  std::vector<std::size_t> m_kept;
  Eigen::MatrixXd m_potential_basis; // per kept direction, its potential (a column), or empty
  Eigen::MatrixXd m_Q;
  Reduced_integer_quadratic m_reduced;
  // branch points on the lattice
  struct Branch
  {
    std::size_t face = 0, component = 0;
    Eigen::Matrix2i K;
    std::array<std::size_t, 3> edge{};
    std::array<std::array<Eigen::Matrix2d, 3>, 3> R; // R[k][j]: the coefficient of y_(edge j) in spoke k
    std::array<double, 3> spoke_weight{0., 0., 0.};
    std::array<Value, 3> target{Value::Zero(), Value::Zero(), Value::Zero()};
  };
  bool m_spokes = false;
  std::vector<Branch> m_branch;
  std::vector<std::vector<Face_index>> m_direction_curl; // per free direction, at every branch face
  bool m_lattice = false, m_lattice_ready = false;
  Eigen::MatrixXd m_lattice_basis;
  Reduced_integer_quadratic m_lattice_reduced;
};

} // namespace internal
} // namespace Surface_design
} // namespace CGAL

#endif // CGAL_SURFACE_DESIGN_INTERNAL_CORE_BRANCHED_ONE_FORM_SOLVER_H
