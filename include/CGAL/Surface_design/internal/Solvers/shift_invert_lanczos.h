// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The smallest eigenpair of a generalized problem A u = lambda M u (M diagonal) per block of a
// block-diagonal matrix, by shift-invert Lanczos on one factorization.

#ifndef CGAL_SURFACE_DESIGN_INTERNAL_SOLVERS_SHIFT_INVERT_LANCZOS_H
#define CGAL_SURFACE_DESIGN_INTERNAL_SOLVERS_SHIFT_INVERT_LANCZOS_H

#include <CGAL/Surface_design/internal/Solvers/large_buffer.h>

#include <Eigen/Dense>

#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Surface_design {
namespace internal {

struct Lanczos_result
{
  Eigen::VectorXd x;          ///< per active group: the Ritz vector, unit M-norm; 0 on inactive rows
  std::vector<double> theta;  ///< per group: the largest Ritz value of B = S^-1 M (0 if inactive)
  std::size_t solves = 0;     ///< back-substitutions done
  bool converged = false;
};

/// Lanczos in the M inner product on B = S^-1 M, which is M-self-adjoint for symmetric S and
/// diagonal M > 0; the largest eigenvalues theta of B are 1 / (lambda + shift) for the smallest
/// lambda of A u = lambda M u when S = A + shift M. Rows are partitioned into groups (connected
/// components, on which S is block diagonal): every active group runs its own Lanczos process,
/// all of them sharing each back-substitution. Full reorthogonalization (two Gram-Schmidt passes),
/// explicit restart from the current Ritz vector when the basis reaches `max_basis` vectors.
/// A group has converged when its Lanczos residual ||B y - theta y||_M = beta |s_last| is at
/// most `tolerance * theta`; the eigenvalue is then accurate to about tolerance^2 / (relative gap).
///
/// `solve(b, x)` must compute x = S^-1 b.
template <class Solve>
Lanczos_result largest_eigenvectors_by_group(Solve&& solve, const Eigen::VectorXd& mass,
                                             const std::vector<std::size_t>& group_of_row,
                                             const std::vector<bool>& active, Eigen::VectorXd start,
                                             double tolerance, std::size_t max_solves,
                                             std::size_t max_basis = 48)
{
  const std::size_t G = active.size();
  const Eigen::Index N = mass.size();
  // one group (a connected mesh): plain vectorized products
  const bool single = G == 1;
  auto dots = [&](const auto& a, const auto& b) {
    std::vector<double> d(G, 0.);
    if(single)
      d[0] = mass.cwiseProduct(a).dot(b);
    else
      for(Eigen::Index r = 0; r < N; ++r)
        d[group_of_row[std::size_t(r)]] += mass[r] * a[r] * b[r];
    return d;
  };
  auto scale_by_group = [&](auto&& a, const std::vector<double>& s) {
    if(single)
      a *= s[0];
    else
      for(Eigen::Index r = 0; r < N; ++r)
        a[r] *= s[group_of_row[std::size_t(r)]];
  };
  auto subtract_by_group = [&](auto&& w, const std::vector<double>& c, const auto& q) {
    if(single)
      w -= c[0] * q;
    else
      for(Eigen::Index r = 0; r < N; ++r)
        w[r] -= c[group_of_row[std::size_t(r)]] * q[r];
  };
  auto inverse_norms = [&](const std::vector<double>& n2) {
    std::vector<double> s(G, 0.);
    for(std::size_t g = 0; g < G; ++g)
      s[g] = active[g] && n2[g] > 0. ? 1. / std::sqrt(n2[g]) : 0.;
    return s;
  };

  Lanczos_result out;
  out.theta.assign(G, 0.);
  scale_by_group(start, inverse_norms(dots(start, start)));
  if(max_basis < 2)
    max_basis = 2;

  // the basis in one buffer of max_basis columns (huge pages where it is large: a fresh 4 kB page
  // costs as much as the products on it on some virtual machines), the work vectors reused
  Large_buffer<double> basis;
  basis.resize_uninitialized(std::size_t(N) * max_basis);
  auto q = [&](std::size_t i) { return Eigen::Map<Eigen::VectorXd>(basis.data() + std::size_t(N) * i, N); };
  Eigen::VectorXd w(N), rhs(N);
  std::vector<Eigen::MatrixXd> h(G);
  std::vector<bool> done(G, false);
  while(true)
  {
    q(0) = start;
    for(auto& hg : h)
      hg = Eigen::MatrixXd::Zero(Eigen::Index(max_basis), Eigen::Index(max_basis));
    std::vector<Eigen::VectorXd> ritz(G);
    for(std::size_t j = 0;; ++j)
    {
      rhs = mass.cwiseProduct(q(j));
      solve(rhs, w);
      ++out.solves;
      for(int pass = 0; pass < 2; ++pass)
        for(std::size_t i = 0; i <= j; ++i)
        {
          const std::vector<double> c = dots(q(i), w);
          for(std::size_t g = 0; g < G; ++g)
            h[g](Eigen::Index(i), Eigen::Index(j)) += c[g];
          subtract_by_group(w, c, q(i));
        }
      const std::vector<double> beta2 = dots(w, w);

      // Ritz pairs of every active group
      bool all_done = true;
      for(std::size_t g = 0; g < G; ++g)
      {
        if(!active[g])
          continue;
        const Eigen::Index k = Eigen::Index(j + 1);
        // the projection Q^T M B Q from its upper triangle (the entries computed as <q_i, B q_j>)
        const Eigen::MatrixXd t = h[g].topLeftCorner(k, k).template selfadjointView<Eigen::Upper>();
        Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(t);
        const Eigen::VectorXd s = eig.eigenvectors().col(k - 1);
        out.theta[g] = eig.eigenvalues()[k - 1];
        ritz[g] = s;
        const double residual = std::sqrt((std::max)(beta2[g], 0.)) * std::abs(s[k - 1]);
        done[g] = residual <= tolerance * std::abs(out.theta[g]);
        all_done = all_done && done[g];
      }
      out.converged = all_done;
      const bool stop = all_done || out.solves >= max_solves || j + 1 == max_basis;
      if(stop)
      {
        // Ritz vectors, group by group
        Eigen::VectorXd x = Eigen::VectorXd::Zero(N);
        for(std::size_t i = 0; i <= j; ++i)
        {
          std::vector<double> c(G, 0.);
          for(std::size_t g = 0; g < G; ++g)
            c[g] = active[g] ? -ritz[g][Eigen::Index(i)] : 0.;
          subtract_by_group(x, c, q(i));
        }
        scale_by_group(x, inverse_norms(dots(x, x)));
        out.x = x;
        break;
      }
      for(std::size_t g = 0; g < G; ++g)
        if(active[g])
          h[g](Eigen::Index(j + 1), Eigen::Index(j)) = std::sqrt((std::max)(beta2[g], 0.));
      scale_by_group(w, inverse_norms(beta2)); // an exhausted group (beta = 0) continues with zeros
      q(j + 1) = w;
    }
    if(out.converged || out.solves >= max_solves)
      return out;
    start = out.x; // explicit restart
  }
}

} // namespace internal
} // namespace Surface_design
} // namespace CGAL

#endif // CGAL_SURFACE_DESIGN_INTERNAL_SOLVERS_SHIFT_INVERT_LANCZOS_H
