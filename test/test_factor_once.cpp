// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Factor once, solve many: every algorithm factors exactly once and then only back-substitutes,
// counted by a solver traits that counts its calls (not inferred from equal results).

#include <test_support.h>

#include <CGAL/Surface_design/Barycentric_embedder.h>
#include <CGAL/Surface_design/direction_fields.h>
#include <CGAL/Surface_design/Field_aligned_parameterizer.h>
#include <CGAL/Surface_design/mesh_generators.h>
#include <CGAL/Surface_design/octahedron_membrane.h>
#include <CGAL/Surface_design/Trivial_connection.h>

#include <map>
#include <vector>

namespace SD = CGAL::Surface_design;
namespace P = CGAL::Surface_design::parameters;
using test::Counting_solver_traits;

namespace {

template <class Mesh>
using Vector_map = std::map<typename boost::graph_traits<Mesh>::vertex_descriptor, test::Kernel::Vector_3>;

template <class Mesh>
auto constant_field(const Mesh& mesh)
{
  Vector_map<Mesh> field;
  for(auto v : vertices(mesh))
    field[v] = test::Kernel::Vector_3(0.3, 1., 0.2);
  return field;
}

} // namespace

TEMPLATE_TEST_CASE("Stripes: one factorization, one back-substitution per solve", "[factor-once]", SD_MESH_TYPES_WITH_IDS)
{
  TestType mesh;
  SD::make_torus(mesh, 24, 10, 1., 0.35); // genus 1: two automatic generator windings
  Counting_solver_traits solver;
  SD::Field_aligned_parameterizer<TestType, test::Vpm<TestType>, Counting_solver_traits> fap(
    mesh, P::sparse_linear_solver(solver));
  REQUIRE(solver.counts().factorizations == 1);
  REQUIRE(solver.counts().solves == 0);

  auto field = constant_field(mesh);
  fap.set_field(boost::make_assoc_property_map(field), 2.);
  fap.solve();
  // one solve for dalpha, one per automatic winding direction for the harmonic basis (once)
  REQUIRE(solver.counts().solves == 1 + 2);
  const std::size_t faces_n = num_faces(mesh);
  fap.set_index(std::size_t(3), 1);
  fap.set_index(faces_n / 2, -1);
  fap.solve();
  fap.move_singularity(*std::next(faces(mesh).begin(), 3), *std::next(faces(mesh).begin(), 40));
  fap.solve();
  fap.set_loop_winding(0, 2);
  fap.solve(); // a different set of automatic directions: one new basis solve
  REQUIRE(fap.energy_with_windings({2, 0}) >= fap.energy() * (1. - 1e-12));
  REQUIRE(solver.counts().factorizations == 1);
  REQUIRE(solver.counts().solves == 3 + 1 + 1 + (1 + 1) + 1);
}

TEMPLATE_TEST_CASE("Trivial connections: one factorization for any number of edits", "[factor-once]",
                   SD_MESH_TYPES_WITH_IDS)
{
  TestType mesh;
  SD::make_sphere(mesh, 6);
  Counting_solver_traits solver;
  SD::Trivial_connection<TestType, test::Vpm<TestType>, Counting_solver_traits> tc(mesh, P::sparse_linear_solver(solver));
  REQUIRE(solver.counts().factorizations == 1);
  const auto f0 = *faces(mesh).begin(), f1 = *std::next(faces(mesh).begin(), 200),
             f2 = *std::next(faces(mesh).begin(), 300);
  tc.set_index(f0, 1);
  tc.set_index(f1, 1);
  tc.solve();
  tc.move_singularity(f1, f2);
  tc.solve();
  REQUIRE(solver.counts().factorizations == 1);
  REQUIRE(solver.counts().solves == 2); // a sphere has no loops: one back-substitution per solve
}

TEMPLATE_TEST_CASE("Barycentric embedder: update() only back-substitutes", "[factor-once]", SD_MESH_TYPES_WITH_IDS)
{
  TestType mesh;
  const auto loops = SD::make_octahedron_membrane(mesh, 3);
  std::vector<typename boost::graph_traits<TestType>::vertex_descriptor> fixed;
  for(const auto& loop : loops)
    fixed.insert(fixed.end(), loop.begin(), loop.end());
  Counting_solver_traits solver;
  SD::Barycentric_embedder<TestType, typename boost::property_map<TestType, CGAL::vertex_point_t>::type,
                           Counting_solver_traits>
    embedder(mesh, fixed, P::sparse_linear_solver(solver));
  REQUIRE(solver.counts().factorizations == 1);
  for(int step = 0; step < 4; ++step)
    embedder.update();
  REQUIRE(solver.counts().factorizations == 1);
  REQUIRE(solver.counts().solves == 4 * 3); // x, y, z per update
}

TEMPLATE_TEST_CASE("Smoothest field: one factorization, one back-substitution per Lanczos step",
                   "[factor-once]", SD_MESH_TYPES_WITH_IDS)
{
  TestType mesh;
  SD::make_sphere(mesh, 5);
  Counting_solver_traits solver;
  Vector_map<TestType> field;
  const SD::Smoothest_direction_field_result info =
    SD::smoothest_direction_field(mesh, boost::make_assoc_property_map(field), P::sparse_linear_solver(solver));
  REQUIRE(info.converged);
  REQUIRE(info.iterations > 0);
  REQUIRE(solver.counts().factorizations == 1);
  REQUIRE(solver.counts().solves == info.iterations);
}
