// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The nested-dissection fill-reducing ordering: a permutation of any pattern (empty, isolated
// vertices, complete graphs, several components), fewer factor flops than AMD on large meshes, and
// factorizations with it that solve exactly like the default ones (real and Hermitian systems,
// through the solver traits and through a package).

#include <sparse_test_matrices.h>
#include <test_support.h>

#include <CGAL/Surface_design/Boundary_first_flattener.h>
#include <CGAL/Surface_design/nested_dissection_ordering.h>
#include <CGAL/Surface_design/supernodal_cholesky.h>
#include <CGAL/Surface_design/internal/Core/dec.h>
#include <CGAL/Surface_design/internal/Solvers/Factored_system.h>
#include <CGAL/Surface_design/internal/Solvers/Hermitian_system.h>
#include <CGAL/Surface_design/internal/Core/geometry.h>
#include <CGAL/Surface_design/internal/Core/Mesh_indices.h>

#include <Eigen/SparseCholesky>

#include <complex>
#include <type_traits>

namespace SD = CGAL::Surface_design;
namespace SDI = CGAL::Surface_design::internal;

namespace {

using Permutation = Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int>;

using test::graph_matrix;
using test::screened_laplacian;
using test::test_vector;
using test::triangulated_grid;

void require_permutation(const Permutation& p, Eigen::Index n)
{
  REQUIRE(p.size() == n);
  std::vector<char> seen(std::size_t(n), 0);
  for(Eigen::Index k = 0; k < n; ++k)
  {
    const int v = p.indices()[k];
    REQUIRE(v >= 0);
    REQUIRE(v < n);
    REQUIRE(!seen[std::size_t(v)]);
    seen[std::size_t(v)] = 1;
  }
}

template <class Ordering>
Permutation ordering_of(const SDI::Sparse_matrix& a)
{
  Permutation p;
  Ordering()(a, p);
  return p;
}

// The factor's fill and flop count for a given elimination order, from the factor itself:
// nnz(L) and sum over columns of nnz(L_j)^2 (the multiply-adds of a column Cholesky).
struct Fill
{
  double nonzeros = 0., flops = 0.;
};

Permutation g_given; // the order used by Given_ordering
struct Given_ordering
{
  using PermutationType = Permutation;
  template <class M>
  void operator()(const M&, Permutation& p) const { p = g_given; }
};

Fill fill_of(const SDI::Sparse_matrix& a, const Permutation& order)
{
  g_given = order;
  Eigen::SimplicialLDLT<SDI::Sparse_matrix, Eigen::Lower, Given_ordering> ldlt(a);
  REQUIRE(ldlt.info() == Eigen::Success);
  const auto& l = ldlt.matrixL().nestedExpression();
  Fill f;
  for(int j = 0; j < l.outerSize(); ++j)
  {
    const double c = double(l.outerIndexPtr()[j + 1] - l.outerIndexPtr()[j]);
    f.nonzeros += c;
    f.flops += c * c;
  }
  return f;
}

} // namespace

TEST_CASE("Nested dissection: a permutation of every pattern", "[ordering]")
{
  using ND = SD::Nested_dissection_ordering<int>;
  SECTION("empty and single") {
    require_permutation(ordering_of<ND>(SDI::Sparse_matrix(0, 0)), 0);
    require_permutation(ordering_of<ND>(graph_matrix(1, {})), 1);
  }
  SECTION("isolated vertices (a diagonal matrix of 1000)") {
    require_permutation(ordering_of<ND>(graph_matrix(1000, {})), 1000);
  }
  SECTION("a complete graph of 150 vertices (no level separates it)") {
    std::vector<std::pair<int, int>> edges;
    for(int i = 0; i < 150; ++i)
      for(int j = i + 1; j < 150; ++j)
        edges.push_back({i, j});
    require_permutation(ordering_of<ND>(graph_matrix(150, edges)), 150);
  }
  SECTION("a path of 5000 vertices and a star of 300") {
    std::vector<std::pair<int, int>> edges;
    for(int i = 0; i + 1 < 5000; ++i)
      edges.push_back({i, i + 1});
    for(int i = 1; i < 300; ++i)
      edges.push_back({5000, 5000 + i});
    const SDI::Sparse_matrix a = graph_matrix(5300, edges);
    const Permutation p = ordering_of<ND>(a);
    require_permutation(p, 5300);
    // eliminating a path vertex joins its two neighbours: the graph stays a path, so no column
    // of L has more than 2 entries; the star's centre separates its leaves, so it comes after
    // them and their columns have 1 entry each
    REQUIRE(fill_of(a, p).nonzeros <= 2. * 4999. + 299.);
    std::vector<int> position(5300);
    for(int k = 0; k < 5300; ++k)
      position[std::size_t(p.indices()[k])] = k;
    for(int i = 1; i < 300; ++i)
      REQUIRE(position[std::size_t(5000 + i)] < position[5000]);
  }
  SECTION("one stored triangle is enough: the pattern is symmetrized") {
    const SDI::Sparse_matrix a = triangulated_grid(30);
    const SDI::Sparse_matrix lower = a.triangularView<Eigen::Lower>();
    REQUIRE(ordering_of<ND>(lower).indices() == ordering_of<ND>(a).indices());
  }
}

// the mesh data structure only feeds the matrix here (the Laplacian's independence of it: test_geometry_dec)
TEST_CASE("Nested dissection: a permutation of mesh Laplacians, several components and holes", "[ordering]")
{
  for(const std::string name : {"bunny_1k.off", "blobby_3cc.off", "mech-holes-shark.off", "bones.off"})
  {
    INFO(name);
    const SDI::Sparse_matrix a = screened_laplacian(test::load_mesh<test::Surface_mesh>(name));
    require_permutation(ordering_of<SD::Nested_dissection_ordering<int>>(a), a.rows());
  }
}

TEST_CASE("Nested dissection: parts dissected concurrently give a permutation of the same quality", "[ordering]")
{
  // run_parallel (used with TBB from 50k vertices on) cuts the graph into parts ordered by their
  // own dissectors on copies of the parts; called directly here on smaller graphs, with and
  // without several components
  const SDI::Sparse_matrix grid = triangulated_grid(150);
  const SDI::Sparse_matrix blobs = screened_laplacian(test::load_mesh<test::Surface_mesh>("blobby_3cc.off"));
  for(const SDI::Sparse_matrix* a : {&grid, &blobs})
  {
    const SDI::Adjacency_graph g = SDI::symmetric_adjacency(*a);
    const std::vector<int> sequential = SDI::nested_dissection_detail::Dissector(g).run();
    const std::vector<int> concurrent = SDI::nested_dissection_detail::Dissector(g).run_parallel();
    REQUIRE(SDI::nested_dissection_detail::Dissector(g).run_parallel() == concurrent); // deterministic
    Permutation p_sequential(a->rows()), p_concurrent(a->rows());
    for(Eigen::Index k = 0; k < a->rows(); ++k)
    {
      p_sequential.indices()[k] = sequential[std::size_t(k)];
      p_concurrent.indices()[k] = concurrent[std::size_t(k)];
    }
    require_permutation(p_concurrent, a->rows());
    const Fill f_sequential = fill_of(*a, p_sequential), f_concurrent = fill_of(*a, p_concurrent);
    INFO("nnz sequential " << f_sequential.nonzeros << ", concurrent " << f_concurrent.nonzeros);
    REQUIRE(f_concurrent.nonzeros <= 1.1 * f_sequential.nonzeros);
    REQUIRE(f_concurrent.flops <= 1.2 * f_sequential.flops);
  }
}

TEST_CASE("Nested dissection: fewer factor flops than minimum degree on large planar meshes", "[ordering]")
{
  // Nested dissection's flops grow as n^1.5 on planar graphs (Lipton, Rose & Tarjan), minimum
  // degree's faster: on a 200 x 200 triangulated grid (40k unknowns) and larger the dissection
  // must win. Its fill must also stay O(n log n): below 4 n log2 n on every size (measured:
  // 2.2-2.5 n log2 n).
  for(int k : {100, 200, CGAL_SURFACE_DESIGN_TESTS_UNDER_SANITIZERS ? 200 : 400})
  {
    INFO("grid " << k << " x " << k);
    const SDI::Sparse_matrix a = triangulated_grid(k);
    const Fill nd = fill_of(a, ordering_of<SD::Nested_dissection_ordering<int>>(a));
    const Fill amd = fill_of(a, ordering_of<Eigen::AMDOrdering<int>>(a));
    const double n = double(k) * k;
    INFO("flops ND " << nd.flops << " AMD " << amd.flops << ", nnz ND " << nd.nonzeros << " AMD " << amd.nonzeros);
    REQUIRE(nd.nonzeros <= 4. * n * std::log2(n));
    if(k >= 200)
      REQUIRE(nd.flops < amd.flops);
  }
}

TEST_CASE("Nested dissection LDLT: the same solutions as the default solver to 1e-10", "[ordering]")
{
  for(const std::string name : {"bunny_8k.off", "mech-holes-shark.off", "blobby_3cc.off"})
  {
    INFO(name);
    const SDI::Sparse_matrix a = screened_laplacian(test::load_mesh<test::Surface_mesh>(name));
    SDI::Factored_system<SD::Default_solver_traits> amd;
    SDI::Factored_system<SD::Nested_dissection_ldlt_solver_traits> nd;
    amd.factor(SDI::Sparse_matrix(a));
    nd.factor(SDI::Sparse_matrix(a));
    for(unsigned seed = 1; seed <= 3; ++seed)
    {
      const Eigen::VectorXd b = test_vector(a.rows(), seed);
      const Eigen::VectorXd x = nd.solve(b);
      REQUIRE((a * x - b).norm() <= 1e-10 * a.norm() * x.norm());
      REQUIRE((x - amd.solve(b)).norm() <= 1e-10 * x.norm());
    }
  }
}

TEST_CASE("Nested dissection LDLT: Hermitian systems in complex arithmetic", "[ordering]")
{
  // a Hermitian positive definite matrix on the kitten's graph: a magnetic graph Laplacian
  // (off-diagonal -e^{+-0.3 i}) plus the identity, diagonally dominant
  using test::Complex_matrix;
  const Complex_matrix a = test::magnetic_laplacian(screened_laplacian(test::load_mesh<test::Surface_mesh>("kitten.off")));
  const Eigen::VectorXcd b = test::complex_test_vector(a.rows(), 7);
  Eigen::SimplicialLDLT<Complex_matrix, Eigen::Lower, SD::Nested_dissection_ordering<int>> nd(a);
  Eigen::SimplicialLDLT<Complex_matrix> amd(a);
  REQUIRE(nd.info() == Eigen::Success);
  const Eigen::VectorXcd x = nd.solve(b);
  REQUIRE((a * x - b).norm() <= 1e-10 * a.norm() * x.norm());
  REQUIRE((x - amd.solve(b)).norm() <= 1e-10 * x.norm());

  // the library's Hermitian systems take the complex path with these traits, as with the default
  test::require_hermitian_system_solution<SD::Nested_dissection_ldlt_solver_traits>(a, b, x);
}

TEMPLATE_TEST_CASE("Nested dissection LDLT and the supernodal Cholesky through a package: BFF flattens exactly as "
                   "with the default", "[ordering]", SD_MESH_TYPES)
{
  // the hemisphere is a disk: one Dirichlet and one Neumann factorization
  const TestType mesh = test::load_mesh<TestType>("hemisphere.off");
  using Uv = std::map<typename boost::graph_traits<TestType>::vertex_descriptor, test::Kernel::Point_2>;
  auto flatten = [&](auto traits) {
    using Traits = decltype(traits);
    SD::Boundary_first_flattener<TestType, typename boost::property_map<TestType, CGAL::vertex_point_t>::const_type, Traits>
      bff(mesh);
    Uv uv;
    bff.flatten(boost::make_assoc_property_map(uv));
    return uv;
  };
  const Uv reference = flatten(SD::Default_solver_traits());
  for(const Uv& other : {flatten(SD::Nested_dissection_ldlt_solver_traits()), flatten(SD::Supernodal_solver_traits())})
  {
    REQUIRE(other.size() == reference.size());
    double largest = 0., difference = 0.;
    for(const auto& [v, p] : reference)
    {
      largest = std::max(largest, std::abs(p.x()) + std::abs(p.y()));
      difference = std::max(difference, std::abs(p.x() - other.at(v).x()) + std::abs(p.y() - other.at(v).y()));
    }
    REQUIRE(difference <= 1e-10 * largest);
  }
}
