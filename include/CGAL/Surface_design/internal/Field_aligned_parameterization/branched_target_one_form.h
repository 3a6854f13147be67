// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The target one-form of the stripes of an n-direction field on its cover: per edge and sheet,
// the field integrated along the edge; per branch face, along its spokes to the branch point.

#ifndef CGAL_SURFACE_DESIGN_INTERNAL_FIELD_ALIGNED_PARAMETERIZATION_BRANCHED_TARGET_ONE_FORM_H
#define CGAL_SURFACE_DESIGN_INTERNAL_FIELD_ALIGNED_PARAMETERIZATION_BRANCHED_TARGET_ONE_FORM_H

#include <CGAL/Surface_design/internal/Core/angles.h>
#include <CGAL/Surface_design/internal/Core/direction_field_cover.h>
#include <CGAL/Surface_design/internal/Core/geometry.h>
#include <CGAL/Surface_design/internal/Core/vertex_frames.h>
#include <CGAL/Surface_design/internal/Field_aligned_parameterization/stripe_interpolation.h>
#include <CGAL/Surface_design/internal/Field_aligned_parameterization/stripe_weights.h>

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Surface_design {
namespace internal {

/// The field of the cover's sheets: sheet s at vertex v is the representative turned by
/// 2 pi s / n; sheet s + n/2 is exactly the opposite of sheet s. `scale` (empty: 1) multiplies
/// the frequency vertex by vertex.
struct Cover_sheet_field
{
  const Vertex_frames& frames;
  const Direction_field_cover& cover;
  const std::vector<double>& scale;

  double scale_at(std::size_t v) const { return scale.empty() ? 1. : scale[v]; }
  double angle(std::size_t v, int sheet) const { return cover.angle[v] + two_pi * sheet / double(cover.n); }
  Eigen::Vector3d vector(std::size_t v, int sheet) const
  {
    const int n = cover.n;
    const int half = (std::max)(n / 2, 1);
    const int base = n == 1 ? 0 : sheet % half;
    const double sign = n == 1 || (sheet % n) < half ? 1. : -1.;
    return sign * frames.to_vector(v, angle(v, base));
  }
};

/// omega per edge and sheet: the field of sheet a at i and of sheet a + r at j (r the matching)
/// integrated along the edge i -> j by the trapezoid rule, each end's vector scaled by its
/// frequency scale, times 2 pi `frequency`: projected onto the edge (`projected`), or from the
/// rescaled angles and the edge's length (`angle_rescaled`, the vector case's conventions).
template <class Indices, class VertexPointMap>
std::vector<Eigen::Vector2d> branched_edge_targets(const Indices& idx, const VertexPointMap& vpm,
                                                   const Cover_sheet_field& field, const std::vector<double>& length,
                                                   double frequency, bool projected)
{
  const auto& tm = idx.mesh();
  const double nu = two_pi * frequency;
  std::vector<Eigen::Vector2d> omega(idx.number_of_edges(), Eigen::Vector2d::Zero());
  for(std::size_t e = 0; e < omega.size(); ++e)
  {
    const auto h = idx.oriented_halfedge(e);
    const std::size_t i = idx.source_index(h), j = idx.target_index(h);
    const double si = field.scale_at(i), sj = field.scale_at(j);
    for(int a = 0; a < field.cover.d; ++a)
    {
      const int b = a + field.cover.matching[e];
      if(projected)
      {
        const Eigen::Vector3d d = position(vpm, idx.vertex(j)) - position(vpm, idx.vertex(i));
        omega[e][a] = 0.5 * nu * (si * field.vector(i, a) + sj * field.vector(j, b)).dot(d);
      }
      else
        omega[e][a] = 0.5 * nu * length[e] *
                      (si * std::cos(field.angle(i, a) - field.frames.angle[idx.index(h)]) -
                       sj * std::cos(field.angle(j, b) - field.frames.angle[idx.index(opposite(h, tm))]));
    }
  }
  return omega;
}

/// The spokes' targets of every branch face f: the field of the face's reference sheets at
/// corner k integrated from the corner to the branch point o, at the mean of the corners'
/// frequency scales (on corner k, reference sheet a is sheet b of its vertex where the walk's
/// transport M_k has its entry +-1; `transition(h)` is the transport along halfedge index h);
/// for a cross field, the cone's exact map (`conformal_cone_targets()`). Regular faces: zero.
template <class Indices, class VertexPointMap, class Transition>
std::vector<std::array<Eigen::Vector2d, 3>> branched_spoke_targets(const Indices& idx, const VertexPointMap& vpm,
                                                                   const Cover_sheet_field& field, double frequency,
                                                                   const Transition& transition)
{
  const auto& tm = idx.mesh();
  const Direction_field_cover& c = field.cover;
  const double nu = two_pi * frequency;
  std::vector<std::array<Eigen::Vector2d, 3>> target(idx.number_of_faces());
  for(std::size_t f = 0; f < target.size(); ++f)
  {
    target[f].fill(Eigen::Vector2d::Zero());
    if(c.regular[f])
      continue;
    const Eigen::Vector3d o = branch_point_position(idx, vpm, f);
    double face_scale = 0.; // (exactly 1 without a scale)
    for(auto v : vertices_around_face(halfedge(idx.face(f), tm), tm))
      face_scale += field.scale_at(idx.index(v));
    face_scale /= 3.;
    Eigen::Matrix2d M = Eigen::Matrix2d::Identity();
    int k = 0;
    for(auto h : halfedges_around_face(halfedge(idx.face(f), tm), tm))
    {
      const std::size_t v = idx.index(source(h, tm));
      const Eigen::Vector3d x = position(vpm, source(h, tm));
      for(int a = 0; a < c.d; ++a)
        for(int s = 0; s < c.d; ++s)
          if(M(a, s) != 0.)
            target[f][std::size_t(k)][a] = nu * face_scale * M(a, s) * field.vector(v, s).dot(o - x);
      M = M * transition(idx.index(h));
      ++k;
    }
    if(c.d == 2)
      target[f] = conformal_cone_targets(face_corners(idx, vpm, f), o, target[f], 1. - c.index_numerator[f] / double(c.n));
  }
  return target;
}

} // namespace internal
} // namespace Surface_design
} // namespace CGAL

#endif // CGAL_SURFACE_DESIGN_INTERNAL_FIELD_ALIGNED_PARAMETERIZATION_BRANCHED_TARGET_ONE_FORM_H
