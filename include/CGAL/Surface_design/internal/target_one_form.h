// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The target 1-form omega of a per-vertex tangent vector field (Noma & Kawahara, eq. 12).

#ifndef CGAL_SURFACE_DESIGN_INTERNAL_TARGET_ONE_FORM_H
#define CGAL_SURFACE_DESIGN_INTERNAL_TARGET_ONE_FORM_H

#include <CGAL/Surface_design/internal/geometry.h>
#include <CGAL/Surface_design/internal/Mesh_indices.h>
#include <CGAL/Surface_design/internal/vertex_frames.h>

#include <Eigen/Core>

#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Surface_design {

/// \ingroup PkgFieldAlignedParameterizationRef
/// How the target 1-form omega is computed from a per-vertex field X. Both integrate X along each
/// edge e = (i, j), X_i ruling the half of the edge next to i (paper, eq. 12):
/// omega_ij = 1/2 (integral contribution of X_i + that of X_j).
enum class One_form_convention
{
  /// X_i is projected to the tangent plane of vertex i (angle-weighted vertex normal) and
  /// omega_ij = 1/2 <X_i + X_j, p_j - p_i>. Extrinsic, simple, exact on planar meshes.
  projected,
  /// The paper's convention (sec. 4.1, after Knöppel et al. 2015): angles around vertex i are
  /// rescaled by s_i = 2 pi / (angle sum at i) (s_i = 1 on the boundary) so that the vertex star
  /// is flat; with theta_i the rescaled angle of X_i and phi_ij that of the edge leaving i towards
  /// j, omega_ij = l_ij / 2 (|X_i| cos(theta_i - phi_ij) - |X_j| cos(theta_j - phi_ji)): X_j is
  /// integrated along i -> j, i.e. against the direction phi_ji of the edge leaving j. (The paper's
  /// eq. 12 prints "+"; with phi_ji read as the direction j -> i that sign would make the integral
  /// of a constant planar field vanish, so the consistent sign is used.)
  /// A 3D vector is converted to a rescaled angle by locating it, after projection to the
  /// tangent plane, in the wedge of one corner and interpolating linearly inside that corner.
  angle_rescaled
};

namespace internal {

/// Per-vertex field as tangent vectors: projected to the vertex tangent planes and, when
/// `radians_per_unit_length > 0`, normalized to that length (zero vectors stay zero).
template <class Indices, class VertexPointMap, class VertexVectorMap>
std::vector<Eigen::Vector3d> tangent_field(const Indices& idx, const VertexPointMap& vpm,
                                           const VertexVectorMap& field,
                                           double radians_per_unit_length)
{
  const std::vector<Eigen::Vector3d> normal = vertex_normals(idx, vpm);
  std::vector<Eigen::Vector3d> x(idx.number_of_vertices());
  for(std::size_t v = 0; v < x.size(); ++v)
  {
    const auto& f = get(field, idx.vertex(v));
    Eigen::Vector3d xv(CGAL::to_double(f.x()), CGAL::to_double(f.y()), CGAL::to_double(f.z()));
    xv -= xv.dot(normal[v]) * normal[v];
    if(radians_per_unit_length > 0.)
    {
      const double len = xv.norm();
      xv = len > 0. ? Eigen::Vector3d(xv * (radians_per_unit_length / len)) : Eigen::Vector3d::Zero();
    }
    x[v] = xv;
  }
  return x;
}

/// omega per edge (oriented from the smaller to the larger vertex index), projected convention.
template <class Indices, class VertexPointMap>
std::vector<double> projected_one_form(const Indices& idx, const VertexPointMap& vpm,
                                       const std::vector<Eigen::Vector3d>& x)
{
  std::vector<double> omega(idx.number_of_edges());
  for(std::size_t e = 0; e < omega.size(); ++e)
  {
    const auto ij = idx.edge_vertices(e);
    const Eigen::Vector3d d =
      position(vpm, idx.vertex(ij.second)) - position(vpm, idx.vertex(ij.first));
    omega[e] = 0.5 * (x[ij.first] + x[ij.second]).dot(d);
  }
  return omega;
}

/// omega per edge, the paper's angle-rescaled convention (see One_form_convention).
template <class Indices, class VertexPointMap>
std::vector<double> angle_rescaled_one_form(const Indices& idx, const VertexPointMap& vpm,
                                            const std::vector<Eigen::Vector3d>& x)
{
  const auto& tm = idx.mesh();
  const Vertex_frames frames = vertex_frames(idx, vpm, corner_angles(idx, vpm));
  // projection of X_i on edge ij in the rescaled star of i: |X_i| cos(theta_i - phi_ij), stored
  // per outgoing halfedge
  std::vector<double> theta(x.size());
  for(std::size_t v = 0; v < x.size(); ++v)
    theta[v] = frames.to_angle(v, x[v]);
  std::vector<double> along(idx.number_of_halfedges(), 0.);
  for(std::size_t h = 0; h < along.size(); ++h)
  {
    const std::size_t v = idx.source_index(idx.halfedge(h));
    along[h] = x[v].norm() * std::cos(theta[v] - frames.angle[h]);
  }

  const std::vector<double> length = edge_lengths(idx, vpm);
  std::vector<double> omega(idx.number_of_edges());
  for(std::size_t e = 0; e < omega.size(); ++e)
  {
    const auto h = idx.oriented_halfedge(e); // i -> j
    const auto o = opposite(h, tm);          // j -> i
    // X_j contributes along j -> i; the form is oriented i -> j, hence the minus sign
    omega[e] = 0.5 * length[e] * (along[idx.index(h)] - along[idx.index(o)]);
  }
  return omega;
}

} // namespace internal
} // namespace Surface_design
} // namespace CGAL

#endif // CGAL_SURFACE_DESIGN_INTERNAL_TARGET_ONE_FORM_H
