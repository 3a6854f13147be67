// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The one definition of pi and of angle wrapping used by every package.

#ifndef CGAL_SURFACE_DESIGN_INTERNAL_CORE_ANGLES_H
#define CGAL_SURFACE_DESIGN_INTERNAL_CORE_ANGLES_H

#include <CGAL/number_type_config.h>

#include <cmath>

namespace CGAL {
namespace Surface_design {
namespace internal {

constexpr double pi = CGAL_PI;
constexpr double two_pi = 2. * CGAL_PI;

/// `x` wrapped into the half-open interval [lower, lower + 2 pi): by default [-pi, pi), the
/// representative of a rotation angle or an angle difference; `wrap_angle(x, 0.)` gives [0, 2 pi),
/// the representative of a direction. The result is exactly `lower` or above and strictly below
/// `lower + 2 pi`, also where rounding of `x - 2 pi k` would land on the excluded end.
inline double wrap_angle(double x, double lower = -pi)
{
  double w = x - two_pi * std::floor((x - lower) / two_pi);
  if(w >= lower + two_pi)
    w -= two_pi;
  if(w < lower)
    w = lower;
  return w;
}

} // namespace internal
} // namespace Surface_design
} // namespace CGAL

#endif // CGAL_SURFACE_DESIGN_INTERNAL_CORE_ANGLES_H
