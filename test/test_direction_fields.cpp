// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Direction fields: smoothest fields (tangency, Poincaré-Hopf, the eigenvalue against a dense
// eigensolver and Rayleigh quotients, planar disks, boundary and curvature alignment), the
// singularity index on analytic fields, trivial connections (exactly the prescribed
// singularities, zero holonomy elsewhere, least-norm optimality, re-solves), bad input.

#include <largest_face_angles.h>
#include <test_support.h>

#include <CGAL/Surface_design/direction_fields.h>
#include <CGAL/Surface_design/mesh_generators.h>
#include <CGAL/Surface_design/Trivial_connection.h>

#include <CGAL/boost/graph/copy_face_graph.h>

#include <Eigen/Dense>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseLU>

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <random>

namespace SD = CGAL::Surface_design;
namespace SDI = CGAL::Surface_design::internal;

namespace {

using SDI::pi;

using Vector = test::Kernel::Vector_3;

template <class Mesh>
using Vertex = typename boost::graph_traits<Mesh>::vertex_descriptor;
template <class Mesh>
using Face = typename boost::graph_traits<Mesh>::face_descriptor;
template <class Mesh>
using Vector_map = std::map<Vertex<Mesh>, Vector>;
using test::Vpm;

template <class Mesh>
Mesh make_case(const std::string& name)
{
  Mesh mesh;
  if(name == "sphere")
    SD::make_sphere(mesh, 6);
  else if(name == "small sphere")
    SD::make_sphere(mesh, 4);
  else if(name == "torus")
    SD::make_torus(mesh, 40, 12, 1., 0.3, true);
  else if(name == "disk")
    SD::make_grid(mesh, 12, 12, 0.15);
  else if(name == "grid with holes")
    SD::make_grid(mesh, 16, 16, 0.1, [](std::size_t i, std::size_t j) {
      return (i >= 3 && i < 6 && j >= 3 && j < 6) || (i >= 10 && i < 12 && j >= 9 && j < 13);
    });
  else
    mesh = test::load_mesh<Mesh>(name);
  return mesh;
}

template <class Mesh>
long euler_characteristic(const Mesh& mesh)
{
  return long(num_vertices(mesh)) - long(num_edges(mesh)) + long(num_faces(mesh));
}

Eigen::Vector3d to_eigen(const Vector& v) { return Eigen::Vector3d(v.x(), v.y(), v.z()); }

template <class Mesh>
std::map<Face<Mesh>, double> indices_of(const Mesh& mesh, const Vector_map<Mesh>& field, int n)
{
  std::map<Face<Mesh>, int> numerator; // the index in units of 1/n
  SD::direction_field_singularities(mesh, boost::make_assoc_property_map(field),
                                    boost::make_assoc_property_map(numerator),
                                    SD::parameters::symmetry_order(n));
  std::map<Face<Mesh>, double> index;
  for(const auto& [f, k] : numerator)
    index[f] = double(k) / n;
  return index;
}

// Every vector is tangent to the angle-weighted vertex normal and has unit length.
template <class Mesh>
void check_unit_tangent(const Mesh& mesh, const Vector_map<Mesh>& field)
{
  const SDI::Mesh_indices<Mesh> idx(mesh);
  const auto normal = SDI::vertex_normals(idx, get(CGAL::vertex_point, mesh));
  for(auto v : vertices(mesh))
  {
    const Eigen::Vector3d x = to_eigen(field.at(v));
    REQUIRE(std::abs(x.norm() - 1.) < 1e-12);
    REQUIRE(std::abs(x.dot(normal[idx.index(v)])) <= 1e-9 * x.norm());
  }
}

// The complex value u_v of a field (n-th power representation) in the vertex frames.
template <class Mesh>
Eigen::VectorXd complex_values(const Mesh& mesh, const SDI::Discrete_connection& c,
                               const Vector_map<Mesh>& field, int n)
{
  const SDI::Mesh_indices<Mesh> idx(mesh);
  Eigen::VectorXd u(2 * num_vertices(mesh));
  for(std::size_t v = 0; v < idx.number_of_vertices(); ++v)
  {
    const Eigen::Vector3d x = to_eigen(field.at(idx.vertex(v)));
    const double a = n * c.frames.to_angle(v, x);
    u[Eigen::Index(2 * v)] = x.norm() * std::cos(a);
    u[Eigen::Index(2 * v + 1)] = x.norm() * std::sin(a);
  }
  return u;
}

} // namespace

TEMPLATE_TEST_CASE("Singularity index of analytic fields on a planar disk", "[direction_fields]", SD_MESH_TYPES)
{
  const TestType mesh = make_case<TestType>("disk");
  // the face containing the centre (0.5, 0.5) + a small offset that avoids vertices and edges
  const Eigen::Vector3d c(0.5 + 0.013, 0.5 + 0.021, 0.);
  Face<TestType> centre{};
  for(auto f : faces(mesh))
  {
    std::vector<Eigen::Vector3d> p;
    for(auto v : vertices_around_face(halfedge(f, mesh), mesh))
    {
      const auto& q = get(CGAL::vertex_point, mesh, v);
      p.emplace_back(q.x(), q.y(), 0.);
    }
    auto side = [&](int i) { return (p[(i + 1) % 3] - p[i]).cross(c - p[i]).z(); };
    if(side(0) > 0 && side(1) > 0 && side(2) > 0)
      centre = f;
  }
  REQUIRE(centre != Face<TestType>());

  struct Case
  {
    int n;
    double turns; // the field's angle is turns * (polar angle around c)
    double index;
  };
  for(const Case& k : {Case{1, 1., 1.}, Case{1, -1., -1.}, Case{1, 2., 2.}, Case{2, 0.5, 0.5},
                       Case{4, -0.25, -0.25}, Case{4, 0.75, 0.75}, Case{1, 0., 0.}})
  {
    Vector_map<TestType> field;
    for(auto v : vertices(mesh))
    {
      const auto& q = get(CGAL::vertex_point, mesh, v);
      const double phi = std::atan2(q.y() - c.y(), q.x() - c.x());
      field[v] = Vector(std::cos(k.turns * phi + 0.3), std::sin(k.turns * phi + 0.3), 0.);
    }
    const auto index = indices_of(mesh, field, k.n);
    INFO("n = " << k.n << ", turns = " << k.turns);
    if(std::abs(k.index) * k.n <= 1.)
    {
      for(auto f : faces(mesh))
        REQUIRE(index.at(f) == (f == centre ? k.index : 0.));
    }
    else
    {
      // more than 1/n cannot sit in one triangle (the field turns by less than pi per edge):
      // the index is shared by faces around the centre, and adds up
      double sum = 0.;
      for(auto f : faces(mesh))
        if(index.at(f) != 0.)
        {
          sum += index.at(f);
          for(auto v : vertices_around_face(halfedge(f, mesh), mesh))
          {
            const auto& q = get(CGAL::vertex_point, mesh, v);
            REQUIRE(std::hypot(q.x() - c.x(), q.y() - c.y()) < 0.2);
          }
        }
      REQUIRE(sum == k.index);
    }
  }
}

TEMPLATE_TEST_CASE("Smoothest fields: tangent, unit, and Poincaré-Hopf", "[direction_fields]", SD_MESH_TYPES)
{
  for(const std::string name : {"sphere", "torus", "eight.off", "bunny_1k.off"})
    for(int n : {1, 2, 4})
    {
      const TestType mesh = make_case<TestType>(name);
      Vector_map<TestType> field;
      const SD::Smoothest_direction_field_result info = SD::smoothest_direction_field(
        mesh, boost::make_assoc_property_map(field), SD::parameters::symmetry_order(n));
      INFO(name << ", n = " << n);
      REQUIRE(info.converged);
      REQUIRE(info.eigenvalues.size() == 1);
      REQUIRE(info.eigenvalues[0] > 0.); // curved closed surfaces have no parallel field
      check_unit_tangent(mesh, field);
      double sum = 0.;
      for(const auto& fi : indices_of(mesh, field, n))
      {
        REQUIRE(std::abs(fi.second * n - std::round(fi.second * n)) < 1e-12); // multiples of 1/n
        sum += fi.second;
      }
      REQUIRE(std::abs(sum - double(euler_characteristic(mesh))) < 1e-9);
      if(name == "sphere" && n == 1)
        REQUIRE(sum == 2.);
    }
}

TEMPLATE_TEST_CASE("Smoothest field on a sphere: the smallest eigenvalue, never undercut", "[direction_fields]",
                   SD_MESH_TYPES)
{
  const TestType mesh = make_case<TestType>("small sphere");
  const SDI::Mesh_indices<TestType> idx(mesh);
  const auto vpm = get(CGAL::vertex_point, mesh);
  const SDI::Discrete_connection c = SDI::levi_civita_connection(idx, vpm);
  for(int n : {1, 2, 4})
  {
    // the generalized eigenproblem A u = lambda M u, dense and independent of inverse iteration
    const Eigen::MatrixXd a = Eigen::MatrixXd(SDI::connection_laplacian(idx, c, SDI::cotangent_weights(idx, vpm), n));
    const std::vector<double> mass = SDI::vertex_areas(idx, SDI::face_areas(idx, vpm));
    Eigen::MatrixXd m = Eigen::MatrixXd::Zero(a.rows(), a.cols());
    for(std::size_t v = 0; v < mass.size(); ++v)
      m(2 * v, 2 * v) = m(2 * v + 1, 2 * v + 1) = mass[v];
    Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> dense(a, m);
    const double lambda_min = dense.eigenvalues()[0];

    auto rayleigh = [&](const Eigen::VectorXd& u) { return u.dot(a * u) / u.dot(m * u); };
#define SD_RUN(Solver, label)                                                                      \
    {                                                                                              \
      INFO("n = " << n << ", solver " << label);                                                   \
      Vector_map<TestType> field;                                                                  \
      const auto info = SD::smoothest_direction_field(                                             \
        mesh, boost::make_assoc_property_map(field),                                               \
        SD::parameters::symmetry_order(n, SD::parameters::normalize_field(false,                     \
          SD::parameters::sparse_linear_solver(Solver()))));                                       \
      REQUIRE(info.converged);                                                                     \
      REQUIRE(std::abs(info.eigenvalues[0] - lambda_min) <= 1e-8 * lambda_min);                    \
      const Eigen::VectorXd u = complex_values(mesh, c, field, n);                                 \
      REQUIRE(std::abs(rayleigh(u) - lambda_min) <= 1e-8 * lambda_min);                            \
      /* the field's magnitude is scaled to sum m |u|^2 = area */                                  \
      double area = 0.;                                                                            \
      for(double mv : mass)                                                                        \
        area += mv;                                                                                \
      REQUIRE(std::abs(u.dot(m * u) - area) <= 1e-9 * area);                                       \
      std::mt19937 random(7);                                                                      \
      std::normal_distribution<double> normal;                                                     \
      for(int trial = 0; trial < 20; ++trial)                                                      \
      {                                                                                            \
        Eigen::VectorXd r(u.size());                                                               \
        for(Eigen::Index i = 0; i < r.size(); ++i)                                                 \
          r[i] = normal(random);                                                                   \
        REQUIRE(rayleigh(r) >= lambda_min * (1. - 1e-12));                                         \
        const double size = std::pow(10., -1 - trial % 6);                                         \
        REQUIRE(rayleigh(u + size * r.norm() / u.norm() * r) >= lambda_min * (1. - 1e-12));        \
      }                                                                                            \
    }
    SD_FOR_EACH_SOLVER(SD_RUN)
#undef SD_RUN
  }
}

TEST_CASE("Smoothest field on a scanned mesh of 4k vertices: optimal against independent inverse iteration",
          "[direction_fields]")
{
  // bunny_8k: 4151 vertices. The reference eigenpair comes from plain inverse iteration on a
  // sparse LU factorization of A (not Lanczos, not LDLT) with A assembled here from its formula
  // by triplets (not by the library's assembly), so that a wrong assembly, a wrong eigenvector
  // or a stalled Lanczos process would all show.
  using Mesh = test::Surface_mesh;
  const Mesh mesh = test::load_mesh<Mesh>("bunny_8k.off");
  const SDI::Mesh_indices<Mesh> idx(mesh);
  const auto vpm = get(CGAL::vertex_point, mesh);
  const SDI::Discrete_connection c = SDI::levi_civita_connection(idx, vpm);
  const std::vector<double> w = SDI::cotangent_weights(idx, vpm);
  const std::vector<double> mass = SDI::vertex_areas(idx, SDI::face_areas(idx, vpm));
  const Eigen::Index nv = Eigen::Index(idx.number_of_vertices());
  for(int n : {1, 4})
  {
    INFO("n = " << n);
    std::vector<Eigen::Triplet<std::complex<double>>> t;
    for(std::size_t e = 0; e < idx.number_of_edges(); ++e)
    {
      const auto ij = idx.edge_vertices(e);
      const Eigen::Index i = Eigen::Index(ij.first), j = Eigen::Index(ij.second);
      const std::complex<double> r = std::polar(1., n * c.rho[e]); // transport i -> j, n-fold
      t.emplace_back(i, i, w[e]);
      t.emplace_back(j, j, w[e]);
      t.emplace_back(j, i, -w[e] * r);
      t.emplace_back(i, j, -w[e] * std::conj(r));
    }
    Eigen::SparseMatrix<std::complex<double>> a(nv, nv);
    a.setFromTriplets(t.begin(), t.end());
    Eigen::SparseLU<Eigen::SparseMatrix<std::complex<double>>> lu(a);
    REQUIRE(lu.info() == Eigen::Success);
    const Eigen::Map<const Eigen::VectorXd> m(mass.data(), nv);
    auto rayleigh = [&](const Eigen::VectorXcd& u) {
      return (u.dot(a * u)).real() / (u.dot(m.cast<std::complex<double>>().cwiseProduct(u))).real();
    };
    Eigen::VectorXcd x = Eigen::VectorXcd::Ones(nv);
    double lambda = rayleigh(x), previous = 0.;
    for(int it = 0; it < 2000 && std::abs(lambda - previous) > 1e-15 * lambda; ++it)
    {
      x = lu.solve(Eigen::VectorXcd(m.cast<std::complex<double>>().cwiseProduct(x)));
      x /= x.norm();
      previous = lambda;
      lambda = rayleigh(x);
    }
    // the reference is an eigenpair: the residual of A x = lambda M x is at rounding level
    const Eigen::VectorXcd residual = a * x - lambda * m.cast<std::complex<double>>().cwiseProduct(x);
    REQUIRE(residual.norm() <= 1e-7 * lambda * (m.cast<std::complex<double>>().cwiseProduct(x)).norm());

    Vector_map<Mesh> field;
    const auto info = SD::smoothest_direction_field(
      mesh, boost::make_assoc_property_map(field),
      SD::parameters::symmetry_order(n, SD::parameters::normalize_field(false)));
    REQUIRE(info.converged);
    REQUIRE(std::abs(info.eigenvalues[0] - lambda) <= 1e-8 * lambda);
    const Eigen::VectorXd ur = complex_values(mesh, c, field, n);
    Eigen::VectorXcd u(nv);
    for(Eigen::Index v = 0; v < nv; ++v)
      u[v] = std::complex<double>(ur[2 * v], ur[2 * v + 1]);
    REQUIRE(std::abs(rayleigh(u) - lambda) <= 1e-8 * lambda);
    // and the field is that eigenvector (up to a global phase): |<x, u>_M| = |x|_M |u|_M
    const std::complex<double> inner = x.dot(m.cast<std::complex<double>>().cwiseProduct(u));
    const double nx = std::sqrt((x.dot(m.cast<std::complex<double>>().cwiseProduct(x))).real());
    const double nu = std::sqrt((u.dot(m.cast<std::complex<double>>().cwiseProduct(u))).real());
    REQUIRE(std::abs(inner) >= (1. - 1e-8) * nx * nu);
  }
}

TEST_CASE("Shift-invert Lanczos: several components, restarts, non-convergence", "[direction_fields]")
{
  // Block-diagonal S (three path-graph Laplacians plus a shift, sizes 30, 45, 60) and a positive
  // diagonal M: the largest theta of M x = theta S x per block, against a dense eigensolver.
  const std::vector<Eigen::Index> size{30, 45, 60};
  const Eigen::Index N = size[0] + size[1] + size[2];
  std::vector<Eigen::Triplet<double>> t;
  std::vector<std::size_t> group(static_cast<std::size_t>(N));
  Eigen::VectorXd mass(N);
  std::mt19937 random(11);
  std::uniform_real_distribution<double> uniform(0.5, 2.);
  Eigen::Index begin = 0;
  for(std::size_t g = 0; g < size.size(); ++g)
  {
    for(Eigen::Index i = begin; i < begin + size[g]; ++i)
    {
      group[std::size_t(i)] = g;
      mass[i] = uniform(random);
      t.emplace_back(i, i, 2. + 0.01 * double(g + 1));
      if(i + 1 < begin + size[g])
      {
        t.emplace_back(i, i + 1, -1.);
        t.emplace_back(i + 1, i, -1.);
      }
    }
    begin += size[g];
  }
  Eigen::SparseMatrix<double> S(N, N);
  S.setFromTriplets(t.begin(), t.end());
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt(S);
  auto solve = [&ldlt](const Eigen::VectorXd& b, Eigen::VectorXd& x) { x = ldlt.solve(b); };

  std::vector<double> reference(size.size());
  begin = 0;
  for(std::size_t g = 0; g < size.size(); ++g)
  {
    const Eigen::MatrixXd Sg = Eigen::MatrixXd(S).block(begin, begin, size[g], size[g]);
    const Eigen::MatrixXd Mg = mass.segment(begin, size[g]).asDiagonal();
    Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> dense(Mg, Sg);
    reference[g] = dense.eigenvalues()[size[g] - 1];
    begin += size[g];
  }
  Eigen::VectorXd start(N);
  for(Eigen::Index i = 0; i < N; ++i)
    start[i] = uniform(random) - 1.25;
  const std::vector<bool> active{true, false, true};

  auto check = [&](const SDI::Lanczos_result& r, double tolerance) {
    for(std::size_t g = 0; g < size.size(); ++g)
    {
      double norm2 = 0.;
      for(Eigen::Index i = 0; i < N; ++i)
        if(group[std::size_t(i)] == g)
          norm2 += mass[i] * r.x[i] * r.x[i];
      if(!active[g])
      {
        REQUIRE(norm2 == 0.); // inactive groups stay zero
        continue;
      }
      REQUIRE(std::abs(norm2 - 1.) <= 1e-10); // unit M-norm per group
      REQUIRE(std::abs(r.theta[g] - reference[g]) <= tolerance * reference[g]);
    }
  };
  SECTION("converges per active group, sharing back-substitutions")
  {
    const SDI::Lanczos_result r = SDI::largest_eigenvectors_by_group(solve, mass, group, active, start, 1e-10, 500);
    REQUIRE(r.converged);
    check(r, 1e-12);
  }
  SECTION("explicit restarts when the basis is full")
  {
    const SDI::Lanczos_result r =
      SDI::largest_eigenvectors_by_group(solve, mass, group, active, start, 1e-10, 2000, /*max_basis=*/4);
    REQUIRE(r.converged);
    REQUIRE(r.solves > 4); // it had to restart
    check(r, 1e-12);
  }
  SECTION("stops at the iteration limit and says so")
  {
    const SDI::Lanczos_result r = SDI::largest_eigenvectors_by_group(solve, mass, group, active, start, 1e-14, 2);
    REQUIRE_FALSE(r.converged);
    REQUIRE(r.solves == 2);
    for(std::size_t g = 0; g < size.size(); ++g)
      if(active[g])
        REQUIRE(r.theta[g] <= reference[g] * (1. + 1e-12)); // Ritz values approach from below
  }
  SECTION("through the public function: several components, and the iteration limit reported")
  {
    const test::Surface_mesh blobs = test::load_mesh<test::Surface_mesh>("blobby_3cc.off");
    Vector_map<test::Surface_mesh> field;
    const auto all = SD::smoothest_direction_field(blobs, boost::make_assoc_property_map(field));
    REQUIRE(all.converged);
    REQUIRE(all.eigenvalues.size() == 3);
    for(double l : all.eigenvalues)
      REQUIRE(l > 0.);
    const auto limited = SD::smoothest_direction_field(blobs, boost::make_assoc_property_map(field),
                                                       SD::parameters::number_of_iterations(2));
    REQUIRE_FALSE(limited.converged);
    REQUIRE(limited.iterations == 2);
  }
}

TEMPLATE_TEST_CASE("Complex and real forms of the Hermitian system give the same field", "[direction_fields]",
                   SD_MESH_TYPES)
{
  // a solver traits type the library has no complex counterpart for: the real 2|V| form
  using Real_form = CGAL::Eigen_solver_traits<Eigen::SimplicialLLT<CGAL::Eigen_sparse_matrix<double>::EigenType>>;
  static_assert(!SDI::Hermitian_system<Real_form>::uses_complex_arithmetic());
  static_assert(SDI::Hermitian_system<SD::Default_solver_traits>::uses_complex_arithmetic());
  for(const std::string name : {"bunny_1k.off", "hemisphere.off"})
    for(int n : {1, 4})
    {
      const TestType mesh = make_case<TestType>(name);
      const SDI::Mesh_indices<TestType> idx(mesh);
      const auto vpm = get(CGAL::vertex_point, mesh);
      const SDI::Discrete_connection c = SDI::levi_civita_connection(idx, vpm);
      const std::vector<double> mass = SDI::vertex_areas(idx, SDI::face_areas(idx, vpm));
      Vector_map<TestType> complex_field, real_field;
      const auto bc = name == "hemisphere.off" ? SD::Direction_field_boundary::tangent : SD::Direction_field_boundary::free;
      const auto a = SD::smoothest_direction_field(
        mesh, boost::make_assoc_property_map(complex_field),
        SD::parameters::symmetry_order(n, SD::parameters::normalize_field(false, SD::parameters::field_boundary_condition(bc))));
      const auto b = SD::smoothest_direction_field(
        mesh, boost::make_assoc_property_map(real_field),
        SD::parameters::symmetry_order(n, SD::parameters::normalize_field(false, SD::parameters::field_boundary_condition(
                                              bc, SD::parameters::sparse_linear_solver(Real_form())))));
      INFO(name << ", n = " << n);
      REQUIRE(a.iterations == b.iterations);
      if(bc == SD::Direction_field_boundary::free)
        REQUIRE(std::abs(a.eigenvalues[0] - b.eigenvalues[0]) <= 1e-10 * a.eigenvalues[0]);
      // the same complex field up to a global phase
      const Eigen::VectorXd ua = complex_values(mesh, c, complex_field, n), ub = complex_values(mesh, c, real_field, n);
      std::complex<double> inner = 0.;
      double norm2 = 0.;
      for(std::size_t v = 0; v < mass.size(); ++v)
      {
        const std::complex<double> za(ua[2 * v], ua[2 * v + 1]), zb(ub[2 * v], ub[2 * v + 1]);
        inner += mass[v] * std::conj(zb) * za;
        norm2 += mass[v] * std::norm(za);
      }
      const std::complex<double> phase = inner / std::abs(inner);
      double difference = 0.;
      for(std::size_t v = 0; v < mass.size(); ++v)
      {
        const std::complex<double> za(ua[2 * v], ua[2 * v + 1]), zb(ub[2 * v], ub[2 * v + 1]);
        difference += mass[v] * std::norm(za - phase * zb);
      }
      REQUIRE(std::sqrt(difference / norm2) < 1e-8);
    }
}

TEMPLATE_TEST_CASE("A planar disk gives a constant smoothest field", "[direction_fields]", SD_MESH_TYPES)
{
  const TestType mesh = make_case<TestType>("disk");
  for(int n : {1, 2, 4})
  {
    Vector_map<TestType> field;
    const auto info = SD::smoothest_direction_field(
      mesh, boost::make_assoc_property_map(field),
      SD::parameters::symmetry_order(n, SD::parameters::eigen_tolerance(1e-10)));
    REQUIRE(info.converged);
    REQUIRE(std::abs(info.eigenvalues[0]) < 1e-9);
    check_unit_tangent(mesh, field);
    // the same n-direction everywhere: n * angle agrees modulo 2 pi
    const Vector x0 = field.begin()->second;
    const double a0 = std::atan2(x0.y(), x0.x());
    for(const auto& vx : field)
      REQUIRE(std::abs(SDI::wrap_angle(n * (std::atan2(vx.second.y(), vx.second.x()) - a0))) < 1e-7);
    for(const auto& fi : indices_of(mesh, field, n))
      REQUIRE(fi.second == 0.);
  }
}

TEMPLATE_TEST_CASE("Boundary-aligned smoothest fields", "[direction_fields]", SD_MESH_TYPES)
{
  for(const std::string name : {"disk", "grid with holes", "hemisphere.off"})
    for(SD::Direction_field_boundary bc : {SD::Direction_field_boundary::tangent, SD::Direction_field_boundary::normal})
    {
      const TestType mesh = make_case<TestType>(name);
      Vector_map<TestType> field;
      const auto info = SD::smoothest_direction_field(mesh, boost::make_assoc_property_map(field),
                                                      SD::parameters::field_boundary_condition(bc));
      INFO(name);
      REQUIRE(info.iterations == 0); // a linear solve, no eigenproblem
      check_unit_tangent(mesh, field);
      // boundary vertices: along the outgoing boundary edge (tangent) or at a right angle to it,
      // pointing into the surface (normal)
      const SDI::Mesh_indices<TestType> idx(mesh);
      const auto normal = SDI::vertex_normals(idx, get(CGAL::vertex_point, mesh));
      for(auto h : halfedges(mesh))
        if(is_border(opposite(h, mesh), mesh))
        {
          const auto v = source(h, mesh);
          const auto& p = get(CGAL::vertex_point, mesh, v);
          const auto& q = get(CGAL::vertex_point, mesh, target(h, mesh));
          Eigen::Vector3d t(q.x() - p.x(), q.y() - p.y(), q.z() - p.z());
          const Eigen::Vector3d nv = normal[idx.index(v)];
          t = (t - t.dot(nv) * nv).normalized();
          const Eigen::Vector3d x = to_eigen(field.at(v));
          const Eigen::Vector3d expected = bc == SD::Direction_field_boundary::tangent ? t : nv.cross(t);
          // exact on planar meshes; on a curved boundary star the inward normal is measured in the
          // star's own angles, which its projection to the tangent plane distorts a little
          REQUIRE((x - expected).norm() < (bc == SD::Direction_field_boundary::tangent || name != "hemisphere.off" ? 1e-9 : 1e-2));
        }
      // the field is parallel along the straightened boundary: Poincaré-Hopf with chi alone
      double sum = 0.;
      for(const auto& fi : indices_of(mesh, field, 1))
        sum += fi.second;
      REQUIRE(sum == double(euler_characteristic(mesh)));
    }
}

// A slab with a square hole (genus 1): its creases (interior edges whose faces' normals differ by
// more than 30 degrees, read here from the geometry) are straight lines of 90 degrees meeting at
// the box's corners.
TEMPLATE_TEST_CASE("Crease-aligned smoothest fields: one direction along every straight crease", "[direction_fields]",
                   SD_MESH_TYPES)
{
  using Edge = typename boost::graph_traits<TestType>::edge_descriptor;
  TestType mesh;
  SD::make_slab(mesh, 12, 8, 0.3, [](std::size_t i, std::size_t j) { return i >= 4 && i <= 6 && j >= 3 && j <= 4; });
  const SDI::Mesh_indices<TestType> idx(mesh);
  const auto vpm = get(CGAL::vertex_point, mesh);
  auto point = [&](auto v) {
    const auto& p = get(vpm, v);
    return Eigen::Vector3d(p.x(), p.y(), p.z());
  };
  auto face_normal = [&](auto h) {
    const Eigen::Vector3d a = point(source(h, mesh)), b = point(target(h, mesh)),
                          c = point(target(next(h, mesh), mesh));
    return Eigen::Vector3d((b - a).cross(c - a).normalized());
  };
  std::map<Edge, bool> crease;
  std::map<Vertex<TestType>, std::vector<Eigen::Vector3d>> along; // per vertex, its creases' directions
  for(auto e : edges(mesh))
  {
    const auto h = halfedge(e, mesh);
    const bool sharp = !is_border_edge(h, mesh) && face_normal(h).dot(face_normal(opposite(h, mesh))) < std::cos(pi / 6.);
    crease[e] = sharp;
    if(sharp)
    {
      const Eigen::Vector3d d = (point(target(h, mesh)) - point(source(h, mesh))).normalized();
      along[source(h, mesh)].push_back(d);
      along[target(h, mesh)].push_back(-d);
    }
  }
  REQUIRE(along.size() > 50);
  // the vertices inside a straight crease line: two opposite crease directions
  std::vector<Vertex<TestType>> straight;
  for(const auto& [v, d] : along)
    if(d.size() == 2 && d[0].dot(d[1]) < -1. + 1e-12)
      straight.push_back(v);
  REQUIRE(straight.size() > 40);
  const auto normal = SDI::vertex_normals(idx, vpm);
  // how far the field at v is from the crease t: |x . (n x t)| for a line field (0: along it),
  // min(|x . t|, |x . (n x t)|) for a cross field (0: one of its four directions along it)
  auto misalignment = [&](const Vector_map<TestType>& field, int order = 4) {
    double worst = 0.;
    for(auto v : straight)
    {
      const Eigen::Vector3d n = normal[idx.index(v)];
      Eigen::Vector3d t = along.at(v)[0];
      t = (t - t.dot(n) * n).normalized();
      const Eigen::Vector3d x = to_eigen(field.at(v)).normalized();
      const double across = std::abs(x.dot(n.cross(t)));
      worst = (std::max)(worst, order == 2 ? across : (std::min)(std::abs(x.dot(t)), across));
    }
    return worst;
  };
  const auto creases = boost::make_assoc_property_map(crease);
  Vector_map<TestType> aligned, free_field, none;
  const auto info = SD::smoothest_direction_field(
    mesh, boost::make_assoc_property_map(aligned),
    SD::parameters::symmetry_order(4, CGAL::parameters::edge_is_constrained_map(creases)));
  check_unit_tangent(mesh, aligned);
  REQUIRE(info.iterations == 0); // fixed vertices: one linear solve
  CHECK(misalignment(aligned) < 1e-9);
  // exactly the vertices inside the crease lines are fixed: the corners (three creases) stay free
  CHECK(info.feature_vertices == straight.size());
  CHECK(straight.size() + 16 == along.size()); // the box's 8 corners and the hole's 8
  // the control: the free smoothest field is not along the creases (the oracle sees it), and a map
  // without a crease is no map
  SD::smoothest_direction_field(mesh, boost::make_assoc_property_map(free_field), SD::parameters::symmetry_order(4));
  CHECK(misalignment(free_field) > 0.05);
  std::map<Edge, bool> nothing;
  for(auto e : edges(mesh))
    nothing[e] = false;
  const auto info_none = SD::smoothest_direction_field(
    mesh, boost::make_assoc_property_map(none),
    SD::parameters::symmetry_order(4, CGAL::parameters::edge_is_constrained_map(boost::make_assoc_property_map(nothing))));
  CHECK(info_none.feature_vertices == 0);
  for(auto v : vertices(mesh))
    CHECK((to_eigen(none.at(v)) - to_eigen(free_field.at(v))).norm() < 1e-12);
  // a line field (n = 2) follows the creases too; with the normalized flow the fixed vertices stay
  Vector_map<TestType> line;
  SD::smoothest_direction_field(mesh, boost::make_assoc_property_map(line),
                                SD::parameters::symmetry_order(
                                  2, SD::parameters::unit_length_iterations(
                                       10, CGAL::parameters::edge_is_constrained_map(creases))));
  CHECK(misalignment(line, 2) < 1e-9);
#if defined(CGAL_SURFACE_DESIGN_HAS_CHOLMOD)
  Vector_map<TestType> other;
  SD::smoothest_direction_field(mesh, boost::make_assoc_property_map(other),
                                SD::parameters::symmetry_order(
                                  4, CGAL::parameters::edge_is_constrained_map(creases).sparse_linear_solver(
                                       SD::Cholmod_solver_traits())));
  for(auto v : vertices(mesh))
    CHECK((to_eigen(other.at(v)) - to_eigen(aligned.at(v))).norm() < 1e-8);
#else
  SD_CHOLMOD_UNAVAILABLE("the crease-aligned field of both solvers");
#endif
}

// the face centroids of the nonzero indices
template <class Mesh>
std::vector<std::pair<Eigen::Vector3d, double>> cones_with_positions(const Mesh& mesh, const Vector_map<Mesh>& field, int n)
{
  std::vector<std::pair<Eigen::Vector3d, double>> cones;
  for(const auto& [f, k] : indices_of(mesh, field, n))
    if(k != 0.)
    {
      Eigen::Vector3d c = Eigen::Vector3d::Zero();
      for(auto v : vertices_around_face(halfedge(f, mesh), mesh))
      {
        const auto& p = get(CGAL::vertex_point, mesh, v);
        c += Eigen::Vector3d(p.x(), p.y(), p.z()) / 3.;
      }
      cones.emplace_back(c, k);
    }
  return cones;
}

TEMPLATE_TEST_CASE("Boundary-aligned cross fields: the normalized flow moves the linear solve's clustered zeros apart",
                   "[direction_fields]", SD_MESH_TYPES)
{
  // the hemisphere (radius 1): the linear solve's four quarter turns cluster near the pole (|u|
  // ~ r^4 there); the flow's rest point has four +1/4 cones kept apart
  const TestType mesh = make_case<TestType>("hemisphere.off");
  auto field_after = [&](int steps, auto traits) {
    Vector_map<TestType> field;
    SD::smoothest_direction_field(
      mesh, boost::make_assoc_property_map(field),
      SD::parameters::symmetry_order(4, SD::parameters::field_boundary_condition(
                                          SD::Direction_field_boundary::tangent,
                                          SD::parameters::unit_length_iterations(steps).sparse_linear_solver(traits))));
    return field;
  };
  auto closest_pair = [](const std::vector<std::pair<Eigen::Vector3d, double>>& cones) {
    double d = 1e300;
    for(std::size_t i = 0; i < cones.size(); ++i)
      for(std::size_t j = i + 1; j < cones.size(); ++j)
        d = (std::min)(d, (cones[i].first - cones[j].first).norm());
    return d;
  };
  const auto linear = field_after(0, SD::Default_solver_traits());
  const auto linear_cones = cones_with_positions(mesh, linear, 4);
  double linear_sum = 0.;
  for(const auto& c : linear_cones)
    linear_sum += c.second;
  CHECK(linear_sum == 1.); // Poincare-Hopf with chi alone (the boundary is parallel)
  // the oracle below sees the cluster
  CHECK(closest_pair(linear_cones) < 0.15);
#define SD_FLOW_CASE(Traits, label)                                                                     \
  {                                                                                                     \
    CAPTURE(label);                                                                                     \
    const auto flowed = field_after(30, Traits());                                                      \
    check_unit_tangent(mesh, flowed);                                                                   \
    const auto cones = cones_with_positions(mesh, flowed, 4);                                           \
    REQUIRE(cones.size() == 4);                                                                         \
    for(const auto& c : cones)                                                                          \
      CHECK(c.second == 0.25);                                                                          \
    CHECK(closest_pair(cones) > 0.4); /* 0.57 measured: the cones at about 0.4 from the pole */        \
    /* the boundary values are kept */                                                                  \
    for(auto h : halfedges(mesh))                                                                       \
      if(is_border(h, mesh))                                                                            \
        CHECK((to_eigen(flowed.at(target(h, mesh))) - to_eigen(linear.at(target(h, mesh)))).norm() < 1e-12); \
  }
  SD_FOR_EACH_SOLVER(SD_FLOW_CASE)
#undef SD_FLOW_CASE
  // and nothing changes without a boundary condition (the steps apply to Dirichlet components)
  const TestType sphere = make_case<TestType>("small sphere");
  Vector_map<TestType> plain, with_steps;
  SD::smoothest_direction_field(sphere, boost::make_assoc_property_map(plain), SD::parameters::symmetry_order(4));
  SD::smoothest_direction_field(sphere, boost::make_assoc_property_map(with_steps),
                                SD::parameters::symmetry_order(4, SD::parameters::unit_length_iterations(30)));
  for(auto v : vertices(sphere))
    CHECK((to_eigen(plain.at(v)) - to_eigen(with_steps.at(v))).norm() == 0.);
  for(int bad : {-1, 1001})
  {
    Vector_map<TestType> untouched;
    CHECK_THROWS_AS(SD::smoothest_direction_field(mesh, boost::make_assoc_property_map(untouched),
                                                  SD::parameters::unit_length_iterations(bad)),
                    SD::Invalid_parameter);
    CHECK(untouched.empty());
  }
}

TEMPLATE_TEST_CASE("Curvature-aligned cross fields follow the principal directions of a torus",
                   "[direction_fields]", SD_MESH_TYPES)
{
  const TestType mesh = make_case<TestType>("torus");
  for(int n : {2, 4})
  {
    Vector_map<TestType> field;
    SD::smoothest_direction_field(mesh, boost::make_assoc_property_map(field),
                                  SD::parameters::symmetry_order(n, SD::parameters::curvature_alignment_weight(1.)));
    check_unit_tangent(mesh, field);
    // on a torus of revolution about z the principal directions are the parallels (larger
    // curvature on the outer half for n = 2 is not asserted: only the n-fold alignment)
    std::vector<double> error;
    for(auto v : vertices(mesh))
    {
      const auto& p = get(CGAL::vertex_point, mesh, v);
      const Eigen::Vector3d parallel = Eigen::Vector3d(-p.y(), p.x(), 0.).normalized();
      const Eigen::Vector3d x = to_eigen(field.at(v));
      const double c = std::clamp(x.dot(parallel), -1., 1.);
      const double angle = std::acos(c);
      // distance of the angle to the nearest multiple of pi / 2 (n = 4) or pi (n = 2)... in degrees
      const double period = n == 4 ? pi / 2. : pi;
      const double r = std::fmod(angle, period);
      error.push_back((std::min)(r, period - r) * 180. / pi);
    }
    std::sort(error.begin(), error.end());
    INFO("n = " << n << ", median misalignment " << error[error.size() / 2] << " degrees, 95% "
                << error[error.size() * 95 / 100]);
    if(n == 4)
      REQUIRE(error[error.size() * 95 / 100] < 3.);
    else
    {
      // n = 2 picks one of the two principal directions: parallels or meridians, i.e. aligned
      // modulo pi / 2 as well
      std::vector<double> e4;
      for(double e : error)
        e4.push_back((std::min)(e, std::abs(90. - e)));
      std::sort(e4.begin(), e4.end());
      REQUIRE(e4[e4.size() * 95 / 100] < 3.);
    }
  }
  // odd n and planar meshes have nothing to align to
  Vector_map<TestType> field;
  REQUIRE_THROWS_AS(SD::smoothest_direction_field(mesh, boost::make_assoc_property_map(field),
                                                  SD::parameters::curvature_alignment_weight(1.)),
                    SD::Invalid_parameter);
  const TestType disk = make_case<TestType>("disk");
  REQUIRE_THROWS_AS(SD::smoothest_direction_field(disk, boost::make_assoc_property_map(field),
                                                  SD::parameters::symmetry_order(4, SD::parameters::curvature_alignment_weight(1.))),
                    SD::Invalid_parameter);
  REQUIRE(field.empty());
}

namespace {

// Sets the indices (face index, numerator) of a trivial connection; returns them by face.
template <class Tc>
auto prescribe(Tc& tc, const std::vector<std::pair<std::size_t, int>>& singularities)
{
  std::map<typename Tc::face_descriptor, int> prescribed;
  for(const auto& [f, i] : singularities)
  {
    tc.set_index(f, i);
    prescribed[tc.indices().face(f)] = i;
  }
  return prescribed;
}

// The field of a solved trivial connection, checked: every |x_e| below pi, unit tangent vectors,
// exactly the prescribed indices read back from them.
template <class Mesh, class Tc>
Vector_map<Mesh> checked_field(const Mesh& mesh, const Tc& tc, const std::map<Face<Mesh>, int>& prescribed)
{
  REQUIRE(tc.largest_adjustment() < pi);
  Vector_map<Mesh> field;
  tc.field(boost::make_assoc_property_map(field));
  check_unit_tangent(mesh, field);
  const auto index = indices_of(mesh, field, tc.symmetry_order());
  for(auto f : faces(mesh))
  {
    const auto it = prescribed.find(f);
    REQUIRE(index.at(f) == double(it == prescribed.end() ? 0 : it->second) / tc.symmetry_order());
  }
  return field;
}

// Checks a solved trivial connection: exactly the prescribed indices, zero holonomy elsewhere,
// least-norm optimality (the adjustment is co-closed: d0^T x = 0).
template <class Mesh, class Tc>
void check_trivial_connection(const Mesh& mesh, const Tc& tc, const std::map<Face<Mesh>, int>& prescribed)
{
  const int n = tc.symmetry_order();
  const auto& idx = tc.indices();
  checked_field(mesh, tc, prescribed);
  const std::vector<double> x = tc.adjustment();
  const auto& c = tc.connection();
  for(auto f : faces(mesh))
  {
    const auto it = prescribed.find(f);
    const int k = it == prescribed.end() ? 0 : it->second;
    double holonomy = n * c.curvature[idx.index(f)];
    for(auto h : halfedges_around_face(halfedge(f, mesh), mesh))
      holonomy += idx.orientation_sign(h) * x[idx.edge_index(h)];
    REQUIRE(std::abs(holonomy - 2. * pi * k) < 1e-9);
  }
  const Eigen::VectorXd xe = Eigen::Map<const Eigen::VectorXd>(x.data(), Eigen::Index(x.size()));
  const Eigen::VectorXd div = SDI::Sparse_matrix(SDI::d0(idx).transpose()) * xe;
  REQUIRE(div.cwiseAbs().maxCoeff() < 1e-9);
}

} // namespace

TEMPLATE_TEST_CASE("Trivial connections have exactly the prescribed singularities", "[direction_fields]",
                   SD_MESH_TYPES)
{
  struct Case
  {
    std::string mesh;
    int n;
    std::vector<std::pair<std::size_t, int>> singularities; // face index, numerator
  };
  const std::vector<Case> cases = {
    {"sphere", 1, {{10, 1}, {300, 1}}},
    {"sphere", 4, {{3, 1}, {50, 1}, {100, 1}, {150, 1}, {200, 1}, {250, 1}, {300, 1}, {350, 1}}},
    {"sphere", 2, {{5, 1}, {220, 1}, {100, 1}, {400, 1}}},
    {"torus", 1, {}},
    {"torus", 1, {{100, 1}, {700, -1}}},
    {"eight.off", 1, {{10, -1}, {900, -1}}},
    {"disk", 1, {{140, 1}}},
    {"grid with holes", 4, {{40, 1}, {300, -1}}},
  };
  for(const Case& k : cases)
  {
    const TestType mesh = make_case<TestType>(k.mesh);
#define SD_RUN(Solver, label)                                                                      \
    {                                                                                              \
      INFO(k.mesh << ", n = " << k.n << ", solver " << label);                                     \
      SD::Trivial_connection<TestType, Vpm<TestType>, Solver> tc(                                    \
        mesh, SD::parameters::symmetry_order(k.n, SD::parameters::sparse_linear_solver(Solver())));  \
      const std::map<Face<TestType>, int> prescribed = prescribe(tc, k.singularities);              \
      tc.solve();                                                                                  \
      check_trivial_connection(mesh, tc, prescribed);                                              \
    }
    SD_FOR_EACH_SOLVER(SD_RUN)
#undef SD_RUN
  }
}

namespace {

// Checks a trivial connection whose field follows the boundary: exactly the prescribed indices;
// at every boundary vertex one of the n directions along the boundary edge leaving it (read back
// from the 3D vectors); least norm given the boundary: d0^T x = 0 at every interior vertex, but
// not at every boundary vertex (else the condition would be the free problem's).
template <class Mesh, class Tc>
void check_boundary_aligned(const Mesh& mesh, const Tc& tc, const std::map<Face<Mesh>, int>& prescribed)
{
  const int n = tc.symmetry_order();
  const auto& idx = tc.indices();
  const Vector_map<Mesh> field = checked_field(mesh, tc, prescribed);
  const auto& frames = tc.connection().frames;
  const SDI::Mesh_indices<Mesh> own(mesh);
  const auto normal = SDI::vertex_normals(own, get(CGAL::vertex_point, mesh));
  for(auto h : halfedges(mesh))
    if(is_border(opposite(h, mesh), mesh))
    {
      const std::size_t v = idx.index(source(h, mesh));
      const Eigen::Vector3d x = to_eigen(field.at(source(h, mesh)));
      // the field's angle in the frame, where the boundary edge leaving v has angle 0
      const double a = n * frames.to_angle(v, x);
      REQUIRE(std::abs(SDI::wrap_angle(a)) < 1e-9);
      // and in 3D: x at a multiple of 2 pi / n from the edge projected to the tangent plane
      const auto& p = get(CGAL::vertex_point, mesh, source(h, mesh));
      const auto& q = get(CGAL::vertex_point, mesh, target(h, mesh));
      Eigen::Vector3d t(q.x() - p.x(), q.y() - p.y(), q.z() - p.z());
      const Eigen::Vector3d nv = normal[own.index(source(h, mesh))];
      t = (t - t.dot(nv) * nv).normalized();
      const double turn = std::atan2(nv.dot(t.cross(x)), t.dot(x));
      REQUIRE(std::abs(SDI::wrap_angle(n * turn)) < 1e-6);
    }
  const std::vector<double> x = tc.adjustment();
  const Eigen::VectorXd xe = Eigen::Map<const Eigen::VectorXd>(x.data(), Eigen::Index(x.size()));
  const Eigen::VectorXd div = SDI::Sparse_matrix(SDI::d0(idx).transpose()) * xe;
  double largest_at_boundary = 0.;
  for(auto v : vertices(mesh))
    if(CGAL::is_border(v, mesh))
      largest_at_boundary = (std::max)(largest_at_boundary, std::abs(div[Eigen::Index(idx.index(v))]));
    else
      REQUIRE(std::abs(div[Eigen::Index(idx.index(v))]) < 1e-9);
  REQUIRE(largest_at_boundary > 1e-3);
}

} // namespace

TEMPLATE_TEST_CASE("Trivial connections along the boundary: the field follows it, the sum is Poincaré-Hopf's "
                   "with the boundary's corners, the rest of least norm", "[direction_fields][boundary]",
                   SD_MESH_TYPES)
{
  struct Case
  {
    std::string mesh;
    int n;
    long required; // Poincaré-Hopf: n chi less the corners the field turns with (see the class)
    std::vector<std::pair<std::size_t, int>> singularities;
  };
  // the square: its corners turn by 90 degrees, a full turn for n = 4 (no cone needed) and a
  // quarter for n = 1 (one +1 inside); the grid with two square holes, chi = -1: a constant
  // cross field follows all three loops; the hemisphere's equator is a geodesic: 4 chi = 4
  const std::vector<Case> cases = {
    {"disk", 4, 0, {{40, 1}, {200, -1}}},
    {"disk", 1, 1, {{140, 1}}},
    {"grid with holes", 4, 0, {{200, 1}, {250, -1}}},
    {"hemisphere.off", 4, 4, {{275, 1}, {128, 1}, {2759, 1}, {3511, 1}, {2586, 1}, {1840, -1}}},
  };
  for(const Case& k : cases)
  {
    const TestType mesh = make_case<TestType>(k.mesh);
#define SD_RUN(Solver, label)                                                                      \
    {                                                                                              \
      INFO(k.mesh << ", n = " << k.n << ", solver " << label);                                     \
      SD::Trivial_connection<TestType, Vpm<TestType>, Solver> tc(                                    \
        mesh, SD::parameters::symmetry_order(k.n, SD::parameters::field_boundary_condition(          \
                SD::Direction_field_boundary::tangent, SD::parameters::sparse_linear_solver(Solver())))); \
      REQUIRE(tc.required_index_sum(0) == std::optional<long>(k.required));                        \
      const std::map<Face<TestType>, int> prescribed = prescribe(tc, k.singularities);              \
      tc.solve();                                                                                  \
      check_boundary_aligned(mesh, tc, prescribed);                                                \
      /* the free connection with the same cones: its norm is the smaller one (fewer constraints) */ \
      SD::Trivial_connection<TestType, Vpm<TestType>, Solver> free(                                  \
        mesh, SD::parameters::symmetry_order(k.n, SD::parameters::sparse_linear_solver(Solver()))); \
      prescribe(free, k.singularities);                                                            \
      free.solve();                                                                                \
      REQUIRE(free.required_index_sum(0) == std::nullopt);                                         \
      REQUIRE(free.adjustment_norm2() < tc.adjustment_norm2());                                    \
    }
    SD_FOR_EACH_SOLVER(SD_RUN)
#undef SD_RUN
  }
}

TEMPLATE_TEST_CASE("Trivial connections along the boundary: the inward normal, rotations, several components, "
                   "bad sums and values", "[direction_fields][boundary]", SD_MESH_TYPES)
{
  // the normal condition: the same connection, the field a quarter turn away (n = 1)
  const TestType disk = make_case<TestType>("disk");
  SD::Trivial_connection<TestType> tangent(
    disk, SD::parameters::field_boundary_condition(SD::Direction_field_boundary::tangent));
  SD::Trivial_connection<TestType> normal(
    disk, SD::parameters::field_boundary_condition(SD::Direction_field_boundary::normal));
  tangent.set_index(std::size_t(140), 1);
  normal.set_index(std::size_t(140), 1);
  tangent.solve();
  normal.solve();
  normal.set_rotation(1.); // not applied: the component has a boundary
  for(auto v : vertices(disk))
    REQUIRE(std::abs(SDI::wrap_angle(normal.angle(v) - tangent.angle(v) - pi / 2.)) < 1e-9);
  REQUIRE(normal.boundary_condition() == SD::Direction_field_boundary::normal);

  // a sphere and a disk in one mesh: the sphere's field rotates, the disk's stays along its boundary
  TestType two = make_case<TestType>("small sphere");
  const std::size_t sphere_faces = num_faces(two);
  CGAL::copy_face_graph(disk, two);
  SD::Trivial_connection<TestType> tc(two, SD::parameters::field_boundary_condition(SD::Direction_field_boundary::tangent));
  const auto& topology = tc.topology();
  REQUIRE(topology.components.size() == 2);
  const std::size_t sphere = topology.components.face_component[0];
  REQUIRE(tc.required_index_sum(sphere) == std::optional<long>(2));
  REQUIRE(tc.required_index_sum(1 - sphere) == std::optional<long>(1));
  CHECK_THROWS_AS(tc.required_index_sum(2), SD::Invalid_parameter);
  tc.set_index(std::size_t(0), 1);
  tc.set_index(std::size_t(7), 1);
  tc.set_index(sphere_faces + 140, 1);
  tc.solve();
  std::vector<double> before;
  for(auto v : vertices(two))
    before.push_back(tc.angle(v));
  tc.set_rotation(0.5);
  std::size_t i = 0;
  for(auto v : vertices(two))
  {
    const bool on_sphere = topology.components.vertex_component[tc.indices().index(v)] == sphere;
    REQUIRE(std::abs(SDI::wrap_angle(tc.angle(v) - before[i++] - (on_sphere ? 0.5 : 0.))) < 1e-12);
  }

  // the indices must sum to what the boundary allows: a clear message
  SD::Trivial_connection<TestType> cross(
    disk, SD::parameters::symmetry_order(4, SD::parameters::field_boundary_condition(SD::Direction_field_boundary::tangent)));
  cross.set_index(std::size_t(40), 1);
  REQUIRE_THROWS_WITH(cross.solve(), Catch::Contains("sum to 1/4 but must sum to 0/4 for a field along the boundary"));
  REQUIRE(!cross.is_solved());
  // a line field cannot follow the square's right angles (half-way between its two directions)
  SD::Trivial_connection<TestType> line(
    disk, SD::parameters::symmetry_order(2, SD::parameters::field_boundary_condition(SD::Direction_field_boundary::tangent)));
  REQUIRE_THROWS_WITH(line.solve(), Catch::Contains("the boundary turns by about 90 degrees at its edge"));
  // without the condition any sum is allowed on a disk
  SD::Trivial_connection<TestType> loose(disk, SD::parameters::symmetry_order(4));
  loose.set_index(std::size_t(40), 1);
  REQUIRE_NOTHROW(loose.solve());
  REQUIRE_THROWS_AS(SD::Trivial_connection<TestType>(
                      disk, SD::parameters::field_boundary_condition(static_cast<SD::Direction_field_boundary>(7))),
                    SD::Invalid_parameter);
}

TEMPLATE_TEST_CASE("Trivial connections move negative singularities out of wide faces", "[direction_fields]",
                   SD_MESH_TYPES)
{
  using Mesh = TestType;
  // a decimated scan (obtuse 40%, angles up to 178.8 degrees), genus 1
  const Mesh mesh = test::load_mesh<Mesh>("kitten_4k_decimated.off");
  SD::Trivial_connection<Mesh, Vpm<Mesh>> tc(mesh, SD::parameters::symmetry_order(4));
  const auto& idx = tc.indices();
  const std::size_t nf = idx.number_of_faces();
  // the largest angle of every face, read here from the points
  const std::vector<double> largest = test::largest_face_angles(mesh, idx);
  auto neighbours = [&](std::size_t f) {
    std::vector<std::size_t> g;
    for(auto h : halfedges_around_face(halfedge(idx.face(f), mesh), mesh))
      g.push_back(idx.index(face(opposite(h, mesh), mesh)));
    return g;
  };
  const double wide = 2. * pi / 3.;
  // a wide face with a neighbour under 120 degrees (the -1/4 cone's), the narrowest neighbour
  // (where it must go), and another wide face, not next to it (a +1/4 cone's, which stays)
  std::size_t a = nf, target = nf, b = nf;
  for(std::size_t f = 0; f < nf && a == nf; ++f)
  {
    if(largest[f] < wide + 0.2)
      continue;
    std::size_t t = f;
    for(std::size_t g : neighbours(f))
      if(largest[g] < largest[t])
        t = g;
    if(largest[t] < wide)
    {
      a = f;
      target = t;
    }
  }
  REQUIRE(a < nf);
  for(std::size_t f = nf; f-- > 0 && b == nf;)
    if(largest[f] >= wide && f != a && f != target)
    {
      const auto ga = neighbours(a);
      if(std::find(ga.begin(), ga.end(), f) == ga.end())
        b = f;
    }
  REQUIRE(b < nf);
  tc.set_index(a, -1);
  tc.set_index(b, 1); // the indices sum to 4 chi = 0
  CHECK(tc.move_singularities_from_wide_faces() == 1);
  CHECK(tc.index(idx.face(a)) == 0);
  CHECK(tc.index(idx.face(target)) == -1);
  CHECK(tc.index(idx.face(b)) == 1);
  // the field has exactly the moved singularities, read from the field itself (not the
  // least-norm check of check_trivial_connection(): on this scan the local correction of
  // adjustments near pi applies)
  {
    Vector_map<Mesh> field;
    tc.field(boost::make_assoc_property_map(field));
    check_unit_tangent(mesh, field);
    const auto index = indices_of(mesh, field, 4);
    std::size_t wrong = 0;
    for(std::size_t f = 0; f < nf; ++f)
    {
      const int k = f == target ? -1 : (f == b ? 1 : 0);
      wrong += index.at(idx.face(f)) == double(k) / 4. ? 0 : 1;
    }
    CHECK(wrong == 0);
  }
  // nothing left to move; a threshold above every angle moves nothing either
  CHECK(tc.move_singularities_from_wide_faces() == 0);
  tc.set_index(target, 0);
  tc.set_index(a, -1);
  CHECK(tc.move_singularities_from_wide_faces(pi) == 0);
  CHECK(tc.index(idx.face(a)) == -1);
  CHECK_THROWS_AS(tc.move_singularities_from_wide_faces(0.), SD::Invalid_parameter);
  CHECK_THROWS_AS(tc.move_singularities_from_wide_faces(3.5), SD::Invalid_parameter);
  CHECK_THROWS_AS(tc.move_singularities_from_wide_faces(std::nan("")), SD::Invalid_parameter);
  CHECK(tc.index(idx.face(a)) == -1); // a refused call changes nothing
}

TEMPLATE_TEST_CASE("Trivial connections: re-solves, the one-call function, bad sums", "[direction_fields]",
                   SD_MESH_TYPES)
{
  const TestType mesh = make_case<TestType>("sphere");
  SD::Trivial_connection<TestType> tc(mesh);
  const auto& idx = tc.indices();
  const auto f1 = idx.face(10), f2 = idx.face(300), f3 = idx.face(420);
  tc.set_index(f1, 1);
  tc.set_index(f2, 1);
  tc.solve();
  tc.move_singularity(f2, f3);
  tc.solve();
  check_trivial_connection(mesh, tc, {{f1, 1}, {f3, 1}});

  SD::Trivial_connection<TestType> fresh(mesh);
  fresh.set_index(f1, 1);
  fresh.set_index(f3, 1);
  fresh.solve();
  for(auto v : vertices(mesh))
    REQUIRE(std::abs(SDI::wrap_angle(tc.angle(v) - fresh.angle(v))) < 1e-10);
  REQUIRE(std::abs(tc.adjustment_norm2() - fresh.adjustment_norm2()) < 1e-10 * fresh.adjustment_norm2());

  // the one-call function gives the same field
  std::map<Face<TestType>, int> k{{f1, 1}, {f3, 1}};
  Vector_map<TestType> field, expected;
  SD::trivial_connection_field(mesh, boost::make_assoc_property_map(k), boost::make_assoc_property_map(field));
  fresh.field(boost::make_assoc_property_map(expected));
  for(auto v : vertices(mesh))
    REQUIRE((to_eigen(field.at(v)) - to_eigen(expected.at(v))).norm() < 1e-10);

  // Poincaré-Hopf violated: a clear message, nothing written
  k[f3] = 0;
  Vector_map<TestType> untouched;
  try
  {
    SD::trivial_connection_field(mesh, boost::make_assoc_property_map(k), boost::make_assoc_property_map(untouched));
    FAIL("no exception");
  }
  catch(const SD::Invalid_constraints& e)
  {
    const std::string what = e.what();
    INFO(what);
    REQUIRE(what.find("sum to 1 but must sum to 2") != std::string::npos);
  }
  REQUIRE(untouched.empty());
  SD::Trivial_connection<TestType> cross(mesh, SD::parameters::symmetry_order(4));
  cross.set_index(f1, 1);
  REQUIRE_THROWS_WITH(cross.solve(), Catch::Contains("sum to 1/4 but must sum to 2"));
  REQUIRE_THROWS_AS(cross.set_index(std::size_t(100000), 1), SD::Invalid_constraints);
  // a triangle cannot hold more than 1/n
  SD::Trivial_connection<TestType> two(mesh);
  two.set_index(f1, 2);
  REQUIRE_THROWS_WITH(two.solve(), Catch::Contains("at most 1 in magnitude"));
}

TEST_CASE("Trivial connections stay exact on scanned meshes: folded stars, adjustments of pi and more",
          "[direction_fields]")
{
  using Mesh = test::Surface_mesh;
  // The vector <-> angle conversion of the frames is a bijection at every vertex, also at the 22
  // vertices of the triceratops whose projected star folds (it was off by up to pi there).
  const Mesh tri = test::load_mesh<Mesh>("triceratops.off");
  {
    const SD::Trivial_connection<Mesh> probe(tri);
    const SDI::Vertex_frames& fr = probe.connection().frames;
    double error = 0.;
    for(std::size_t v = 0; v < num_vertices(tri); ++v)
      for(int i = 0; i < 720; ++i)
      {
        const double a = 2. * pi * (i + 0.5) / 720.;
        error = (std::max)(error, std::abs(SDI::wrap_angle(fr.to_angle(v, fr.to_vector(v, a)) - a)));
      }
    REQUIRE(error < 1e-9);
  }
  // The written field has exactly the prescribed singularities at every global rotation (which
  // sweeps the direction at every vertex), where the least-norm adjustment of some edges reaches
  // pi or more: triceratops n = 4 (up to 3.97 rad), singular boundary faces of a hemisphere (3.31).
  struct Case
  {
    std::string mesh;
    int n;
    std::vector<std::pair<std::size_t, int>> singularities;
  };
  const std::vector<Case> cases = {
    {"triceratops.off", 1, {{0, 1}, {2455, 1}}},
    {"triceratops.off", 2, {{0, 1}, {945, 1}, {2455, 1}, {5112, 1}}},
    {"triceratops.off", 4, {{0, 1}, {287, 1}, {945, 1}, {2047, 1}, {2319, 1}, {2455, 1}, {4098, 1}, {5112, 1}}},
    {"hemisphere.off", 1, {{0, 1}, {2226, 1}, {3805, -1}}},
    {"hemisphere.off", 4, {{0, 1}, {2226, 1}, {3805, -1}}},
  };
  for(const Case& c : cases)
  {
    INFO(c.mesh << ", n = " << c.n);
    const Mesh mesh = test::load_mesh<Mesh>(c.mesh);
    SD::Trivial_connection<Mesh> tc(mesh, SD::parameters::symmetry_order(c.n));
    std::map<Face<Mesh>, int> prescribed;
    for(const auto& [f, k] : c.singularities)
    {
      tc.set_index(f, k);
      prescribed[tc.indices().face(f)] = k;
    }
    tc.solve();
    REQUIRE(tc.largest_adjustment() <= pi - 1e-3 + 1e-12);
    // the corrected adjustment keeps the prescribed holonomy in every face
    const std::vector<double> x = tc.adjustment();
    const auto& idx = tc.indices();
    for(auto f : faces(mesh))
    {
      double holonomy = c.n * tc.connection().curvature[idx.index(f)];
      for(auto h : halfedges_around_face(halfedge(f, mesh), mesh))
        holonomy += idx.orientation_sign(h) * x[idx.edge_index(h)];
      const auto it = prescribed.find(f);
      REQUIRE(std::abs(holonomy - 2. * pi * (it == prescribed.end() ? 0 : it->second)) < 1e-9);
    }
    for(int r = 0; r < 8; ++r)
    {
      INFO("rotation " << r);
      tc.set_rotation(2. * pi * r / 8.);
      Vector_map<Mesh> field;
      tc.field(boost::make_assoc_property_map(field));
      const auto index = indices_of(mesh, field, c.n);
      std::size_t wrong = 0;
      for(auto f : faces(mesh))
      {
        const auto it = prescribed.find(f);
        wrong += index.at(f) != (it == prescribed.end() ? 0. : double(it->second) / c.n);
      }
      REQUIRE(wrong == 0);
    }
  }
  // No vertex-based cross field on the kitten is free of singularities: around the 3 faces of a
  // spike vertex (rescaled curvature 3.149 rad) it would turn by 4.01 pi along 3 edges.
  const Mesh kitten = test::load_mesh<Mesh>("kitten.off");
  SD::Trivial_connection<Mesh> cross(kitten, SD::parameters::symmetry_order(4));
  REQUIRE_THROWS_WITH(cross.solve(), Catch::Contains("no vertex-based field has these singularities") &&
                                       Catch::Contains("the 3 faces it encloses (139 137 140)") &&
                                       Catch::Contains("1/4, 2/4 or 3/4 there would fit"));
}

TEMPLATE_TEST_CASE("Direction fields reject bad input and leave the mesh untouched", "[direction_fields]",
                   SD_MESH_TYPES)
{
  Vector_map<TestType> field;
  std::map<Face<TestType>, int> index;
  {
    const TestType empty;
    REQUIRE_THROWS_AS(SD::smoothest_direction_field(empty, boost::make_assoc_property_map(field)), SD::Invalid_mesh);
    REQUIRE_THROWS_AS(SD::Trivial_connection<TestType>(empty), SD::Invalid_mesh);
  }
  {
    TestType quads;
    CGAL::make_hexahedron(CGAL::Point_3<test::Kernel>(0, 0, 0), CGAL::Point_3<test::Kernel>(1, 0, 0),
                          CGAL::Point_3<test::Kernel>(1, 1, 0), CGAL::Point_3<test::Kernel>(0, 1, 0),
                          CGAL::Point_3<test::Kernel>(0, 1, 1), CGAL::Point_3<test::Kernel>(0, 0, 1),
                          CGAL::Point_3<test::Kernel>(1, 0, 1), CGAL::Point_3<test::Kernel>(1, 1, 1), quads);
    const test::Mesh_snapshot before(quads);
    try
    {
      SD::smoothest_direction_field(quads, boost::make_assoc_property_map(field));
      FAIL("no exception");
    }
    catch(const SD::Invalid_mesh& e)
    {
      REQUIRE(e.defect() == SD::Mesh_defect::not_triangle);
    }
    REQUIRE(test::Mesh_snapshot(quads) == before);
  }
  {
    TestType degenerate = test::load_mesh<TestType>("degtri_four.off");
    const test::Mesh_snapshot before(degenerate);
    REQUIRE_THROWS_AS(SD::Trivial_connection<TestType>(degenerate), SD::Invalid_mesh);
    REQUIRE(test::Mesh_snapshot(degenerate) == before);
  }
  REQUIRE(field.empty());

  const TestType mesh = make_case<TestType>("sphere");
  const test::Mesh_snapshot before(mesh);
  REQUIRE_THROWS_AS(SD::smoothest_direction_field(mesh, boost::make_assoc_property_map(field),
                                                  SD::parameters::symmetry_order(0)),
                    SD::Invalid_parameter);
  REQUIRE_THROWS_AS(SD::Trivial_connection<TestType>(mesh, SD::parameters::symmetry_order(-1)), SD::Invalid_parameter);
  // a zero or normal field vector makes the index undefined
  for(auto v : vertices(mesh))
    field[v] = Vector(1, 0, 0);
  const auto v0 = *vertices(mesh).begin();
  const SDI::Mesh_indices<TestType> idx(mesh);
  const Eigen::Vector3d n0 = SDI::vertex_normals(idx, get(CGAL::vertex_point, mesh))[idx.index(v0)];
  field[v0] = Vector(n0.x(), n0.y(), n0.z());
  REQUIRE_THROWS_WITH(SD::direction_field_singularities(mesh, boost::make_assoc_property_map(field),
                                                         boost::make_assoc_property_map(index)),
                      Catch::Contains("no tangential component"));
  field[v0] = Vector(std::nan(""), 0, 0);
  REQUIRE_THROWS_WITH(SD::direction_field_singularities(mesh, boost::make_assoc_property_map(field),
                                                         boost::make_assoc_property_map(index)),
                      Catch::Contains("not finite"));
  REQUIRE(index.empty());
  REQUIRE(test::Mesh_snapshot(mesh) == before);
}
