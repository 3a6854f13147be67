// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The supernodal multifrontal Cholesky factorization: the same factor as a simplicial one with the
// same order (pivot by pivot), the same solutions as the default solver, every pattern (single,
// diagonal, dense, path and star, several components, one or both triangles stored), Hermitian
// matrices, an analysis shared between matrices (by hand and through a Symbolic_analysis_cache,
// across packages), refactorization, several right-hand sides, and clear failures (indefinite,
// singular, missing diagonal, wrong size or pattern).

#include <sparse_test_matrices.h>
#include <test_support.h>

#include <CGAL/Surface_design/direction_fields.h>
#include <CGAL/Surface_design/Field_aligned_parameterizer.h>
#include <CGAL/Surface_design/supernodal_cholesky.h>
#include <CGAL/Surface_design/Trivial_connection.h>
#include <CGAL/Surface_design/internal/Solvers/Factored_system.h>
#include <CGAL/Surface_design/internal/Solvers/Hermitian_system.h>

#include <Eigen/OrderingMethods>
#include <Eigen/SparseCholesky>

#include <algorithm>
#include <complex>
#include <map>
#include <memory>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#if defined(CGAL_LINKED_WITH_TBB)
#include <tbb/task_arena.h>
#endif

namespace SD = CGAL::Surface_design;
namespace SDI = CGAL::Surface_design::internal;

namespace {

using Real_matrix = Eigen::SparseMatrix<double>;
using test::Complex_matrix;

// Checks A x = b to 1e-10 relative for several right-hand sides, against a reference solver.
template <class Solver, class Reference, class Matrix>
void require_same_solutions(const Solver& solver, const Reference& reference, const Matrix& a)
{
  using Vector = Eigen::Matrix<typename Matrix::Scalar, Eigen::Dynamic, 1>;
  for(unsigned seed = 1; seed <= 3; ++seed)
  {
    Vector b;
    if constexpr(std::is_same<typename Matrix::Scalar, double>::value)
      b = test::test_vector(a.rows(), seed);
    else
      b = test::complex_test_vector(a.rows(), seed);
    const Vector x = solver.solve(b);
    const Matrix full = a.template selfadjointView<Eigen::Lower>();
    REQUIRE((full * x - b).norm() <= 1e-10 * full.norm() * x.norm());
    REQUIRE((x - reference.solve(b)).norm() <= 1e-10 * x.norm());
  }
}

// The supernodal factor against Eigen's simplicial LDL^T with the same order: a postorder of the
// elimination tree is an equivalent order, so every pivot |L_jj|^2 must equal D_jj of the same
// unknown; the stored entries cover the simplicial factor's nonzeros (supernodes add explicit zeros).
template <class Matrix>
void require_factor_of_simplicial(const Matrix& a)
{
  SD::Supernodal_cholesky<Matrix> supernodal(a);
  REQUIRE(supernodal.info() == Eigen::Success);
  Eigen::SimplicialLDLT<Matrix, Eigen::Lower, SD::Nested_dissection_ordering<int>> simplicial(a);
  REQUIRE(simplicial.info() == Eigen::Success);
  const Eigen::VectorXd d_supernodal = supernodal.vectorD();
  // Eigen's D is in elimination order: back to the original order of the unknowns
  Eigen::VectorXd d_simplicial(a.rows());
  for(Eigen::Index i = 0; i < a.rows(); ++i)
    d_simplicial[i] = std::real(simplicial.vectorD()[simplicial.permutationP().indices()[i]]);
  REQUIRE(d_supernodal.size() == a.rows());
  REQUIRE((d_supernodal - d_simplicial).cwiseAbs().maxCoeff() <= 1e-10 * d_simplicial.cwiseAbs().maxCoeff());
  REQUIRE(supernodal.factor_nonzeros() >= double(simplicial.matrixL().nestedExpression().nonZeros()) - double(a.rows()));
  REQUIRE(supernodal.supernode_count() >= 1);
  REQUIRE(supernodal.supernode_count() <= a.rows());
  require_same_solutions(supernodal, simplicial, a);
}

} // namespace

TEST_CASE("Supernodal Cholesky: the simplicial factor, pivot by pivot, on grids", "[supernodal]")
{
  for(int k : {1, 2, 7, 60, CGAL_SURFACE_DESIGN_TESTS_UNDER_SANITIZERS ? 80 : 200})
  {
    INFO("grid " << k << " x " << k);
    require_factor_of_simplicial(test::triangulated_grid(k));
  }
}

// the mesh data structure only feeds the matrix here (the Laplacian's independence of it: test_geometry_dec)
TEST_CASE("Supernodal Cholesky: mesh Laplacians with holes, several components, skinny triangles", "[supernodal]")
{
  for(const std::string name : {"bunny_8k.off", "blobby_3cc.off", "mech-holes-shark.off", "bones.off"})
  {
    INFO(name);
    require_factor_of_simplicial(test::screened_laplacian(test::load_mesh<test::Surface_mesh>(name)));
  }
}

TEST_CASE("Supernodal Cholesky: every pattern", "[supernodal]")
{
  SECTION("one unknown") {
    const Real_matrix a = test::graph_matrix(1, {});
    SD::Supernodal_cholesky<Real_matrix> s(a);
    REQUIRE(s.info() == Eigen::Success);
    REQUIRE(s.supernode_count() == 1);
    Eigen::VectorXd b(1);
    b << 3.;
    REQUIRE(std::abs(s.solve(b)[0] - 3.) <= 1e-15); // the diagonal is 1
  }
  SECTION("1000 isolated unknowns (a diagonal matrix)") {
    require_factor_of_simplicial(test::graph_matrix(1000, {}));
  }
  SECTION("a complete graph of 150 vertices: one dense supernode") {
    std::vector<std::pair<int, int>> edges;
    for(int i = 0; i < 150; ++i)
      for(int j = i + 1; j < 150; ++j)
        edges.push_back({i, j});
    const Real_matrix a = test::graph_matrix(150, edges);
    require_factor_of_simplicial(a);
    REQUIRE(SD::Supernodal_cholesky<Real_matrix>(a).supernode_count() == 1);
  }
  SECTION("a path of 5000 vertices and a star of 300 (long chains, many leaves)") {
    std::vector<std::pair<int, int>> edges;
    for(int i = 0; i + 1 < 5000; ++i)
      edges.push_back({i, i + 1});
    for(int i = 1; i < 300; ++i)
      edges.push_back({5000, 5000 + i});
    require_factor_of_simplicial(test::graph_matrix(5300, edges));
  }
  SECTION("one triangle or both stored; the upper triangle is not read") {
    const Real_matrix a = test::triangulated_grid(30);
    const Real_matrix lower = a.triangularView<Eigen::Lower>();
    Real_matrix garbage_above = a;
    for(int k = 0; k < garbage_above.outerSize(); ++k)
      for(Real_matrix::InnerIterator it(garbage_above, k); it; ++it)
        if(it.row() < it.col())
          it.valueRef() = 1e6;
    SD::Supernodal_cholesky<Real_matrix> from_lower(lower), from_full(a), from_garbage(garbage_above);
    const Eigen::VectorXd b = test::test_vector(a.rows(), 1);
    const Eigen::VectorXd x = from_lower.solve(b);
    REQUIRE((a * x - b).norm() <= 1e-12 * a.norm() * x.norm());
    REQUIRE((from_full.solve(b) - x).norm() <= 1e-14 * x.norm());
    REQUIRE((from_garbage.solve(b) - x).norm() <= 1e-14 * x.norm());
  }
  SECTION("with Eigen's AMD ordering") {
    const Real_matrix a = test::triangulated_grid(50);
    SD::Supernodal_cholesky<Real_matrix, Eigen::AMDOrdering<int>> amd(a);
    REQUIRE(amd.info() == Eigen::Success);
    require_same_solutions(amd, Eigen::SimplicialLDLT<Real_matrix>(a), a);
    // the ordering, computed by AMD from the pattern of the lower triangle alone, is as good as
    // the one Eigen's AMDOrdering computes from the whole matrix (the same fill and flops; the
    // permutation may differ where AMD breaks ties, as the rows of a column come in another
    // order): real and complex, one triangle stored or both, explicit zeros in the pattern
    auto require_eigen_amd = [](const auto& m) {
      using Matrix = std::decay_t<decltype(m)>;
      Eigen::AMDOrdering<int>::PermutationType order;
      Eigen::AMDOrdering<int>()(Matrix(m.template selfadjointView<Eigen::Lower>()), order);
      std::vector<int> eigen_order(std::size_t(order.size()));
      for(Eigen::Index k = 0; k < order.size(); ++k)
        eigen_order[std::size_t(k)] = order.indices()[k];
      const auto eigen = SD::internal::supernodal_analysis(m, eigen_order);
      SD::Supernodal_cholesky<Matrix, Eigen::AMDOrdering<int>> s;
      s.analyzePattern(m);
      REQUIRE(s.info() == Eigen::Success);
      std::vector<int> sorted = s.analysis()->old_of_new;
      std::sort(sorted.begin(), sorted.end());
      for(std::size_t k = 0; k < sorted.size(); ++k)
        REQUIRE(sorted[k] == int(k)); // a permutation of every unknown
      REQUIRE(s.analysis()->factor_nonzeros == eigen->factor_nonzeros);
      REQUIRE(s.analysis()->factor_flops == eigen->factor_flops);
    };
    require_eigen_amd(a);
    require_eigen_amd(Real_matrix(a.triangularView<Eigen::Lower>()));
    require_eigen_amd(test::magnetic_laplacian(a));
    Real_matrix zeros = a;
    for(int k = 0; k < zeros.outerSize(); k += 3)
      for(Real_matrix::InnerIterator it(zeros, k); it; ++it)
        if(it.row() != it.col())
          it.valueRef() = 0.; // stored, so part of the pattern
    require_eigen_amd(zeros);
    require_eigen_amd(test::screened_laplacian(test::load_mesh<test::Surface_mesh>("bunny_1k.off")));
    // and it is not the natural order, whose fill is larger (the comparison has something to compare)
    SD::Supernodal_cholesky<Real_matrix, Eigen::AMDOrdering<int>> s;
    s.analyzePattern(a);
    std::size_t moved = 0;
    for(std::size_t k = 0; k < s.analysis()->old_of_new.size(); ++k)
      moved += s.analysis()->old_of_new[k] != int(k) ? 1 : 0;
    REQUIRE(moved > s.analysis()->old_of_new.size() / 2);
    std::vector<int> natural(std::size_t(a.rows()));
    for(std::size_t k = 0; k < natural.size(); ++k)
      natural[k] = int(k);
    REQUIRE(SD::internal::supernodal_analysis(a, natural)->factor_nonzeros > 1.2 * s.analysis()->factor_nonzeros);
  }
}

TEST_CASE("Supernodal Cholesky: several right-hand sides, refactorization, shared analysis", "[supernodal]")
{
  const Real_matrix a = test::screened_laplacian(test::load_mesh<test::Surface_mesh>("bunny_1k.off"));
  SD::Supernodal_cholesky<Real_matrix> s(a);
  REQUIRE(s.info() == Eigen::Success);

  Eigen::MatrixXd b(a.rows(), 3);
  for(unsigned k = 0; k < 3; ++k)
    b.col(k) = test::test_vector(a.rows(), k + 1);
  const Eigen::MatrixXd x = s.solve(b);
  for(Eigen::Index k = 0; k < 3; ++k)
    REQUIRE((x.col(k) - s.solve(Eigen::VectorXd(b.col(k)))).norm() <= 1e-14 * x.col(k).norm());
  // the columns are solved in two halves, concurrently with TBB: the same bits within one thread,
  // and every column (an odd count: halves of 2 and 3) that of its own solve
  Eigen::MatrixXd five(a.rows(), 5);
  for(unsigned k = 0; k < 5; ++k)
    five.col(k) = test::test_vector(a.rows(), k + 11);
  const Eigen::MatrixXd x5 = s.solve(five);
  Eigen::MatrixXd x5_one_thread;
#if defined(CGAL_LINKED_WITH_TBB)
  tbb::task_arena one_thread(1);
  one_thread.execute([&] { x5_one_thread = s.solve(five); });
#else
  x5_one_thread = s.solve(five);
#endif
  REQUIRE(x5 == x5_one_thread);
  const Real_matrix full = a.selfadjointView<Eigen::Lower>();
  for(Eigen::Index k = 0; k < 5; ++k)
  {
    REQUIRE((x5.col(k) - s.solve(Eigen::VectorXd(five.col(k)))).norm() <= 1e-14 * x5.col(k).norm());
    REQUIRE((full * x5.col(k) - five.col(k)).norm() <= 1e-12 * full.norm() * x5.col(k).norm());
  }

  // new values on the same pattern: factorize only
  Real_matrix shifted = a;
  shifted.diagonal().array() += 2.;
  s.factorize(shifted);
  REQUIRE(s.info() == Eigen::Success);
  require_same_solutions(s, Eigen::SimplicialLDLT<Real_matrix>(shifted), shifted);

  // the analysis of the real Laplacian serves a complex Hermitian matrix with the same pattern
  const Complex_matrix h = test::magnetic_laplacian(a);
  SD::Supernodal_cholesky<Complex_matrix> own(h), shared;
  shared.set_analysis(s.analysis());
  shared.factorize(h);
  REQUIRE(shared.info() == Eigen::Success);
  REQUIRE(shared.analysis() == s.analysis());
  const Eigen::VectorXcd c = test::complex_test_vector(h.rows(), 4);
  REQUIRE((shared.solve(c) - own.solve(c)).norm() <= 1e-12 * own.solve(c).norm());
}

TEST_CASE("Supernodal Cholesky: Hermitian systems, in complex arithmetic through the traits", "[supernodal]")
{
  const Complex_matrix h =
    test::magnetic_laplacian(test::screened_laplacian(test::load_mesh<test::Surface_mesh>("kitten.off")));
  require_factor_of_simplicial(h);

  const Eigen::VectorXcd b = test::complex_test_vector(h.rows(), 7);
  test::require_hermitian_system_solution<SD::Supernodal_solver_traits>(
    h, b, Eigen::SimplicialLDLT<Complex_matrix>(h).solve(b));
}

TEST_CASE("Supernodal Cholesky: concurrent subtrees and blocked dense kernels give the sequential factor",
          "[supernodal]")
{
  // the grid's tree has enough work for concurrent subtree tasks and separator fronts of several
  // hundred rows; the complete graph is one front of 600 rows, factored by blocks of columns
  std::vector<std::pair<int, int>> edges;
  for(int i = 0; i < 600; ++i)
    for(int j = i + 1; j < 600; ++j)
      edges.push_back({i, j});
  for(const Real_matrix& a : {test::triangulated_grid(CGAL_SURFACE_DESIGN_TESTS_UNDER_SANITIZERS ? 150 : 300),
                              test::graph_matrix(600, edges)})
  {
    INFO(a.rows() << " unknowns");
    SD::Supernodal_cholesky<Real_matrix> analysed;
    analysed.analyzePattern(a);
    SDI::Supernodal_factor<double> sequential, concurrent;
    REQUIRE(sequential.factorize(analysed.analysis(), a, false) == -1);
    REQUIRE(concurrent.factorize(analysed.analysis(), a, true) == -1);
    const Eigen::VectorXd d = sequential.pivots();
    REQUIRE((concurrent.pivots() - d).cwiseAbs().maxCoeff() <= 1e-12 * d.maxCoeff());
    const Eigen::VectorXd b = test::test_vector(a.rows(), 2);
    Eigen::VectorXd x, y;
    sequential.solve(b, x);
    concurrent.solve(b, y);
    REQUIRE((a * y - b).norm() <= 1e-10 * a.norm() * y.norm());
    REQUIRE((x - y).norm() <= 1e-12 * x.norm());
    // a failure inside a concurrent task is reported, not lost
    Real_matrix broken = a;
    broken.coeffRef(7, 7) = -1e3;
    SDI::Supernodal_factor<double> failing;
    REQUIRE(failing.factorize(analysed.analysis(), broken, true) != -1);
    REQUIRE_FALSE(failing.is_factored());
  }
}

namespace {

// One right-hand side solved by independent subtrees, with TBB's threads and within one thread:
// the same bits (the split depends on the analysis alone); the solution of the sequential
// factorization and of the multi-column solve (another code path, by dense kernels); a small
// residual.
template <class Matrix, class Ordering>
std::size_t require_subtree_solve(const Matrix& a)
{
  using Scalar = typename Matrix::Scalar;
  using Vector = Eigen::Matrix<Scalar, Eigen::Dynamic, 1>;
  using Dense = Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic>;
  SD::Supernodal_cholesky<Matrix, Ordering> analysed;
  analysed.analyzePattern(a);
  SDI::Supernodal_factor<Scalar> sequential, concurrent;
  REQUIRE(sequential.factorize(analysed.analysis(), a, false) == -1);
  REQUIRE(concurrent.factorize(analysed.analysis(), a, true) == -1);
  Dense b(a.rows(), 2);
  for(Eigen::Index i = 0; i < a.rows(); ++i)
  {
    b(i, 0) = Scalar(std::sin(0.7 * double(i) + 1.));
    b(i, 1) = Scalar(std::cos(0.3 * double(i)));
  }
  if constexpr(!std::is_same<Scalar, double>::value)
    b.col(0) += Scalar(0., 1.) * Vector(b.col(1));
  Vector x, y, z;
  sequential.solve(Vector(b.col(0)), x);
  concurrent.solve(Vector(b.col(0)), y);
#if defined(CGAL_LINKED_WITH_TBB)
  tbb::task_arena one_thread(1);
  one_thread.execute([&] { concurrent.solve(Vector(b.col(0)), z); });
#else
  concurrent.solve(Vector(b.col(0)), z);
#endif
  REQUIRE(y == z); // the same factor, one thread or more: the same bits
  REQUIRE((x - y).norm() <= 1e-12 * x.norm());
  Dense columns;
  sequential.solve(b, columns);
  const Matrix full = a.template selfadjointView<Eigen::Lower>();
  REQUIRE((full * x - Vector(b.col(0))).norm() <= 1e-12 * full.norm() * x.norm());
  REQUIRE((x - Vector(columns.col(0))).norm() <= 1e-12 * x.norm());
  REQUIRE(concurrent.solve_group_count() == sequential.solve_group_count());
  return sequential.solve_group_count();
}

} // namespace

TEST_CASE("Supernodal Cholesky: a back-substitution by subtrees is exact and does not depend on the threads",
          "[supernodal]")
{
  using ND = SD::Nested_dissection_ordering<int>;
  using AMD = Eigen::AMDOrdering<int>;
  const Real_matrix grid = test::triangulated_grid(CGAL_SURFACE_DESIGN_TESTS_UNDER_SANITIZERS ? 120 : 200);
  // split below a chain of separators: several groups, for both orderings and arithmetics
  CHECK(require_subtree_solve<Real_matrix, ND>(grid) >= 2);
  CHECK(require_subtree_solve<Real_matrix, AMD>(grid) >= 2);
  CHECK(require_subtree_solve<Complex_matrix, ND>(test::magnetic_laplacian(grid)) >= 2);
  // several components: a forest, split at its roots (no top to collect into)
  std::vector<std::pair<int, int>> edges;
  const int k = 90, components = 5;
  for(int c = 0; c < components; ++c)
    for(int i = 0; i < k; ++i)
      for(int j = 0; j < k; ++j)
      {
        const int v = c * k * k + i * k + j;
        if(j + 1 < k) edges.push_back({v, v + 1});
        if(i + 1 < k) edges.push_back({v, v + k});
      }
  CHECK(require_subtree_solve<Real_matrix, ND>(test::graph_matrix(components * k * k, edges)) == 4);
  // a path: its elimination tree under the natural order is a chain, nothing to split
  std::vector<std::pair<int, int>> path;
  for(int i = 0; i + 1 < 60000; ++i)
    path.push_back({i, i + 1});
  CHECK(require_subtree_solve<Real_matrix, Eigen::NaturalOrdering<int>>(test::graph_matrix(60000, path)) == 0);
  // small factors are solved in sequence
  CHECK(require_subtree_solve<Real_matrix, ND>(test::triangulated_grid(20)) == 0);
}

TEST_CASE("Supernodal Cholesky: clear failures, nothing solved with a bad factor", "[supernodal]")
{
  const Real_matrix good = test::triangulated_grid(20);
  SECTION("indefinite") {
    Real_matrix a = good;
    a.coeffRef(210, 210) = -50.;
    SD::Supernodal_cholesky<Real_matrix> s(a);
    REQUIRE(s.info() == Eigen::NumericalIssue);
    SDI::Factored_system<SD::Supernodal_solver_traits> system(SD::Supernodal_solver_traits(), "test system");
    REQUIRE_THROWS_WITH(system.factor(Real_matrix(a)), Catch::Contains("not positive definite"));
    REQUIRE_FALSE(system.is_factored());
  }
  SECTION("singular: the Laplacian of a closed mesh without screening") {
    const Real_matrix a = test::screened_laplacian(test::load_mesh<test::Surface_mesh>("bunny_1k.off"), 0.);
    REQUIRE(SD::Supernodal_cholesky<Real_matrix>(a).info() == Eigen::NumericalIssue);
  }
  SECTION("a missing diagonal entry") {
    Real_matrix a = good;
    a.coeffRef(5, 5) = 0.;
    a.prune(0.);
    REQUIRE(SD::Supernodal_cholesky<Real_matrix>(a).info() == Eigen::NumericalIssue);
  }
  SECTION("not square") {
    REQUIRE(SD::Supernodal_cholesky<Real_matrix>(Real_matrix(4, 5)).info() == Eigen::InvalidInput);
  }
  SECTION("factorize with another pattern than the analysed one") {
    SD::Supernodal_cholesky<Real_matrix> s;
    s.analyzePattern(good);
    s.factorize(test::triangulated_grid(21));
    REQUIRE(s.info() == Eigen::InvalidInput);
    Real_matrix extra = good;
    extra.coeffRef(399, 0) = -0.5;
    s.factorize(extra);
    REQUIRE(s.info() == Eigen::InvalidInput);
    s.factorize(good);
    REQUIRE(s.info() == Eigen::Success);
  }
  SECTION("no analysis") {
    SD::Supernodal_cholesky<Real_matrix> s;
    s.factorize(good);
    REQUIRE(s.info() == Eigen::InvalidInput);
  }
}

TEMPLATE_TEST_CASE("Supernodal Cholesky through a package: the smoothest field as with the default solver",
                   "[supernodal]", SD_MESH_TYPES)
{
  // the Lanczos iteration is deterministic given the solves: the same field to 1e-9 when the
  // solves agree to 1e-10 (the fields are unit vectors with a fixed global phase from the same
  // start vector)
  for(const std::string name : {"bunny_1k.off", "hemisphere.off"})
  {
    INFO(name);
    const TestType mesh = test::load_mesh<TestType>(name);
    using Field = std::map<typename boost::graph_traits<TestType>::vertex_descriptor, test::Kernel::Vector_3>;
    Field reference, supernodal;
    const auto a = SD::smoothest_direction_field(mesh, boost::make_assoc_property_map(reference),
                                                 SD::parameters::symmetry_order(4));
    const auto b = SD::smoothest_direction_field(
      mesh, boost::make_assoc_property_map(supernodal),
      SD::parameters::symmetry_order(4, SD::parameters::sparse_linear_solver(SD::Supernodal_solver_traits())));
    REQUIRE(a.iterations == b.iterations);
    REQUIRE(std::abs(a.eigenvalues[0] - b.eigenvalues[0]) <= 1e-10 * a.eigenvalues[0]);
    double difference = 0.;
    for(const auto& [v, u] : reference)
      difference = std::max(difference, std::sqrt((u - supernodal.at(v)).squared_length()));
    REQUIRE(difference <= 1e-9);
  }
}

namespace {

// The default solver traits forced to the supernodal factorization, sharing `cache` (none: null).
SD::Default_solver_traits supernodal_traits(const std::shared_ptr<SD::Symbolic_analysis_cache>& cache)
{
  SD::Default_solver_traits traits;
  traits.solver().set_size_threshold(0);
  traits.solver().set_analysis_cache(cache);
  return traits;
}

// The smoothest vector field, then the stripes along it (one +1 / -1 pair), with the given traits:
// the stripes' one-form and the field.
template <class Mesh>
std::pair<std::vector<double>, std::vector<double>> field_then_stripes(const Mesh& mesh,
                                                                       SD::Default_solver_traits field_traits,
                                                                       SD::Default_solver_traits stripe_traits)
{
  using vertex_descriptor = typename boost::graph_traits<Mesh>::vertex_descriptor;
  std::map<vertex_descriptor, test::Kernel::Vector_3> field;
  SD::smoothest_direction_field(mesh, boost::make_assoc_property_map(field),
                                SD::parameters::symmetry_order(1, SD::parameters::sparse_linear_solver(field_traits)));
  SD::Field_aligned_parameterizer<Mesh, typename boost::property_map<Mesh, CGAL::vertex_point_t>::const_type,
                                  SD::Default_solver_traits>
    fap(mesh, SD::parameters::sparse_linear_solver(stripe_traits));
  fap.set_field(boost::make_assoc_property_map(field), 0.);
  fap.set_index(std::size_t(10), 1);
  fap.set_index(std::size_t(num_faces(mesh) / 2), -1);
  fap.solve();
  std::vector<double> components;
  for(const auto& [v, u] : field)
    components.insert(components.end(), {u.x(), u.y(), u.z()});
  return {fap.one_form(), components};
}

} // namespace

TEMPLATE_TEST_CASE("Analysis cache: the smoothest field, the stripes and a trivial connection analysed once",
                   "[supernodal]", SD_MESH_TYPES)
{
  for(const std::string name : {"bunny_1k.off", "mech-holes-shark.off", "blobby_3cc.off"})
  {
    INFO(name);
    const TestType mesh = test::load_mesh<TestType>(name);
    const auto alone = field_then_stripes(mesh, supernodal_traits(nullptr), supernodal_traits(nullptr));
    auto cache = std::make_shared<SD::Symbolic_analysis_cache>();
    const auto shared = field_then_stripes(mesh, supernodal_traits(cache), supernodal_traits(cache));
    // the complex connection Laplacian and the pinned cotangent Laplacian: one pattern, one analysis
    REQUIRE(cache->size() == 1);
    REQUIRE(cache->hits() == 1);
    // the same analysis (the nested dissection is deterministic): the same numbers, to roundoff
    auto max_difference = [](const std::vector<double>& a, const std::vector<double>& b) {
      REQUIRE(a.size() == b.size());
      double d = 0.;
      for(std::size_t i = 0; i < a.size(); ++i)
        d = std::max(d, std::abs(a[i] - b[i]) / (1. + std::abs(a[i])));
      return d;
    };
    REQUIRE(max_difference(shared.first, alone.first) <= 1e-9);
    REQUIRE(max_difference(shared.second, alone.second) <= 1e-9);
    // a trivial connection (pinned graph Laplacian) on the same mesh finds it too
    SD::Trivial_connection<TestType, typename boost::property_map<TestType, CGAL::vertex_point_t>::const_type,
                           SD::Default_solver_traits>
      tc(mesh, SD::parameters::sparse_linear_solver(supernodal_traits(cache)));
    REQUIRE(cache->size() == 1);
    REQUIRE(cache->hits() == 2);
    cache->clear();
    REQUIRE(cache->size() == 0);
    REQUIRE(cache->hits() == 0);
  }
}

TEST_CASE("Analysis cache: other patterns are analysed, equal ones found, in both arithmetics", "[supernodal]")
{
  auto cache = std::make_shared<SD::Symbolic_analysis_cache>();
  const Eigen::SparseMatrix<double> grid = test::triangulated_grid(30), other = test::triangulated_grid(31);
  SD::Supernodal_cholesky<Eigen::SparseMatrix<double>> a, b, c;
  SD::Supernodal_cholesky<Complex_matrix> h;
  for(auto* s : {&a, &b, &c})
    s->set_analysis_cache(cache);
  h.use_settings_of(a);
  REQUIRE(h.analysis_cache() == cache);
  a.compute(grid);
  b.compute(other);
  REQUIRE(cache->size() == 2);
  REQUIRE(cache->hits() == 0);
  REQUIRE(a.analysis() != b.analysis());
  // the same pattern with other values, and the Hermitian matrix on it: found
  const Eigen::SparseMatrix<double> scaled = 3. * grid;
  c.compute(scaled);
  h.compute(test::magnetic_laplacian(grid));
  REQUIRE(cache->hits() == 2);
  REQUIRE(c.analysis() == a.analysis());
  REQUIRE(h.analysis() == a.analysis());
  REQUIRE(c.info() == Eigen::Success);
  REQUIRE(h.info() == Eigen::Success);
  const Eigen::VectorXd rhs = test::test_vector(grid.rows(), 2);
  const Eigen::VectorXd x = c.solve(rhs);
  REQUIRE((scaled * x - rhs).norm() <= 1e-10 * rhs.norm());
  const Eigen::VectorXcd rhs_c = test::complex_test_vector(grid.rows(), 3);
  const Eigen::VectorXcd y = h.solve(rhs_c);
  REQUIRE((test::magnetic_laplacian(grid) * y - rhs_c).norm() <= 1e-10 * rhs_c.norm());

  // same size and number of entries, other rows: a path 0-1-2-3 and a star around 0
  const Eigen::SparseMatrix<double> path = test::graph_matrix(4, {{0, 1}, {1, 2}, {2, 3}});
  const Eigen::SparseMatrix<double> star = test::graph_matrix(4, {{0, 1}, {0, 2}, {0, 3}});
  SD::Supernodal_cholesky<Eigen::SparseMatrix<double>> p, q;
  p.set_analysis_cache(cache);
  q.set_analysis_cache(cache);
  p.compute(path);
  q.compute(star);
  REQUIRE(cache->size() == 4);
  REQUIRE(p.analysis() != q.analysis());
  // the same count in every column, other rows: {0-2, 1-3} and {0-3, 1-2}
  const Eigen::SparseMatrix<double> crossed = test::graph_matrix(4, {{0, 2}, {1, 3}});
  const Eigen::SparseMatrix<double> swapped = test::graph_matrix(4, {{0, 3}, {1, 2}});
  SD::Supernodal_cholesky<Eigen::SparseMatrix<double>> u, w;
  u.set_analysis_cache(cache);
  w.set_analysis_cache(cache);
  u.compute(crossed);
  w.compute(swapped);
  REQUIRE(cache->size() == 6);
  REQUIRE(u.analysis() != w.analysis());
  REQUIRE((swapped * Eigen::VectorXd(w.solve(Eigen::VectorXd::Ones(4))) - Eigen::VectorXd::Ones(4)).norm() <= 1e-12);
  REQUIRE((star * Eigen::VectorXd(q.solve(Eigen::VectorXd::Ones(4))) - Eigen::VectorXd::Ones(4)).norm() <= 1e-12);
  // without a cache nothing is shared
  SD::Supernodal_cholesky<Eigen::SparseMatrix<double>> lone;
  lone.compute(grid);
  REQUIRE(lone.analysis() != a.analysis());
  REQUIRE(cache->size() == 6);
}

TEST_CASE("Analysis cache: the default solver uses it at every size, one analysis per ordering", "[supernodal]")
{
  auto cache = std::make_shared<SD::Symbolic_analysis_cache>();
  const Eigen::SparseMatrix<double> grid = test::triangulated_grid(20); // 400 unknowns
  SD::Size_switched_cholesky<Eigen::SparseMatrix<double>> small, small_again, large;
  small.set_analysis_cache(cache);
  small_again.set_analysis_cache(cache);
  large.set_analysis_cache(cache);
  large.set_size_threshold(400);
  small.compute(grid);
  REQUIRE_FALSE(small.uses_supernodal());
  REQUIRE(cache->size() == 1); // the AMD analysis
  small_again.compute(grid);
  REQUIRE(cache->hits() == 1);
  large.compute(grid);
  REQUIRE(large.uses_supernodal());
  REQUIRE(cache->size() == 2); // nested dissection: not the AMD analysis of the same pattern
  REQUIRE(cache->hits() == 1);
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(grid.rows(), -1., 2.);
  const Eigen::VectorXd x_small = small_again.solve(b), x_large = large.solve(b);
  CHECK((grid.selfadjointView<Eigen::Lower>() * x_small - b).norm() <= 1e-10 * b.norm());
  CHECK((x_small - x_large).norm() <= 1e-10 * x_large.norm());
  // a Hermitian system through the traits follows the traits' threshold and cache
  SD::Default_solver_traits traits;
  traits.solver().set_size_threshold(0);
  traits.solver().set_analysis_cache(cache);
  test::require_hermitian_system_solution<SD::Default_solver_traits>(
    test::magnetic_laplacian(grid), test::complex_test_vector(grid.rows(), 1),
    Eigen::SimplicialLDLT<Complex_matrix>(test::magnetic_laplacian(grid)).solve(test::complex_test_vector(grid.rows(), 1)),
    traits);
  REQUIRE(cache->hits() == 2);
}
