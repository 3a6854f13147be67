// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Index maps and input validation, on Surface_mesh and Polyhedron_3 (with and without ids).

#include <test_support.h>

#include <CGAL/Surface_design/internal/Core/Mesh_indices.h>
#include <CGAL/Surface_design/internal/Core/validation.h>
#include <CGAL/Surface_design/mesh_generators.h>

#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/boost/graph/Euler_operations.h>

#include <array>
#include <cmath>
#include <limits>
#include <vector>

namespace SD = CGAL::Surface_design;
using SD::internal::Mesh_indices;
using SD::internal::validate_mesh;
namespace SDI = CGAL::Surface_design::internal;

namespace {

// Builds a mesh face by face with Euler::add_face, which (unlike polygon-soup conversion) also
// accepts configurations that validation must reject, such as a vertex joining two fans.
template <class Mesh>
Mesh build_with_euler(const std::vector<std::array<double, 3>>& points,
                      const std::vector<std::vector<std::size_t>>& polygons)
{
  Mesh mesh;
  std::vector<typename boost::graph_traits<Mesh>::vertex_descriptor> vs;
  for(const auto& p : points)
  {
    vs.push_back(add_vertex(mesh));
    put(get(CGAL::vertex_point, mesh), vs.back(), test::Point(p[0], p[1], p[2]));
  }
  for(const auto& poly : polygons)
  {
    std::vector<typename boost::graph_traits<Mesh>::vertex_descriptor> face_vertices;
    for(std::size_t i : poly)
      face_vertices.push_back(vs[i]);
    REQUIRE(CGAL::Euler::add_face(face_vertices, mesh) != boost::graph_traits<Mesh>::null_face());
  }
  return mesh;
}

template <class Mesh>
SD::Mesh_defect defect_of(const Mesh& mesh)
{
  const test::Mesh_snapshot before(mesh);
  try
  {
    Mesh_indices<Mesh> idx(mesh);
    validate_mesh(idx, get(CGAL::vertex_point, mesh));
  }
  catch(const SD::Invalid_mesh& e)
  {
    INFO(e.what());
    CHECK(test::Mesh_snapshot(mesh) == before); // validation never modifies the mesh
    return e.defect();
  }
  FAIL("no exception");
  return SD::Mesh_defect::empty;
}

} // namespace

TEMPLATE_TEST_CASE("Index maps are bijections in the input order", "[indices]", SD_MESH_TYPES_WITH_IDS)
{
  for(const std::string name : {"bunny_1k.off", "mech-holes-shark.off", "eight.off"})
  {
    INFO(name);
    const TestType mesh = test::load_mesh<TestType>(name);
    std::vector<test::Point> points;
    std::vector<std::vector<std::size_t>> polygons;
    REQUIRE(CGAL::IO::read_polygon_soup(test::data_path(name), points, polygons));

    Mesh_indices<TestType> idx(mesh);
    REQUIRE(idx.number_of_vertices() == points.size());
    REQUIRE(idx.number_of_faces() == polygons.size());
    REQUIRE(idx.number_of_halfedges() == 2 * idx.number_of_edges());

    for(std::size_t v = 0; v < points.size(); ++v)
    {
      REQUIRE(idx.index(idx.vertex(v)) == v);
      REQUIRE(get(CGAL::vertex_point, mesh, idx.vertex(v)) == points[v]);
    }
    for(std::size_t f = 0; f < polygons.size(); ++f)
    {
      REQUIRE(idx.index(idx.face(f)) == f);
      // same cyclic vertex sequence as in the file
      std::vector<std::size_t> cycle;
      for(auto v : vertices_around_face(halfedge(idx.face(f), mesh), mesh))
        cycle.push_back(idx.index(v));
      const auto start = std::find(cycle.begin(), cycle.end(), polygons[f][0]);
      REQUIRE(start != cycle.end());
      std::rotate(cycle.begin(), start, cycle.end());
      REQUIRE(cycle == polygons[f]);
    }
    for(std::size_t h = 0; h < idx.number_of_halfedges(); ++h)
      REQUIRE(idx.index(idx.halfedge(h)) == h);
    for(std::size_t e = 0; e < idx.number_of_edges(); ++e)
    {
      REQUIRE(idx.index(idx.edge(e)) == e);
      const auto ij = idx.edge_vertices(e);
      REQUIRE(ij.first < ij.second); // the documented orientation
      REQUIRE(idx.orientation_sign(idx.oriented_halfedge(e)) == 1);
      REQUIRE(idx.orientation_sign(opposite(idx.oriented_halfedge(e), mesh)) == -1);
    }
  }
}

TEST_CASE("User-supplied index maps are honoured", "[indices]")
{
  test::Surface_mesh mesh = test::load_mesh<test::Surface_mesh>("bunny_1k.off");
  auto reversed = mesh.add_property_map<test::Surface_mesh::Vertex_index, std::size_t>("v:rev").first;
  auto face_reversed = mesh.add_property_map<test::Surface_mesh::Face_index, std::size_t>("f:rev").first;
  auto edge_reversed = mesh.add_property_map<test::Surface_mesh::Edge_index, std::size_t>("e:rev").first;
  const std::size_t n = num_vertices(mesh), nf = num_faces(mesh), ne = num_edges(mesh);
  for(auto v : vertices(mesh))
    put(reversed, v, n - 1 - std::size_t(v));
  for(auto f : faces(mesh))
    put(face_reversed, f, nf - 1 - std::size_t(f));
  for(auto e : edges(mesh))
    put(edge_reversed, e, ne - 1 - std::size_t(e));
  const auto np =
    CGAL::parameters::vertex_index_map(reversed).face_index_map(face_reversed).edge_index_map(edge_reversed);
  Mesh_indices<test::Surface_mesh> idx(mesh, np);
  for(auto v : vertices(mesh))
  {
    REQUIRE(idx.index(v) == n - 1 - std::size_t(v));
    REQUIRE(idx.find(v) == idx.index(v));
  }
  for(auto f : faces(mesh))
  {
    REQUIRE(idx.index(f) == nf - 1 - std::size_t(f));
    REQUIRE(idx.face(idx.index(f)) == f);
  }
  for(auto e : edges(mesh))
  {
    REQUIRE(idx.index(e) == ne - 1 - std::size_t(e));
    REQUIRE(idx.edge(idx.index(e)) == e);
  }
  REQUIRE(idx.vertex(0) == *std::prev(vertices(mesh).end()));
  // a descriptor that is not an element of the mesh is not found
  REQUIRE(idx.find(test::Surface_mesh::Face_index(test::Surface_mesh::size_type(nf + 7))) == SDI::npos);

  // a user map that is not a bijection is rejected with the defect named
  put(face_reversed, *faces(mesh).begin(), 0); // index 0 now used twice
  try
  {
    Mesh_indices<test::Surface_mesh> bad(mesh, CGAL::parameters::face_index_map(face_reversed));
    FAIL("no exception");
  }
  catch(const SD::Invalid_mesh& e)
  {
    CHECK(e.defect() == SD::Mesh_defect::invalid_index_map);
    CHECK(std::string(e.what()).find("face index map") != std::string::npos);
  }
}

TEST_CASE("A Surface_mesh with removed elements is rejected until garbage is collected", "[indices]")
{
  test::Surface_mesh mesh = test::load_mesh<test::Surface_mesh>("hemisphere.off");
  CGAL::Euler::remove_face(halfedge(*faces(mesh).begin(), mesh), mesh);
  REQUIRE(mesh.has_garbage());
  try
  {
    Mesh_indices<test::Surface_mesh> idx(mesh);
    FAIL("no exception");
  }
  catch(const SD::Invalid_mesh& e)
  {
    INFO(e.what());
    CHECK(e.defect() == SD::Mesh_defect::invalid_index_map);
    CHECK(std::string(e.what()).find("collect_garbage") != std::string::npos);
  }
  mesh.collect_garbage();
  Mesh_indices<test::Surface_mesh> idx(mesh);
  CHECK_NOTHROW(validate_mesh(idx, get(CGAL::vertex_point, mesh)));
}

TEMPLATE_TEST_CASE("Valid meshes pass validation", "[validation]", SD_MESH_TYPES_WITH_IDS)
{
  for(const std::string name : {"bunny_1k.off", "torus.off", "eight.off", "hemisphere.off",
                                "mech-holes-shark.off", "bones.off", "blobby_3cc.off",
                                "triceratops.off", "elephant-with-holes.off"})
  {
    INFO(name);
    const TestType mesh = test::load_mesh<TestType>(name);
    Mesh_indices<TestType> idx(mesh);
    CHECK_NOTHROW(validate_mesh(idx, get(CGAL::vertex_point, mesh)));
  }
}

TEMPLATE_TEST_CASE("Bad input is rejected with a clear exception", "[validation]", SD_MESH_TYPES_WITH_IDS)
{
  SECTION("empty mesh")
  {
    TestType mesh;
    CHECK(defect_of(mesh) == SD::Mesh_defect::empty);
    add_vertex(mesh);
    CHECK(defect_of(mesh) == SD::Mesh_defect::empty);
  }
  SECTION("non-finite coordinates")
  {
    for(double bad : {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()})
    {
      TestType mesh = test::load_mesh<TestType>("bunny_1k.off");
      Mesh_indices<TestType> idx(mesh);
      put(get(CGAL::vertex_point, mesh), idx.vertex(17), test::Point(0., bad, 1.));
      CHECK(defect_of(mesh) == SD::Mesh_defect::non_finite_coordinates);
      try { validate_mesh(Mesh_indices<TestType>(mesh), get(CGAL::vertex_point, mesh)); }
      catch(const SD::Invalid_mesh& e) { CHECK(e.element() == 17); }
    }
  }
  SECTION("isolated vertex")
  {
    TestType mesh = test::load_mesh<TestType>("bunny_1k.off");
    auto v = add_vertex(mesh);
    put(get(CGAL::vertex_point, mesh), v, test::Point(0, 0, 0));
    CHECK(defect_of(mesh) == SD::Mesh_defect::isolated_vertex);
  }
  SECTION("not a triangle mesh")
  {
    // two quads sharing an edge
    const TestType mesh = build_with_euler<TestType>(
      {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {0, 1, 0}, {1, 1, 0}, {2, 1, 0}}, {{0, 1, 4, 3}, {1, 2, 5, 4}});
    CHECK(defect_of(mesh) == SD::Mesh_defect::not_triangle);
    SD::internal::Validation_options polygons_allowed;
    polygons_allowed.require_triangles = false;
    CHECK_NOTHROW(validate_mesh(Mesh_indices<TestType>(mesh), get(CGAL::vertex_point, mesh),
                                polygons_allowed));
  }
  SECTION("non-manifold vertex")
  {
    // a bow tie: two triangles sharing only vertex 0
    const TestType bowtie = build_with_euler<TestType>(
      {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {-1, 0, 0}, {-1, -1, 0}}, {{0, 1, 2}, {0, 3, 4}});
    CHECK(defect_of(bowtie) == SD::Mesh_defect::non_manifold_vertex);
    // two closed tetrahedra glued at a vertex cannot be built by add_face; a pinched pair of
    // open fans can: four triangles around vertex 0 forming two separate fans
    const TestType pinched = build_with_euler<TestType>(
      {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {-1, 0, 0}, {-1, -1, 0}, {0, -1, 0}},
      {{0, 1, 2}, {0, 2, 3}, {0, 4, 5}, {0, 5, 6}});
    CHECK(defect_of(pinched) == SD::Mesh_defect::non_manifold_vertex);
  }
  SECTION("degenerate faces")
  {
    const TestType collinear = test::load_mesh<TestType>("degtri_four.off");
    CHECK(defect_of(collinear) == SD::Mesh_defect::degenerate_face);
    // coincident vertices
    const TestType coincident = build_with_euler<TestType>(
      {{0, 0, 0}, {1, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}, {0, 2, 3}});
    CHECK(defect_of(coincident) == SD::Mesh_defect::degenerate_face);
    // a sliver that is thin but not degenerate is accepted (scale invariance: tiny mesh)
    const TestType sliver = build_with_euler<TestType>(
      {{0, 0, 0}, {1e-6, 0, 0}, {0.5e-6, 1e-15, 0}}, {{0, 1, 2}});
    CHECK_NOTHROW(validate_mesh(Mesh_indices<TestType>(sliver), get(CGAL::vertex_point, sliver)));
  }
}

TEMPLATE_TEST_CASE("The mesh generators refuse bad sizes with Invalid_parameter", "[validation][generators]", SD_MESH_TYPES_WITH_IDS)
{
  TestType mesh;
  CHECK_THROWS_AS(SD::make_torus(mesh, 2, 8), SD::Invalid_parameter);
  CHECK_THROWS_AS(SD::make_torus(mesh, 8, 8, 0.3, 0.4), SD::Invalid_parameter);
  CHECK_THROWS_AS(SD::make_sphere(mesh, 0), SD::Invalid_parameter);
  CHECK_THROWS_AS(SD::make_grid(mesh, 0, 4), SD::Invalid_parameter);
  CHECK_THROWS_AS(SD::make_grid(mesh, 4, 4, 0.5), SD::Invalid_parameter);
  CHECK_THROWS_AS(SD::make_slab(mesh, 4, 4, 0.), SD::Invalid_parameter);
  CHECK(num_vertices(mesh) == 0); // nothing was built
  SD::make_sphere(mesh, 1);
  CHECK(num_faces(mesh) == 12);
}

TEMPLATE_TEST_CASE("Error messages name the offending element", "[validation]", SD_MESH_TYPES_WITH_IDS)
{
  const TestType mesh = test::load_mesh<TestType>("degtri_four.off");
  try
  {
    validate_mesh(Mesh_indices<TestType>(mesh), get(CGAL::vertex_point, mesh));
    FAIL("no exception");
  }
  catch(const SD::Invalid_mesh& e)
  {
    const std::string what = e.what();
    INFO(what);
    CHECK(what.find("face " + std::to_string(e.element())) != std::string::npos);
    CHECK(what.find("degenerate") != std::string::npos);
  }
}
