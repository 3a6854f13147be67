// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The library's own supernodal Cholesky factorization, as an Eigen sparse solver and as solver
// traits, with its nested-dissection ordering and the cache of its symbolic analyses (public
// types, made public by `CGAL/Surface_design/supernodal_cholesky.h`); the default solver traits
// (solver_traits.h of this folder) use it for large systems.

#ifndef CGAL_SURFACE_DESIGN_INTERNAL_SOLVERS_SUPERNODAL_CHOLESKY_CLASS_H
#define CGAL_SURFACE_DESIGN_INTERNAL_SOLVERS_SUPERNODAL_CHOLESKY_CLASS_H

#include <CGAL/Surface_design/internal/Solvers/nested_dissection.h>
#include <CGAL/Surface_design/internal/Solvers/supernodal_kernels.h>

#include <CGAL/Eigen_matrix.h>
#include <CGAL/Eigen_solver_traits.h>

#include <Eigen/OrderingMethods>
#include <Eigen/SparseCore>

#include <algorithm>
#include <cstddef>
#include <memory>
#include <mutex>
#include <type_traits>
#include <typeindex>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_design {

/// \ingroup PkgSurfaceDesignRef
/// Nested-dissection fill-reducing ordering of the symmetric pattern of a sparse matrix, as an
/// Eigen ordering functor (the `Ordering` parameter of `Eigen::SimplicialLDLT`,
/// `Eigen::SimplicialLLT`, like `Eigen::AMDOrdering`): breadth-first level-set separators from a
/// pseudo-peripheral vertex, refined by Fiduccia-Mattheyses moves, recursively, with exact minimum
/// degree on parts of at most 64 vertices. Built for the graphs of surface meshes (level sets are
/// short rings), it needs no coordinates and works on any pattern (real or complex matrices, one
/// triangle or both stored, several components).
///
/// Complexity: O(n log n) time, O(n + nnz) memory. On the cotangent Laplacians of meshes of 30k to
/// 480k vertices its factors need 1.5 to 2.3 times fewer flops than AMD's, for 1 to 2.5 times
/// AMD's ordering time; METIS's orderings need fewer flops still but cost 2 to 5 times more. Below
/// about 20k unknowns AMD is the better choice (see the benchmark's `factorization` workload and
/// the foundation manual, section Solvers).
template <class StorageIndex>
using Nested_dissection_ordering = internal::Nested_dissection_ordering<StorageIndex>;

/// \ingroup PkgSurfaceDesignRef
/// The symbolic analyses of `Supernodal_cholesky` (fill-reducing ordering, supernodes, the place of
/// every entry), remembered by the pattern of the lower triangle of the analysed matrix, so that
/// the systems built on one mesh are ordered and analysed once: the smoothest direction field (a
/// complex Hermitian matrix), the stripes and the trivial connections (their pinned Laplacians keep
/// the pinned rows in the pattern), any other vertex system with one entry per edge and vertex.
///
/// Give one cache to the solvers of every system that should share (`Size_switched_cholesky` and
/// `Supernodal_cholesky` have `set_analysis_cache()`; the default solver traits reach theirs with
/// `traits.solver().set_analysis_cache(cache)`, and Hermitian systems inherit it from the traits).
/// An analysis is found only for a pattern equal, entry for entry, to one analysed before with the
/// same fill-reducing ordering (AMD and nested dissection are kept apart), in real or complex
/// arithmetic; any other pattern is analysed and added. Patterns are compared in O(nnz)
/// and kept (one `int` per stored lower entry, plus the analysis) until `clear()` or the cache's
/// destruction. Thread-safe.
class Symbolic_analysis_cache
{
public:
  using Analysis = internal::Supernodal_symbolic;

  /// Number of patterns analysed so far.
  std::size_t size() const
  {
    std::lock_guard<std::mutex> lock(m_mutex);
    return m_entries.size();
  }
  /// Number of analyses reused.
  std::size_t hits() const
  {
    std::lock_guard<std::mutex> lock(m_mutex);
    return m_hits;
  }
  /// Forgets every pattern (solvers keep the analyses they use).
  void clear()
  {
    std::lock_guard<std::mutex> lock(m_mutex);
    m_entries.clear();
    m_hits = 0;
  }

  /// \cond SKIP_IN_MANUAL
  /// The analysis of a matrix with the lower pattern of `a` under the fill-reducing ordering
  /// `ordering`, made by `analyse()` if there is none yet.
  template <class SparseMatrixType, class Analyse>
  std::shared_ptr<const Analysis> find_or_analyse(const SparseMatrixType& a, std::type_index ordering,
                                                  const Analyse& analyse)
  {
    Entry key{ordering, {}, {}, nullptr};
    key.column_start.assign(std::size_t(a.cols()) + 1, 0);
    key.rows.reserve(std::size_t(a.nonZeros()));
    internal::supernodal_detail::for_each_lower_entry(a, [&](int i, int j, const auto&) {
      ++key.column_start[std::size_t(j) + 1];
      key.rows.push_back(i);
    });
    if(auto found = find(key))
      return found;
    // analysed without the lock: the analysis may run parallel tasks, and a thread waiting for them
    // may pick up another task that looks in this cache
    key.analysis = analyse();
    if(!key.analysis)
      return key.analysis;
    std::lock_guard<std::mutex> lock(m_mutex);
    for(const Entry& e : m_entries)
      if(same_pattern(e, key)) // analysed by another thread meanwhile
      {
        ++m_hits;
        return e.analysis;
      }
    m_entries.push_back(std::move(key));
    return m_entries.back().analysis;
  }
  /// \endcond

private:
  struct Entry
  {
    std::type_index ordering;
    std::vector<int> column_start, rows; // per column, the count of lower entries (then the rows)
    std::shared_ptr<const Analysis> analysis;
  };

  static bool same_pattern(const Entry& a, const Entry& b)
  {
    return a.ordering == b.ordering && a.rows.size() == b.rows.size() && a.column_start == b.column_start &&
           a.rows == b.rows;
  }

  std::shared_ptr<const Analysis> find(const Entry& key)
  {
    std::lock_guard<std::mutex> lock(m_mutex);
    for(const Entry& e : m_entries)
      if(same_pattern(e, key))
      {
        ++m_hits;
        return e.analysis;
      }
    return nullptr;
  }

  mutable std::mutex m_mutex;
  std::vector<Entry> m_entries;
  std::size_t m_hits = 0;
};

/// \ingroup PkgSurfaceDesignRef
/// Supernodal multifrontal Cholesky factorization \f$ P A P^T = L L^H \f$ of a sparse symmetric
/// (real) or Hermitian (complex) positive definite matrix, as an Eigen sparse solver (same
/// interface as `Eigen::SimplicialLLT`: `analyzePattern`, `factorize`, `compute`, `info`, `solve`).
/// It reads the lower triangle of the matrix.
///
/// The columns of \f$ L \f$ are grouped into supernodes (columns with the same structure below
/// them, relaxed to admit a few explicit zeros) stored as dense panels, and factored with Eigen's
/// blocked dense kernels (Cholesky of the diagonal block, a triangular solve, one symmetric rank-k
/// update of the front), so that almost all of the work runs at the speed of dense matrix products.
/// Header-only, no BLAS needed. When CGAL is linked with TBB (`CGAL_LINKED_WITH_TBB`), independent
/// subtrees of the supernode tree are factored by concurrent tasks and the large fronts of the top
/// separators by blocks in parallel.
///
/// The symbolic analysis (`analyzePattern`: ordering, elimination tree, supernodes, the place of
/// every entry) depends on the pattern only. It is held through a shared pointer: `analysis()` hands
/// it to another solver (`set_analysis()`) whose matrices have the same stored pattern, in real or
/// complex arithmetic, and a `Symbolic_analysis_cache` (`set_analysis_cache()`) does so for every
/// solver that shares it, so that systems on one mesh are ordered and analysed once.
///
/// \tparam MatrixType_ `Eigen::SparseMatrix<Scalar>` (column-major), `Scalar` = `double` or
///         `std::complex<double>`
/// \tparam Ordering_ an Eigen ordering functor; the library's `Nested_dissection_ordering` by
///         default (`Eigen::AMDOrdering<int>` is the alternative for small systems)
template <class MatrixType_, class Ordering_ = Nested_dissection_ordering<int>>
class Supernodal_cholesky : public Eigen::SparseSolverBase<Supernodal_cholesky<MatrixType_, Ordering_>>
{
  using Base = Eigen::SparseSolverBase<Supernodal_cholesky<MatrixType_, Ordering_>>;
  using Base::m_isInitialized;

  template <class Ordering, class = void>
  struct Reads_one_triangle : std::false_type {};
  template <class Index>
  struct Reads_one_triangle<internal::Nested_dissection_ordering<Index>> : std::true_type {};

public:
  using MatrixType = MatrixType_;
  using Scalar = typename MatrixType::Scalar;
  using RealScalar = typename Eigen::NumTraits<Scalar>::Real;
  using StorageIndex = typename MatrixType::StorageIndex;
  using Analysis = internal::Supernodal_symbolic;
  enum { ColsAtCompileTime = Eigen::Dynamic, MaxColsAtCompileTime = Eigen::Dynamic };

  Supernodal_cholesky() = default;
  explicit Supernodal_cholesky(const MatrixType& a) { compute(a); }

  /// Orders the unknowns and analyses the pattern of `a`.
  void analyzePattern(const MatrixType& a)
  {
    m_isInitialized = false;
    m_factor = internal::Supernodal_factor<Scalar>();
    if(a.rows() != a.cols())
    {
      m_analysis.reset();
      m_info = Eigen::InvalidInput;
      return;
    }
    auto analyse = [&a]() -> std::shared_ptr<const Analysis> {
      typename Ordering_::PermutationType order;
      if constexpr(Reads_one_triangle<Ordering_>::value)
        Ordering_()(a, order);
      else if constexpr(std::is_same<Ordering_, Eigen::AMDOrdering<StorageIndex>>::value)
      {
        // AMD on the pattern alone, both triangles, a byte per entry, without the two full
        // copies of the values that Eigen's AMDOrdering makes (they took twice the ordering's
        // own time on bunny_8k's complex connection Laplacian). Its ties may be broken otherwise
        // (the rows of a column come sorted here); the fill matched Eigen's on every mesh tried.
        Eigen::SparseMatrix<char, Eigen::ColMajor, StorageIndex> pattern = symmetric_pattern(a);
        Eigen::internal::minimum_degree_ordering(pattern, order);
      }
      else // Eigen's other orderings expect both triangles
        Ordering_()(MatrixType(a.template selfadjointView<Eigen::Lower>()), order);
      std::vector<int> old_of_new(std::size_t(a.rows()));
      for(Eigen::Index k = 0; k < a.rows(); ++k) // an empty permutation (Eigen::NaturalOrdering): none
        old_of_new[std::size_t(k)] = order.size() == 0 ? int(k) : int(order.indices()[k]);
      return internal::supernodal_analysis(a, std::move(old_of_new));
    };
    m_analysis = m_cache ? m_cache->find_or_analyse(a, std::type_index(typeid(Ordering_)), analyse) : analyse();
    m_info = Eigen::Success;
  }

  /// Analyses are taken from (and added to) `cache` from now on; null: none.
  void set_analysis_cache(std::shared_ptr<Symbolic_analysis_cache> cache) { m_cache = std::move(cache); }
  const std::shared_ptr<Symbolic_analysis_cache>& analysis_cache() const { return m_cache; }

  /// Takes the analysis cache of another `Supernodal_cholesky` (e.g. the real one of the traits
  /// that a complex system is factored for).
  template <class OtherSolver>
  void use_settings_of(const OtherSolver& other)
  {
    m_cache = other.analysis_cache();
  }

  /// Uses the analysis of another solver (made for a matrix with the same stored pattern).
  void set_analysis(std::shared_ptr<const Analysis> analysis)
  {
    m_isInitialized = false;
    m_factor = internal::Supernodal_factor<Scalar>();
    m_analysis = std::move(analysis);
    m_info = m_analysis ? Eigen::Success : Eigen::InvalidInput;
  }

  /// The analysis, to share with solvers of matrices with the same pattern (null before one).
  std::shared_ptr<const Analysis> analysis() const { return m_analysis; }

  /// Factors `a`, whose stored pattern must be that of the analysed matrix. `info()` is
  /// `NumericalIssue` when `a` is not positive definite: a pivot |L_jj|^2 is not larger than
  /// `internal::ldlt_pivot_tolerance` times the largest (as `Factored_system` requires of LDLT pivots).
  void factorize(const MatrixType& a)
  {
    m_isInitialized = false;
    if(!m_analysis || a.rows() != m_analysis->n || a.cols() != m_analysis->n ||
       lower_entries(a) != m_analysis->entry_target.size())
    {
      m_info = Eigen::InvalidInput;
      return;
    }
    m_info = m_factor.factorize(m_analysis, a) == -1 ? Eigen::Success : Eigen::NumericalIssue;
    if(m_info == Eigen::Success)
    {
      const auto d = m_factor.pivots();
      if(d.size() > 0 && !(d.minCoeff() > internal::ldlt_pivot_tolerance * d.maxCoeff()))
        m_info = Eigen::NumericalIssue;
    }
    m_isInitialized = m_info == Eigen::Success;
  }

  Supernodal_cholesky& compute(const MatrixType& a)
  {
    analyzePattern(a);
    if(m_info == Eigen::Success)
      factorize(a);
    return *this;
  }

  Eigen::ComputationInfo info() const { return m_info; }
  Eigen::Index rows() const { return m_analysis ? m_analysis->n : 0; }
  Eigen::Index cols() const { return rows(); }

  /// The pivots |L_jj|^2, in the original order of the unknowns: those of an LDL^T factorization
  /// with the same ordering, so `Factored_system` checks them as it checks `SimplicialLDLT`'s.
  Eigen::Matrix<RealScalar, Eigen::Dynamic, 1> vectorD() const
  {
    return m_factor.is_factored() ? m_factor.pivots() : Eigen::Matrix<RealScalar, Eigen::Dynamic, 1>();
  }

  /// Number of supernodes, stored entries of L below the diagonal, multiply-adds of a factorization.
  int supernode_count() const { return m_analysis ? m_analysis->supernode_count() : 0; }
  double factor_nonzeros() const { return m_analysis ? m_analysis->factor_nonzeros : 0.; }
  double factor_flops() const { return m_analysis ? m_analysis->factor_flops : 0.; }

  /// \cond SKIP_IN_MANUAL
  template <class Rhs, class Dest>
  void _solve_impl(const Eigen::MatrixBase<Rhs>& b, Eigen::MatrixBase<Dest>& x) const
  {
    m_factor.solve(b, x);
  }
  using Base::_solve_impl;
  /// \endcond

private:
  // The structure of a + a^T from the stored lower triangle of a (the diagonal as stored), the
  // rows of every column in increasing order: a column receives its entries above the diagonal
  // while the columns before it are read, then its own lower entries, which are sorted.
  static Eigen::SparseMatrix<char, Eigen::ColMajor, StorageIndex> symmetric_pattern(const MatrixType& a)
  {
    const std::size_t n = std::size_t(a.rows());
    std::vector<StorageIndex> start(n + 1, 0);
    internal::supernodal_detail::for_each_lower_entry(a, [&](int i, int j, const Scalar&) {
      ++start[std::size_t(j) + 1];
      if(i != j)
        ++start[std::size_t(i) + 1];
    });
    for(std::size_t k = 0; k < n; ++k)
      start[k + 1] += start[k];
    Eigen::SparseMatrix<char, Eigen::ColMajor, StorageIndex> pattern(a.rows(), a.cols());
    pattern.resizeNonZeros(Eigen::Index(start[n]));
    std::copy(start.begin(), start.end(), pattern.outerIndexPtr());
    std::fill(pattern.valuePtr(), pattern.valuePtr() + start[n], char(1));
    StorageIndex* rows = pattern.innerIndexPtr();
    internal::supernodal_detail::for_each_lower_entry(a, [&](int i, int j, const Scalar&) {
      rows[start[std::size_t(j)]++] = StorageIndex(i);
      if(i != j)
        rows[start[std::size_t(i)]++] = StorageIndex(j);
    });
    return pattern;
  }

  static std::size_t lower_entries(const MatrixType& a)
  {
    std::size_t count = 0;
    internal::supernodal_detail::for_each_lower_entry(a, [&](int, int, const Scalar&) { ++count; });
    return count;
  }

  std::shared_ptr<const Analysis> m_analysis;
  std::shared_ptr<Symbolic_analysis_cache> m_cache;
  internal::Supernodal_factor<Scalar> m_factor;
  Eigen::ComputationInfo m_info = Eigen::InvalidInput;
};

/// \ingroup PkgSurfaceDesignRef
/// `Supernodal_cholesky` with the library's nested dissection behind `CGAL::Eigen_solver_traits`:
/// a model of `SparseLinearAlgebraWithFactorTraits_d` for symmetric positive definite systems;
/// Hermitian systems (the smoothest direction fields) are factored in complex arithmetic. Choose
/// it for large systems (`Default_solver_traits` orders by nested dissection from 20k unknowns on):
/// its advantage over `Simplicial_ldlt_solver_traits` grows with the size; below about 20k
/// unknowns the AMD ordering of `Default_solver_traits` costs less to compute (figures in the
/// foundation manual, section "Sparse solvers and optimizers").
using Supernodal_solver_traits =
  CGAL::Eigen_solver_traits<Supernodal_cholesky<CGAL::Eigen_sparse_matrix<double>::EigenType>>;

} // namespace Surface_design
} // namespace CGAL

#endif // CGAL_SURFACE_DESIGN_INTERNAL_SOLVERS_SUPERNODAL_CHOLESKY_CLASS_H
