// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Shared test helpers: the mesh types every test runs on, mesh loading, snapshots to prove that a
// failed call left the mesh untouched.

#ifndef CGAL_SURFACE_DESIGN_TEST_SUPPORT_H
#define CGAL_SURFACE_DESIGN_TEST_SUPPORT_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Polyhedron_items_with_id_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/Surface_design/mesh_generators.h>
#include <CGAL/Surface_design/solver_traits.h>

#include <catch2/catch.hpp>

#include "../../examples/Programs/common/configured_paths.h"

#include <array>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <map>
#include <memory>
#include <fstream>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace test {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Surface_mesh = CGAL::Surface_mesh<Point>;
using Polyhedron = CGAL::Polyhedron_3<Kernel>;
using Polyhedron_with_id = CGAL::Polyhedron_3<Kernel, CGAL::Polyhedron_items_with_id_3>;

// Every generic test runs on CGAL's two halfedge data structures. The mesh core's tests (index
// maps, validation, geometry and DEC, topology, factor-once classes) also run on Polyhedron_3 with
// internal ids, where CGAL's index maps read the items' ids instead of dynamic maps: the packages
// get their index maps from there, and a third type in every package's tests cost about a tenth of
// their compile time under the sanitizers (test_field_aligned_parameterization: 182 s against 163).
#define SD_MESH_TYPES test::Surface_mesh, test::Polyhedron
#define SD_MESH_TYPES_WITH_IDS test::Surface_mesh, test::Polyhedron, test::Polyhedron_with_id

/// Expands F(Traits, "label") for every sparse solver of the build.
#if defined(CGAL_SURFACE_DESIGN_HAS_CHOLMOD)
#define SD_FOR_EACH_SOLVER(F)                                                                      \
  F(CGAL::Surface_design::Default_solver_traits, "ldlt")                                           \
  F(CGAL::Surface_design::Cholmod_solver_traits, "cholmod")
#else
#define SD_FOR_EACH_SOLVER(F) F(CGAL::Surface_design::Default_solver_traits, "ldlt")
#endif

/// A model of `SparseLinearAlgebraWithFactorTraits_d` that counts the factorizations and the
/// solves it performs (around Eigen's SimplicialLDLT). Copies share the counts, as copies of
/// CGAL's Eigen traits share their factorization. Not one of the library's own traits: the
/// direction fields factor their Hermitian systems in the real form with it.
class Counting_solver_traits
{
  using Base = CGAL::Surface_design::Default_solver_traits;

public:
  using Matrix = Base::Matrix;
  using Vector = Base::Vector;
  using NT = Base::NT;

  struct Counts
  {
    std::size_t factorizations = 0, solves = 0;
  };

  Counting_solver_traits() : m_counts(std::make_shared<Counts>()) {}

  bool factor(const Matrix& A, NT& D)
  {
    ++m_counts->factorizations;
    return m_base.factor(A, D);
  }
  bool linear_solver(const Vector& B, Vector& X)
  {
    ++m_counts->solves;
    return m_base.linear_solver(B, X);
  }
  bool linear_solver(const Matrix& A, const Vector& B, Vector& X, NT& D)
  {
    ++m_counts->factorizations;
    ++m_counts->solves;
    return m_base.linear_solver(A, B, X, D);
  }

  const Counts& counts() const { return *m_counts; }

private:
  Base m_base;
  std::shared_ptr<Counts> m_counts;
};

/// Fails if CHOLMOD was required for this build (CMake option
/// CGAL_SURFACE_DESIGN_REQUIRE_CHOLMOD, set by scripts/test.sh, which installs it), else warns
/// that the cross-check `what` was skipped.
#define SD_CHOLMOD_UNAVAILABLE(what)                                                               \
  do                                                                                               \
  {                                                                                                \
    if(CGAL_SURFACE_DESIGN_TESTS_REQUIRE_CHOLMOD)                                                  \
      FAIL("CHOLMOD is required for this build but not available: " << what);                      \
    else                                                                                           \
      WARN("CHOLMOD is not available: skipped " << what);                                          \
  } while(false)

using Soup_points = std::vector<std::array<double, 3>>;
using Soup_triangles = std::vector<std::array<std::size_t, 3>>;

/// A triangle mesh of any type from a soup (checked: a valid polygon mesh with every triangle).
template <class Mesh>
Mesh from_soup(const Soup_points& points, const Soup_triangles& triangles)
{
  Mesh mesh;
  CGAL::Surface_design::internal::soup_to_mesh(points, triangles, mesh);
  REQUIRE(CGAL::is_valid_polygon_mesh(mesh));
  REQUIRE(num_faces(mesh) == triangles.size());
  return mesh;
}

/// A prism cylinder of radius 1 (n sides, m rings of quads split into triangles with alternating
/// diagonals) or a cone (radii shrinking to half), from z = 0 to z = `height`, open at both ends;
/// `seam`: the first column is duplicated, i.e. the surface is already cut along a ruling.
inline void ruled_soup(std::size_t n, std::size_t m, bool cone, bool seam, Soup_points& points,
                       Soup_triangles& triangles, double height = 1.5)
{
  points.clear();
  triangles.clear();
  const std::size_t columns = seam ? n + 1 : n;
  for(std::size_t j = 0; j <= m; ++j)
    for(std::size_t i = 0; i < columns; ++i)
    {
      const double t = double(j) / double(m), theta = 2. * 3.14159265358979323846 * double(i) / double(n);
      const double r = cone ? 1. - 0.5 * t : 1.;
      points.push_back({r * std::cos(theta), r * std::sin(theta), height * t});
    }
  auto id = [&](std::size_t i, std::size_t j) { return j * columns + (seam ? i : i % n); };
  for(std::size_t j = 0; j < m; ++j)
    for(std::size_t i = 0; i < n; ++i)
    {
      const std::size_t a = id(i, j), b = id(i + 1, j), c = id(i + 1, j + 1), d = id(i, j + 1);
      if((i + j) % 2 == 0)
      {
        triangles.push_back({a, b, c});
        triangles.push_back({a, c, d});
      }
      else
      {
        triangles.push_back({a, b, d});
        triangles.push_back({b, c, d});
      }
    }
}

/// The mesh's own (read-only) vertex point map type.
template <class Mesh>
using Vpm = typename boost::property_map<Mesh, CGAL::vertex_point_t>::const_type;

/// Path of a mesh bundled with the project (data/; the folder comes from configured_paths.txt
/// beside the test program, or the environment variable CGAL_SURFACE_DESIGN_DATA_DIR).
inline std::string data_path(const std::string& name)
{
  const std::string dir = program::configured_path("CGAL_SURFACE_DESIGN_DATA_DIR");
  if(dir.empty())
    throw std::runtime_error("the folder of the bundled meshes is unknown: set CGAL_SURFACE_DESIGN_DATA_DIR "
                             "(CMake writes it to configured_paths.txt beside the test programs)");
  return dir + "/" + name;
}

/// Path of a larger mesh from ../shared/data/meshes (or CGAL_SURFACE_DESIGN_SHARED_MESH_DIR), or
/// nothing when that folder is absent.
inline std::optional<std::string> shared_mesh_path(const std::string& name)
{
  const std::string path = program::configured_path("CGAL_SURFACE_DESIGN_SHARED_MESH_DIR") + "/" + name;
  if(std::ifstream(path).good())
    return path;
  return std::nullopt;
}

template <class Mesh>
Mesh load_mesh_file(const std::string& path)
{
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(path, mesh) || CGAL::is_empty(mesh))
    throw std::runtime_error("cannot read mesh " + path);
  return mesh;
}

/// Loads a bundled mesh (vertices and faces keep the file's order).
template <class Mesh>
Mesh load_mesh(const std::string& name)
{
  return load_mesh_file<Mesh>(data_path(name));
}

/// Everything a user can observe of a mesh: positions and faces (as vertex sequences), in
/// iteration order. Two snapshots are equal iff the mesh was not modified.
struct Mesh_snapshot
{
  std::vector<double> coordinates;
  std::vector<std::vector<std::size_t>> faces;

  template <class Mesh>
  explicit Mesh_snapshot(const Mesh& mesh)
  {
    std::map<typename boost::graph_traits<Mesh>::vertex_descriptor, std::size_t> id;
    for(auto v : vertices(mesh))
    {
      id.emplace(v, id.size());
      const auto& p = get(CGAL::vertex_point, mesh, v);
      coordinates.insert(coordinates.end(), {p.x(), p.y(), p.z()});
    }
    for(auto f : CGAL::faces(mesh))
    {
      faces.emplace_back();
      for(auto v : vertices_around_face(halfedge(f, mesh), mesh))
        faces.back().push_back(id.at(v));
    }
  }

  bool operator==(const Mesh_snapshot& other) const
  {
    // bitwise comparison of coordinates (NaN-safe): untouched means identical bits
    if(coordinates.size() != other.coordinates.size() || faces != other.faces)
      return false;
    return coordinates.empty() || std::memcmp(coordinates.data(), other.coordinates.data(),
                                              coordinates.size() * sizeof(double)) == 0;
  }
};

} // namespace test

#endif // CGAL_SURFACE_DESIGN_TEST_SUPPORT_H
