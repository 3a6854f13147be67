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
#include <type_traits>
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

namespace supernodal_detail {

// The kernels of the back-substitution take the columns of a supernode four at a time (`K` <= 4
// columns): every entry of the vector they run along is then read or written once for the K
// columns, and the K sums of the backward dot products are independent chains. One column at a
// time, the backward sums were one chain of dependent additions (latency-bound, twice the time of
// the forward pass) and the forward pass wrote every row below a supernode once per column.

// t[i] -= sum_q col[q][i] x[q], for i in [0, count)
template <int K, class Scalar>
void subtract_columns(const Scalar* const* col, const Scalar* x, int count, Scalar* t)
{
  for(int i = 0; i < count; ++i)
  {
    Scalar sum = times(col[0][i], x[0]);
    for(int q = 1; q < K; ++q)
      sum += times(col[q][i], x[q]);
    t[i] -= sum;
  }
}

// s[q] -= sum_i conj(col[q][i]) v[i], for i in [0, count)
template <int K, class Scalar>
void subtract_dots(const Scalar* const* col, const Scalar* v, int count, Scalar* s)
{
  Scalar sum[K];
  for(int q = 0; q < K; ++q)
    sum[q] = Scalar(0);
  for(int i = 0; i < count; ++i)
  {
    const Scalar vi = v[i];
    for(int q = 0; q < K; ++q)
      sum[q] += conj_times(col[q][i], vi);
  }
  for(int q = 0; q < K; ++q)
    s[q] -= sum[q];
}

// the same for complex numbers, with the real and imaginary parts summed apart (2K independent
// chains, in plain real arithmetic)
template <int K, class T>
void subtract_dots(const std::complex<T>* const* col, const std::complex<T>* v, int count, std::complex<T>* s)
{
  T re[K], im[K];
  for(int q = 0; q < K; ++q)
    re[q] = im[q] = T(0);
  for(int i = 0; i < count; ++i)
  {
    const T vr = v[i].real(), vi = v[i].imag();
    for(int q = 0; q < K; ++q)
    {
      const T ar = col[q][i].real(), ai = col[q][i].imag();
      re[q] += ar * vr + ai * vi;
      im[q] += ar * vi - ai * vr;
    }
  }
  for(int q = 0; q < K; ++q)
    s[q] -= std::complex<T>(re[q], im[q]);
}

// Calls kernel(std::integral_constant<int, K>(), c) for the number of columns k in [1, 4] known
// at run time, c[q] = col[q] + offset.
template <class Scalar, class Kernel>
void with_columns(int k, const Scalar* const* col, std::int64_t offset, Kernel kernel)
{
  const Scalar* c[4];
  for(int q = 0; q < k; ++q)
    c[q] = col[q] + offset;
  switch(k)
  {
  case 1: kernel(std::integral_constant<int, 1>(), c); break;
  case 2: kernel(std::integral_constant<int, 2>(), c); break;
  case 3: kernel(std::integral_constant<int, 3>(), c); break;
  default: kernel(std::integral_constant<int, 4>(), c); break;
  }
}

template <class Scalar>
void subtract_columns(int k, const Scalar* const* col, std::int64_t offset, const Scalar* x, int count, Scalar* t)
{
  if(count > 0)
    with_columns(k, col, offset, [&](auto columns, const Scalar* const* c) {
      subtract_columns<decltype(columns)::value>(c, x, count, t);
    });
}
template <class Scalar>
void subtract_dots(int k, const Scalar* const* col, std::int64_t offset, const Scalar* v, int count, Scalar* s)
{
  if(count > 0)
    with_columns(k, col, offset, [&](auto columns, const Scalar* const* c) {
      subtract_dots<decltype(columns)::value>(c, v, count, s);
    });
}

} // namespace supernodal_detail

/// L y = b within supernode s of the factor whose panels are `values`; updates of rows at or past
/// `top_column` go to `collected` (added to collected[row - top_column]), the others to y.
/// `work` holds at least `sym.largest_below` entries.
template <class Scalar>
void supernodal_forward(const Supernodal_symbolic& sym, const Scalar* values, int s, Scalar* y, Scalar* collected,
                        int top_column, Scalar* work)
{
  using namespace supernodal_detail;
  const int c = sym.columns(s), m = sym.row_count(s), below = m - c;
  const int* rows = sym.rows.data() + sym.row_offsets[std::size_t(s)];
  const int split = int(std::lower_bound(rows + c, rows + m, top_column) - rows);
  const Scalar* panel = values + sym.panel_offsets[std::size_t(s)];
  Scalar* block = y + sym.first[std::size_t(s)];
  std::fill(work, work + below, Scalar(0));
  for(int j0 = 0; j0 < c; j0 += 4)
  {
    const int k = (std::min)(4, c - j0);
    const Scalar* col[4];
    for(int q = 0; q < k; ++q)
      col[q] = panel + std::int64_t(j0 + q) * m;
    for(int q = 0; q < k; ++q) // the group's own triangle
    {
      block[j0 + q] = over_diagonal(block[j0 + q], col[q][j0 + q]);
      for(int p = q + 1; p < k; ++p)
        block[j0 + p] -= times(col[q][j0 + p], block[j0 + q]);
    }
    subtract_columns(k, col, j0 + k, block + j0, c - j0 - k, block + j0 + k); // the supernode's later columns
    subtract_columns(k, col, c, block + j0, below, work);                     // the rows below it
  }
  for(int i = c; i < split; ++i)
    y[rows[i]] += work[i - c];
  for(int i = split; i < m; ++i)
    collected[rows[i] - top_column] += work[i - c];
}

/// L^H x = y within supernode s, the rows below it already final. `work` holds at least
/// `sym.largest_below` entries.
template <class Scalar>
void supernodal_backward(const Supernodal_symbolic& sym, const Scalar* values, int s, Scalar* y, Scalar* work)
{
  using namespace supernodal_detail;
  const int c = sym.columns(s), m = sym.row_count(s), below = m - c;
  const int* rows = sym.rows.data() + sym.row_offsets[std::size_t(s)];
  const Scalar* panel = values + sym.panel_offsets[std::size_t(s)];
  Scalar* block = y + sym.first[std::size_t(s)];
  for(int i = 0; i < below; ++i)
    work[i] = y[rows[c + i]];
  for(int j1 = c; j1 > 0; j1 -= 4)
  {
    const int j0 = (std::max)(0, j1 - 4), k = j1 - j0;
    const Scalar* col[4];
    for(int q = 0; q < k; ++q)
      col[q] = panel + std::int64_t(j0 + q) * m;
    subtract_dots(k, col, j1, block + j1, c - j1, block + j0); // the supernode's later columns, final
    subtract_dots(k, col, c, work, below, block + j0);         // the rows below it
    for(int q = k; q-- > 0;)                                   // the group's own triangle
    {
      Scalar sum = block[j0 + q];
      for(int p = q + 1; p < k; ++p)
        sum -= conj_times(col[q][j0 + p], block[j0 + p]);
      block[j0 + q] = over_diagonal(sum, col[q][j0 + q]);
    }
  }
}

} // namespace internal
} // namespace Surface_design
} // namespace CGAL

#endif // CGAL_SURFACE_DESIGN_INTERNAL_SOLVERS_SUPERNODAL_SOLVE_H
