// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The developability flow (make_piecewise_developable), its remeshing (4-1 subdivision,
// small-angle flips and collapses) and its metrics:
// - a noisy cylinder and a noisy cone flow to energy ~ 0 and their rulings (the normal of the
//   plane of each star's normals, computed here independently) are the generators: parallel to
//   the axis, through the apex;
// - a noisy cube keeps its valence-3 corners (omitted from the energy) with their pi/2 of
//   curvature, and loses them when they are not omitted;
// - an icosphere becomes piecewise developable with its curvature concentrated on a few seam
//   vertices;
// - subdivision and small-angle removal keep a valid, oriented, manifold mesh of the same
//   topology; the metrics on analytic cases (flat grid, exact cube, cone apex);
// - the visitor stops the flow, the same run on Surface_mesh and Polyhedron_3 gives the same
//   result, gradient descent also descends, and bad meshes and parameters throw before anything
//   is modified;
// - with a separate vertex_point_map (a Surface_mesh property, a std::map for Polyhedron_3) the
//   flow, new vertices included, gives bit for bit the result of the default map and leaves the
//   mesh's own points alone; vertex_energy_map sums to the total energy (and matches the
//   definitions per star), vertex_gradient_map matches central differences of the total.

#include <test_support.h>

#include <CGAL/Surface_design/developability.h>
#include <CGAL/Surface_design/internal/Developability/remeshing.h>
#include <CGAL/Surface_design/mesh_generators.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <random>
#include <set>
#include <type_traits>
#include <vector>

namespace SD = CGAL::Surface_design;
namespace SDI = CGAL::Surface_design::internal;
namespace PMP = CGAL::Polygon_mesh_processing;

namespace {

#if defined(__SANITIZE_ADDRESS__)
constexpr bool sanitized = true; // the flows are ~20x slower there: lighter meshes
#else
constexpr bool sanitized = false;
#endif

using test::Soup_points;
using test::Soup_triangles;
using test::from_soup;

/// Open tube around the z axis: `around` x `along` quads, radius r0 at z = 0 and r1 at z = h,
/// each quad split along alternating diagonals; radial noise of up to `noise` times the ring
/// spacing (deterministic).
template <class Mesh>
Mesh make_tube(std::size_t around, std::size_t along, double r0, double r1, double h, double noise,
               unsigned seed = 7)
{
  Soup_points p;
  Soup_triangles t;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1., 1.);
  for(std::size_t j = 0; j <= along; ++j)
    for(std::size_t i = 0; i < around; ++i)
    {
      const double z = h * double(j) / double(along), a = SDI::two_pi * double(i) / double(around);
      const double r = r0 + (r1 - r0) * z / h + noise * (h / double(along)) * u(rng);
      p.push_back({r * std::cos(a), r * std::sin(a), z});
    }
  auto id = [&](std::size_t i, std::size_t j) { return j * around + i % around; };
  for(std::size_t j = 0; j < along; ++j)
    for(std::size_t i = 0; i < around; ++i)
    {
      const std::size_t a = id(i, j), b = id(i + 1, j), c = id(i + 1, j + 1), d = id(i, j + 1);
      if((i + j) % 2 == 0)
      {
        t.push_back({a, b, c});
        t.push_back({a, c, d});
      }
      else
      {
        t.push_back({a, b, d});
        t.push_back({b, c, d});
      }
    }
  return from_soup<Mesh>(p, t);
}

/// The surface of the cube [0, n]^3 as n x n grids of split quads whose diagonals avoid the
/// corners, so that the eight corners have valence 3; optional noise on every vertex (up to
/// `noise` grid cells along each axis).
template <class Mesh>
Mesh make_cube(std::size_t n, double noise = 0., unsigned seed = 11)
{
  Soup_points p;
  Soup_triangles t;
  std::map<std::array<std::size_t, 3>, std::size_t> id;
  auto vertex = [&](std::array<std::size_t, 3> c) {
    auto it = id.find(c);
    if(it != id.end())
      return it->second;
    id.emplace(c, p.size());
    p.push_back({double(c[0]), double(c[1]), double(c[2])});
    return p.size() - 1;
  };
  const double center = 0.5 * double(n);
  for(int axis = 0; axis < 3; ++axis)
    for(std::size_t side : {std::size_t(0), n})
    {
      const int a1 = (axis + 1) % 3, a2 = (axis + 2) % 3;
      auto at = [&](std::size_t i, std::size_t j) {
        std::array<std::size_t, 3> c{};
        c[std::size_t(axis)] = side;
        c[std::size_t(a1)] = i;
        c[std::size_t(a2)] = j;
        return vertex(c);
      };
      for(std::size_t i = 0; i < n; ++i)
        for(std::size_t j = 0; j < n; ++j)
        {
          const std::size_t v00 = at(i, j), v10 = at(i + 1, j), v11 = at(i + 1, j + 1), v01 = at(i, j + 1);
          // the diagonal v00-v11 would touch a corner in the quads (0,0) and (n-1,n-1)
          const bool other = (i == 0 && j == 0) || (i + 1 == n && j + 1 == n);
          std::array<std::array<std::size_t, 3>, 2> quad =
            other ? std::array<std::array<std::size_t, 3>, 2>{{{v00, v10, v01}, {v10, v11, v01}}}
                  : std::array<std::array<std::size_t, 3>, 2>{{{v00, v10, v11}, {v00, v11, v01}}};
          for(auto tri : quad)
          {
            const Eigen::Vector3d A(p[tri[0]].data()), B(p[tri[1]].data()), C(p[tri[2]].data());
            const Eigen::Vector3d outward = (A + B + C) / 3. - Eigen::Vector3d::Constant(center);
            if((B - A).cross(C - A).dot(outward) < 0.)
              std::swap(tri[1], tri[2]);
            t.push_back(tri);
          }
        }
    }
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1., 1.);
  for(auto& q : p)
    for(double& c : q)
      c += noise * u(rng);
  return from_soup<Mesh>(p, t);
}

/// Icosahedron, 4-1 subdivided `levels` times, projected to the unit sphere: 10 * 4^levels + 2
/// vertices (642 for 3 levels, the reference code's sphere).
template <class Mesh>
Mesh make_icosphere(std::size_t levels)
{
  const double g = (1. + std::sqrt(5.)) / 2.;
  const Soup_points p{{-1, g, 0}, {1, g, 0}, {-1, -g, 0}, {1, -g, 0}, {0, -1, g}, {0, 1, g},
                      {0, -1, -g}, {0, 1, -g}, {g, 0, -1}, {g, 0, 1}, {-g, 0, -1}, {-g, 0, 1}};
  const Soup_triangles t{{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
                         {11, 10, 2}, {10, 7, 6}, {7, 1, 8},   {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
                         {3, 8, 9},  {4, 9, 5},  {2, 4, 11},  {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
  Mesh mesh = from_soup<Mesh>(p, t);
  auto vpm = get(CGAL::vertex_point, mesh);
  for(std::size_t l = 0; l < levels; ++l)
    SDI::midpoint_subdivision(mesh, vpm);
  for(auto v : vertices(mesh))
  {
    const auto q = get(vpm, v);
    const double r = std::sqrt(q.x() * q.x() + q.y() * q.y() + q.z() * q.z());
    put(vpm, v, test::Point(q.x() / r, q.y() / r, q.z() / r));
  }
  return mesh;
}

template <class Mesh>
Eigen::Vector3d pos(const Mesh& mesh, typename boost::graph_traits<Mesh>::vertex_descriptor v)
{
  const auto& q = get(CGAL::vertex_point, mesh, v);
  return Eigen::Vector3d(q.x(), q.y(), q.z());
}

/// Per interior vertex: sum of its corner angles, and the eigen-decomposition of the
/// angle-weighted covariance of its face normals, sum theta_f N_f N_f^T (computed here, apart
/// from the library): the smallest eigenvalue is lambda_i, its eigenvector the ruling.
template <class Mesh>
struct Star_data
{
  typename boost::graph_traits<Mesh>::vertex_descriptor v;
  Eigen::Vector3d position;
  std::size_t valence = 0;
  double angle_sum = 0., lambda = 0.;
  Eigen::Vector3d ruling;
};

template <class Mesh>
std::vector<Star_data<Mesh>> interior_stars(const Mesh& mesh)
{
  std::vector<Star_data<Mesh>> out;
  for(auto v : vertices(mesh))
  {
    if(CGAL::is_border(v, mesh))
      continue;
    Star_data<Mesh> s;
    s.v = v;
    s.position = pos(mesh, v);
    Eigen::Matrix3d A = Eigen::Matrix3d::Zero();
    for(auto h : CGAL::halfedges_around_target(halfedge(v, mesh), mesh))
    {
      const Eigen::Vector3d a = pos(mesh, source(h, mesh)) - s.position,
                            b = pos(mesh, target(next(h, mesh), mesh)) - s.position;
      const Eigen::Vector3d n = a.cross(b);
      const double theta = std::atan2(n.norm(), a.dot(b));
      s.angle_sum += theta;
      A += theta * n.normalized() * n.normalized().transpose();
      ++s.valence;
    }
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(A);
    s.lambda = eig.eigenvalues()(0);
    s.ruling = eig.eigenvectors().col(0);
    out.push_back(s);
  }
  return out;
}

template <class Mesh>
std::size_t number_of_boundary_cycles(const Mesh& mesh)
{
  std::vector<typename boost::graph_traits<Mesh>::halfedge_descriptor> cycles;
  PMP::extract_boundary_cycles(mesh, std::back_inserter(cycles));
  return cycles.size();
}

/// Valid, triangles only, consistently oriented, manifold vertices; Euler characteristic and
/// boundary cycles as given.
template <class Mesh>
void check_valid_mesh(const Mesh& mesh, long euler, std::size_t boundary_cycles)
{
  REQUIRE(CGAL::is_valid_polygon_mesh(mesh));
  REQUIRE(CGAL::is_triangle_mesh(mesh));
  CHECK(long(num_vertices(mesh)) - long(num_edges(mesh)) + long(num_faces(mesh)) == euler);
  CHECK(number_of_boundary_cycles(mesh) == boundary_cycles);
  const SDI::Mesh_indices<Mesh> idx(mesh);
  CHECK_NOTHROW(SDI::validate_mesh(idx, get(CGAL::vertex_point, mesh))); // manifold, no degenerate face
}

template <class Mesh>
long euler_characteristic(const Mesh& mesh)
{
  return long(num_vertices(mesh)) - long(num_edges(mesh)) + long(num_faces(mesh));
}

template <class Mesh>
double bounding_diagonal(const Mesh& mesh)
{
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(1e300), hi = -lo;
  for(auto v : vertices(mesh))
  {
    lo = lo.cwiseMin(pos(mesh, v));
    hi = hi.cwiseMax(pos(mesh, v));
  }
  return (hi - lo).norm();
}

/// The covariance flow (no subdivision) from a noisy open tube: the energy must vanish (below
/// 1e-6 of the initial one) and the tube stay a valid annulus.
template <class Mesh>
Mesh flow_tube_to_zero(const Mesh& input)
{
  Mesh mesh = input;
  const double e0 = SD::developability_energy(mesh);
  const SD::Developability_flow_result r = SD::make_piecewise_developable(
    mesh, SD::parameters::developability_energy(SD::Developability_energy::covariance).number_of_iterations(2000));
  const double e1 = SD::developability_energy(mesh);
  INFO("energy " << e0 << " -> " << e1 << " in " << r.iterations << " iterations, end: " << r.levels.back().end);
  CHECK(e1 < 1e-6 * e0);
  check_valid_mesh(mesh, 0, 2);
  return mesh;
}

} // namespace

// --- flows on shapes with a known developable answer

TEMPLATE_TEST_CASE("a noisy cylinder flows to zero energy with rulings along its axis", "[developability][flow]",
                   test::Surface_mesh, test::Polyhedron)
{
  using Mesh = TestType;
  const std::size_t around = sanitized ? 16 : 24, along = sanitized ? 6 : 10;
  const Mesh input = make_tube<Mesh>(around, along, 1., 1., 2., 0.1);
  const Mesh mesh = flow_tube_to_zero(input);

  std::size_t measured = 0, aligned = 0;
  double worst = 0.;
  for(const auto& s : interior_stars(mesh))
  {
    ++measured;
    CHECK(s.lambda < SDI::two_pi * 1e-4); // every interior star is a hinge
    worst = (std::max)(worst, 1. - std::abs(s.ruling.z()));
    aligned += std::abs(s.ruling.z()) > std::cos(5. * SDI::pi / 180.);
  }
  INFO("largest 1 - |cos(ruling, axis)|: " << worst);
  CHECK(measured == around * (along - 1));
  CHECK(aligned == measured); // every ruling within 5 degrees of the axis
  const SD::Developability_metrics m = SD::developability_metrics(mesh, input);
  CHECK(m.hinge_share_1e4 == 1.);
  CHECK(m.hausdorff_distance < 0.05);
}

TEMPLATE_TEST_CASE("a noisy cone flows to zero energy with rulings through its apex", "[developability][flow]",
                   test::Surface_mesh, test::Polyhedron)
{
  using Mesh = TestType;
  const std::size_t around = sanitized ? 16 : 24, along = sanitized ? 6 : 10;
  // frustum of the cone with apex (0, 0, 3): radius 1.5 at z = 0, 0.5 at z = 2
  const Mesh input = make_tube<Mesh>(around, along, 1.5, 0.5, 2., 0.1, 3);
  const Eigen::Vector3d apex(0., 0., 3.);
  const Mesh mesh = flow_tube_to_zero(input);
  double worst = 0.;
  for(const auto& s : interior_stars(mesh))
  {
    CHECK(s.lambda < SDI::two_pi * 1e-4);
    // distance from the apex to the ruling line through the vertex, relative to the height
    worst = (std::max)(worst, (apex - s.position).cross(s.ruling).norm() / 3.);
  }
  INFO("largest distance apex - ruling / height: " << worst);
  CHECK(worst < 0.05);
}

TEMPLATE_TEST_CASE("a noisy cube keeps its valence-3 corners, unless they are not omitted", "[developability][flow]",
                   test::Surface_mesh, test::Polyhedron)
{
  using Mesh = TestType;
  const std::size_t n = sanitized ? 3 : 4;
  const Mesh input = make_cube<Mesh>(n, 0.05);
  auto corner_defects = [](const Mesh& mesh) {
    std::vector<double> defects;
    for(const auto& s : interior_stars(mesh))
      if(s.valence == 3)
        defects.push_back(SDI::two_pi - s.angle_sum);
    return defects;
  };
  REQUIRE(corner_defects(input).size() == 8);

  Mesh kept = input;
  SD::make_piecewise_developable(kept, SD::parameters::number_of_iterations(1000));
  check_valid_mesh(kept, 2, 0);
  const std::vector<double> defects = corner_defects(kept);
  REQUIRE(defects.size() == 8);
  for(double d : defects)
    CHECK(std::abs(d - SDI::pi / 2.) < 0.05); // each corner keeps its pi/2 of curvature
  const SD::Developability_metrics m = SD::developability_metrics(kept, input);
  CHECK(m.hinge_share_1e4 == 1.); // the faces are flat again, the edges are hinges
  CHECK(m.seam_curvature_share > 0.99);
  CHECK(m.hausdorff_distance < 0.03);

  // the same flow with the corners in the energy: a valence-3 star is a hinge only when flat
  Mesh rounded = input;
  SD::make_piecewise_developable(rounded, SD::parameters::omit_valence_three_vertices(false).number_of_iterations(1000));
  check_valid_mesh(rounded, 2, 0);
  double largest = 0.;
  for(const auto& s : interior_stars(rounded))
    if(s.valence == 3)
      largest = (std::max)(largest, s.lambda);
  const double kept_smallest = [&] {
    double l = 1e300;
    for(const auto& s : interior_stars(kept))
      if(s.valence == 3)
        l = (std::min)(l, s.lambda);
    return l;
  }();
  INFO("corner lambda kept >= " << kept_smallest << ", not omitted <= " << largest);
  CHECK(largest < 0.1 * kept_smallest);
}

TEST_CASE("an icosphere becomes piecewise developable with its curvature on seams", "[developability][flow]")
{
  using Mesh = test::Surface_mesh;
  // 162 vertices, then two 4-1 subdivisions, with the CLI's defaults; the same under the
  // sanitizers (~1 min there): a coarser sphere of 42 vertices is no sphere (it folds flat), and
  // one subdivision leaves only ~60% hinges
  const Mesh input = make_icosphere<Mesh>(2);
  Mesh mesh = input;
  const SD::Developability_flow_result r = SD::make_piecewise_developable(
    mesh, SD::parameters::developability_energy(SD::Developability_energy::intrinsic_width,
                                                SD::parameters::number_of_subdivisions(std::size_t(2))));
  check_valid_mesh(mesh, 2, 0);
  const SD::Developability_metrics m = SD::developability_metrics(mesh, input);
  const double seam_vertex_share = double(m.seam_vertices) / double(m.measured_vertices);
  INFO(r.iterations << " iterations; hinges " << m.hinge_share_1e4 << ", seam vertices " << seam_vertex_share
                    << " carry " << m.seam_curvature_share << " of |Omega|, " << m.seam_curves << " seam curves, Hausdorff "
                    << m.hausdorff_distance);
  CHECK(m.hinge_share_1e4 >= 0.8);
  // concentration: at most 20% of the vertices carry at least 60% of the total |angle defect|
  // (spread evenly, they would carry 20%; on the input every vertex carries 1/|V| of it)
  CHECK(seam_vertex_share <= 0.2);
  CHECK(m.seam_curvature_share >= 0.6);
  CHECK(m.seam_curves >= 1);
  CHECK(m.hausdorff_distance < 0.1);
}

TEST_CASE("acceptance: coarse egg, twisted pebble and bunny become piecewise developable with the CLI's defaults",
          "[developability][flow][acceptance]")
{
  // the CLI's defaults before the flow converged: intrinsic width energy, 2 subdivisions, at most
  // 1000 iterations per level (a level may now also end when it has converged). Under
  // the sanitizers (~20x slower) the same flows without subdivision and 100 iterations, checked
  // for validity only.
  using Mesh = test::Surface_mesh;
  for(const char* name : {"egg_1k.off", "pebble_1k.off", "bunny_1k.off"})
  {
    const Mesh input = test::load_mesh<Mesh>(name);
    Mesh mesh = input;
    const SD::Developability_flow_result r = SD::make_piecewise_developable(
      mesh, SD::parameters::developability_energy(SD::Developability_energy::intrinsic_width,
                                                  SD::parameters::number_of_subdivisions(std::size_t(sanitized ? 0 : 2)))
              .number_of_iterations(sanitized ? 100 : 1000));
    check_valid_mesh(mesh, 2, 0); // closed genus 0 stays closed genus 0
    if(sanitized)
      continue;
    const SD::Developability_metrics m = SD::developability_metrics(mesh, input);
    INFO(name << ": " << r.iterations << " iterations in " << r.total_seconds << " s; hinges " << m.hinge_share_1e4
              << ", Hausdorff " << m.hausdorff_distance << ", seam vertices " << m.seam_vertices << " carry "
              << m.seam_curvature_share << " of |Omega|");
    CHECK(m.hinge_share_1e4 >= 0.8);
    CHECK(m.hausdorff_distance < 0.06);
    CHECK(r.subdivisions == 2);
  }
}

// --- remeshing

TEMPLATE_TEST_CASE("4-1 midpoint subdivision keeps the shape and the topology", "[developability][remeshing]",
                   test::Surface_mesh, test::Polyhedron)
{
  using Mesh = TestType;
  for(int which = 0; which < 3; ++which)
  {
    Mesh mesh = which == 0 ? make_tube<Mesh>(12, 4, 1., 0.6, 1., 0.2)
                : which == 1 ? make_cube<Mesh>(2, 0.1)
                             : test::load_mesh<Mesh>("bunny_1k.off");
    const long euler = euler_characteristic(mesh);
    const std::size_t cycles = number_of_boundary_cycles(mesh);
    const std::size_t V = num_vertices(mesh), E = num_edges(mesh), F = num_faces(mesh);
    std::vector<Eigen::Vector3d> old_points;
    for(auto v : vertices(mesh))
      old_points.push_back(pos(mesh, v));
    std::map<std::pair<std::size_t, std::size_t>, bool> old_edges;
    SDI::midpoint_subdivision(mesh, get(CGAL::vertex_point, mesh));
    check_valid_mesh(mesh, euler, cycles);
    CHECK(num_vertices(mesh) == V + E);
    CHECK(num_edges(mesh) == 2 * E + 3 * F);
    CHECK(num_faces(mesh) == 4 * F);
    // every new vertex is the midpoint of two old vertices it is not joined to any more; every
    // face has at least two new corners and the four children of a face are similar to it
    std::size_t new_vertices = 0;
    for(auto v : vertices(mesh))
    {
      const Eigen::Vector3d q = pos(mesh, v);
      const bool old = std::any_of(old_points.begin(), old_points.end(), [&](const Eigen::Vector3d& o) { return o == q; });
      if(old)
        continue;
      ++new_vertices;
      std::vector<Eigen::Vector3d> ring;
      for(auto w : CGAL::vertices_around_target(halfedge(v, mesh), mesh))
        ring.push_back(pos(mesh, w));
      bool midpoint = false;
      for(const auto& a : ring)
        for(const auto& b : ring)
          if(std::any_of(old_points.begin(), old_points.end(), [&](const Eigen::Vector3d& o) { return o == a; }) &&
             std::any_of(old_points.begin(), old_points.end(), [&](const Eigen::Vector3d& o) { return o == b; }) &&
             (0.5 * (a + b) - q).norm() < 1e-12)
            midpoint = true;
      CHECK(midpoint);
    }
    CHECK(new_vertices == E);
    const SDI::Mesh_indices<Mesh> idx(mesh);
    CHECK_NOTHROW(SDI::validate_mesh(idx, get(CGAL::vertex_point, mesh)));
  }
}

TEMPLATE_TEST_CASE("small angles are removed by flips and collapses that keep a valid manifold",
                   "[developability][remeshing]", test::Surface_mesh, test::Polyhedron)
{
  using Mesh = TestType;
  SECTION("a cap (two small angles) is flipped, a needle (one small angle) collapsed")
  {
    // a 4 x 4 grid of [0, 1]^2 whose vertex (0.5, 0.5) (valence 8, convex star [0.25, 0.75]^2)
    // is moved (a) next to the middle of its link edge (0.75, 0.5)-(0.75, 0.75): caps, or (b)
    // next to its neighbour (0.75, 0.5): needles
    for(int which = 0; which < 2; ++which)
    {
      Mesh mesh;
      SD::make_grid(mesh, 4, 4);
      auto vpm = get(CGAL::vertex_point, mesh);
      typename boost::graph_traits<Mesh>::vertex_descriptor center = *vertices(mesh).begin();
      for(auto v : vertices(mesh))
        if((pos(mesh, v) - Eigen::Vector3d(0.5, 0.5, 0.)).norm() < 1e-12)
          center = v;
      REQUIRE((pos(mesh, center) - Eigen::Vector3d(0.5, 0.5, 0.)).norm() < 1e-12);
      put(vpm, center, which == 0 ? test::Point(0.7499, 0.625, 0.) : test::Point(0.7499, 0.5, 0.));
      const long euler = euler_characteristic(mesh);
      const std::size_t F = num_faces(mesh);
      const double min_before = SD::developability_metrics(mesh).minimum_angle;
      REQUIRE(min_before < 0.01);
      const SDI::Small_angle_report r = SDI::remove_small_angles(mesh, vpm, 0.01);
      INFO("case " << which << ": flips " << r.flips << ", collapses " << r.collapses);
      CHECK(r.flips + r.collapses > 0);
      check_valid_mesh(mesh, euler, 1);
      CHECK(SD::developability_metrics(mesh).minimum_angle > min_before);
      CHECK(num_faces(mesh) == F - 2 * r.collapses);
      if(which == 0)
        CHECK(r.flips > 0);
      else
        CHECK(r.collapses > 0);
    }
  }
  SECTION("random slivers everywhere: every operation keeps the mesh valid")
  {
    for(unsigned seed = 0; seed < 4; ++seed)
    {
      Mesh mesh = test::load_mesh<Mesh>("bunny_1k.off");
      auto vpm = get(CGAL::vertex_point, mesh);
      std::mt19937 rng(seed);
      std::uniform_real_distribution<double> u(0., 1.);
      // pull a tenth of the vertices almost onto a neighbour (needles) and a tenth almost onto
      // the middle of the opposite edge of one of their triangles (caps)
      for(auto v : std::vector<typename boost::graph_traits<Mesh>::vertex_descriptor>(vertices(mesh).begin(), vertices(mesh).end()))
      {
        const double coin = u(rng);
        if(coin > 0.2)
          continue;
        const auto h = halfedge(v, mesh); // target v
        const Eigen::Vector3d a = pos(mesh, v), b = pos(mesh, source(h, mesh));
        const Eigen::Vector3d c = is_border(h, mesh) ? b : pos(mesh, target(next(h, mesh), mesh));
        const Eigen::Vector3d toward = coin < 0.1 ? b : 0.5 * (b + c);
        const Eigen::Vector3d q = toward + (0.001 + 0.01 * u(rng)) * (a - toward);
        put(vpm, v, test::Point(q.x(), q.y(), q.z()));
      }
      const long euler = euler_characteristic(mesh);
      const std::size_t cycles = number_of_boundary_cycles(mesh);
      const SDI::Small_angle_report r = SDI::remove_small_angles(mesh, vpm, 0.05);
      INFO("seed " << seed << ": flips " << r.flips << ", collapses " << r.collapses);
      CHECK(r.flips > 0);
      CHECK(r.collapses > 0);
      REQUIRE(CGAL::is_valid_polygon_mesh(mesh));
      CHECK(euler_characteristic(mesh) == euler);
      CHECK(number_of_boundary_cycles(mesh) == cycles);
      CHECK(PMP::is_outward_oriented(mesh) == PMP::is_outward_oriented(test::load_mesh<Mesh>("bunny_1k.off")));
      for(auto v : vertices(mesh))
        CHECK(CGAL::halfedges_around_target(halfedge(v, mesh), mesh).size() >= 3);
    }
  }
}

// --- metrics on analytic cases

TEMPLATE_TEST_CASE("metrics of a flat grid, an exact cube and a cone apex", "[developability][metrics]",
                   test::Surface_mesh, test::Polyhedron)
{
  using Mesh = TestType;
  SECTION("a flat grid: every star a hinge, no curvature")
  {
    Mesh mesh;
    SD::make_grid(mesh, 6, 5, 0.2);
    const SD::Developability_metrics m = SD::developability_metrics(mesh, mesh);
    CHECK(m.measured_vertices > 0);
    CHECK(m.energy == Approx(0.).margin(1e-24));
    CHECK(m.lambda_max < 1e-14);
    CHECK(m.hinge_share_1e4 == 1.);
    CHECK(m.angle_defect_max < 1e-12);
    CHECK(m.seam_vertices == 0);
    CHECK(m.seam_curves == 0);
    CHECK(m.hausdorff_distance == Approx(0.).margin(1e-12));
  }
  SECTION("an exact cube: hinges on the edges, pi/2 at each corner, no seam edge")
  {
    const Mesh mesh = make_cube<Mesh>(3);
    const SD::Developability_metrics m = SD::developability_metrics(mesh);
    CHECK(m.vertices == 6 * 9 + 2);
    CHECK(m.measured_vertices == m.vertices - 8); // the corners have valence 3
    CHECK(m.hinge_share_1e4 == 1.);
    CHECK(m.seam_vertices == 8);
    CHECK(m.seam_curvature_share == Approx(1.));
    CHECK(m.seam_curves == 0); // no two corners are joined by an edge
    CHECK(m.seam_length == 0.);
    CHECK(m.angle_defect_max == Approx(SDI::pi / 2.));
    CHECK(m.angle_defect_mean == Approx(4. * SDI::pi / double(m.vertices))); // Gauss-Bonnet: 4 pi in all
    CHECK(m.minimum_angle == Approx(SDI::pi / 4.));
    CHECK(m.energy == Approx(0.).margin(1e-20)); // covariance energy: the corners are omitted
  }
  SECTION("a cone apex: angle defect 2 pi (1 - sin alpha), covariance lambda from the closed form")
  {
    // apex (0,0,h) over a regular k-gon of radius 1: half-angle alpha = atan(1/h)
    const std::size_t k = 12;
    const double h = 1.5;
    Soup_points p{{0., 0., h}};
    Soup_triangles t;
    for(std::size_t i = 0; i < k; ++i)
    {
      const double a = SDI::two_pi * double(i) / double(k);
      p.push_back({std::cos(a), std::sin(a), 0.});
      t.push_back({0, 1 + i, 1 + (i + 1) % k});
    }
    const Mesh mesh = from_soup<Mesh>(p, t);
    const SD::Developability_metrics m = SD::developability_metrics(mesh);
    REQUIRE(m.measured_vertices == 1);
    const double edge = 2. * std::sin(SDI::pi / double(k)), slant = std::sqrt(1. + h * h);
    const double theta = 2. * std::asin(0.5 * edge / slant); // tip angle of each triangle
    CHECK(m.angle_defect_max == Approx(SDI::two_pi - double(k) * theta).epsilon(1e-12));
    // face normals at angle beta to the axis, tan(beta) = h / cos(pi/k) (the apothem):
    // sum theta N N^T has eigenvalue k theta cos^2(beta) on the axis, k theta sin^2(beta) / 2 across
    const double beta = std::atan(h / std::cos(SDI::pi / double(k)));
    const double lambda = (std::min)(double(k) * theta * std::cos(beta) * std::cos(beta),
                                     double(k) * theta * std::sin(beta) * std::sin(beta) / 2.);
    CHECK(m.lambda_max == Approx(lambda).epsilon(1e-10));
    CHECK(m.seam_vertices == 1);
    CHECK(m.seam_curvature_share == Approx(1.));
  }
}

// --- the driver: visitor, mesh types, descent method, levels

TEST_CASE("the visitor sees every iteration and can stop the flow", "[developability][flow]")
{
  using Mesh = test::Surface_mesh;
  Mesh mesh = test::load_mesh<Mesh>("bunny_1k.off");
  std::vector<SD::Developability_iteration> seen;
  const SD::Developability_flow_result r = SD::make_piecewise_developable(
    mesh, SD::parameters::number_of_subdivisions(std::size_t(1)).visitor([&](const SD::Developability_iteration& it) {
      seen.push_back(it);
      return seen.size() < 25;
    }));
  CHECK(r.stopped_by_visitor);
  CHECK(r.iterations == 25);
  REQUIRE(seen.size() == 25);
  CHECK(r.subdivisions == 0); // stopped in the first level
  REQUIRE(r.levels.size() == 1);
  CHECK(r.levels[0].end == std::string("stopped by the visitor"));
  CHECK(seen.back().faces == num_faces(mesh));
  CHECK(seen.back().vertices == num_vertices(mesh));
  for(std::size_t i = 0; i < seen.size(); ++i)
  {
    CHECK(seen[i].iteration == i + 1);
    CHECK(seen[i].level == 0);
    if(i > 0 && !seen[i].line_search_failed && seen[i].flips + seen[i].collapses == 0)
      CHECK(seen[i].energy < seen[i - 1].energy); // the line search accepts descent steps only
  }
  // the mesh holds the positions of the last iteration: its energy is the last one reported
  CHECK(SD::developability_energy(mesh) == Approx(seen.back().energy).epsilon(1e-9));
}

// The stopping rule: a level ends when, over 300 iterations, the descent gained less than 1% of
// the energy and the vertices above the target stopped falling. It fires on the coarse pebble
// (about 1.7k iterations) and the stop is not premature: 600 more iterations that never stop
// gain little. With a cap of 100 iterations it does not fire.
TEMPLATE_TEST_CASE("the flow stops when it has converged, not at the iteration cap", "[developability][flow][stopping]",
                   test::Surface_mesh, test::Polyhedron)
{
  using Mesh = TestType;
  const Mesh input = test::load_mesh<Mesh>("pebble_320.off");
  const auto np = SD::parameters::developability_energy(SD::Developability_energy::intrinsic_width);
  Mesh mesh = input;
  const SD::Developability_flow_result r = SD::make_piecewise_developable(mesh, np);
  REQUIRE(r.levels.size() == 1);
  INFO(r.levels[0].iterations << " iterations, end: " << r.levels[0].end);
  CHECK(r.levels[0].end == std::string("converged"));
  CHECK(r.converged);
  CHECK(r.iterations < 5000);
  CHECK(r.iterations % 50 == 0); // checked every 50 iterations
  // the count it reports, counted here from the stars
  std::size_t measured = 0, above = 0;
  for(const auto& star : interior_stars(mesh))
    if(star.valence >= 4)
    {
      ++measured;
      above += star.lambda > SDI::two_pi * 1e-4;
    }
  CHECK(r.levels[0].measured_vertices == measured);
  CHECK(r.levels[0].vertices_above_target == above);

  Mesh longer = mesh;
  const double energy = SD::developability_energy(longer, np);
  const SD::Developability_flow_result more = SD::make_piecewise_developable(
    longer, SD::parameters::developability_energy(SD::Developability_energy::intrinsic_width,
                                                  SD::parameters::energy_tolerance(0.))
              .number_of_iterations(600));
  CHECK(more.levels[0].end == std::string("iteration limit"));
  CHECK(!more.converged);
  const double after = SD::developability_energy(longer, np);
  INFO("energy at the stop " << energy << ", 600 iterations later " << after);
  CHECK(after >= 0.9 * energy);
  CHECK(double(more.levels[0].vertices_above_target) >= 0.9 * double(above));

  Mesh capped = input;
  const SD::Developability_flow_result c = SD::make_piecewise_developable(
    capped, SD::parameters::developability_energy(SD::Developability_energy::intrinsic_width).number_of_iterations(100));
  CHECK(c.levels[0].end == std::string("iteration limit"));
  CHECK(!c.converged);
}

// A zero gradient ends a level as converged: the L1 energy of a closed surface whose defects are
// all positive is the constant 4 pi (Gauss-Bonnet), so the flow of a noisy sphere has nothing to
// descend from its first iteration.
TEST_CASE("a stationary start ends the level as converged", "[developability][flow][stopping]")
{
  using Mesh = test::Surface_mesh;
  Mesh sphere = make_icosphere<Mesh>(2);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-0.01, 0.01);
  for(auto v : vertices(sphere))
  {
    const test::Point q = get(CGAL::vertex_point, sphere, v);
    put(get(CGAL::vertex_point, sphere), v, test::Point(q.x() + u(rng), q.y() + u(rng), q.z() + u(rng)));
  }
  const SD::Developability_flow_result r = SD::make_piecewise_developable(
    sphere, SD::parameters::developability_energy(SD::Developability_energy::absolute_angle_defect));
  REQUIRE(r.levels.size() == 1);
  CHECK(r.levels[0].end == std::string("gradient below tolerance"));
  CHECK(r.converged);
  CHECK(r.iterations <= 2);
  CHECK(r.levels[0].final_energy == Approx(4. * SDI::pi).epsilon(1e-12));
}

// A target on lambda: the flow of a noisy tube stops as soon as every measured vertex is at
// most the target (counted here apart), before the flow without a target, which goes on to a
// zero gradient.
TEMPLATE_TEST_CASE("the flow stops when every vertex meets the target", "[developability][flow][stopping]",
                   test::Surface_mesh, test::Polyhedron)
{
  using Mesh = TestType;
  const Mesh input = make_tube<Mesh>(16, 6, 1., 1., 2., 0.1);
  Mesh free = input;
  const SD::Developability_flow_result all = SD::make_piecewise_developable(
    free, SD::parameters::developability_energy(SD::Developability_energy::covariance));
  CHECK(all.levels[0].end == std::string("gradient below tolerance"));
  for(double target : {1e-2, 1e-3})
  {
    INFO("target " << target);
    Mesh mesh = input;
    const SD::Developability_flow_result r = SD::make_piecewise_developable(
      mesh, SD::parameters::developability_energy(SD::Developability_energy::covariance,
                                                  SD::parameters::developability_target(target)));
    CHECK(r.levels[0].end == std::string("target reached"));
    CHECK(r.converged);
    CHECK(r.levels[0].vertices_above_target == 0);
    double largest = 0.;
    for(const auto& star : interior_stars(mesh))
      if(star.valence >= 4)
        largest = (std::max)(largest, star.lambda);
    CHECK(largest <= target);
    CHECK(r.iterations < all.iterations);
  }
}

TEST_CASE("levels: subdivisions multiply the faces by 4 and every level descends", "[developability][flow]")
{
  using Mesh = test::Surface_mesh;
  Mesh mesh = make_tube<Mesh>(12, 5, 1., 0.7, 1.5, 0.15);
  const std::size_t F = num_faces(mesh);
  const SD::Developability_flow_result r = SD::make_piecewise_developable(
    mesh, SD::parameters::developability_energy(SD::Developability_energy::intrinsic,
                                                SD::parameters::number_of_subdivisions(std::size_t(2)))
            .number_of_iterations(sanitized ? 40 : 150));
  REQUIRE(r.levels.size() == 3);
  CHECK(r.subdivisions == 2);
  for(const auto& level : r.levels)
  {
    INFO("level from " << level.initial_energy << " to " << level.final_energy << " (" << level.end << ")");
    CHECK(level.final_energy <= level.initial_energy);
    CHECK(level.iterations >= 1);
  }
  CHECK(r.levels[0].faces + 2 * r.collapses >= F); // collapses remove two faces each
  CHECK(r.levels[1].faces <= 4 * r.levels[0].faces);
  CHECK(num_faces(mesh) == r.levels.back().faces);
  CHECK(r.iterations == r.levels[0].iterations + r.levels[1].iterations + r.levels[2].iterations);
  CHECK(r.evaluations >= r.iterations);
  CHECK(r.total_seconds >= r.evaluation_seconds);
  check_valid_mesh(mesh, 0, 2);
}

TEST_CASE("the same flow on Surface_mesh and Polyhedron_3 gives the same shape", "[developability][flow]")
{
  const auto a0 = test::load_mesh<test::Surface_mesh>("bunny_1k.off");
  const auto b0 = test::load_mesh<test::Polyhedron>("bunny_1k.off");
  auto a = a0;
  auto b = b0;
  // without small-angle handling: the Euler operations of the two types number and visit the
  // elements in different orders, so that after the first flip or collapse the runs may differ
  const auto np = SD::parameters::developability_energy(SD::Developability_energy::intrinsic,
                                                        SD::parameters::minimum_angle(0.))
                    .number_of_iterations(sanitized ? 30 : 200);
  const SD::Developability_flow_result ra = SD::make_piecewise_developable(a, np);
  const SD::Developability_flow_result rb = SD::make_piecewise_developable(b, np);
  CHECK(ra.iterations == rb.iterations);
  CHECK(ra.flips == rb.flips);
  CHECK(ra.collapses == rb.collapses);
  REQUIRE(num_vertices(a) == num_vertices(b));
  CHECK(SD::developability_energy(a) == Approx(SD::developability_energy(b)).epsilon(1e-9));
  double largest = 0.;
  auto vb = vertices(b).begin();
  for(auto v : vertices(a))
    largest = (std::max)(largest, (pos(a, v) - pos(b, *vb++)).norm());
  CHECK(largest < 1e-9 * bounding_diagonal(a));
}

TEST_CASE("gradient descent with Armijo also descends, more slowly than L-BFGS", "[developability][flow]")
{
  using Mesh = test::Surface_mesh;
  const Mesh input = make_tube<Mesh>(16, 6, 1., 1., 1.5, 0.1);
  Mesh gd = input, lbfgs = input;
  const std::size_t n = 100;
  SD::make_piecewise_developable(gd, SD::parameters::descent_method(SD::Developability_descent::gradient_descent).number_of_iterations(n));
  SD::make_piecewise_developable(lbfgs, SD::parameters::number_of_iterations(n));
  const double e0 = SD::developability_energy(input), e_gd = SD::developability_energy(gd), e_lbfgs = SD::developability_energy(lbfgs);
  INFO("energy " << e0 << ", after " << n << " iterations: gradient descent " << e_gd << ", L-BFGS " << e_lbfgs);
  CHECK(e_gd < 0.9 * e0);
  CHECK(e_lbfgs < e_gd);
}

TEST_CASE("the flow on an open mesh with boundary: boundary vertices omitted or included", "[developability][flow]")
{
  using Mesh = test::Surface_mesh;
  // a bumpy open patch; with boundary vertices included their stars (partial fans) count too
  Mesh input;
  SD::make_grid(input, 8, 8, 0.1);
  auto vpm = get(CGAL::vertex_point, input);
  for(auto v : vertices(input))
  {
    const auto q = get(vpm, v);
    put(vpm, v, test::Point(q.x(), q.y(), 0.3 * std::sin(3. * q.x()) * std::cos(2. * q.y())));
  }
  for(bool include : {false, true})
  {
    Mesh mesh = input;
    const auto np = SD::parameters::include_boundary_vertices(include).number_of_iterations(300);
    const double e0 = SD::developability_energy(mesh, np);
    SD::make_piecewise_developable(mesh, np);
    const double e1 = SD::developability_energy(mesh, np);
    INFO("boundary included: " << include << ", energy " << e0 << " -> " << e1);
    CHECK(e1 < 0.05 * e0);
    check_valid_mesh(mesh, 1, 1);
  }
}

// --- the user's maps: a separate point map through the flow, per-vertex energies and gradients

namespace {

test::Point nan_point()
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  return test::Point(nan, nan, nan);
}

bool is_finite(const test::Point& p) { return std::isfinite(p.x()) && std::isfinite(p.y()) && std::isfinite(p.z()); }

/// A writable vertex point map other than the mesh's own, filled with the mesh's positions: a
/// `std::map` keyed by the vertex descriptors, through `boost::associative_property_map`. The
/// handles of a Polyhedron_3 stay valid through flips, collapses and splits.
template <class Mesh>
class Associative_points
{
public:
  using vertex_descriptor = typename boost::graph_traits<Mesh>::vertex_descriptor;
  using Map = boost::associative_property_map<std::map<vertex_descriptor, test::Point>>;

  explicit Associative_points(const Mesh& mesh)
  {
    for(auto v : vertices(mesh))
      m_points.emplace(v, get(CGAL::vertex_point, mesh, v));
  }
  Map map() { return Map(m_points); }
  /// The position of `v`, NaN if the map has none.
  test::Point at(vertex_descriptor v) const
  {
    const auto it = m_points.find(v);
    return it == m_points.end() ? nan_point() : it->second;
  }

private:
  std::map<vertex_descriptor, test::Point> m_points;
};

/// For a Surface_mesh, a second point property: `collect_garbage()` renumbers it along with the
/// mesh; new vertices start at NaN.
class Property_points
{
  using Mesh = test::Surface_mesh;

public:
  using vertex_descriptor = Mesh::Vertex_index;
  using Map = Mesh::Property_map<vertex_descriptor, test::Point>;

  explicit Property_points(Mesh& mesh)
    : m_map(mesh.add_property_map<vertex_descriptor, test::Point>("v:user_point", nan_point()).first)
  {
    for(auto v : vertices(mesh))
      put(m_map, v, mesh.point(v));
  }
  Map map() const { return m_map; }
  test::Point at(vertex_descriptor v) const { return get(m_map, v); }

private:
  Map m_map;
};

/// What a user observes of a mesh through a point map: coordinates and faces (as vertex
/// sequences), in iteration order.
struct Observed_mesh
{
  std::vector<double> coordinates;
  std::vector<std::vector<std::size_t>> faces;
};

template <class Mesh, class PointAt>
Observed_mesh observe(const Mesh& mesh, const PointAt& point_at)
{
  Observed_mesh o;
  std::map<typename boost::graph_traits<Mesh>::vertex_descriptor, std::size_t> id;
  for(auto v : vertices(mesh))
  {
    id.emplace(v, id.size());
    const test::Point p = point_at(v);
    o.coordinates.insert(o.coordinates.end(), {p.x(), p.y(), p.z()});
  }
  for(auto f : faces(mesh))
  {
    o.faces.emplace_back();
    for(auto v : vertices_around_face(halfedge(f, mesh), mesh))
      o.faces.back().push_back(id.at(v));
  }
  return o;
}

/// The mesh's own points, moved by an affine map that changes the angles: reading them instead
/// of the user's map would change what the flow flips, collapses and writes.
std::array<double, 3> own_point_of(const test::Point& p) { return {1.5 * p.x() + 3., p.y() - 2., 0.5 * p.z()}; }

/// The flow on bunny_1k with the point map of `Points` (new vertices, flips and collapses) against
/// the same flow with the mesh's own point map on a copy: (a) every vertex of the result has a
/// finite position in the user's map, (b) the two results are the same, vertex for vertex and
/// bit for bit, (c) the mesh's own points were neither read nor written.
template <class Mesh, class Points>
void check_flow_with_separate_points()
{
  using vertex_descriptor = typename boost::graph_traits<Mesh>::vertex_descriptor;
  const Mesh input = test::load_mesh<Mesh>("bunny_1k.off");
  // one subdivision (new vertices), and a minimum angle of about 9 degrees so that the flow flips
  // and collapses within a few iterations
  const auto np = SD::parameters::number_of_subdivisions(std::size_t(1), SD::parameters::minimum_angle(0.15))
                    .number_of_iterations(sanitized ? 8 : 20);

  // the reference: the same flow with the mesh's own point map, on a copy
  Mesh reference = input;
  const SD::Developability_flow_result expected = SD::make_piecewise_developable(reference, np);
  INFO("reference run: " << expected.flips << " flips, " << expected.collapses << " collapses, "
                         << num_vertices(input) << " -> " << num_vertices(reference) << " vertices");
  REQUIRE(expected.subdivisions == 1);
  REQUIRE(expected.flips > 0);
  REQUIRE(expected.collapses > 0);

  Mesh mesh = input;
  Points points(mesh);
  // the mesh's own points move away from the shape, and, for a Surface_mesh, every vertex keeps
  // its input index in a property that collect_garbage() renumbers with it
  auto own = get(CGAL::vertex_point, mesh);
  std::vector<std::array<double, 3>> own_input;
  std::set<std::array<double, 3>> own_input_set;
  for(auto v : vertices(mesh))
  {
    const std::array<double, 3> q = own_point_of(get(own, v));
    put(own, v, test::Point(q[0], q[1], q[2]));
    own_input.push_back(q);
    own_input_set.insert(q);
  }
  constexpr bool surface_mesh = std::is_same<Mesh, test::Surface_mesh>::value;
  using Input_index_map = test::Surface_mesh::Property_map<test::Surface_mesh::Vertex_index, std::size_t>;
  [[maybe_unused]] Input_index_map input_index;
  if constexpr(surface_mesh)
  {
    input_index = mesh.template add_property_map<vertex_descriptor, std::size_t>("v:input_index", SDI::npos).first;
    std::size_t i = 0;
    for(auto v : vertices(mesh))
      put(input_index, v, i++);
  }
  const std::size_t input_vertices = num_vertices(mesh);

  const SD::Developability_flow_result r = SD::make_piecewise_developable(mesh, np.vertex_point_map(points.map()));

  // the same run, operation for operation
  CHECK(r.iterations == expected.iterations);
  CHECK(r.evaluations == expected.evaluations);
  CHECK(r.flips == expected.flips);
  CHECK(r.collapses == expected.collapses);
  CHECK(r.subdivisions == expected.subdivisions);
  REQUIRE(r.levels.size() == expected.levels.size());
  for(std::size_t l = 0; l < r.levels.size(); ++l)
  {
    CHECK(r.levels[l].final_energy == expected.levels[l].final_energy);
    CHECK(r.levels[l].vertices == expected.levels[l].vertices);
  }

  // (a) every vertex of the result, new ones included, has a finite position in the user's map
  std::size_t missing = 0;
  for(auto v : vertices(mesh))
    missing += !is_finite(points.at(v));
  CHECK(missing == 0);
  CHECK(num_vertices(mesh) > input_vertices);

  // (b) vertex for vertex the result of the reference run: same faces, bitwise same positions
  const Observed_mesh got = observe(mesh, [&](vertex_descriptor v) { return points.at(v); });
  const Observed_mesh want = observe(reference, [&](vertex_descriptor v) { return get(CGAL::vertex_point, reference, v); });
  REQUIRE(got.coordinates.size() == want.coordinates.size());
  CHECK(got.faces == want.faces);
  double largest = 0.;
  for(std::size_t i = 0; i < got.coordinates.size(); ++i)
    largest = (std::max)(largest, std::abs(got.coordinates[i] - want.coordinates[i]));
  CHECK(largest == 0.);

  // (c) the mesh's own points: never written. Every collapse removes one vertex, so at least
  // `input - collapses` input vertices survive, each with its own point as it was; no vertex has
  // its own point equal to its output.
  std::size_t unchanged = 0, written = 0;
  for(auto v : vertices(mesh))
  {
    const test::Point q = get(own, v), p = points.at(v);
    unchanged += own_input_set.count({q.x(), q.y(), q.z()});
    written += q == p;
  }
  CHECK(unchanged >= input_vertices - r.collapses);
  CHECK(written == 0);
  if constexpr(surface_mesh)
  {
    std::size_t survivors = 0, moved = 0;
    for(auto v : vertices(mesh))
    {
      const std::size_t i = get(input_index, v);
      if(i == SDI::npos)
        continue; // a vertex of the subdivision
      ++survivors;
      const test::Point q = get(own, v);
      moved += !(q.x() == own_input[i][0] && q.y() == own_input[i][1] && q.z() == own_input[i][2]);
    }
    CHECK(survivors >= input_vertices - r.collapses);
    CHECK(moved == 0);
  }
}

} // namespace

TEMPLATE_TEST_CASE("the flow reads and writes only a separate vertex_point_map, new vertices included",
                   "[developability][flow][point_map]", SD_MESH_TYPES)
{
  using Mesh = TestType;
  if constexpr(std::is_same<Mesh, test::Surface_mesh>::value)
    check_flow_with_separate_points<Mesh, Property_points>();
  else
    check_flow_with_separate_points<Mesh, Associative_points<Mesh>>();
}

// The flow collects the garbage of a Surface_mesh after its collapses, which renumbers the
// vertices: a point map keyed by vertex index outside the mesh (here a std::map) must be carried
// across (once, every vertex got the position of another one and the flow went on, silently,
// from a scrambled mesh: 416 collapses instead of 19).
TEST_CASE("The flow on a Surface_mesh with a std::map point map keyed by vertex index",
          "[developability][flow][point_map]")
{
  check_flow_with_separate_points<test::Surface_mesh, Associative_points<test::Surface_mesh>>();
}

TEMPLATE_TEST_CASE("vertex_energy_map sums to the total energy and vertex_gradient_map is its gradient",
                   "[developability][energy_maps]", SD_MESH_TYPES)
{
  using Mesh = TestType;
  using vertex_descriptor = typename boost::graph_traits<Mesh>::vertex_descriptor;
  using Vector = test::Kernel::Vector_3;
  // central differences of step h = 1e-6 (relative to the bounding diagonal) are accurate to
  // ~h^2 / edge^2 + 1e-16 / h of the gradient, ~1e-10 here: the tolerance, 10 h, is loose for a
  // correct gradient and tight for a wrong one. Where the steps h and h/2 disagree, a kink of
  // the energy (a repeated eigenvalue) lies within the stencil and the coordinate is skipped.
  constexpr double relative_step = 1e-6, tolerance = 10. * relative_step;

  Mesh sphere = make_icosphere<Mesh>(1); // 42 vertices of valence 5 and 6
  {
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> u(-0.05, 0.05);
    auto vpm = get(CGAL::vertex_point, sphere);
    for(auto v : vertices(sphere))
    {
      const test::Point q = get(vpm, v);
      put(vpm, v, test::Point(q.x() + u(rng), q.y() + u(rng), q.z() + u(rng)));
    }
  }
  const Mesh tube = make_tube<Mesh>(8, 3, 1., 0.8, 1.2, 0.15); // open: boundary stars
  struct Case
  {
    const char* name;
    const Mesh* mesh;
    bool boundary;
  };
  for(const Case& c : {Case{"noisy icosphere", &sphere, false}, Case{"noisy tube", &tube, false},
                       Case{"noisy tube with boundary stars", &tube, true}})
    for(SD::Developability_energy e : {SD::Developability_energy::covariance, SD::Developability_energy::intrinsic,
                                       SD::Developability_energy::squared_angle_defect,
                                       SD::Developability_energy::absolute_angle_defect})
    {
      INFO(c.name << ", " << SD::to_string(e));
      const Mesh& mesh = *c.mesh;
      // the positions come from a map of the user, which the finite differences perturb
      std::map<vertex_descriptor, test::Point> points;
      std::map<vertex_descriptor, double> energy;
      std::map<vertex_descriptor, Vector> gradient;
      for(auto v : vertices(mesh))
      {
        points.emplace(v, get(CGAL::vertex_point, mesh, v));
        energy.emplace(v, std::numeric_limits<double>::quiet_NaN());
        gradient.emplace(v, Vector(nan_point().x(), 0., 0.));
      }
      const auto np = SD::parameters::developability_energy(
        e, SD::parameters::include_boundary_vertices(c.boundary,
                                                     CGAL::parameters::vertex_point_map(boost::make_assoc_property_map(points))));
      const double total = SD::developability_energy(
        mesh, SD::parameters::vertex_energy_map(boost::make_assoc_property_map(energy),
                                                SD::parameters::vertex_gradient_map(boost::make_assoc_property_map(gradient), np)));
      CHECK(total > 0.);
      CHECK(SD::developability_energy(mesh, np) == total); // the maps do not change the result
      CHECK(energy.size() == num_vertices(mesh));         // written for the mesh's vertices only
      CHECK(gradient.size() == num_vertices(mesh));

      // the per-vertex energies: nonnegative, zero on omitted boundary stars, summing to the total;
      // on the closed sphere, computed here from the definitions
      double sum = 0.;
      const auto stars = interior_stars(mesh);
      for(auto v : vertices(mesh))
      {
        REQUIRE(std::isfinite(energy.at(v)));
        CHECK(energy.at(v) >= 0.);
        if(!c.boundary && CGAL::is_border(v, mesh))
          CHECK(energy.at(v) == 0.);
        sum += energy.at(v);
      }
      CHECK(sum == Approx(total).epsilon(1e-12));
      if(!c.boundary && e != SD::Developability_energy::intrinsic)
        for(const auto& s : stars)
        {
          if(s.valence < 4)
          {
            CHECK(energy.at(s.v) == 0.); // valence 3: omitted by default
            continue;
          }
          const double defect = SDI::two_pi - s.angle_sum;
          const double value = e == SD::Developability_energy::covariance            ? s.lambda
                               : e == SD::Developability_energy::squared_angle_defect ? defect * defect
                                                                                      : std::abs(defect);
          CHECK(energy.at(s.v) == Approx(value).epsilon(1e-10).margin(1e-14));
        }

      // the per-vertex gradient: central differences of the total, one coordinate at a time
      const double h = relative_step * bounding_diagonal(mesh);
      double largest = 0.;
      for(auto v : vertices(mesh))
      {
        const Vector& g = gradient.at(v);
        REQUIRE((std::isfinite(g.x()) && std::isfinite(g.y()) && std::isfinite(g.z())));
        largest = (std::max)({largest, std::abs(g.x()), std::abs(g.y()), std::abs(g.z())});
      }
      if(e == SD::Developability_energy::absolute_angle_defect && !c.boundary && c.mesh == &sphere)
      {
        // every defect of the sphere is positive: sum |Omega| = sum Omega = 2 pi chi = 4 pi
        // (Gauss-Bonnet), whatever the positions, so the gradient vanishes
        CHECK(total == Approx(4. * SDI::pi).epsilon(1e-13));
        CHECK(largest <= 1e-12);
        continue;
      }
      REQUIRE(largest > 0.);
      std::size_t checked = 0, skipped = 0;
      double worst = 0.;
      for(auto v : vertices(mesh))
        for(int k = 0; k < 3; ++k)
        {
          const test::Point p0 = points.at(v);
          auto at = [&](double t) {
            std::array<double, 3> q{p0.x(), p0.y(), p0.z()};
            q[std::size_t(k)] += t;
            points[v] = test::Point(q[0], q[1], q[2]);
            const double value = SD::developability_energy(mesh, np);
            points[v] = p0;
            return value;
          };
          const double fd = (at(h) - at(-h)) / (2. * h), fd_half = (at(h / 2.) - at(-h / 2.)) / h;
          if(std::abs(fd - fd_half) > 0.1 * tolerance * largest)
          {
            ++skipped;
            continue;
          }
          ++checked;
          worst = (std::max)(worst, std::abs(gradient.at(v)[k] - fd));
        }
      INFO("largest difference to the finite differences " << worst / largest << " of the largest entry, "
                                                             << skipped << " coordinates skipped at a kink");
      CHECK(worst <= tolerance * largest);
      if(e == SD::Developability_energy::squared_angle_defect) // smooth everywhere
        CHECK(skipped == 0);
      CHECK(skipped * 20 <= checked + skipped);
    }
}

// --- bad input

TEMPLATE_TEST_CASE("bad meshes and parameters throw before anything is modified", "[developability][input]",
                   test::Surface_mesh, test::Polyhedron)
{
  using Mesh = TestType;
  const Mesh good = test::load_mesh<Mesh>("bunny_1k.off");
  SECTION("parameters")
  {
    Mesh mesh = good;
    const test::Mesh_snapshot before(mesh);
    auto expect = [&](const auto& np, const std::string& name) {
      try
      {
        SD::make_piecewise_developable(mesh, np);
        FAIL("no exception for " << name);
      }
      catch(const SD::Invalid_parameter& e)
      {
        CHECK(e.name() == name);
      }
      CHECK(test::Mesh_snapshot(mesh) == before);
    };
    expect(SD::parameters::number_of_subdivisions(std::size_t(7)), "number_of_subdivisions");
    expect(SD::parameters::minimum_angle(-0.1), "minimum_angle");
    expect(SD::parameters::minimum_angle(1.), "minimum_angle");
    expect(SD::parameters::minimum_angle(std::numeric_limits<double>::quiet_NaN()), "minimum_angle");
    expect(SD::parameters::gradient_tolerance(-1.), "gradient_tolerance");
    expect(SD::parameters::gradient_tolerance(std::numeric_limits<double>::infinity()), "gradient_tolerance");
    expect(SD::parameters::energy_tolerance(std::numeric_limits<double>::quiet_NaN()), "energy_tolerance");
    expect(SD::parameters::developability_target(-1e-3), "developability_target");
    expect(SD::parameters::developability_target(2.5), "developability_target"); // above 2 pi / 3
    expect(SD::parameters::developability_target(std::numeric_limits<double>::quiet_NaN()), "developability_target");
    expect(SD::parameters::developability_energy(SD::Developability_energy(99)), "developability_energy");
    expect(SD::parameters::descent_method(SD::Developability_descent(7)), "descent_method");
    CHECK_THROWS_AS(SD::developability_energy(mesh, SD::parameters::developability_energy(SD::Developability_energy(99))),
                    SD::Invalid_parameter);
  }
  SECTION("meshes")
  {
    auto expect = [](Mesh mesh, SD::Mesh_defect defect) {
      const test::Mesh_snapshot before(mesh);
      try
      {
        SD::make_piecewise_developable(mesh);
        FAIL("no exception for " << SD::to_string(defect));
      }
      catch(const SD::Invalid_mesh& e)
      {
        CHECK(e.defect() == defect);
        CHECK(std::string(e.what()).find(SD::to_string(defect)) != std::string::npos);
      }
      CHECK(test::Mesh_snapshot(mesh) == before);
      CHECK_THROWS_AS(SD::developability_energy(mesh), SD::Invalid_mesh);
      CHECK_THROWS_AS(SD::developability_metrics(mesh), SD::Invalid_mesh);
    };
    expect(Mesh(), SD::Mesh_defect::empty);
    {
      Mesh mesh = good;
      auto v = *vertices(mesh).begin();
      put(get(CGAL::vertex_point, mesh), v, test::Point(std::numeric_limits<double>::quiet_NaN(), 0., 0.));
      expect(mesh, SD::Mesh_defect::non_finite_coordinates);
    }
    {
      Mesh mesh = good; // two corners of a face at the same place
      const auto h = halfedge(*faces(mesh).begin(), mesh);
      put(get(CGAL::vertex_point, mesh), target(h, mesh), get(CGAL::vertex_point, mesh, source(h, mesh)));
      expect(mesh, SD::Mesh_defect::degenerate_face);
    }
    {
      Mesh mesh; // a quad
      Soup_points p{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
      std::vector<std::vector<std::size_t>> quad{{0, 1, 2, 3}};
      std::vector<test::Point> pts;
      for(const auto& q : p)
        pts.emplace_back(q[0], q[1], q[2]);
      PMP::polygon_soup_to_polygon_mesh(pts, quad, mesh);
      expect(mesh, SD::Mesh_defect::not_triangle);
    }
    {
      Mesh mesh; // two triangles sharing one vertex only: a non-manifold (pinched) vertex
      Soup_points p{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {0, -1, 0}};
      std::vector<test::Point> pts;
      for(const auto& q : p)
        pts.emplace_back(q[0], q[1], q[2]);
      using Vd = typename boost::graph_traits<Mesh>::vertex_descriptor;
      std::vector<Vd> vs;
      for(const auto& q : pts)
        vs.push_back(add_vertex(q, mesh));
      CGAL::Euler::add_face(std::vector<Vd>{vs[0], vs[1], vs[2]}, mesh);
      CGAL::Euler::add_face(std::vector<Vd>{vs[0], vs[3], vs[4]}, mesh);
      expect(mesh, SD::Mesh_defect::non_manifold_vertex);
    }
  }
}
