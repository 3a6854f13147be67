// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The operators of vertex-based n-direction fields: the Hermitian connection Laplacian, principal
// curvature directions, conversion between field vectors and frame angles, and the singularity
// index of a field in every face.

#ifndef CGAL_SURFACE_DESIGN_INTERNAL_DIRECTION_FIELDS_DIRECTION_FIELD_OPERATORS_H
#define CGAL_SURFACE_DESIGN_INTERNAL_DIRECTION_FIELDS_DIRECTION_FIELD_OPERATORS_H

#include <CGAL/Surface_design/exceptions.h>
#include <CGAL/Surface_design/internal/Core/angles.h>
#include <CGAL/Surface_design/internal/Core/dec.h>
#include <CGAL/Surface_design/internal/Core/discrete_connection.h>
#include <CGAL/Surface_design/internal/Core/geometry.h>
#include <CGAL/Surface_design/internal/Solvers/Hermitian_system.h>
#include <CGAL/Surface_design/internal/Core/vertex_frames.h>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <cmath>
#include <complex>
#include <cstddef>
#include <string>
#include <vector>

namespace CGAL {
namespace Surface_design {
namespace internal {

/// The connection Laplacian of n-direction fields, the Hermitian |V| x |V| matrix A of
///   E(u) = u^H A u = sum_edges w_ij |u_j - r_ij^n u_i|^2,  r_ij = exp(i rho_ij),
/// with w the given edge weights (cotangent weights: the Dirichlet energy of the field):
/// A_ii = sum_j w_ij, A_ji = -w_ij r_ij^n, A_ij = conj(A_ji).
template <class Indices>
Complex_sparse_matrix complex_connection_laplacian(const Indices& idx, const Discrete_connection& c,
                                                   const std::vector<double>& weight, int n)
{
  std::vector<double> diagonal(idx.number_of_vertices(), 0.);
  for(std::size_t e = 0; e < idx.number_of_edges(); ++e)
  {
    const auto ij = idx.edge_vertices(e);
    diagonal[ij.first] += weight[e];
    diagonal[ij.second] += weight[e];
  }
  // entry (source(h), target(h)) for h = i -> j: A_ij = conj(A_ji) = -w exp(-i n transport(h))
  return assemble_vertex_matrix<std::complex<double>>(
    idx,
    [&](std::size_t h) {
      return -weight[idx.edge_index(idx.halfedge(h))] * std::polar(1., -n * c.transport(idx, h));
    },
    [&](std::size_t v) { return std::complex<double>(diagonal[v]); });
}

/// The same as a real symmetric matrix of size 2|V| (unknowns Re u_v, Im u_v interleaved).
template <class Indices>
Sparse_matrix connection_laplacian(const Indices& idx, const Discrete_connection& c,
                                   const std::vector<double>& weight, int n)
{
  return realify(complex_connection_laplacian(idx, c, weight, n));
}

/// The traceless part of the shape operator at every vertex as a complex number in the vertex
/// frame, of doubled angle: -sum over the edges ij at i of (beta_ij l_ij / 2) exp(2 i phi_ij), with
/// beta the signed dihedral angle (positive where the surface is convex for the face orientation).
/// Its argument / 2 is the direction of the larger principal curvature (Cohen-Steiner & Morvan's
/// edge-based curvature tensor: an edge bends the surface across itself).
template <class Indices, class VertexPointMap>
std::vector<std::complex<double>> principal_curvature_directions(const Indices& idx, const VertexPointMap& vpm,
                                                                 const Discrete_connection& c)
{
  const auto& tm = idx.mesh();
  const std::vector<Eigen::Vector3d> fn = face_normals(idx, vpm);
  std::vector<std::complex<double>> q(idx.number_of_vertices(), 0.);
  for(std::size_t e = 0; e < idx.number_of_edges(); ++e)
  {
    const auto h = idx.oriented_halfedge(e), o = opposite(h, tm);
    if(idx.is_border(h) || idx.is_border(o))
      continue;
    const Eigen::Vector3d d = position(vpm, target(h, tm)) - position(vpm, source(h, tm));
    const Eigen::Vector3d& n1 = fn[idx.index(face(h, tm))];
    const Eigen::Vector3d& n2 = fn[idx.index(face(o, tm))];
    const double beta = std::atan2(n1.cross(n2).dot(d.normalized()), n1.dot(n2));
    const double weight = -0.5 * beta * d.norm();
    q[idx.source_index(h)] += weight * std::polar(1., 2. * c.frames.angle[idx.index(h)]);
    q[idx.source_index(o)] += weight * std::polar(1., 2. * c.frames.angle[idx.index(o)]);
  }
  return q;
}

/// Writes, per vertex, the direction of angle `angle[v]` (rescaled, in the vertex frame) scaled
/// by `magnitude[v]` (unit when `magnitude` is empty).
template <class Indices, class VertexVectorMap>
void write_field(const Indices& idx, const Vertex_frames& frames, const std::vector<double>& angle,
                 const std::vector<double>& magnitude, VertexVectorMap out)
{
  using Vector = typename boost::property_traits<VertexVectorMap>::value_type;
  for(std::size_t v = 0; v < angle.size(); ++v)
  {
    const Eigen::Vector3d x = (magnitude.empty() ? 1. : magnitude[v]) * frames.to_vector(v, angle[v]);
    put(out, idx.vertex(v), Vector(x.x(), x.y(), x.z()));
  }
}

inline void check_symmetry_order(int n)
{
  if(n < 1)
    throw Invalid_parameter("symmetry_order", "the symmetry order n of a direction field must be at least 1 "
                                              "(1: vector field, 2: line field, 4: cross field), got " +
                                                std::to_string(n));
}

} // namespace internal
} // namespace Surface_design
} // namespace CGAL

#endif // CGAL_SURFACE_DESIGN_INTERNAL_DIRECTION_FIELDS_DIRECTION_FIELD_OPERATORS_H
