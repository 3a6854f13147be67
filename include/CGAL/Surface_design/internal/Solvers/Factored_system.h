// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Factor once, solve many times, through any model of SparseLinearAlgebraWithFactorTraits_d.

#ifndef CGAL_SURFACE_DESIGN_INTERNAL_SOLVERS_FACTORED_SYSTEM_H
#define CGAL_SURFACE_DESIGN_INTERNAL_SOLVERS_FACTORED_SYSTEM_H

#include <CGAL/Surface_design/exceptions.h>
#include <CGAL/Surface_design/internal/Solvers/solver_traits.h>

#include <CGAL/Eigen_matrix.h>
#include <CGAL/Eigen_vector.h>

#include <Eigen/Sparse>

#include <cmath>
#include <complex>
#include <limits>
#include <memory>
#include <sstream>
#include <string>
#include <type_traits>
#include <utility>

namespace CGAL {
namespace Surface_design {
namespace internal {

namespace factored_system_detail {

// Detects solver traits exposing an Eigen LDLT factorization (`solver().vectorD()`), whose pivots
// tell whether a matrix that must be positive definite really is.
template <class Traits, class = void>
struct Has_ldlt_pivots : std::false_type {};
template <class Traits>
struct Has_ldlt_pivots<Traits, std::void_t<decltype(std::declval<Traits&>().solver().vectorD())>>
  : std::true_type {};

} // namespace factored_system_detail

/// Throws `Linear_solver_failure` naming the system if an LDLT pivot (real part, for Hermitian
/// systems) is not safely positive.
template <class Pivots>
void check_ldlt_pivots(const Pivots& d, const std::string& name, Eigen::Index size, const char* unknowns)
{
  if(d.size() == 0)
    return;
  const double largest = d.cwiseAbs().maxCoeff();
  for(Eigen::Index i = 0; i < d.size(); ++i)
  {
    const double pivot = std::real(d[i]);
    if(!(pivot > ldlt_pivot_tolerance * largest))
    {
      std::ostringstream s;
      s << "the " << name << " (" << size << ' ' << unknowns << ") is not positive definite: LDLT pivot "
        << i << " is " << pivot << " (largest " << largest << ")"
        << (pivot > 0 ? "; the matrix is singular to working precision" : "");
      throw Linear_solver_failure(s.str());
    }
  }
}

// Detects solver traits exposing an Eigen sparse solver (`solver().solve(dense matrix)`).
template <class Traits, class = void>
struct Has_eigen_solver : std::false_type {};
template <class Traits>
struct Has_eigen_solver<Traits, std::void_t<decltype(Eigen::MatrixXd(std::declval<Traits&>().solver().solve(
                                   std::declval<const Eigen::MatrixXd&>())))>> : std::true_type {};

/// A sparse symmetric system factored once and solved for any number of right-hand sides.
///
/// `SolverTraits` is any model of CGAL's `SparseLinearAlgebraWithFactorTraits_d`
/// (`Eigen_solver_traits<SimplicialLDLT>` by default, `Eigen_solver_traits<CholmodSupernodalLLT>`,
/// ...). Copies of an `Eigen_solver_traits` share their factorization, so every Factored_system
/// must own its traits object: pass a fresh one.
///
/// The matrix is moved into the solver's own matrix type when that type is CGAL's
/// `Eigen_sparse_matrix` (no copy), else copied coefficient by coefficient.
template <class SolverTraits = Default_solver_traits>
class Factored_system
{
  using Matrix = typename SolverTraits::Matrix;
  using Vector = typename SolverTraits::Vector;

public:

  explicit Factored_system(SolverTraits traits = SolverTraits(), std::string name = "linear system")
    : m_traits(std::move(traits)), m_name(std::move(name))
  {}

  /// Factors `a` (square, symmetric; the solvers read its lower triangle).
  /// \throws Linear_solver_failure if the factorization fails or, when `positive_definite` is
  /// true and the solver exposes LDLT pivots, if a pivot is not safely positive.
  void factor(Eigen::SparseMatrix<double>&& a, bool positive_definite = true)
  {
    m_factored = false;
    m_size = a.rows();
    if(a.rows() != a.cols() || a.rows() == 0)
      throw Linear_solver_failure("the " + m_name + " is not a non-empty square matrix (" +
                                  std::to_string(a.rows()) + " x " + std::to_string(a.cols()) + ")");
    // the square constructor: CGAL 5.5's rectangular one reads a member before initializing it
    m_matrix = std::make_unique<Matrix>(int(a.rows()));
    if constexpr(std::is_base_of<CGAL::Eigen_sparse_matrix<double>, Matrix>::value)
    {
      m_matrix->eigen_object() = std::move(a);
    }
    else
    {
      for(int k = 0; k < a.outerSize(); ++k)
        for(Eigen::SparseMatrix<double>::InnerIterator it(a, k); it; ++it)
          m_matrix->set_coef(std::size_t(it.row()), std::size_t(it.col()), it.value(), true);
    }
    typename SolverTraits::NT denominator;
    if(!m_traits.factor(*m_matrix, denominator))
      throw Linear_solver_failure("the factorization of the " + m_name + " (" +
                                  std::to_string(m_size) + " unknowns) failed" +
                                  (positive_definite ? ": the matrix is not positive definite" : ""));
    if constexpr(factored_system_detail::Has_ldlt_pivots<SolverTraits>::value)
    {
      if(positive_definite)
        check_ldlt_pivots(m_traits.solver().vectorD(), m_name, m_size, "unknowns");
    }
    m_factored = true;
  }

  bool is_factored() const { return m_factored; }
  Eigen::Index size() const { return m_size; }
  SolverTraits& traits() { return m_traits; }

  /// Solves A x = b with the stored factorization.
  /// \throws Linear_solver_failure if the solver reports failure or returns non-finite values.
  void solve(const Eigen::VectorXd& b, Eigen::VectorXd& x)
  {
    if(!m_factored)
      throw Linear_solver_failure("the " + m_name + " was solved before being factored");
    Vector rhs(std::size_t(b.size())), sol(std::size_t(b.size()));
    if constexpr(std::is_base_of<Eigen::VectorXd, Vector>::value)
      static_cast<Eigen::VectorXd&>(rhs) = b;
    else
      for(Eigen::Index i = 0; i < b.size(); ++i)
        rhs[std::size_t(i)] = b[i];
    if(!m_traits.linear_solver(rhs, sol))
      throw Linear_solver_failure("the solve of the " + m_name + " failed");
    x.resize(b.size());
    for(Eigen::Index i = 0; i < b.size(); ++i)
      x[i] = sol[std::size_t(i)];
    if(!x.allFinite())
      throw Linear_solver_failure("the solve of the " + m_name +
                                  " produced non-finite values (singular or ill-conditioned matrix)");
  }

  Eigen::VectorXd solve(const Eigen::VectorXd& b)
  {
    Eigen::VectorXd x;
    solve(b, x);
    return x;
  }

  /// Solves A X = B for every column of B. Traits that expose an Eigen solver (`solver()`, as
  /// `CGAL::Eigen_solver_traits` does) solve all columns in one call, which lets a supernodal
  /// factorization read its factor once for all of them; others solve column by column. `b` and
  /// `x` may be one matrix (solved in place): every solver of the library reads all of B before it
  /// writes X (the supernodal one per half of the columns; Eigen's simplicial one permutes in place,
  /// CHOLMOD solves into its own buffer).
  /// \throws Linear_solver_failure as `solve()`
  void solve_many(const Eigen::MatrixXd& b, Eigen::MatrixXd& x)
  {
    if(!m_factored)
      throw Linear_solver_failure("the " + m_name + " was solved before being factored");
    if(b.rows() != m_size)
      throw Linear_solver_failure("the right-hand sides of the " + m_name + " have " + std::to_string(b.rows()) +
                                  " rows, not " + std::to_string(m_size));
    if constexpr(Has_eigen_solver<SolverTraits>::value)
    {
      x = m_traits.solver().solve(b);
      if(m_traits.solver().info() != Eigen::Success)
        throw Linear_solver_failure("the solve of the " + m_name + " failed");
      if(!x.allFinite())
        throw Linear_solver_failure("the solve of the " + m_name +
                                    " produced non-finite values (singular or ill-conditioned matrix)");
    }
    else
    {
      x.resize(b.rows(), b.cols());
      Eigen::VectorXd column;
      for(Eigen::Index k = 0; k < b.cols(); ++k)
      {
        solve(Eigen::VectorXd(b.col(k)), column);
        x.col(k) = column;
      }
    }
  }

private:
  SolverTraits m_traits;
  std::unique_ptr<Matrix> m_matrix; // the traits keep a pointer to it: its address must not change
  std::string m_name;
  Eigen::Index m_size = 0;
  bool m_factored = false;
};

/// Solves A x = b for the values of x at `free` (indices, each once), those elsewhere given: A's
/// block of the free rows and columns factored (a fresh `SolverTraits`), the given values' terms
/// moved to the right-hand side. A is symmetric and stored whole; the block must be definite.
/// \throws Linear_solver_failure as `Factored_system::factor()` and `solve()`
template <class SolverTraits>
void solve_on_subset(const Eigen::SparseMatrix<double>& a, const Eigen::VectorXd& b, Eigen::VectorXd& x,
                 const std::vector<Eigen::Index>& free, const std::string& name)
{
  if(free.empty())
    return;
  std::vector<Eigen::Index> local(std::size_t(a.rows()), -1);
  for(std::size_t k = 0; k < free.size(); ++k)
    local[std::size_t(free[k])] = Eigen::Index(k);
  const Eigen::Index n = Eigen::Index(free.size());
  Eigen::VectorXd r(n);
  std::vector<Eigen::Triplet<double>> entries;
  for(Eigen::Index k = 0; k < n; ++k)
  {
    r[k] = b[free[std::size_t(k)]];
    for(Eigen::SparseMatrix<double>::InnerIterator it(a, free[std::size_t(k)]); it; ++it) // (column = row)
    {
      const Eigen::Index row = local[std::size_t(it.row())];
      if(row >= 0)
        entries.emplace_back(row, k, it.value());
      else
        r[k] -= it.value() * x[it.row()];
    }
  }
  Eigen::SparseMatrix<double> block(n, n);
  block.setFromTriplets(entries.begin(), entries.end());
  Factored_system<SolverTraits> system(SolverTraits(), name);
  system.factor(std::move(block));
  const Eigen::VectorXd solved = system.solve(r);
  for(Eigen::Index k = 0; k < n; ++k)
    x[free[std::size_t(k)]] = solved[k];
}

} // namespace internal
} // namespace Surface_design
} // namespace CGAL

#endif // CGAL_SURFACE_DESIGN_INTERNAL_SOLVERS_FACTORED_SYSTEM_H
