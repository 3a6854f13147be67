// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Parametric test meshes of any size, for tests, examples and benchmarks.

#ifndef CGAL_SURFACE_DESIGN_MESH_GENERATORS_H
#define CGAL_SURFACE_DESIGN_MESH_GENERATORS_H

#include <CGAL/Surface_design/exceptions.h>
#include <CGAL/Surface_design/internal/Core/angles.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <functional>
#include <map>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_design {

namespace internal {

template <class PolygonMesh>
void soup_to_mesh(const std::vector<std::array<double, 3>>& points,
                  const std::vector<std::array<std::size_t, 3>>& triangles, PolygonMesh& mesh)
{
  using Point = typename boost::property_traits<
    typename boost::property_map<PolygonMesh, CGAL::vertex_point_t>::type>::value_type;
  std::vector<Point> pts;
  pts.reserve(points.size());
  for(const auto& p : points)
    pts.emplace_back(p[0], p[1], p[2]);
  CGAL::clear(mesh);
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(pts, triangles, mesh);
}

} // namespace internal

/// \ingroup PkgSurfaceDesignRef
/// Torus of major radius `R` and minor radius `r` around the z axis, tessellated as a
/// `major_segments` x `minor_segments` grid of quads, each split into two triangles along the same
/// diagonal: 2 * major * minor triangles, genus 1, closed. Vertex (i, j) has index i * minor + j.
/// With `staggered`, every other ring (odd j) is rotated by half a major step and the quads are
/// split accordingly, which gives nearly isosceles triangles: with suitable proportions (e.g.
/// 40 x 12 segments, R = 1, r = 0.3) every angle is acute and every cotangent weight positive.
/// \pre `major_segments >= 3`, `minor_segments >= 3` (even if staggered), `R > r > 0`.
template <class PolygonMesh>
void make_torus(PolygonMesh& mesh, std::size_t major_segments, std::size_t minor_segments,
                double R = 1., double r = 0.4, bool staggered = false)
{
  if(major_segments < 3 || minor_segments < 3 || !(R > r && r > 0) ||
     (staggered && minor_segments % 2 != 0))
    throw Invalid_parameter("major_segments, minor_segments, R, r", "make_torus needs >= 3 segments each way (an even number of "
                                "minor segments if staggered) and R > r > 0");
  constexpr double two_pi = internal::two_pi;
  std::vector<std::array<double, 3>> pts;
  std::vector<std::array<std::size_t, 3>> tris;
  for(std::size_t i = 0; i < major_segments; ++i)
    for(std::size_t j = 0; j < minor_segments; ++j)
    {
      const double shift = staggered && j % 2 == 1 ? 0.5 : 0.;
      const double u = two_pi * (double(i) + shift) / double(major_segments);
      const double v = two_pi * double(j) / double(minor_segments);
      pts.push_back({(R + r * std::cos(v)) * std::cos(u), (R + r * std::cos(v)) * std::sin(u),
                     r * std::sin(v)});
    }
  auto id = [&](std::size_t i, std::size_t j) {
    return (i % major_segments) * minor_segments + (j % minor_segments);
  };
  for(std::size_t i = 0; i < major_segments; ++i)
    for(std::size_t j = 0; j < minor_segments; ++j)
    {
      if(staggered && j % 2 == 0)
      {
        tris.push_back({id(i, j), id(i + 1, j), id(i, j + 1)});
        tris.push_back({id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
      }
      else
      {
        tris.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
        tris.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
      }
    }
  internal::soup_to_mesh(pts, tris, mesh);
}

/// \ingroup PkgSurfaceDesignRef
/// Unit sphere made from a cube whose faces are `n` x `n` grids, projected radially:
/// 12 n^2 triangles, 6 n^2 + 2 vertices, genus 0, closed, all triangles well shaped.
/// \pre `n >= 1`.
template <class PolygonMesh>
void make_sphere(PolygonMesh& mesh, std::size_t n)
{
  if(n < 1)
    throw Invalid_parameter("n", "make_sphere: n must be at least 1");
  std::vector<std::array<double, 3>> pts;
  std::vector<std::array<std::size_t, 3>> tris;
  std::map<std::array<long, 3>, std::size_t> lattice; // shared vertices on cube edges
  const long N = long(n);
  auto vertex = [&](std::array<long, 3> q) {
    auto it = lattice.find(q);
    if(it != lattice.end())
      return it->second;
    // map [0, N]^3 to [-1, 1]^3, then use the area-equalizing tangent warp before projecting
    std::array<double, 3> p;
    for(int k = 0; k < 3; ++k)
      p[k] = std::tan(std::atan(1.) * (2. * double(q[k]) / double(N) - 1.));
    const double len = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
    pts.push_back({p[0] / len, p[1] / len, p[2] / len});
    lattice.emplace(q, pts.size() - 1);
    return pts.size() - 1;
  };
  // each cube face: fixed axis a at value 0 or N, spanned by axes b, c (oriented outward)
  for(int a = 0; a < 3; ++a)
    for(int side = 0; side < 2; ++side)
    {
      const int b = (a + 1) % 3, c = (a + 2) % 3;
      for(long i = 0; i < N; ++i)
        for(long j = 0; j < N; ++j)
        {
          auto corner = [&](long di, long dj) {
            std::array<long, 3> q;
            q[a] = side ? N : 0;
            q[b] = i + di;
            q[c] = j + dj;
            return vertex(q);
          };
          std::size_t v00 = corner(0, 0), v10 = corner(1, 0), v11 = corner(1, 1), v01 = corner(0, 1);
          if(side == 1)
          {
            tris.push_back({v00, v10, v11});
            tris.push_back({v00, v11, v01});
          }
          else
          {
            tris.push_back({v00, v11, v10});
            tris.push_back({v00, v01, v11});
          }
        }
    }
  internal::soup_to_mesh(pts, tris, mesh);
}

namespace internal {

// the triangles of `make_grid` (see there)
inline void grid_soup(std::size_t nx, std::size_t ny, double jitter,
                      const std::function<bool(std::size_t, std::size_t)>& is_hole,
                      std::vector<std::array<double, 3>>& pts, std::vector<std::array<std::size_t, 3>>& tris)
{
  pts.clear();
  tris.clear();
  std::vector<std::size_t> remap((nx + 1) * (ny + 1), std::size_t(-1));
  unsigned long state = 12345u; // linear congruential generator: reproducible on every platform
  auto uniform = [&state]() {
    state = (state * 1103515245u + 12345u) % 2147483648u;
    return double(state) / 2147483648. * 2. - 1.;
  };
  auto id = [&](std::size_t i, std::size_t j) {
    std::size_t& r = remap[j * (nx + 1) + i];
    if(r == std::size_t(-1))
    {
      r = pts.size();
      pts.push_back({double(i) / double(nx), double(j) / double(ny), 0.});
    }
    return r;
  };
  for(std::size_t j = 0; j < ny; ++j)
    for(std::size_t i = 0; i < nx; ++i)
    {
      if(is_hole && is_hole(i, j))
        continue;
      const std::size_t a = id(i, j), b = id(i + 1, j), c = id(i + 1, j + 1), d = id(i, j + 1);
      if((i + j) % 2 == 0)
      {
        tris.push_back({a, b, c});
        tris.push_back({a, c, d});
      }
      else
      {
        tris.push_back({a, b, d});
        tris.push_back({b, c, d});
      }
    }
  if(jitter > 0.)
  {
    // only vertices strictly inside the square: the outer boundary stays a convex square
    for(std::size_t j = 1; j < ny; ++j)
      for(std::size_t i = 1; i < nx; ++i)
      {
        const std::size_t r = remap[j * (nx + 1) + i];
        const double dx = jitter * uniform() / double(nx), dy = jitter * uniform() / double(ny);
        if(r != std::size_t(-1))
        {
          pts[r][0] += dx;
          pts[r][1] += dy;
        }
      }
  }
}

} // namespace internal

/// \ingroup PkgSurfaceDesignRef
/// Planar grid on [0, 1]^2 (z = 0) with `nx` x `ny` square cells, each split into two triangles
/// (alternating diagonals, so that the mesh has no preferred direction). Cells (i, j) for which
/// `is_hole(i, j)` is true are left out, which makes holes (boundary loops); vertices are numbered
/// in the order the cells first use them (row by row), unused ones are dropped. Every interior vertex can be moved
/// in the plane by up to `jitter` cell sizes along each axis (deterministic pseudo-random), which
/// makes obtuse triangles and negative cotangent weights. No triangle can flip for jitter < 1/6;
/// larger values may flip some (check the orientation if it matters).
/// \pre `nx, ny >= 1`, `0 <= jitter < 0.5`.
template <class PolygonMesh>
void make_grid(PolygonMesh& mesh, std::size_t nx, std::size_t ny, double jitter = 0.,
               const std::function<bool(std::size_t, std::size_t)>& is_hole = {})
{
  if(nx < 1 || ny < 1 || !(jitter >= 0. && jitter < 0.5))
    throw Invalid_parameter("nx, ny, jitter", "make_grid needs nx, ny >= 1 and 0 <= jitter < 0.5");
  std::vector<std::array<double, 3>> pts;
  std::vector<std::array<std::size_t, 3>> tris;
  internal::grid_soup(nx, ny, jitter, is_hole, pts, tris);
  internal::soup_to_mesh(pts, tris, mesh);
}

/// \ingroup PkgSurfaceDesignRef
/// The grid of `make_grid` (no jitter) thickened into a closed slab: its top at z = thickness / 2,
/// a mirrored copy at z = -thickness / 2, and a wall of `wall_segments` rows of triangles along
/// every boundary loop, straight for one row, else on a half circle of diameter `thickness`
/// that bulges outwards (into the holes: keep `thickness` below the holes' width). A hole is a group of edge-adjacent hole cells; every hole goes through
/// the slab, so the surface has genus equal to the number of holes. Its mirror symmetry puts the
/// saddles of symmetric functions in pairs at one value. Hole cells must not lie on the border
/// nor meet other hole cells only at a corner (the grid would not be a manifold).
/// \pre `nx, ny >= 1`, `thickness > 0`, `wall_segments >= 1`.
template <class PolygonMesh>
void make_slab(PolygonMesh& mesh, std::size_t nx, std::size_t ny, double thickness,
               const std::function<bool(std::size_t, std::size_t)>& is_hole = {}, std::size_t wall_segments = 1)
{
  if(nx < 1 || ny < 1 || !(thickness > 0. && std::isfinite(thickness)) || wall_segments < 1)
    throw Invalid_parameter("nx, ny, thickness, wall_segments", "make_slab needs nx, ny >= 1, a finite thickness > 0 and wall_segments >= 1");
  auto hole = [&](std::ptrdiff_t i, std::ptrdiff_t j) {
    return i >= 0 && j >= 0 && std::size_t(i) < nx && std::size_t(j) < ny && is_hole &&
           is_hole(std::size_t(i), std::size_t(j));
  };
  for(std::ptrdiff_t j = 0; j < std::ptrdiff_t(ny); ++j)
    for(std::ptrdiff_t i = 0; i < std::ptrdiff_t(nx); ++i)
      if(hole(i, j) && (i == 0 || j == 0 || i + 1 == std::ptrdiff_t(nx) || j + 1 == std::ptrdiff_t(ny)))
        throw Invalid_parameter("is_hole", "make_slab: hole cell (" + std::to_string(i) + ", " + std::to_string(j) +
                                    ") is on the border");
  for(std::ptrdiff_t j = 1; j < std::ptrdiff_t(ny); ++j)
    for(std::ptrdiff_t i = 1; i < std::ptrdiff_t(nx); ++i)
    {
      // the cells around grid vertex (i, j): holes meeting diagonally make it non-manifold
      const bool sw = hole(i - 1, j - 1), se = hole(i, j - 1), ne = hole(i, j), nw = hole(i - 1, j);
      if(sw == ne && se == nw && sw != se)
        throw Invalid_parameter("is_hole", "make_slab: holes meet diagonally at grid vertex (" + std::to_string(i) + ", " +
                                    std::to_string(j) + ")");
    }
  std::vector<std::array<double, 3>> pts;
  std::vector<std::array<std::size_t, 3>> tris;
  internal::grid_soup(nx, ny, 0., is_hole, pts, tris);
  // the layers z_0 = top, ..., z_wall_segments = bottom; interior vertices only on top and bottom
  const std::size_t n = pts.size(), top_triangles = tris.size();
  std::map<std::pair<std::size_t, std::size_t>, int> directed;
  for(const auto& t : tris)
    for(int k = 0; k < 3; ++k)
      ++directed[{t[std::size_t(k)], t[std::size_t((k + 1) % 3)]}];
  std::vector<std::pair<std::size_t, std::size_t>> boundary; // (a, b): a top triangle has a -> b
  for(const auto& [e, count] : directed)
    if(directed.count({e.second, e.first}) == 0)
      boundary.push_back(e);
  std::map<std::pair<std::size_t, std::size_t>, std::size_t> layer_vertex; // (vertex, layer) -> index
  // the outward normal (in the plane) at every boundary vertex: the mean of its two edges'
  std::map<std::size_t, std::array<double, 2>> outward;
  for(const auto& [a, b] : boundary)
  {
    const double dx = pts[b][0] - pts[a][0], dy = pts[b][1] - pts[a][1], l = std::hypot(dx, dy);
    for(std::size_t v : {a, b})
    {
      outward[v][0] += dy / l;
      outward[v][1] -= dx / l;
    }
  }
  for(auto& [v, o] : outward)
  {
    const double l = std::hypot(o[0], o[1]);
    o = {o[0] / l, o[1] / l};
  }
  constexpr double pi = internal::pi;
  auto at = [&](std::size_t v, std::size_t layer) -> std::size_t {
    if(layer == 0)
      return v;
    if(layer == wall_segments)
      return n + v;
    auto [it, inserted] = layer_vertex.emplace(std::make_pair(v, layer), pts.size());
    if(inserted)
    {
      const double angle = pi * double(layer) / double(wall_segments), bulge = 0.5 * thickness * std::sin(angle);
      pts.push_back({pts[v][0] + bulge * outward[v][0], pts[v][1] + bulge * outward[v][1],
                     0.5 * thickness * std::cos(angle)});
    }
    return it->second;
  };
  for(std::size_t v = 0; v < n; ++v)
    pts.push_back({pts[v][0], pts[v][1], -0.5 * thickness});
  for(std::size_t v = 0; v < n; ++v)
    pts[v][2] = 0.5 * thickness;
  for(std::size_t t = 0; t < top_triangles; ++t)
    tris.push_back({n + tris[t][2], n + tris[t][1], n + tris[t][0]});
  for(const auto& [a, b] : boundary)
    for(std::size_t layer = 0; layer < wall_segments; ++layer)
    {
      // the wall quad b_l -> a_l -> a_(l+1) -> b_(l+1) (its edge b -> a is the twin of the top's a -> b)
      const std::size_t a0 = at(a, layer), b0 = at(b, layer), a1 = at(a, layer + 1), b1 = at(b, layer + 1);
      tris.push_back({b0, a0, a1});
      tris.push_back({b0, a1, b1});
    }
  internal::soup_to_mesh(pts, tris, mesh);
}

} // namespace Surface_design
} // namespace CGAL

#endif // CGAL_SURFACE_DESIGN_MESH_GENERATORS_H
