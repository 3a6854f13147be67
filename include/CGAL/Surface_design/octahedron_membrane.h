// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The example surface of the barycentric embedding paper (Imafuji & Ochiai, Fig. 2-5, Table 1):
// an octahedron with circular holes at its vertices.

#ifndef CGAL_SURFACE_DESIGN_OCTAHEDRON_MEMBRANE_H
#define CGAL_SURFACE_DESIGN_OCTAHEDRON_MEMBRANE_H

#include <CGAL/Surface_design/exceptions.h>
#include <CGAL/Surface_design/internal/Core/angles.h>
#include <CGAL/Surface_design/mesh_generators.h>

#include <boost/graph/graph_traits.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <map>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_design {

/// \ingroup PkgBarycentricEmbeddingRef
/// How `make_octahedron_membrane()` places the 4m vertices of a loop on its circle.
enum class Octahedron_loop_placement
{
  equal_angles,     ///< at angles 2 pi t / (4m), t = 0..4m-1, vertex 0 on an octahedron edge
  radial_projection ///< each lattice point of the truncated corner projected radially
};

/// \ingroup PkgBarycentricEmbeddingRef
/// The example surface of Imafuji & Ochiai (Fig. 2-5): an octahedron whose six vertices become
/// circular holes and whose eight faces become hexagons, each triangulated as a regular
/// triangular grid with `m` segments per side (Fig. 4). Faces: 48 m^2 triangles; vertices
/// 24 m^2 + 12 m - 4 (m = 4, 8, 12: 428, 1628, 3596, Table 1); genus 0 with 6 boundary loops of
/// 4m vertices each.
///
/// The loops lie in the planes z = d, z = -d, x = d, y = d, x = -d, y = -d (the paper's L1..L6,
/// `d = center_distance`), on circles of radius `radius` centred on the axes. Vertices are
/// numbered as in the paper (sec. 3.2): loop L1 is vertices 0..4m-1, L2 4m..8m-1, ..., then the
/// free vertices from the top (decreasing z). Each loop runs counter-clockwise seen from outside
/// the surface, starting at its vertex on the octahedron edge towards +x (L1, L2: x; L3, L5: y;
/// L4, L6: z, then around). Free vertices get their lattice positions on the flat faces of the
/// octahedron with vertices at distance `d`: a starting guess only, since the embedding defines
/// their final positions.
///
/// \returns the six loops as vertex descriptors, L1 first
/// \pre `m >= 1`, `0 < radius < center_distance` (larger loops meet their neighbours)
/// \throws Invalid_parameter otherwise
template <class PolygonMesh>
std::array<std::vector<typename boost::graph_traits<PolygonMesh>::vertex_descriptor>, 6>
make_octahedron_membrane(PolygonMesh& mesh, std::size_t m, double radius = 1.,
                         double center_distance = 3.,
                         Octahedron_loop_placement placement = Octahedron_loop_placement::equal_angles)
{
  if(m < 1)
    throw Invalid_parameter("m", "must be at least 1, got 0");
  if(!(center_distance > 0.) || !std::isfinite(center_distance))
    throw Invalid_parameter("center_distance", "must be a finite number > 0");
  // Loops L1 (plane z = d) and L3 (plane x = d) meet at (d, +-sqrt(R^2 - d^2), d) when R >= d:
  // the loops are disjoint, each inside its face of the cube [-d, d]^3, exactly when R < d.
  if(!(radius > 0. && radius < center_distance))
    throw Invalid_parameter("radius", "must lie in (0, center_distance) = (0, " + std::to_string(center_distance) +
                                        "): loops of radius >= center_distance meet their neighbours");
  const long M = long(m);
  using Key = std::array<long, 3>; // lattice point: d / (3m) times this is its flat position
  // the loops: axis and side of L1..L6 (paper, sec. 3.2)
  const std::array<std::pair<int, long>, 6> loop_axis{
    {{2, 1}, {2, -1}, {0, 1}, {1, 1}, {0, -1}, {1, -1}}};
  std::map<Key, std::size_t> index;
  std::vector<std::array<double, 3>> pts;
  for(const auto& [a, side] : loop_axis)
  {
    // frame (b, c) of the loop's plane, with e_b x e_c = the outward normal side * e_a
    int b = (a + 1) % 3, c = (a + 2) % 3;
    if(side < 0)
      std::swap(b, c);
    const long start[4][2] = {{M, 0}, {0, M}, {-M, 0}, {0, -M}};
    const long step[4][2] = {{-1, 1}, {-1, -1}, {1, -1}, {1, 1}};
    for(long t = 0; t < 4 * M; ++t)
    {
      const long q = t / M, r = t % M;
      Key k{0, 0, 0};
      k[a] = side * 2 * M;
      k[b] = start[q][0] + r * step[q][0];
      k[c] = start[q][1] + r * step[q][1];
      const double angle = placement == Octahedron_loop_placement::equal_angles
                             ? internal::two_pi * double(t) / double(4 * M)
                             : std::atan2(double(k[c]), double(k[b]));
      std::array<double, 3> p{0., 0., 0.};
      p[a] = double(side) * center_distance;
      p[b] = radius * std::cos(angle);
      p[c] = radius * std::sin(angle);
      index.emplace(k, pts.size());
      pts.push_back(p);
    }
  }
  // the hexagons: face (sx, sy, sz) of the octahedron, lattice points (i, j, k), i + j + k = 3m,
  // at (sx i, sy j, sz k); the corners i, j or k > 2m are cut off
  std::vector<std::array<Key, 3>> keyed_triangles;
  std::vector<Key> free_keys;
  for(long sx = -1; sx <= 1; sx += 2)
    for(long sy = -1; sy <= 1; sy += 2)
      for(long sz = -1; sz <= 1; sz += 2)
      {
        auto key = [&](long i, long j) { return Key{sx * i, sy * j, sz * (3 * M - i - j)}; };
        auto kept = [&](long i, long j) {
          const long k = 3 * M - i - j;
          return i <= 2 * M && j <= 2 * M && k >= 0 && k <= 2 * M;
        };
        auto add = [&](Key p, Key q, Key r) {
          if(sx * sy * sz < 0) // keep the normals outward
            std::swap(q, r);
          keyed_triangles.push_back({p, q, r});
        };
        for(long i = 0; i < 3 * M; ++i)
          for(long j = 0; i + j < 3 * M; ++j)
          {
            if(kept(i, j) && kept(i + 1, j) && kept(i, j + 1))
              add(key(i, j), key(i + 1, j), key(i, j + 1));
            if(i + j + 2 <= 3 * M && kept(i + 1, j) && kept(i + 1, j + 1) && kept(i, j + 1))
              add(key(i + 1, j), key(i + 1, j + 1), key(i, j + 1));
          }
        for(long i = 0; i <= 3 * M; ++i)
          for(long j = 0; i + j <= 3 * M; ++j)
            if(kept(i, j) && index.find(key(i, j)) == index.end())
              free_keys.push_back(key(i, j));
      }
  // free vertices from the top: decreasing z, then y, then x
  std::sort(free_keys.begin(), free_keys.end(), [](const Key& p, const Key& q) {
    return std::make_tuple(-p[2], -p[1], -p[0]) < std::make_tuple(-q[2], -q[1], -q[0]);
  });
  free_keys.erase(std::unique(free_keys.begin(), free_keys.end()), free_keys.end());
  const double scale = center_distance / double(3 * M);
  for(const Key& k : free_keys)
  {
    index.emplace(k, pts.size());
    pts.push_back({scale * double(k[0]), scale * double(k[1]), scale * double(k[2])});
  }
  std::vector<std::array<std::size_t, 3>> tris;
  tris.reserve(keyed_triangles.size());
  for(const auto& t : keyed_triangles)
    tris.push_back({index.at(t[0]), index.at(t[1]), index.at(t[2])});
  internal::soup_to_mesh(pts, tris, mesh);

  // polygon_soup_to_polygon_mesh adds the vertices in the order of the points (all are used)
  using vertex_descriptor = typename boost::graph_traits<PolygonMesh>::vertex_descriptor;
  std::vector<vertex_descriptor> vertex_of_point;
  vertex_of_point.reserve(pts.size());
  for(vertex_descriptor v : vertices(mesh))
    vertex_of_point.push_back(v);
  if(vertex_of_point.size() != pts.size())
    throw Internal_error("make_octahedron_membrane: the mesh has " +
                           std::to_string(vertex_of_point.size()) + " vertices instead of " +
                           std::to_string(pts.size()));
  std::array<std::vector<vertex_descriptor>, 6> loops;
  for(std::size_t l = 0; l < 6; ++l)
    loops[l].assign(vertex_of_point.begin() + std::ptrdiff_t(l * 4 * m),
                    vertex_of_point.begin() + std::ptrdiff_t((l + 1) * 4 * m));
  return loops;
}

} // namespace Surface_design
} // namespace CGAL

#endif // CGAL_SURFACE_DESIGN_OCTAHEDRON_MEMBRANE_H
