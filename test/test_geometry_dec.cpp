// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Geometry (angles, cotangents, areas, normals, lengths) and DEC operators (d0, d1, Laplacian).

#include <test_support.h>

#include <CGAL/Surface_design/internal/Core/dec.h>
#include <CGAL/Surface_design/internal/Core/discrete_connection.h>
#include <CGAL/Surface_design/internal/Core/geometry.h>
#include <CGAL/Surface_design/internal/Core/Mesh_indices.h>
#include <CGAL/Surface_design/internal/Core/topology.h>
#include <CGAL/Surface_design/mesh_generators.h>

#include <Eigen/Dense>
#include <Eigen/SparseCholesky>

#include <cmath>
#include <random>

#if defined(CGAL_LINKED_WITH_TBB)
#include <tbb/task_arena.h>
#endif

namespace SD = CGAL::Surface_design;
namespace SDI = CGAL::Surface_design::internal;

namespace {

using SDI::pi;

const std::vector<std::string> closed_and_open_meshes = {
  "bunny_1k.off", "torus.off", "eight.off", "hemisphere.off", "mech-holes-shark.off",
  "triceratops.off", "bones.off"};

} // namespace

TEMPLATE_TEST_CASE("d1 * d0 = 0 exactly and both have the documented structure", "[dec]",
                   SD_MESH_TYPES_WITH_IDS)
{
  for(const std::string& name : closed_and_open_meshes)
  {
    INFO(name);
    const TestType mesh = test::load_mesh<TestType>(name);
    SDI::Mesh_indices<TestType> idx(mesh);
    const SDI::Sparse_matrix d0 = SDI::d0(idx), d1 = SDI::d1(idx);
    REQUIRE(d0.rows() == Eigen::Index(idx.number_of_edges()));
    REQUIRE(d0.cols() == Eigen::Index(idx.number_of_vertices()));
    REQUIRE(d1.rows() == Eigen::Index(idx.number_of_faces()));
    REQUIRE(d1.cols() == Eigen::Index(idx.number_of_edges()));

    const SDI::Sparse_matrix dd = d1 * d0;
    for(int k = 0; k < dd.outerSize(); ++k)
      for(SDI::Sparse_matrix::InnerIterator it(dd, k); it; ++it)
        REQUIRE(it.value() == 0.); // exact: integer arithmetic in floating point

    // d0: one -1 at the smaller vertex index, one +1 at the larger
    for(std::size_t e = 0; e < idx.number_of_edges(); ++e)
    {
      const auto ij = idx.edge_vertices(e);
      REQUIRE(d0.coeff(int(e), int(ij.first)) == -1.);
      REQUIRE(d0.coeff(int(e), int(ij.second)) == 1.);
    }
    REQUIRE(d0.nonZeros() == Eigen::Index(2 * idx.number_of_edges()));

    // d1 columns: an interior edge is in two faces with opposite signs (orientability), a border
    // edge in one face
    for(int e = 0; e < d1.outerSize(); ++e)
    {
      int count = 0;
      double sum = 0.;
      for(SDI::Sparse_matrix::InnerIterator it(d1, e); it; ++it)
      {
        REQUIRE(std::abs(it.value()) == 1.);
        ++count;
        sum += it.value();
      }
      const auto h = idx.oriented_halfedge(std::size_t(e));
      const bool border = idx.is_border(h) || idx.is_border(opposite(h, mesh));
      REQUIRE(count == (border ? 1 : 2));
      if(!border)
        REQUIRE(sum == 0.);
    }
  }
}

TEMPLATE_TEST_CASE("Corner angles, areas, lengths and normals are consistent", "[geometry]",
                   SD_MESH_TYPES_WITH_IDS)
{
  for(const std::string& name : closed_and_open_meshes)
  {
    INFO(name);
    const TestType mesh = test::load_mesh<TestType>(name);
    const auto vpm = get(CGAL::vertex_point, mesh);
    SDI::Mesh_indices<TestType> idx(mesh);
    const auto angle = SDI::corner_angles(idx, vpm);
    const auto area = SDI::face_areas(idx, vpm);
    const auto length = SDI::edge_lengths(idx, vpm);
    const auto varea = SDI::vertex_areas(idx, area);
    const auto fnormal = SDI::face_normals(idx, vpm);
    const auto vnormal = SDI::vertex_normals(idx, vpm);

    // angles of every triangle sum to pi
    for(std::size_t f = 0; f < idx.number_of_faces(); ++f)
    {
      double sum = 0.;
      for(auto h : halfedges_around_face(halfedge(idx.face(f), mesh), mesh))
        sum += angle[idx.index(h)];
      REQUIRE(sum == Approx(pi).epsilon(1e-12));
    }
    // law of cosines links angles and edge lengths; Heron's formula links areas and lengths
    for(std::size_t f = 0; f < idx.number_of_faces(); ++f)
    {
      const auto h = halfedge(idx.face(f), mesh);
      const double a = length[idx.edge_index(h)], b = length[idx.edge_index(next(h, mesh))],
                   c = length[idx.edge_index(prev(h, mesh))];
      // the angle at target(h) lies between h (length a) and next(h) (length b), opposite c
      const double gamma = angle[idx.index(h)];
      REQUIRE(c * c == Approx(a * a + b * b - 2 * a * b * std::cos(gamma)).epsilon(1e-8).margin(1e-12 * c * c));
      const double s = 0.5 * (a + b + c);
      const double heron2 = s * (s - a) * (s - b) * (s - c);
      REQUIRE(area[f] * area[f] == Approx(heron2).epsilon(1e-6).margin(1e-9 * s * s * s * s));
      REQUIRE(fnormal[f].norm() == Approx(1.).epsilon(1e-12));
    }
    // barycentric vertex areas sum to the total area
    double total = 0., vtotal = 0.;
    for(double x : area)
      total += x;
    for(double x : varea)
      vtotal += x;
    REQUIRE(vtotal == Approx(total).epsilon(1e-12));
    for(const auto& n : vnormal)
      REQUIRE(n.norm() == Approx(1.).epsilon(1e-12));

    // discrete Gauss-Bonnet: sum of angle defects (2 pi at interior vertices, pi at border
    // vertices) equals 2 pi chi, for each mesh as a whole
    const SDI::Topology topo = SDI::compute_topology(idx);
    const auto sums = SDI::vertex_angle_sums(idx, angle);
    std::vector<bool> on_border(idx.number_of_vertices(), false);
    for(const auto& loop : topo.boundary.loops)
      for(std::size_t h : loop)
        on_border[idx.target_index(idx.halfedge(h))] = true;
    double defect = 0.;
    long chi = 0;
    for(std::size_t v = 0; v < sums.size(); ++v)
      defect += (on_border[v] ? pi : 2 * pi) - sums[v];
    for(const auto& c : topo.components.info)
      chi += c.euler_characteristic();
    REQUIRE(defect == Approx(2 * pi * double(chi)).margin(1e-8));
  }
}

TEMPLATE_TEST_CASE("Normals point outwards on a sphere and areas converge", "[geometry]", SD_MESH_TYPES_WITH_IDS)
{
  TestType mesh;
  SD::make_sphere(mesh, 24);
  const auto vpm = get(CGAL::vertex_point, mesh);
  SDI::Mesh_indices<TestType> idx(mesh);
  const auto fnormal = SDI::face_normals(idx, vpm);
  const auto vnormal = SDI::vertex_normals(idx, vpm);
  for(std::size_t f = 0; f < idx.number_of_faces(); ++f)
  {
    Eigen::Vector3d a, b, c;
    SDI::triangle_of(idx, vpm, halfedge(idx.face(f), mesh), a, b, c);
    REQUIRE(fnormal[f].dot((a + b + c) / 3.) > 0.99);
  }
  for(std::size_t v = 0; v < idx.number_of_vertices(); ++v)
    REQUIRE(vnormal[v].dot(SDI::position(vpm, idx.vertex(v))) > 0.999);
  double total = 0.;
  for(double x : SDI::face_areas(idx, vpm))
    total += x;
  REQUIRE(total == Approx(4 * pi).epsilon(2e-3)); // inscribed polyhedron: slightly smaller
  REQUIRE(total < 4 * pi);
}

TEMPLATE_TEST_CASE("Cotangents: CGAL::Weights agrees with the corner angles", "[geometry]", SD_MESH_TYPES_WITH_IDS)
{
  for(const std::string name : {"triceratops.off", "bunny_1k.off", "mech-holes-shark.off"})
  {
    INFO(name);
    const TestType mesh = test::load_mesh<TestType>(name);
    const auto vpm = get(CGAL::vertex_point, mesh);
    SDI::Mesh_indices<TestType> idx(mesh);
    const auto angle = SDI::corner_angles(idx, vpm);
    const auto cot = SDI::halfedge_cotangents(idx, vpm);
    std::size_t negative = 0;
    for(std::size_t h = 0; h < idx.number_of_halfedges(); ++h)
    {
      const auto hd = idx.halfedge(h);
      if(idx.is_border(hd))
      {
        REQUIRE(cot[h] == 0.);
        continue;
      }
      const double opposite_angle = angle[idx.index(next(hd, mesh))];
      const double expected = std::cos(opposite_angle) / std::sin(opposite_angle);
      REQUIRE(cot[h] == Approx(expected).epsilon(1e-9).margin(1e-12));
      negative += cot[h] < 0;
    }
    REQUIRE(negative > 0); // these meshes have obtuse triangles: the test covers negative values
  }
}

TEMPLATE_TEST_CASE("The cotangent Laplacian: symmetric, PSD, constants in its kernel", "[dec]",
                   SD_MESH_TYPES_WITH_IDS)
{
  for(const std::string name : {"bunny_1k.off", "triceratops.off", "hemisphere.off", "bones.off"})
  {
    INFO(name);
    const TestType mesh = test::load_mesh<TestType>(name);
    const auto vpm = get(CGAL::vertex_point, mesh);
    SDI::Mesh_indices<TestType> idx(mesh);
    const auto w = SDI::cotangent_weights(idx, vpm);
    const SDI::Sparse_matrix L = SDI::weighted_laplacian(idx, w);

    // equals d0^T W d0 assembled from the operators
    const SDI::Sparse_matrix d0 = SDI::d0(idx);
    const SDI::Sparse_matrix reference = SDI::Sparse_matrix(d0.transpose()) * SDI::diagonal_matrix(w) * d0;
    REQUIRE((L - reference).norm() <= 1e-12 * L.norm());
    REQUIRE((L - SDI::Sparse_matrix(L.transpose())).norm() == 0.);

    // constants are in the kernel
    const Eigen::VectorXd ones = Eigen::VectorXd::Ones(L.rows());
    REQUIRE((L * ones).norm() <= 1e-12 * L.norm());

    // positive semi-definite: quadratic form of random vectors
    std::mt19937 rng(7);
    std::normal_distribution<double> normal;
    for(int trial = 0; trial < 20; ++trial)
    {
      Eigen::VectorXd x(L.rows());
      for(Eigen::Index i = 0; i < x.size(); ++i)
        x[i] = normal(rng);
      REQUIRE(x.dot(L * x) >= -1e-12 * L.norm() * x.squaredNorm());
    }
    // kernel dimension = number of components: an LDLT factorization of the singular matrix has
    // exactly that many (numerically) zero pivots, all others clearly positive
    const std::size_t components = SDI::compute_topology(idx).components.size();
    Eigen::SimplicialLDLT<SDI::Sparse_matrix> ldlt(L);
    const Eigen::VectorXd pivots = ldlt.vectorD();
    const double largest = pivots.cwiseAbs().maxCoeff();
    std::size_t zero_pivots = 0;
    for(Eigen::Index i = 0; i < pivots.size(); ++i)
    {
      REQUIRE(pivots[i] >= -1e-12 * largest);
      zero_pivots += pivots[i] <= 1e-12 * largest;
    }
    REQUIRE(zero_pivots == components);
    if(idx.number_of_vertices() <= 1100)
    {
      // and the spectrum itself, on the small meshes
      Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(Eigen::MatrixXd(L), Eigen::EigenvaluesOnly);
      const Eigen::VectorXd lambda = eig.eigenvalues(); // ascending
      const double scale = lambda.cwiseAbs().maxCoeff();
      REQUIRE(lambda[0] >= -1e-10 * scale);
      double zero_noise = 0.;
      for(std::size_t k = 0; k < components; ++k)
        zero_noise = (std::max)(zero_noise, std::abs(lambda[Eigen::Index(k)]));
      REQUIRE(zero_noise <= 1e-10 * scale);
      REQUIRE(lambda[Eigen::Index(components)] > 1e3 * zero_noise);
    }
  }
}

TEMPLATE_TEST_CASE("Block pattern on d values per vertex: every fill equals the triplet sum, zeros kept", "[dec]",
                   SD_MESH_TYPES_WITH_IDS)
{
  for(const std::string name : {"bunny_1k.off", "hemisphere.off", "bones.off", "mech-holes-shark.off"})
    for(int d : {1, 2})
    {
      INFO(name << ", d = " << d);
      const TestType mesh = test::load_mesh<TestType>(name);
      SDI::Mesh_indices<TestType> idx(mesh);
      const std::size_t nv = idx.number_of_vertices(), nh = idx.number_of_halfedges();
      const SDI::Vertex_block_pattern pattern(idx, d);
      std::mt19937 rng(11);
      std::uniform_real_distribution<double> value(-1., 1.);
      auto random_block = [&] { return Eigen::Matrix2d(Eigen::Matrix2d::NullaryExpr([&] { return value(rng); })); };
      for(int fill = 0; fill < 2; ++fill) // the pattern filled twice, with other values
      {
        INFO("fill " << fill);
        std::vector<Eigen::Matrix2d> off(nh), diagonal(nv);
        for(auto& b : off)
          b = random_block();
        for(auto& b : diagonal)
          b = random_block();
        for(std::size_t h = std::size_t(fill); h < nh; h += 3) // zero blocks: their entries stay in the pattern
          off[h].setZero();
        const SDI::Sparse_matrix a =
          pattern.fill([&](std::size_t h) { return off[h]; }, [&](std::size_t v) { return diagonal[v]; });

        std::vector<Eigen::Triplet<double>> t;
        for(std::size_t h = 0; h < nh; ++h)
        {
          const auto hd = idx.halfedge(h); // border halfedges too: their edges are in the pattern
          for(int r = 0; r < d; ++r)
            for(int c = 0; c < d; ++c)
              t.emplace_back(int(idx.source_index(hd)) * d + r, int(idx.target_index(hd)) * d + c, off[h](r, c));
        }
        for(std::size_t v = 0; v < nv; ++v)
          for(int r = 0; r < d; ++r)
            for(int c = 0; c < d; ++c)
              t.emplace_back(int(v) * d + r, int(v) * d + c, diagonal[v](r, c));
        SDI::Sparse_matrix reference(a.rows(), a.cols());
        reference.setFromTriplets(t.begin(), t.end());
        REQUIRE(a.rows() == Eigen::Index(nv) * d);
        REQUIRE(a.isCompressed());
        CHECK((a - reference).norm() == 0.);
        // the pattern: d x d blocks on the vertex adjacency and the diagonal, every column's rows
        // strictly increasing (as compressed storage requires)
        CHECK(std::size_t(a.nonZeros()) == std::size_t(d * d) * (nv + 2 * idx.number_of_edges()));
        bool sorted = true;
        for(Eigen::Index c = 0; c < a.outerSize(); ++c)
          for(int k = a.outerIndexPtr()[c] + 1; k < a.outerIndexPtr()[c + 1]; ++k)
            sorted = sorted && a.innerIndexPtr()[k - 1] < a.innerIndexPtr()[k];
        CHECK(sorted);
      }
    }
}

TEMPLATE_TEST_CASE("The cotangent Laplacian has linear precision on planar meshes", "[dec]",
                   SD_MESH_TYPES_WITH_IDS)
{
  // jittered grids have obtuse triangles and negative weights; linear precision must still hold
  for(double jitter : {0., 0.15, 0.3})
  {
    INFO("jitter " << jitter);
    TestType mesh;
    SD::make_grid(mesh, 20, 17, jitter, [](std::size_t i, std::size_t j) {
      return i >= 6 && i < 9 && j >= 5 && j < 8; // one hole: two boundary loops
    });
    const auto vpm = get(CGAL::vertex_point, mesh);
    SDI::Mesh_indices<TestType> idx(mesh);
    const auto w = SDI::cotangent_weights(idx, vpm);
    for(const Eigen::Vector3d& n : SDI::face_normals(idx, vpm))
      REQUIRE(n.z() > 0.); // no flipped triangle: the premise of linear precision
    if(jitter >= 0.3)
      REQUIRE(*std::min_element(w.begin(), w.end()) < -1.); // strongly non-Delaunay
    const SDI::Sparse_matrix L = SDI::weighted_laplacian(idx, w);
    std::vector<bool> on_border(idx.number_of_vertices(), false);
    for(std::size_t h = 0; h < idx.number_of_halfedges(); ++h)
      if(idx.is_border(idx.halfedge(h)))
        on_border[idx.target_index(idx.halfedge(h))] = true;
    for(int coordinate = 0; coordinate < 2; ++coordinate)
    {
      Eigen::VectorXd f(L.rows());
      for(std::size_t v = 0; v < idx.number_of_vertices(); ++v)
      {
        const Eigen::Vector3d p = SDI::position(vpm, idx.vertex(v));
        f[Eigen::Index(v)] = 0.3 + (coordinate == 0 ? 2. * p.x() - p.y() : p.y() + 0.5 * p.x());
      }
      const Eigen::VectorXd Lf = L * f;
      for(std::size_t v = 0; v < idx.number_of_vertices(); ++v)
        if(!on_border[v])
          REQUIRE(std::abs(Lf[Eigen::Index(v)]) <= 1e-12 * L.norm());
    }
  }
}

TEMPLATE_TEST_CASE("Operators do not depend on the mesh data structure", "[dec]", test::Polyhedron,
                   test::Polyhedron_with_id)
{
  const test::Surface_mesh reference_mesh = test::load_mesh<test::Surface_mesh>("eight.off");
  const TestType mesh = test::load_mesh<TestType>("eight.off");
  SDI::Mesh_indices<test::Surface_mesh> ridx(reference_mesh);
  SDI::Mesh_indices<TestType> idx(mesh);
  // edges may be numbered differently: compare through the vertex pairs
  std::map<std::pair<std::size_t, std::size_t>, double> reference_weight;
  const auto rw = SDI::cotangent_weights(ridx, get(CGAL::vertex_point, reference_mesh));
  for(std::size_t e = 0; e < ridx.number_of_edges(); ++e)
    reference_weight[ridx.edge_vertices(e)] = rw[e];
  const auto w = SDI::cotangent_weights(idx, get(CGAL::vertex_point, mesh));
  for(std::size_t e = 0; e < idx.number_of_edges(); ++e)
    REQUIRE(w[e] == reference_weight.at(idx.edge_vertices(e)));
  const SDI::Sparse_matrix L = SDI::weighted_laplacian(idx, w);
  const SDI::Sparse_matrix rL = SDI::weighted_laplacian(ridx, rw);
  REQUIRE((L - rL).norm() <= 1e-14 * L.norm()); // vertex-indexed: identical up to summation order
}

// The corner angles, the vertex frames and the connection's transport angles and curvatures run
// as concurrent tasks on meshes above a few thousand elements (bunny_8k: 4151 vertices, 24k
// halfedges); every element is computed alone, so one thread and several give the same bits.
TEMPLATE_TEST_CASE("The connection and its frames do not depend on the number of threads", "[geometry]",
                   SD_MESH_TYPES_WITH_IDS)
{
  const TestType mesh = test::load_mesh<TestType>("bunny_8k.off");
  SDI::Mesh_indices<TestType> idx(mesh);
  const auto vpm = get(CGAL::vertex_point, mesh);
  REQUIRE(SDI::worth_parallel(idx.number_of_vertices()));
  const SDI::Discrete_connection concurrent = SDI::levi_civita_connection(idx, vpm);
  SDI::Discrete_connection alone;
#if defined(CGAL_LINKED_WITH_TBB)
  tbb::task_arena one_thread(1);
  one_thread.execute([&] { alone = SDI::levi_civita_connection(idx, vpm); });
#else
  alone = SDI::levi_civita_connection(idx, vpm);
#endif
  REQUIRE(concurrent.rho == alone.rho);
  REQUIRE(concurrent.curvature == alone.curvature);
  REQUIRE(concurrent.frames.angle == alone.frames.angle);
  REQUIRE(concurrent.frames.scale == alone.frames.scale);
  REQUIRE(concurrent.frames.star_begin == alone.frames.star_begin);
  REQUIRE(concurrent.frames.star_psi == alone.frames.star_psi);
  REQUIRE(concurrent.frames.star_phi == alone.frames.star_phi);
  REQUIRE(concurrent.frames.e0 == alone.frames.e0);
  REQUIRE(concurrent.frames.border == alone.frames.border);
  // and every element was computed: each star ends on its 2 pi sentinel, the rescaled angles of
  // an interior star end short of 2 pi, the face curvatures sum to 2 pi chi (closed, genus 0)
  double total = 0.;
  for(double k : concurrent.curvature)
    total += k;
  REQUIRE(std::abs(total - 4. * SDI::pi) <= 1e-9);
  for(std::size_t v = 0; v < idx.number_of_vertices(); ++v)
  {
    const std::size_t b = concurrent.frames.star_begin[v], e = concurrent.frames.star_begin[v + 1] - 1;
    REQUIRE(e > b + 1);
    REQUIRE(concurrent.frames.star_psi[e] == SDI::two_pi);
    REQUIRE(concurrent.frames.star_phi[e - 1] < SDI::two_pi);
    REQUIRE(concurrent.frames.star_phi[e - 1] > 0.);
  }
}
