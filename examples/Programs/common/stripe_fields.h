// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Vector fields for stripes, shared by the `stripes` program and the editor: vertex normals and
// the heat-method field (gradient of the geodesic distance from a vertex, turned about the normal:
// rings, spokes, spirals). The geodesic distance is computed here by the heat method of Crane,
// Weischedel and Wardetzky (2013) with Eigen, not by CGAL 5.5's Heat_method_3, whose
// Eigen_sparse_matrix swaps an uninitialized bool (undefined behaviour that UBSan stops at).

#ifndef CGAL_SURFACE_DESIGN_EXAMPLE_STRIPE_FIELDS_H
#define CGAL_SURFACE_DESIGN_EXAMPLE_STRIPE_FIELDS_H

#include "program_support.h"

#include <CGAL/Polygon_mesh_processing/compute_normal.h>

#include <Eigen/Geometry>
#include <Eigen/SparseCholesky>

#include <cmath>
#include <stdexcept>
#include <vector>

namespace program {

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

/// The geodesic distance from `source_vertex` on a connected triangle mesh, by the heat method:
/// (M + t L) u = delta_source with t = h^2 (h the mean edge length, M the lumped masses, L the
/// cotangent Laplacian), X = -grad u / |grad u| per face, then L phi = -div X with phi = 0 at the
/// source. The result is the distance up to the method's smoothing (exact gradients are not
/// needed: only the direction of grad phi is used).
inline std::vector<double> heat_geodesic_distance(const Mesh& mesh, Mesh::Vertex_index source_vertex)
{
  const std::size_t nv = num_vertices(mesh), src = std::size_t(source_vertex);
  struct Corner_data
  {
    std::size_t v[3];
    Eigen::Vector3d p[3];
    double cot[3]; // cotangent of the angle at corner i
    Eigen::Vector3d n; // (p1 - p0) x (p2 - p0): twice the area times the unit normal
  };
  std::vector<Corner_data> face_data;
  face_data.reserve(num_faces(mesh));
  std::vector<Eigen::Triplet<double>> laplacian;
  std::vector<double> mass(nv, 0.);
  for(auto f : faces(mesh))
  {
    Corner_data d;
    int k = 0;
    for(auto w : vertices_around_face(halfedge(f, mesh), mesh))
    {
      d.v[k] = std::size_t(w);
      d.p[k] = eigen(mesh.point(w));
      ++k;
    }
    d.n = (d.p[1] - d.p[0]).cross(d.p[2] - d.p[0]);
    const double twice_area = d.n.norm();
    for(int i = 0; i < 3; ++i)
    {
      const int j = (i + 1) % 3, l = (i + 2) % 3;
      d.cot[i] = (d.p[j] - d.p[i]).dot(d.p[l] - d.p[i]) / twice_area;
      const double w = 0.5 * d.cot[i]; // the weight of edge (j, l), opposite corner i
      laplacian.emplace_back(Eigen::Index(d.v[j]), Eigen::Index(d.v[j]), w);
      laplacian.emplace_back(Eigen::Index(d.v[l]), Eigen::Index(d.v[l]), w);
      laplacian.emplace_back(Eigen::Index(d.v[j]), Eigen::Index(d.v[l]), -w);
      laplacian.emplace_back(Eigen::Index(d.v[l]), Eigen::Index(d.v[j]), -w);
      mass[d.v[i]] += twice_area / 6.;
    }
    face_data.push_back(d);
  }
  double h = 0.;
  for(auto e : edges(mesh))
    h += std::sqrt(CGAL::squared_distance(mesh.point(source(halfedge(e, mesh), mesh)),
                                          mesh.point(target(halfedge(e, mesh), mesh))));
  h /= double(num_edges(mesh));
  const Eigen::Index n = Eigen::Index(nv);
  Eigen::SparseMatrix<double> L(n, n);
  L.setFromTriplets(laplacian.begin(), laplacian.end());

  // heat flow for a short time
  Eigen::SparseMatrix<double> A = h * h * L;
  for(std::size_t v = 0; v < nv; ++v)
    A.coeffRef(Eigen::Index(v), Eigen::Index(v)) += mass[v];
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> heat(A);
  Eigen::VectorXd delta = Eigen::VectorXd::Zero(Eigen::Index(nv));
  delta[Eigen::Index(src)] = 1.;
  const Eigen::VectorXd u = heat.solve(delta);

  // the integrated divergence of the normalized flow direction
  Eigen::VectorXd divergence = Eigen::VectorXd::Zero(Eigen::Index(nv));
  for(const Corner_data& d : face_data)
  {
    Eigen::Vector3d grad = Eigen::Vector3d::Zero(); // sum_i u_i (n x e_i) / |n|^2, e_i opposite i
    for(int i = 0; i < 3; ++i)
      grad += u[Eigen::Index(d.v[i])] * d.n.cross(d.p[(i + 2) % 3] - d.p[(i + 1) % 3]);
    const double norm = grad.norm();
    if(!(norm > 0.))
      continue;
    const Eigen::Vector3d X = -grad / norm;
    for(int i = 0; i < 3; ++i)
    {
      const int j = (i + 1) % 3, l = (i + 2) % 3;
      divergence[Eigen::Index(d.v[i])] += 0.5 * (d.cot[l] * (d.p[j] - d.p[i]).dot(X) + d.cot[j] * (d.p[l] - d.p[i]).dot(X));
    }
  }

  // L phi = -div X, phi = 0 at the source (row and column replaced by the identity)
  std::vector<Eigen::Triplet<double>> pinned;
  pinned.reserve(laplacian.size() + 1);
  for(const auto& t : laplacian)
    if(std::size_t(t.row()) != src && std::size_t(t.col()) != src)
      pinned.push_back(t);
  pinned.emplace_back(Eigen::Index(src), Eigen::Index(src), 1.);
  Eigen::SparseMatrix<double> P(n, n);
  P.setFromTriplets(pinned.begin(), pinned.end());
  Eigen::VectorXd rhs = -divergence;
  rhs[Eigen::Index(src)] = 0.;
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> poisson(P);
  const Eigen::VectorXd phi = poisson.solve(rhs);
  if(heat.info() != Eigen::Success || poisson.info() != Eigen::Success || !phi.allFinite())
    throw std::runtime_error("the heat method failed on this mesh (is it connected, without degenerate faces?)");
  return std::vector<double>(phi.data(), phi.data() + phi.size());
}

/// The gradient of the geodesic distance from `source_vertex` (heat_geodesic_distance()), per
/// face, area-averaged to the vertices, then turned by `degrees` about the vertex normals: 0 gives
/// rings around the source, 90 spokes, anything between spirals. `mesh` must be connected.
inline std::vector<Vector> heat_field(const Mesh& mesh, Mesh::Vertex_index source_vertex, double degrees)
{
  const std::vector<double> distance_values = heat_geodesic_distance(mesh, source_vertex);
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

} // namespace program

#endif // CGAL_SURFACE_DESIGN_EXAMPLE_STRIPE_FIELDS_H
