// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Workload `factorization`: the first solve split into its phases (ordering, symbolic analysis,
// numeric factorization, solve) for each fill-reducing ordering and factorization kernel, on the
// regularized cotangent Laplacian of workload `laplacian`, with the fill and flops of each order.

#ifndef CGAL_SURFACE_DESIGN_BENCHMARK_WORKLOAD_FACTORIZATION_H
#define CGAL_SURFACE_DESIGN_BENCHMARK_WORKLOAD_FACTORIZATION_H

#include "harness.h"
#include "workload_laplacian.h"

#include <CGAL/Surface_design/nested_dissection_ordering.h>
#include <CGAL/Surface_design/supernodal_cholesky.h>

#include <Eigen/OrderingMethods>
#include <Eigen/SparseCholesky>
#if defined(CGAL_SURFACE_DESIGN_HAS_METIS)
#include <Eigen/MetisSupport>
#endif
#if defined(CGAL_SURFACE_DESIGN_HAS_CHOLMOD)
#include <cholmod.h>
#endif

#include <algorithm>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>

namespace benchmark {

namespace factorization_detail {

namespace SDI = CGAL::Surface_design::internal;
using Permutation = Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int>;

/// Hands a precomputed order to Eigen's simplicial factorization, so that the ordering is timed
/// apart from the symbolic analysis.
struct Given_ordering
{
  using PermutationType = Permutation;
  static const Permutation*& order()
  {
    static const Permutation* p = nullptr;
    return p;
  }
  template <class Matrix>
  void operator()(const Matrix&, Permutation& p) const { p = *order(); }
};

/// The fill-reducing order of the symmetric matrix `a` for the solver name: AMD for "ldlt" and
/// "default" below its size threshold (Eigen's), METIS for "ldlt-metis", the library's nested dissection for
/// "ldlt-nd", "supernodal" and "cholmod".
inline Permutation ordering(const std::string& solver, const SDI::Sparse_matrix& a)
{
  Permutation p;
  if(solver == "ldlt" || solver == "default")
    Eigen::AMDOrdering<int>()(a, p);
#if defined(CGAL_SURFACE_DESIGN_HAS_METIS)
  else if(solver == "ldlt-metis")
    Eigen::MetisOrdering<int>()(a, p);
#endif
  else
    CGAL::Surface_design::Nested_dissection_ordering<int>()(a, p);
  return p;
}

/// Counts of the factor of a column-compressed L: nonzeros and sum of squared column counts
/// (the multiply-adds of a column Cholesky).
template <class Factor>
void report_fill(const Factor& l, Run& run)
{
  double nonzeros = 0., flops = 0.;
  for(Eigen::Index j = 0; j < l.outerSize(); ++j)
  {
    const double c = double(l.outerIndexPtr()[j + 1] - l.outerIndexPtr()[j]);
    nonzeros += c;
    flops += c * c;
  }
  run.check("nnz(L), strictly lower", nonzeros, 1e300);
  run.check("factor multiply-adds sum_j nnz(L_j)^2", flops, 1e300);
}

inline void run_eigen(const std::string& solver, const SDI::Sparse_matrix& a, const Eigen::VectorXd& b, Run& run)
{
  Permutation p;
  run.phase("ordering", [&] { p = ordering(solver, a); });
  Given_ordering::order() = &p;
  Eigen::SimplicialLDLT<SDI::Sparse_matrix, Eigen::Lower, Given_ordering> ldlt;
  run.phase("symbolic", [&] { ldlt.analyzePattern(a); });
  run.phase("numeric", [&] { ldlt.factorize(a); });
  if(ldlt.info() != Eigen::Success)
    throw std::runtime_error("the LDLT factorization failed");
  Eigen::VectorXd x;
  run.phase("solve", [&] { x = ldlt.solve(b); });
  run.sum_phase("first solve", {"ordering", "symbolic", "numeric", "solve"});
  if(run.checks_enabled())
  {
    report_fill(ldlt.matrixL().nestedExpression(), run);
    run.check("relative residual |Ax-b|/|b|", (a * x - b).norm() / b.norm(), laplacian_detail::residual_bound);
  }
}

/// The library's supernodal Cholesky in its phases: the nested dissection of the lower triangle
/// (as `Supernodal_cholesky` orders), the symbolic analysis (postorder, supernodes, structures,
/// entry map), the numeric factorization, one solve.
inline void run_supernodal(const SDI::Sparse_matrix& a, const Eigen::VectorXd& b, bool amd, Run& run)
{
  const SDI::Sparse_matrix lower = a.triangularView<Eigen::Lower>();
  Permutation p;
  run.phase("ordering", [&] {
    if(amd)
      Eigen::AMDOrdering<int>()(a, p);
    else
      CGAL::Surface_design::Nested_dissection_ordering<int>()(lower, p);
  });
  std::shared_ptr<const SDI::Supernodal_symbolic> symbolic;
  run.phase("symbolic", [&] {
    symbolic = SDI::supernodal_analysis(lower, std::vector<int>(p.indices().data(), p.indices().data() + p.size()));
  });
  SDI::Supernodal_factor<double> factor;
  Eigen::Index failed = 0;
  run.phase("numeric", [&] { failed = factor.factorize(symbolic, lower); });
  if(failed != -1)
    throw std::runtime_error("the supernodal factorization failed at column " + std::to_string(failed));
  Eigen::VectorXd x;
  run.phase("solve", [&] { factor.solve(b, x); });
  run.sum_phase("first solve", {"ordering", "symbolic", "numeric", "solve"});
  if(run.checks_enabled())
  {
    run.check("nnz(L), strictly lower (explicit zeros of supernodes included)", symbolic->factor_nonzeros, 1e300);
    run.check("factor multiply-adds sum_j nnz(L_j)^2", symbolic->factor_flops, 1e300);
    run.check("supernodes", double(symbolic->supernode_count()), 1e300);
    run.check("relative residual |Ax-b|/|b|", (a * x - b).norm() / b.norm(), laplacian_detail::residual_bound);
  }
}

#if defined(CGAL_SURFACE_DESIGN_HAS_CHOLMOD)
/// CHOLMOD's supernodal LL^T with the library's nested-dissection order given
/// (`cholmod_analyze_p`, ordering CHOLMOD_GIVEN), through its C interface.
inline void run_cholmod(const SDI::Sparse_matrix& a, const Eigen::VectorXd& b, Run& run)
{
  Permutation p;
  run.phase("ordering", [&] { p = ordering("cholmod", a); });
  SDI::Sparse_matrix lower = a.triangularView<Eigen::Lower>();
  cholmod_common common;
  cholmod_start(&common);
  std::unique_ptr<cholmod_common, void (*)(cholmod_common*)> finish(&common, [](cholmod_common* c) { cholmod_finish(c); });
  common.nmethods = 1;
  common.method[0].ordering = CHOLMOD_GIVEN;
  common.supernodal = CHOLMOD_SUPERNODAL;
  cholmod_sparse view{};
  view.nrow = view.ncol = std::size_t(a.rows());
  view.nzmax = std::size_t(lower.nonZeros());
  view.p = lower.outerIndexPtr();
  view.i = lower.innerIndexPtr();
  view.x = lower.valuePtr();
  view.stype = -1;
  view.itype = CHOLMOD_INT;
  view.xtype = CHOLMOD_REAL;
  view.dtype = CHOLMOD_DOUBLE;
  view.sorted = 1;
  view.packed = 1;
  cholmod_factor* factor = nullptr;
  run.phase("symbolic", [&] { factor = cholmod_analyze_p(&view, p.indices().data(), nullptr, 0, &common); });
  run.phase("numeric", [&] { cholmod_factorize(&view, factor, &common); });
  const bool ok = common.status == CHOLMOD_OK;
  Eigen::VectorXd x(b.size());
  if(ok)
  {
    cholmod_dense rhs{};
    rhs.nrow = std::size_t(b.size());
    rhs.ncol = 1;
    rhs.nzmax = std::size_t(b.size());
    rhs.d = std::size_t(b.size());
    rhs.x = const_cast<double*>(b.data());
    rhs.xtype = CHOLMOD_REAL;
    rhs.dtype = CHOLMOD_DOUBLE;
    run.phase("solve", [&] {
      cholmod_dense* solution = cholmod_solve(CHOLMOD_A, factor, &rhs, &common);
      if(solution == nullptr)
      {
        x.setConstant(std::numeric_limits<double>::quiet_NaN()); // the residual check reports it
        return;
      }
      std::copy(static_cast<double*>(solution->x), static_cast<double*>(solution->x) + b.size(), x.data());
      cholmod_free_dense(&solution, &common);
    });
    run.sum_phase("first solve", {"ordering", "symbolic", "numeric", "solve"});
    if(run.checks_enabled())
    {
      run.check("nnz(L), strictly lower", common.lnz - double(a.rows()), 1e300);
      run.check("factor multiply-adds (CHOLMOD's flop count)", common.fl, 1e300);
      run.check("relative residual |Ax-b|/|b|", (a * x - b).norm() / b.norm(), laplacian_detail::residual_bound);
    }
  }
  cholmod_free_factor(&factor, &common);
  if(!ok)
    throw std::runtime_error("the CHOLMOD factorization failed (status " + std::to_string(common.status) + ")");
}
#endif

} // namespace factorization_detail

/// Phases: `ordering` (AMD for `ldlt`, METIS for `ldlt-metis`, the library's nested dissection for
/// `ldlt-nd`, `supernodal` and `cholmod`), `symbolic` (Eigen's `analyzePattern` with that order,
/// the supernodal analysis or `cholmod_analyze_p`), `numeric` (`factorize`, the supernodal
/// factorization or `cholmod_factorize`), `solve`
/// (one right-hand side), `first solve` = their sum. Checks: fill and flops of the factor, the
/// relative residual. The system is that of workload `laplacian`, assembled untimed. `default`
/// runs as `supernodal` with the AMD ordering below `Size_switched_cholesky`'s size threshold and
/// as `supernodal` from there on.
inline void factorization_workload(const Mesh& mesh, const std::string& solver, Run& run)
{
  namespace SDI = CGAL::Surface_design::internal;
  const SDI::Mesh_indices<Mesh> idx(mesh);
  const SDI::Sparse_matrix a = laplacian_detail::regularized_laplacian(mesh, idx);
  const Eigen::VectorXd b = laplacian_detail::right_hand_side(idx);
#if defined(CGAL_SURFACE_DESIGN_HAS_CHOLMOD)
  if(solver == "cholmod")
  {
    factorization_detail::run_cholmod(a, b, run);
    return;
  }
#endif
  using Default_solver = CGAL::Surface_design::Default_solver_traits::Solver;
  if(solver == "supernodal" || solver == "default")
  {
    factorization_detail::run_supernodal(a, b, solver == "default" && a.rows() < Default_solver::default_size_threshold,
                                         run);
    return;
  }
  factorization_detail::run_eigen(solver, a, b, run);
}

} // namespace benchmark

#endif // CGAL_SURFACE_DESIGN_BENCHMARK_WORKLOAD_FACTORIZATION_H
