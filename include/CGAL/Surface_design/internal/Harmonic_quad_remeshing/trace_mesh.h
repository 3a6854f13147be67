// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A flat copy of a triangle mesh for walking curves across it: triangles, neighbours across
// every edge, per-face frames, vertex stars and boundary loops.

#ifndef CGAL_SURFACE_DESIGN_INTERNAL_HARMONIC_QUAD_REMESHING_TRACE_MESH_H
#define CGAL_SURFACE_DESIGN_INTERNAL_HARMONIC_QUAD_REMESHING_TRACE_MESH_H

#include <CGAL/Surface_design/internal/Core/geometry.h>
#include <CGAL/Surface_design/internal/Core/Mesh_indices.h>
#include <CGAL/Surface_design/internal/Core/topology.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_design {
namespace internal {
namespace harmonic_quad {

/// Triangle f has corners tri[f][0..2] (counter-clockwise about its normal); its local edge i runs
/// from corner i to corner i+1 (mod 3) and is opposite corner i+2.
struct Trace_mesh
{
  std::vector<Eigen::Vector3d> point;
  std::vector<std::array<std::size_t, 3>> tri;
  std::vector<std::array<std::size_t, 3>> neighbour;  ///< face across local edge i, npos on the boundary
  std::vector<std::array<unsigned char, 3>> neighbour_edge; ///< local index of that edge there
  std::vector<std::array<std::size_t, 3>> edge;       ///< mesh edge index of local edge i
  std::vector<Eigen::Vector3d> normal;                ///< unit face normals
  std::vector<double> area;
  /// grad_lambda[f][i]: gradient of the barycentric coordinate of corner i (constant on f)
  std::vector<std::array<Eigen::Vector3d, 3>> grad_lambda;
  /// star[v]: (face, corner) pairs around vertex v
  std::vector<std::vector<std::pair<std::size_t, unsigned char>>> star;
  std::vector<char> on_boundary;                      ///< vertex flag
  /// boundary loops as vertex cycles, each with the interior on the left of the walk
  std::vector<std::vector<std::size_t>> boundary_loop;
  /// (loop, position) of a boundary vertex, npos elsewhere
  std::vector<std::pair<std::size_t, std::size_t>> boundary_position;
  /// mesh edge -> (face, local edge) of one side
  std::vector<std::pair<std::size_t, unsigned char>> edge_side;

  std::size_t number_of_vertices() const { return point.size(); }
  std::size_t number_of_faces() const { return tri.size(); }

  /// Gradient of the piecewise-linear function with vertex values `u` on face f (from the
  /// differences, so that it is exactly zero where the three values are equal).
  Eigen::Vector3d gradient(std::size_t f, const std::vector<double>& u) const
  {
    const auto& t = tri[f];
    return (u[t[1]] - u[t[0]]) * grad_lambda[f][1] + (u[t[2]] - u[t[0]]) * grad_lambda[f][2];
  }

  /// Barycentric coordinates of p in face f (p projected to its plane, clamped to the face).
  Eigen::Vector3d barycentric(std::size_t f, const Eigen::Vector3d& p) const
  {
    const auto& t = tri[f];
    const Eigen::Vector3d centroid = (point[t[0]] + point[t[1]] + point[t[2]]) / 3.;
    Eigen::Vector3d b;
    for(int i = 0; i < 3; ++i)
      b[i] = (std::max)(0., 1. / 3. + grad_lambda[f][std::size_t(i)].dot(p - centroid));
    return b / b.sum();
  }

  Eigen::Vector3d at(std::size_t f, const Eigen::Vector3d& bary) const
  {
    const auto& t = tri[f];
    return bary[0] * point[t[0]] + bary[1] * point[t[1]] + bary[2] * point[t[2]];
  }
};

template <class Indices, class VertexPointMap>
Trace_mesh make_trace_mesh(const Indices& idx, const VertexPointMap& vpm)
{
  const auto& tm = idx.mesh();
  Trace_mesh m;
  const std::size_t nv = idx.number_of_vertices(), nf = idx.number_of_faces();
  m.point.resize(nv);
  for(std::size_t v = 0; v < nv; ++v)
    m.point[v] = position(vpm, idx.vertex(v));
  m.tri.resize(nf);
  m.neighbour.resize(nf);
  m.neighbour_edge.resize(nf);
  m.edge.resize(nf);
  m.normal.resize(nf);
  m.area.resize(nf);
  m.grad_lambda.resize(nf);
  m.star.assign(nv, {});
  m.edge_side.assign(idx.number_of_edges(), {npos, 0});
  std::vector<std::pair<std::size_t, unsigned char>> side_of_halfedge(idx.number_of_halfedges(), {npos, 0});
  for(std::size_t f = 0; f < nf; ++f)
  {
    auto h = halfedge(idx.face(f), tm);
    for(unsigned char i = 0; i < 3; ++i, h = next(h, tm))
    {
      m.tri[f][i] = idx.source_index(h);
      m.edge[f][i] = idx.edge_index(h);
      side_of_halfedge[idx.index(h)] = {f, i};
      m.edge_side[idx.edge_index(h)] = {f, i};
      m.star[idx.source_index(h)].emplace_back(f, i);
    }
    const Eigen::Vector3d& a = m.point[m.tri[f][0]];
    const Eigen::Vector3d& b = m.point[m.tri[f][1]];
    const Eigen::Vector3d& c = m.point[m.tri[f][2]];
    const Eigen::Vector3d n = (b - a).cross(c - a);
    const double twice_area = n.norm();
    m.area[f] = 0.5 * twice_area;
    m.normal[f] = n / twice_area;
    // grad lambda_i = n x (edge opposite i, counter-clockwise) / (2 A)
    m.grad_lambda[f][0] = m.normal[f].cross(c - b) / twice_area;
    m.grad_lambda[f][1] = m.normal[f].cross(a - c) / twice_area;
    m.grad_lambda[f][2] = m.normal[f].cross(b - a) / twice_area;
  }
  for(std::size_t f = 0; f < nf; ++f)
  {
    auto h = halfedge(idx.face(f), tm);
    for(unsigned char i = 0; i < 3; ++i, h = next(h, tm))
    {
      const auto o = opposite(h, tm);
      m.neighbour[f][i] = npos;
      if(!idx.is_border(o))
      {
        m.neighbour[f][i] = side_of_halfedge[idx.index(o)].first;
        m.neighbour_edge[f][i] = side_of_halfedge[idx.index(o)].second;
      }
    }
  }
  m.on_boundary.assign(nv, 0);
  m.boundary_position.assign(nv, {npos, npos});
  const Boundary_loops loops = boundary_loops(idx);
  for(const auto& loop : loops.loops)
  {
    // border halfedges run with the hole on their left: reverse them so that the interior is
    // on the left
    std::vector<std::size_t> cycle;
    for(auto it = loop.rbegin(); it != loop.rend(); ++it)
      cycle.push_back(idx.target_index(idx.halfedge(*it)));
    for(std::size_t k = 0; k < cycle.size(); ++k)
    {
      m.on_boundary[cycle[k]] = 1;
      m.boundary_position[cycle[k]] = {m.boundary_loop.size(), k};
    }
    m.boundary_loop.push_back(std::move(cycle));
  }
  return m;
}


/// The faces around vertex v between its edge to `from` and the first edge to one of `stops`,
/// swept counter-clockwise (`ccw`) or clockwise, in the mesh's own order around v (which angles
/// in a tangent plane do not give where the surface turns sharply at v), with their corner angles
/// at v, and the face holding the bisector of the sector's angle.
struct Vertex_sector
{
  std::vector<std::pair<std::size_t, unsigned char>> faces; ///< (face, corner of v), from `from`
  std::vector<double> angle;                                ///< corner angle of each at v
  std::size_t end = npos; ///< the vertex of `stops` where the sector ends (npos: none met)
  bool ccw = true;
  std::size_t middle = 0; ///< the face holding the bisector
  double fraction = 0.5;  ///< of its angle before the bisector, from the sweep's side (0.05 to 0.95)
};

inline Vertex_sector vertex_sector(const Trace_mesh& m, std::size_t v, std::size_t from,
                                   const std::array<std::size_t, 2>& stops, bool ccw)
{
  Vertex_sector sector;
  sector.ccw = ccw;
  // the face after (counter-clockwise) or before the edge from v to `from`
  std::size_t f = npos;
  unsigned char corner = 0;
  for(const auto& [g, i] : m.star[v])
    if(m.tri[g][(i + (ccw ? 1 : 2)) % 3] == from)
    {
      f = g;
      corner = i;
    }
  double total = 0.;
  for(std::size_t guard = 0; f != npos && guard < m.star[v].size(); ++guard)
  {
    const std::size_t a = m.tri[f][(corner + 1) % 3], b = m.tri[f][(corner + 2) % 3];
    const Eigen::Vector3d da = m.point[a] - m.point[v], db = m.point[b] - m.point[v];
    sector.faces.emplace_back(f, corner);
    sector.angle.push_back(std::atan2(da.cross(db).norm(), da.dot(db)));
    total += sector.angle.back();
    const std::size_t far = ccw ? b : a; // the edge where the sweep leaves f
    if(far == stops[0] || far == stops[1])
    {
      sector.end = far;
      break;
    }
    const std::size_t edge = ccw ? (corner + 2) % 3 : corner;
    const std::size_t g = m.neighbour[f][edge];
    if(g == npos)
      break;
    // counter-clockwise, f's edge b -> v runs v -> b in g: v is corner e there; clockwise, f's
    // edge v -> a runs a -> v in g: v is corner e + 1
    const unsigned char e = m.neighbour_edge[f][edge];
    f = g;
    corner = (unsigned char)(ccw ? e : (e + 1) % 3);
  }
  if(sector.end == npos)
    return sector;
  double before = 0.;
  for(std::size_t k = 0; k < sector.faces.size(); ++k)
  {
    if(before + sector.angle[k] >= 0.5 * total || k + 1 == sector.faces.size())
    {
      sector.middle = k;
      sector.fraction = sector.angle[k] > 0. ? std::clamp((0.5 * total - before) / sector.angle[k], 0.05, 0.95) : 0.5;
      break;
    }
    before += sector.angle[k];
  }
  return sector;
}

} // namespace harmonic_quad
} // namespace internal
} // namespace Surface_design
} // namespace CGAL

#endif // CGAL_SURFACE_DESIGN_INTERNAL_HARMONIC_QUAD_REMESHING_TRACE_MESH_H
