// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The sparse solvers the library is tested with, as models of CGAL's
// `SparseLinearAlgebraWithFactorTraits_d` concept (public types, made public by
// `CGAL/Surface_design/solver_traits.h` and `nested_dissection_ordering.h`), and how the library
// makes a new solver of a given type.

#ifndef CGAL_SURFACE_DESIGN_INTERNAL_SOLVERS_SOLVER_TRAITS_H
#define CGAL_SURFACE_DESIGN_INTERNAL_SOLVERS_SOLVER_TRAITS_H

#include <CGAL/Surface_design/exceptions.h>
#include <CGAL/Surface_design/internal/Solvers/Supernodal_cholesky.h>

#include <CGAL/Eigen_solver_traits.h>
#include <CGAL/Eigen_matrix.h>

#include <Eigen/SparseCholesky>
#include <Eigen/SparseLU>

#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>

#if defined(CGAL_SURFACE_DESIGN_HAS_CHOLMOD)
#include <Eigen/CholmodSupport>
#endif

#if defined(CGAL_SURFACE_DESIGN_HAS_METIS)
#include <Eigen/MetisSupport>
#endif

namespace CGAL {
namespace Surface_design {

/// \ingroup PkgSurfaceDesignRef
/// Eigen's `SimplicialLDLT` with its AMD fill-reducing ordering behind `CGAL::Eigen_solver_traits`:
/// about as fast as the default on small systems (1k vertices), slower from a few thousand
/// unknowns on. Header-only, single-threaded; its LDLT pivots tell whether a system that must be
/// positive definite is.
using Simplicial_ldlt_solver_traits =
  CGAL::Eigen_solver_traits<Eigen::SimplicialLDLT<CGAL::Eigen_sparse_matrix<double>::EigenType>>;

/// \ingroup PkgSurfaceDesignRef
/// A Cholesky factorization of a sparse symmetric (real) or Hermitian (complex) positive definite
/// matrix: the library's `Supernodal_cholesky`, ordered by the fill-reducing ordering that suits
/// the size of each system on the library's (mesh) systems: AMD (Eigen's approximate minimum
/// degree) below `size_threshold()` unknowns (20000 by default), the library's nested dissection
/// from there on. It reads the lower triangle and exposes its pivots |L_jj|^2 (`vectorD()`, those
/// of an LDL^T factorization with the same order), so positive definiteness is checked as for
/// `SimplicialLDLT`. An Eigen sparse solver (`analyzePattern`, `factorize`, `compute`, `info`,
/// `solve`).
///
/// Why: AMD orders small systems cheaply and well; nested dissection costs more to compute but
/// makes fewer flops on large ones, and its advantage grows with the size. The supernodal
/// factorization does its work in dense kernels and its back-substitution runs the independent
/// subtrees concurrently; against Eigen's `SimplicialLDLT` with the same AMD ordering it is about
/// as fast on 1k-vertex meshes and faster from a few thousand unknowns on, most for complex systems
/// (whose simplicial loops multiply through the checked operators of `std::complex`) and for systems
/// with 2x2 blocks. Measured on the kitten (11k vertices), factorization and solve: Laplacian 12.7
/// and 0.40 ms by `SimplicialLDLT`, 9.9 and 0.32 ms supernodal; smoothest line field's connection
/// Laplacian (complex) 26.0 and 0.99 ms against 19.3 and 0.49 ms (figures in the foundation
/// manual, section "Sparse solvers and optimizers", and the benchmark).
///
/// \tparam MatrixType_ `Eigen::SparseMatrix<Scalar>` (column-major), `Scalar` = `double` or
///         `std::complex<double>`
template <class MatrixType_>
class Size_switched_cholesky : public Eigen::SparseSolverBase<Size_switched_cholesky<MatrixType_>>
{
  using Base = Eigen::SparseSolverBase<Size_switched_cholesky<MatrixType_>>;

public:
  using MatrixType = MatrixType_;
  using Scalar = typename MatrixType::Scalar;
  using RealScalar = typename Eigen::NumTraits<Scalar>::Real;
  using StorageIndex = typename MatrixType::StorageIndex;
  using Small = Supernodal_cholesky<MatrixType, Eigen::AMDOrdering<StorageIndex>>;
  using Large = Supernodal_cholesky<MatrixType>;
  enum { ColsAtCompileTime = Eigen::Dynamic, MaxColsAtCompileTime = Eigen::Dynamic };

  /// Systems of at least this many unknowns are ordered by nested dissection by default.
  static constexpr Eigen::Index default_size_threshold = 20000;

  Size_switched_cholesky() = default;

  /// Systems of at least `n` unknowns (n >= 0) are ordered by nested dissection, smaller ones by
  /// AMD: 0 always chooses nested dissection. Takes effect at the next `analyzePattern()` or
  /// `compute()`.
  /// \throws Invalid_parameter if `n` is negative
  void set_size_threshold(Eigen::Index n)
  {
    if(n < 0)
      throw Invalid_parameter("size_threshold", "Size_switched_cholesky's size threshold must be >= 0, got " +
                                                  std::to_string(n));
    m_threshold = n;
  }
  Eigen::Index size_threshold() const { return m_threshold; }

  /// Whether the last analysed system was at or above the size threshold (ordered by nested
  /// dissection).
  bool uses_supernodal() const { return m_large_system; }

  /// The factorization takes its analyses from (and adds them to) `cache` from the next
  /// `analyzePattern()` or `compute()` on; null: none. Systems with the same pattern on one mesh
  /// are then ordered and analysed once (see `Symbolic_analysis_cache`), whatever their size.
  void set_analysis_cache(std::shared_ptr<Symbolic_analysis_cache> cache)
  {
    m_cache = std::move(cache);
    if(m_small)
      m_small->set_analysis_cache(m_cache);
    if(m_large)
      m_large->set_analysis_cache(m_cache);
  }
  const std::shared_ptr<Symbolic_analysis_cache>& analysis_cache() const { return m_cache; }

  /// Takes the size threshold and the analysis cache of another `Size_switched_cholesky` (of any
  /// scalar type): a Hermitian system factored for solver traits follows the traits' settings.
  template <class OtherMatrix>
  void use_settings_of(const Size_switched_cholesky<OtherMatrix>& other)
  {
    set_size_threshold(other.size_threshold());
    set_analysis_cache(other.analysis_cache());
  }

  void analyzePattern(const MatrixType& a)
  {
    choose(a);
    visit([&a](auto& solver) { solver.analyzePattern(a); });
    m_isInitialized = false;
  }

  /// Factors `a`, whose pattern must be that of the analysed matrix.
  void factorize(const MatrixType& a)
  {
    visit([&a](auto& solver) { solver.factorize(a); });
    m_isInitialized = info() == Eigen::Success;
  }

  Size_switched_cholesky& compute(const MatrixType& a)
  {
    choose(a);
    visit([&a](auto& solver) { solver.compute(a); });
    m_isInitialized = info() == Eigen::Success;
    return *this;
  }

  /// `InvalidInput` before any `analyzePattern()` or `compute()`.
  Eigen::ComputationInfo info() const
  {
    return visit([](const auto& solver) { return solver.info(); }, Eigen::InvalidInput);
  }
  Eigen::Index rows() const
  {
    return visit([](const auto& solver) { return solver.rows(); }, Eigen::Index(0));
  }
  Eigen::Index cols() const { return rows(); }

  /// The pivots |L_jj|^2 of the factorization, in the original order of the unknowns; empty
  /// before a successful factorization.
  Eigen::Matrix<RealScalar, Eigen::Dynamic, 1> vectorD() const
  {
    return visit([](const auto& solver) { return solver.vectorD(); }, Eigen::Matrix<RealScalar, Eigen::Dynamic, 1>());
  }

  /// \cond SKIP_IN_MANUAL
  template <class Rhs, class Dest>
  void _solve_impl(const Eigen::MatrixBase<Rhs>& b, Eigen::MatrixBase<Dest>& x) const
  {
    visit([&](const auto& solver) { solver._solve_impl(b, x); });
  }
  using Base::_solve_impl;
  /// \endcond

private:
  using Base::m_isInitialized;

  // Picks the ordering for `a` and releases the other factorization.
  void choose(const MatrixType& a)
  {
    m_large_system = a.rows() >= m_threshold;
    if(m_large_system)
    {
      m_small.reset();
      if(!m_large)
      {
        m_large.emplace();
        m_large->set_analysis_cache(m_cache);
      }
    }
    else
    {
      m_large.reset();
      if(!m_small)
      {
        m_small.emplace();
        m_small->set_analysis_cache(m_cache);
      }
    }
  }

  // f(the factorization in use); `none` when there is none yet (f must then return a value)
  template <class F>
  void visit(const F& f)
  {
    if(m_large_system && m_large)
      f(*m_large);
    else if(!m_large_system && m_small)
      f(*m_small);
  }
  template <class F>
  void visit(const F& f) const
  {
    if(m_large_system && m_large)
      f(*m_large);
    else if(!m_large_system && m_small)
      f(*m_small);
  }
  template <class F, class R>
  R visit(const F& f, R none) const
  {
    if(m_large_system && m_large)
      return f(*m_large);
    if(!m_large_system && m_small)
      return f(*m_small);
    return none;
  }

  std::optional<Small> m_small;
  std::optional<Large> m_large;
  std::shared_ptr<Symbolic_analysis_cache> m_cache;
  Eigen::Index m_threshold = default_size_threshold;
  bool m_large_system = false;
};

/// \ingroup PkgSurfaceDesignRef
/// Default solver of every algorithm: `Size_switched_cholesky` behind `CGAL::Eigen_solver_traits`,
/// i.e. the library's supernodal Cholesky, ordered by AMD below 20k unknowns and by its nested
/// dissection from 20k on (`Supernodal_solver_traits` always orders by nested dissection).
/// Header-only, no dependency beyond Eigen (TBB, when CGAL is linked with it, runs independent
/// parts of the factorization and of each back-substitution concurrently). Change the threshold
/// with `traits.solver().set_size_threshold(n)`.
using Default_solver_traits =
  CGAL::Eigen_solver_traits<Size_switched_cholesky<CGAL::Eigen_sparse_matrix<double>::EigenType>>;

namespace internal {

template <class SolverTraits, class = void>
struct Has_solver_settings : std::false_type {};
template <class SolverTraits>
struct Has_solver_settings<SolverTraits, std::void_t<decltype(std::declval<SolverTraits&>().solver().use_settings_of(
                                           std::declval<SolverTraits&>().solver()))>> : std::true_type {};

/// A new traits object of the type of `traits`, for another system: copies of CGAL's Eigen traits
/// share their factorization, so every system needs its own object. It takes the settings of
/// `traits`' solver (size threshold, analysis cache) when the solver has them (the library's own).
template <class SolverTraits>
SolverTraits new_solver_like(SolverTraits& traits)
{
  SolverTraits fresh;
  if constexpr(Has_solver_settings<SolverTraits>::value)
    fresh.solver().use_settings_of(traits.solver());
  (void)traits;
  return fresh;
}

} // namespace internal

#if defined(CGAL_SURFACE_DESIGN_HAS_CHOLMOD) || defined(DOXYGEN_RUNNING)
/// \ingroup PkgSurfaceDesignRef
/// Eigen's `CholmodSupernodalLLT` with CHOLMOD's fill-reducing ordering fixed to AMD. CHOLMOD's
/// default tries AMD and then, when AMD's fill looks high (it always does on mesh Laplacians),
/// METIS too, keeping the better. On mesh Laplacians that double analysis costs more than the
/// factorization it improves, so AMD alone gives the smaller total (analysis and factorization)
/// for the factor-once, solve-many use of the library (figures in the foundation manual).
template <class MatrixType>
class Cholmod_amd_supernodal_llt : public Eigen::CholmodSupernodalLLT<MatrixType>
{
public:
  Cholmod_amd_supernodal_llt()
  {
    this->cholmod().nmethods = 1;
    this->cholmod().method[0].ordering = CHOLMOD_AMD;
  }
};

/// \ingroup PkgSurfaceDesignRef
/// SuiteSparse CHOLMOD's supernodal Cholesky factorization (AMD ordering, see
/// `Cholmod_amd_supernodal_llt`) behind `CGAL::Eigen_solver_traits`. Defined when the library was
/// configured with CHOLMOD (macro `CGAL_SURFACE_DESIGN_HAS_CHOLMOD`, set by the CMake target). Its
/// supernodal kernels call BLAS: with an optimized BLAS (Debian: `libopenblas-dev`) the
/// factorization of large Laplacians is several times faster than with the reference BLAS.
using Cholmod_solver_traits =
  CGAL::Eigen_solver_traits<Cholmod_amd_supernodal_llt<CGAL::Eigen_sparse_matrix<double>::EigenType>>;

/// \ingroup PkgSurfaceDesignRef
/// Eigen's `CholmodSupernodalLLT` with the library's `Nested_dissection_ordering` given to CHOLMOD
/// (`cholmod_analyze_p`, ordering `CHOLMOD_GIVEN`, postordered by CHOLMOD) instead of its own
/// orderings: CHOLMOD's supernodal factorization with the fill of the nested dissection, for a
/// comparison with `Supernodal_cholesky` on the same ordering or where CHOLMOD's BLAS kernels are
/// wanted. Real or complex (`std::complex<double>`) matrices, lower triangle read.
template <class MatrixType>
class Cholmod_nested_dissection_llt : public Eigen::CholmodSupernodalLLT<MatrixType>
{
  using StorageIndex = typename MatrixType::StorageIndex;

public:
  Cholmod_nested_dissection_llt()
  {
    this->cholmod().nmethods = 1;
    this->cholmod().method[0].ordering = CHOLMOD_GIVEN;
  }

  /// Orders the pattern by nested dissection and analyses it with that order.
  void analyzePattern(const MatrixType& a)
  {
    if(this->m_cholmodFactor)
    {
      Eigen::internal::cm_free_factor<StorageIndex>(this->m_cholmodFactor, this->cholmod());
      this->m_cholmodFactor = nullptr;
    }
    typename internal::Nested_dissection_ordering<StorageIndex>::PermutationType order;
    internal::Nested_dissection_ordering<StorageIndex>()(a, order);
    cholmod_sparse view = Eigen::viewAsCholmod(a.template selfadjointView<Eigen::Lower>());
    if constexpr(std::is_same<StorageIndex, SuiteSparse_long>::value)
      this->m_cholmodFactor = cholmod_l_analyze_p(&view, order.indices().data(), nullptr, 0, &this->cholmod());
    else
      this->m_cholmodFactor = cholmod_analyze_p(&view, order.indices().data(), nullptr, 0, &this->cholmod());
    this->m_isInitialized = true;
    this->m_info = this->m_cholmodFactor ? Eigen::Success : Eigen::InvalidInput;
    this->m_analysisIsOk = this->m_cholmodFactor != nullptr;
    this->m_factorizationIsOk = false;
  }

  /// `analyzePattern()` then `factorize()`.
  Cholmod_nested_dissection_llt& compute(const MatrixType& a)
  {
    analyzePattern(a);
    if(this->m_analysisIsOk)
      this->factorize(a);
    return *this;
  }

  /// The ordering CHOLMOD recorded in its factor (`CHOLMOD_GIVEN` once analysed), -1 before.
  int ordering_used() const { return this->m_cholmodFactor ? this->m_cholmodFactor->ordering : -1; }
};

/// \ingroup PkgSurfaceDesignRef
/// `Cholmod_nested_dissection_llt` behind `CGAL::Eigen_solver_traits`; defined with CHOLMOD as
/// `Cholmod_solver_traits`. On the library's mesh systems `Supernodal_solver_traits` (the same
/// ordering, the library's own supernodal factorization) was faster at every size measured (the
/// foundation manual, section "Sparse solvers and optimizers"), so this one is for comparisons.
using Cholmod_nested_dissection_solver_traits =
  CGAL::Eigen_solver_traits<Cholmod_nested_dissection_llt<CGAL::Eigen_sparse_matrix<double>::EigenType>>;
#endif

#if defined(CGAL_SURFACE_DESIGN_HAS_METIS) || defined(DOXYGEN_RUNNING)
/// \ingroup PkgSurfaceDesignRef
/// Eigen's `SimplicialLDLT` as in `Simplicial_ldlt_solver_traits`, but with the nested-dissection
/// fill-reducing ordering of METIS (`METIS_NodeND`) instead of AMD. Nested dissection targets the
/// fill-in of large 2D-like graphs such as mesh Laplacians, where AMD's fill grows faster; the
/// factorization itself stays simplicial, single-threaded and BLAS-free. Its LDLT pivots are
/// exposed as for the default, so `Factored_system` checks positive definiteness the same way.
/// Defined when the library was configured with METIS (macro `CGAL_SURFACE_DESIGN_HAS_METIS`, set
/// by the CMake target; Debian: `libmetis-dev`) built with 32-bit indices (`IDXTYPEWIDTH` 32, the
/// default): Eigen's `MetisOrdering<int>` passes `int` arrays to METIS.
using Metis_ldlt_solver_traits =
  CGAL::Eigen_solver_traits<Eigen::SimplicialLDLT<CGAL::Eigen_sparse_matrix<double>::EigenType,
                                                  Eigen::Lower, Eigen::MetisOrdering<int>>>;
#endif

/// \ingroup PkgSurfaceDesignRef
/// Eigen's `SimplicialLDLT` (as `Simplicial_ldlt_solver_traits`) with `Nested_dissection_ordering`
/// instead of AMD, behind `CGAL::Eigen_solver_traits`: header-only, single-threaded, BLAS-free;
/// faster than AMD for meshes of more than about 30k vertices, slower than `Supernodal_solver_traits`
/// (which the default uses there). Its LDLT pivots are exposed, so positive definiteness is checked
/// the same way; Hermitian systems factor with the same ordering in complex arithmetic.
using Nested_dissection_ldlt_solver_traits =
  CGAL::Eigen_solver_traits<Eigen::SimplicialLDLT<CGAL::Eigen_sparse_matrix<double>::EigenType, Eigen::Lower,
                                                  Nested_dissection_ordering<int>>>;

/// \ingroup PkgSurfaceDesignRef
/// Eigen's sparse LU factorization (`SparseLU`, COLAMD ordering) behind `CGAL::Eigen_solver_traits`:
/// for the systems of the library that are not symmetric (e.g. barycentric embeddings with
/// mean-value weights). Header-only, like the default.
using Sparse_lu_solver_traits =
  CGAL::Eigen_solver_traits<Eigen::SparseLU<CGAL::Eigen_sparse_matrix<double>::EigenType,
                                            Eigen::COLAMDOrdering<int>>>;

} // namespace Surface_design
} // namespace CGAL

#endif // CGAL_SURFACE_DESIGN_INTERNAL_SOLVERS_SOLVER_TRAITS_H
