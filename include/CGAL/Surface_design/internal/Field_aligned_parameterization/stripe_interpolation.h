// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The stripe angle inside a triangle (Knöppel et al. 2015, sec. 6): linear in a regular face, with
// a winding term in a face that holds a stripe singularity, and on three sub-triangles around the
// branch point of a field singularity.

#ifndef CGAL_SURFACE_DESIGN_INTERNAL_FIELD_ALIGNED_PARAMETERIZATION_STRIPE_INTERPOLATION_H
#define CGAL_SURFACE_DESIGN_INTERNAL_FIELD_ALIGNED_PARAMETERIZATION_STRIPE_INTERPOLATION_H

#include <CGAL/Surface_design/internal/Core/angles.h>

#include <algorithm>
#include <array>

namespace CGAL {
namespace Surface_design {
namespace internal {

/// A discrete argument about the barycentre: 0, 2 pi / 3 and 4 pi / 3 at the corners 0, 1, 2,
/// linear along the edges 0-1 and 1-2, and from 4 pi / 3 to 2 pi along the edge 2-0, so that it
/// winds once around the barycentre. Piecewise on the three regions where one coordinate is the
/// smallest.
inline double barycentric_argument(const std::array<double, 3>& b)
{
  int k = 0; // the smallest coordinate
  for(int i = 1; i < 3; ++i)
    if(b[std::size_t(i)] < b[std::size_t(k)])
      k = i;
  const int i = (k + 1) % 3, j = (k + 2) % 3;
  const double denominator = 1. - 3. * b[std::size_t(k)];
  if(!(denominator > 1e-15))
    return 0.; // the barycentre itself: any value
  // offsets: region k = 2 starts at corner 0 (0), k = 0 at corner 1 (2 pi / 3), k = 1 at corner 2
  const double offset = k == 2 ? 1. : (k == 0 ? 3. : 5.);
  return (pi / 3.) * (offset + (b[std::size_t(j)] - b[std::size_t(i)]) / denominator);
}

/// The stripe angle at barycentric coordinates b of a regular face whose corner values c are
/// unwrapped along its first two edges and whose stripe index is k (the walk around the face
/// returns to c[0] + 2 pi k): linear for k = 0; otherwise the corners are shifted by 2 pi k j / 3
/// and k times the discrete argument added, which restores the linear interpolation of the edge
/// values on every edge (c[2] to c[0] + 2 pi k on the third) and puts the zero at the barycentre.
inline double regular_face_value(const std::array<double, 3>& c, int k, const std::array<double, 3>& b)
{
  if(k == 0)
    return b[0] * c[0] + b[1] * c[1] + b[2] * c[2];
  const double step = two_pi * double(k) / 3.;
  return b[0] * c[0] + b[1] * (c[1] - step) + b[2] * (c[2] - 2. * step) + double(k) * barycentric_argument(b);
}

/// The stripe angle in a branch face split at its centroid into (0, 1, c), (1, 2, c), (2, 0', c):
/// beta[0..2] the corner values along the walk, beta[3] the value at corner 0 reached after the
/// walk (on another sheet), centre the value at the branch point.
inline double branch_face_value(const std::array<double, 4>& beta, double centre, const std::array<double, 3>& b)
{
  int k = 0;
  for(int i = 1; i < 3; ++i)
    if(b[std::size_t(i)] < b[std::size_t(k)])
      k = i;
  const int i = (k + 1) % 3; // the sub-triangle (i, i + 1, centre)
  const double lc = 3. * b[std::size_t(k)];
  const double li = b[std::size_t(i)] - b[std::size_t(k)], lj = b[std::size_t((i + 1) % 3)] - b[std::size_t(k)];
  return li * beta[std::size_t(i)] + lj * beta[std::size_t(i + 1)] + lc * centre;
}

} // namespace internal
} // namespace Surface_design
} // namespace CGAL

#endif // CGAL_SURFACE_DESIGN_INTERNAL_FIELD_ALIGNED_PARAMETERIZATION_STRIPE_INTERPOLATION_H
