// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The closest 1-form with prescribed integer periods: the solver core shared by the stripes
// (Field_aligned_parameterizer) and trivial connections (Trivial_connection).

#ifndef CGAL_SURFACE_DESIGN_INTERNAL_CORE_PERIODIC_ONE_FORM_SOLVER_H
#define CGAL_SURFACE_DESIGN_INTERNAL_CORE_PERIODIC_ONE_FORM_SOLVER_H

#include <CGAL/Surface_design/exceptions.h>
#include <CGAL/Surface_design/internal/Core/angles.h>
#include <CGAL/Surface_design/internal/Core/dec.h>
#include <CGAL/Surface_design/internal/Solvers/Factored_system.h>
#include <CGAL/Surface_design/internal/Solvers/integer_quadratic.h>
#include <CGAL/Surface_design/internal/Core/Mesh_indices.h>
#include <CGAL/Surface_design/internal/Core/topology.h>

#include <Eigen/Dense>

#include <cmath>
#include <cstddef>
#include <optional>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_design {
namespace internal {

/// Solves, for a target 1-form omega (per edge, oriented as in Mesh_indices), integers k_f per
/// face and integer windings per loop,
///
///   minimize sum_e w_e (y_e - omega_e)^2
///   subject to (d1 y)_f = 2 pi k_f on every face, and the integral of y along every homology
///   generator loop and every boundary loop (surface on its left) = 2 pi (its winding),
///
/// where a loop's winding is either given or *automatic*: chosen among the integers to minimize
/// the energy. This is the stripe problem of Noma & Kawahara (eq. 15-16) and the least-change
/// problem of trivial connections (Crane et al. 2010), which differ only in omega, k and w.
///
/// **How.** Every feasible y is y* + d0 f for one feasible y* and some vertex function f. y* is
/// built in O(|E|) on a tree-cotree decomposition (zero on the primal tree, 2 pi h on each
/// generator edge; the dual tree is peeled from its leaves so that every face, and every boundary
/// loop closed by a virtual face, gets its prescribed curl). The optimal f solves
/// L f = d0^T W (omega - y*), L the weighted Laplacian with one vertex pinned per component:
/// positive definite for cotangent weights on every mesh, negative weights included (the P1
/// stiffness matrix), and for positive weights. L is factored once; every solve costs O(|E|)
/// plus one back-substitution.
///
/// **Automatic windings.** A free integer direction adds 1 to one loop (generators) or moves 1
/// between two boundary loops of a component (the Stokes balance stays fixed). Its harmonic part
/// xi_j costs one back-substitution, once per set of directions; the integer minimizer of the
/// quadratic 2 g^T c + c^T Q c (Q = Xi^T W Xi) is the best floor/ceiling rounding of the relaxed
/// optimum (all of them for up to 12 directions), improved by +-1 steps until none helps.
template <class TriangleMesh, class SolverTraits>
class Periodic_one_form_solver
{
public:
  using Indices = Mesh_indices<TriangleMesh>;

  /// The result of a solve: y per edge, the windings used per loop, the energy.
  struct Solution
  {
    std::vector<double> y;
    std::vector<int> windings;
    double energy = 0.;
  };

  /// Computes the topology and factors the pinned Laplacian of the edge weights `weight`.
  /// `closed_surface_hint` is appended to the message of an inconsistent prescription on a closed
  /// component (what the indices of the caller's problem must sum to).
  /// \throws Linear_solver_failure if the factorization fails
  Periodic_one_form_solver(Indices idx, std::vector<double> weight, SolverTraits traits, const std::string& name,
                           std::string closed_surface_hint = "")
    : m_idx(std::move(idx)), m_topology(compute_topology(m_idx)), m_weight(std::move(weight)),
      m_system(std::move(traits), name), m_closed_hint(std::move(closed_surface_hint))
  {
    m_edge_ends.resize(m_idx.number_of_edges());
    for(std::size_t e = 0; e < m_edge_ends.size(); ++e)
      m_edge_ends[e] = m_idx.edge_vertices(e);

    // L = d0^T W d0 with the root vertex of every component pinned (row and column replaced by
    // the identity): f_root = 0 fixes the additive constant of each component. The zeros of the
    // pinned rows and columns stay in the pattern, which is then the one of every vertex system
    // on the mesh (one entry per vertex and edge), so that a `Symbolic_analysis_cache` shares the
    // analysis with them (the smoothest field's, for one).
    m_pinned.assign(m_idx.number_of_vertices(), false);
    for(const auto& c : m_topology.components.info)
      m_pinned[c.root_vertex] = true;
    Sparse_matrix L = weighted_laplacian(m_idx, m_weight);
    for(Eigen::Index k = 0; k < L.outerSize(); ++k)
      for(Sparse_matrix::InnerIterator it(L, k); it; ++it)
        if(m_pinned[std::size_t(it.row())] || m_pinned[std::size_t(it.col())])
          it.valueRef() = it.row() == it.col() ? 1. : 0.;
    L.makeCompressed();
    m_system.factor(std::move(L));
    build_solve_plans();
  }

  const Indices& indices() const { return m_idx; }
  const Topology& topology() const { return m_topology; }
  const std::vector<double>& weights() const { return m_weight; }

  /// \name Loops: generators first (2g per component of genus g), then boundary loops
  /// @{
  std::size_t number_of_generator_loops() const { return m_topology.tree.generator_loops.size(); }
  std::size_t number_of_boundary_loops() const { return m_topology.boundary.size(); }
  std::size_t number_of_loops() const { return number_of_generator_loops() + number_of_boundary_loops(); }
  bool is_boundary_loop(std::size_t l) const { return l >= number_of_generator_loops(); }

  /// Halfedge indices of loop l, oriented as its winding is measured: generator loops as built by
  /// the tree-cotree decomposition, boundary loops with the surface on their left.
  std::vector<std::size_t> oriented_loop(std::size_t l) const
  {
    const std::size_t G = number_of_generator_loops();
    if(l < G)
      return m_topology.tree.generator_loops[l];
    std::vector<std::size_t> out;
    const auto& border = m_topology.boundary.loops[l - G];
    for(auto it = border.rbegin(); it != border.rend(); ++it) // reversed, then flipped
      out.push_back(m_idx.index(opposite(m_idx.halfedge(*it), m_idx.mesh())));
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
  /// @}

  /// Per component: the sum of the integers k over its faces.
  std::vector<long> index_sums(const std::vector<int>& k) const
  {
    std::vector<long> sum(m_topology.components.size(), 0);
    for(std::size_t f = 0; f < k.size(); ++f)
      sum[m_topology.components.face_component[f]] += k[f];
    return sum;
  }

  /// The minimizer for the target `omega`, face integers `k` and windings (`nullopt`: automatic).
  /// \throws Invalid_constraints if the integers and the given windings violate Stokes' theorem
  /// on a component: the sum of k over its faces must equal the sum of its boundary windings.
  Solution solve(const std::vector<double>& omega, const std::vector<int>& k,
                 const std::vector<std::optional<int>>& windings)
  {
    Solution s;
    s.windings = base_windings(k, windings); // throws on inconsistent data
    s.y = optimal_one_form(particular_solution(k, s.windings), omega);

    const std::vector<Direction> dirs = free_directions(windings);
    if(!dirs.empty())
    {
      ensure_harmonic_basis(dirs);
      const std::size_t m = dirs.size();
      Eigen::VectorXd g = Eigen::VectorXd::Zero(Eigen::Index(m));
      for(std::size_t j = 0; j < m; ++j)
      {
        double sum = 0.;
        for(std::size_t e = 0; e < s.y.size(); ++e)
          sum += m_weight[e] * m_xi[j][e] * (s.y[e] - omega[e]);
        g[Eigen::Index(j)] = sum;
      }
      const Eigen::VectorXi c = integer_quadratic_minimizer(m_Q, g);
      for(std::size_t j = 0; j < m; ++j)
      {
        const int cj = c[Eigen::Index(j)];
        if(cj == 0)
          continue;
        for(std::size_t e = 0; e < s.y.size(); ++e)
          s.y[e] += cj * m_xi[j][e];
        s.windings[dirs[j].loop] += cj;
        if(dirs[j].counter_loop != npos)
          s.windings[dirs[j].counter_loop] -= cj;
      }
    }
    s.energy = energy(s.y, omega);
    return s;
  }

  /// The energy of the minimizer with all windings given. \pre `windings.size() == number_of_loops()`
  /// \throws Invalid_constraints as `solve()`
  double energy_with_windings(const std::vector<double>& omega, const std::vector<int>& k,
                              const std::vector<int>& windings) const
  {
    check_consistency(k, windings);
    return energy(optimal_one_form(particular_solution(k, windings), omega), omega);
  }

  double energy(const std::vector<double>& y, const std::vector<double>& omega) const
  {
    double e = 0.;
    for(std::size_t i = 0; i < y.size(); ++i)
      e += m_weight[i] * (y[i] - omega[i]) * (y[i] - omega[i]);
    return e;
  }

  /// Integrates y along the primal spanning tree from each component's root (value 0):
  /// u[v] = u[parent] + y(parent -> v), unwrapped.
  std::vector<double> integrate(const std::vector<double>& y) const
  {
    std::vector<double> u(m_idx.number_of_vertices(), 0.);
    for(const Tree_step& step : m_tree_steps)
      u[step.vertex] = u[step.parent] + step.edge.sign * y[step.edge.edge];
    return u;
  }

private:
  // A free integer direction of the winding search: +1 on `loop` (and -1 on `counter_loop`, for
  // boundary loops, which keeps the sum of a component's boundary windings fixed).
  struct Direction
  {
    std::size_t loop;
    std::size_t counter_loop;
    bool operator==(const Direction& o) const { return loop == o.loop && counter_loop == o.counter_loop; }
  };

  // Stokes: per component, sum of k = sum of boundary windings.
  void check_consistency(const std::vector<int>& k, const std::vector<int>& windings) const
  {
    const std::vector<long> ksum = index_sums(k);
    std::vector<long> wsum(ksum.size(), 0);
    for(std::size_t l = number_of_generator_loops(); l < number_of_loops(); ++l)
      wsum[loop_component(l)] += windings[l];
    for(std::size_t c = 0; c < ksum.size(); ++c)
      if(ksum[c] != wsum[c])
      {
        std::ostringstream s;
        const auto& info = m_topology.components.info[c];
        s << "on connected component " << c << " (" << info.faces << " faces, " << info.boundary_loops
          << " boundary loops) the singularity indices sum to " << ksum[c];
        if(info.boundary_loops == 0)
          s << " but must sum to 0 on a closed surface (Stokes' theorem" << m_closed_hint << ")";
        else
          s << " but must equal the sum of the boundary windings, " << wsum[c];
        throw Invalid_constraints(s.str());
      }
  }

  // Windings with every automatic loop at a feasible starting value: 0, except one automatic
  // boundary loop per component that absorbs the Stokes balance.
  std::vector<int> base_windings(const std::vector<int>& k, const std::vector<std::optional<int>>& given) const
  {
    std::vector<int> w(number_of_loops(), 0);
    for(std::size_t l = 0; l < w.size(); ++l)
      if(given[l])
        w[l] = *given[l];
    std::vector<long> balance = index_sums(k);
    std::vector<std::size_t> absorber(balance.size(), npos);
    for(std::size_t l = number_of_generator_loops(); l < number_of_loops(); ++l)
    {
      const std::size_t c = loop_component(l);
      if(given[l])
        balance[c] -= *given[l];
      else if(absorber[c] == npos)
        absorber[c] = l;
    }
    for(std::size_t c = 0; c < balance.size(); ++c)
      if(absorber[c] != npos)
        w[absorber[c]] = int(balance[c]);
    check_consistency(k, w);
    return w;
  }

  std::vector<Direction> free_directions(const std::vector<std::optional<int>>& given) const
  {
    std::vector<Direction> dirs;
    std::vector<std::size_t> absorber(m_topology.components.size(), npos);
    for(std::size_t l = 0; l < number_of_loops(); ++l)
    {
      if(given[l])
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

  // Everything a solve walks over, flattened once into index arrays so that a re-solve is a few
  // tight loops: the dual-tree peeling order (for y*) and the primal-tree order (integration).
  void build_solve_plans()
  {
    const Tree_cotree& t = m_topology.tree;
    const std::size_t nf = m_idx.number_of_faces();
    const auto& tm = m_idx.mesh();
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
        for(auto h : halfedges_around_face(halfedge(m_idx.face(node), tm), tm))
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
  std::vector<double> optimal_one_form(const std::vector<double>& ystar, const std::vector<double>& omega) const
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

  Indices m_idx;
  Topology m_topology;
  std::vector<double> m_weight;
  mutable Factored_system<SolverTraits> m_system; // solving does not change the factor
  std::string m_closed_hint;
  std::vector<std::pair<std::size_t, std::size_t>> m_edge_ends; // per edge: (i, j), oriented i -> j
  std::vector<bool> m_pinned;

  std::vector<Peel_step> m_peel;
  std::vector<Signed_edge> m_peel_others;
  std::vector<Tree_step> m_tree_steps;

  std::vector<Direction> m_xi_dirs;
  std::vector<std::vector<double>> m_xi;
  Eigen::MatrixXd m_Q;
};

} // namespace internal
} // namespace Surface_design
} // namespace CGAL

#endif // CGAL_SURFACE_DESIGN_INTERNAL_CORE_PERIODIC_ONE_FORM_SOLVER_H
