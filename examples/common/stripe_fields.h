// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Vector fields for stripes, shared by the `stripes` program and the editor: vertex normals and
// the heat-method field (gradient of the geodesic distance from a vertex, turned about the normal:
// rings, spokes, spirals).

#ifndef CGAL_SURFACE_DESIGN_EXAMPLE_STRIPE_FIELDS_H
#define CGAL_SURFACE_DESIGN_EXAMPLE_STRIPE_FIELDS_H

#include "example_support.h"

#include <CGAL/Heat_method_3/Surface_mesh_geodesic_distances_3.h>
#include <CGAL/Polygon_mesh_processing/compute_normal.h>

#include <Eigen/Geometry>

#include <cmath>
#include <vector>

namespace example {

inline Eigen::Vector3d eigen(const Point& p) { return Eigen::Vector3d(p.x(), p.y(), p.z()); }

/// Unit vertex normals (CGAL's default weighting), indexed by vertex.
inline std::vector<Eigen::Vector3d> vertex_normals(const Mesh& mesh)
{
  std::vector<Eigen::Vector3d> normal;
  for(auto v : vertices(mesh))
  {
    const Vector n = CGAL::Polygon_mesh_processing::compute_vertex_normal(v, mesh);
    normal.emplace_back(n.x(), n.y(), n.z());
  }
  return normal;
}

/// The gradient of the geodesic distance from `source_vertex` (CGAL Heat_method_3), per face,
/// area-averaged to the vertices, then turned by `degrees` about the vertex normals: 0 gives
/// rings around the source, 90 spokes, anything between spirals. `mesh` must be connected (the
/// distance is infinite on other components).
inline std::vector<Vector> heat_field(const Mesh& mesh, Mesh::Vertex_index source_vertex, double degrees)
{
  std::vector<double> distance_values(num_vertices(mesh), 0.);
  auto distance = CGAL::make_property_map(distance_values);
  CGAL::Heat_method_3::estimate_geodesic_distances(mesh, distance, source_vertex);
  const std::vector<Eigen::Vector3d> normal = vertex_normals(mesh);
  std::vector<Eigen::Vector3d> g(num_vertices(mesh), Eigen::Vector3d::Zero());
  for(auto f : faces(mesh))
  {
    Eigen::Vector3d p[3];
    double d[3];
    Mesh::Vertex_index vs[3];
    int k = 0;
    for(auto w : vertices_around_face(halfedge(f, mesh), mesh))
    {
      vs[k] = w;
      p[k] = eigen(mesh.point(w));
      d[k] = distance_values[std::size_t(w)];
      ++k;
    }
    const Eigen::Vector3d n = (p[1] - p[0]).cross(p[2] - p[0]);
    const double area2 = n.squaredNorm();
    // grad d = sum_i d_i (N x e_i) / (2A), e_i the edge opposite vertex i
    Eigen::Vector3d grad = Eigen::Vector3d::Zero();
    for(int i = 0; i < 3; ++i)
      grad += d[i] * n.cross(p[(i + 2) % 3] - p[(i + 1) % 3]);
    grad /= area2;
    for(int i = 0; i < 3; ++i)
      g[std::size_t(vs[i])] += std::sqrt(area2) * grad;
  }
  const double theta = degrees * CGAL_PI / 180.;
  std::vector<Vector> field;
  field.reserve(g.size());
  for(std::size_t i = 0; i < g.size(); ++i)
  {
    const Eigen::Vector3d r = std::cos(theta) * g[i] + std::sin(theta) * normal[i].cross(g[i]);
    field.emplace_back(r.x(), r.y(), r.z());
  }
  return field;
}

} // namespace example

#endif // CGAL_SURFACE_DESIGN_EXAMPLE_STRIPE_FIELDS_H
