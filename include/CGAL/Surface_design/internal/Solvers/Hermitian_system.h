// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A sparse Hermitian positive definite system factored once and solved many times, through the
// user's `SolverTraits`: in complex arithmetic for the library's own traits, as the equivalent
// real symmetric system of twice the size for any other model of the concept.

#ifndef CGAL_SURFACE_DESIGN_INTERNAL_SOLVERS_HERMITIAN_SYSTEM_H
#define CGAL_SURFACE_DESIGN_INTERNAL_SOLVERS_HERMITIAN_SYSTEM_H

#include <CGAL/Surface_design/exceptions.h>
#include <CGAL/Surface_design/internal/Solvers/Factored_system.h>
#include <CGAL/Surface_design/internal/Solvers/solver_traits.h>
#include <CGAL/Surface_design/internal/Solvers/sparse_types.h>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <complex>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_design {
namespace internal {

/// The real symmetric form of a Hermitian matrix: entry p + iq of (i, j) becomes the block
/// [p -q; q p] at rows 2i, 2i+1 and columns 2j, 2j+1, so that a complex vector with (Re, Im)
/// interleaved is multiplied exactly as in complex arithmetic.
inline Sparse_matrix realify(const Complex_sparse_matrix& a)
{
  std::vector<Eigen::Triplet<double>> t;
  t.reserve(std::size_t(4 * a.nonZeros()));
  for(Eigen::Index k = 0; k < a.outerSize(); ++k)
    for(Complex_sparse_matrix::InnerIterator it(a, k); it; ++it)
    {
      const Eigen::Index i = 2 * it.row(), j = 2 * it.col();
      const double p = it.value().real(), q = it.value().imag();
      t.emplace_back(i, j, p);
      t.emplace_back(i + 1, j + 1, p);
      if(q != 0.)
      {
        t.emplace_back(i, j + 1, -q);
        t.emplace_back(i + 1, j, q);
      }
    }
  Sparse_matrix r(2 * a.rows(), 2 * a.cols());
  r.setFromTriplets(t.begin(), t.end());
  return r;
}

/// The complex Eigen solver with the same factorization as the library's solver traits
/// (`void` for any other traits: those go through the real form).
template <class SolverTraits>
struct Complex_solver_of
{
  using type = void;
};
template <>
struct Complex_solver_of<Default_solver_traits>
{
  using type = Size_switched_cholesky<Complex_sparse_matrix>;
};
template <>
struct Complex_solver_of<Simplicial_ldlt_solver_traits>
{
  using type = Eigen::SimplicialLDLT<Complex_sparse_matrix>;
};
template <>
struct Complex_solver_of<Supernodal_solver_traits>
{
  using type = Supernodal_cholesky<Complex_sparse_matrix>;
};
// with the same ordering in complex arithmetic, rather than in the real form of twice the size
template <>
struct Complex_solver_of<Nested_dissection_ldlt_solver_traits>
{
  using type = Eigen::SimplicialLDLT<Complex_sparse_matrix, Eigen::Lower, Nested_dissection_ordering<int>>;
};
#if defined(CGAL_SURFACE_DESIGN_HAS_CHOLMOD)
template <>
struct Complex_solver_of<Cholmod_solver_traits>
{
  using type = Cholmod_amd_supernodal_llt<Complex_sparse_matrix>;
};
template <>
struct Complex_solver_of<Cholmod_nested_dissection_solver_traits>
{
  using type = Cholmod_nested_dissection_llt<Complex_sparse_matrix>;
};
#endif
#if defined(CGAL_SURFACE_DESIGN_HAS_METIS)
template <>
struct Complex_solver_of<Metis_ldlt_solver_traits>
{
  using type = Eigen::SimplicialLDLT<Complex_sparse_matrix, Eigen::Lower, Eigen::MetisOrdering<int>>;
};
#endif

/// Factors a Hermitian positive definite matrix once (`factor`) and solves for any number of
/// right-hand sides (`solve`), vectors given with (Re, Im) interleaved. With the library's own
/// traits (`Default_solver_traits`, `Simplicial_ldlt_solver_traits`, `Supernodal_solver_traits`,
/// `Nested_dissection_ldlt_solver_traits`, `Cholmod_solver_traits`, `Cholmod_nested_dissection_solver_traits`,
/// `Metis_ldlt_solver_traits`) the
/// same factorization runs in complex arithmetic (half the floating-point operations of the real
/// form and a quarter of its index work); any other model of
/// `SparseLinearAlgebraWithFactorTraits_d` factors the real symmetric form (`realify`).
template <class SolverTraits>
class Hermitian_system
{
  // Eigen solvers that expose the pivots of their factorization (`vectorD()`)
  template <class Solver, class = void>
  struct Has_pivots : std::false_type {};
  template <class Solver>
  struct Has_pivots<Solver, std::void_t<decltype(std::declval<const Solver&>().vectorD())>> : std::true_type {};
  // the library's solvers take the settings (size threshold, analysis cache) of the traits' solver
  template <class Solver, class = void>
  struct Follows_traits : std::false_type {};
  template <class Solver>
  struct Follows_traits<Solver, std::void_t<decltype(std::declval<Solver&>().use_settings_of(
                                  std::declval<SolverTraits&>().solver()))>> : std::true_type {};

  using Complex_solver = typename Complex_solver_of<SolverTraits>::type;
  static constexpr bool complex_path = !std::is_void<Complex_solver>::value;
  using Complex_storage = std::conditional_t<complex_path, Complex_solver, int>;

public:
  Hermitian_system(SolverTraits traits, std::string name)
    : m_real(std::move(traits), name), m_name(std::move(name))
  {}

  static constexpr bool uses_complex_arithmetic() { return complex_path; }

  /// \throws Linear_solver_failure if the factorization fails or finds the matrix not positive definite
  void factor(Complex_sparse_matrix&& a)
  {
    if constexpr(complex_path)
    {
      m_size = a.rows();
      m_complex.emplace();
      if constexpr(Follows_traits<Complex_solver>::value)
        m_complex->use_settings_of(m_real.traits().solver());
      m_complex->compute(a);
      if(m_complex->info() != Eigen::Success)
        throw Linear_solver_failure("the factorization of the " + m_name + " (" + std::to_string(a.rows()) +
                                    " complex unknowns) failed: the matrix is not positive definite");
      if constexpr(Has_pivots<Complex_solver>::value)
        check_ldlt_pivots(m_complex->vectorD(), m_name, m_size, "complex unknowns");
    }
    else
    {
      m_size = a.rows();
      m_real.factor(realify(a), true);
    }
  }

  /// x = A^-1 b, both of size 2n with (Re, Im) interleaved.
  void solve(const Eigen::VectorXd& b, Eigen::VectorXd& x)
  {
    if constexpr(complex_path)
    {
      x.resize(b.size());
      Eigen::Map<const Eigen::VectorXcd> bc(reinterpret_cast<const std::complex<double>*>(b.data()), m_size);
      Eigen::Map<Eigen::VectorXcd> xc(reinterpret_cast<std::complex<double>*>(x.data()), m_size);
      xc = m_complex->solve(bc);
      if(!x.allFinite())
        throw Linear_solver_failure("the solve of the " + m_name + " produced non-finite values");
    }
    else
      m_real.solve(b, x);
  }

private:
  Factored_system<SolverTraits> m_real;
  std::optional<Complex_storage> m_complex;
  std::string m_name;
  Eigen::Index m_size = 0;
};

} // namespace internal
} // namespace Surface_design
} // namespace CGAL

#endif // CGAL_SURFACE_DESIGN_INTERNAL_SOLVERS_HERMITIAN_SYSTEM_H
