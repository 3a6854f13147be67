// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Field-aligned parameterization with prescribed singularities (Noma & Kawahara), solved exactly
// in vertex space: one factorization of the cotangent Laplacian, then one back-substitution per
// change of the field, of the singularities or of the loop windings.

#ifndef CGAL_SURFACE_DESIGN_FIELD_ALIGNED_PARAMETERIZER_H
#define CGAL_SURFACE_DESIGN_FIELD_ALIGNED_PARAMETERIZER_H

#include <CGAL/Surface_design/exceptions.h>
#include <CGAL/Surface_design/internal/dec.h>
#include <CGAL/Surface_design/internal/Factored_system.h>
#include <CGAL/Surface_design/internal/geometry.h>
#include <CGAL/Surface_design/internal/Mesh_indices.h>
#include <CGAL/Surface_design/internal/target_one_form.h>
#include <CGAL/Surface_design/internal/topology.h>
#include <CGAL/Surface_design/internal/validation.h>
#include <CGAL/Surface_design/parameters.h>
#include <CGAL/Surface_design/solver_traits.h>

#include <CGAL/boost/graph/named_params_helper.h>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace CGAL {
namespace Surface_design {

/// \ingroup PkgFieldAlignedParameterizationRef
/// The edge weights w_e of the least-squares energy.
enum class Edge_weighting
{
  cotangent, ///< w_e = (cot a + cot b) / 2, the paper's (and the Dirichlet energy's) weights
  uniform    ///< w_e = 1: the plain l2 norm of the 1-form (used by trivial connections)
};

/// \ingroup PkgFieldAlignedParameterizationRef
///
/// Computes a circle-valued *stripe function* alpha (one angle per vertex) whose differential
/// follows a target 1-form omega (from a tangent vector field) in the cotangent-weighted least
/// squares sense, with singularities exactly at prescribed faces with prescribed integer indices
/// and nowhere else, and with prescribed (or automatically chosen) windings along the
/// non-contractible loops of the surface (Noma & Kawahara).
///
/// **The problem** (paper, eq. 15-16). Unknown: a 1-form y = dalpha on the edges.
/// Minimize sum_e w_e (y_e - omega_e)^2, w_e the cotangent weights (or 1: Edge_weighting), subject to
/// - (d1 y)_f = 2 pi k_f on every face (k_f = prescribed index, 0 almost everywhere),
/// - the integral of y along each homology generator loop = 2 pi h (its winding), and along each
///   boundary loop (oriented with the surface on its left) = 2 pi W (its winding).
///
/// **How it is solved.** Every feasible y is y* + d0 f for a particular feasible y* and some
/// vertex function f. y* is built in O(|E|) on a tree-cotree decomposition (zero on the primal
/// tree, 2 pi h on each generator edge, then the dual tree is peeled from its leaves so that every
/// face, and every boundary loop closed by a virtual face, gets its prescribed curl). The
/// optimal f solves L f = d0^T W (omega - y*), L the cotangent Laplacian with one vertex pinned
/// per component: positive definite on every mesh, including negative cotangent weights (it is
/// the P1 stiffness matrix). L is factored once in the constructor; every solve() afterwards
/// costs O(|E|) plus one back-substitution. alpha is integrated along the primal tree.
///
/// **Windings.** Loops are numbered generators first (2g per component of genus g, from the
/// tree-cotree decomposition), then boundary loops. A loop's winding is either set with
/// `set_loop_winding()` or *automatic* (the default): automatic windings minimize the energy over
/// the integers. The relaxed (real) optimum costs one extra back-substitution per automatic loop,
/// once for the mesh; the best of the floor/ceiling roundings (all of them for up to 12 loops) is
/// then improved by +-1 steps until no single step lowers the energy.
///
/// **Consistency.** By Stokes' theorem, on each connected component the indices must sum to the
/// sum of its boundary windings (to 0 on a closed component). With automatic boundary windings
/// the sum is met by construction; otherwise solve() throws `Invalid_constraints` with the sums.
///
/// \tparam TriangleMesh a model of `FaceListGraph` and `HalfedgeListGraph`
/// \tparam VertexPointMap a readable property map from vertices to `Point_3`
/// \tparam SolverTraits a model of `SparseLinearAlgebraWithFactorTraits_d`. Copies of a
/// `CGAL::Eigen_solver_traits` share one factorization: give every parameterizer its own solver
/// object (the default argument does), never one object to two parameterizers.
template <class TriangleMesh,
          class VertexPointMap = typename boost::property_map<TriangleMesh, CGAL::vertex_point_t>::const_type,
          class SolverTraits = Default_solver_traits>
class Field_aligned_parameterizer
{
  using GT = boost::graph_traits<TriangleMesh>;
  using Indices = internal::Mesh_indices<TriangleMesh>;
  using Sparse_matrix = internal::Sparse_matrix;
  static constexpr std::size_t npos = internal::npos;

public:
  using vertex_descriptor = typename GT::vertex_descriptor;
  using halfedge_descriptor = typename GT::halfedge_descriptor;
  using edge_descriptor = typename GT::edge_descriptor;
  using face_descriptor = typename GT::face_descriptor;

  /// Validates the mesh, computes the edge weights (cotangent by default) and the topology, and
  /// factors the Laplacian. The mesh must not change while this object is used.
  /// \throws Invalid_mesh (empty, non-triangle, non-manifold, degenerate face, non-finite point)
  /// \throws Linear_solver_failure if the factorization fails
  Field_aligned_parameterizer(const TriangleMesh& tm, VertexPointMap vpm,
                              SolverTraits solver = SolverTraits(),
                              Edge_weighting weighting = Edge_weighting::cotangent)
    : m_tm(tm), m_vpm(vpm), m_idx(tm), m_system(std::move(solver), "pinned cotangent Laplacian")
  {
    internal::validate_mesh(m_idx, m_vpm);
    m_topology = internal::compute_topology(m_idx);
    m_weight = weighting == Edge_weighting::cotangent ? internal::cotangent_weights(m_idx, m_vpm)
                                                      : std::vector<double>(m_idx.number_of_edges(), 1.);
    // d0 as its edge list: (d0 f)_e = f(j) - f(i) for the edge oriented i -> j
    m_edge_ends.resize(m_idx.number_of_edges());
    for(std::size_t e = 0; e < m_edge_ends.size(); ++e)
      m_edge_ends[e] = m_idx.edge_vertices(e);

    // L = d0^T W d0 with the root vertex of every component pinned (row and column replaced by
    // the identity): f_root = 0, which fixes the additive constant of each component.
    std::vector<bool> pinned(m_idx.number_of_vertices(), false);
    for(const auto& c : m_topology.components.info)
      pinned[c.root_vertex] = true;
    m_pinned = pinned;
    Sparse_matrix L = internal::weighted_laplacian(m_idx, m_weight);
    L.prune([&pinned](Eigen::Index i, Eigen::Index j, double) {
      return !pinned[std::size_t(i)] && !pinned[std::size_t(j)];
    });
    for(const auto& c : m_topology.components.info)
      L.coeffRef(Eigen::Index(c.root_vertex), Eigen::Index(c.root_vertex)) = 1.;
    L.makeCompressed();
    m_system.factor(std::move(L));

    m_omega.assign(m_idx.number_of_edges(), 0.);
    m_index.assign(m_idx.number_of_faces(), 0);
    m_winding.assign(number_of_loops(), std::nullopt);
    build_solve_plans();
  }

  /// Same, with the mesh's internal vertex point map.
  explicit Field_aligned_parameterizer(const TriangleMesh& tm, SolverTraits solver = SolverTraits())
    : Field_aligned_parameterizer(tm, get(CGAL::vertex_point, tm), std::move(solver))
  {}

  const TriangleMesh& mesh() const { return m_tm; }

  /// \name The target field
  /// @{

  /// Sets the target 1-form from a per-vertex vector field (any vectors: they are projected to
  /// the vertex tangent planes). If `stripes_per_unit_length > 0` the field is normalized and
  /// alpha advances by 2 pi * stripes_per_unit_length per unit length along it; otherwise the
  /// field is used as given (alpha advances by |X| radians per unit length).
  template <class VertexVectorMap>
  void set_field(const VertexVectorMap& field, double stripes_per_unit_length = 0.,
                 One_form_convention convention = One_form_convention::projected)
  {
    const double two_pi = 2. * std::acos(-1.);
    const auto x = internal::tangent_field(m_idx, m_vpm, field, two_pi * stripes_per_unit_length);
    m_omega = convention == One_form_convention::projected
                ? internal::projected_one_form(m_idx, m_vpm, x)
                : internal::angle_rescaled_one_form(m_idx, m_vpm, x);
  }

  /// Sets the target 1-form directly: `omega(h)` for the halfedge `h = halfedge(e, tm)` of
  /// every edge (the value along h).
  template <class EdgeScalarMap>
  void set_target_one_form(const EdgeScalarMap& omega)
  {
    for(std::size_t e = 0; e < m_idx.number_of_edges(); ++e)
    {
      const edge_descriptor ed = m_idx.edge(e);
      m_omega[e] = m_idx.orientation_sign(halfedge(ed, m_tm)) * double(get(omega, ed));
    }
  }

  /// Target 1-form along halfedge `h`.
  double omega(halfedge_descriptor h) const
  {
    return m_idx.orientation_sign(h) * m_omega[m_idx.edge_index(h)];
  }
  /// @}

  /// \name Singularities
  /// @{

  /// Index of the singularity prescribed in face `f` (0: no singularity).
  int index(face_descriptor f) const { return m_index[checked_face(f)]; }
  /// Prescribes index `k` in face `f`. \throws Invalid_constraints if `f` is not a face of the mesh
  void set_index(face_descriptor f, int k) { m_index[checked_face(f)] = k; }
  /// Same, with the face given by its index (the input order for meshes read from a file).
  void set_index(std::size_t face_index, int k)
  {
    if(face_index >= m_idx.number_of_faces())
      throw Invalid_constraints("face " + std::to_string(face_index) + " does not exist (the mesh has " +
                                std::to_string(m_idx.number_of_faces()) + " faces)");
    m_index[face_index] = k;
  }
  /// Reads all indices from a face -> integer map.
  template <class FaceIndexMap>
  void set_indices(const FaceIndexMap& k)
  {
    for(std::size_t f = 0; f < m_idx.number_of_faces(); ++f)
      m_index[f] = int(get(k, m_idx.face(f)));
  }
  /// Removes every singularity.
  void clear_indices() { std::fill(m_index.begin(), m_index.end(), 0); }
  /// Moves the singularity of face `from` to face `to` (adding its index to that of `to`).
  void move_singularity(face_descriptor from, face_descriptor to)
  {
    const std::size_t a = checked_face(from), b = checked_face(to);
    if(a == b)
      return;
    if(m_topology.components.face_component[a] != m_topology.components.face_component[b])
      throw Invalid_constraints("cannot move a singularity from face " + std::to_string(a) +
                                " to face " + std::to_string(b) + " of another connected component");
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

  /// \name Loops and their windings
  /// @{
  std::size_t number_of_generator_loops() const { return m_topology.tree.generator_loops.size(); }
  std::size_t number_of_boundary_loops() const { return m_topology.boundary.size(); }
  std::size_t number_of_loops() const { return number_of_generator_loops() + number_of_boundary_loops(); }
  bool is_boundary_loop(std::size_t loop) const { return checked_loop(loop) >= number_of_generator_loops(); }

  /// The halfedges of a loop, in order, oriented as its winding is measured: generator loops as
  /// built by the tree-cotree decomposition, boundary loops with the surface on their left.
  std::vector<halfedge_descriptor> loop(std::size_t l) const
  {
    std::vector<halfedge_descriptor> out;
    for(std::size_t h : oriented_loop(checked_loop(l)))
      out.push_back(m_idx.halfedge(h));
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
    return m_used_winding[checked_loop(l)];
  }
  /// @}

  /// \name Solving
  /// @{

  /// Computes dalpha and alpha for the current field, indices and windings. O(|E|) plus one
  /// back-substitution (and, the first time automatic windings are used, one per automatic loop).
  /// \throws Invalid_constraints if the indices and explicit windings violate Stokes' theorem
  void solve()
  {
    const std::vector<int> base = base_windings(); // throws on inconsistent data
    std::vector<double> y = optimal_one_form(particular_solution(m_index, base), m_omega);

    // automatic windings: minimize over the free integer directions
    const std::vector<Direction> dirs = free_directions();
    std::vector<int> winding = base;
    if(!dirs.empty())
    {
      ensure_harmonic_basis(dirs);
      const std::size_t m = dirs.size();
      Eigen::VectorXd g = Eigen::VectorXd::Zero(Eigen::Index(m));
      for(std::size_t j = 0; j < m; ++j)
      {
        double s = 0.;
        for(std::size_t e = 0; e < y.size(); ++e)
          s += m_weight[e] * m_xi[j][e] * (y[e] - m_omega[e]);
        g[Eigen::Index(j)] = s;
      }
      const Eigen::VectorXi c = integer_minimizer(m_Q, g);
      for(std::size_t j = 0; j < m; ++j)
      {
        const int cj = c[Eigen::Index(j)];
        if(cj == 0)
          continue;
        for(std::size_t e = 0; e < y.size(); ++e)
          y[e] += cj * m_xi[j][e];
        winding[dirs[j].loop] += cj;
        if(dirs[j].counter_loop != npos)
          winding[dirs[j].counter_loop] -= cj;
      }
    }
    m_y = std::move(y);
    m_used_winding = winding;
    m_energy = energy_of(m_y);

    // alpha: integrate dalpha along the primal tree from each component's root (alpha = 0)
    m_alpha.assign(m_idx.number_of_vertices(), 0.);
    for(const Tree_step& step : m_tree_steps)
      m_alpha[step.vertex] = m_alpha[step.parent] + step.edge.sign * m_y[step.edge.edge];
    for(double& a : m_alpha)
      a = internal::wrap_angle(a);
    m_solved = true;
  }

  bool is_solved() const { return m_solved; }

  /// alpha at vertex `v`, in [-pi, pi).
  double alpha(vertex_descriptor v) const
  {
    require_solved();
    return m_alpha[m_idx.index(v)];
  }

  /// Writes alpha (in [-pi, pi)) to a vertex -> double map.
  template <class VertexScalarMap>
  void alpha(VertexScalarMap out) const
  {
    require_solved();
    for(std::size_t v = 0; v < m_alpha.size(); ++v)
      put(out, m_idx.vertex(v), m_alpha[v]);
  }

  /// dalpha along halfedge `h`, unwrapped: alpha(target) = alpha(source) + dalpha (mod 2 pi).
  double dalpha(halfedge_descriptor h) const
  {
    require_solved();
    return m_idx.orientation_sign(h) * m_y[m_idx.edge_index(h)];
  }

  /// Writes dalpha along `halfedge(e, tm)` for every edge `e` to an edge -> double map.
  template <class EdgeScalarMap>
  void dalpha(EdgeScalarMap out) const
  {
    require_solved();
    for(std::size_t e = 0; e < m_idx.number_of_edges(); ++e)
      put(out, m_idx.edge(e), dalpha(halfedge(m_idx.edge(e), m_tm)));
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
    for(std::size_t f = 0; f < m_idx.number_of_faces(); ++f)
    {
      const halfedge_descriptor h0 = halfedge(m_idx.face(f), m_tm);
      double u = m_alpha[m_idx.source_index(h0)];
      put(out, prev(h0, m_tm), u);
      u += dalpha(h0);
      put(out, h0, u);
      u += dalpha(next(h0, m_tm));
      put(out, next(h0, m_tm), u);
    }
  }

  /// The energy sum_e w_e (dalpha_e - omega_e)^2 of the last solve (with the field of that
  /// solve). With negative cotangent weights it can be negative: the energy is convex on the
  /// feasible set, not positive on every 1-form.
  double energy() const
  {
    require_solved();
    return m_energy;
  }

  /// The energy of the optimal dalpha for the current field and indices with the given windings
  /// of all loops (no refactorization; one back-substitution). Used to compare winding choices.
  double energy_with_windings(const std::vector<int>& windings) const
  {
    if(windings.size() != number_of_loops())
      throw Invalid_constraints("expected " + std::to_string(number_of_loops()) + " windings, got " +
                                std::to_string(windings.size()));
    check_consistency(windings);
    return energy_of(optimal_one_form(particular_solution(m_index, windings), m_omega));
  }
  /// @}

  /// \name Access for tests, examples and benchmarks
  /// @{
  const std::vector<double>& edge_weights() const { return m_weight; } ///< per edge index
  const internal::Mesh_indices<TriangleMesh>& indices() const { return m_idx; }
  const internal::Topology& topology() const { return m_topology; }
  /// dalpha per edge index, oriented from the smaller to the larger vertex index
  const std::vector<double>& one_form() const { require_solved(); return m_y; }
  /// omega per edge index, same orientation
  const std::vector<double>& target_one_form() const { return m_omega; }
  /// Sets omega per edge index, same orientation. \throws Invalid_constraints on a size mismatch
  void set_target_one_form_by_edge_index(std::vector<double> omega)
  {
    if(omega.size() != m_idx.number_of_edges())
      throw Invalid_constraints("the target 1-form has " + std::to_string(omega.size()) +
                                " values but the mesh has " + std::to_string(m_idx.number_of_edges()) + " edges");
    m_omega = std::move(omega);
  }
  const std::vector<int>& indices_per_face() const { return m_index; }
  /// every loop as halfedge indices, oriented as its winding is measured
  std::vector<std::vector<std::size_t>> loops_as_indices() const
  {
    std::vector<std::vector<std::size_t>> out;
    for(std::size_t l = 0; l < number_of_loops(); ++l)
      out.push_back(oriented_loop(l));
    return out;
  }
  /// @}

private:
  // A free integer direction of the winding search: +1 on `loop` (and -1 on `counter_loop`, for
  // boundary loops, which keeps the sum of a component's boundary windings fixed).
  struct Direction
  {
    std::size_t loop;
    std::size_t counter_loop;
    bool operator==(const Direction& o) const { return loop == o.loop && counter_loop == o.counter_loop; }
  };

  std::size_t checked_face(face_descriptor f) const
  {
    const std::size_t i = m_idx.index(f);
    if(i >= m_idx.number_of_faces() || m_idx.face(i) != f)
      throw Invalid_constraints("the face is not a face of this mesh");
    return i;
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

  // Halfedge indices of loop l, oriented as its winding is measured.
  std::vector<std::size_t> oriented_loop(std::size_t l) const
  {
    const std::size_t G = number_of_generator_loops();
    if(l < G)
      return m_topology.tree.generator_loops[l];
    std::vector<std::size_t> out;
    const auto& border = m_topology.boundary.loops[l - G];
    for(auto it = border.rbegin(); it != border.rend(); ++it) // reversed, then flipped
      out.push_back(m_idx.index(opposite(m_idx.halfedge(*it), m_tm)));
    return out;
  }

  std::size_t loop_component(std::size_t l) const
  {
    const std::size_t G = number_of_generator_loops();
    if(l < G)
      return m_topology.tree.generator_component[l];
    const std::size_t h = m_topology.boundary.loops[l - G].front();
    return m_topology.components.vertex_component[m_idx.target_index(m_idx.halfedge(h))];
  }

  std::vector<long> index_sums() const
  {
    std::vector<long> sum(m_topology.components.size(), 0);
    for(std::size_t f = 0; f < m_index.size(); ++f)
      sum[m_topology.components.face_component[f]] += m_index[f];
    return sum;
  }

  // Stokes: per component, sum of indices = sum of boundary windings.
  void check_consistency(const std::vector<int>& windings) const
  {
    const std::vector<long> ksum = index_sums();
    std::vector<long> wsum(ksum.size(), 0);
    for(std::size_t l = number_of_generator_loops(); l < number_of_loops(); ++l)
      wsum[loop_component(l)] += windings[l];
    for(std::size_t c = 0; c < ksum.size(); ++c)
      if(ksum[c] != wsum[c])
      {
        std::ostringstream s;
        const auto& info = m_topology.components.info[c];
        s << "on connected component " << c << " (" << info.faces << " faces, "
          << info.boundary_loops << " boundary loops) the singularity indices sum to " << ksum[c];
        if(info.boundary_loops == 0)
          s << " but must sum to 0 on a closed surface (Stokes' theorem; unlike a vector field, a"
               " stripe function's indices do not sum to the Euler characteristic)";
        else
          s << " but must equal the sum of the boundary windings, " << wsum[c];
        throw Invalid_constraints(s.str());
      }
  }

  // Windings with every automatic loop at a feasible starting value: 0, except one automatic
  // boundary loop per component that absorbs the Stokes balance.
  std::vector<int> base_windings() const
  {
    std::vector<int> w(number_of_loops(), 0);
    for(std::size_t l = 0; l < w.size(); ++l)
      if(m_winding[l])
        w[l] = *m_winding[l];
    const std::vector<long> ksum = index_sums();
    std::vector<long> balance = ksum;
    std::vector<std::size_t> absorber(ksum.size(), npos);
    for(std::size_t l = number_of_generator_loops(); l < number_of_loops(); ++l)
    {
      const std::size_t c = loop_component(l);
      if(m_winding[l])
        balance[c] -= *m_winding[l];
      else if(absorber[c] == npos)
        absorber[c] = l;
    }
    for(std::size_t c = 0; c < ksum.size(); ++c)
      if(absorber[c] != npos)
        w[absorber[c]] = int(balance[c]);
    check_consistency(w);
    return w;
  }

  std::vector<Direction> free_directions() const
  {
    std::vector<Direction> dirs;
    std::vector<std::size_t> absorber(m_topology.components.size(), npos);
    for(std::size_t l = 0; l < number_of_loops(); ++l)
    {
      if(m_winding[l])
        continue;
      if(l < number_of_generator_loops())
        dirs.push_back({l, npos});
      else
      {
        const std::size_t c = loop_component(l);
        if(absorber[c] == npos)
          absorber[c] = l;
        else
          dirs.push_back({l, absorber[c]});
      }
    }
    return dirs;
  }

  // Everything solve() walks over, flattened once into index arrays so that a re-solve is a few
  // tight loops: the dual-tree peeling order (for y*) and the primal-tree order (for alpha).
  void build_solve_plans()
  {
    const internal::Tree_cotree& t = m_topology.tree;
    const std::size_t nf = m_idx.number_of_faces();
    auto signed_edge = [this](std::size_t h) {
      const auto hd = m_idx.halfedge(h);
      return Signed_edge{m_idx.edge_index(hd), double(m_idx.orientation_sign(hd))};
    };
    for(auto it = t.dual_order.rbegin(); it != t.dual_order.rend(); ++it)
    {
      const std::size_t node = *it, parent_h = t.dual_parent_halfedge[node];
      if(parent_h == npos)
        continue; // a root: closes by consistency
      Peel_step step{node, signed_edge(parent_h), m_peel_others.size(), 0};
      auto add = [&](std::size_t h) {
        if(h != parent_h)
          m_peel_others.push_back(signed_edge(h));
      };
      if(node < nf)
        for(auto h : halfedges_around_face(halfedge(m_idx.face(node), m_tm), m_tm))
          add(m_idx.index(h));
      else
        for(std::size_t h : m_topology.boundary.loops[node - nf])
          add(h);
      step.others_end = m_peel_others.size();
      m_peel.push_back(step);
    }
    for(std::size_t v : t.vertex_order)
      if(t.parent_halfedge[v] != npos)
        m_tree_steps.push_back({v, m_idx.source_index(m_idx.halfedge(t.parent_halfedge[v])),
                                signed_edge(t.parent_halfedge[v])});
  }

  // y* with (d1 y*)_f = 2 pi k_f, generator integrals 2 pi h and boundary integrals 2 pi W;
  // zero on the primal tree. O(|E|): the dual tree is peeled from its leaves, each node fixing
  // the edge to its parent; a virtual face runs along the border halfedges, i.e. against the
  // boundary orientation, so its curl is -2 pi W.
  std::vector<double> particular_solution(const std::vector<int>& k, const std::vector<int>& windings) const
  {
    constexpr double two_pi = 2. * 3.14159265358979323846;
    const std::size_t nf = m_idx.number_of_faces(), G = number_of_generator_loops();
    std::vector<double> y(m_idx.number_of_edges(), 0.);
    for(std::size_t g = 0; g < G; ++g)
      y[m_topology.tree.generator_edges[g]] = two_pi * windings[g]; // the loop runs along its edge
    for(const Peel_step& step : m_peel)
    {
      const double target = step.node < nf ? two_pi * k[step.node] : -two_pi * windings[G + step.node - nf];
      double others = 0.;
      for(std::size_t i = step.others_begin; i < step.others_end; ++i)
        others += m_peel_others[i].sign * y[m_peel_others[i].edge];
      y[step.parent.edge] = step.parent.sign * (target - others);
    }
    return y;
  }

  // The optimal y = ystar + d0 f, L f = d0^T W (omega - ystar), f = 0 at pinned roots.
  std::vector<double> optimal_one_form(const std::vector<double>& ystar,
                                       const std::vector<double>& omega) const
  {
    const std::size_t ne = ystar.size();
    Eigen::VectorXd b = Eigen::VectorXd::Zero(Eigen::Index(m_pinned.size()));
    for(std::size_t e = 0; e < ne; ++e) // b = d0^T W (omega - ystar)
    {
      const double x = m_weight[e] * (omega[e] - ystar[e]);
      b[Eigen::Index(m_edge_ends[e].first)] -= x;
      b[Eigen::Index(m_edge_ends[e].second)] += x;
    }
    for(std::size_t v = 0; v < m_pinned.size(); ++v)
      if(m_pinned[v])
        b[Eigen::Index(v)] = 0.;
    const Eigen::VectorXd f = m_system.solve(b);
    std::vector<double> y(ne);
    for(std::size_t e = 0; e < ne; ++e) // y = ystar + d0 f
      y[e] = ystar[e] + f[Eigen::Index(m_edge_ends[e].second)] - f[Eigen::Index(m_edge_ends[e].first)];
    return y;
  }

  // Harmonic parts xi_j of the free directions (eta_j minus its W-projection on exact forms)
  // and their Gram matrix Q = Xi^T W Xi; depend on the mesh only, computed once per direction set.
  void ensure_harmonic_basis(const std::vector<Direction>& dirs)
  {
    if(dirs == m_xi_dirs)
      return;
    const std::size_t m = dirs.size();
    m_xi.assign(m, {});
    const std::vector<int> no_index(m_idx.number_of_faces(), 0);
    const std::vector<double> no_omega(m_idx.number_of_edges(), 0.);
    for(std::size_t j = 0; j < m; ++j)
    {
      std::vector<int> w(number_of_loops(), 0);
      w[dirs[j].loop] = 1;
      if(dirs[j].counter_loop != npos)
        w[dirs[j].counter_loop] = -1;
      m_xi[j] = optimal_one_form(particular_solution(no_index, w), no_omega); // eta - d0 f
    }
    m_Q.resize(Eigen::Index(m), Eigen::Index(m));
    for(std::size_t i = 0; i < m; ++i)
      for(std::size_t j = 0; j <= i; ++j)
      {
        double s = 0.;
        for(std::size_t e = 0; e < m_weight.size(); ++e)
          s += m_weight[e] * m_xi[i][e] * m_xi[j][e];
        m_Q(Eigen::Index(i), Eigen::Index(j)) = m_Q(Eigen::Index(j), Eigen::Index(i)) = s;
      }
    m_xi_dirs = dirs;
  }

  // Integer c minimizing 2 g^T c + c^T Q c: best floor/ceil rounding of the relaxed optimum
  // (exhaustive for up to 12 directions, plain rounding otherwise), then +-1 coordinate steps
  // until none improves.
  static Eigen::VectorXi integer_minimizer(const Eigen::MatrixXd& Q, const Eigen::VectorXd& g)
  {
    const Eigen::Index m = g.size();
    const Eigen::VectorXd relaxed = -Q.ldlt().solve(g);
    auto cost = [&](const Eigen::VectorXd& c) { return 2. * g.dot(c) + c.dot(Q * c); };
    Eigen::VectorXd best(m);
    for(Eigen::Index i = 0; i < m; ++i)
      best[i] = std::round(relaxed[i]);
    double best_cost = cost(best);
    if(m <= 12)
    {
      Eigen::VectorXd c(m);
      for(long mask = 0; mask < (1L << m); ++mask)
      {
        for(Eigen::Index i = 0; i < m; ++i)
          c[i] = (mask >> i) & 1 ? std::ceil(relaxed[i]) : std::floor(relaxed[i]);
        const double cc = cost(c);
        if(cc < best_cost)
        {
          best_cost = cc;
          best = c;
        }
      }
    }
    // coordinate descent: the change of cost for c_i += d is 2 d (g + Q c)_i + d^2 Q_ii
    const double tolerance = 1e-12 * (std::abs(best_cost) + Q.diagonal().cwiseAbs().sum());
    for(bool improved = true; improved;)
    {
      improved = false;
      const Eigen::VectorXd grad = g + Q * best;
      for(Eigen::Index i = 0; i < m && !improved; ++i)
        for(int d : {-1, 1})
          if(2. * d * grad[i] + Q(i, i) < -tolerance)
          {
            best[i] += d;
            improved = true;
            break;
          }
    }
    return best.cast<int>();
  }

  double energy_of(const std::vector<double>& y) const
  {
    double e = 0.;
    for(std::size_t i = 0; i < y.size(); ++i)
      e += m_weight[i] * (y[i] - m_omega[i]) * (y[i] - m_omega[i]);
    return e;
  }

  const TriangleMesh& m_tm;
  VertexPointMap m_vpm;
  Indices m_idx;
  internal::Topology m_topology;
  std::vector<double> m_weight;
  std::vector<std::pair<std::size_t, std::size_t>> m_edge_ends; // per edge: (i, j), oriented i -> j
  std::vector<bool> m_pinned;
  mutable internal::Factored_system<SolverTraits> m_system; // solving does not change the factor

  std::vector<double> m_omega;
  std::vector<int> m_index;
  std::vector<std::optional<int>> m_winding;

  struct Signed_edge
  {
    std::size_t edge;
    double sign;
  };
  struct Peel_step
  {
    std::size_t node;
    Signed_edge parent;
    std::size_t others_begin, others_end; // range in m_peel_others
  };
  struct Tree_step
  {
    std::size_t vertex, parent;
    Signed_edge edge;
  };
  std::vector<Peel_step> m_peel;
  std::vector<Signed_edge> m_peel_others;
  std::vector<Tree_step> m_tree_steps;

  std::vector<Direction> m_xi_dirs;
  std::vector<std::vector<double>> m_xi;
  Eigen::MatrixXd m_Q;

  bool m_solved = false;
  std::vector<double> m_y, m_alpha;
  double m_energy = 0.;
  std::vector<int> m_used_winding;
};

} // namespace Surface_design
} // namespace CGAL

#endif // CGAL_SURFACE_DESIGN_FIELD_ALIGNED_PARAMETERIZER_H
