// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Factor-once / solve-many through CGAL's solver traits: SimplicialLDLT and CHOLMOD agree,
// failures are reported clearly.

#include <test_support.h>

#include <CGAL/Surface_design/internal/Core/dec.h>
#include <CGAL/Surface_design/internal/Core/Factored_system.h>
#include <CGAL/Surface_design/internal/Core/geometry.h>
#include <CGAL/Surface_design/internal/Core/Mesh_indices.h>
#include <CGAL/Surface_design/solver_traits.h>

#include <random>

namespace SD = CGAL::Surface_design;
namespace SDI = CGAL::Surface_design::internal;

namespace {

// A screened cotangent-Laplace system L + s M (SPD), the typical system of the library.
template <class Mesh>
SDI::Sparse_matrix screened_laplacian(const Mesh& mesh, double screening)
{
  const auto vpm = get(CGAL::vertex_point, mesh);
  SDI::Mesh_indices<Mesh> idx(mesh);
  const SDI::Sparse_matrix L = SDI::weighted_laplacian(idx, SDI::cotangent_weights(idx, vpm));
  const SDI::Sparse_matrix M = SDI::diagonal_matrix(SDI::vertex_areas(idx, SDI::face_areas(idx, vpm)));
  return L + screening * M;
}

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

TEMPLATE_TEST_CASE("Factor once, solve many: LDLT and CHOLMOD agree to 1e-10", "[solver]", SD_MESH_TYPES)
{
  for(const std::string name : {"bunny_1k.off", "triceratops.off", "mech-holes-shark.off"})
  {
    INFO(name);
    const TestType mesh = test::load_mesh<TestType>(name);
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
  SDI::Factored_system<SD::Default_solver_traits> system;
  system.factor(SDI::Sparse_matrix(A));
  // the solver object holds the factor of A: solving with it twice gives identical results
  const Eigen::VectorXd b = random_vector(A.rows(), 9);
  const Eigen::VectorXd x1 = system.solve(b), x2 = system.solve(b);
  REQUIRE((x1 - x2).norm() == 0.);
  // a copy of the system's traits shares the factorization (Eigen_solver_traits semantics)
  SD::Default_solver_traits copy = system.traits();
  REQUIRE(&copy.solver() == &system.traits().solver());
}

#if defined(CGAL_SURFACE_DESIGN_HAS_CHOLMOD)
#define SD_SOLVER_TYPES SD::Default_solver_traits, SD::Cholmod_solver_traits
#else
#define SD_SOLVER_TYPES SD::Default_solver_traits
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
  SDI::Factored_system<SD::Default_solver_traits> system(SD::Default_solver_traits(), "Laplacian");
  CHECK_THROWS_AS(system.factor(SDI::Sparse_matrix(L)), SD::Linear_solver_failure);
  // pinning one vertex (Dirichlet row) makes it definite
  SDI::Sparse_matrix pinned = L;
  pinned.coeffRef(0, 0) += 1.;
  CHECK_NOTHROW(system.factor(std::move(pinned)));
}
