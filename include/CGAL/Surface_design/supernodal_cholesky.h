// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The library's own supernodal Cholesky factorization, as an Eigen sparse solver and as solver
// traits. A header of its own (not `solver_traits.h`) so that code that keeps the default solver does
// not compile it.

#ifndef CGAL_SURFACE_DESIGN_SUPERNODAL_CHOLESKY_H
#define CGAL_SURFACE_DESIGN_SUPERNODAL_CHOLESKY_H

#include <CGAL/Surface_design/nested_dissection_ordering.h>
#include <CGAL/Surface_design/solver_traits.h>
#include <CGAL/Surface_design/internal/Core/Factored_system.h>
#include <CGAL/Surface_design/internal/Core/Hermitian_system.h>
#include <CGAL/Surface_design/internal/Core/supernodal_cholesky.h>

#include <CGAL/Eigen_matrix.h>
#include <CGAL/Eigen_solver_traits.h>

#include <Eigen/SparseCore>

#include <memory>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_design {

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
/// complex arithmetic, so that systems on one mesh are ordered and analysed once.
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
  struct Reads_one_triangle<Nested_dissection_ordering<Index>> : std::true_type {};

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
    typename Ordering_::PermutationType order;
    if constexpr(Reads_one_triangle<Ordering_>::value)
      Ordering_()(a, order);
    else // Eigen's orderings expect both triangles
      Ordering_()(MatrixType(a.template selfadjointView<Eigen::Lower>()), order);
    std::vector<int> old_of_new(std::size_t(a.rows()));
    for(Eigen::Index k = 0; k < a.rows(); ++k)
      old_of_new[std::size_t(k)] = int(order.indices()[k]);
    m_analysis = internal::supernodal_analysis(a, std::move(old_of_new));
    m_info = Eigen::Success;
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
  Eigen::Matrix<RealScalar, Eigen::Dynamic, 1> vectorD() const { return m_factor.pivots(); }

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
  static std::size_t lower_entries(const MatrixType& a)
  {
    std::size_t count = 0;
    internal::supernodal_detail::for_each_lower_entry(a, [&](int, int, const Scalar&) { ++count; });
    return count;
  }

  std::shared_ptr<const Analysis> m_analysis;
  internal::Supernodal_factor<Scalar> m_factor;
  Eigen::ComputationInfo m_info = Eigen::InvalidInput;
};

/// \ingroup PkgSurfaceDesignRef
/// `Supernodal_cholesky` with the library's nested dissection behind `CGAL::Eigen_solver_traits`:
/// a model of `SparseLinearAlgebraWithFactorTraits_d` for symmetric positive definite systems;
/// Hermitian systems (the smoothest direction fields) are factored in complex arithmetic. The
/// fastest first solve of the library's solvers from about 20k unknowns on: about 2 times faster
/// than `Default_solver_traits` at 30k unknowns, 3 to 4 times at 119k, 8 to 10 times at 477k (below 20k, AMD
/// with the simplicial factorization is as fast or faster; see the foundation manual, section
/// Solvers).
using Supernodal_solver_traits =
  CGAL::Eigen_solver_traits<Supernodal_cholesky<CGAL::Eigen_sparse_matrix<double>::EigenType>>;

namespace internal {

template <>
struct Complex_solver_of<Supernodal_solver_traits>
{
  using type = Supernodal_cholesky<Complex_sparse_matrix>;
};

} // namespace internal

} // namespace Surface_design
} // namespace CGAL

#endif // CGAL_SURFACE_DESIGN_SUPERNODAL_CHOLESKY_H
