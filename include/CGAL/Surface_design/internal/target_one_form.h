// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The target 1-form omega of a per-vertex tangent vector field (Noma & Kawahara, eq. 12).

#ifndef CGAL_SURFACE_DESIGN_INTERNAL_TARGET_ONE_FORM_H
#define CGAL_SURFACE_DESIGN_INTERNAL_TARGET_ONE_FORM_H

#include <CGAL/Surface_design/internal/geometry.h>
#include <CGAL/Surface_design/internal/Mesh_indices.h>

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
  const double two_pi = 2. * std::acos(-1.);
  const std::vector<double> corner = corner_angles(idx, vpm);
  const std::vector<Eigen::Vector3d> normal = vertex_normals(idx, vpm);
  // projection of X_i on edge ij in the rescaled star of i: |X_i| cos(theta_i - phi_ij), stored
  // per outgoing halfedge
  std::vector<double> along(idx.number_of_halfedges(), 0.);

  for(std::size_t v = 0; v < idx.number_of_vertices(); ++v)
  {
    const auto vd = idx.vertex(v);
    // outgoing halfedges in counter-clockwise order, starting after the boundary gap if any
    auto start = opposite(halfedge(vd, tm), tm); // an outgoing halfedge
    for(auto h : halfedges_around_source(vd, tm))
      if(idx.is_border(opposite(h, tm)))
        start = h;
    std::vector<std::size_t> out;
    std::vector<double> wedge; // corner angle between out[k] and out[k+1]; -1 for the gap
    auto h = start;
    do
    {
      out.push_back(idx.index(h));
      wedge.push_back(idx.is_border(h) ? -1. : corner[idx.index(prev(h, tm))]);
      h = opposite(prev(h, tm), tm);
    } while(h != start);

    const bool border = wedge.back() < 0.;
    double angle_sum = 0.;
    for(double w : wedge)
      angle_sum += (std::max)(w, 0.);
    const double s = border ? 1. : two_pi / angle_sum;

    // rescaled angle of every outgoing edge, from the first one
    std::vector<double> phi(out.size(), 0.);
    for(std::size_t k = 1; k < out.size(); ++k)
      phi[k] = phi[k - 1] + s * wedge[k - 1];
    const double gap = border ? two_pi - s * angle_sum : 0.; // the boundary gap takes the rest

    const double magnitude = x[v].norm();
    if(magnitude == 0.)
      continue;
    // tangent-plane polar angles of the edges and of X, measured from the first edge
    const Eigen::Vector3d n = normal[v];
    auto planar = [&](const Eigen::Vector3d& d) { return Eigen::Vector3d(d - d.dot(n) * n); };
    const Eigen::Vector3d p = position(vpm, vd);
    const Eigen::Vector3d e0 = planar(position(vpm, target(idx.halfedge(out[0]), tm)) - p).normalized();
    const Eigen::Vector3d e1 = n.cross(e0);
    auto polar = [&](const Eigen::Vector3d& d) {
      double a = std::atan2(d.dot(e1), d.dot(e0));
      return a < 0. ? a + two_pi : a;
    };
    std::vector<double> psi(out.size() + 1);
    for(std::size_t k = 0; k < out.size(); ++k)
      psi[k] = k == 0 ? 0. : polar(planar(position(vpm, target(idx.halfedge(out[k]), tm)) - p));
    psi[out.size()] = two_pi;
    const double psi_x = polar(x[v]);
    // locate X in a wedge [psi_k, psi_k+1] and interpolate the rescaled angle there; if the
    // projected star is not monotone (strongly folded vertex), fall back to the nearest edge
    double theta = 0.;
    bool located = false;
    for(std::size_t k = 0; k < out.size() && !located; ++k)
    {
      const double a = psi[k], b = psi[k + 1];
      if(b > a && psi_x >= a && psi_x <= b)
      {
        const double span = (k + 1 < out.size() || !border) ? s * (std::max)(wedge[k], 0.) : gap;
        theta = phi[k] + (psi_x - a) / (b - a) * span;
        located = true;
      }
    }
    if(!located)
    {
      double best = two_pi;
      for(std::size_t k = 0; k < out.size(); ++k)
      {
        double d = std::abs(psi_x - psi[k]);
        d = (std::min)(d, two_pi - d);
        if(d < best)
        {
          best = d;
          theta = phi[k];
        }
      }
    }
    for(std::size_t k = 0; k < out.size(); ++k)
      along[out[k]] = magnitude * std::cos(theta - phi[k]);
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
