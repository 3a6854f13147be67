// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A trivial connection whose field follows the boundary: the transport's adjustment pinned on the
// boundary edges, the rest of least norm (Dirichlet problem for the vertex potential).

#ifndef CGAL_SURFACE_DESIGN_INTERNAL_DIRECTION_FIELDS_BOUNDARY_ALIGNMENT_H
#define CGAL_SURFACE_DESIGN_INTERNAL_DIRECTION_FIELDS_BOUNDARY_ALIGNMENT_H

#include <CGAL/Surface_design/internal/Core/angles.h>
#include <CGAL/Surface_design/internal/Core/topology.h>
#include <CGAL/Surface_design/internal/Solvers/Factored_system.h>
#include <CGAL/Surface_design/internal/Solvers/integer_quadratic.h>
#include <CGAL/Surface_design/internal/Solvers/sparse_types.h>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_design {
namespace internal {

/// A vertex-based n-direction field (rescaled angles alpha = n times the field's angle) that
/// follows the boundary has alpha = c at every boundary vertex, the same constant c on every
/// boundary loop (0 along the boundary, n pi / 2 along its inward normal): the boundary halfedge
/// leaving a boundary vertex has rescaled angle 0 in its frame (`Vertex_frames`). Its one-form
/// y = d alpha is then 0 on every boundary edge (the multiple of 2 pi closest to the transport
/// n rho_e, which lies in [-pi, pi)), and so is every boundary loop's winding.
///
/// `correct()` takes a feasible y (the prescribed curl on every face, winding 0 on every boundary
/// loop: `Periodic_one_form_solver` with those windings given) to the minimizer of
/// sum_e w_e (y_e - omega_e)^2 among the feasible y that are 0 on the boundary edges: y + d0 g.
/// Along each loop g follows -y (so that y + d0 g is 0 there) up to a constant c_L per loop; one
/// loop per component is the reference (c = 0), and on each other loop c_L is fixed modulo 2 pi,
/// since alpha must take the same value modulo 2 pi on all loops: c_L = a_L + 2 pi N_L. The
/// interior values of g solve the Dirichlet problem (the interior Laplacian, factored once), which
/// is affine in the c_L (one back-substitution per loop but the reference ones, once); the energy
/// is then a quadratic in the integers N_L, minimized like the windings
/// (`integer_quadratic_minimizer()`). Components without boundary are left as they are.
template <class Indices, class SolverTraits>
class Boundary_aligned_one_form
{
public:
  /// \throws Linear_solver_failure if the factorization fails
  Boundary_aligned_one_form(const Indices& idx, const Topology& topology, std::vector<double> weight, SolverTraits traits)
    : m_weight(std::move(weight)), m_system(std::move(traits), "Laplacian of the interior vertices (field along the boundary)")
  {
    const std::size_t nv = idx.number_of_vertices(), ne = idx.number_of_edges(), nl = topology.boundary.size();
    m_node.assign(nv, npos);
    m_loop_of_vertex.assign(nv, npos);
    m_aligned.assign(topology.components.size(), false);
    m_free_edge.assign(ne, false);
    m_loop_unknown.assign(nl, npos);
    m_reference_loop.assign(topology.components.size(), npos);
    for(std::size_t l = 0; l < nl; ++l)
    {
      const std::size_t c = topology.components.vertex_component[idx.source_index(idx.halfedge(topology.boundary.loops[l].front()))];
      m_aligned[c] = true;
      if(m_reference_loop[c] == npos)
        m_reference_loop[c] = l;
      else
        m_loop_unknown[l] = m_loops++;
      for(std::size_t h : topology.boundary.loops[l])
        m_loop_of_vertex[idx.source_index(idx.halfedge(h))] = l;
    }
    std::size_t nodes = 0;
    for(std::size_t v = 0; v < nv; ++v)
      if(m_aligned[topology.components.vertex_component[v]] && m_loop_of_vertex[v] == npos)
        m_node[v] = nodes++;
    m_nodes = nodes;
    m_border_edge.assign(ne, false);
    for(const auto& loop : topology.boundary.loops)
      for(std::size_t h : loop)
        m_border_edge[idx.edge_index(idx.halfedge(h))] = true;
    for(std::size_t e = 0; e < ne; ++e)
      m_free_edge[e] = !m_border_edge[e] && m_aligned[topology.components.vertex_component[idx.edge_vertices(e).first]];
    if(nodes > 0)
    {
      std::vector<Eigen::Triplet<double>> t;
      for(std::size_t e = 0; e < ne; ++e)
      {
        if(!m_free_edge[e])
          continue;
        const auto [i, j] = idx.edge_vertices(e);
        const std::size_t a = m_node[i], b = m_node[j];
        if(a != npos)
          t.emplace_back(Eigen::Index(a), Eigen::Index(a), m_weight[e]);
        if(b != npos)
          t.emplace_back(Eigen::Index(b), Eigen::Index(b), m_weight[e]);
        if(a != npos && b != npos)
        {
          t.emplace_back(Eigen::Index(a), Eigen::Index(b), -m_weight[e]);
          t.emplace_back(Eigen::Index(b), Eigen::Index(a), -m_weight[e]);
        }
      }
      Sparse_matrix L{Eigen::Index(nodes), Eigen::Index(nodes)};
      L.setFromTriplets(t.begin(), t.end());
      L.makeCompressed();
      m_system.factor(std::move(L));
    }
    // per loop unknown: g = 1 on the loop, 0 on the other loops, harmonic inside (phi), and the
    // Gram matrix of the resulting edge differences (the quadratic in the loop constants)
    std::vector<std::vector<double>> phi(m_loops);
    for(std::size_t l = 0; l < nl; ++l)
    {
      const std::size_t u = m_loop_unknown[l];
      if(u == npos)
        continue;
      std::vector<double> known(nv, 0.);
      for(std::size_t v = 0; v < nv; ++v)
        known[v] = m_loop_of_vertex[v] == l ? 1. : 0.;
      phi[u] = dirichlet(idx, std::vector<double>(ne, 0.), known);
    }
    m_difference.assign(m_loops, std::vector<double>(ne, 0.));
    for(std::size_t u = 0; u < m_loops; ++u)
      for(std::size_t e = 0; e < ne; ++e)
        if(m_free_edge[e])
        {
          const auto [i, j] = idx.edge_vertices(e);
          m_difference[u][e] = phi[u][j] - phi[u][i];
        }
    m_gram = Eigen::MatrixXd::Zero(Eigen::Index(m_loops), Eigen::Index(m_loops));
    for(std::size_t a = 0; a < m_loops; ++a)
      for(std::size_t b = a; b < m_loops; ++b)
      {
        double sum = 0.;
        for(std::size_t e = 0; e < ne; ++e)
          sum += m_weight[e] * m_difference[a][e] * m_difference[b][e];
        m_gram(Eigen::Index(a), Eigen::Index(b)) = m_gram(Eigen::Index(b), Eigen::Index(a)) = sum;
      }
  }

  /// A boundary that the field follows smoothed (`smoothed_boundary()`): y on the boundary edges
  /// (`boundary_y`, per edge in its orientation, the multiples of 2 pi making each loop's winding)
  /// and alpha's offset from the constant c at the boundary vertices (`alpha_offset`, per vertex)
  /// instead of 0.
  void set_boundary_values(std::vector<double> boundary_y, std::vector<double> alpha_offset)
  {
    m_boundary_y = std::move(boundary_y);
    m_alpha_offset = std::move(alpha_offset);
  }
  double boundary_y(std::size_t e) const { return m_boundary_y.empty() ? 0. : m_boundary_y[e]; }
  double alpha_offset(std::size_t v) const { return m_alpha_offset.empty() ? 0. : m_alpha_offset[v]; }

  /// Whether vertex v lies on the boundary.
  bool on_boundary(std::size_t v) const { return m_loop_of_vertex[v] != npos; }

  /// A boundary edge along which the transport turns an n-direction by more than `bound` (|omega_e|
  /// > bound: the boundary turns by about pi / n there, half-way between two of the field's
  /// directions), which a field along the boundary cannot follow; npos if there is none.
  std::size_t sharp_turn(const std::vector<double>& omega, double bound) const
  {
    for(std::size_t e = 0; e < omega.size(); ++e)
      if(m_border_edge[e] && !(std::abs(omega[e] - boundary_y(e)) <= bound))
        return e;
    return npos;
  }

  /// y (feasible, winding 0 on every boundary loop) -> the minimizer that is 0 on the boundary
  /// edges, as above. `alpha` is y integrated along a spanning tree of each component (any
  /// roots); `idx` and `topology` are those given to the constructor.
  void correct(const Indices& idx, const Topology& topology, std::vector<double>& y, const std::vector<double>& omega,
               const std::vector<double>& alpha) const
  {
    const std::size_t nv = idx.number_of_vertices(), ne = idx.number_of_edges();
    // g along each loop from its first vertex: g(target) = g(source) - (y along the border halfedge)
    std::vector<double> known(nv, 0.);
    std::vector<double> phase(topology.boundary.size(), 0.); // alpha + g at the loop's first vertex
    for(std::size_t l = 0; l < topology.boundary.size(); ++l)
    {
      const auto& loop = topology.boundary.loops[l];
      for(std::size_t k = 0; k + 1 < loop.size(); ++k)
      {
        const auto hd = idx.halfedge(loop[k]);
        const std::size_t e = idx.edge_index(hd);
        known[idx.target_index(hd)] = known[idx.source_index(hd)] + idx.orientation_sign(hd) * (boundary_y(e) - y[e]);
      }
      const std::size_t first = idx.source_index(idx.halfedge(loop.front()));
      phase[l] = alpha[first] - alpha_offset(first);
    }
    // each loop's constant, modulo 2 pi, so that alpha + g has the reference loop's phase on it
    std::vector<double> fraction(m_loops, 0.);
    for(std::size_t l = 0; l < topology.boundary.size(); ++l)
      if(m_loop_unknown[l] != npos)
      {
        const std::size_t c = topology.components.vertex_component[idx.source_index(idx.halfedge(topology.boundary.loops[l].front()))];
        fraction[m_loop_unknown[l]] = phase[m_reference_loop[c]] - phase[l];
      }
    for(std::size_t v = 0; v < nv; ++v)
      if(m_loop_of_vertex[v] != npos && m_loop_unknown[m_loop_of_vertex[v]] != npos)
        known[v] += fraction[m_loop_unknown[m_loop_of_vertex[v]]];
    std::vector<double> residual(ne, 0.);
    for(std::size_t e = 0; e < ne; ++e)
      residual[e] = y[e] - omega[e];
    std::vector<double> g = dirichlet(idx, residual, known);
    // the integers: 2 pi N_L more on loop L changes the free edges by 2 pi N_L times its differences
    if(m_loops > 0)
    {
      Eigen::VectorXd b = Eigen::VectorXd::Zero(Eigen::Index(m_loops));
      for(std::size_t u = 0; u < m_loops; ++u)
        for(std::size_t e = 0; e < ne; ++e)
          if(m_free_edge[e])
          {
            const auto [i, j] = idx.edge_vertices(e);
            b[Eigen::Index(u)] += m_weight[e] * (residual[e] + g[j] - g[i]) * m_difference[u][e];
          }
      const Eigen::VectorXi N = integer_quadratic_minimizer(4. * pi * pi * m_gram, 2. * pi * b);
      for(std::size_t l = 0; l < topology.boundary.size(); ++l)
        if(m_loop_unknown[l] != npos && N[Eigen::Index(m_loop_unknown[l])] != 0)
          for(std::size_t v = 0; v < nv; ++v)
            if(m_loop_of_vertex[v] == l)
              known[v] += two_pi * N[Eigen::Index(m_loop_unknown[l])];
      g = dirichlet(idx, residual, known);
    }
    for(std::size_t e = 0; e < ne; ++e)
      if(m_free_edge[e])
      {
        const auto [i, j] = idx.edge_vertices(e);
        y[e] += g[j] - g[i];
      }
      else if(m_aligned[topology.components.vertex_component[idx.edge_vertices(e).first]])
        y[e] = boundary_y(e); // a boundary edge
  }

private:
  // g: `known` on the boundary vertices, inside the minimizer of sum over the free edges of
  // w_e (r_e + g_j - g_i)^2 (the values of `known` elsewhere are kept: 0 on closed components)
  std::vector<double> dirichlet(const Indices& idx, const std::vector<double>& r, const std::vector<double>& known) const
  {
    std::vector<double> g = known;
    if(m_nodes == 0)
      return g;
    Eigen::VectorXd rhs = Eigen::VectorXd::Zero(Eigen::Index(m_nodes));
    for(std::size_t e = 0; e < r.size(); ++e)
    {
      if(!m_free_edge[e])
        continue;
      const auto [i, j] = idx.edge_vertices(e);
      const double t = r[e] + (m_node[j] == npos ? known[j] : 0.) - (m_node[i] == npos ? known[i] : 0.);
      if(m_node[i] != npos)
        rhs[Eigen::Index(m_node[i])] += m_weight[e] * t;
      if(m_node[j] != npos)
        rhs[Eigen::Index(m_node[j])] -= m_weight[e] * t;
    }
    const Eigen::VectorXd z = m_system.solve(rhs);
    for(std::size_t v = 0; v < g.size(); ++v)
      if(m_node[v] != npos)
        g[v] = z[Eigen::Index(m_node[v])];
    return g;
  }

  std::vector<double> m_weight, m_boundary_y, m_alpha_offset;
  mutable Factored_system<SolverTraits> m_system;
  std::vector<std::size_t> m_node, m_loop_of_vertex, m_loop_unknown, m_reference_loop;
  std::vector<bool> m_aligned, m_free_edge, m_border_edge;
  std::size_t m_nodes = 0, m_loops = 0;
  std::vector<std::vector<double>> m_difference; // per loop unknown, per edge
  Eigen::MatrixXd m_gram;
};

} // namespace internal
} // namespace Surface_design
} // namespace CGAL

#endif // CGAL_SURFACE_DESIGN_INTERNAL_DIRECTION_FIELDS_BOUNDARY_ALIGNMENT_H
