// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The target 1-form omega of a per-vertex tangent vector field (Noma & Kawahara, eq. 12).

#ifndef CGAL_SURFACE_DESIGN_INTERNAL_FIELD_ALIGNED_PARAMETERIZATION_TARGET_ONE_FORM_H
#define CGAL_SURFACE_DESIGN_INTERNAL_FIELD_ALIGNED_PARAMETERIZATION_TARGET_ONE_FORM_H

#include <CGAL/Surface_design/exceptions.h>
#include <CGAL/Surface_design/internal/Core/geometry.h>
#include <CGAL/Surface_design/internal/Core/Mesh_indices.h>
#include <CGAL/Surface_design/internal/Core/topology.h>
#include <CGAL/Surface_design/internal/Core/vertex_frames.h>

#include <Eigen/Core>

#include <cmath>
#include <cstddef>
#include <sstream>
#include <string>
#include <vector>

namespace CGAL {
namespace Surface_design {

namespace internal {

/// Per-vertex field as tangent vectors: projected to the vertex tangent planes and, when
/// `radians_per_unit_length > 0`, normalized to that length (vectors that project to zero stay
/// zero: a field may vanish at isolated vertices, e.g. a constant direction at the poles).
/// \throws Invalid_parameter (`field`) if a vector is not finite, or if the field is to be
///         normalized and vanishes at every vertex of a connected component (it gives no
///         direction there)
template <class Indices, class VertexPointMap, class VertexVectorMap>
std::vector<Eigen::Vector3d> tangent_field(const Indices& idx, const VertexPointMap& vpm,
                                           const VertexVectorMap& field, double radians_per_unit_length,
                                           const Components& components)
{
  const std::vector<Eigen::Vector3d> normal = vertex_normals(idx, vpm);
  std::vector<Eigen::Vector3d> x(idx.number_of_vertices());
  std::vector<bool> has_direction(components.size(), false);
  for(std::size_t v = 0; v < x.size(); ++v)
  {
    const auto& f = get(field, idx.vertex(v));
    const Eigen::Vector3d input(CGAL::to_double(f.x()), CGAL::to_double(f.y()), CGAL::to_double(f.z()));
    if(!input.allFinite())
    {
      std::ostringstream s;
      s << "the vector at vertex " << v << " is (" << input.x() << ", " << input.y() << ", " << input.z() << ")";
      throw Invalid_parameter("field", s.str());
    }
    Eigen::Vector3d xv = input - input.dot(normal[v]) * normal[v];
    // a tangential part below 1e-12 of the vector is rounding: the vector is normal there
    const double len = xv.norm();
    const bool tangent = len > 1e-12 * input.norm();
    has_direction[components.vertex_component[v]] = has_direction[components.vertex_component[v]] || tangent;
    if(radians_per_unit_length > 0.)
      xv = tangent ? Eigen::Vector3d(xv * (radians_per_unit_length / len)) : Eigen::Vector3d::Zero();
    x[v] = xv;
  }
  if(radians_per_unit_length > 0.)
    for(std::size_t c = 0; c < has_direction.size(); ++c)
      if(!has_direction[c])
        throw Invalid_parameter("field", "the field has no tangential component at any vertex of connected component " +
                                           std::to_string(c) + ": there is no direction to normalize");
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

/// omega per edge, the paper's angle-rescaled convention (see `One_form_convention`).
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

#endif // CGAL_SURFACE_DESIGN_INTERNAL_FIELD_ALIGNED_PARAMETERIZATION_TARGET_ONE_FORM_H
