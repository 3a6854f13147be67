// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Multifrontal supernodal Cholesky factorization A = L L^H of sparse symmetric (real) or Hermitian
// (complex) positive definite matrices, with Eigen's dense kernels on the supernodes.
//
// Symbolic analysis (pattern only, reusable for any matrix with the same pattern):
//  1. a fill-reducing order (an Eigen ordering functor, the library's nested dissection by default),
//     composed with a postorder of the elimination tree of the permuted matrix (Liu's algorithm);
//  2. column counts of L by row subtrees; fundamental supernodes (chains of columns with nested
//     structures), then relaxed amalgamation: a supernode absorbs the child that precedes it when the
//     explicit zeros this adds stay small (the thresholds of CHOLMOD's defaults: always up to 4
//     columns, 80% zeros up to 16 columns, 10% up to 48, 5% beyond);
//  3. the row structure of every supernode (its columns, then the union of its columns' entries and
//     its children's structures below it), the position of each child's rows in its parent's front,
//     the destination of every stored entry of A in the factor, and the workspace sizes.
//  Its result, `Supernodal_symbolic`, is declared in supernodal_solve.h with the back-substitution,
//  which needs the pattern only.
// Numeric factorization, supernodes in postorder: the entries of A are scattered into the dense
// panels of L (nrows x ncols each), the update matrices of the children are added to the panel and to
// the supernode's own update matrix (extend-add, from a stack), then the panel is factored by dense
// blocked kernels: L11 = chol(A11), L21 = A21 L11^-H, U -= L21 L21^H (one symmetric rank-k update), and
// U is pushed. The dense kernels do almost all the flops at the speed of Eigen's matrix products,
// where a simplicial factorization spends its time on indirect addressing. With TBB, independent
// subtrees are factored by concurrent tasks (each with its own stack; the update matrices of their
// roots are kept aside for the sequential top of the tree), and the large fronts of the top
// separators by blocks of rows or columns in parallel.

#ifndef CGAL_SURFACE_DESIGN_INTERNAL_SOLVERS_SUPERNODAL_KERNELS_H
#define CGAL_SURFACE_DESIGN_INTERNAL_SOLVERS_SUPERNODAL_KERNELS_H

#include <CGAL/Surface_design/internal/Solvers/large_buffer.h>
#include <CGAL/Surface_design/internal/Solvers/nested_dissection.h>
#include <CGAL/Surface_design/internal/Solvers/parallel.h>
#include <CGAL/Surface_design/internal/Solvers/supernodal_solve.h>

#include <Eigen/Cholesky>
#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <memory>
#include <new>
#include <type_traits>
#include <utility>
#include <vector>

#if defined(CGAL_LINKED_WITH_TBB)
#include <tbb/task_arena.h>
#endif

namespace CGAL {
namespace Surface_design {
namespace internal {

namespace supernodal_detail {

using internal::Large_buffer; // (large_buffer.h)

/// The lower-triangle entries of a sparse matrix (row >= column), visited in storage order.
template <class SparseMatrixType, class Function>
void for_each_lower_entry(const SparseMatrixType& a, const Function& f)
{
  for(Eigen::Index j = 0; j < a.outerSize(); ++j)
    for(typename SparseMatrixType::InnerIterator it(a, j); it; ++it)
      if(it.row() >= it.col())
        f(int(it.row()), int(it.col()), it.value());
}

/// Compressed lists: list v is items[offsets[v] .. offsets[v+1]).
struct Lists
{
  std::vector<int> offsets;
  std::vector<int> items;
};

/// The strictly-lower pattern of the permuted matrix, by columns (`lower`: rows > column) and by
/// rows (`upper`: columns < row). The stored lower entries of `a` are numbered in their iteration
/// order: `lower_entry` (aligned with `lower.items`) and `diagonal_entry` (per permuted column, -1
/// when absent) give the number of each, `conjugated[e]` tells whether entry e lands above the
/// diagonal after permutation (so that its mirror, the conjugate, is the one in L's triangle).
struct Permuted_pattern
{
  Lists lower, upper;
  std::vector<int> lower_entry, diagonal_entry;
  std::vector<unsigned char> conjugated;
};

template <class SparseMatrixType>
void permuted_pattern(const SparseMatrixType& a, const std::vector<int>& new_of_old, Permuted_pattern& pattern)
{
  Lists& lower = pattern.lower;
  Lists& upper = pattern.upper;
  const std::size_t n = new_of_old.size();
  lower.offsets.assign(n + 1, 0);
  upper.offsets.assign(n + 1, 0);
  std::size_t entries = 0;
  for_each_lower_entry(a, [&](int i, int j, const auto&) {
    ++entries;
    if(i == j)
      return;
    const int pi = new_of_old[std::size_t(i)], pj = new_of_old[std::size_t(j)];
    ++lower.offsets[std::size_t(std::min(pi, pj)) + 1];
    ++upper.offsets[std::size_t(std::max(pi, pj)) + 1];
  });
  for(std::size_t v = 0; v < n; ++v)
  {
    lower.offsets[v + 1] += lower.offsets[v];
    upper.offsets[v + 1] += upper.offsets[v];
  }
  lower.items.resize(std::size_t(lower.offsets[n]));
  pattern.lower_entry.resize(lower.items.size());
  upper.items.resize(std::size_t(upper.offsets[n]));
  pattern.diagonal_entry.assign(n, -1);
  pattern.conjugated.assign(entries, 0);
  std::vector<int> lower_fill(lower.offsets.begin(), lower.offsets.end() - 1);
  std::vector<int> upper_fill(upper.offsets.begin(), upper.offsets.end() - 1);
  int e = 0;
  for_each_lower_entry(a, [&](int i, int j, const auto&) {
    const int pi = new_of_old[std::size_t(i)], pj = new_of_old[std::size_t(j)];
    if(i == j)
      pattern.diagonal_entry[std::size_t(pi)] = e;
    else
    {
      const int lo = std::min(pi, pj), hi = std::max(pi, pj);
      pattern.conjugated[std::size_t(e)] = pi < pj ? 1 : 0;
      pattern.lower_entry[std::size_t(lower_fill[std::size_t(lo)])] = e;
      lower.items[std::size_t(lower_fill[std::size_t(lo)]++)] = hi;
      upper.items[std::size_t(upper_fill[std::size_t(hi)]++)] = lo;
    }
    ++e;
  });
}

/// Elimination tree of the permuted matrix from its rows (Liu's algorithm with path compression).
inline std::vector<int> elimination_tree(const Lists& upper)
{
  const std::size_t n = upper.offsets.size() - 1;
  std::vector<int> parent(n, -1), ancestor(n, -1);
  for(std::size_t k = 0; k < n; ++k)
    for(int p = upper.offsets[k]; p < upper.offsets[k + 1]; ++p)
    {
      int i = upper.items[std::size_t(p)];
      while(i != -1 && i < int(k))
      {
        const int next = ancestor[std::size_t(i)];
        ancestor[std::size_t(i)] = int(k);
        if(next == -1)
          parent[std::size_t(i)] = int(k);
        i = next;
      }
    }
  return parent;
}

/// A postorder of a forest: post[k] is the k-th node visited; children in increasing order.
inline std::vector<int> postorder(const std::vector<int>& parent)
{
  const std::size_t n = parent.size();
  std::vector<int> head(n, -1), next(n, -1);
  for(std::size_t j = n; j-- > 0;) // children lists in increasing order
    if(parent[j] != -1)
    {
      next[j] = head[std::size_t(parent[j])];
      head[std::size_t(parent[j])] = int(j);
    }
  std::vector<int> post;
  post.reserve(n);
  std::vector<int> stack;
  for(std::size_t root = 0; root < n; ++root)
  {
    if(parent[root] != -1)
      continue;
    stack.push_back(int(root));
    while(!stack.empty())
    {
      const int v = stack.back();
      const int child = head[std::size_t(v)];
      if(child == -1)
      {
        post.push_back(v);
        stack.pop_back();
      }
      else
      {
        head[std::size_t(v)] = next[std::size_t(child)]; // visit the next child next time
        stack.push_back(child);
      }
    }
  }
  return post;
}

/// Entries of the trapezoid of a supernode of `c` columns with `b` rows below them.
inline double trapezoid(double c, double b) { return c * (c + 1.) / 2. + c * b; }

/// Relaxed amalgamation rule (CHOLMOD's default thresholds).
inline bool merge_allowed(int columns, double zeros, double total)
{
  const double fraction = zeros / total;
  return columns <= 4 || (columns <= 16 && fraction < 0.8) || (columns <= 48 && fraction < 0.1) ||
         fraction < 0.05;
}

} // namespace supernodal_detail

/// Symbolic analysis of the lower triangle of `a` (square) with the fill-reducing order
/// `old_of_new` (a permutation of 0..n-1: the k-th unknown eliminated).
template <class SparseMatrixType>
std::shared_ptr<Supernodal_symbolic> supernodal_analysis(const SparseMatrixType& a, std::vector<int> old_of_new)
{
  using namespace supernodal_detail;
  auto result = std::make_shared<Supernodal_symbolic>();
  Supernodal_symbolic& sym = *result;
  const int n = int(a.rows());
  const std::size_t un = std::size_t(n);
  sym.n = n;

  // 1. the order, composed with a postorder of the elimination tree
  std::vector<int> new_of_old(un);
  for(int k = 0; k < n; ++k)
    new_of_old[std::size_t(old_of_new[std::size_t(k)])] = k;
  Permuted_pattern pattern;
  const Lists& lower = pattern.lower;
  const Lists& upper = pattern.upper;
  permuted_pattern(a, new_of_old, pattern);
  {
    const std::vector<int> post = postorder(elimination_tree(upper));
    std::vector<int> composed(un);
    for(std::size_t k = 0; k < un; ++k)
      composed[k] = old_of_new[std::size_t(post[k])];
    old_of_new = std::move(composed);
    for(int k = 0; k < n; ++k)
      new_of_old[std::size_t(old_of_new[std::size_t(k)])] = k;
    permuted_pattern(a, new_of_old, pattern);
  }
  const std::vector<int> etree = elimination_tree(upper);

  // 2. column counts (strictly below the diagonal) by row subtrees, O(nnz(L))
  std::vector<int> count(un, 0), mark(un, -1), children(un, 0);
  for(int k = 0; k < n; ++k)
  {
    mark[std::size_t(k)] = k;
    for(int p = upper.offsets[std::size_t(k)]; p < upper.offsets[std::size_t(k) + 1]; ++p)
      for(int j = upper.items[std::size_t(p)]; mark[std::size_t(j)] != k; j = etree[std::size_t(j)])
      {
        ++count[std::size_t(j)];
        mark[std::size_t(j)] = k;
      }
    if(etree[std::size_t(k)] != -1)
      ++children[std::size_t(etree[std::size_t(k)])];
  }

  // fundamental supernodes, then relaxed amalgamation in postorder: the supernode that ends just
  // before a supernode's first column is its last child when its parent column lies in it
  struct Node { int first, columns, below; double zeros; };
  std::vector<Node> nodes;
  for(int j = 0; j < n;)
  {
    int last = j;
    while(last + 1 < n && etree[std::size_t(last)] == last + 1 && children[std::size_t(last) + 1] == 1 &&
          count[std::size_t(last)] == count[std::size_t(last) + 1] + 1)
      ++last;
    Node node{j, last - j + 1, count[std::size_t(last)], 0.};
    while(!nodes.empty())
    {
      const Node& child = nodes.back();
      const int child_parent = etree[std::size_t(child.first + child.columns - 1)];
      if(child_parent < node.first || child_parent >= node.first + node.columns)
        break;
      const int columns = child.columns + node.columns;
      const double total = trapezoid(columns, node.below);
      const double zeros = total - (trapezoid(child.columns, child.below) - child.zeros) -
                           (trapezoid(node.columns, node.below) - node.zeros);
      if(!merge_allowed(columns, zeros, total))
        break;
      node = Node{child.first, columns, node.below, zeros};
      nodes.pop_back();
    }
    nodes.push_back(node);
    j = last + 1;
  }
  const int ns = int(nodes.size());
  const std::size_t uns = std::size_t(ns);
  sym.first.resize(uns + 1);
  std::vector<int> supernode_of(un);
  for(int s = 0; s < ns; ++s)
  {
    sym.first[std::size_t(s)] = nodes[std::size_t(s)].first;
    for(int c = 0; c < nodes[std::size_t(s)].columns; ++c)
      supernode_of[std::size_t(nodes[std::size_t(s)].first + c)] = s;
  }
  sym.first[uns] = n;
  sym.parent.assign(uns, -1);
  std::vector<int> child_offsets(uns + 1, 0);
  for(int s = 0; s < ns; ++s)
  {
    const int up = etree[std::size_t(sym.first[std::size_t(s) + 1] - 1)];
    if(up != -1)
    {
      sym.parent[std::size_t(s)] = supernode_of[std::size_t(up)];
      ++child_offsets[std::size_t(sym.parent[std::size_t(s)]) + 1];
    }
  }
  for(std::size_t s = 0; s < uns; ++s)
    child_offsets[s + 1] += child_offsets[s];
  std::vector<int> child_list(std::size_t(child_offsets[uns]), 0);
  {
    std::vector<int> fill(child_offsets.begin(), child_offsets.end() - 1);
    for(int s = 0; s < ns; ++s)
      if(sym.parent[std::size_t(s)] != -1)
        child_list[std::size_t(fill[std::size_t(sym.parent[std::size_t(s)])]++)] = s;
  }
  sym.subtree_first.resize(uns);
  sym.subtree_work.assign(uns, 0.);

  // 3. row structures, children's relative positions, panels, workspaces
  sym.row_offsets.assign(uns + 1, 0);
  sym.panel_offsets.assign(uns + 1, 0);
  std::vector<int> position(un, -1);
  {
    std::size_t total_rows = 0;
    for(const Node& node : nodes)
      total_rows += std::size_t(node.columns + node.below);
    sym.rows.reserve(total_rows);
    sym.relative.assign(total_rows, -1);
  }
  sym.entry_target.resize(pattern.conjugated.size());
  sym.entry_conjugated = std::move(pattern.conjugated);
  std::fill(mark.begin(), mark.end(), -1);
  std::size_t stack = 0;
  for(int s = 0; s < ns; ++s)
  {
    const int f = sym.first[std::size_t(s)], l = sym.first[std::size_t(s) + 1];
    const std::size_t begin = sym.rows.size();
    for(int j = f; j < l; ++j)
    {
      sym.rows.push_back(j);
      mark[std::size_t(j)] = s;
    }
    auto add = [&](int i) {
      if(mark[std::size_t(i)] != s)
      {
        mark[std::size_t(i)] = s;
        sym.rows.push_back(i);
      }
    };
    for(int j = f; j < l; ++j)
      for(int p = lower.offsets[std::size_t(j)]; p < lower.offsets[std::size_t(j) + 1]; ++p)
        add(lower.items[std::size_t(p)]);
    for(int p = child_offsets[std::size_t(s)]; p < child_offsets[std::size_t(s) + 1]; ++p)
    {
      const int c = child_list[std::size_t(p)];
      for(std::int64_t q = sym.row_offsets[std::size_t(c)] + sym.columns(c); q < sym.row_offsets[std::size_t(c) + 1]; ++q)
        add(sym.rows[std::size_t(q)]);
    }
    std::sort(sym.rows.begin() + std::ptrdiff_t(begin) + (l - f), sym.rows.end());
    sym.row_offsets[std::size_t(s) + 1] = std::int64_t(sym.rows.size());
    for(std::size_t q = begin; q < sym.rows.size(); ++q)
      position[std::size_t(sym.rows[q])] = int(q - begin);
    std::size_t popped = 0;
    for(int p = child_offsets[std::size_t(s)]; p < child_offsets[std::size_t(s) + 1]; ++p)
    {
      const int c = child_list[std::size_t(p)];
      for(std::int64_t q = sym.row_offsets[std::size_t(c)] + sym.columns(c); q < sym.row_offsets[std::size_t(c) + 1]; ++q)
        sym.relative[std::size_t(q)] = position[std::size_t(sym.rows[std::size_t(q)])];
      const std::size_t below = std::size_t(sym.row_count(c) - sym.columns(c));
      popped += below * below;
    }
    const std::size_t columns = std::size_t(l - f), row_count = std::size_t(sym.row_count(s)), below = row_count - columns;
    sym.panel_offsets[std::size_t(s) + 1] = sym.panel_offsets[std::size_t(s)] + std::int64_t(row_count * columns);
    // destination of the stored entries of A in the panel: row max(pi, pj) of column min(pi, pj)
    for(int j = f; j < l; ++j)
    {
      const std::int64_t column_start = sym.panel_offsets[std::size_t(s)] + std::int64_t(j - f) * std::int64_t(row_count);
      if(pattern.diagonal_entry[std::size_t(j)] != -1)
        sym.entry_target[std::size_t(pattern.diagonal_entry[std::size_t(j)])] = column_start + (j - f);
      for(int p = lower.offsets[std::size_t(j)]; p < lower.offsets[std::size_t(j) + 1]; ++p)
        sym.entry_target[std::size_t(pattern.lower_entry[std::size_t(p)])] =
          column_start + position[std::size_t(lower.items[std::size_t(p)])];
    }
    sym.update_size = std::max(sym.update_size, below * below);
    sym.largest_below = std::max(sym.largest_below, below);
    stack = stack - popped + below * below;
    sym.stack_size = std::max(sym.stack_size, stack);
    double work = 0.;
    for(std::size_t t = 0; t < columns; ++t)
    {
      const double c = double(row_count - t - 1); // below the diagonal in column t
      sym.factor_nonzeros += c;
      work += c * c;
    }
    sym.factor_flops += work;
    sym.subtree_first[std::size_t(s)] = s;
    sym.subtree_work[std::size_t(s)] += work;
    for(int p = child_offsets[std::size_t(s)]; p < child_offsets[std::size_t(s) + 1]; ++p)
    {
      const int c = child_list[std::size_t(p)];
      sym.subtree_first[std::size_t(s)] = std::min(sym.subtree_first[std::size_t(s)], sym.subtree_first[std::size_t(c)]);
      sym.subtree_work[std::size_t(s)] += sym.subtree_work[std::size_t(c)];
    }
  }
  sym.child_offsets = std::move(child_offsets);
  sym.children = std::move(child_list);

  sym.old_of_new = std::move(old_of_new);
  return result;
}

/// The numeric factor L of a supernodal symbolic analysis, and its solves.
template <class Scalar>
class Supernodal_factor
{
public:
  using RealScalar = typename Eigen::NumTraits<Scalar>::Real;
  using Dense = Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic>;
  using Map = Eigen::Map<Dense>;
  using Const_map = Eigen::Map<const Dense>;

  /// Factors the matrix `a` analysed by `symbolic`; with `parallel` (and TBB), independent subtrees
  /// of the supernode tree are factored by concurrent tasks. Returns -1 on success, else a
  /// (permuted) column whose pivot is not positive.
  template <class SparseMatrixType>
  Eigen::Index factorize(std::shared_ptr<const Supernodal_symbolic> symbolic, const SparseMatrixType& a,
                         bool parallel = true)
  {
    m_symbolic = std::move(symbolic);
    m_parallel = parallel;
    const Supernodal_symbolic& sym = *m_symbolic;
    const int ns = sym.supernode_count();
    m_values.assign_zero(std::size_t(sym.panel_offsets.back()));
    std::size_t e = 0;
    supernodal_detail::for_each_lower_entry(a, [&](int, int, const Scalar& v) {
      m_values.data()[sym.entry_target[e]] += sym.entry_conjugated[e] ? Eigen::numext::conj(v) : v;
      ++e;
    });

    // subtrees for concurrent tasks; the rest (the top of the tree) is factored afterwards
    std::vector<int> task_of(std::size_t(ns), -1);
    const std::vector<int> tasks = parallel ? parallel_subtrees(sym, task_of) : std::vector<int>();
    std::vector<std::vector<Scalar>> kept(tasks.empty() ? 0 : std::size_t(ns)); // update matrices of task roots
    std::atomic<Eigen::Index> failed(-1);
    m_workspaces.resize(tasks.size() + 1); // kept between factorizations: no new pages
    for_each_index(tasks.size(), true, [&](std::size_t t) {
      const int root = tasks[t];
      Workspace& w = m_workspaces[t + 1];
      w.reserve(sym, sym.subtree_first[std::size_t(root)], root + 1, task_of, int(t));
      for(int s = sym.subtree_first[std::size_t(root)]; s <= root && failed.load() == -1; ++s)
        if(!factor_supernode(s, w, kept, s == root))
          failed.store(sym.first[std::size_t(s)]);
    });
    if(failed.load() != -1)
    {
      m_symbolic.reset();
      return failed.load();
    }
    Workspace& w = m_workspaces[0];
    w.reserve(sym, 0, ns, task_of, -1);
    for(int s = 0; s < ns; ++s)
      if(task_of[std::size_t(s)] == -1 && !factor_supernode(s, w, kept, false))
      {
        m_symbolic.reset();
        return sym.first[std::size_t(s)];
      }
    return -1;
  }

  bool is_factored() const { return m_symbolic != nullptr; }

  /// Number of groups of subtrees that a back-substitution of one right-hand side solves
  /// independently (0: all of it in sequence); depends on the analysis alone.
  std::size_t solve_group_count() const
  {
    return m_symbolic ? supernodal_solve_split(*m_symbolic).groups.size() : 0;
  }
  const Supernodal_symbolic& symbolic() const { return *m_symbolic; }

  /// The pivots |L_jj|^2 in the original order of the unknowns (those of an LDL^T factorization
  /// with the same order).
  Eigen::Matrix<RealScalar, Eigen::Dynamic, 1> pivots() const
  {
    const Supernodal_symbolic& sym = *m_symbolic;
    Eigen::Matrix<RealScalar, Eigen::Dynamic, 1> d(sym.n);
    for(int s = 0; s < sym.supernode_count(); ++s)
    {
      const Const_map panel(m_values.data() + sym.panel_offsets[std::size_t(s)], sym.row_count(s), sym.columns(s));
      for(Eigen::Index t = 0; t < sym.columns(s); ++t)
        d[sym.old_of_new[std::size_t(sym.first[std::size_t(s)] + t)]] = Eigen::numext::abs2(panel(t, t));
    }
    return d;
  }

  /// x = A^-1 b for every column of b.
  template <class Rhs, class Dest>
  void solve(const Eigen::MatrixBase<Rhs>& b, Eigen::MatrixBase<Dest>& x) const
  {
    const Supernodal_symbolic& sym = *m_symbolic;
    const Eigen::Index n = sym.n, k = b.cols();
    if(k == 1)
    {
      solve_one(b, x);
      return;
    }
    // the columns are independent: two halves, solved concurrently (a fixed split, so that the
    // result does not depend on the number of threads; measured on the 58 harmonic parts of the
    // kitten's cross-field stripes, 22k unknowns: 70 -> 40 ms on 2 cores)
    x.derived().resize(n, k);
    const Eigen::Index half = k / 2;
    for_each_index(2, m_parallel, [&](std::size_t part) {
      const Eigen::Index first = part == 0 ? 0 : half, count = part == 0 ? half : k - half;
      Dense y(n, count);
      for(Eigen::Index i = 0; i < n; ++i)
        y.row(i) = b.row(sym.old_of_new[std::size_t(i)]).segment(first, count);
      solve_permuted(y);
      for(Eigen::Index i = 0; i < n; ++i)
        x.row(sym.old_of_new[std::size_t(i)]).segment(first, count) = y.row(i);
    });
  }

private:
  // y = P A^-1 P^T y for the permuted right-hand sides y (one per column), by blocks of columns
  void solve_permuted(Dense& y) const
  {
    const Supernodal_symbolic& sym = *m_symbolic;
    Dense gathered(Eigen::Index(sym.largest_below), y.cols());
    const int ns = sym.supernode_count();
    for(int s = 0; s < ns; ++s) // L y = b
    {
      const Eigen::Index columns = sym.columns(s), below = sym.row_count(s) - columns;
      const Const_map panel(m_values.data() + sym.panel_offsets[std::size_t(s)], sym.row_count(s), columns);
      auto block = y.middleRows(sym.first[std::size_t(s)], columns);
      panel.topRows(columns).template triangularView<Eigen::Lower>().solveInPlace(block);
      if(below == 0)
        continue;
      auto product = gathered.topRows(below);
      product.noalias() = panel.bottomRows(below) * block;
      const int* rows = sym.rows.data() + sym.row_offsets[std::size_t(s)] + columns;
      for(Eigen::Index r = 0; r < below; ++r)
        y.row(rows[r]) -= product.row(r);
    }
    for(int s = ns; s-- > 0;) // L^H x = y
    {
      const Eigen::Index columns = sym.columns(s), below = sym.row_count(s) - columns;
      const Const_map panel(m_values.data() + sym.panel_offsets[std::size_t(s)], sym.row_count(s), columns);
      auto block = y.middleRows(sym.first[std::size_t(s)], columns);
      if(below > 0)
      {
        auto values = gathered.topRows(below);
        const int* rows = sym.rows.data() + sym.row_offsets[std::size_t(s)] + columns;
        for(Eigen::Index r = 0; r < below; ++r)
          values.row(r) = y.row(rows[r]);
        block.noalias() -= panel.bottomRows(below).adjoint() * values;
      }
      panel.topRows(columns).template triangularView<Eigen::Lower>().adjoint().solveInPlace(block);
    }
  }

  // One right-hand side (the common case: every re-solve of an edit): through the panels four
  // columns at a time (`supernodal_forward`, `supernodal_backward`), the rows below a supernode
  // gathered (backward) or accumulated (forward) in a small contiguous buffer once per supernode.
  // A back-substitution reads the factor once, so it should run at memory speed; per-supernode
  // calls of Eigen's dense kernels cost more than they save there (measured: 1.2-1.4x slower than
  // a column loop on meshes of 20k to 120k vertices). Against the column loop, four columns at a
  // time: the 60k bunny's Laplacian (30k unknowns) 1.95 -> 1.14 ms a solve, its line-field
  // connection Laplacian (30k complex unknowns) 5.1 -> 4.0 ms (medians of 21, on 2 cores).
  //
  // Large factors are solved by independent subtrees (`supernodal_solve_split`): forward, each group of
  // subtrees runs on its own, its updates of the top of the tree collected in a buffer of its own
  // and added in a fixed order; backward, the top first, then the groups on their own. The split
  // depends on the analysis alone, so that the result does not depend on the number of threads.
  template <class Rhs, class Dest>
  void solve_one(const Eigen::MatrixBase<Rhs>& b, Eigen::MatrixBase<Dest>& x) const
  {
    const Supernodal_symbolic& sym = *m_symbolic;
    const Eigen::Index n = sym.n;
    const int ns = sym.supernode_count();
    std::vector<Scalar> y(std::size_t(n) + 1); // + 1: a valid pointer for n = 0
    for(Eigen::Index i = 0; i < n; ++i)
      y[std::size_t(i)] = b(sym.old_of_new[std::size_t(i)], 0);
    const Supernodal_solve_split split = supernodal_solve_split(sym);
    const int top_column = split.top < ns ? sym.first[std::size_t(split.top)] : int(n);
    const std::size_t top_rows = std::size_t(n - top_column);
    std::vector<std::vector<Scalar>> collected(split.groups.size());
    const std::size_t work_size = sym.largest_below + 1; // + 1: a valid pointer when nothing is below
    for_each_index(split.groups.size(), m_parallel, [&](std::size_t g) {
      collected[g].assign(top_rows + 1, Scalar(0));
      std::vector<Scalar> work(work_size);
      for(int root : split.groups[g])
        for(int s = sym.subtree_first[std::size_t(root)]; s <= root; ++s)
          supernodal_forward(sym, m_values.data(), s, y.data(), collected[g].data(), top_column, work.data());
    });
    for(const std::vector<Scalar>& c : collected)
      for(std::size_t i = 0; i < top_rows; ++i)
        y[std::size_t(top_column) + i] += c[i];
    std::vector<Scalar> work(work_size);
    for(int s = split.top; s < ns; ++s)
      supernodal_forward(sym, m_values.data(), s, y.data(), static_cast<Scalar*>(nullptr), int(n), work.data());
    for(int s = ns; s-- > split.top;)
      supernodal_backward(sym, m_values.data(), s, y.data(), work.data());
    for_each_index(split.groups.size(), m_parallel, [&](std::size_t g) {
      std::vector<Scalar> group_work(work_size);
      for(int root : split.groups[g])
        for(int s = root + 1; s-- > sym.subtree_first[std::size_t(root)];)
          supernodal_backward(sym, m_values.data(), s, y.data(), group_work.data());
    });
    x.derived().resize(n, 1);
    for(Eigen::Index i = 0; i < n; ++i)
      x(sym.old_of_new[std::size_t(i)], 0) = y[std::size_t(i)];
  }

  // Dense kernels of the fronts. Large fronts (at the top of a nested-dissection tree: the
  // separators, up to a few thousand rows) hold half of the flops and come after the subtrees'
  // tasks; with TBB they are cut into blocks of rows or columns factored concurrently.
  static constexpr Eigen::Index block_size = 128;
  static constexpr Eigen::Index parallel_front = 384; // fronts at least this large use the blocked kernels

  bool use_blocks(Eigen::Index rows) const
  {
#if defined(CGAL_LINKED_WITH_TBB)
    return m_parallel && rows >= parallel_front && tbb::this_task_arena::max_concurrency() > 1;
#else
    (void)rows;
    return false;
#endif
  }

  // x = x l^-H for the lower triangular l: independent rows, solved by blocks of rows
  template <class X, class L>
  void solve_right_adjoint(X& x, const L& l) const
  {
    if(!use_blocks(x.rows()))
    {
      l.template triangularView<Eigen::Lower>().adjoint().template solveInPlace<Eigen::OnTheRight>(x);
      return;
    }
    const Eigen::Index blocks = (x.rows() + block_size - 1) / block_size;
    for_each_index(std::size_t(blocks), true, [&](std::size_t b) {
      const Eigen::Index r0 = Eigen::Index(b) * block_size, rows = std::min(block_size, x.rows() - r0);
      auto part = x.middleRows(r0, rows);
      l.template triangularView<Eigen::Lower>().adjoint().template solveInPlace<Eigen::OnTheRight>(part);
    });
  }

  // lower triangle of u -= a a^H, by blocks of columns: the diagonal block by a symmetric
  // rank update, the rows below it by a matrix product
  template <class U, class A>
  void rank_update(U& u, const A& a) const
  {
    if(!use_blocks(u.rows()))
    {
      u.template selfadjointView<Eigen::Lower>().rankUpdate(a, RealScalar(-1));
      return;
    }
    const Eigen::Index blocks = (u.rows() + block_size - 1) / block_size;
    for_each_index(std::size_t(blocks), true, [&](std::size_t b) {
      const Eigen::Index c0 = Eigen::Index(b) * block_size, width = std::min(block_size, u.rows() - c0);
      auto diagonal_block = u.block(c0, c0, width, width);
      diagonal_block.template selfadjointView<Eigen::Lower>().rankUpdate(a.middleRows(c0, width), RealScalar(-1));
      const Eigen::Index rest = u.rows() - c0 - width;
      if(rest > 0)
        u.block(c0 + width, c0, rest, width).noalias() -= a.bottomRows(rest) * a.middleRows(c0, width).adjoint();
    });
  }

  // in-place Cholesky factorization of the lower triangle of d; right-looking by blocks of
  // columns for large d. False if a pivot is not positive.
  template <class D>
  bool dense_cholesky(D& d) const
  {
    const Eigen::Index n = d.rows();
    const Eigen::Index step = use_blocks(n) ? block_size : n;
    for(Eigen::Index k0 = 0; k0 < n; k0 += step)
    {
      const Eigen::Index width = std::min(step, n - k0), rest = n - k0 - width;
      auto pivot_block = d.block(k0, k0, width, width);
      Eigen::LLT<Eigen::Ref<Dense>, Eigen::Lower> llt(pivot_block);
      if(llt.info() != Eigen::Success)
        return false;
      if(rest > 0)
      {
        auto below = d.block(k0 + width, k0, rest, width);
        solve_right_adjoint(below, pivot_block);
        auto trailing = d.bottomRightCorner(rest, rest);
        rank_update(trailing, below);
      }
    }
    return true;
  }

  // The update matrices of one sequence of supernodes: a stack (children are on top when their
  // parent comes) and the front's own update matrix.
  struct Workspace
  {
    supernodal_detail::Large_buffer<Scalar> update, stack;
    std::vector<std::pair<int, std::size_t>> stacked; // (supernode, offset of its update matrix)
    std::size_t top = 0;

    // sizes for the supernodes s in [begin, end) with task_of[s] == task
    void reserve(const Supernodal_symbolic& sym, int begin, int end, const std::vector<int>& task_of, int task)
    {
      std::size_t largest = 0, height = 0, peak = 0;
      std::vector<std::size_t> sizes;
      for(int s = begin; s < end; ++s)
      {
        if(task_of[std::size_t(s)] != task)
          continue;
        const std::size_t below = std::size_t(sym.row_count(s) - sym.columns(s));
        largest = std::max(largest, below * below);
        for(int p = sym.child_offsets[std::size_t(s)]; p < sym.child_offsets[std::size_t(s) + 1]; ++p)
        {
          const int c = sym.children[std::size_t(p)];
          if(task_of[std::size_t(c)] == task)
          {
            const std::size_t child_below = std::size_t(sym.row_count(c) - sym.columns(c));
            height -= child_below * child_below;
          }
        }
        height += below * below;
        peak = std::max(peak, height);
      }
      update.resize_uninitialized(largest); // each front clears its part
      stack.resize_uninitialized(peak);     // written before read
      stacked.clear();
      top = 0;
    }
  };

  // Assembles the children's update matrices into the front of s, factors its panel and pushes
  // its update matrix (into kept[s] for the root of a task). False if a pivot is not positive.
  bool factor_supernode(int s, Workspace& w, std::vector<std::vector<Scalar>>& kept, bool keep)
  {
    const Supernodal_symbolic& sym = *m_symbolic;
    const Eigen::Index columns = sym.columns(s), row_count = sym.row_count(s), below = row_count - columns;
    Map panel(m_values.data() + sym.panel_offsets[std::size_t(s)], row_count, columns);
    Map update(w.update.data(), below, below);
    update.template triangularView<Eigen::Lower>().setZero();
    auto extend_add = [&](int c, const Scalar* values) {
      const Eigen::Index child_below = sym.row_count(c) - sym.columns(c);
      const Const_map child_update(values, child_below, child_below);
      const int* relative = sym.relative.data() + sym.row_offsets[std::size_t(c)] + sym.columns(c);
      for(Eigen::Index q = 0; q < child_below; ++q)
      {
        const Eigen::Index target = relative[q];
        if(target < columns)
          for(Eigen::Index r = q; r < child_below; ++r)
            panel(relative[r], target) += child_update(r, q);
        else
          for(Eigen::Index r = q; r < child_below; ++r)
            update(relative[r] - columns, target - columns) += child_update(r, q);
      }
    };
    while(!w.stacked.empty() && sym.parent[std::size_t(w.stacked.back().first)] == s)
    {
      extend_add(w.stacked.back().first, w.stack.data() + w.stacked.back().second);
      w.top = w.stacked.back().second;
      w.stacked.pop_back();
    }
    if(!kept.empty())
      for(int p = sym.child_offsets[std::size_t(s)]; p < sym.child_offsets[std::size_t(s) + 1]; ++p)
      {
        std::vector<Scalar>& child = kept[std::size_t(sym.children[std::size_t(p)])];
        if(!child.empty())
        {
          extend_add(sym.children[std::size_t(p)], child.data());
          std::vector<Scalar>().swap(child);
        }
      }
    // dense partial factorization of the front: L11 = chol(F11), L21 = F21 L11^-H, U -= L21 L21^H
    auto diagonal = panel.topRows(columns);
    auto off_diagonal = panel.bottomRows(below);
    if(!dense_cholesky(diagonal))
      return false;
    if(below > 0)
    {
      solve_right_adjoint(off_diagonal, diagonal);
      rank_update(update, off_diagonal);
      if(keep)
        kept[std::size_t(s)].assign(w.update.data(), w.update.data() + below * below);
      else
      {
        std::copy(w.update.data(), w.update.data() + below * below, w.stack.data() + w.top);
        w.stacked.emplace_back(s, w.top);
        w.top += std::size_t(below * below);
      }
    }
    return true;
  }

  // Roots of disjoint subtrees for concurrent tasks, largest first (empty without TBB, with one
  // thread, or for small factorizations): the heaviest subtree is split (its root stays for the
  // sequential top) until every subtree holds at most 1/8 of a thread's share of the work.
  // task_of[s] is set to the task of each supernode of those subtrees.
  static std::vector<int> parallel_subtrees(const Supernodal_symbolic& sym, std::vector<int>& task_of)
  {
    std::vector<int> tasks;
#if defined(CGAL_LINKED_WITH_TBB)
    const int threads = tbb::this_task_arena::max_concurrency();
    double total = 0.;
    std::vector<std::pair<double, int>> heap;
    for(int s = 0; s < sym.supernode_count(); ++s)
      if(sym.parent[std::size_t(s)] == -1)
      {
        total += sym.subtree_work[std::size_t(s)];
        heap.emplace_back(sym.subtree_work[std::size_t(s)], s);
      }
    if(threads < 2 || total < parallel_work_threshold / scalar_cost)
      return tasks;
    const double limit = total / (8. * threads);
    std::make_heap(heap.begin(), heap.end());
    while(!heap.empty())
    {
      std::pop_heap(heap.begin(), heap.end());
      const auto [work, s] = heap.back();
      heap.pop_back();
      if(work <= limit)
      {
        tasks.push_back(s);
        continue;
      }
      for(int p = sym.child_offsets[std::size_t(s)]; p < sym.child_offsets[std::size_t(s) + 1]; ++p)
      {
        const int c = sym.children[std::size_t(p)];
        heap.emplace_back(sym.subtree_work[std::size_t(c)], c);
        std::push_heap(heap.begin(), heap.end());
      }
    }
    for(std::size_t t = 0; t < tasks.size(); ++t)
      for(int s = sym.subtree_first[std::size_t(tasks[t])]; s <= tasks[t]; ++s)
        task_of[std::size_t(s)] = int(t);
#else
    (void)sym;
    (void)task_of;
#endif
    return tasks;
  }

  // below this many real multiply-adds a factorization is not worth splitting into tasks; a complex
  // multiply-add costs four real ones (measured: the complex factorization of bunny_8k's
  // line-field connection Laplacian, 10.2 million multiply-adds, takes 4.2 times the real one of
  // the same pattern), so complex factorizations are split from a quarter of the count on
  static constexpr double parallel_work_threshold = 2e7;
  static constexpr double scalar_cost = Eigen::NumTraits<Scalar>::IsComplex ? 4. : 1.;

  std::shared_ptr<const Supernodal_symbolic> m_symbolic;
  supernodal_detail::Large_buffer<Scalar> m_values; // the panels of L
  std::vector<Workspace> m_workspaces;              // the top's, then one per task
  bool m_parallel = true;
};

} // namespace internal
} // namespace Surface_design
} // namespace CGAL

#endif // CGAL_SURFACE_DESIGN_INTERNAL_SOLVERS_SUPERNODAL_KERNELS_H
