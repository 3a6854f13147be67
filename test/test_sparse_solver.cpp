// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Factor-once / solve-many through CGAL's solver traits: SimplicialLDLT and CHOLMOD agree,
// failures are reported clearly; the default solver switches from the simplicial to the
// supernodal factorization by size, with the same solutions, pivots and failures.

#include <sparse_test_matrices.h>
#include <test_support.h>

#include <CGAL/Surface_design/internal/Core/dec.h>
#include <CGAL/Surface_design/internal/Solvers/Factored_system.h>
#include <CGAL/Surface_design/internal/Solvers/sparse_types.h>
#include <CGAL/Surface_design/internal/Core/geometry.h>
#include <CGAL/Surface_design/internal/Core/Mesh_indices.h>
#include <CGAL/Surface_design/solver_traits.h>

#include <random>

namespace SD = CGAL::Surface_design;
namespace SDI = CGAL::Surface_design::internal;

namespace {

// screened cotangent-Laplace systems L + s M (SPD for s > 0), the typical systems of the library
using test::screened_laplacian;

Eigen::VectorXd random_vector(Eigen::Index n, unsigned seed)
{
  std::mt19937 rng(seed);
  std::normal_distribution<double> normal;
  Eigen::VectorXd b(n);
  for(Eigen::Index i = 0; i < n; ++i)
    b[i] = normal(rng);
  return b;
}

template <class Traits>
std::vector<Eigen::VectorXd> factor_and_solve(const SDI::Sparse_matrix& A,
                                              const std::vector<Eigen::VectorXd>& rhs)
{
  SDI::Factored_system<Traits> system(Traits(), "test system");
  system.factor(SDI::Sparse_matrix(A));
  REQUIRE(system.is_factored());
  std::vector<Eigen::VectorXd> x;
  for(const auto& b : rhs)
  {
    x.push_back(system.solve(b));
    // every solve is exact to working precision: residual relative to |A| |x|
    REQUIRE((A * x.back() - b).norm() <= 1e-10 * (A.norm() * x.back().norm()));
  }
  return x;
}

} // namespace

// the mesh data structure only feeds the matrix in these tests (the Laplacian's independence of it:
// test_geometry_dec)
TEST_CASE("Factor once, solve many: LDLT and CHOLMOD agree to 1e-10", "[solver]")
{
  for(const std::string name : {"bunny_1k.off", "triceratops.off", "mech-holes-shark.off"})
  {
    INFO(name);
    const test::Surface_mesh mesh = test::load_mesh<test::Surface_mesh>(name);
    const SDI::Sparse_matrix A = screened_laplacian(mesh, 1e-2);
    std::vector<Eigen::VectorXd> rhs;
    for(unsigned seed = 1; seed <= 4; ++seed)
      rhs.push_back(random_vector(A.rows(), seed));

    const auto ldlt = factor_and_solve<SD::Default_solver_traits>(A, rhs);
#if defined(CGAL_SURFACE_DESIGN_HAS_CHOLMOD)
    const auto cholmod = factor_and_solve<SD::Cholmod_solver_traits>(A, rhs);
    for(std::size_t k = 0; k < rhs.size(); ++k)
      REQUIRE((ldlt[k] - cholmod[k]).norm() <= 1e-10 * ldlt[k].norm());
#else
    SD_CHOLMOD_UNAVAILABLE("the cross-check of the two solvers");
#endif
  }
}

TEST_CASE("The factorization is reused: later solves do not refactor", "[solver]")
{
  const test::Surface_mesh mesh = test::load_mesh<test::Surface_mesh>("bunny_1k.off");
  const SDI::Sparse_matrix A = screened_laplacian(mesh, 1e-2);
  // counted, not inferred: one factorization, then every solve is a back-substitution only
  test::Counting_solver_traits counting;
  SDI::Factored_system<test::Counting_solver_traits> counted(counting);
  counted.factor(SDI::Sparse_matrix(A));
  const Eigen::VectorXd b = random_vector(A.rows(), 9);
  const Eigen::VectorXd y1 = counted.solve(b), y2 = counted.solve(2. * b);
  REQUIRE(counting.counts().factorizations == 1);
  REQUIRE(counting.counts().solves == 2);
  REQUIRE((y2 - 2. * y1).norm() <= 1e-12 * y2.norm());
  REQUIRE((A * y1 - b).norm() <= 1e-10 * b.norm());
  SDI::Factored_system<SD::Default_solver_traits> system;
  system.factor(SDI::Sparse_matrix(A));
  // the solver object holds the factor of A: solving with it twice gives identical results
  const Eigen::VectorXd x1 = system.solve(b), x2 = system.solve(b);
  REQUIRE((x1 - x2).norm() == 0.);
  // a copy of the system's traits shares the factorization (Eigen_solver_traits semantics)
  SD::Default_solver_traits copy = system.traits();
  REQUIRE(&copy.solver() == &system.traits().solver());
}

#if defined(CGAL_SURFACE_DESIGN_HAS_CHOLMOD)
#define SD_SOLVER_TYPES                                                                                               \
  SD::Default_solver_traits, SD::Simplicial_ldlt_solver_traits, SD::Supernodal_solver_traits, SD::Cholmod_solver_traits, \
    SD::Cholmod_nested_dissection_solver_traits
#else
#define SD_SOLVER_TYPES SD::Default_solver_traits, SD::Simplicial_ldlt_solver_traits, SD::Supernodal_solver_traits
#endif

TEMPLATE_TEST_CASE("Failures are reported as Linear_solver_failure", "[solver]", SD_SOLVER_TYPES)
{
  const test::Surface_mesh mesh = test::load_mesh<test::Surface_mesh>("bunny_1k.off");
  SECTION("indefinite matrix")
  {
    // L - s M has negative eigenvalues for s above the first non-zero eigenvalue of (L, M)
    const SDI::Sparse_matrix A = screened_laplacian(mesh, -1e3);
    SDI::Factored_system<TestType> system(TestType(), "indefinite test system");
    try
    {
      system.factor(SDI::Sparse_matrix(A));
      FAIL("no exception");
    }
    catch(const SD::Linear_solver_failure& e)
    {
      INFO(e.what());
      CHECK(std::string(e.what()).find("indefinite test system") != std::string::npos);
      CHECK(std::string(e.what()).find("positive definite") != std::string::npos);
    }
    CHECK_FALSE(system.is_factored());
    CHECK_THROWS_AS(system.solve(Eigen::VectorXd::Ones(A.rows())), SD::Linear_solver_failure);
  }
  SECTION("solve before factor")
  {
    SDI::Factored_system<TestType> system;
    CHECK_THROWS_AS(system.solve(Eigen::VectorXd::Ones(3)), SD::Linear_solver_failure);
  }
}

TEST_CASE("LDLT detects a singular Laplacian (no pinned vertex)", "[solver]")
{
  const test::Surface_mesh mesh = test::load_mesh<test::Surface_mesh>("bunny_1k.off");
  const SDI::Sparse_matrix L = screened_laplacian(mesh, 0.);
  for(const Eigen::Index threshold : {Eigen::Index(0), SD::Size_switched_cholesky<SDI::Sparse_matrix>::default_size_threshold})
  {
    INFO("size threshold " << threshold);
    SD::Default_solver_traits traits;
    traits.solver().set_size_threshold(threshold);
    SDI::Factored_system<SD::Default_solver_traits> system(traits, "Laplacian");
    CHECK_THROWS_AS(system.factor(SDI::Sparse_matrix(L)), SD::Linear_solver_failure);
    CHECK(traits.solver().uses_supernodal() == (threshold == 0));
    // pinning one vertex (Dirichlet row) makes it definite
    SDI::Sparse_matrix pinned = L;
    pinned.coeffRef(0, 0) += 1.;
    CHECK_NOTHROW(system.factor(std::move(pinned)));
  }
}

namespace {

// The default solver's two factorizations, forced by the size threshold: the simplicial LDLT with
// AMD and the supernodal Cholesky with nested dissection. Their orders differ, so their pivots do
// not match one by one, but their product is det A whatever the order.
template <class Matrix>
struct Both_factorizations
{
  SD::Size_switched_cholesky<Matrix> simplicial, supernodal;

  explicit Both_factorizations(const Matrix& a)
  {
    simplicial.set_size_threshold(a.rows() + 1);
    supernodal.set_size_threshold(0);
    simplicial.compute(a);
    supernodal.compute(a);
    REQUIRE(simplicial.info() == Eigen::Success);
    REQUIRE(supernodal.info() == Eigen::Success);
    REQUIRE_FALSE(simplicial.uses_supernodal());
    REQUIRE(supernodal.uses_supernodal());
  }
};

double log_determinant(const Eigen::VectorXd& pivots) { return pivots.array().log().sum(); }

} // namespace

TEST_CASE("Default solver: the simplicial and the supernodal factorization agree", "[solver]")
{
  for(const std::string name : {"bunny_8k.off", "mech-holes-shark.off", "blobby_3cc.off", "triceratops.off"})
  {
    INFO(name);
    const SDI::Sparse_matrix a = screened_laplacian(test::load_mesh<test::Surface_mesh>(name), 1e-2);
    Both_factorizations<SDI::Sparse_matrix> both(a);
    REQUIRE(both.simplicial.vectorD().size() == a.rows());
    REQUIRE(both.supernodal.vectorD().size() == a.rows());
    const double ld1 = log_determinant(both.simplicial.vectorD()), ld2 = log_determinant(both.supernodal.vectorD());
    REQUIRE(std::abs(ld1 - ld2) <= 1e-9 * (std::abs(ld1) + double(a.rows())));
    for(unsigned seed = 1; seed <= 3; ++seed)
    {
      const Eigen::VectorXd b = random_vector(a.rows(), seed);
      const Eigen::VectorXd x1 = both.simplicial.solve(b), x2 = both.supernodal.solve(b);
      REQUIRE((a * x2 - b).norm() <= 1e-10 * a.norm() * x2.norm());
      REQUIRE((x1 - x2).norm() <= 1e-10 * x1.norm());
    }
    // refactorization with the same pattern: analyse once, factor 2A, the solution halves
    const SDI::Sparse_matrix twice = 2. * a;
    both.supernodal.analyzePattern(a);
    both.supernodal.factorize(twice);
    REQUIRE(both.supernodal.info() == Eigen::Success);
    const Eigen::VectorXd b = random_vector(a.rows(), 4);
    const Eigen::VectorXd x = both.simplicial.solve(b);
    REQUIRE((2. * Eigen::VectorXd(both.supernodal.solve(b)) - x).norm() <= 1e-10 * x.norm());
  }
}

TEST_CASE("Default solver: the supernodal factorization from 20k unknowns on, by default", "[solver]")
{
  // 140^2 = 19600 and 142^2 = 20164 unknowns on either side of the default threshold
  for(const int k : {140, 142})
  {
    const SDI::Sparse_matrix a = test::triangulated_grid(k);
    SDI::Factored_system<SD::Default_solver_traits> system(SD::Default_solver_traits(), "grid");
    system.factor(SDI::Sparse_matrix(a));
    CHECK(system.traits().solver().uses_supernodal() == (k * k >= 20000));
    const Eigen::VectorXd b = random_vector(a.rows(), 5);
    const Eigen::VectorXd x = system.solve(b);
    REQUIRE((a * x - b).norm() <= 1e-10 * a.norm() * x.norm());
  }
  SD::Default_solver_traits traits;
  CHECK(traits.solver().size_threshold() == 20000);
  CHECK(traits.solver().info() == Eigen::InvalidInput);     // nothing analysed yet
  CHECK_THROWS_AS(traits.solver().set_size_threshold(-1), SD::Invalid_parameter);
  CHECK(traits.solver().size_threshold() == 20000);
}

TEST_CASE("Default solver: one object across the size threshold, analysis and factorization apart", "[solver]")
{
  SD::Size_switched_cholesky<SDI::Sparse_matrix> solver;
  solver.set_size_threshold(500);
  for(const int k : {20, 30, 20}) // 400, 900, 400 unknowns
  {
    INFO("grid " << k);
    const SDI::Sparse_matrix a = test::triangulated_grid(k);
    const Eigen::VectorXd b = random_vector(a.rows(), unsigned(k));
    solver.compute(a);
    REQUIRE(solver.info() == Eigen::Success);
    REQUIRE(solver.uses_supernodal() == (k * k >= 500));
    REQUIRE(solver.rows() == a.rows());
    REQUIRE((a * Eigen::VectorXd(solver.solve(b)) - b).norm() <= 1e-10 * b.norm());
    // analysis once, then factorizations of other values on the same pattern
    solver.analyzePattern(a);
    const SDI::Sparse_matrix twice = 2. * a;
    solver.factorize(twice);
    REQUIRE(solver.info() == Eigen::Success);
    REQUIRE((twice * Eigen::VectorXd(solver.solve(b)) - b).norm() <= 1e-10 * b.norm());
    REQUIRE(solver.vectorD().size() == a.rows());
  }
}

TEST_CASE("Default solver: Hermitian systems in complex arithmetic with both factorizations", "[solver]")
{
  const test::Complex_matrix h =
    test::magnetic_laplacian(test::screened_laplacian(test::load_mesh<test::Surface_mesh>("kitten.off")));
  static_assert(SDI::Hermitian_system<SD::Default_solver_traits>::uses_complex_arithmetic());
  Both_factorizations<test::Complex_matrix> both(h);
  const double ld1 = log_determinant(both.simplicial.vectorD()), ld2 = log_determinant(both.supernodal.vectorD());
  REQUIRE(std::abs(ld1 - ld2) <= 1e-9 * (std::abs(ld1) + double(h.rows())));
  const Eigen::VectorXcd b = test::complex_test_vector(h.rows(), 3);
  const Eigen::VectorXcd reference = Eigen::SimplicialLDLT<test::Complex_matrix>(h).solve(b);
  REQUIRE((Eigen::VectorXcd(both.supernodal.solve(b)) - reference).norm() <= 1e-10 * reference.norm());
  // through the traits (the threshold of the traits' solver holds for the complex factorization)
  for(const Eigen::Index threshold : {Eigen::Index(0), Eigen::Index(1) << 40})
  {
    SD::Default_solver_traits traits;
    traits.solver().set_size_threshold(threshold);
    test::require_hermitian_system_solution<SD::Default_solver_traits>(h, b, reference, traits);
  }
}

TEST_CASE("CHOLMOD with the library's nested dissection: the order given, the same solutions, Hermitian too", "[solver]")
{
#if defined(CGAL_SURFACE_DESIGN_HAS_CHOLMOD)
  const test::Surface_mesh mesh = test::load_mesh<test::Surface_mesh>("kitten.off");
  const SDI::Sparse_matrix A = screened_laplacian(mesh, 1e-2);
  const std::vector<Eigen::VectorXd> rhs{random_vector(A.rows(), 1), random_vector(A.rows(), 2)};
  const auto nd = factor_and_solve<SD::Cholmod_nested_dissection_solver_traits>(A, rhs);
  const auto reference = factor_and_solve<SD::Default_solver_traits>(A, rhs);
  for(std::size_t k = 0; k < rhs.size(); ++k)
    REQUIRE((nd[k] - reference[k]).norm() <= 1e-10 * reference[k].norm());
  // CHOLMOD analysed with the order given, and that order is the nested dissection's: its factor
  // has exactly the nonzeros of SimplicialLDLT's with Nested_dissection_ordering (CHOLMOD only
  // postorders the order it is given, which keeps the fill), not those of AMD's
  SD::Cholmod_nested_dissection_llt<SDI::Sparse_matrix> given;
  CHECK(given.ordering_used() == -1);
  given.compute(A);
  REQUIRE(given.info() == Eigen::Success);
  CHECK(given.ordering_used() == CHOLMOD_GIVEN);
  const Eigen::SimplicialLDLT<SDI::Sparse_matrix, Eigen::Lower, SD::Nested_dissection_ordering<int>> nd_ldlt(A);
  const Eigen::SimplicialLDLT<SDI::Sparse_matrix> amd_ldlt(A);
  const double strictly_lower = given.cholmod().lnz - double(A.rows());
  INFO("strictly lower nnz(L): CHOLMOD given the nested dissection " << strictly_lower << ", SimplicialLDLT with it "
       << nd_ldlt.matrixL().nestedExpression().nonZeros() << ", with AMD " << amd_ldlt.matrixL().nestedExpression().nonZeros());
  CHECK(strictly_lower == double(nd_ldlt.matrixL().nestedExpression().nonZeros()));
  CHECK(strictly_lower != double(amd_ldlt.matrixL().nestedExpression().nonZeros()));
  // a Hermitian system in complex arithmetic with the same order
  const test::Complex_matrix h = test::magnetic_laplacian(screened_laplacian(mesh, 1e-2));
  const Eigen::VectorXcd b = test::complex_test_vector(h.rows(), 5);
  const Eigen::VectorXcd x = Eigen::SimplicialLDLT<test::Complex_matrix>(h).solve(b);
  test::require_hermitian_system_solution<SD::Cholmod_nested_dissection_solver_traits>(h, b, x);
#else
  SD_CHOLMOD_UNAVAILABLE("CHOLMOD with the nested dissection");
#endif
}

TEST_CASE("Default solver: indefinite and singular systems fail with both factorizations", "[solver]")
{
  const test::Surface_mesh mesh = test::load_mesh<test::Surface_mesh>("bunny_1k.off");
  for(const double screening : {-1e3, 0.})
  {
    const SDI::Sparse_matrix a = screened_laplacian(mesh, screening);
    for(const Eigen::Index threshold : {Eigen::Index(0), Eigen::Index(1) << 40})
    {
      INFO("screening " << screening << ", size threshold " << threshold);
      SD::Size_switched_cholesky<SDI::Sparse_matrix> solver;
      solver.set_size_threshold(threshold);
      solver.compute(a);
      // the simplicial LDLT factors any non-singular symmetric matrix: its pivots tell
      const bool rejected = solver.info() != Eigen::Success ||
                            !(solver.vectorD().minCoeff() > SDI::ldlt_pivot_tolerance * solver.vectorD().cwiseAbs().maxCoeff());
      CHECK(rejected);
      SD::Default_solver_traits traits;
      traits.solver().set_size_threshold(threshold);
      SDI::Factored_system<SD::Default_solver_traits> system(traits, "test system");
      CHECK_THROWS_AS(system.factor(SDI::Sparse_matrix(a)), SD::Linear_solver_failure);
      CHECK_FALSE(system.is_factored());
    }
  }
}


TEMPLATE_TEST_CASE("solve_many in place (one matrix for B and X) equals the solve into another matrix", "[solver]",
                   SD_SOLVER_TYPES)
{
  // bunny_1k: the default solver's simplicial side; the 142^2 grid: its supernodal side
  const test::Surface_mesh mesh = test::load_mesh<test::Surface_mesh>("bunny_1k.off");
  for(const SDI::Sparse_matrix& a : {screened_laplacian(mesh, 1e-2), test::triangulated_grid(142)})
  {
    INFO(a.rows() << " unknowns");
    SDI::Factored_system<TestType> system(TestType(), "test system");
    system.factor(SDI::Sparse_matrix(a));
    for(const Eigen::Index k : {1, 2, 5})
    {
      INFO(k << " right-hand sides");
      Eigen::MatrixXd b(a.rows(), k);
      for(Eigen::Index c = 0; c < k; ++c)
        b.col(c) = random_vector(a.rows(), unsigned(10 + c));
      Eigen::MatrixXd x, y = b;
      system.solve_many(b, x);
      system.solve_many(y, y);
      CHECK((x - y).norm() == 0.);
      CHECK((a * y - b).norm() <= 1e-10 * a.norm() * y.norm());
    }
  }
}
