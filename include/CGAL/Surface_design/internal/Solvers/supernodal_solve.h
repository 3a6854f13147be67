// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The pattern-only part of a supernodal Cholesky factorization (`Supernodal_symbolic`) and the
// back-substitution of one right-hand side through the panels of its factor, supernode by
// supernode, with the split of the supernode tree into subtrees solved independently.

#ifndef CGAL_SURFACE_DESIGN_INTERNAL_SOLVERS_SUPERNODAL_SOLVE_H
#define CGAL_SURFACE_DESIGN_INTERNAL_SOLVERS_SUPERNODAL_SOLVE_H

#include <algorithm>
#include <complex>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

namespace CGAL {
namespace Surface_design {
namespace internal {

/// Relative size below which a pivot of a positive definite system (an LDLT pivot d_j, or |L_jj|^2
/// of a Cholesky factor) counts as zero: the matrix is then taken as singular to working precision.
constexpr double ldlt_pivot_tolerance = 100. * std::numeric_limits<double>::epsilon();

/// The pattern-only part of a supernodal Cholesky factorization, shared by every matrix with the
/// same pattern (same stored entries, in the same order). Indices of unknowns after permutation are
/// called "permuted".
struct Supernodal_symbolic
{
  int n = 0;
  std::vector<int> old_of_new;              // old_of_new[k]: original index of permuted unknown k
  std::vector<int> first;                   // supernode s holds permuted columns [first[s], first[s+1])
  std::vector<int> parent;                  // parent supernode, -1 for roots
  std::vector<int> child_offsets, children; // children of s: children[child_offsets[s] .. child_offsets[s+1])
  std::vector<int> subtree_first;           // the subtree of s is the supernodes [subtree_first[s], s]
  std::vector<double> subtree_work;         // multiply-adds of the factorization of that subtree
  std::vector<std::int64_t> row_offsets;    // rows of s: rows[row_offsets[s] .. row_offsets[s+1])
  std::vector<int> rows;                    // its columns first, then the rows below them, ascending
  std::vector<int> relative;                // aligned with rows: position of a row below s in its parent's rows
  std::vector<std::int64_t> panel_offsets;  // the dense panel of s (nrows x ncols, column-major) in L's values
  std::vector<std::int64_t> entry_target;   // per stored lower entry of A (iteration order): its place in L
  std::vector<unsigned char> entry_conjugated; // 1 when the entry lands in the other triangle after permutation
  std::size_t update_size = 0;              // largest update matrix (entries)
  std::size_t stack_size = 0;               // peak of the update matrices stacked at once (entries)
  std::size_t largest_below = 0;            // most rows below a supernode (the solve's workspace)
  double factor_nonzeros = 0.;              // entries of L stored (explicit zeros of amalgamation included)
  double factor_flops = 0.;                 // multiply-adds of the factorization, sum over columns of count^2

  int supernode_count() const { return int(first.size()) - 1; }
  int columns(int s) const { return first[std::size_t(s) + 1] - first[std::size_t(s)]; }
  int row_count(int s) const { return int(row_offsets[std::size_t(s) + 1] - row_offsets[std::size_t(s)]); }
};

namespace supernodal_detail {

// Products of the back-substitution in plain real arithmetic. The operators of std::complex
// check their result for NaN (C99 Annex G) unless the compiler may assume finite values
// (-ffast-math, -fcx-limited-range), which keeps the complex loops scalar and branchy; the values
// here are finite (a factorization with non-finite entries is refused), so the checks buy nothing.
// Measured on the 60k bunny's line-field connection Laplacian (30k complex unknowns), one solve:
// 8.6 ms with the operators, 7.5 ms without (before the solve by subtrees).
template <class T>
T times(T a, T b)
{
  return a * b;
}
template <class T>
std::complex<T> times(const std::complex<T>& a, const std::complex<T>& b)
{
  return {a.real() * b.real() - a.imag() * b.imag(), a.real() * b.imag() + a.imag() * b.real()};
}
// conj(a) * b
template <class T>
T conj_times(T a, T b)
{
  return a * b;
}
template <class T>
std::complex<T> conj_times(const std::complex<T>& a, const std::complex<T>& b)
{
  return {a.real() * b.real() + a.imag() * b.imag(), a.real() * b.imag() - a.imag() * b.real()};
}
// x / d for the real, positive diagonal entry d of a Cholesky factor (stored as a Scalar)
template <class T>
T over_diagonal(T x, T d)
{
  return x / d;
}
template <class T>
std::complex<T> over_diagonal(const std::complex<T>& x, const std::complex<T>& d)
{
  return {x.real() / d.real(), x.imag() / d.real()};
}

} // namespace supernodal_detail

/// Subtrees of the supernode tree solved independently: the supernodes from `top` on form a chain
/// from the root (or are none, for a forest) and are solved after the subtrees (forward) or before
/// them (backward); below them hang the subtrees, in `groups` of similar size (by entries of L),
/// at most `supernodal_solve_groups`. No groups for a small factor (below
/// `supernodal_parallel_solve_nonzeros` entries) or a tree that is a chain. Depends on the
/// analysis alone, so that a solve gives the same bits whatever the number of threads.
struct Supernodal_solve_split
{
  int top = 0;
  std::vector<std::vector<int>> groups; // roots of subtrees, ascending within a group
};
constexpr double supernodal_parallel_solve_nonzeros = 2e4;
constexpr std::size_t supernodal_solve_groups = 4;

inline Supernodal_solve_split supernodal_solve_split(const Supernodal_symbolic& sym)
{
  const int ns = sym.supernode_count();
  Supernodal_solve_split split;
  split.top = 0;
  if(sym.factor_nonzeros < supernodal_parallel_solve_nonzeros)
    return split; // everything in the sequential part
  std::vector<int> front;
  for(int s = 0; s < ns; ++s)
    if(sym.parent[std::size_t(s)] == -1)
      front.push_back(s);
  split.top = ns;
  while(front.size() == 1)
  {
    const int s = front[0];
    const int k0 = sym.child_offsets[std::size_t(s)], k1 = sym.child_offsets[std::size_t(s) + 1];
    split.top = s;
    if(k0 == k1)
      return split; // a chain: no subtrees
    front.assign(sym.children.begin() + k0, sym.children.begin() + k1);
  }
  auto entries = [&sym](int root) {
    const std::size_t first = std::size_t(sym.subtree_first[std::size_t(root)]);
    return sym.panel_offsets[std::size_t(root) + 1] - sym.panel_offsets[first];
  };
  std::sort(front.begin(), front.end(), [&](int a, int b) {
    const auto ea = entries(a), eb = entries(b);
    return ea != eb ? ea > eb : a < b;
  });
  split.groups.resize((std::min)(front.size(), supernodal_solve_groups));
  std::vector<std::int64_t> load(split.groups.size(), 0);
  for(int root : front) // the largest first, to the least loaded group
  {
    const std::size_t g = std::size_t(std::min_element(load.begin(), load.end()) - load.begin());
    split.groups[g].push_back(root);
    load[g] += entries(root);
  }
  for(std::vector<int>& g : split.groups)
    std::sort(g.begin(), g.end());
  return split;
}

/// L y = b within supernode s of the factor whose panels are `values`; updates of rows at or past
/// `top_column` go to `collected` (subtracted from collected[row - top_column]), the others to y.
template <class Scalar>
void supernodal_forward(const Supernodal_symbolic& sym, const Scalar* values, int s, Scalar* y, Scalar* collected,
                        int top_column)
{
  const int c = sym.columns(s), m = sym.row_count(s);
  const int* rows = sym.rows.data() + sym.row_offsets[std::size_t(s)];
  const int split = int(std::lower_bound(rows + c, rows + m, top_column) - rows);
  Scalar* block = y + sym.first[std::size_t(s)];
  for(int j = 0; j < c; ++j)
  {
    const Scalar* column = values + sym.panel_offsets[std::size_t(s)] + std::int64_t(j) * m;
    const Scalar yj = supernodal_detail::over_diagonal(block[j], column[j]);
    block[j] = yj;
    for(int i = j + 1; i < c; ++i)
      block[i] -= supernodal_detail::times(column[i], yj);
    for(int i = c; i < split; ++i)
      y[rows[i]] -= supernodal_detail::times(column[i], yj);
    for(int i = split; i < m; ++i)
      collected[rows[i] - top_column] -= supernodal_detail::times(column[i], yj);
  }
}

/// L^H x = y within supernode s, the rows below it already final.
template <class Scalar>
void supernodal_backward(const Supernodal_symbolic& sym, const Scalar* values, int s, Scalar* y)
{
  const int c = sym.columns(s), m = sym.row_count(s);
  const int* rows = sym.rows.data() + sym.row_offsets[std::size_t(s)];
  Scalar* block = y + sym.first[std::size_t(s)];
  for(int j = c; j-- > 0;)
  {
    const Scalar* column = values + sym.panel_offsets[std::size_t(s)] + std::int64_t(j) * m;
    Scalar sum = block[j];
    for(int i = j + 1; i < c; ++i)
      sum -= supernodal_detail::conj_times(column[i], block[i]);
    for(int i = c; i < m; ++i)
      sum -= supernodal_detail::conj_times(column[i], y[rows[i]]);
    block[j] = supernodal_detail::over_diagonal(sum, column[j]);
  }
}

} // namespace internal
} // namespace Surface_design
} // namespace CGAL

#endif // CGAL_SURFACE_DESIGN_INTERNAL_SOLVERS_SUPERNODAL_SOLVE_H
