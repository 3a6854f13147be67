// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A small integer quadratic minimizer: the loop windings of the periodic one-form solvers, and
// the integer points with prescribed parities (the windings that put the cones on the lattice).

#ifndef CGAL_SURFACE_DESIGN_INTERNAL_SOLVERS_INTEGER_QUADRATIC_H
#define CGAL_SURFACE_DESIGN_INTERNAL_SOLVERS_INTEGER_QUADRATIC_H

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_design {
namespace internal {

/// The columns of the Gram matrix `gram` (symmetric positive semi-definite) whose vectors are not
/// numerically in the span of the earlier kept ones (an incremental Cholesky factorization: a
/// column stays when its residual square norm is above `relative` times its square norm).
inline std::vector<std::size_t> independent_gram_columns(const Eigen::MatrixXd& gram, double relative = 1e-9)
{
  const Eigen::Index m = gram.rows();
  Eigen::MatrixXd chol = Eigen::MatrixXd::Zero(m, m);
  std::vector<std::size_t> kept;
  for(Eigen::Index j = 0; j < m; ++j)
  {
    const Eigen::Index r = Eigen::Index(kept.size());
    Eigen::VectorXd q(r);
    for(Eigen::Index i = 0; i < r; ++i)
      q[i] = gram(Eigen::Index(kept[std::size_t(i)]), j);
    const Eigen::VectorXd z = r > 0 ? Eigen::VectorXd(chol.topLeftCorner(r, r).triangularView<Eigen::Lower>().solve(q)) : q;
    const double diag = gram(j, j), rest = diag - z.squaredNorm();
    if(!(diag > 0.) || !(rest > relative * diag))
      continue;
    chol.row(r).head(r) = z.transpose();
    chol(r, r) = std::sqrt(rest);
    kept.push_back(std::size_t(j));
  }
  return kept;
}

/// Integer c minimizing 2 g^T c + c^T Q c (Q symmetric positive definite): the best floor/ceil
/// rounding of the relaxed optimum (exhaustive for up to 12 unknowns, plain rounding otherwise),
/// then +-1 coordinate steps until none improves. Exact for one unknown; a local optimum in the
/// +-1 neighbourhood otherwise.
inline Eigen::VectorXi integer_quadratic_minimizer(const Eigen::MatrixXd& Q, const Eigen::VectorXd& g)
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

/// LLL reduction (Lenstra, Lenstra & Lovasz; Cohen, Algorithm 2.6.3 in floating point) of the
/// lattice basis whose Gram matrix is Q: returns the unimodular integer matrix U (stored in
/// doubles) such that the basis B U is reduced; its Gram matrix is U^T Q U. A reduced basis is
/// nearly orthogonal, which makes rounding nearly optimal and lattice enumeration fast.
inline Eigen::MatrixXd lll_reduction(Eigen::MatrixXd G, double delta = 0.99)
{
  const Eigen::Index m = G.rows();
  Eigen::MatrixXd U = Eigen::MatrixXd::Identity(m, m);
  if(m < 2)
    return U;
  Eigen::MatrixXd mu = Eigen::MatrixXd::Zero(m, m);
  Eigen::VectorXd B = Eigen::VectorXd::Zero(m);
  B[0] = G(0, 0);
  auto reduce = [&](Eigen::Index k, Eigen::Index l) {
    if(std::abs(mu(k, l)) <= 0.5)
      return;
    const double q = std::round(mu(k, l));
    U.col(k) -= q * U.col(l);
    // b_k -= q b_l in the Gram matrix: row and column k
    const double gkk = G(k, k) - 2. * q * G(k, l) + q * q * G(l, l);
    G.row(k) -= q * G.row(l);
    G.col(k) -= q * G.col(l);
    G(k, k) = gkk;
    mu(k, l) -= q;
    for(Eigen::Index j = 0; j < l; ++j)
      mu(k, j) -= q * mu(l, j);
  };
  Eigen::Index k = 1, kmax = 0;
  std::size_t guard = 0;
  while(k < m && ++guard < 100000)
  {
    if(k > kmax)
    {
      kmax = k;
      for(Eigen::Index j = 0; j <= k; ++j)
      {
        double u = G(k, j);
        for(Eigen::Index i = 0; i < j; ++i)
          u -= mu(j, i) * mu(k, i) * B[i];
        if(j < k)
          mu(k, j) = B[j] > 0. ? u / B[j] : 0.;
        else
          B[k] = u;
      }
    }
    reduce(k, k - 1);
    if(B[k] < (delta - mu(k, k - 1) * mu(k, k - 1)) * B[k - 1])
    {
      // swap b_k and b_{k-1}
      U.col(k).swap(U.col(k - 1));
      G.row(k).swap(G.row(k - 1));
      G.col(k).swap(G.col(k - 1));
      for(Eigen::Index j = 0; j < k - 1; ++j)
        std::swap(mu(k, j), mu(k - 1, j));
      const double m1 = mu(k, k - 1);
      const double Bn = B[k] + m1 * m1 * B[k - 1];
      if(!(Bn > 0.))
        break; // a dependent basis: leave it as it is
      mu(k, k - 1) = m1 * B[k - 1] / Bn;
      B[k] = B[k - 1] * B[k] / Bn;
      B[k - 1] = Bn;
      for(Eigen::Index i = k + 1; i <= kmax; ++i)
      {
        const double t = mu(i, k);
        mu(i, k) = mu(i, k - 1) - m1 * t;
        mu(i, k - 1) = t + mu(k, k - 1) * mu(i, k);
      }
      k = (std::max)(Eigen::Index(1), k - 1);
    }
    else
    {
      for(Eigen::Index l = k - 2; l >= 0; --l)
        reduce(k, l);
      ++k;
    }
  }
  return U;
}

/// A positive definite quadratic form prepared for integer minimization: the LLL-reduced basis U
/// and, in its coordinates, the Gram matrix U^T Q U and its Cholesky factor. Depends on Q only:
/// computed once, it serves every right-hand side g.
struct Reduced_integer_quadratic
{
  Eigen::MatrixXd U, Q, R; ///< R upper triangular, Q = R^T R
  bool definite = false;
};

inline Reduced_integer_quadratic reduce_integer_quadratic(const Eigen::MatrixXd& Q)
{
  Reduced_integer_quadratic r;
  r.U = lll_reduction(Q);
  r.Q = r.U.transpose() * Q * r.U;
  r.Q = (0.5 * (r.Q + r.Q.transpose())).eval();
  const Eigen::LLT<Eigen::MatrixXd> llt(r.Q);
  r.definite = llt.info() == Eigen::Success;
  if(r.definite)
    r.R = llt.matrixU();
  return r;
}

/// Integer c minimizing 2 g^T c + c^T Q c = (c - c*)^T Q (c - c*) + const, c* = -Q^-1 g, by
/// depth-first enumeration of the lattice points inside the ellipsoid of the best point found so
/// far (Schnorr-Euchner: coordinates visited from the last one, the nearest values first), in the
/// LLL-reduced basis of `reduced`. Exact unless more than `max_nodes` nodes are needed, in which
/// case the best point found is returned (the budget shrinks as 1/m above 100 unknowns, each node
/// costing O(m)); starts from the rounded optimum improved by +-1 coordinate steps in the reduced
/// basis, so it never does worse than that. Unlike rounding in the given basis, it finds the
/// optimum on skewed lattices (a bad basis of the loops).
inline Eigen::VectorXi closest_integer_point(const Reduced_integer_quadratic& reduced, const Eigen::VectorXd& g0,
                                            std::size_t max_nodes = 200000)
{
  const Eigen::Index m = g0.size();
  if(m == 0)
    return Eigen::VectorXi();
  const Eigen::MatrixXd& U = reduced.U;
  const Eigen::MatrixXd& Q = reduced.Q;
  const Eigen::VectorXd g = U.transpose() * g0;
  auto back = [&U](const Eigen::VectorXi& c) -> Eigen::VectorXi {
    return (U * c.cast<double>()).array().round().cast<int>().matrix();
  };
  if(!reduced.definite)
    return back(integer_quadratic_minimizer(Q, g));
  const Eigen::MatrixXd& R = reduced.R;
  // c* = -Q^-1 g by the cached factor (no O(m^3) work per call)
  const Eigen::VectorXd center =
    -R.triangularView<Eigen::Upper>().solve(R.transpose().triangularView<Eigen::Lower>().solve(g));
  auto distance = [&](const Eigen::VectorXd& c) {
    const Eigen::VectorXd d = c - center;
    return d.dot(Q * d);
  };
  // start: the rounded optimum, then +-1 coordinate steps while one lowers the cost
  // (the change for c_i += t is 2 t (Q (c - c*))_i + t^2 Q_ii)
  Eigen::VectorXd start = center.array().round().matrix();
  Eigen::VectorXd residual = Q * (start - center);
  for(bool improved = true; improved;)
  {
    improved = false;
    for(Eigen::Index i = 0; i < m; ++i)
      for(int t : {-1, 1})
        if(2. * t * residual[i] + Q(i, i) < -1e-12 * Q(i, i))
        {
          start[i] += t;
          residual += double(t) * Q.col(i);
          improved = true;
          break;
        }
  }
  Eigen::VectorXi best = start.cast<int>();
  double radius = distance(best.cast<double>()) * (1. + 1e-12) + 1e-300;
  // partial[i] = sum over rows >= i of (R (c - center))_row^2
  Eigen::VectorXd c = Eigen::VectorXd::Zero(m), partial = Eigen::VectorXd::Zero(m + 1);
  Eigen::VectorXd mid = Eigen::VectorXd::Zero(m);
  std::vector<double> step(std::size_t(m), 0.), dir(std::size_t(m), 0.);
  std::size_t nodes = 0;
  const std::size_t budget = (std::min)(max_nodes, max_nodes * 100 / std::size_t(m));
  auto enter = [&](Eigen::Index i) {
    // the unconstrained best c_i given c_{i+1..m-1}
    double s = 0.;
    for(Eigen::Index j = i + 1; j < m; ++j)
      s += R(i, j) * (c[j] - center[j]);
    mid[i] = center[i] - s / R(i, i);
    c[i] = std::round(mid[i]);
    step[std::size_t(i)] = 0.;
    dir[std::size_t(i)] = c[i] >= mid[i] ? -1. : 1.;
  };
  auto next_value = [&](Eigen::Index i) {
    // zig-zag around mid: c, c + dir, c - dir, c + 2 dir, ...
    step[std::size_t(i)] += 1.;
    const double k = step[std::size_t(i)];
    const double base = std::round(mid[i]);
    const double offset = std::ceil(k / 2.) * (int(k) % 2 == 1 ? dir[std::size_t(i)] : -dir[std::size_t(i)]);
    c[i] = base + offset;
  };
  Eigen::Index i = m - 1;
  enter(i);
  while(++nodes <= budget)
  {
    const double r = R(i, i) * (c[i] - mid[i]);
    const double d2 = partial[i + 1] + r * r;
    if(d2 < radius)
    {
      if(i == 0)
      {
        radius = d2;
        best = c.cast<int>();
        next_value(i);
      }
      else
      {
        partial[i] = d2;
        --i;
        enter(i);
      }
    }
    else
    {
      // values further from mid only grow: go up
      if(++i == m)
        break;
      next_value(i);
    }
  }
  return back(best);
}

/// The integer points x in Z^n whose parities solve a linear system modulo 2 for some values of
/// n_aux auxiliary binary unknowns s: A (x, s) = b (mod 2), each row of A holding n + n_aux
/// entries 0 or 1. They are x = offset + basis z, z in Z^n: `offset` in {0, 1}^n, `basis` (n x n,
/// integer) a basis of the lattice {x : A (x, s) = 0 (mod 2) for some s}, of index 2^(n - r) in
/// Z^n where r is the dimension over GF(2) of the parities it allows. `feasible` is false when no
/// x solves the system (then offset and basis are empty).
struct Parity_coset
{
  bool feasible = false;
  Eigen::VectorXi offset;
  Eigen::MatrixXi basis;
};

inline Parity_coset parity_coset(std::vector<std::vector<std::uint8_t>> A, std::vector<std::uint8_t> b,
                                 std::size_t n, std::size_t n_aux)
{
  const std::size_t cols = n + n_aux, rows = A.size();
  // reduced row echelon form over GF(2), the auxiliary columns eliminated first
  std::vector<std::size_t> order;
  for(std::size_t j = n; j < cols; ++j)
    order.push_back(j);
  for(std::size_t j = 0; j < n; ++j)
    order.push_back(j);
  std::vector<std::pair<std::size_t, std::size_t>> pivots; // (column, row)
  std::vector<bool> is_pivot(cols, false);
  std::size_t rank = 0;
  for(std::size_t col : order)
  {
    std::size_t r = rank;
    while(r < rows && !A[r][col])
      ++r;
    if(r == rows)
      continue;
    std::swap(A[r], A[rank]);
    std::swap(b[r], b[rank]);
    for(std::size_t i = 0; i < rows; ++i)
      if(i != rank && A[i][col])
      {
        for(std::size_t j = 0; j < cols; ++j)
          A[i][j] ^= A[rank][j];
        b[i] ^= b[rank];
      }
    pivots.emplace_back(col, rank);
    is_pivot[col] = true;
    ++rank;
  }
  Parity_coset result;
  for(std::size_t i = rank; i < rows; ++i)
    if(b[i])
      return result; // 0 = 1
  result.feasible = true;
  // the particular solution with the free unknowns at 0, restricted to x
  result.offset = Eigen::VectorXi::Zero(Eigen::Index(n));
  for(const auto& [col, row] : pivots)
    if(col < n)
      result.offset[Eigen::Index(col)] = b[row];
  // the null space (one vector per free column) restricted to x, then brought to reduced echelon
  // form: the parities x may take are offset + its span
  std::vector<std::vector<std::uint8_t>> span;
  for(std::size_t free_col = 0; free_col < cols; ++free_col)
  {
    if(is_pivot[free_col])
      continue;
    std::vector<std::uint8_t> v(n, 0);
    if(free_col < n)
      v[free_col] = 1;
    for(const auto& [col, row] : pivots)
      if(col < n)
        v[col] = A[row][free_col];
    span.push_back(std::move(v));
  }
  std::vector<std::size_t> span_pivot;
  std::size_t r = 0;
  for(std::size_t col = 0; col < n && r < span.size(); ++col)
  {
    std::size_t i = r;
    while(i < span.size() && !span[i][col])
      ++i;
    if(i == span.size())
      continue;
    std::swap(span[i], span[r]);
    for(std::size_t k = 0; k < span.size(); ++k)
      if(k != r && span[k][col])
        for(std::size_t j = 0; j < n; ++j)
          span[k][j] ^= span[r][j];
    span_pivot.push_back(col);
    ++r;
  }
  // basis: the r echelon vectors, and 2 e_j for every other column (determinant 2^(n - r))
  result.basis = Eigen::MatrixXi::Zero(Eigen::Index(n), Eigen::Index(n));
  std::vector<bool> covered(n, false);
  for(std::size_t k = 0; k < r; ++k)
  {
    covered[span_pivot[k]] = true;
    for(std::size_t j = 0; j < n; ++j)
      result.basis(Eigen::Index(j), Eigen::Index(span_pivot[k])) = span[k][j];
  }
  for(std::size_t j = 0; j < n; ++j)
    if(!covered[j])
      result.basis(Eigen::Index(j), Eigen::Index(j)) = 2;
  return result;
}

} // namespace internal
} // namespace Surface_design
} // namespace CGAL

#endif // CGAL_SURFACE_DESIGN_INTERNAL_SOLVERS_INTEGER_QUADRATIC_H
