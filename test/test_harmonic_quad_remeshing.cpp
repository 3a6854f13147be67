// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Harmonic-function quad-dominant remeshing (Dong, Kircher & Garland 2005):
// - the harmonic function meets its constraints exactly and its Laplacian vanishes at every other
//   vertex (<= 1e-10), with either weights and either solver, and both solvers agree;
// - critical points: a monkey saddle, a maximum, a regular vertex (analytic functions on a fan);
//   #max + #min - sum of saddle multiplicities = chi on sphere, torus, eight and kitten, and the
//   index sum equals chi on meshes with boundary;
// - intrinsic Delaunay weights remove the spurious extrema of the cotangent weights (triceratops:
//   its negative weights counted independently, at least one flip for each);
// - isolines lie exactly on their level and run along n x grad u; gradient lines land on their
//   isoline;
// - odd faces: a line that stops on an isoline is continued through the next band into the next
//   T-junction (eight unit squares, every corner 90 degrees, the flat corners now valence 4); a
//   single pentagon is led to the boundary; two triangles are merged rather than split; even
//   polygons split by the diagonal across, or by a centre where a path turns (45 degrees at worst
//   where any diagonal leaves a flat corner), never repeating an edge;
// - a cylinder with its rims as minimum and maximum becomes quads only; eight, kitten, fertility,
//   a hemisphere and three components with boundaries become valid quad-dominant nets of the
//   same topology (>= 85% quads) and, by default, valid meshes of quads only with at most a
//   quarter of the net's T-junctions and at most 0.2 irregular vertices per face; so do a genus-3
//   mesh with 106 holes, 26 components and a mesh of slivers (>= 80% quads);
// - curvature-adapted spacing: half of a strip rolled onto a cylinder gets about four times the
//   vertices and a quarter of the sagitta (h^2 / 8r), the flat half about the same;
// - the output goes into a Polyhedron_3 as well, and into a mesh that already holds faces: the
//   same points and polygons as into an empty Surface_mesh, appended, the old faces untouched;
// - spectacles on a sheet with three holes: the two interior saddles that chi = -2 demands, one
//   with spectacles (the other would cross them), a valid output of the same topology whose
//   boundary follows the input's;
// - the spectacles' re-solve gives the same spectacles and nets of the same size with CHOLMOD;
// - thresholds that are not derived are marked as regression guards with the measured value;
// - one factorization serves new values on the same constrained vertices and every remesh;
// - bad input throws clear exceptions and leaves the meshes untouched;
// - the topology is kept or the remesher throws: generated surfaces (a coarse genus-2 slab, a
//   genus-100 slab, a square with 100 holes, a torus of triangles with 145-degree angles) keep
//   it with quads only and a Hausdorff distance <= 1.5% of the diagonal; the failures found
//   before the check are reproduced (nets with spectacles of another genus on the slabs and on
//   triceratops, an invalid net where two saddles share a band) and now fall back; a tube
//   thinner than the spacing throws Remeshing_failure with every attempt listed, `out`
//   untouched; the soup topology has a negative control and a slit cell is cut by one chord.

#include <test_support.h>

#include <CGAL/Surface_design/Harmonic_quad_remesher.h>
#include <CGAL/Surface_design/harmonic_quad_remeshing.h>
#include <CGAL/Surface_design/internal/Harmonic_quad_remeshing/curves.h>
#include <CGAL/Surface_design/internal/Harmonic_quad_remeshing/net_cells.h>
#include <CGAL/Surface_design/internal/Harmonic_quad_remeshing/odd_faces.h>
#include <CGAL/Surface_design/internal/Harmonic_quad_remeshing/quad_net.h>
#include <CGAL/Surface_design/internal/Harmonic_quad_remeshing/snap.h>
#include <CGAL/Surface_design/internal/Harmonic_quad_remeshing/spectacles.h>
#include <CGAL/Surface_design/mesh_generators.h>
#include <CGAL/Surface_design/quad_mesh_quality.h>

#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Surface_mesh.h>

#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <set>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace SD = CGAL::Surface_design;
namespace SDI = CGAL::Surface_design::internal;
namespace H = CGAL::Surface_design::internal::harmonic_quad;
namespace P = CGAL::Surface_design::parameters;

namespace {

using Quad_mesh = CGAL::Surface_mesh<test::Point>;

// Whether a test of several remeshing cases runs them all on `Mesh`. Under the sanitizers the two
// Polyhedron_3 types run the first case only, every case still running on Surface_mesh: what the
// type changes is the input's adaptor (its indices, points and ids), the same code on any input,
// while most of these tests' time under ASan is the Hausdorff distance of the quality check (90%
// with CGAL's bounded-error distance, measured with perf; the library's own certified distance,
// which replaced it, halved these tests' time there), the same computation on every type (the
// output is a Surface_mesh). In the Release build every type runs every case.
template <class Mesh>
constexpr bool every_case()
{
  return !CGAL_SURFACE_DESIGN_TESTS_UNDER_SANITIZERS || std::is_same_v<Mesh, test::Surface_mesh>;
}
using test::from_soup;
using test::Soup_points;
using test::Soup_triangles;

// the triangles of an nx x ny grid of points numbered i * ny + j (two per cell)
Soup_triangles grid_triangles(std::size_t nx, std::size_t ny)
{
  Soup_triangles triangles;
  for(std::size_t i = 0; i + 1 < nx; ++i)
    for(std::size_t j = 0; j + 1 < ny; ++j)
    {
      const std::size_t a = i * ny + j, b = (i + 1) * ny + j;
      triangles.push_back({a, b, b + 1});
      triangles.push_back({a, b + 1, a + 1});
    }
  return triangles;
}

template <class Mesh>
long euler_characteristic(const Mesh& m)
{
  return long(num_vertices(m)) - long(num_edges(m)) + long(num_faces(m));
}

template <class Mesh, class Traits>
void check_harmonic(const Mesh& mesh, SD::Harmonic_weights weights, const std::string& label)
{
  INFO(label);
  SD::Harmonic_quad_remesher<Mesh, test::Vpm<Mesh>, Traits> remesher(mesh, P::harmonic_weights(weights));
  std::map<typename boost::graph_traits<Mesh>::vertex_descriptor, double> values;
  remesher.harmonic_function(boost::make_assoc_property_map(values));
  const std::vector<double>& u = remesher.harmonic_function();
  REQUIRE(values.size() == num_vertices(mesh));
  REQUIRE(remesher.constraints().size() >= 2);
  for(const auto& [v, value] : remesher.constraints())
    CHECK(values.at(v) == value); // exactly: constrained values are copied, not solved for
  CHECK(remesher.harmonic_residual() <= 1e-10);
  // the maximum principle, for weights that are all positive
  if(remesher.number_of_negative_weights() == 0)
  {
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for(const auto& [v, value] : remesher.constraints())
    {
      lo = (std::min)(lo, value);
      hi = (std::max)(hi, value);
    }
    for(double x : u)
    {
      CHECK(x >= lo - 1e-12);
      CHECK(x <= hi + 1e-12);
    }
  }
}

// The part of a mesh that a remesh appended to it, as a Surface_mesh: the faces after its first
// `old_faces` (in iteration order) with the vertices after its first `old_vertices`; false if an
// appended face uses an older vertex or an older face a newer one.
bool appended_part(const test::Mesh_snapshot& after, std::size_t old_vertices, std::size_t old_faces, Quad_mesh& part)
{
  std::vector<test::Point> points;
  for(std::size_t i = 3 * old_vertices; i + 2 < after.coordinates.size(); i += 3)
    points.emplace_back(after.coordinates[i], after.coordinates[i + 1], after.coordinates[i + 2]);
  std::vector<std::vector<std::size_t>> polygons;
  for(std::size_t f = 0; f < after.faces.size(); ++f)
  {
    if(f >= old_faces)
      polygons.emplace_back();
    for(std::size_t v : after.faces[f])
    {
      if((f >= old_faces) != (v >= old_vertices))
        return false;
      if(f >= old_faces)
        polygons.back().push_back(v - old_vertices);
    }
  }
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, polygons, part);
  return true;
}

// Faces as vertex cycles that start at their smallest vertex index (the same polygons whatever
// halfedge a mesh type keeps for a face)
std::vector<std::vector<std::size_t>> canonical_faces(const test::Mesh_snapshot& s)
{
  std::vector<std::vector<std::size_t>> out = s.faces;
  for(auto& f : out)
    std::rotate(f.begin(), std::min_element(f.begin(), f.end()), f.end());
  return out;
}

// Edges whose cotangent weight cot alpha + cot beta (one term on the boundary) is negative,
// computed here as dot / |cross| of the edge vectors at the opposite corners (the library uses
// Heron's formula on intrinsic lengths): {below -tol, below +tol}, tol = `tolerance` (|cot alpha|
// + |cot beta|), the two counts between which a formula accurate to that relative error lands.
// `interior`: only edges with two faces.
template <class Mesh>
std::pair<std::size_t, std::size_t> negative_cotangent_edges(const Mesh& mesh, bool interior, double tolerance)
{
  std::size_t surely = 0, possibly = 0;
  for(auto e : edges(mesh))
  {
    if(interior && is_border(e, mesh))
      continue;
    double sum = 0., size = 0.;
    for(auto h : {halfedge(e, mesh), opposite(halfedge(e, mesh), mesh)})
    {
      if(is_border(h, mesh))
        continue;
      const test::Point& a = get(CGAL::vertex_point, mesh, source(h, mesh));
      const test::Point& b = get(CGAL::vertex_point, mesh, target(h, mesh));
      const test::Point& c = get(CGAL::vertex_point, mesh, target(next(h, mesh), mesh));
      const auto ca = a - c, cb = b - c;
      const double cot = (ca * cb) / std::sqrt(CGAL::cross_product(ca, cb).squared_length());
      sum += cot;
      size += std::abs(cot);
    }
    surely += sum < -tolerance * size;
    possibly += sum < tolerance * size;
  }
  return {surely, possibly};
}

// Remeshes `mesh` into an empty Out and into an Out that already holds other faces, and compares
// both with `reference` (the same remesh into an empty Surface_mesh): the same points in the
// same order, the same polygons, the old faces kept in front of the new ones.
template <class Out, class Mesh>
void check_appended_remesh(const Mesh& mesh, SD::Harmonic_quad_remesher<Mesh>& remesher, bool all_quads,
                           const Quad_mesh& reference, const SD::Harmonic_quad_remeshing_result& rr,
                           const SD::Quad_mesh_quality& qr)
{
  using Out_vertex = typename boost::graph_traits<Out>::vertex_descriptor;
  INFO((std::is_same<Out, test::Polyhedron>::value ? "into a Polyhedron_3" : "into a Surface_mesh"));
  const test::Mesh_snapshot expected(reference);
  // (the Hausdorff distance is not needed: the points are compared with the reference's)
  const auto no_hausdorff = P::hausdorff_error_bound(1.);
  auto check_like_reference = [&](const SD::Quad_mesh_quality& q, const SD::Harmonic_quad_remeshing_result& r,
                                  const test::Mesh_snapshot& got) {
    CHECK(q.valid);
    CHECK(q.same_topology);
    CHECK(q.vertices == qr.vertices);
    CHECK(q.edges == qr.edges);
    CHECK(q.faces == qr.faces);
    CHECK(q.faces_by_sides == qr.faces_by_sides); // with all_quads: quads only, as the reference
    CHECK(q.quad_fraction == qr.quad_fraction);
    CHECK(q.t_junctions == qr.t_junctions);
    CHECK(q.irregular_vertices == qr.irregular_vertices);
    CHECK(r.faces == rr.faces);
    CHECK(r.vertices == rr.vertices);
    CHECK(r.spectacles == rr.spectacles);
    CHECK(got.coordinates == expected.coordinates);
    CHECK(canonical_faces(got) == canonical_faces(expected));
  };
  {
    Out fresh;
    const SD::Harmonic_quad_remeshing_result r = remesher.remesh(fresh, P::all_quads(all_quads));
    check_like_reference(SD::quad_mesh_quality(fresh, mesh, CGAL::parameters::default_values(), no_hausdorff), r,
                         test::Mesh_snapshot(fresh));
  }
  // an Out that holds an annulus of triangles (a 3 x 3 grid without its middle cell) and, apart
  // from it, one quad: two components, three boundary loops, chi = 0 + 1
  Out out;
  SD::make_grid(out, 3, 3, 0., [](std::size_t i, std::size_t j) { return i == 1 && j == 1; });
  std::vector<Out_vertex> quad;
  for(const test::Point& p : {test::Point(5, 0, 0), test::Point(6, 0, 0), test::Point(6, 1, 0), test::Point(5, 1, 0)})
    quad.push_back(add_vertex(p, out));
  CGAL::Euler::add_face(quad, out);
  long chi_before = 0;
  std::size_t loops_before = 0, components_before = 0;
  SDI::topology_counts(out, chi_before, loops_before, components_before);
  REQUIRE(chi_before == 1);
  REQUIRE(loops_before == 3);
  REQUIRE(components_before == 2);
  const test::Mesh_snapshot before(out);
  const std::size_t old_vertices = num_vertices(out), old_faces = num_faces(out);
  CHECK_THROWS_AS(SD::harmonic_quad_remeshing(mesh, out, P::target_edge_length(-1.)), SD::Invalid_parameter);
  CHECK_THROWS_AS(SD::harmonic_quad_remeshing(mesh, out, P::harmonic_weights(static_cast<SD::Harmonic_weights>(7))),
                  SD::Invalid_parameter);
  CHECK(test::Mesh_snapshot(out) == before);

  // (the free function: the same remesh, since the constraints are the default ones)
  const SD::Harmonic_quad_remeshing_result r = SD::harmonic_quad_remeshing(mesh, out, P::all_quads(all_quads));
  CHECK(CGAL::is_valid_polygon_mesh(out));
  CHECK(num_vertices(out) == old_vertices + r.vertices);
  CHECK(num_faces(out) == old_faces + r.faces);
  // what was there is still there, unchanged and first
  const test::Mesh_snapshot after(out);
  REQUIRE(after.faces.size() >= old_faces);
  REQUIRE(after.coordinates.size() >= before.coordinates.size());
  CHECK(std::equal(before.coordinates.begin(), before.coordinates.end(), after.coordinates.begin()));
  CHECK(std::equal(before.faces.begin(), before.faces.end(), after.faces.begin()));
  // the whole: the old parts and the remeshed surface side by side, not connected
  long chi = 0;
  std::size_t loops = 0, components = 0;
  SDI::topology_counts(out, chi, loops, components);
  CHECK(chi == chi_before + qr.euler_characteristic);
  CHECK(loops == loops_before + qr.boundary_loops);
  CHECK(components == components_before + qr.connected_components);
  // the appended part alone is the reference
  Quad_mesh part;
  REQUIRE(appended_part(after, old_vertices, old_faces, part));
  check_like_reference(SD::quad_mesh_quality(part, mesh, CGAL::parameters::default_values(), no_hausdorff), r,
                       test::Mesh_snapshot(part));
}

} // namespace

TEMPLATE_TEST_CASE("The harmonic function meets its constraints and is harmonic elsewhere",
                   "[harmonic_quad][harmonic]", SD_MESH_TYPES)
{
  using Mesh = TestType;
  const Mesh eight = test::load_mesh<Mesh>("eight.off");
  const Mesh hemisphere = test::load_mesh<Mesh>("hemisphere.off");
  Mesh torus;
  SD::make_torus(torus, 40, 16, 1., 0.3);
  for(auto weights : {SD::Harmonic_weights::cotangent, SD::Harmonic_weights::intrinsic_delaunay})
  {
#define SD_CHECK_WITH(Traits, name)                                                                \
  check_harmonic<Mesh, Traits>(eight, weights, std::string("eight, ") + name);                     \
  check_harmonic<Mesh, Traits>(hemisphere, weights, std::string("hemisphere, ") + name);           \
  check_harmonic<Mesh, Traits>(torus, weights, std::string("torus, ") + name);
    SD_FOR_EACH_SOLVER(SD_CHECK_WITH)
#undef SD_CHECK_WITH
  }
#if defined(CGAL_SURFACE_DESIGN_HAS_CHOLMOD)
  // the two solvers agree
  SD::Harmonic_quad_remesher<Mesh, test::Vpm<Mesh>, SD::Default_solver_traits> ldlt(eight);
  SD::Harmonic_quad_remesher<Mesh, test::Vpm<Mesh>, SD::Cholmod_solver_traits> cholmod(eight);
  const std::vector<double>& a = ldlt.harmonic_function();
  const std::vector<double>& b = cholmod.harmonic_function();
  for(std::size_t v = 0; v < a.size(); ++v)
    CHECK(std::abs(a[v] - b[v]) <= 1e-8);
#else
  SD_CHOLMOD_UNAVAILABLE("the LDLT / CHOLMOD cross-check of the harmonic function");
#endif
}

TEMPLATE_TEST_CASE("The remesher's types are deduced from the mesh and the named parameters",
                   "[harmonic_quad][harmonic]", SD_MESH_TYPES)
{
  using Mesh = TestType;
  Mesh torus;
  SD::make_torus(torus, 24, 10, 1., 0.3);
  SD::Harmonic_quad_remesher plain(torus);
  static_assert(std::is_same_v<decltype(plain), SD::Harmonic_quad_remesher<Mesh>>);
  const auto vpm = get(CGAL::vertex_point, torus); // a writable map: its own type is deduced
  SD::Harmonic_quad_remesher chosen(torus, P::sparse_linear_solver(SD::Simplicial_ldlt_solver_traits()).vertex_point_map(vpm));
  static_assert(std::is_same_v<decltype(chosen), SD::Harmonic_quad_remesher<Mesh, std::decay_t<decltype(vpm)>,
                                                                            SD::Simplicial_ldlt_solver_traits>>);
  // the same function either way
  const std::vector<double>& a = plain.harmonic_function();
  const std::vector<double>& b = chosen.harmonic_function();
  REQUIRE(a.size() == b.size());
  for(std::size_t v = 0; v < a.size(); ++v)
    CHECK(std::abs(a[v] - b[v]) <= 1e-9);
}

TEMPLATE_TEST_CASE("Linear functions are harmonic on a planar mesh with obtuse triangles, with both weights",
                   "[harmonic_quad][harmonic]", SD_MESH_TYPES)
{
  // The cotangent Laplacian of any planar triangulation (the intrinsic Delaunay one included)
  // reproduces linear functions: a wrong cotangent or a wrong flipped edge length breaks this.
  using Mesh = TestType;
  Mesh grid;
  SD::make_grid(grid, 14, 11, 0.16); // jittered: obtuse triangles, negative cotangent weights
  auto linear = [](const test::Point& p) { return 0.7 * p.x() - 0.3 * p.y() + 0.1; };
  std::vector<std::pair<typename boost::graph_traits<Mesh>::vertex_descriptor, double>> boundary;
  for(auto v : vertices(grid))
    if(CGAL::is_border(v, grid))
      boundary.emplace_back(v, linear(get(CGAL::vertex_point, grid, v)));
  REQUIRE(boundary.size() == 2 * (14 + 11));
  std::size_t negative_cotangent = 0;
  for(auto weights : {SD::Harmonic_weights::cotangent, SD::Harmonic_weights::intrinsic_delaunay})
  {
    SD::Harmonic_quad_remesher<Mesh> remesher(grid, P::harmonic_constraints(boundary, P::harmonic_weights(weights)));
    std::map<typename boost::graph_traits<Mesh>::vertex_descriptor, double> u;
    remesher.harmonic_function(boost::make_assoc_property_map(u));
    double worst = 0.;
    for(auto v : vertices(grid))
      worst = (std::max)(worst, std::abs(u.at(v) - linear(get(CGAL::vertex_point, grid, v))));
    CHECK(worst <= 1e-12);
    if(weights == SD::Harmonic_weights::cotangent)
      negative_cotangent = remesher.number_of_negative_weights();
    else
    {
      CHECK(remesher.number_of_flips() > 0);
      CHECK(remesher.number_of_negative_weights() < negative_cotangent);
    }
  }
  CHECK(negative_cotangent > 10);
}

TEST_CASE("Critical points of analytic functions on a fan: monkey saddle, maximum, regular",
          "[harmonic_quad][critical]")
{
  // a hexagonal fan around vertex 0, and a second ring so that the ring vertices are interior too
  Soup_points points = {{0, 0, 0}};
  for(int ring = 1; ring <= 2; ++ring)
    for(int k = 0; k < 6; ++k)
    {
      const double a = SDI::pi / 3. * (k + (ring == 2 ? 0.5 : 0.));
      points.push_back({ring * std::cos(a), ring * std::sin(a), 0.});
    }
  Soup_triangles triangles;
  for(std::size_t k = 0; k < 6; ++k)
  {
    const std::size_t a = 1 + k, b = 1 + (k + 1) % 6, c = 7 + k;
    triangles.push_back({0, a, b});
    triangles.push_back({a, c, b});
    triangles.push_back({b, c, 7 + (k + 1) % 6});
  }
  const test::Surface_mesh mesh = from_soup<test::Surface_mesh>(points, triangles);
  SDI::Mesh_indices<test::Surface_mesh> idx(mesh);
  const H::Trace_mesh m = H::make_trace_mesh(idx, get(CGAL::vertex_point, mesh));
  auto classify = [&](auto f) {
    std::vector<double> u;
    for(const auto& p : m.point)
      u.push_back(f(p.x(), p.y()));
    const auto [list, sum] = H::critical_points(m, u);
    CHECK(sum == 1); // a disk
    for(const auto& c : list)
      if(c.vertex == 0)
        return std::make_pair(c.kind, c.multiplicity);
    return std::make_pair(H::Critical_kind::regular, 0);
  };
  // Re (x + iy)^3: three lower and three upper wedges around the origin
  const auto monkey = classify([](double x, double y) { return x * x * x - 3. * x * y * y; });
  CHECK(monkey.first == H::Critical_kind::saddle);
  CHECK(monkey.second == 2);
  const auto saddle = classify([](double x, double y) { return x * x - y * y + 0.1 * x * y; });
  CHECK(saddle.first == H::Critical_kind::saddle);
  CHECK(saddle.second == 1);
  CHECK(classify([](double x, double y) { return -(x * x + y * y); }).first == H::Critical_kind::maximum);
  CHECK(classify([](double x, double y) { return 2. * x + y; }).first == H::Critical_kind::regular);
  // ties are broken by index: a constant function has one minimum (vertex 0, the smallest index)
  CHECK(classify([](double, double) { return 1.; }).first == H::Critical_kind::minimum);
}

TEMPLATE_TEST_CASE("#max + #min - sum of saddle multiplicities is the Euler characteristic",
                   "[harmonic_quad][critical]", SD_MESH_TYPES)
{
  using Mesh = TestType;
  Mesh sphere, torus;
  SD::make_sphere(sphere, 8);
  SD::make_torus(torus, 40, 16, 1., 0.3);
  const std::vector<std::pair<std::string, Mesh>> closed = {
    {"sphere", sphere}, {"torus", torus}, {"eight", test::load_mesh<Mesh>("eight.off")},
    {"kitten", test::load_mesh<Mesh>("kitten.off")}};
  for(const auto& [name, mesh] : closed)
  {
    INFO(name);
    SD::Harmonic_quad_remesher<Mesh> remesher(mesh);
    const SD::Harmonic_critical_points cp = remesher.critical_points();
    CHECK(cp.euler_characteristic == euler_characteristic(mesh));
    CHECK(long(cp.maxima.size() + cp.minima.size()) - cp.saddle_multiplicity() == cp.euler_characteristic);
    CHECK(cp.index_sum == cp.euler_characteristic);
  }
  // eight (genus 2) with one minimum and one maximum: four saddles; kitten (genus 1): two
  {
    SD::Harmonic_quad_remesher<Mesh> remesher(test::load_mesh<Mesh>("eight.off"), P::protrusion_maxima(false));
    const SD::Harmonic_critical_points cp = remesher.critical_points();
    CHECK(cp.minima.size() == 1);
    CHECK(cp.maxima.size() == 1);
    CHECK(cp.saddle_multiplicity() == 4);
  }
  // with boundary: the index sum (1 - chi of the lower link, over every vertex) is still chi
  for(const std::string name : {"hemisphere.off", "camelhead.off", "blobby_3cc.off"})
  {
    INFO(name);
    const Mesh mesh = test::load_mesh<Mesh>(name);
    SD::Harmonic_quad_remesher<Mesh> remesher(mesh);
    CHECK(remesher.critical_points().index_sum == euler_characteristic(mesh));
  }
}

TEMPLATE_TEST_CASE("Intrinsic Delaunay weights remove the spurious extrema of cotangent weights",
                   "[harmonic_quad][harmonic]", SD_MESH_TYPES)
{
  using Mesh = TestType;
  // triceratops: slivers down to 0.0002 degrees, many negative cotangent weights
  const Mesh mesh = test::load_mesh<Mesh>("triceratops.off");
  SD::Harmonic_quad_remesher<Mesh> cotangent(mesh);
  SD::Harmonic_quad_remesher<Mesh> delaunay(mesh, P::harmonic_weights(SD::Harmonic_weights::intrinsic_delaunay));
  CHECK(cotangent.constraints() == delaunay.constraints());
  // the negative weights counted independently (dot / |cross| at the opposite corners, not Heron's
  // formula on lengths, which loses about eps / theta^2 on a needle of angle theta: 2e-5 at 2e-4
  // degrees, hence the band of 1e-4): 1402 surely, 1444 at most (this build), all interior edges
  const auto [surely, possibly] = negative_cotangent_edges(mesh, false, 1e-4);
  CHECK(cotangent.number_of_negative_weights() >= surely);
  CHECK(cotangent.number_of_negative_weights() <= possibly);
  // regression guard (a hard input stays hard): measured 1436 on triceratops, margin 436
  CHECK(cotangent.number_of_negative_weights() > 1000);
  // an interior edge with alpha + beta > pi has no empty circumdisk (any circle through its ends
  // holds one of the two opposite corners), so it is no edge of the intrinsic Delaunay
  // triangulation: each is flipped away, one flip each. Hence flips >= 1402 > 1000 (measured 1668)
  CHECK(delaunay.number_of_flips() >= negative_cotangent_edges(mesh, true, 1e-4).first);
  CHECK(delaunay.number_of_flips() > 1000);
  // regression guard: measured 25 of 1436 (none in exact arithmetic on this closed mesh: rounding
  // at near-zero weights), margin 46
  CHECK(delaunay.number_of_negative_weights() < cotangent.number_of_negative_weights() / 20);
  CHECK(cotangent.critical_points().spurious_extrema > 0);
  const SD::Harmonic_critical_points cp = delaunay.critical_points();
  CHECK(cp.spurious_extrema == 0);
  CHECK(cp.minima.size() + cp.maxima.size() == delaunay.constraints().size());
}

TEST_CASE("Isolines lie on their level along n x grad u, gradient lines land on their isoline",
          "[harmonic_quad][curves]")
{
  const test::Surface_mesh mesh = test::load_mesh<test::Surface_mesh>("kitten.off");
  SD::Harmonic_quad_remesher<test::Surface_mesh> remesher(mesh);
  const std::vector<double> u = remesher.harmonic_function();
  SDI::Mesh_indices<test::Surface_mesh> idx(mesh);
  const H::Trace_mesh m = H::make_trace_mesh(idx, get(CGAL::vertex_point, mesh));
  std::vector<double> sorted(u);
  std::sort(sorted.begin(), sorted.end());
  std::vector<std::vector<H::Face_level>> levels(m.number_of_faces());
  std::vector<H::Isoline> all;
  std::size_t checked_points = 0;
  for(double c : {0.1, 0.3, 0.5, 0.7, 0.9})
  {
    c = H::avoid_vertex_values(c, sorted, 1e-9);
    for(H::Isoline& iso : H::extract_isolines(m, u, c))
    {
      CHECK(iso.closed); // a closed mesh
      for(std::size_t k = 0; k < iso.segments(); ++k)
      {
        const std::size_t f = iso.faces[k];
        const auto& t = m.tri[f];
        // the point lies on its level: u interpolated linearly in the face
        const Eigen::Vector3d g = m.gradient(f, u);
        const double value = u[t[0]] + g.dot(iso.point[k] - m.point[t[0]]);
        CHECK(std::abs(value - c) <= 1e-9);
        // and the segment runs along n x grad u
        CHECK((iso.segment_end(k) - iso.point[k]).dot(m.normal[f].cross(g)) > 0.);
        ++checked_points;
      }
      const std::size_t id = all.size();
      for(std::size_t k = 0; k < iso.segments(); ++k)
        levels[iso.faces[k]].push_back({c, id, k});
      all.push_back(std::move(iso));
    }
  }
  CHECK(checked_points > 500);
  // ascending lines from the 0.3 isoline end on the 0.5 one (or at an extremum)
  H::Gradient_walker walker(m, u, levels);
  std::size_t landed = 0;
  for(const H::Isoline& iso : all)
  {
    if(std::abs(iso.value - 0.3) > 1e-6)
      continue;
    for(std::size_t k = 0; k < iso.segments(); k += 7)
    {
      const H::Trace_end e = walker.from_face(iso.faces[k], iso.point[k], iso.value, +1);
      REQUIRE(e.kind != H::Trace_end::lost);
      if(e.kind != H::Trace_end::isoline)
        continue;
      const H::Isoline& target = all[e.curve];
      CHECK(std::abs(target.value - 0.5) <= 1e-6);
      const std::size_t f = target.faces[e.segment];
      const double value = u[m.tri[f][0]] + m.gradient(f, u).dot(e.point - m.point[m.tri[f][0]]);
      CHECK(std::abs(value - target.value) <= 1e-9);
      ++landed;
    }
  }
  CHECK(landed > 20);
}

namespace {

// corner angles (degrees) of every face of a planar soup in the plane z = 0, and the number of
// faces around every vertex
void planar_soup_angles(const H::Polygon_soup& soup, std::vector<double>& angles, std::vector<std::size_t>& valence)
{
  angles.clear();
  valence.assign(soup.points.size(), 0);
  for(const auto& f : soup.faces)
    for(std::size_t k = 0; k < f.size(); ++k)
    {
      angles.push_back(H::polygon_corner_angle(soup.points[f[(k + f.size() - 1) % f.size()]], soup.points[f[k]],
                                               soup.points[f[(k + 1) % f.size()]], Eigen::Vector3d::UnitZ()) *
                       180. / SDI::pi);
      ++valence[f[k]];
    }
}

} // namespace

TEST_CASE("Odd faces: a line that ends on an isoline is continued to the next T-junction", "[harmonic_quad][odd_faces]")
{
  // a 2 x 4 rectangle in bands of height 1; the vertical line x = 1 runs in the lowest and the
  // highest band only, so the middle bands are pentagons with a flat corner at (1, 1) and (1, 3)
  H::Polygon_soup soup;
  auto add = [&](double x, double y) {
    soup.points.emplace_back(x, y, 0.);
    soup.kind.push_back(H::Net_point_kind::crossing);
    return soup.points.size() - 1;
  };
  std::size_t v[3][5];
  for(int y = 0; y <= 4; ++y)
    for(int x = 0; x <= 2; x += 2)
      v[x][y] = add(x, y);
  for(int y : {0, 1, 3, 4})
    v[1][y] = add(1, y);
  soup.faces = {{v[0][0], v[1][0], v[1][1], v[0][1]},
                {v[1][0], v[2][0], v[2][1], v[1][1]},
                {v[0][1], v[1][1], v[2][1], v[2][2], v[0][2]},
                {v[0][2], v[2][2], v[2][3], v[1][3], v[0][3]},
                {v[0][3], v[1][3], v[1][4], v[0][4]},
                {v[1][3], v[2][3], v[2][4], v[1][4]}};
  const H::Odd_face_statistics s = H::Odd_face_pairing(soup).run();
  CHECK(s.odd_faces == 2);
  CHECK(s.paths == 1); // straight up from one pentagon into the other, not to the boundary
  CHECK(s.boundary_paths == 0);
  CHECK(s.split_edges == 1);
  CHECK(s.unpaired == 0);
  REQUIRE(soup.points.size() == 15);
  CHECK((soup.points.back() - Eigen::Vector3d(1., 2., 0.)).norm() <= 1e-15); // the midpoint of y = 2
  // eight unit squares: every corner a right angle, every interior vertex of valence 4
  REQUIRE(soup.faces.size() == 8);
  std::vector<double> angles;
  std::vector<std::size_t> valence;
  planar_soup_angles(soup, angles, valence);
  for(const auto& f : soup.faces)
    CHECK(f.size() == 4);
  for(double a : angles)
    CHECK(std::abs(a - 90.) <= 1e-9);
  for(int y = 1; y <= 3; ++y)
    CHECK(valence[y == 2 ? 14 : v[1][y]] == 4);
  CHECK(CGAL::Polygon_mesh_processing::is_polygon_soup_a_polygon_mesh(soup.faces));
}

TEST_CASE("Odd faces: a single pentagon is led to the boundary, a triangle is merged and not made flat",
          "[harmonic_quad][odd_faces]")
{
  // the lowest band of the previous case only: one pentagon above two quads
  H::Polygon_soup soup;
  soup.points = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {0, 1, 0}, {1, 1, 0}, {2, 1, 0}, {0, 2, 0}, {2, 2, 0}};
  soup.kind.assign(soup.points.size(), H::Net_point_kind::crossing);
  soup.faces = {{0, 1, 4, 3}, {1, 2, 5, 4}, {3, 4, 5, 7, 6}};
  H::Odd_face_statistics s = H::Odd_face_pairing(soup).run();
  CHECK(s.odd_faces == 1);
  CHECK(s.boundary_paths == 1);
  CHECK(s.split_edges == 1);
  REQUIRE(soup.points.size() == 9);
  CHECK((soup.points.back() - Eigen::Vector3d(1., 2., 0.)).norm() <= 1e-15);
  std::vector<double> angles;
  std::vector<std::size_t> valence;
  planar_soup_angles(soup, angles, valence);
  CHECK(soup.faces.size() == 4);
  for(double a : angles)
    CHECK(std::abs(a - 90.) <= 1e-9);

  // two triangles making up a unit square between two unit squares: odd neighbours are merged
  // across their edge instead of getting a vertex there (which would leave two flat corners)
  H::Polygon_soup tri;
  tri.points = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, 0, 0}, {0, 1, 0}, {1, 1, 0}, {2, 1, 0}, {3, 1, 0}};
  tri.kind.assign(tri.points.size(), H::Net_point_kind::crossing);
  tri.faces = {{0, 1, 5, 4}, {1, 2, 6}, {1, 6, 5}, {2, 3, 7, 6}};
  s = H::Odd_face_pairing(tri).run();
  CHECK(s.odd_faces == 2);
  CHECK(s.paths == 1);
  CHECK(s.merged_triangles == 1);
  CHECK(s.split_edges == 0);
  CHECK(tri.points.size() == 8);
  REQUIRE(tri.faces.size() == 3);
  planar_soup_angles(tri, angles, valence);
  for(double a : angles)
    CHECK(std::abs(a - 90.) <= 1e-9);
  CHECK(CGAL::Polygon_mesh_processing::is_polygon_soup_a_polygon_mesh(tri.faces));
}

TEST_CASE("Even polygons split into quads: diagonals across, a centre where a path turns", "[harmonic_quad][odd_faces]")
{
  // the unit square with vertices added in the middle of the bottom (1), the top (4) and the
  // right (6) side
  H::Polygon_soup soup;
  soup.points = {{0, 0, 0}, {0.5, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0.5, 1, 0}, {0, 1, 0}, {1, 0.5, 0}};
  soup.kind.assign(soup.points.size(), H::Net_point_kind::crossing);
  std::set<std::pair<std::size_t, std::size_t>> edges;
  H::Even_polygon_splitter splitter(soup, edges);
  auto worst_corner = [&](const std::vector<std::array<std::size_t, 4>>& quads) {
    double worst = 0.;
    for(const auto& q : quads)
      for(std::size_t k = 0; k < 4; ++k)
        worst = (std::max)(worst, std::abs(H::polygon_corner_angle(soup.points[q[(k + 3) % 4]], soup.points[q[k]],
                                                                   soup.points[q[(k + 1) % 4]], Eigen::Vector3d::UnitZ()) *
                                                 180. / SDI::pi -
                                               90.));
    return worst;
  };
  // opposite sides: the diagonal 1 - 4, two half squares
  const auto across = splitter.split({0, 1, 2, 3, 4, 5});
  REQUIRE(across.size() == 2);
  CHECK(worst_corner(across) <= 1e-9);
  CHECK(soup.points.size() == 7);
  CHECK(edges.count({1, 4}) == 1);
  // adjacent sides: any diagonal leaves a flat corner (90 degrees off); a centre joined to the
  // two added vertices and the far corner makes three quads 45 degrees off at worst
  const auto turn = splitter.split({0, 1, 2, 6, 3, 5});
  REQUIRE(turn.size() == 3);
  REQUIRE(soup.points.size() == 8);
  CHECK(worst_corner(turn) <= 45. + 1e-9);
  std::set<std::size_t> spokes;
  for(const auto& q : turn)
  {
    CHECK(q[3] == 7);
    spokes.insert(q[0]);
  }
  CHECK(spokes == std::set<std::size_t>{1, 6, 5});
  // a diagonal that is an edge already is never taken: with all three taken, a centre
  std::set<std::pair<std::size_t, std::size_t>> taken{{1, 4}, {0, 3}, {2, 5}};
  H::Polygon_soup square = soup;
  H::Even_polygon_splitter blocked(square, taken);
  const auto other = blocked.split({0, 1, 2, 3, 4, 5});
  REQUIRE(other.size() == 3);
  for(const auto& q : other)
    CHECK(q[3] == soup.points.size());
}

TEMPLATE_TEST_CASE("A cylinder with its rims as minimum and maximum becomes quads only",
                   "[harmonic_quad][remesh]", SD_MESH_TYPES)
{
  using Mesh = TestType;
  Soup_points points;
  Soup_triangles triangles;
  test::ruled_soup(48, 40, false, false, points, triangles, 4.);
  const Mesh mesh = from_soup<Mesh>(points, triangles);
  std::vector<std::pair<typename boost::graph_traits<Mesh>::vertex_descriptor, double>> rims;
  for(auto v : vertices(mesh))
  {
    const double z = get(CGAL::vertex_point, mesh, v).z();
    if(z < 1e-9 || z > 4. - 1e-9)
      rims.emplace_back(v, z < 1e-9 ? 0. : 1.);
  }
  REQUIRE(rims.size() == 96);
  Quad_mesh out;
  const SD::Harmonic_quad_remeshing_result r =
    SD::harmonic_quad_remeshing(mesh, out, P::harmonic_constraints(rims, P::target_edge_length(0.25)));
  const SD::Quad_mesh_quality q = SD::quad_mesh_quality(out, mesh);
  INFO("faces " << q.faces << " quads " << q.faces_by_sides[1] << "; lines " << r.gradient_lines << " started "
                  << r.started_lines << " stopped " << r.stopped_lines << " merged " << r.merged_lines << " levels "
                  << r.levels << " isolines " << r.isolines);
  CHECK(q.valid);
  CHECK(q.same_topology);
  CHECK(q.boundary_loops == 2);
  CHECK(q.faces_by_sides[1] == q.faces); // every face a quad
  CHECK(q.irregular_vertices == 0);
  CHECK(q.t_junctions == 0);
  CHECK(r.stopped_lines == 0);
  // about 2 pi / 0.25 lines around and 4 / 0.25 bands
  CHECK(q.faces >= 20 * 12);
  CHECK(q.faces <= 30 * 20);
  CHECK(q.angle_deviation_max <= 5.);
  CHECK(q.relative_hausdorff_distance <= 0.01);
  // one line per column of vertices: the lines run along mesh edges and through vertices, and
  // end on the rims at their vertices (equal values along the rim: no crawling along it)
  Quad_mesh aligned;
  SD::harmonic_quad_remeshing(mesh, aligned, P::harmonic_constraints(rims, P::target_edge_length(2. * SDI::pi / 48.)));
  const SD::Quad_mesh_quality qa = SD::quad_mesh_quality(aligned, mesh);
  INFO("aligned: faces " << qa.faces << " quads " << qa.faces_by_sides[1]);
  CHECK(qa.valid);
  CHECK(qa.same_topology);
  CHECK(qa.faces_by_sides[1] == qa.faces);
}

TEST_CASE("The net's four phases on a cylinder: levels, crossings and spacing, tracing, assembly",
          "[harmonic_quad][net]")
{
  // A cylinder of radius 1 and height 4 with its rims at 0 and 1: u = z / 4 (|grad u| = 1/4), so
  // with h = 0.25 the levels are 1/16 apart, every isoline is a circle of length 2 pi, and
  // 2 pi / h = 25.1 lines run straight up, each crossing every isoline.
  using Mesh = CGAL::Surface_mesh<test::Point>;
  Soup_points points;
  Soup_triangles triangles;
  test::ruled_soup(48, 40, false, false, points, triangles, 4.);
  const Mesh mesh = from_soup<Mesh>(points, triangles);
  std::vector<std::pair<Mesh::Vertex_index, double>> rims;
  for(auto v : vertices(mesh))
  {
    const double z = mesh.point(v).z();
    if(z < 1e-9 || z > 4. - 1e-9)
      rims.emplace_back(v, z < 1e-9 ? 0. : 1.);
  }
  SD::Harmonic_quad_remesher<Mesh> remesher(mesh, P::harmonic_constraints(rims));
  const std::vector<double>& u = remesher.harmonic_function();
  const SDI::Mesh_indices<Mesh> idx(mesh);
  const H::Trace_mesh m = H::make_trace_mesh(idx, get(CGAL::vertex_point, mesh));
  for(auto v : vertices(mesh))
    REQUIRE(std::abs(u[idx.index(v)] - mesh.point(v).z() / 4.) <= 1e-9); // the function is z / 4
  H::Net_options options;
  options.edge_length = 0.25;

  // levels: h times the gradient norm apart, strictly inside (0, 1)
  const std::vector<double> levels = H::Quad_net_builder(m, u, options).regular_levels();
  REQUIRE(levels.size() >= 14);
  CHECK(levels.size() <= 16);
  for(std::size_t k = 0; k < levels.size(); ++k)
  {
    CHECK(levels[k] > 0.);
    CHECK(levels[k] < 1.);
    if(k > 0)
      CHECK(std::abs(levels[k] - levels[k - 1] - 1. / 16.) <= 1e-6);
  }

  H::Quad_net_builder builder(m, u, options);
  const H::Polygon_soup soup = builder.build();
  const H::Net_statistics& stats = builder.statistics();
  // one closed isoline of length 2 pi (to the chords' error) per level
  CHECK(stats.levels == levels.size());
  REQUIRE(builder.isolines().size() == levels.size());
  for(const H::Isoline& iso : builder.isolines())
  {
    CHECK(iso.closed);
    CHECK(iso.role == H::Curve_role::level_set);
    CHECK(std::abs(iso.length() - 2. * SDI::pi) <= 0.01);
  }
  // crossings and spacing: the lines keep their spacing, none stops or merges, and none starts
  // but those that leave the lower rim
  INFO("lines: " << stats.gradient_lines << " traced, " << stats.started_lines << " started, " << stats.stopped_lines
                 << " stopped; levels " << levels.size());
  CHECK(stats.stopped_lines == 0);
  CHECK(stats.merged_lines == 0);
  // tracing: every line lands on the next isoline or the rim, none is lost
  CHECK(stats.lost_lines == 0);
  // assembly: only quads, one per line and band, a crossing at every inner corner
  const std::size_t lines_around = stats.gradient_lines / (levels.size() + 1);
  CHECK(lines_around * (levels.size() + 1) == stats.gradient_lines); // the same lines in every band
  CHECK(lines_around >= 24);
  CHECK(lines_around <= 26);
  CHECK(stats.started_lines == lines_around);
  CHECK(soup.faces.size() == lines_around * (levels.size() + 1));
  for(const auto& f : soup.faces)
    CHECK(f.size() == 4);
  std::size_t crossings = 0, boundary = 0;
  for(H::Net_point_kind k : soup.kind)
  {
    crossings += k == H::Net_point_kind::crossing;
    boundary += k == H::Net_point_kind::boundary;
  }
  CHECK(crossings == lines_around * levels.size());
  CHECK(boundary == 2 * lines_around);

  // on a closed sphere with one minimum and one maximum the lines end at the two extrema: two
  // poles, no boundary point, every other point a crossing
  Mesh sphere;
  SD::make_sphere(sphere, 8);
  SD::Harmonic_quad_remesher<Mesh> on_sphere(sphere);
  const SDI::Mesh_indices<Mesh> sphere_idx(sphere);
  const H::Trace_mesh sm = H::make_trace_mesh(sphere_idx, get(CGAL::vertex_point, sphere));
  H::Net_options sphere_options;
  sphere_options.edge_length = 0.3;
  const H::Polygon_soup sphere_soup = H::Quad_net_builder(sm, on_sphere.harmonic_function(), sphere_options).build();
  std::size_t poles = 0, others = 0;
  for(H::Net_point_kind k : sphere_soup.kind)
  {
    poles += k == H::Net_point_kind::pole;
    others += k != H::Net_point_kind::pole && k != H::Net_point_kind::crossing;
  }
  CHECK(poles == 2);
  CHECK(others == 0);
}

TEMPLATE_TEST_CASE("Curvature-adapted spacing refines where the surface bends, and only there",
                   "[harmonic_quad][remesh]", SD_MESH_TYPES)
{
  using Mesh = TestType;
  // a strip 4 x 1: flat for x < 2, then rolled on a cylinder of radius 1/2 (curvature 2) through
  // 4 radians; arc length is kept, so with its two ends as minimum and maximum u is x / 4 on both
  // halves and the uniform net is alike on both
  Soup_points points;
  const std::size_t nx = 161, ny = 41;
  for(std::size_t i = 0; i < nx; ++i)
    for(std::size_t j = 0; j < ny; ++j)
    {
      const double x = 4. * double(i) / double(nx - 1), y = double(j) / double(ny - 1);
      if(x <= 2.)
        points.push_back({x, y, 0.});
      else
        points.push_back({2. + 0.5 * std::sin(2. * (x - 2.)), y, 0.5 * (1. - std::cos(2. * (x - 2.)))});
    }
  const Mesh mesh = from_soup<Mesh>(points, grid_triangles(nx, ny));
  std::vector<std::pair<typename boost::graph_traits<Mesh>::vertex_descriptor, double>> ends;
  const double end_x = 2. + 0.5 * std::sin(4.), end_z = 0.5 * (1. - std::cos(4.));
  for(auto v : vertices(mesh))
  {
    const auto& p = get(CGAL::vertex_point, mesh, v);
    if(p.x() < 1e-12 && std::abs(p.z()) < 1e-12)
      ends.emplace_back(v, 0.);
    else if(std::abs(p.x() - end_x) < 1e-12 && std::abs(p.z() - end_z) < 1e-12)
      ends.emplace_back(v, 1.);
  }
  REQUIRE(ends.size() == 2 * ny);
  SD::Harmonic_quad_remesher<Mesh> remesher(mesh, P::harmonic_constraints(ends));
  // output vertices on the curved half (z > 0 or x > 2) against the flat half
  auto halves = [&](const Quad_mesh& q) {
    std::size_t curved = 0, flat = 0;
    for(auto v : vertices(q))
    {
      const auto& p = q.point(v);
      (p.z() > 1e-9 ? curved : flat) += 1;
    }
    return std::make_pair(double(curved), double(flat));
  };
  Quad_mesh uniform, adapted;
  remesher.remesh(uniform, P::target_edge_length(0.1));
  remesher.remesh(adapted, P::target_edge_length(0.1, P::curvature_adaptation(5.)));
  const auto [cu, fu] = halves(uniform);
  const auto [ca, fa] = halves(adapted);
  INFO("uniform: curved " << cu << ", flat " << fu << "; adapted: curved " << ca << ", flat " << fa);
  // uniform: the halves alike; adapted (scale 1 / (1 + 5 * 0.1 * 2) = 1/2 on the cylinder): about
  // four times the vertices on the curved half, the flat half as before
  CHECK(cu / fu >= 0.7);
  CHECK(cu / fu <= 1.4);
  CHECK(ca / fa >= 2.5);
  CHECK(std::abs(fa - fu) <= 0.25 * fu);
  for(const Quad_mesh* q : {&uniform, &adapted})
  {
    const SD::Quad_mesh_quality quality = SD::quad_mesh_quality(*q, mesh);
    CHECK(quality.valid);
    CHECK(quality.same_topology);
    CHECK(quality.faces_by_sides[1] == quality.faces);
  }
  // the finer half follows the cylinder more closely: the sagitta of its faces (how far the face
  // centroids lie inside the cylinder of radius 1/2) is smaller
  auto sagitta = [&](const Quad_mesh& q) {
    double worst = 0.;
    for(auto f : faces(q))
    {
      double cx = 0., cz = 0., n = 0.;
      bool curved = true;
      for(auto v : vertices_around_face(halfedge(f, q), q))
      {
        curved = curved && q.point(v).z() > 1e-9;
        cx += q.point(v).x();
        cz += q.point(v).z();
        n += 1.;
      }
      if(curved)
        worst = (std::max)(worst, 0.5 - std::hypot(cx / n - 2., cz / n - 0.5));
    }
    return worst;
  };
  INFO("sagitta uniform " << sagitta(uniform) << ", adapted " << sagitta(adapted));
  CHECK(sagitta(adapted) < 0.5 * sagitta(uniform));
  Quad_mesh untouched;
  CHECK_THROWS_AS(remesher.remesh(untouched, P::curvature_adaptation(-1.)), SD::Invalid_parameter);
  CHECK_THROWS_AS(remesher.remesh(untouched, P::curvature_adaptation(std::numeric_limits<double>::quiet_NaN())),
                  SD::Invalid_parameter);
  CHECK(num_faces(untouched) == 0);
}

TEST_CASE("Creases for snapping: a fold of 40 degrees is one, a fold of 20 degrees is not", "[harmonic_quad][remesh]")
{
  // a 5 x 5 grid of unit spacing folded along x = 2 by the angle (up or down): the fold's 4 edges
  // are the only candidates; at spacing 0.3 each gets ceil(1 / 0.3) - 1 = 3 points
  for(const double degrees : {20., 40., -40.})
  {
    INFO("fold " << degrees << " degrees");
    Soup_points points;
    const double slope = std::tan(degrees * SDI::pi / 180.);
    for(std::size_t i = 0; i < 5; ++i) // (point i * 5 + j, as grid_triangles numbers them)
      for(std::size_t j = 0; j < 5; ++j)
        points.push_back({double(i), double(j), i > 2 ? slope * (double(i) - 2.) : 0.});
    const test::Surface_mesh mesh = from_soup<test::Surface_mesh>(points, grid_triangles(5, 5));
    const SDI::Mesh_indices<test::Surface_mesh> idx(mesh);
    const H::Trace_mesh m = H::make_trace_mesh(idx, get(CGAL::vertex_point, mesh));
    const std::vector<Eigen::Vector3d> targets = H::snap_targets(m, 0.3);
    std::size_t interior = 0;
    for(std::size_t v = 0; v < m.number_of_vertices(); ++v)
      interior += !m.on_boundary[v];
    REQUIRE(interior == 9);
    const std::size_t crease_points = targets.size() - interior;
    CHECK(crease_points == (std::abs(degrees) > 30. ? 4 * 3 : 0));
    for(std::size_t k = interior; k < targets.size(); ++k)
    {
      CHECK(std::abs(targets[k].x() - 2.) < 1e-12); // on the fold
      CHECK(std::abs(targets[k].z()) < 1e-12);
    }
  }
}

TEST_CASE("The faces around a vertex between two of its edges, in the mesh's order and by angle",
          "[harmonic_quad][spectacles]")
{
  // a fan of six triangles around vertex 0, neighbours 1..6 counter-clockwise at 60 degree steps
  // in the plane, vertex 5 lifted out of it (its faces' angles at 0 grow past 60 degrees): from
  // the edge to 1, turning counter-clockwise, the sector ends at 3 (faces 0-1-2, 0-2-3, 120
  // degrees, the bisector on the edge to 2); turning clockwise it ends at 5 (faces 0-6-1, 0-5-6:
  // the bisector inside the second); a sector that meets neither stop goes once around
  Soup_points points{{0., 0., 0.}};
  for(int k = 0; k < 6; ++k)
    points.push_back({std::cos(k * SDI::pi / 3.), std::sin(k * SDI::pi / 3.), k == 4 ? 1.5 : 0.});
  Soup_triangles triangles;
  for(std::size_t k = 0; k < 6; ++k)
    triangles.push_back({0, 1 + k, 1 + (k + 1) % 6});
  const test::Surface_mesh mesh = from_soup<test::Surface_mesh>(points, triangles);
  const SDI::Mesh_indices<test::Surface_mesh> idx(mesh);
  const H::Trace_mesh m = H::make_trace_mesh(idx, get(CGAL::vertex_point, mesh));
  auto face_with = [&](std::size_t a, std::size_t b) { // the face 0-a-b, counter-clockwise
    for(std::size_t f = 0; f < m.number_of_faces(); ++f)
      for(std::size_t i = 0; i < 3; ++i)
        if(m.tri[f][i] == 0 && m.tri[f][(i + 1) % 3] == a && m.tri[f][(i + 2) % 3] == b)
          return f;
    return SDI::npos;
  };
  // the bisector's position (the angle swept before it) within the clamp of its fraction to
  // [0.05, 0.95] of its face's angle
  auto bisector_found = [](const H::Vertex_sector& sector) {
    double total = 0., before = 0.;
    for(std::size_t k = 0; k < sector.angle.size(); ++k)
    {
      total += sector.angle[k];
      before += k < sector.middle ? sector.angle[k] : 0.;
    }
    const double at = before + sector.fraction * sector.angle[sector.middle];
    return std::abs(at - 0.5 * total) <= 0.05 * sector.angle[sector.middle] + 1e-12;
  };
  const H::Vertex_sector ccw = H::vertex_sector(m, 0, 1, {3, 5}, true);
  CHECK(ccw.end == 3);
  REQUIRE(ccw.faces.size() == 2);
  CHECK(ccw.faces[0].first == face_with(1, 2));
  CHECK(ccw.faces[1].first == face_with(2, 3));
  for(const auto& [f, corner] : ccw.faces)
    CHECK(m.tri[f][corner] == 0);
  CHECK(std::abs(ccw.angle[0] + ccw.angle[1] - 2. * SDI::pi / 3.) < 1e-12);
  CHECK(bisector_found(ccw));
  const H::Vertex_sector cw = H::vertex_sector(m, 0, 1, {3, 5}, false);
  CHECK(cw.end == 5);
  CHECK(!cw.ccw);
  REQUIRE(cw.faces.size() == 2);
  CHECK(cw.faces[0].first == face_with(6, 1));
  CHECK(cw.faces[1].first == face_with(5, 6));
  for(const auto& [f, corner] : cw.faces)
    CHECK(m.tri[f][corner] == 0);
  const double lifted = std::acos(0.5 / std::sqrt(1. + 1.5 * 1.5)); // the angle of 0-5-6 at 0
  CHECK(std::abs(cw.angle[0] - SDI::pi / 3.) < 1e-12);
  CHECK(std::abs(cw.angle[1] - lifted) < 1e-12);
  CHECK(cw.middle == 1); // (60 degrees before it, less than half of 60 + 73.9)
  CHECK(std::abs(cw.fraction - (0.5 * (SDI::pi / 3. + lifted) - SDI::pi / 3.) / lifted) < 1e-12);
  CHECK(bisector_found(cw));
  const H::Vertex_sector none = H::vertex_sector(m, 0, 1, {SDI::npos, SDI::npos}, true);
  CHECK(none.end == SDI::npos);
  CHECK(none.faces.size() == 6);
}

TEST_CASE("Snapping targets: the interior vertices, and points along the creases at most the given spacing apart",
          "[harmonic_quad][remesh]")
{
  // a slab with one hole of one cell (cells 0.2 x 0.333, 0.25 thick): every edge of its box and
  // hole is a crease (90 degrees), the grid's diagonals and inner edges are flat
  test::Surface_mesh slab;
  SD::make_slab(slab, 3, 3, 0.25, [](std::size_t i, std::size_t j) { return i == 1 && j == 1; });
  const SDI::Mesh_indices<test::Surface_mesh> idx(slab);
  const H::Trace_mesh m = H::make_trace_mesh(idx, get(CGAL::vertex_point, slab));
  const double spacing = 0.04;
  const std::vector<Eigen::Vector3d> targets = H::snap_targets(m, spacing);
  REQUIRE(targets.size() > m.number_of_vertices());
  for(std::size_t v = 0; v < m.number_of_vertices(); ++v)
    CHECK(targets[v] == m.point[v]); // (closed: every vertex is interior)
  // every other target lies on a crease edge, and consecutive targets along it (with its ends)
  // are at most `spacing` apart; no target on a flat edge
  std::size_t crease_edges = 0, on_creases = 0;
  for(std::size_t f = 0; f < m.number_of_faces(); ++f)
    for(std::size_t i = 0; i < 3; ++i)
    {
      const std::size_t g = m.neighbour[f][i];
      if(g < f)
        continue;
      const Eigen::Vector3d a = m.point[m.tri[f][i]], b = m.point[m.tri[f][(i + 1) % 3]];
      std::vector<double> along{0., 1.};
      for(std::size_t k = m.number_of_vertices(); k < targets.size(); ++k)
      {
        const double t = (targets[k] - a).dot(b - a) / (b - a).squaredNorm();
        if(t > 1e-9 && t < 1. - 1e-9 && (a + t * (b - a) - targets[k]).norm() < 1e-12)
          along.push_back(t);
      }
      const bool crease = std::abs(m.normal[f].dot(m.normal[g])) < 0.5;
      crease_edges += crease;
      on_creases += along.size() - 2;
      if(!crease)
      {
        CHECK(along.size() == 2);
        continue;
      }
      std::sort(along.begin(), along.end());
      for(std::size_t k = 0; k + 1 < along.size(); ++k)
        CHECK((along[k + 1] - along[k]) * (b - a).norm() <= spacing + 1e-12);
      CHECK(along.size() == std::size_t(std::ceil((b - a).norm() / spacing)) + 1);
    }
  CHECK(crease_edges > 0);
  CHECK(on_creases == targets.size() - m.number_of_vertices());
}

TEMPLATE_TEST_CASE("A serrated boundary is followed and a narrow spike is reached (boundary detail, feature snapping)",
                   "[harmonic_quad][remesh]", SD_MESH_TYPES)
{
  using Mesh = TestType;
  // the unit square on a grid of spacing 0.02, its lower side serrated (every other vertex 0.06
  // lower: teeth 0.04 wide, narrower than h = 0.1) and the vertex at (0.54, 0.54) lifted by 0.15: a
  // spike 0.04 wide between the net's curves (u = x at levels 0.1 apart, lines along y about 0.1
  // apart), which they pass by
  Soup_points points;
  const std::size_t n = 51;
  const double h = 0.1;
  for(std::size_t i = 0; i < n; ++i)
    for(std::size_t j = 0; j < n; ++j)
    {
      const double x = double(i) / double(n - 1), y = double(j) / double(n - 1);
      points.push_back({x, j == 0 && i % 2 == 1 ? -0.06 : y, i == 27 && j == 27 ? 0.15 : 0.});
    }
  const Mesh mesh = from_soup<Mesh>(points, grid_triangles(n, n));
  // u = 0 on the left side, 1 on the right one (the default constraints would put a maximum, so a
  // vertex of the net, on the spike's tip)
  std::vector<std::pair<typename boost::graph_traits<Mesh>::vertex_descriptor, double>> sides;
  for(auto v : vertices(mesh))
  {
    const auto& p = get(CGAL::vertex_point, mesh, v);
    if(p.x() < 1e-12 || p.x() > 1. - 1e-12)
      sides.emplace_back(v, p.x() < 0.5 ? 0. : 1.);
  }
  REQUIRE(sides.size() == 2 * n);
  SD::Harmonic_quad_remesher<Mesh> remesher(mesh, P::harmonic_constraints(sides));
  Quad_mesh snapped, plain;
  const SD::Harmonic_quad_remeshing_result r = remesher.remesh(snapped, P::target_edge_length(h));
  const SD::Harmonic_quad_remeshing_result r0 =
    remesher.remesh(plain, P::target_edge_length(h, P::feature_snapping(false)));
  INFO("boundary detail vertices " << r.boundary_detail_vertices << ", far input vertices " << r.far_input_vertices
                                   << ", snapped " << r.snapped_vertices);
  CHECK(r.boundary_detail_vertices >= 25);
  CHECK(r0.boundary_detail_vertices == r.boundary_detail_vertices);
  CHECK(r.snapped_vertices >= 1);
  CHECK(r0.snapped_vertices == 0);
  CHECK(r.largest_input_distance > 0.12);
  for(const Quad_mesh* q : {&snapped, &plain})
  {
    const SD::Quad_mesh_quality quality = SD::quad_mesh_quality(*q, mesh);
    CHECK(quality.valid);
    CHECK(quality.same_topology);
    CHECK(quality.faces_by_sides[1] == quality.faces);
    // every boundary vertex of the input (teeth included) within h / 4 of the output's boundary
    double worst = 0.;
    for(const auto& p : points)
    {
      if(p[1] > 1e-12 && p[1] < 1. - 1e-12 && p[0] > 1e-12 && p[0] < 1. - 1e-12)
        continue; // not on the boundary
      const Eigen::Vector3d x(p[0], p[1], p[2]);
      double nearest = std::numeric_limits<double>::infinity();
      for(auto e : edges(*q))
        if(is_border(e, *q))
        {
          const auto& a = q->point(source(halfedge(e, *q), *q));
          const auto& b = q->point(target(halfedge(e, *q), *q));
          const Eigen::Vector3d pa(a.x(), a.y(), a.z()), d = Eigen::Vector3d(b.x(), b.y(), b.z()) - pa;
          const double t = std::clamp((x - pa).dot(d) / d.squaredNorm(), 0., 1.);
          nearest = (std::min)(nearest, (x - pa - t * d).norm());
        }
      worst = (std::max)(worst, nearest);
    }
    INFO("farthest input boundary vertex from the output's boundary: " << worst);
    CHECK(worst <= 0.25 * h + 1e-12);
  }
  // the spike's tip is a vertex of the snapped output; the Hausdorff distance, the spike's height
  // without snapping, drops to about half of it (the faces pulled up to the tip form a tent over
  // the plane, whose middle is about half the height above it)
  double tip = std::numeric_limits<double>::infinity();
  for(auto v : vertices(snapped))
    tip = (std::min)(tip, std::sqrt(CGAL::squared_distance(snapped.point(v), test::Point(0.54, 0.54, 0.15))));
  CHECK(tip <= 1e-12);
  const double with = SD::quad_mesh_quality(snapped, mesh).relative_hausdorff_distance;
  const double without = SD::quad_mesh_quality(plain, mesh).relative_hausdorff_distance;
  INFO("relative Hausdorff distance with snapping " << with << ", without " << without);
  CHECK(without >= 0.95 * 0.15 / std::sqrt(1. + 1.06 * 1.06 + 0.15 * 0.15)); // the tip is missed
  CHECK(with <= 0.55 * without);
}

TEMPLATE_TEST_CASE("Remeshing keeps the topology and makes mostly quads", "[harmonic_quad][remesh]", SD_MESH_TYPES)
{
  using Mesh = TestType;
  struct Case
  {
    const char* name;
    double max_hausdorff; // relative to the bounding-box diagonal
  };
  // measured here (quads only): eight 0.30%, kitten 0.67%, hemisphere 0.10%, fertility 0.86%,
  // blobby_3cc 0.35%, mech-holes-shark 0.70%;
  // under the sanitizers the lighter torus (genus 1 as well, 0.69%) replaces the kitten (22k faces)
  // (and the double torus, 6k faces, the fertility statue, 9k)
  const char* genus_one = CGAL_SURFACE_DESIGN_TESTS_UNDER_SANITIZERS ? "torus.off" : "kitten.off";
  const char* high_genus = CGAL_SURFACE_DESIGN_TESTS_UNDER_SANITIZERS ? "double-torus.off" : "fertility.off";
  // blobby_3cc: three components with boundaries; mech-holes-shark: a serrated boundary loop and
  // a conical pit narrower than h (2.1% without boundary detail and feature snapping)
  // (blobby_3cc first: the one case of the Polyhedron_3 types under the sanitizers, see every_case)
  std::vector<Case> cases{Case{"blobby_3cc.off", 0.015}, Case{"eight.off", 0.015}, Case{genus_one, 0.015},
                          Case{"hemisphere.off", 0.015}, Case{high_genus, 0.015}};
  if(!CGAL_SURFACE_DESIGN_TESTS_UNDER_SANITIZERS)
    cases.push_back(Case{"mech-holes-shark.off", 0.015});
  if(!every_case<Mesh>())
    cases.resize(1);
  for(const Case& c : cases)
  {
    INFO(c.name);
    const Mesh mesh = test::load_mesh<Mesh>(c.name);
    const test::Mesh_snapshot before(mesh);
    // the net as it is (quad-dominant), then quads only (the default)
    Quad_mesh net;
    const SD::Harmonic_quad_remeshing_result rn = SD::harmonic_quad_remeshing(mesh, net, P::all_quads(false));
    const SD::Quad_mesh_quality qn = SD::quad_mesh_quality(net, mesh);
    INFO("net: faces " << qn.faces << ", quads " << qn.quad_fraction << ", Hausdorff " << qn.relative_hausdorff_distance
                       << ", T-junctions " << qn.t_junctions << ", irregular " << qn.irregular_vertices);
    CHECK(qn.valid);
    CHECK(qn.same_topology);
    CHECK(qn.degenerate_edges == 0); // no two nodes at one point
    CHECK(CGAL::is_closed(net) == CGAL::is_closed(mesh));
    CHECK(qn.quad_fraction >= 0.85);
    CHECK(qn.faces >= 2000);
    CHECK(qn.faces <= 4500);
    CHECK(qn.relative_hausdorff_distance <= c.max_hausdorff);
    // regression guard: measured 4.24 degrees on fertility (the largest; eight 2.59, kitten 2.65,
    // hemisphere 1.32, blobby_3cc 3.39, mech-holes-shark 2.27, torus 2.21, double torus 2.07),
    // margin 1.76 degrees
    CHECK(qn.angle_deviation_mean <= 6.);
    CHECK(rn.faces == qn.faces);
    CHECK(rn.split_edges == 0);
    Quad_mesh out;
    const SD::Harmonic_quad_remeshing_result r = SD::harmonic_quad_remeshing(mesh, out);
    CHECK(test::Mesh_snapshot(mesh) == before);
    const SD::Quad_mesh_quality q = SD::quad_mesh_quality(out, mesh);
    INFO("quads only: faces " << q.faces << ", quads " << q.quad_fraction << ", Hausdorff "
                              << q.relative_hausdorff_distance << ", T-junctions " << q.t_junctions << ", irregular "
                              << q.irregular_vertices << ", corners " << q.angle_deviation_mean);
    CHECK(q.valid);
    CHECK(q.same_topology);
    CHECK(q.degenerate_edges == 0);
    CHECK(CGAL::is_closed(out) == CGAL::is_closed(mesh));
    CHECK(q.faces_by_sides[1] == q.faces); // every face a quad
    CHECK(r.odd_faces == rn.odd_faces); // the same net
    CHECK(rn.odd_faces >= qn.faces_by_sides[0] + qn.faces_by_sides[2]);
    CHECK(rn.odd_faces <= qn.faces_by_sides[0] + qn.faces_by_sides[2] + qn.faces_by_sides[4]);
    CHECK(r.odd_face_paths * 2 >= r.odd_faces); // a path pairs two of them, or one with the boundary
    CHECK(r.odd_face_paths <= r.odd_faces);
    CHECK(r.faces == q.faces);
    // regression guard: measured 1.304 on fertility (5201 / 3987, the largest; eight 1.295,
    // kitten 1.219, hemisphere 1.126, blobby_3cc 1.272, mech-holes-shark 1.202, torus 1.214,
    // double torus 1.192), margin 0.096 (about 380 faces on fertility)
    CHECK(q.faces <= qn.faces * 14 / 10);
    // the pentagons' flat corners were continued into lines: most T-junctions are gone, at
    // the price of some irregular vertices where paths turn (still far fewer than a
    // recombination of triangles makes: 0.4 per face for gmsh)
    CHECK(q.t_junctions * 4 <= qn.t_junctions);
    CHECK(double(q.irregular_vertices) <= 0.2 * double(q.faces));
    CHECK(q.relative_hausdorff_distance <= c.max_hausdorff);
    // regression guard: measured 7.70 degrees on fertility (the largest; eight 6.23, kitten 5.24,
    // hemisphere 3.40, blobby_3cc 7.48, mech-holes-shark 5.52, torus 5.11, double torus 4.62),
    // margin 1.30 degrees
    CHECK(q.angle_deviation_mean <= 9.);
  }
}

TEST_CASE("Spectacles become edge chains of a refined mesh of the same topology", "[harmonic_quad][spectacles]")
{
  using Mesh = CGAL::Surface_mesh<test::Point>;
  std::size_t planned = 0;
  for(const char* name : {"eight.off", "torus.off", "double-torus.off"})
  {
    INFO(name);
    const Mesh mesh = test::load_mesh<Mesh>(name);
    SD::Harmonic_quad_remesher<Mesh> remesher(mesh);
    const std::vector<double>& u = remesher.harmonic_function();
    const SDI::Mesh_indices<Mesh> idx(mesh);
    const H::Trace_mesh m = H::make_trace_mesh(idx, get(CGAL::vertex_point, mesh));
    double area = 0.;
    for(double a : m.area)
      area += a;
    H::Net_options options;
    options.edge_length = std::sqrt(area / 3000.);
    const std::vector<double> levels = H::Quad_net_builder(m, u, options).regular_levels();
    H::Spectacles_planner planner(m, u, levels, options.edge_length);
    const auto critical = H::critical_points(m, u).first;
    planner.plan(critical);
    std::size_t saddles = 0;
    for(const auto& c : critical)
      saddles += c.kind == H::Critical_kind::saddle;
    // every saddle has spectacles or a reason
    CHECK(planner.plans().size() + planner.skipped().size() == saddles);
    for(const auto& s : planner.skipped())
      CHECK(!s.reason.empty());
    H::Polyline_inserter inserter(m);
    for(const H::Spectacles_plan& p : planner.plans())
    {
      ++planned;
      // the bridge runs from one frame's junction through the saddle to the other's
      CHECK(p.bridge.front().point == p.frame[0][p.junction[0]].point);
      CHECK(p.bridge.back().point == p.frame[1][p.junction[1]].point);
      bool through_saddle = false;
      for(const auto& q : p.bridge)
        through_saddle = through_saddle || (q.kind == H::Surface_point::vertex && q.a == p.saddle);
      CHECK(through_saddle);
      // the frames lie on their level, the bridge between the saddle's value and it
      for(const auto& frame : p.frame)
        for(const auto& q : frame)
          if(q.kind == H::Surface_point::edge)
            CHECK(std::abs((1. - q.t) * u[q.a] + q.t * u[q.b] - p.value) <= 1e-12);
      inserter.add(p.frame[0], true);
      inserter.add(p.frame[1], true);
      inserter.add(p.bridge, false);
    }
    H::Refined_mesh r;
    std::string error;
    REQUIRE(inserter.build(r, error));
    // a closed manifold of the same Euler characteristic, the input's vertices kept in place
    Mesh refined;
    test::Soup_points points;
    for(const auto& p : r.points)
      points.push_back({p.x(), p.y(), p.z()});
    test::Soup_triangles triangles(r.triangles.begin(), r.triangles.end());
    refined = from_soup<Mesh>(points, triangles);
    CHECK(CGAL::is_valid_polygon_mesh(refined));
    CHECK(CGAL::is_closed(refined));
    CHECK(euler_characteristic(refined) == euler_characteristic(mesh));
    for(std::size_t v = 0; v < m.number_of_vertices(); ++v)
      CHECK(r.points[v] == m.point[v]);
    // every curve runs along edges of the refined mesh
    std::set<std::pair<std::size_t, std::size_t>> edge_set;
    for(const auto& t : r.triangles)
      for(int i = 0; i < 3; ++i)
        edge_set.insert({(std::min)(t[i], t[(i + 1) % 3]), (std::max)(t[i], t[(i + 1) % 3])});
    for(std::size_t k = 0; k < r.chains.size(); ++k)
    {
      const auto& chain = r.chains[k];
      const bool closed = k % 3 != 2;
      for(std::size_t j = 0; j + (closed ? 0 : 1) < chain.size(); ++j)
      {
        const std::size_t a = chain[j], b = chain[(j + 1) % chain.size()];
        CHECK(edge_set.count({(std::min)(a, b), (std::max)(a, b)}) == 1);
      }
    }
  }
  CHECK(planned >= 4);
}

TEMPLATE_TEST_CASE("Spectacles: every saddle accounted for, a valid output, fewer non-quads near saddles",
                   "[harmonic_quad][spectacles]", SD_MESH_TYPES)
{
  using Mesh = TestType;
  // regression guard (non-quads within 2h of the saddles, without / with spectacles, this build):
  // eight 7 / 6, kitten 8 / 7, torus 4 / 0, double torus 6 / 6; margin one face on eight and
  // kitten, none on the double torus (checked for "not more" only). The torus replaces the kitten
  // under the sanitizers.
  struct Case
  {
    const char* name;
    bool fewer; // strictly fewer non-quads near the saddles with spectacles (else not more)
  };
  const Case genus_one{CGAL_SURFACE_DESIGN_TESTS_UNDER_SANITIZERS ? "torus.off" : "kitten.off", true};
  std::vector<Case> cases{Case{"eight.off", true}, genus_one, Case{"double-torus.off", false}};
  if(!every_case<Mesh>())
    cases.resize(1);
  for(const Case c : cases)
  {
    INFO(c.name);
    const Mesh mesh = test::load_mesh<Mesh>(c.name);
    SD::Harmonic_quad_remesher<Mesh> remesher(mesh);
    std::vector<test::Point> saddles;
    for(const auto& [v, multiplicity] : remesher.critical_points().saddles)
      saddles.push_back(get(CGAL::vertex_point, mesh, SDI::Mesh_indices<Mesh>(mesh).vertex(v)));
    std::size_t near[2] = {0, 0};
    double hausdorff[2] = {0., 0.};
    for(const bool spectacles : {false, true})
    {
      INFO("spectacles " << spectacles);
      Quad_mesh out;
      // (on the net as it is: quads only would hide the cells the spectacles change)
      const SD::Harmonic_quad_remeshing_result r = remesher.remesh(out, P::spectacles(spectacles, P::all_quads(false)));
      CHECK(r.saddles == saddles.size());
      if(spectacles)
      {
        CHECK(r.spectacles >= 2);
        CHECK(r.spectacles + r.skipped_saddles.size() == r.saddles);
      }
      else
        CHECK((r.spectacles == 0 && r.skipped_saddles.empty()));
      for(const auto& [v, why] : r.skipped_saddles)
      {
        CHECK(v < num_vertices(mesh));
        CHECK(!why.empty());
      }
      const SD::Quad_mesh_quality q = SD::quad_mesh_quality(out, mesh);
      CHECK(q.valid);
      CHECK(q.same_topology);
      CHECK(q.quad_fraction >= 0.85);
      near[spectacles] = SD::count_non_quads_near(out, saddles, 2. * r.target_edge_length);
      hausdorff[spectacles] = q.relative_hausdorff_distance;
    }
    INFO("non-quads near the saddles without / with spectacles: " << near[0] << " / " << near[1]);
    if(c.fewer)
      CHECK(near[1] < near[0]); // (regression guard, see above)
    else
      CHECK(near[1] <= near[0]);
    // the big cell at each saddle was the worst place for the distance to the input
    CHECK(hausdorff[1] <= hausdorff[0]);
  }
}

TEST_CASE("Spectacles re-solve with either solver: the same saddles, nets of the same size",
          "[harmonic_quad][spectacles]")
{
#if defined(CGAL_SURFACE_DESIGN_HAS_CHOLMOD)
  using Mesh = CGAL::Surface_mesh<test::Point>;
  const Mesh eight = test::load_mesh<Mesh>("eight.off");
  SD::Harmonic_quad_remesher<Mesh, test::Vpm<Mesh>, SD::Default_solver_traits> ldlt(eight);
  SD::Harmonic_quad_remesher<Mesh, test::Vpm<Mesh>, SD::Cholmod_solver_traits> cholmod(eight);
  Quad_mesh a, b;
  const SD::Harmonic_quad_remeshing_result ra = ldlt.remesh(a, P::all_quads(false));
  const SD::Harmonic_quad_remeshing_result rb = cholmod.remesh(b, P::all_quads(false));
  INFO("faces " << ra.faces << " / " << rb.faces);
  // 4 = #min + #max - chi = 1 + 1 - (-2) simple saddles on the closed genus-2 eight (its default
  // constraints are one minimum and one maximum, no tip), and every one of them given spectacles:
  // that part is a regression guard (measured 4 of 4, none skipped, margin 0); a failed re-solve
  // would fall back to no spectacles
  const SD::Harmonic_critical_points cp = ldlt.critical_points();
  CHECK(cp.minima.size() == 1);
  CHECK(cp.maxima.size() == 1);
  CHECK(cp.saddles.size() == 4);
  CHECK(cp.saddle_multiplicity() == 4);
  CHECK(ra.saddles == 4);
  CHECK(ra.spectacles == 4);
  CHECK(rb.spectacles == ra.spectacles);
  CHECK(rb.skipped_saddles.size() == ra.skipped_saddles.size());
  CHECK(ra.spectacles_lines == rb.spectacles_lines);
  // the functions agree to rounding; a decision taken at a tie may differ, not the net's size
  CHECK(std::abs(double(ra.faces) - double(rb.faces)) <= 0.01 * double(ra.faces));
  CHECK(SD::quad_mesh_quality(b, eight).valid);
#else
  SD_CHOLMOD_UNAVAILABLE("the spectacles' re-solve with CHOLMOD");
#endif
}

TEMPLATE_TEST_CASE("Spectacles on a sheet with three holes: at an interior saddle, the topology and boundary kept",
                   "[harmonic_quad][spectacles]", SD_MESH_TYPES)
{
  using Mesh = TestType;
  // a square sheet with three square holes in a row, jittered and bent into a dome; u = 0 on the
  // holes' boundaries, 1 on the outer one. Just above 0 the isolines are loops around the holes;
  // they merge pairwise at saddles between neighbouring holes.
  // How many: a boundary loop held at one value adds 0 to the index sum (on a minimum loop the
  // vertices of smaller index form runs along it, index +1 where a run is empty and -1 where two
  // meet, as many of each; on the maximum loop every vertex has one lower path), so with no
  // interior extremum chi = 1 - 3 = -(sum of the interior saddles' multiplicities): two.
  // Which get spectacles: upwards, both wedges of a saddle lead to one isoline (every component
  // of {u > c} reaches the outer loop, the only maximum); downwards, the frames are the loops
  // around the holes on either side, so a saddle without spectacles is one whose curves would
  // cross those of the other (both want a loop around the middle hole; measured: one each).
  Mesh mesh;
  const auto is_hole = [](std::size_t i, std::size_t j) {
    return j >= 22 && j < 26 && ((i >= 8 && i < 12) || (i >= 22 && i < 26) || (i >= 36 && i < 41));
  };
  SD::make_grid(mesh, 48, 48, 0.1, is_hole);
  for(auto v : vertices(mesh))
  {
    const test::Point p = get(CGAL::vertex_point, mesh, v);
    put(CGAL::vertex_point, mesh, v,
        test::Point(p.x(), p.y(), 0.2 * std::sin(SDI::pi * p.x()) * std::sin(SDI::pi * p.y())));
  }
  std::vector<std::pair<typename boost::graph_traits<Mesh>::vertex_descriptor, double>> constraints;
  for(auto v : vertices(mesh))
    if(is_border(v, mesh))
    {
      const test::Point& p = get(CGAL::vertex_point, mesh, v);
      const bool outer = (std::min)({p.x(), p.y(), 1. - p.x(), 1. - p.y()}) < 1e-12;
      constraints.emplace_back(v, outer ? 1. : 0.);
    }
  const long chi = euler_characteristic(mesh);
  REQUIRE(chi == -2);
  SD::Harmonic_quad_remesher<Mesh> remesher(mesh, P::harmonic_constraints(constraints));
  const SD::Harmonic_critical_points cp = remesher.critical_points();
  const SDI::Mesh_indices<Mesh> idx(mesh);
  auto on_border = [&](std::size_t v) { return static_cast<bool>(is_border(idx.vertex(v), mesh)); };
  std::vector<test::Point> interior_saddles;
  int interior_multiplicity = 0;
  for(const auto& [v, multiplicity] : cp.saddles)
    if(!on_border(v))
    {
      interior_saddles.push_back(get(CGAL::vertex_point, mesh, idx.vertex(v)));
      interior_multiplicity += multiplicity;
    }
  INFO("saddles " << cp.saddles.size() << ", interior " << interior_saddles.size() << ", spurious extrema "
                  << cp.spurious_extrema);
  CHECK(cp.spurious_extrema == 0);
  CHECK(interior_multiplicity == -chi);
  CHECK(interior_saddles.size() == 2); // both simple

  std::vector<typename test::Kernel::Segment_3> input_border;
  for(auto e : edges(mesh))
    if(is_border(e, mesh))
      input_border.emplace_back(get(CGAL::vertex_point, mesh, source(halfedge(e, mesh), mesh)),
                                get(CGAL::vertex_point, mesh, target(halfedge(e, mesh), mesh)));
  for(const bool all_quads : {false, true})
  {
    INFO((all_quads ? "quads only" : "the net"));
    Quad_mesh out;
    const SD::Harmonic_quad_remeshing_result r = remesher.remesh(out, P::all_quads(all_quads));
    const SD::Quad_mesh_quality q = SD::quad_mesh_quality(out, mesh);
    INFO("spectacles " << r.spectacles << ", skipped " << r.skipped_saddles.size() << ", faces " << q.faces
                       << ", quads " << q.quad_fraction);
    // the report agrees with the function and with the output
    CHECK(r.saddles == cp.saddles.size());
    CHECK(r.spectacles >= 1);
    CHECK(r.spectacles_lines > 0);
    CHECK(r.spectacles + r.skipped_saddles.size() == r.saddles);
    std::size_t crossing = 0;
    for(const auto& [v, why] : r.skipped_saddles)
    {
      INFO("skipped " << v << ": " << why);
      if(on_border(v))
        CHECK(why.find("on the boundary") != std::string::npos);
      else
        crossing += why.find("would cross") != std::string::npos;
    }
    CHECK(r.spectacles + crossing == interior_saddles.size());
    CHECK(r.vertices == q.vertices);
    CHECK(r.faces == q.faces);
    // a valid mesh of the input's topology: chi = -2, four boundary loops, one component
    CHECK(q.valid);
    CHECK(q.same_topology);
    CHECK(q.euler_characteristic == chi);
    CHECK(q.boundary_loops == 4);
    CHECK(q.connected_components == 1);
    if(all_quads)
      CHECK(q.faces_by_sides[1] == q.faces);
    // the output's boundary follows the input's: the net's boundary vertices are points of the
    // input's boundary edges (snapping moves no boundary vertex); quads only adds the middles
    // of some of the net's boundary edges, chords whose stretch of the input's boundary stays
    // within h / 4 of them (else its vertices become vertices of the net), hence within h / 4 of
    // it (that stretch projects onto the whole chord)
    double farthest = 0.;
    for(auto v : vertices(out))
      if(is_border(v, out))
      {
        double nearest = std::numeric_limits<double>::infinity();
        for(const auto& segment : input_border)
          nearest = (std::min)(nearest, CGAL::squared_distance(out.point(v), segment));
        farthest = (std::max)(farthest, std::sqrt(nearest));
      }
    INFO("farthest output boundary vertex from the input's boundary: " << farthest << ", h " << r.target_edge_length);
    CHECK(farthest <= (all_quads ? 0.25 * r.target_edge_length : 1e-12));
  }
}

TEMPLATE_TEST_CASE("Awkward meshes keep their topology: 106 holes, 26 components, slivers",
                   "[harmonic_quad][remesh]", SD_MESH_TYPES)
{
  using Mesh = TestType;
  // elephant-with-holes: genus 3 with 106 boundary loops; bones: 26 components; triceratops:
  // angles down to 0.0002 degrees
  std::vector<std::string> names{"elephant-with-holes.off", "bones.off", "triceratops.off"};
  if(!every_case<Mesh>())
    names.resize(1);
  for(const std::string& name : names)
  {
    INFO(name);
    const Mesh mesh = test::load_mesh<Mesh>(name);
    Quad_mesh out;
    SD::harmonic_quad_remeshing(mesh, out);
    const SD::Quad_mesh_quality q = SD::quad_mesh_quality(out, mesh);
    INFO("faces " << q.faces << ", quads " << q.quad_fraction << ", loops " << q.boundary_loops);
    CHECK(q.valid);
    CHECK(q.same_topology);
    // no two vertices at one point: the elephant's net had 9 edges of length 0 where a line
    // that came up along a hole's boundary landed on an isoline's end, a crossing beside the
    // isoline's boundary node (now that crossing is the boundary node)
    CHECK(q.degenerate_edges == 0);
    CHECK(q.quad_fraction >= 0.8);
    CHECK(q.relative_hausdorff_distance <= 0.02);
  }
}

TEST_CASE("Remeshing into a Polyhedron_3 or into a mesh with faces appends the result and keeps the rest",
          "[harmonic_quad][remesh][output]")
{
  // the documentation of remesh() and harmonic_quad_remeshing(): the new vertices and faces are
  // added to `out` (nothing is cleared), and `out` is not modified when they throw
  for(const char* name : {"eight.off", "hemisphere.off"})
    for(const bool all_quads : {true, false})
    {
      INFO(name << (all_quads ? ", quads only" : ", the net"));
      const test::Surface_mesh mesh = test::load_mesh<test::Surface_mesh>(name);
      // the reference: into an empty Surface_mesh (the case every other test checks)
      SD::Harmonic_quad_remesher<test::Surface_mesh> remesher(mesh);
      Quad_mesh reference;
      const SD::Harmonic_quad_remeshing_result rr = remesher.remesh(reference, P::all_quads(all_quads));
      const SD::Quad_mesh_quality qr = SD::quad_mesh_quality(reference, mesh);
      REQUIRE(qr.valid);
      REQUIRE(qr.same_topology);
      if(all_quads)
        REQUIRE(qr.faces_by_sides[1] == qr.faces);
      check_appended_remesh<test::Surface_mesh>(mesh, remesher, all_quads, reference, rr, qr);
      check_appended_remesh<test::Polyhedron>(mesh, remesher, all_quads, reference, rr, qr);
    }
}

TEMPLATE_TEST_CASE("One factorization serves new values and every remesh", "[harmonic_quad][factor_once]",
                   SD_MESH_TYPES)
{
  using Mesh = TestType;
  const Mesh mesh = test::load_mesh<Mesh>("eight.off");
  test::Counting_solver_traits traits;
  SD::Harmonic_quad_remesher<Mesh, test::Vpm<Mesh>, test::Counting_solver_traits> remesher(
    mesh, CGAL::parameters::sparse_linear_solver(traits).vertex_point_map(get(CGAL::vertex_point, mesh)));
  Quad_mesh a, b;
  remesher.critical_points();
  const double h = remesher.remesh(a).target_edge_length;
  remesher.remesh(b, P::target_edge_length(0.7 * h));
  // (with spectacles, the refined mesh of every remesh is factored by a solver of its own)
  CHECK(traits.counts().factorizations == 1);
  CHECK(num_faces(b) > num_faces(a));
  // new values on the same vertices: a solve, no factorization
  std::vector<std::pair<typename boost::graph_traits<Mesh>::vertex_descriptor, double>> c;
  SDI::Mesh_indices<Mesh> idx(mesh);
  for(const auto& [v, value] : remesher.constraints())
    c.emplace_back(v, 2. * value - 1.);
  remesher.set_constraints(c);
  CHECK(remesher.constraints() == c); // in the representation they were given in
  const std::vector<double>& u = remesher.harmonic_function();
  CHECK(traits.counts().factorizations == 1);
  CHECK(traits.counts().solves == 2);
  for(const auto& [v, value] : remesher.constraints())
    CHECK(u[idx.index(v)] == value);
  // another vertex set: a new factorization
  c.pop_back();
  c.emplace_back(idx.vertex(0), 0.5);
  remesher.set_constraints(c);
  remesher.harmonic_function();
  CHECK(traits.counts().factorizations == 2);
}

TEMPLATE_TEST_CASE("Bad input to harmonic remeshing throws clear exceptions and changes nothing",
                   "[harmonic_quad][validation]", SD_MESH_TYPES)
{
  using Mesh = TestType;
  using V = typename boost::graph_traits<Mesh>::vertex_descriptor;
  auto expect_defect = [](auto&& call, SD::Mesh_defect defect) {
    try
    {
      call();
      FAIL("no exception");
    }
    catch(const SD::Invalid_mesh& e)
    {
      INFO(e.what());
      CHECK(e.defect() == defect);
    }
  };
  Quad_mesh out;
  {
    // two quads: not a triangle mesh
    Mesh quads;
    std::vector<test::Point> pts = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {0, 1, 0}, {1, 1, 0}, {2, 1, 0}};
    std::vector<V> v;
    for(const auto& p : pts)
      v.push_back(add_vertex(p, quads));
    CGAL::Euler::add_face(std::vector<V>{v[0], v[1], v[4], v[3]}, quads);
    CGAL::Euler::add_face(std::vector<V>{v[1], v[2], v[5], v[4]}, quads);
    expect_defect([&] { SD::harmonic_quad_remeshing(quads, out); }, SD::Mesh_defect::not_triangle);
  }
  {
    // two fans pinched at vertex 0
    Mesh pinched;
    std::vector<test::Point> pts = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {-1, 0, 0}, {-1, -1, 0}, {0, -1, 0}};
    std::vector<V> v;
    for(const auto& p : pts)
      v.push_back(add_vertex(p, pinched));
    for(const auto& f : std::vector<std::array<int, 3>>{{0, 1, 2}, {0, 2, 3}, {0, 4, 5}, {0, 5, 6}})
      CGAL::Euler::add_face(std::vector<V>{v[f[0]], v[f[1]], v[f[2]]}, pinched);
    expect_defect([&] { SD::harmonic_quad_remeshing(pinched, out); }, SD::Mesh_defect::non_manifold_vertex);
  }
  expect_defect([&] { SD::harmonic_quad_remeshing(test::load_mesh<Mesh>("degtri_four.off"), out); },
                SD::Mesh_defect::degenerate_face);
  expect_defect([&] { SD::harmonic_quad_remeshing(Mesh(), out); }, SD::Mesh_defect::empty);
  Mesh nan_mesh = test::load_mesh<Mesh>("eight.off");
  put(CGAL::vertex_point, nan_mesh, *vertices(nan_mesh).begin(),
      test::Point(std::numeric_limits<double>::quiet_NaN(), 0., 0.));
  expect_defect([&] { SD::harmonic_quad_remeshing(nan_mesh, out); }, SD::Mesh_defect::non_finite_coordinates);

  const Mesh eight = test::load_mesh<Mesh>("eight.off");
  const test::Mesh_snapshot before(eight);
  const std::vector<V> vs(vertices(eight).begin(), vertices(eight).end());
  auto expect_constraints = [&](const std::vector<std::pair<V, double>>& c, const char* words) {
    try
    {
      SD::harmonic_quad_remeshing(eight, out, P::harmonic_constraints(c));
      FAIL("no exception");
    }
    catch(const SD::Invalid_constraints& e)
    {
      INFO(e.what());
      CHECK(std::string(e.what()).find(words) != std::string::npos);
    }
  };
  expect_constraints({{vs[0], 1.}, {vs[5], 1.}}, "one value only");
  expect_constraints({}, "no constraint");
  expect_constraints({{vs[0], 0.}, {vs[5], std::numeric_limits<double>::infinity()}}, "inf");
  expect_constraints({{vs[0], 0.}, {vs[0], 1.}}, "twice");
  auto expect_parameter = [&](double h) {
    try
    {
      SD::harmonic_quad_remeshing(eight, out, P::target_edge_length(h));
      FAIL("no exception");
    }
    catch(const SD::Invalid_parameter& e)
    {
      INFO(e.what());
      CHECK(e.name() == "target_edge_length");
    }
  };
  expect_parameter(0.);
  expect_parameter(-1.);
  expect_parameter(std::numeric_limits<double>::quiet_NaN());
  expect_parameter(1e-6); // 1e12 faces
  CHECK(test::Mesh_snapshot(eight) == before);
  CHECK(num_vertices(out) == 0); // nothing was added to the output
  {
    // a vertex of another mesh
    Quad_mesh other;
    const Mesh other_mesh = test::load_mesh<Mesh>("torus.off");
    SD::Harmonic_quad_remesher<Mesh> remesher(eight);
    std::vector<std::pair<V, double>> foreign = {{*vertices(other_mesh).begin(), 0.}, {vs[3], 1.}};
    if constexpr(std::is_same<Mesh, test::Surface_mesh>::value)
    {
      // Surface_mesh indices of one mesh are valid indices of another: only out-of-range ones fail
      foreign[0].first = V(typename Mesh::size_type(num_vertices(eight) + 5));
    }
    CHECK_THROWS_AS(remesher.set_constraints(foreign), SD::Invalid_constraints);
    CHECK(remesher.constraints().size() >= 2); // the previous constraints stay
  }
}

namespace {

// the four generated surfaces of the topology tests
template <class Mesh>
Mesh generated_surface(const std::string& name)
{
  Mesh mesh;
  if(name == "genus 2, coarse")
    // a slab with two holes of one cell and square rims (300 triangles)
    SD::make_slab(mesh, 5, 3, 0.25, [](std::size_t i, std::size_t j) { return j == 1 && (i == 1 || i == 3); });
  else if(name == "genus 100")
    // 10 x 10 holes of 2 x 2 cells through a slab with rounded rims
    SD::make_slab(mesh, 42, 42, 1. / 42., [](std::size_t i, std::size_t j) { return (i / 2) % 2 == 1 && (j / 2) % 2 == 1; },
                  3);
  else if(name == "100 holes")
    SD::make_grid(mesh, 42, 42, 0.1, [](std::size_t i, std::size_t j) { return (i / 2) % 2 == 1 && (j / 2) % 2 == 1; });
  else // "obtuse torus": rings closer than the major steps, every other one turned by half a step
  {
    SD::make_torus(mesh, 30, 40, 1., 0.4);
    std::size_t k = 0;
    for(auto v : vertices(mesh))
    {
      const double a = SDI::two_pi / 30. * 0.5 * double((k++ % 40) % 2);
      const test::Point p = get(CGAL::vertex_point, mesh, v);
      put(CGAL::vertex_point, mesh, v,
          test::Point(std::cos(a) * p.x() - std::sin(a) * p.y(), std::sin(a) * p.x() + std::cos(a) * p.y(), p.z()));
    }
  }
  return mesh;
}

template <class Mesh>
double largest_angle_degrees(const Mesh& mesh)
{
  double largest = 0.;
  for(auto f : faces(mesh))
  {
    std::vector<test::Point> p;
    for(auto v : vertices_around_face(halfedge(f, mesh), mesh))
      p.push_back(get(CGAL::vertex_point, mesh, v));
    for(std::size_t k = 0; k < 3; ++k)
    {
      const auto a = p[(k + 1) % 3] - p[k], b = p[(k + 2) % 3] - p[k];
      largest = (std::max)(largest, std::acos(a * b / std::sqrt(a.squared_length() * b.squared_length())) * 180. / SDI::pi);
    }
  }
  return largest;
}

} // namespace

TEST_CASE("Snapping reaches the creases: the vertical edges of a coarse slab's holes", "[harmonic_quad][remesh]")
{
  // on the coarse genus-2 slab at h = sqrt(area / 5000), a cell spans a hole's vertical edge
  // (0.25 long, about 10 h) and cuts it off 0.8 h deep; the input has no vertex there to snap to
  const test::Surface_mesh mesh = generated_surface<test::Surface_mesh>("genus 2, coarse");
  const double h = std::sqrt(CGAL::Polygon_mesh_processing::area(mesh) / 5000.);
  SD::Harmonic_quad_remesher<test::Surface_mesh> remesher(mesh);
  Quad_mesh snapped, plain;
  const SD::Harmonic_quad_remeshing_result r = remesher.remesh(snapped, P::target_edge_length(h));
  remesher.remesh(plain, P::target_edge_length(h, P::feature_snapping(false)));
  const double with = SD::quad_mesh_quality(snapped, mesh).relative_hausdorff_distance;
  const double without = SD::quad_mesh_quality(plain, mesh).relative_hausdorff_distance;
  INFO("relative Hausdorff distance with snapping " << with << ", without " << without << "; far points "
                                                    << r.far_input_vertices << ", snapped " << r.snapped_vertices);
  CHECK(r.largest_input_distance > 0.5 * h);
  CHECK(r.snapped_vertices >= 1);
  CHECK(with <= 0.85 * without);
  CHECK(with <= 0.015);
}

TEMPLATE_TEST_CASE("Generated surfaces keep their topology: genus 2 coarse, genus 100, 100 holes, an obtuse torus",
                   "[harmonic_quad][remesh][topology]", SD_MESH_TYPES)
{
  using Mesh = TestType;
  struct Case
  {
    const char* name;
    long chi;
    std::size_t loops;
    double faces_per_area;     // the spacing: h = sqrt(area / this), 0 for the default
    std::size_t spectacles;    // at least this many placed, the net as asked used as it is
  };
  // The first two nets with spectacles once had another topology (genus 3 instead of 2: a line
  // from a junction into its sector started several spacings away on this coarse slab, so the
  // net's edge from the junction jumped over isolines; Euler characteristic -200 instead of -198:
  // where a frame turns sharply at its junction, a sector's line was traced into the other
  // sector). Now both are right with spectacles (regression guard: 2 of 4 and 55 of 200 placed,
  // this build; margins 0 and 5). The Hausdorff distance is checked here; the coarser case below
  // checks the topology only.
  std::vector<Case> cases{Case{"genus 2, coarse", -2, 0, 5000., 2}, Case{"genus 100", -198, 0, 0., 50},
                          Case{"100 holes", -99, 101, 0., 0}, Case{"obtuse torus", 0, 0, 0., 0}};
  if(!every_case<Mesh>())
    cases.resize(1);
  for(const Case c : cases)
  {
    INFO(c.name);
    const Mesh mesh = generated_surface<Mesh>(c.name);
    CHECK(long(num_vertices(mesh)) - long(num_edges(mesh)) + long(num_faces(mesh)) == c.chi);
    if(std::string(c.name) == "obtuse torus")
      CHECK(largest_angle_degrees(mesh) > 140.); // (every triangle has an angle of about 145 degrees)
    const test::Mesh_snapshot before(mesh);
    Quad_mesh out;
    SD::Harmonic_quad_remeshing_result r;
    if(c.faces_per_area > 0.)
      r = SD::harmonic_quad_remeshing(
        mesh, out, P::target_edge_length(std::sqrt(CGAL::Polygon_mesh_processing::area(mesh) / c.faces_per_area)));
    else
      r = SD::harmonic_quad_remeshing(mesh, out);
    CHECK(test::Mesh_snapshot(mesh) == before);
    const SD::Quad_mesh_quality q = SD::quad_mesh_quality(out, mesh);
    INFO("faces " << q.faces << ", quads " << q.quad_fraction << ", Hausdorff " << q.relative_hausdorff_distance
                  << ", chi " << q.euler_characteristic << ", loops " << q.boundary_loops << ", spectacles "
                  << r.spectacles << ", fall-backs " << r.fallbacks.size()
                  << (r.fallbacks.empty() ? "" : ": " + r.fallbacks.front()));
    CHECK(q.valid);
    CHECK(q.same_topology);
    CHECK(q.euler_characteristic == c.chi);
    CHECK(q.boundary_loops == c.loops);
    CHECK(q.connected_components == 1);
    CHECK(r.euler_characteristic == c.chi);
    CHECK(r.boundary_loops == c.loops);
    CHECK(r.components == 1);
    CHECK(q.quad_fraction == 1.); // (quads only, the default)
    CHECK(q.relative_hausdorff_distance <= 0.015);
    CHECK(r.fallbacks.empty());
    CHECK(r.spectacles >= c.spectacles);
  }
}

TEMPLATE_TEST_CASE("Saddles in one band: the coarse genus-2 slab at h = sqrt(area / 800)",
                   "[harmonic_quad][remesh][topology]", SD_MESH_TYPES)
{
  using Mesh = TestType;
  // two of its four saddles lie closer than one step of the net's levels, and the frames of the
  // one's spectacles ran through the other, holding it at their value: the net was invalid
  // (formerly a std::logic_error, then the fall-back without spectacles). Such spectacles are
  // skipped now, with the reason, and the saddle the frames would have crossed keeps none either
  // (its own would cross those); the net as asked is right. (At this spacing, a fifth of a
  // hole's width, the rims are cut off: the Hausdorff distance is not checked.)
  const Mesh mesh = generated_surface<Mesh>("genus 2, coarse");
  Quad_mesh out;
  const SD::Harmonic_quad_remeshing_result r = SD::harmonic_quad_remeshing(
    mesh, out, P::target_edge_length(std::sqrt(CGAL::Polygon_mesh_processing::area(mesh) / 800.)));
  const SD::Quad_mesh_quality q = SD::quad_mesh_quality(out, mesh);
  INFO((r.fallbacks.empty() ? std::string("no fall-back") : r.fallbacks.front()));
  CHECK(r.fallbacks.empty());
  CHECK(r.saddles == 4);
  CHECK(r.spectacles + r.skipped_saddles.size() == r.saddles);
  std::size_t through = 0;
  for(const auto& [v, why] : r.skipped_saddles)
    through += why.find("its curves pass through another critical point (vertex ") == 0;
  CHECK(through == 1);
  CHECK(q.valid);
  CHECK(q.same_topology);
  CHECK(q.euler_characteristic == -2);
  CHECK(q.quad_fraction >= 0.85);
}

TEST_CASE("Every saddle is separated from the next in its band: the straight-walled genus-100 slab at coarse spacing",
          "[harmonic_quad][remesh][topology]")
{
  // 10 x 10 holes of 2 x 2 cells, square rims, no spectacles. Once, at h = sqrt(area / 250) (about
  // two holes' widths) the net lost 6 handles: the two saddles of those holes lay in one band with
  // no isoline between them across the hole's wall, so the cell around the wall held the handle.
  // Saddles of equal value (mirror images across the slab's diagonal) were skipped as a pair, and
  // an isoline between other saddles anywhere counted as separating them. On this symmetric slab
  // the net as asked can still come out with one handle too many at one of the spacings (cause not
  // found), and which one depends on the rounding of the harmonic function: at sqrt(area / 200)
  // with Eigen's SimplicialLDLT, at sqrt(area / 500) with the supernodal factorization ordered by
  // AMD (the default below 20k unknowns), at none of them ordered by nested dissection. The
  // fall-backs (intrinsic Delaunay, then h / sqrt 2) then give the right net.
  test::Surface_mesh mesh;
  SD::make_slab(mesh, 42, 42, 1. / 42., [](std::size_t i, std::size_t j) { return (i / 2) % 2 == 1 && (j / 2) % 2 == 1; });
  const double area = CGAL::Polygon_mesh_processing::area(mesh);
  auto check = [&](auto traits, const char* solver) {
    std::size_t as_asked = 0;
    for(const double faces : {200., 250., 500.})
    {
      INFO(solver << ", h = sqrt(area / " << faces << ")");
      Quad_mesh out;
      const SD::Harmonic_quad_remeshing_result r = SD::harmonic_quad_remeshing(
        mesh, out, P::spectacles(false, P::target_edge_length(std::sqrt(area / faces)).sparse_linear_solver(traits)));
      INFO((r.fallbacks.empty() ? std::string("no fall-back") : r.fallbacks.front()));
      if(r.fallbacks.empty())
      {
        ++as_asked;
        CHECK(r.saddle_levels >= 100); // (one between the two saddles of every hole, at least)
      }
      else
      {
        REQUIRE(r.fallbacks.size() == 3);
        CHECK(r.fallbacks[0].rfind("as asked: the net has Euler characteristic -200", 0) == 0);
        CHECK(r.fallbacks[1].rfind("the intrinsic Delaunay Laplacian: the net has Euler characteristic", 0) == 0);
        CHECK(r.fallbacks[2] == "used: spacing h / sqrt 2");
      }
      const SD::Quad_mesh_quality q = SD::quad_mesh_quality(out, mesh);
      CHECK(q.valid);
      CHECK(q.same_topology);
      CHECK(q.euler_characteristic == -198);
    }
    CHECK(as_asked >= 2);
  };
  check(SD::Default_solver_traits(), "default solver");
  check(SD::Simplicial_ldlt_solver_traits(), "SimplicialLDLT");
}

TEST_CASE("Nets with spectacles keep the topology: the triceratops at 5000 faces, fertility at 12,000",
          "[harmonic_quad][remesh][topology][spectacles]")
{
  struct Case
  {
    const char* file;
    double faces_per_area; // h = sqrt(area / this)
    long chi;
    std::size_t saddles, spectacles; // at least this many spectacles
  };
  // - the sphere-like triceratops (slivers down to 0.0002 degrees): its net with spectacles had
  //   Euler characteristic 0 (and was written as the result before the topology check). On an
  //   isoline just below a bridge, two lines from below joined the lines coming down from the
  //   bridge, each the one nearer to the other's: they crossed. A line now joins a neighbour
  //   along the isoline only. Both saddles given spectacles keep them.
  // - fertility: next to a junction the faces around it hold both the frame and the bridge at one
  //   value; a line reaching the bridge there was taken to the frame (registered first), at a
  //   point on the bridge: the frame's node was out of place and the net had Euler characteristic
  //   -12. The line now lands on the nearer curve. Regression guard: 8 of its 10 saddles get
  //   spectacles (this build, margin 1).
  for(const Case c : {Case{"triceratops.off", 5000., 2, 6, 2}, Case{"fertility.off", 12000., -6, 10, 7}})
  {
    INFO(c.file);
    const test::Surface_mesh mesh = test::load_mesh<test::Surface_mesh>(c.file);
    Quad_mesh out;
    const SD::Harmonic_quad_remeshing_result r = SD::harmonic_quad_remeshing(
      mesh, out, P::target_edge_length(std::sqrt(CGAL::Polygon_mesh_processing::area(mesh) / c.faces_per_area)));
    const SD::Quad_mesh_quality q = SD::quad_mesh_quality(out, mesh);
    INFO((r.fallbacks.empty() ? std::string("no fall-back") : r.fallbacks.front()));
    CHECK(r.fallbacks.empty());
    CHECK(r.saddles == c.saddles);
    CHECK(r.spectacles >= c.spectacles);
    CHECK(r.spectacles + r.skipped_saddles.size() == r.saddles); // every other saddle said why it has none
    CHECK(q.valid);
    CHECK(q.same_topology);
    CHECK(q.euler_characteristic == c.chi);
    CHECK(q.quad_fraction == 1.); // (quads only, the default)
  }
}

TEMPLATE_TEST_CASE("A tube thinner than the spacing: a clear failure after every fall-back, the output untouched",
                   "[harmonic_quad][remesh][topology]", SD_MESH_TYPES)
{
  using Mesh = TestType;
  // circumference of the tube 0.126, spacing 0.3 (and 0.15 at the finest fall-back): every
  // isoline is shorter than the spacing, the net is empty (before: an empty mesh, exit 0)
  Mesh torus;
  SD::make_torus(torus, 80, 8, 1., 0.02);
  Quad_mesh out;
  SD::make_sphere(out, 1);
  const test::Mesh_snapshot before(out);
  try
  {
    SD::harmonic_quad_remeshing(torus, out, P::target_edge_length(0.3));
    FAIL("no exception");
  }
  catch(const SD::Remeshing_failure& e)
  {
    const std::string what = e.what();
    INFO(what);
    CHECK(what.find("Euler characteristic 0, 0 boundary loops, 1 component") != std::string::npos);
    for(const char* attempt : {"as asked:", "the intrinsic Delaunay Laplacian:", "spacing h / 2 within 2 h of the saddles:",
                               "spacing h / sqrt 2:", "spacing h / 2:"})
      CHECK(what.find(attempt) != std::string::npos);
    CHECK(what.find("the net is empty") != std::string::npos);
  }
  CHECK(test::Mesh_snapshot(out) == before);
  // the same tube at a spacing below its circumference: a valid torus
  Quad_mesh fine;
  SD::harmonic_quad_remeshing(torus, fine, P::target_edge_length(0.05));
  const SD::Quad_mesh_quality q = SD::quad_mesh_quality(fine, torus);
  CHECK(q.valid);
  CHECK(q.same_topology);
}

TEST_CASE("Topology of a soup, and a slit cell cut by a chord", "[harmonic_quad][topology]")
{
  H::Polygon_soup soup;
  // an annulus: outer square 0..3 (side 4), inner square 4..7 (side 2), both counter-clockwise
  for(const auto& p : std::vector<std::array<double, 2>>{{-2, -2}, {2, -2}, {2, 2}, {-2, 2}, {-1, -1}, {1, -1}, {1, 1}, {-1, 1}})
    soup.points.emplace_back(p[0], p[1], 0.);
  soup.kind.assign(8, H::Net_point_kind::crossing);
  const std::vector<std::vector<std::size_t>> annulus{{0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
  H::Soup_topology t = H::soup_topology(annulus, 8);
  CHECK(t.euler_characteristic == 0);
  CHECK(t.boundary_loops == 2);
  CHECK(t.components == 1);
  // negative control: the annulus's two boundaries taken as two disks (what a net without a
  // line across a band makes of a cell) have Euler characteristic 2, not 0
  t = H::soup_topology(std::vector<std::vector<std::size_t>>{{0, 1, 2, 3}, {7, 6, 5, 4}}, 8);
  CHECK(t.euler_characteristic == 2);
  CHECK(t.boundary_loops == 2);
  CHECK(t.components == 2);
  // two separate squares, and an unused point
  t = H::soup_topology(std::vector<std::vector<std::size_t>>{{0, 1, 2, 3}, {4, 5, 6, 7}}, 9);
  CHECK(t == H::Soup_topology{2, 2, 2});
  // the annulus as one cell whose walk runs along the single line 0-4 on both sides (a slit):
  // not a polygon; one chord between the two loops makes two simple faces of the annulus
  soup.faces = {{0, 4, 7, 6, 5, 4, 0, 1, 2, 3}};
  CHECK_FALSE(CGAL::Polygon_mesh_processing::is_polygon_soup_a_polygon_mesh(soup.faces));
  CHECK(H::split_pinched_cells(soup) == 1);
  REQUIRE(soup.faces.size() == 2);
  for(const auto& f : soup.faces)
  {
    std::set<std::size_t> distinct(f.begin(), f.end());
    CHECK(distinct.size() == f.size());
  }
  CHECK(CGAL::Polygon_mesh_processing::is_polygon_soup_a_polygon_mesh(soup.faces));
  t = H::soup_topology(soup.faces, 8);
  CHECK(t.euler_characteristic == 0);
  CHECK(t.boundary_loops == 2);
  // the chord joins the closest pair visited once: a corner of the inner square and the outer
  // corner next to it (distance sqrt 2)
  std::size_t sides = 0;
  for(const auto& f : soup.faces)
    sides += f.size();
  CHECK(sides == 10 + 2); // the walk's 10 sides, the chord on both faces
  // a simple face is left alone
  H::Polygon_soup simple = soup;
  CHECK(H::split_pinched_cells(simple) == 0);
  CHECK(simple.faces == soup.faces);
}
