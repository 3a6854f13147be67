// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Controls for the oracles of the other tests. Most tests assert that a metric is zero (no
// flipped face, no T-junction, every piece a disk, ...): a metric that always returns zero
// would pass them all. Here every metric or predicate the tests rely on meets a small input built
// by hand on which it must report a known non-zero value, derived in the comments (counts
// exactly, analytic reals to 1e-12). Zeroing any one of them in the library fails a test below.
// - flattening_distortion(): flips, area and conformal distortion, stretch, area ratio, boundary
//   length error, self-overlapping pieces (and polygon_self_intersects(),
//   compute_overlap_splitting_cut());
// - quad_mesh_quality(): faces by sides, irregular vertices, T-junctions, corner angles, edge
//   lengths, topology, validity, Hausdorff distance (and the certified distance itself,
//   internal::bounded_hausdorff_distance()); count_non_quads_near();
// - developability_metrics(): lambda, hinge shares, angle defects, seams, minimum angle,
//   distances to a reference;
// - singularity indices: direction_field_singularities(), stripe_singularities(),
//   one_form_singularities(), critical points of a piecewise-linear function;
// - topology: components, boundary loops, genus, homology generators; disk-ness of cut pieces
//   (cut_topology(), cut_mesh_along_edges(), require_disks());
// - the fabrication pattern: layout boxes, cut paths and seam labels of the SVG;
// - test::Mesh_snapshot (the "mesh left untouched" oracle).

#include <test_support.h>

#include <CGAL/Surface_design/developability.h>
#include <CGAL/Surface_design/developable_cutting.h>
#include <CGAL/Surface_design/direction_fields.h>
#include <CGAL/Surface_design/fabrication_pattern.h>
#include <CGAL/Surface_design/field_aligned_parameterization.h>
#include <CGAL/Surface_design/flattening_distortion.h>
#include <CGAL/Surface_design/internal/Core/cut_mesh.h>
#include <CGAL/Surface_design/internal/Core/hausdorff_distance.h>
#include <CGAL/Surface_design/internal/Core/topology.h>
#include <CGAL/Surface_design/internal/Developability/bff.h>
#include <CGAL/Surface_design/internal/Harmonic_quad_remeshing/harmonic_function.h>
#include <CGAL/Surface_design/internal/Harmonic_quad_remeshing/trace_mesh.h>
#include <CGAL/Surface_design/mesh_generators.h>
#include <CGAL/Surface_design/overlap_splitting_cut.h>
#include <CGAL/Surface_design/quad_mesh_quality.h>

#include <CGAL/Polygon_mesh_processing/distance.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>

#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace SD = CGAL::Surface_design;
namespace SDI = CGAL::Surface_design::internal;
namespace P = CGAL::Surface_design::parameters;

namespace {

using test::from_soup;
using test::Soup_points;
using test::Soup_triangles;
using Point_2 = test::Kernel::Point_2;
using Vector_3 = test::Kernel::Vector_3;

template <class Mesh>
using Vertex = typename boost::graph_traits<Mesh>::vertex_descriptor;
template <class Mesh>
using Face = typename boost::graph_traits<Mesh>::face_descriptor;
template <class Mesh>
using Edge = typename boost::graph_traits<Mesh>::edge_descriptor;

constexpr double pi = 3.14159265358979323846;
constexpr double tight = 1e-12;

/// A polygon mesh of any type from points and polygons of any size (checked valid).
template <class Mesh>
Mesh polygon_mesh(const Soup_points& points, const std::vector<std::vector<std::size_t>>& polygons)
{
  std::vector<test::Point> p;
  for(const auto& q : points)
    p.emplace_back(q[0], q[1], q[2]);
  Mesh mesh;
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(p, polygons, mesh);
  REQUIRE(CGAL::is_valid_polygon_mesh(mesh));
  REQUIRE(num_faces(mesh) == polygons.size());
  return mesh;
}

/// A value per vertex, as a function of the vertex's position (the hand-built inputs have
/// distinct positions, so this names the vertices without depending on the mesh's numbering).
template <class T, class Mesh, class Function>
std::map<Vertex<Mesh>, T> per_vertex(const Mesh& mesh, Function f)
{
  std::map<Vertex<Mesh>, T> values;
  for(auto v : vertices(mesh))
    values.emplace(v, f(get(CGAL::vertex_point, mesh, v)));
  return values;
}

template <class Mesh>
Vertex<Mesh> vertex_at(const Mesh& mesh, double x, double y, double z = 0.)
{
  for(auto v : vertices(mesh))
    if(get(CGAL::vertex_point, mesh, v) == test::Point(x, y, z))
      return v;
  FAIL("no vertex at (" << x << ", " << y << ", " << z << ")");
  return *vertices(mesh).begin();
}

template <class Mesh>
Edge<Mesh> edge_between(const Mesh& mesh, Vertex<Mesh> a, Vertex<Mesh> b)
{
  const auto h = CGAL::halfedge(a, b, mesh);
  REQUIRE(h.second);
  return edge(h.first, mesh);
}

// The unit square [0, 1]^2 in the plane z = `z`, two triangles (0, 1, 2), (0, 2, 3), shifted by `dx`.
void square_soup(Soup_points& points, Soup_triangles& triangles, double dx = 0., double z = 0.)
{
  const std::size_t o = points.size();
  for(const auto& [x, y] : std::vector<std::pair<double, double>>{{0., 0.}, {1., 0.}, {1., 1.}, {0., 1.}})
    points.push_back({x + dx, y, z});
  triangles.push_back({o, o + 1, o + 2});
  triangles.push_back({o, o + 2, o + 3});
}

// A triangle around the origin, corners A, B, C at angles 90, 210, 330 degrees (radius 1), and
// a flap on each of its edges (apex at radius 2 opposite the edge). Around the inner triangle a
// direction of angle theta (the polar angle) turns once; around every flap it does not turn.
template <class Mesh>
Mesh triangle_with_flaps()
{
  Soup_points points;
  for(double degrees : {90., 210., 330.})
    points.push_back({std::cos(degrees * pi / 180.), std::sin(degrees * pi / 180.), 0.});
  for(double degrees : {150., 270., 30.}) // apexes of the flaps on AB, BC, CA
    points.push_back({2. * std::cos(degrees * pi / 180.), 2. * std::sin(degrees * pi / 180.), 0.});
  const Soup_triangles triangles = {{0, 1, 2}, {1, 0, 3}, {2, 1, 4}, {0, 2, 5}};
  return from_soup<Mesh>(points, triangles);
}

double polar_angle(const test::Point& p) { return std::atan2(p.y(), p.x()); }

// The face of triangle_with_flaps() that contains the origin.
template <class Mesh>
bool is_inner_face(const Mesh& mesh, Face<Mesh> f)
{
  for(auto v : vertices_around_face(halfedge(f, mesh), mesh))
  {
    const auto& p = get(CGAL::vertex_point, mesh, v);
    if(p.x() * p.x() + p.y() * p.y() > 2.)
      return false;
  }
  return true;
}

// Number of elements `<tag` inside `<g id="group" ...> ... </g>` of an SVG text.
std::size_t count_in_group(const std::string& svg, const std::string& group, const std::string& tag)
{
  const std::size_t begin = svg.find("<g id=\"" + group + "\"");
  if(begin == std::string::npos)
    return 0;
  const std::size_t end = svg.find("</g>", begin);
  std::size_t n = 0;
  for(std::size_t at = svg.find("<" + tag, begin); at < end; at = svg.find("<" + tag, at + 1))
    ++n;
  return n;
}

} // namespace

// ---------------------------------------------------------------------------------------------
// flattening_distortion()

TEMPLATE_TEST_CASE("Control: one reflected triangle is one flipped face", "[oracle][flattening]", SD_MESH_TYPES)
{
  using Mesh = TestType;
  Soup_points points = {{0., 0., 0.}, {1., 0., 0.}, {0., 1., 0.}};
  const Mesh triangle = from_soup<Mesh>(points, {{0, 1, 2}});
  SECTION("a mirror image: an isometry of the wrong orientation")
  {
    auto uv = per_vertex<Point_2>(triangle, [](const test::Point& p) { return Point_2(p.x(), -p.y()); });
    const SD::Flattening_distortion d = SD::flattening_distortion(triangle, boost::make_assoc_property_map(uv));
    CHECK(d.faces == 1);
    CHECK(d.pieces == 1);
    CHECK(d.flipped_faces == 1);
    CHECK(d.area_ratio == Approx(-1.).margin(tight)); // signed area ratio
    CHECK(d.area_log_max == Approx(0.).margin(tight)); // singular values 1, 1
    CHECK(d.conformal_log_max == Approx(0.).margin(tight));
    CHECK(d.boundary_length_error == Approx(0.).margin(tight));
    CHECK(d.self_overlapping_pieces == 0);
  }
  SECTION("collapsed to a segment: zero area counts as flipped")
  {
    auto uv = per_vertex<Point_2>(triangle, [](const test::Point& p) { return Point_2(p.x() + p.y(), 0.); });
    const SD::Flattening_distortion d = SD::flattening_distortion(triangle, boost::make_assoc_property_map(uv));
    CHECK(d.flipped_faces == 1);
    CHECK(d.area_log_max == std::numeric_limits<double>::infinity());
  }
  SECTION("a square folded along its diagonal: one face of two flips, the signed areas cancel")
  {
    Soup_points square;
    Soup_triangles triangles;
    square_soup(square, triangles);
    const Mesh mesh = from_soup<Mesh>(square, triangles);
    // (0, 1) goes to its mirror image (1, 0) across the diagonal: each face keeps its shape
    auto uv = per_vertex<Point_2>(mesh, [](const test::Point& p) {
      return p.x() == 0. && p.y() == 1. ? Point_2(1., 0.) : Point_2(p.x(), p.y());
    });
    const SD::Flattening_distortion d = SD::flattening_distortion(mesh, boost::make_assoc_property_map(uv));
    CHECK(d.faces == 2);
    CHECK(d.flipped_faces == 1);
    CHECK(d.area_ratio == Approx(0.).margin(tight));
    CHECK(d.area_log_max == Approx(0.).margin(tight));
    CHECK(d.boundary_length_error == Approx(0.).margin(tight)); // every edge keeps its length
  }
}

TEMPLATE_TEST_CASE("Control: stretched flattenings have the analytic area, angle and boundary-length distortion",
                   "[oracle][flattening]", SD_MESH_TYPES)
{
  using Mesh = TestType;
  SECTION("a triangle scaled by s = 3: area log(s^2), stretch s, boundary error s - 1")
  {
    const Mesh triangle = from_soup<Mesh>({{0., 0., 0.}, {1., 0., 0.}, {0., 1., 0.}}, {{0, 1, 2}});
    auto uv = per_vertex<Point_2>(triangle, [](const test::Point& p) { return Point_2(3. * p.x(), 3. * p.y()); });
    std::map<Face<Mesh>, double> log_area;
    const SD::Flattening_distortion d = SD::flattening_distortion(
      triangle, boost::make_assoc_property_map(uv), P::face_log_area_scale_map(boost::make_assoc_property_map(log_area)));
    CHECK(d.flipped_faces == 0);
    CHECK(d.area_log_mean == Approx(std::log(9.)).epsilon(tight));
    CHECK(d.area_log_max == Approx(std::log(9.)).epsilon(tight));
    CHECK(d.conformal_log_max == Approx(0.).margin(tight)); // a similarity
    CHECK(d.stretch_max == Approx(3.).epsilon(tight));
    CHECK(d.area_ratio == Approx(9.).epsilon(tight));
    CHECK(d.boundary_length_error == Approx(2.).epsilon(tight));     // sum |3 l - l| / sum l
    CHECK(d.boundary_length_error_max == Approx(2.).epsilon(tight)); // |3 l / l - 1|
    REQUIRE(log_area.size() == 1);
    CHECK(log_area.begin()->second == Approx(std::log(9.)).epsilon(tight));
  }
  SECTION("a triangle stretched by 2 and squeezed by 1/2: pure angle distortion log 4")
  {
    const Mesh triangle = from_soup<Mesh>({{0., 0., 0.}, {1., 0., 0.}, {0., 1., 0.}}, {{0, 1, 2}});
    auto uv = per_vertex<Point_2>(triangle, [](const test::Point& p) { return Point_2(2. * p.x(), 0.5 * p.y()); });
    const SD::Flattening_distortion d = SD::flattening_distortion(triangle, boost::make_assoc_property_map(uv));
    CHECK(d.area_log_max == Approx(0.).margin(tight)); // s1 s2 = 1
    CHECK(d.conformal_log_mean == Approx(std::log(4.)).epsilon(tight));
    CHECK(d.conformal_log_max == Approx(std::log(4.)).epsilon(tight));
    CHECK(d.stretch_max == Approx(2.).epsilon(tight)); // max(s1, 1 / s2)
    CHECK(d.area_ratio == Approx(1.).epsilon(tight));
  }
  SECTION("a unit square with one corner pulled from (0, 1) to (0, 2)")
  {
    Soup_points square;
    Soup_triangles triangles;
    square_soup(square, triangles);
    const Mesh mesh = from_soup<Mesh>(square, triangles);
    // (x, y) -> (x, y (2 - x)): face (0, 1, 2) is fixed; face (0, 2, 3) goes to (0,0), (1,1), (0,2),
    // the linear map J = [1 0; -1 2]: J^T J has eigenvalues 3 +- sqrt 5, so s1 s2 = 2 and
    // s1 / s2 = (3 + sqrt 5) / 2 = phi^2 (phi the golden ratio). Each face has area 1/2.
    auto uv = per_vertex<Point_2>(mesh, [](const test::Point& p) { return Point_2(p.x(), p.y() * (2. - p.x())); });
    std::map<Face<Mesh>, double> log_area;
    const SD::Flattening_distortion d = SD::flattening_distortion(
      mesh, boost::make_assoc_property_map(uv), P::face_log_area_scale_map(boost::make_assoc_property_map(log_area)));
    const double sqrt5 = std::sqrt(5.);
    CHECK(d.flipped_faces == 0);
    CHECK(d.area_log_max == Approx(std::log(2.)).epsilon(tight));
    CHECK(d.area_log_mean == Approx(0.5 * std::log(2.)).epsilon(tight));
    CHECK(d.conformal_log_max == Approx(std::log((3. + sqrt5) / 2.)).epsilon(tight));
    CHECK(d.conformal_log_mean == Approx(0.5 * std::log((3. + sqrt5) / 2.)).epsilon(tight));
    CHECK(d.stretch_max == Approx(std::sqrt(3. + sqrt5)).epsilon(tight));
    CHECK(d.area_ratio == Approx(1.5).epsilon(tight));
    // boundary: edges 0-1 and 1-2 keep length 1, 2-3 becomes sqrt 2, 3-0 becomes 2
    CHECK(d.boundary_length_error == Approx((std::sqrt(2.) - 1. + 1.) / 4.).epsilon(tight));
    CHECK(d.boundary_length_error_max == Approx(1.).epsilon(tight));
    std::vector<double> logs;
    for(const auto& entry : log_area)
      logs.push_back(entry.second);
    std::sort(logs.begin(), logs.end());
    REQUIRE(logs.size() == 2);
    CHECK(logs[0] == Approx(0.).margin(tight));
    CHECK(logs[1] == Approx(std::log(2.)).epsilon(tight));
  }
}

TEMPLATE_TEST_CASE("Control: a piece whose boundary crosses itself is one self-overlapping piece",
                   "[oracle][flattening][overlap]", SD_MESH_TYPES)
{
  using Mesh = TestType;
  // two unit squares, the second shifted by 3; in the first, (1, 1) and (0, 1) swap places in
  // the plane: its boundary (0,0), (1,0), (0,1), (1,1) is a figure eight, and its face (0, 2, 3)
  // is flipped. The second square is flattened as it is.
  Soup_points points;
  Soup_triangles triangles;
  square_soup(points, triangles);
  square_soup(points, triangles, 3.);
  const Mesh mesh = from_soup<Mesh>(points, triangles);
  auto uv = per_vertex<Point_2>(mesh, [](const test::Point& p) {
    return p.x() < 2. && p.y() == 1. ? Point_2(1. - p.x(), p.y()) : Point_2(p.x(), p.y());
  });
  const SD::Flattening_distortion d = SD::flattening_distortion(mesh, boost::make_assoc_property_map(uv));
  CHECK(d.pieces == 2);
  CHECK(d.self_overlapping_pieces == 1);
  CHECK(d.flipped_faces == 1);
  CHECK(d.boundary_length_error_max == Approx(std::sqrt(2.) - 1.).epsilon(tight)); // 1-2 and 3-0 become diagonals

  // the detector of the splitting cut agrees; the only interior edge of the piece is its
  // diagonal, which splits it into two triangles
  std::vector<Edge<Mesh>> cut;
  const SD::Overlap_splitting_result r =
    SD::compute_overlap_splitting_cut(mesh, boost::make_assoc_property_map(uv), std::back_inserter(cut));
  CHECK(r.overlapping_pieces == 1);
  CHECK(r.split_pieces == 1);
  CHECK(r.cut_edges == 1);
  REQUIRE(cut.size() == 1);
  CHECK(edge_between(mesh, vertex_at(mesh, 0., 0.), vertex_at(mesh, 1., 1.)) == cut.front());
}

TEST_CASE("Control: polygon crossings", "[oracle][flattening][overlap]")
{
  CHECK(SDI::polygon_self_intersects({{0., 0.}, {1., 0.}, {0., 1.}, {1., 1.}}));           // figure eight
  CHECK(SDI::polygon_self_intersects({{0., 0.}, {2., 0.}, {2., 1.}, {1., -1.}, {0., 1.}})); // a spike through the bottom
  CHECK(!SDI::polygon_self_intersects({{0., 0.}, {2., 0.}, {2., 2.}, {1., 0.5}, {0., 2.}}));
}

// ---------------------------------------------------------------------------------------------
// quad_mesh_quality()

TEMPLATE_TEST_CASE("Control: a 3 x 3 quad grid has four irregular vertices, its corners", "[oracle][quad_quality]",
                   SD_MESH_TYPES)
{
  using Mesh = TestType;
  Soup_points points;
  for(std::size_t j = 0; j <= 3; ++j)
    for(std::size_t i = 0; i <= 3; ++i)
      points.push_back({double(i), double(j), 0.});
  std::vector<std::vector<std::size_t>> quads;
  Soup_triangles triangles;
  for(std::size_t j = 0; j < 3; ++j)
    for(std::size_t i = 0; i < 3; ++i)
    {
      const std::size_t a = 4 * j + i, b = a + 1, c = a + 5, d = a + 4;
      quads.push_back({a, b, c, d});
      triangles.push_back({a, b, c});
      triangles.push_back({a, c, d});
    }
  const Mesh grid = polygon_mesh<Mesh>(points, quads);
  const Mesh reference = from_soup<Mesh>(points, triangles);
  const SD::Quad_mesh_quality q = SD::quad_mesh_quality(grid, reference);
  CHECK(q.vertices == 16);
  CHECK(q.edges == 24);
  CHECK(q.faces == 9);
  CHECK(q.faces_by_sides == std::array<std::size_t, 5>{0, 9, 0, 0, 0});
  CHECK(q.quad_fraction == 1.);
  CHECK(q.quad_area_fraction == Approx(1.).epsilon(tight));
  // corners: boundary valence 2; the 8 other boundary vertices valence 3, the 4 interior ones 4
  CHECK(q.irregular_vertices == 4);
  CHECK(q.t_junctions == 0);
  CHECK(q.angle_deviation_max == Approx(0.).margin(1e-10));
  CHECK(q.edge_length_mean == Approx(1.).epsilon(tight));
  CHECK(q.edge_length_min == Approx(1.).epsilon(tight));
  CHECK(q.edge_length_max == Approx(1.).epsilon(tight));
  CHECK(q.degenerate_edges == 0);
  CHECK(q.valid);
  CHECK(q.euler_characteristic == 1);
  CHECK(q.boundary_loops == 1);
  CHECK(q.connected_components == 1);
  CHECK(q.same_topology);
  CHECK(q.hausdorff_distance == Approx(0.).margin(1e-3 * std::sqrt(18.)));

  // the same grid with its interior vertex (1, 1) moved onto its neighbour (2, 1), as a remesher
  // that made two nodes at one point would leave it: one edge of length 0, the mesh still valid
  Soup_points moved = points;
  moved[5] = moved[6];
  const SD::Quad_mesh_quality d = SD::quad_mesh_quality(polygon_mesh<Mesh>(moved, quads), reference);
  CHECK(d.valid);
  CHECK(d.degenerate_edges == 1);
  CHECK(d.edge_length_min == 0.);
  // nearly coincident (10^-12 apart) is degenerate too; 10^-6 apart is not
  moved[5] = {2. - 1e-12, 1., 0.};
  CHECK(SD::quad_mesh_quality(polygon_mesh<Mesh>(moved, quads), reference).degenerate_edges == 1);
  moved[5] = {2. - 1e-6, 1., 0.};
  CHECK(SD::quad_mesh_quality(polygon_mesh<Mesh>(moved, quads), reference).degenerate_edges == 0);
}

TEMPLATE_TEST_CASE("Control: a quad mesh with one hanging node has one T-junction", "[oracle][quad_quality]",
                   SD_MESH_TYPES)
{
  using Mesh = TestType;
  // a 2 x 2 square on the left, two unit squares on its right: the left face is a pentagon
  // (0,0), (2,0), (2,1), (2,2), (0,2) with a straight corner at the hanging node (2, 1)
  const Soup_points points = {{0., 0., 0.}, {2., 0., 0.}, {3., 0., 0.}, {0., 2., 0.},
                              {2., 2., 0.}, {3., 2., 0.}, {2., 1., 0.}, {3., 1., 0.}};
  const Mesh mesh = polygon_mesh<Mesh>(points, {{0, 1, 6, 4, 3}, {1, 2, 7, 6}, {6, 7, 5, 4}});
  const Mesh reference =
    from_soup<Mesh>(points, {{0, 1, 6}, {0, 6, 4}, {0, 4, 3}, {1, 2, 7}, {1, 7, 6}, {6, 7, 5}, {6, 5, 4}});
  const SD::Quad_mesh_quality q = SD::quad_mesh_quality(mesh, reference);
  CHECK(q.vertices == 8);
  CHECK(q.edges == 10);
  CHECK(q.faces == 3);
  CHECK(q.faces_by_sides == std::array<std::size_t, 5>{0, 2, 1, 0, 0});
  CHECK(q.quad_fraction == Approx(2. / 3.).epsilon(tight));
  CHECK(q.quad_area_fraction == Approx(2. / 6.).epsilon(tight));
  CHECK(q.t_junctions == 1);
  // the four corners (boundary valence 2) and the hanging node (interior valence 3)
  CHECK(q.irregular_vertices == 5);
  CHECK(q.angle_deviation_max == Approx(0.).margin(1e-10)); // the quads are squares
  // edge lengths: three of 2, seven of 1
  CHECK(q.edge_length_mean == Approx(1.3).epsilon(tight));
  CHECK(q.edge_length_min == Approx(1.).epsilon(tight));
  CHECK(q.edge_length_max == Approx(2.).epsilon(tight));
  CHECK(q.edge_length_variation == Approx(std::sqrt(1.9 - 1.3 * 1.3) / 1.3).epsilon(1e-10));
  CHECK(q.valid);
  CHECK(q.euler_characteristic == 1);
  CHECK(q.same_topology);
  // the pentagon's centroid is (6/5, 1)
  CHECK(SD::count_non_quads_near(mesh, std::vector<test::Point>{test::Point(1.2, 1., 0.)}, 1e-6) == 1);
  CHECK(SD::count_non_quads_near(mesh, std::vector<test::Point>{test::Point(2.5, 0.5, 0.)}, 0.5) == 0);
}

TEMPLATE_TEST_CASE("Control: corner angles, Hausdorff distance and topology of quad meshes", "[oracle][quad_quality]",
                   SD_MESH_TYPES)
{
  using Mesh = TestType;
  SECTION("a rhombus of 60 and 120 degrees deviates by 30 degrees at every corner")
  {
    const double h = std::sqrt(3.) / 2.;
    const Soup_points points = {{0., 0., 0.}, {1., 0., 0.}, {1.5, h, 0.}, {0.5, h, 0.}};
    const Mesh rhombus = polygon_mesh<Mesh>(points, {{0, 1, 2, 3}});
    const Mesh reference = from_soup<Mesh>(points, {{0, 1, 2}, {0, 2, 3}});
    const SD::Quad_mesh_quality q = SD::quad_mesh_quality(rhombus, reference);
    CHECK(q.angle_deviation_mean == Approx(30.).epsilon(1e-10));
    CHECK(q.angle_deviation_rms == Approx(30.).epsilon(1e-10));
    CHECK(q.angle_deviation_max == Approx(30.).epsilon(1e-10));
    CHECK(q.t_junctions == 0); // 120 degrees is not straight
    CHECK(q.irregular_vertices == 4);
    CHECK(q.edge_length_variation == Approx(0.).margin(1e-10));
  }
  SECTION("a unit square 1/4 below its reference: Hausdorff distance 1/4")
  {
    const Mesh square = polygon_mesh<Mesh>({{0., 0., 0.}, {1., 0., 0.}, {1., 1., 0.}, {0., 1., 0.}}, {{0, 1, 2, 3}});
    Soup_points points;
    Soup_triangles triangles;
    square_soup(points, triangles, 0., 0.25);
    const Mesh reference = from_soup<Mesh>(points, triangles);
    const double bound = 1e-6;
    const SD::Quad_mesh_quality q =
      SD::quad_mesh_quality(square, reference, CGAL::parameters::default_values(), P::hausdorff_error_bound(bound));
    const double diagonal = std::sqrt(2.); // of the reference's bounding box
    CHECK(std::abs(q.hausdorff_distance - 0.25) <= bound * diagonal);
    CHECK(std::abs(q.relative_hausdorff_distance - 0.25 / diagonal) <= bound);
    CHECK(q.same_topology);
  }
  SECTION("a reference of another topology")
  {
    const Mesh square = polygon_mesh<Mesh>({{0., 0., 0.}, {1., 0., 0.}, {1., 1., 0.}, {0., 1., 0.}}, {{0, 1, 2, 3}});
    // two triangles apart: two components of Euler characteristic 1 each
    const Mesh reference = from_soup<Mesh>({{0., 0., 0.}, {1., 0., 0.}, {0., 1., 0.}, {2., 0., 0.}, {3., 0., 0.}, {2., 1., 0.}},
                                           {{0, 1, 2}, {3, 4, 5}});
    const SD::Quad_mesh_quality q = SD::quad_mesh_quality(square, reference);
    CHECK(q.valid);
    CHECK(q.connected_components == 1);
    CHECK(!q.same_topology);
  }
}

TEMPLATE_TEST_CASE("Control: the certified Hausdorff distance brackets the exact one, also inside a triangle",
                   "[oracle][quad_quality]", SD_MESH_TYPES)
{
  using Mesh = TestType;
  const double error = 1e-3;
  SECTION("a unit square and four corner triangles of it: the farthest point lies inside a triangle")
  {
    // A is the square (two triangles), B four triangles of different sizes at its corners, inside
    // it: h(B, A) = 0, and h(A, B) is reached at an interior point, where no corner of A is (every
    // corner of A lies on B). The exact value is brute-forced on a 201 x 201 grid: with spacing
    // g it lies in [s, s + g / sqrt(2)] (the distance is 1-Lipschitz).
    Soup_points points;
    Soup_triangles triangles;
    square_soup(points, triangles);
    const Mesh square = from_soup<Mesh>(points, triangles);
    const std::array<std::array<double, 3>, 4> corner = {{{0., 0., 0.1}, {1., 0., 0.2}, {1., 1., 0.05}, {0., 1., 0.3}}};
    Soup_points b_points;
    Soup_triangles b_triangles;
    for(const auto& c : corner)
    {
      const double sx = c[0] > 0.5 ? -1. : 1., sy = c[1] > 0.5 ? -1. : 1., d = c[2];
      const std::size_t k = b_points.size();
      b_points.push_back({c[0], c[1], 0.});
      b_points.push_back({c[0] + sx * d, c[1], 0.});
      b_points.push_back({c[0], c[1] + sy * d, 0.});
      if(sx * sy > 0.)
        b_triangles.push_back({k, k + 1, k + 2});
      else
        b_triangles.push_back({k, k + 2, k + 1});
    }
    const Mesh pieces = from_soup<Mesh>(b_points, b_triangles);
    std::vector<SDI::Triangle_soup::Point> bp;
    for(const auto& p : b_points)
      bp.emplace_back(p[0], p[1], p[2]);
    const int n = 200;
    double s = 0.;
    for(int i = 0; i <= n; ++i)
      for(int j = 0; j <= n; ++j)
      {
        const SDI::Triangle_soup::Point p(double(i) / n, double(j) / n, 0.);
        double d = std::numeric_limits<double>::infinity();
        for(const auto& t : b_triangles)
          d = (std::min)(d, std::sqrt(CGAL::squared_distance(p, SDI::hausdorff_internal::Triangle(bp[t[0]], bp[t[1]], bp[t[2]]))));
        s = (std::max)(s, d);
      }
    const double slack = 1. / (n * std::sqrt(2.)) + 1e-12;
    const SDI::Hausdorff_bounds h = SDI::bounded_hausdorff_distance(
      SDI::fanned_triangle_soup(square, get(CGAL::vertex_point, square)),
      SDI::fanned_triangle_soup(pieces, get(CGAL::vertex_point, pieces)), error);
    INFO("brute force " << s << ", bounds [" << h.lower << ", " << h.upper << "]");
    CHECK(s > 0.5); // far from every corner of A: the refinement found it
    CHECK(h.lower <= s + slack);
    CHECK(h.upper >= s - 1e-12);
    CHECK(h.upper - h.lower <= error);
    CHECK(h.lower > s - error - slack);
    // through quad_mesh_quality (relative to B's bounding-box diagonal, sqrt(2))
    const SD::Quad_mesh_quality q =
      SD::quad_mesh_quality(square, pieces, CGAL::parameters::default_values(), P::hausdorff_error_bound(error));
    CHECK(q.hausdorff_distance >= s - 1e-12);
    CHECK(q.hausdorff_distance <= s + slack + error * std::sqrt(2.));
  }
  SECTION("a grid with one vertex raised by 0.3: the distance is 0.3 both ways round")
  {
    // every point of the flat grid lies at most 0.3 below the bumped one, and the raised vertex
    // lies 0.3 above the flat grid (its foot is inside the grid)
    Mesh flat, bumped;
    SD::make_grid(flat, 6, 6);
    SD::make_grid(bumped, 6, 6);
    auto vpm = get(CGAL::vertex_point, bumped);
    std::size_t raised = 0;
    for(auto v : vertices(bumped))
    {
      const auto p = get(vpm, v);
      if(std::abs(p.x() - 0.5) < 1e-9 && std::abs(p.y() - 0.5) < 1e-9)
      {
        put(vpm, v, test::Point(p.x(), p.y(), 0.3));
        ++raised;
      }
    }
    REQUIRE(raised == 1);
    for(int swap = 0; swap < 2; ++swap)
    {
      const Mesh& a = swap ? bumped : flat;
      const Mesh& b = swap ? flat : bumped;
      const SDI::Hausdorff_bounds h = SDI::bounded_hausdorff_distance(
        SDI::fanned_triangle_soup(a, get(CGAL::vertex_point, a)), SDI::fanned_triangle_soup(b, get(CGAL::vertex_point, b)), error);
      CHECK(h.lower == Approx(0.3).epsilon(1e-12));
      CHECK(h.upper >= 0.3);
      CHECK(h.upper <= 0.3 + error);
    }
    // a point of no triangle is not on the surface: a far one changes nothing
    SDI::Triangle_soup flat_soup = SDI::fanned_triangle_soup(flat, get(CGAL::vertex_point, flat));
    const SDI::Triangle_soup bumped_soup = SDI::fanned_triangle_soup(bumped, get(CGAL::vertex_point, bumped));
    flat_soup.points.emplace_back(0.5, 0.5, -40.);
    const SDI::Hausdorff_bounds isolated = SDI::bounded_hausdorff_distance(flat_soup, bumped_soup, error);
    CHECK(isolated.lower == Approx(0.3).epsilon(1e-12));
    CHECK(isolated.upper <= 0.3 + error);
    // an error below what the coordinates resolve is raised to it: the refinement ends
    const SDI::Hausdorff_bounds tiny = SDI::bounded_hausdorff_distance(flat_soup, bumped_soup, 1e-30);
    CHECK(tiny.lower == Approx(0.3).epsilon(1e-12));
    CHECK(tiny.upper - tiny.lower <= 1e-12 * 40.); // the largest coordinate is the isolated point's 40
  }
  SECTION("two spheres of different resolutions: CGAL's bounded-error distance within the error of the bounds")
  {
    // an independent implementation (Polygon Mesh Processing), whose estimate lies within its
    // error bound of the exact value
    Mesh coarse, fine;
    SD::make_sphere(coarse, 2);
    SD::make_sphere(fine, 5);
    const SDI::Hausdorff_bounds h = SDI::bounded_hausdorff_distance(
      SDI::fanned_triangle_soup(coarse, get(CGAL::vertex_point, coarse)),
      SDI::fanned_triangle_soup(fine, get(CGAL::vertex_point, fine)), error);
    const double cgal = CGAL::Polygon_mesh_processing::bounded_error_symmetric_Hausdorff_distance<CGAL::Sequential_tag>(
      coarse, fine, error);
    INFO("CGAL " << cgal << ", bounds [" << h.lower << ", " << h.upper << "]");
    CHECK(h.lower > 0.01); // the coarse sphere's flat faces sink well inside the fine one
    CHECK(h.upper - h.lower <= error);
    CHECK(cgal >= h.lower - error);
    CHECK(cgal <= h.upper + error);
  }
}

// ---------------------------------------------------------------------------------------------
// developability_metrics()

TEMPLATE_TEST_CASE("Control: the developability metrics of a cube with pyramid-split faces", "[oracle][developability]",
                   SD_MESH_TYPES)
{
  using Mesh = TestType;
  // The unit cube, each face split into four right isosceles triangles at its centre: 8 corners
  // of valence 6 and 6 face centres of valence 4, all measured. At a corner the faces of each
  // of the three planes meet with two 45-degree angles, so A = (pi/2) I and lambda = pi/2 (no
  // hinge, a seam vertex); at a face centre the star is flat: lambda = 0 (a hinge). The seam
  // edges are the 12 cube edges, one connected seam curve of length 12.
  Soup_points points;
  for(int k = 0; k < 8; ++k)
    points.push_back({double(k & 1), double((k >> 1) & 1), double((k >> 2) & 1)});
  Soup_triangles triangles;
  // faces as corner cycles, counter-clockwise seen from outside
  const std::vector<std::array<std::size_t, 4>> sides = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                                                         {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for(const auto& s : sides)
  {
    std::array<double, 3> c = {0., 0., 0.};
    for(std::size_t k : s)
      for(int i = 0; i < 3; ++i)
        c[std::size_t(i)] += points[k][std::size_t(i)] / 4.;
    points.push_back(c);
    for(std::size_t k = 0; k < 4; ++k)
      triangles.push_back({points.size() - 1, s[k], s[(k + 1) % 4]});
  }
  const Mesh cube = from_soup<Mesh>(points, triangles);
  const SD::Developability_metrics m = SD::developability_metrics(cube);
  CHECK(m.vertices == 14);
  CHECK(m.faces == 24);
  CHECK(m.measured_vertices == 14);
  CHECK(m.energy == Approx(8. * pi / 2.).epsilon(tight));
  CHECK(m.lambda_max == Approx(pi / 2.).epsilon(tight));
  CHECK(m.lambda_mean == Approx(8. * (pi / 2.) / 14.).epsilon(tight));
  CHECK(m.lambda_p95 == Approx(pi / 2.).epsilon(tight));
  CHECK(m.hinge_share_1e4 == Approx(6. / 14.).epsilon(tight));
  CHECK(m.hinge_share_1e3 == Approx(6. / 14.).epsilon(tight));
  CHECK(m.angle_defect_max == Approx(pi / 2.).epsilon(tight));
  CHECK(m.angle_defect_mean == Approx(4. * pi / 14.).epsilon(tight)); // Gauss-Bonnet: 4 pi in all
  CHECK(m.seam_vertices == 8);
  CHECK(m.seam_curvature_share == Approx(1.).epsilon(tight));
  CHECK(m.seam_curves == 1);
  CHECK(m.seam_length == Approx(12.).epsilon(tight));
  CHECK(m.minimum_angle == Approx(pi / 4.).epsilon(tight));
  // the developable cut: the corners are its terminals; a sphere opens into one disk
  std::vector<Edge<Mesh>> cut;
  const SD::Developable_cut_result r = SD::compute_developable_cut(cube, std::back_inserter(cut));
  CHECK(r.terminals == 8);
  CHECK(r.lambda_max == Approx(pi / 2.).epsilon(tight));
  CHECK(r.generator_loops == 0);
  CHECK(r.pieces == 1);
}

TEMPLATE_TEST_CASE("Control: the distance of a square to its copy 1/4 above", "[oracle][developability]", SD_MESH_TYPES)
{
  using Mesh = TestType;
  Soup_points points, lifted;
  Soup_triangles triangles, lifted_triangles;
  square_soup(points, triangles);
  square_soup(lifted, lifted_triangles, 0., 0.25);
  const Mesh square = from_soup<Mesh>(points, triangles);
  const Mesh reference = from_soup<Mesh>(lifted, lifted_triangles);
  // every point of either square is exactly 1/4 from the other; the reference's diagonal is sqrt 2
  const SD::Developability_metrics m = SD::developability_metrics(square, reference);
  CHECK(m.hausdorff_distance == Approx(0.25 / std::sqrt(2.)).epsilon(tight));
  CHECK(m.mean_distance == Approx(0.25 / std::sqrt(2.)).epsilon(tight));
  // the square read through a point map of its own, 3/4 above (1/2 above the reference): the
  // distances and the other metrics follow that map, not the mesh's points (a bug once)
  const auto raised = per_vertex<test::Point>(square, [](const test::Point& p) { return test::Point(p.x(), p.y(), 0.75); });
  const SD::Developability_metrics r = SD::developability_metrics(
    square, reference, CGAL::parameters::vertex_point_map(boost::make_assoc_property_map(raised)));
  CHECK(r.hausdorff_distance == Approx(0.5 / std::sqrt(2.)).epsilon(tight));
  CHECK(r.mean_distance == Approx(0.5 / std::sqrt(2.)).epsilon(tight));
  const auto sheared = per_vertex<test::Point>(square, [](const test::Point& p) { return test::Point(p.x() + 3. * p.y(), p.y(), 0.25); });
  const SD::Developability_metrics s1 = SD::developability_metrics(
    square, reference, CGAL::parameters::vertex_point_map(boost::make_assoc_property_map(sheared)));
  const SD::Developability_metrics s2 =
    SD::developability_metrics(square, CGAL::parameters::vertex_point_map(boost::make_assoc_property_map(sheared)));
  CHECK(s1.minimum_angle == s2.minimum_angle);
  CHECK(s1.minimum_angle < m.minimum_angle); // shearing makes a sharper corner than the square's pi/4
  CHECK(s1.hausdorff_distance > 0.5); // the sheared square reaches x = 4, far outside the reference
}

// ---------------------------------------------------------------------------------------------
// singularity indices

TEMPLATE_TEST_CASE("Control: a field turning once around a face has index +-1 there", "[oracle][direction_fields]",
                   SD_MESH_TYPES)
{
  using Mesh = TestType;
  const Mesh mesh = triangle_with_flaps<Mesh>();
  for(int n : {1, 2, 4})
    for(int sign : {1, -1})
    {
      INFO("symmetry order " << n << ", turning " << sign);
      // one of the n directions at angle sign theta / n: the n-fold angle is sign theta, which
      // turns by sign 120 degrees along every edge of the inner triangle (k = sign, i.e. index
      // sign / n) and back and forth around every flap (k = 0)
      auto field = per_vertex<Vector_3>(mesh, [&](const test::Point& p) {
        const double a = double(sign) * polar_angle(p) / double(n);
        return Vector_3(std::cos(a), std::sin(a), 0.);
      });
      std::map<Face<Mesh>, int> k;
      const std::size_t count = SD::direction_field_singularities(
        mesh, boost::make_assoc_property_map(field), boost::make_assoc_property_map(k), P::symmetry_order(n));
      CHECK(count == 1);
      REQUIRE(k.size() == 4);
      for(const auto& [f, index] : k)
        CHECK(index == (is_inner_face(mesh, f) ? sign : 0));
    }
}

TEMPLATE_TEST_CASE("Control: stripe and one-form singularities of the polar angle", "[oracle][field_aligned]",
                   SD_MESH_TYPES)
{
  using Mesh = TestType;
  const Mesh mesh = triangle_with_flaps<Mesh>();
  for(int sign : {1, -1})
  {
    INFO("turning " << sign);
    auto alpha = per_vertex<double>(mesh, [&](const test::Point& p) { return double(sign) * polar_angle(p); });
    std::map<Face<Mesh>, int> k;
    CHECK(SD::stripe_singularities(mesh, boost::make_assoc_property_map(alpha), boost::make_assoc_property_map(k)) == 1);
    REQUIRE(k.size() == 4);
    for(const auto& [f, index] : k)
      CHECK(index == (is_inner_face(mesh, f) ? sign : 0));
    // the wrapped differential of alpha: its curl is 2 pi sign on the inner face, 0 on the flaps
    std::map<Edge<Mesh>, double> dalpha;
    for(auto e : edges(mesh))
    {
      const auto h = halfedge(e, mesh);
      dalpha[e] = SDI::wrap_angle(alpha.at(target(h, mesh)) - alpha.at(source(h, mesh)));
    }
    std::map<Face<Mesh>, int> from_form;
    CHECK(SD::one_form_singularities(mesh, boost::make_assoc_property_map(dalpha),
                                     boost::make_assoc_property_map(from_form)) == 1);
    CHECK(from_form == k);
  }
}

TEMPLATE_TEST_CASE("Control: a monkey saddle is a critical point of multiplicity 2", "[oracle][harmonic_quad]",
                   SD_MESH_TYPES)
{
  using Mesh = TestType;
  // a hexagon fanned from its centre; u = Re(z^3) = r^3 cos(3 theta) is 0 at the centre and
  // alternately +1 and -1 on the ring: three lower wedges at the centre (a saddle of index -2),
  // three boundary maxima (index 0) and three minima (index 1); sum 1 = chi(disk)
  Soup_points points = {{0., 0., 0.}};
  Soup_triangles triangles;
  for(std::size_t k = 0; k < 6; ++k)
  {
    points.push_back({std::cos(double(k) * pi / 3.), std::sin(double(k) * pi / 3.), 0.});
    triangles.push_back({0, 1 + k, 1 + (k + 1) % 6});
  }
  const Mesh mesh = from_soup<Mesh>(points, triangles);
  const SDI::Mesh_indices<Mesh> idx(mesh);
  const auto m = SDI::harmonic_quad::make_trace_mesh(idx, get(CGAL::vertex_point, mesh));
  std::vector<double> u(idx.number_of_vertices());
  for(std::size_t v = 0; v < u.size(); ++v)
  {
    const auto& p = get(CGAL::vertex_point, mesh, idx.vertex(v));
    const double r = std::hypot(p.x(), p.y());
    u[v] = r * r * r * std::cos(3. * polar_angle(p));
  }
  const auto [critical, index_sum] = SDI::harmonic_quad::critical_points(m, u);
  CHECK(index_sum == 1);
  std::size_t minima = 0, maxima = 0, saddles = 0;
  int multiplicity = 0;
  for(const auto& c : critical)
  {
    minima += c.kind == SDI::harmonic_quad::Critical_kind::minimum;
    maxima += c.kind == SDI::harmonic_quad::Critical_kind::maximum;
    if(c.kind == SDI::harmonic_quad::Critical_kind::saddle)
    {
      ++saddles;
      multiplicity += c.multiplicity;
      CHECK(!c.on_boundary);
      CHECK(get(CGAL::vertex_point, mesh, idx.vertex(c.vertex)) == test::Point(0., 0., 0.));
    }
  }
  CHECK(minima == 3);
  CHECK(maxima == 3);
  CHECK(saddles == 1);
  CHECK(multiplicity == 2);
}

// ---------------------------------------------------------------------------------------------
// topology and disk-ness

TEMPLATE_TEST_CASE("Control: components, boundary loops, Euler characteristic, genus and generators",
                   "[oracle][topology]", SD_MESH_TYPES)
{
  using Mesh = TestType;
  SECTION("an annulus and a triangle apart")
  {
    Soup_points points;
    Soup_triangles triangles;
    test::ruled_soup(8, 1, false, false, points, triangles); // open cylinder: 16 vertices, 16 faces
    const std::size_t o = points.size();
    for(const auto& p : Soup_points{{5., 0., 0.}, {6., 0., 0.}, {5., 1., 0.}})
      points.push_back(p);
    triangles.push_back({o, o + 1, o + 2});
    const Mesh mesh = from_soup<Mesh>(points, triangles);
    const SDI::Mesh_indices<Mesh> idx(mesh);
    const SDI::Topology t = SDI::compute_topology(idx);
    CHECK(t.boundary.size() == 3);
    REQUIRE(t.components.size() == 2);
    const SDI::Component_info& annulus = t.components.info[0]; // numbered by smallest vertex
    const SDI::Component_info& triangle = t.components.info[1];
    CHECK(annulus.vertices == 16);
    CHECK(annulus.edges == 32);
    CHECK(annulus.faces == 16);
    CHECK(annulus.euler_characteristic() == 0);
    CHECK(annulus.boundary_loops == 2);
    CHECK(annulus.genus() == 0);
    CHECK(triangle.euler_characteristic() == 1);
    CHECK(triangle.boundary_loops == 1);
    CHECK(t.tree.generator_edges.empty());
    // flattening refuses the annulus, naming it
    try
    {
      SDI::require_disks(t.components);
      FAIL("an annulus was taken for a disk");
    }
    catch(const SD::Invalid_mesh& e)
    {
      CHECK(e.defect() == SD::Mesh_defect::not_a_disk);
    }
    // the developable cut joins the annulus' two loops: two disks
    std::vector<Edge<Mesh>> cut;
    const SD::Developable_cut_result r = SD::compute_developable_cut(mesh, std::back_inserter(cut));
    CHECK(r.boundary_loops == 3);
    CHECK(r.terminals == 0); // every vertex is on the boundary
    CHECK(r.pieces == 2);
  }
  SECTION("a torus: genus 1, two generators")
  {
    Mesh torus;
    SD::make_torus(torus, 8, 4);
    const SDI::Mesh_indices<Mesh> idx(torus);
    const SDI::Topology t = SDI::compute_topology(idx);
    CHECK(t.boundary.size() == 0);
    REQUIRE(t.components.size() == 1);
    CHECK(t.components.info[0].euler_characteristic() == 0);
    CHECK(t.components.info[0].genus() == 1);
    CHECK(t.tree.generator_edges.size() == 2);
    CHECK(t.tree.generator_loops.size() == 2);
  }
}

TEMPLATE_TEST_CASE("Control: disk-ness of the pieces of a cut torus and of a cut strip", "[oracle][cut]",
                   SD_MESH_TYPES)
{
  using Mesh = TestType;
  SECTION("torus: a meridian leaves an annulus, a meridian and a longitude a disk")
  {
    Mesh torus;
    SD::make_torus(torus, 8, 4); // 32 vertices, 96 edges, 64 faces; vertex (i, j) is i * 4 + j
    const SDI::Mesh_indices<Mesh> idx(torus);
    auto vertex_ij = [&](std::size_t i, std::size_t j) { return idx.vertex((i % 8) * 4 + j % 4); };
    std::vector<Edge<Mesh>> meridian, both;
    for(std::size_t j = 0; j < 4; ++j)
      meridian.push_back(edge_between(torus, vertex_ij(0, j), vertex_ij(0, j + 1)));
    both = meridian;
    for(std::size_t i = 0; i < 8; ++i)
      both.push_back(edge_between(torus, vertex_ij(i, 0), vertex_ij(i + 1, 0)));
    auto topology_of = [&](const std::vector<Edge<Mesh>>& cut) {
      std::vector<bool> is_cut(idx.number_of_edges(), false);
      for(const auto& e : cut)
        is_cut[idx.edge_index(halfedge(e, torus))] = true;
      return SDI::cut_topology(idx, is_cut, SDI::cut_corners(idx, is_cut));
    };
    const SDI::Cut_topology annulus = topology_of(meridian);
    REQUIRE(annulus.pieces.size() == 1);
    CHECK(annulus.pieces[0].vertices == 36);
    CHECK(annulus.pieces[0].edges == 100);
    CHECK(annulus.pieces[0].euler_characteristic() == 0);
    CHECK(annulus.pieces[0].boundary_loops == 2);
    CHECK(!annulus.all_disks());
    const SDI::Cut_topology disk = topology_of(both);
    REQUIRE(disk.pieces.size() == 1);
    CHECK(disk.pieces[0].vertices == 45); // chi = 1: 45 - 108 + 64
    CHECK(disk.pieces[0].edges == 108);
    CHECK(disk.pieces[0].boundary_loops == 1);
    CHECK(disk.all_disks());
    Mesh open;
    CHECK(SD::cut_mesh_along_edges(torus, both, open) == 1);
    CHECK(num_vertices(open) == 45);
    // the developable cut finds the two generator loops and leaves one disk
    std::vector<Edge<Mesh>> cut;
    const SD::Developable_cut_result r =
      SD::compute_developable_cut(torus, std::back_inserter(cut), P::cut_tolerance(10.)); // no terminal
    CHECK(r.terminals == 0);
    CHECK(r.boundary_loops == 0);
    CHECK(r.generator_loops == 2);
    CHECK(r.pieces == 1);
    CHECK(r.cut_edges == cut.size());
    CHECK(r.cut_edges >= 2);
  }
  SECTION("a strip of two squares cut across the middle falls into two disks")
  {
    const Mesh strip = from_soup<Mesh>({{0., 0., 0.}, {1., 0., 0.}, {2., 0., 0.}, {0., 1., 0.}, {1., 1., 0.}, {2., 1., 0.}},
                                       {{0, 1, 4}, {0, 4, 3}, {1, 2, 5}, {1, 5, 4}});
    REQUIRE(num_vertices(strip) == 6);
    const std::vector<Edge<Mesh>> middle = {edge_between(strip, vertex_at(strip, 1., 0.), vertex_at(strip, 1., 1.))};
    Mesh pieces;
    CHECK(SD::cut_mesh_along_edges(strip, middle, pieces) == 2);
    CHECK(num_vertices(pieces) == 8);
    const SDI::Mesh_indices<Mesh> idx(strip);
    std::vector<bool> is_cut(idx.number_of_edges(), false);
    is_cut[idx.edge_index(halfedge(middle.front(), strip))] = true;
    const SDI::Cut_topology t = SDI::cut_topology(idx, is_cut, SDI::cut_corners(idx, is_cut));
    REQUIRE(t.pieces.size() == 2);
    for(const auto& piece : t.pieces)
    {
      CHECK(piece.vertices == 4);
      CHECK(piece.faces == 2);
      CHECK(piece.boundary_loops == 1);
    }
    CHECK(t.all_disks());
  }
}

// ---------------------------------------------------------------------------------------------
// the fabrication pattern

TEMPLATE_TEST_CASE("Control: the pattern of two unit squares: boxes, cut paths and seam labels", "[oracle][pattern]",
                   SD_MESH_TYPES)
{
  using Mesh = TestType;
  // the strip of two unit squares, cut along its middle side (1,0)-(1,1)
  const Soup_points points = {{0., 0., 0.}, {1., 0., 0.}, {2., 0., 0.}, {0., 1., 0.}, {1., 1., 0.}, {2., 1., 0.}};
  const Mesh strip = from_soup<Mesh>(points, {{0, 1, 4}, {0, 4, 3}, {1, 2, 5}, {1, 5, 4}});
  const std::vector<Edge<Mesh>> middle = {edge_between(strip, vertex_at(strip, 1., 0.), vertex_at(strip, 1., 1.))};
  Mesh pieces;
  std::vector<std::pair<Vertex<Mesh>, Vertex<Mesh>>> pairs;
  REQUIRE(SD::cut_mesh_along_edges(strip, middle, pieces,
                                   CGAL::parameters::vertex_to_vertex_output_iterator(std::back_inserter(pairs))) == 2);
  std::map<Vertex<Mesh>, std::size_t> id, seam_index;
  for(auto v : vertices(strip))
    id.emplace(v, id.size());
  for(const auto& [in, out] : pairs)
    seam_index[out] = id.at(in);
  auto uv = per_vertex<Point_2>(pieces, [](const test::Point& p) { return Point_2(p.x(), p.y()); });
  const SD::Fabrication_layout layout =
    SD::lay_out_flattened_pieces(pieces, boost::make_assoc_property_map(uv),
                                 P::pattern_scale(10., P::sheet_size(std::make_pair(100., 80.))));
  CHECK(layout.scale == 10.);
  CHECK(layout.sheets == 1);
  REQUIRE(layout.pieces.size() == 2);
  for(const auto& piece : layout.pieces)
  {
    CHECK(piece.faces == 2);
    CHECK(piece.width == Approx(10.).epsilon(tight)); // a unit square at 10 mm per unit
    CHECK(piece.height == Approx(10.).epsilon(tight));
  }
  std::ostringstream out;
  SD::write_fabrication_pattern_svg(out, pieces, boost::make_assoc_property_map(uv), layout,
                                    P::seam_vertex_index_map(boost::make_assoc_property_map(seam_index)));
  const std::string svg = out.str();
  CHECK(count_in_group(svg, "sheets", "rect") == 1);
  CHECK(count_in_group(svg, "cuts", "path") == 2);   // one boundary loop per piece
  CHECK(count_in_group(svg, "pieces", "text") == 2); // the piece numbers
  CHECK(count_in_group(svg, "seams", "text") == 2);  // the two sides of the one seam
  CHECK(count_in_group(svg, "folds", "path") == 0);  // flat
}

// ---------------------------------------------------------------------------------------------
// test support

TEMPLATE_TEST_CASE("Control: a mesh snapshot sees a moved vertex and a reversed face", "[oracle][support]",
                   SD_MESH_TYPES)
{
  using Mesh = TestType;
  Soup_points points;
  Soup_triangles triangles;
  square_soup(points, triangles);
  const Mesh mesh = from_soup<Mesh>(points, triangles);
  const test::Mesh_snapshot before(mesh);
  CHECK(test::Mesh_snapshot(from_soup<Mesh>(points, triangles)) == before);
  Mesh moved = from_soup<Mesh>(points, triangles);
  const auto v = vertex_at(moved, 1., 1.);
  put(get(CGAL::vertex_point, moved), v, test::Point(1., 1., 1e-300));
  CHECK(!(test::Mesh_snapshot(moved) == before));
  Soup_triangles reversed = triangles;
  std::swap(reversed[1][1], reversed[1][2]);
  std::swap(reversed[0][1], reversed[0][2]);
  CHECK(!(test::Mesh_snapshot(from_soup<Mesh>(points, reversed)) == before));
}
