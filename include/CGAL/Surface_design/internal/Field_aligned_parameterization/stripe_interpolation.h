// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The stripe angle inside a triangle (Knöppel et al. 2015, sec. 6): linear in a regular face, with
// a winding term in a face that holds a stripe singularity, and on three sub-triangles around the
// branch point of a field singularity.

#ifndef CGAL_SURFACE_DESIGN_INTERNAL_FIELD_ALIGNED_PARAMETERIZATION_STRIPE_INTERPOLATION_H
#define CGAL_SURFACE_DESIGN_INTERNAL_FIELD_ALIGNED_PARAMETERIZATION_STRIPE_INTERPOLATION_H

#include <CGAL/Surface_design/internal/Core/angles.h>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <Eigen/LU>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <utility>

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

/// The branch point of a branch face with corners x[0], x[1], x[2], in barycentric coordinates:
/// the point from which the three edges are seen under 120 degrees (the Fermat point: barycentric
/// coordinates |x_(i+1) - x_(i+2)| / sin(A_i + pi / 3) for the angles A_i at the corners), moved
/// towards the centroid until every coordinate is at least 0.1 (a face with an angle of 120
/// degrees or more has its Fermat point at that corner). The face is drawn as the three triangles
/// from its edges to this point: at a cone of index k / 4 their angles there are scaled by
/// 1 - k / 4 in the parameter plane, 150 degrees each at a -1/4 cone from 120 (at the centroid of
/// a face with an angle of 100 degrees, one of them would be 2 x 100 = 200 > 180: a fold).
inline std::array<double, 3> branch_point_barycentric(const std::array<Eigen::Vector3d, 3>& x)
{
  std::array<double, 3> w{};
  double sum = 0.;
  for(std::size_t i = 0; i < 3; ++i)
  {
    const Eigen::Vector3d p = x[(i + 1) % 3] - x[i], q = x[(i + 2) % 3] - x[i];
    const double angle = std::atan2(p.cross(q).norm(), p.dot(q));
    const double s = (std::max)(std::sin(angle + pi / 3.), 1e-3); // 120 degrees or more: at the corner
    w[i] = (x[(i + 1) % 3] - x[(i + 2) % 3]).norm() / s;
    sum += w[i];
  }
  if(!(sum > 0.) || !std::isfinite(sum))
    return {1. / 3., 1. / 3., 1. / 3.};
  double smallest = 1.;
  for(double& c : w)
  {
    c /= sum;
    smallest = (std::min)(smallest, c);
  }
  const double floor = 0.1;
  if(smallest < floor)
  {
    const double t = (floor - smallest) / (1. / 3. - smallest); // (1 - t) smallest + t / 3 = floor
    for(double& c : w)
      c = (1. - t) * c + t / 3.;
  }
  return w;
}

/// The spokes' targets of a cone of a cross field, made exactly conformal: corner k of a branch
/// face (x[k], branch point o) seen from o at distance r_k and polar angle phi_k (counterclockwise
/// in the face) is sent to target_k = -nu r_k e^(i (s phi_k + psi)) (the target integrates from the
/// corner to o), s = 1 - index the cone's angle scale, the rotation psi the one that fits the
/// field's own targets `field_target` (nu the ratio of their lengths to the r_k) best. The field
/// turns unevenly along a cone face's edges (all of its quarter turn along one edge, say), and
/// three linear triangles that follow it fold; these turn by s times the angles at o, 150 degrees
/// each at a -1/4 cone seen from the Fermat point: never a fold while every angle at o is below
/// 180 / s degrees.
inline std::array<Eigen::Vector2d, 3> conformal_cone_targets(const std::array<Eigen::Vector3d, 3>& x,
                                                             const Eigen::Vector3d& o,
                                                             const std::array<Eigen::Vector2d, 3>& field_target,
                                                             double s)
{
  std::array<double, 3> r{}, phi{};
  for(std::size_t k = 0; k < 3; ++k)
    r[k] = (x[k] - o).norm();
  for(std::size_t k = 0; k + 1 < 3; ++k)
  {
    const Eigen::Vector3d a = x[k] - o, b = x[k + 1] - o;
    phi[k + 1] = phi[k] + std::atan2(a.cross(b).norm(), a.dot(b));
  }
  // the best rotation and the length scale: least squares over the corners
  double re = 0., im = 0., length = 0., radius = 0.;
  for(std::size_t k = 0; k < 3; ++k)
  {
    const Eigen::Vector2d w = -field_target[k]; // where the field puts the corner, seen from o
    const double c = std::cos(s * phi[k]), sn = std::sin(s * phi[k]);
    re += r[k] * (w.x() * c + w.y() * sn);
    im += r[k] * (w.y() * c - w.x() * sn);
    length += w.norm();
    radius += r[k];
  }
  const double psi = std::atan2(im, re), nu = radius > 0. ? length / radius : 0.;
  std::array<Eigen::Vector2d, 3> t;
  for(std::size_t k = 0; k < 3; ++k)
    t[k] = -nu * r[k] * Eigen::Vector2d(std::cos(s * phi[k] + psi), std::sin(s * phi[k] + psi));
  return t;
}

/// The sub-triangle of a face split at the point o (barycentric coordinates, all positive) that
/// holds the point of barycentric coordinates b: the one opposite corner k, k the index of the
/// smallest b_k / o_k, with the coordinates (of corners k + 1 and k + 2, and of o) of b in it.
inline std::pair<int, std::array<double, 3>> branch_sub_triangle(const std::array<double, 3>& o,
                                                                   const std::array<double, 3>& b)
{
  int k = 0;
  for(int i = 1; i < 3; ++i)
    if(b[std::size_t(i)] * o[std::size_t(k)] < b[std::size_t(k)] * o[std::size_t(i)])
      k = i;
  const double lc = b[std::size_t(k)] / o[std::size_t(k)];
  const std::size_t i = std::size_t((k + 1) % 3), j = std::size_t((k + 2) % 3);
  return {k, {b[i] - lc * o[i], b[j] - lc * o[j], lc}};
}

/// The stripe angle in a branch face split at its branch point o (barycentric coordinates, see
/// `branch_point_barycentric()`) into (0, 1, o), (1, 2, o), (2, 0', o): beta[0..2] the corner
/// values along the walk, beta[3] the value at corner 0 reached after the walk (on another sheet),
/// centre the value at the branch point.
inline double branch_face_value(const std::array<double, 4>& beta, double centre, const std::array<double, 3>& o,
                                const std::array<double, 3>& b)
{
  const auto [k, l] = branch_sub_triangle(o, b);
  const int i = (k + 1) % 3; // the sub-triangle (i, i + 1, o)
  return l[0] * beta[std::size_t(i)] + l[1] * beta[std::size_t(i + 1)] + l[2] * centre;
}

/// The walk of a solution of `solver` (`Branched_one_form_solver`) around face f from its corner
/// v0 = source(halfedge(f)): beta[0..2] the values at its corners (unwrapped along its first two
/// halfedges), beta[3] at the first corner again after the third halfedge.
template <class Indices, class Solver>
std::array<Eigen::Vector2d, 4> face_walk(const Indices& idx, const Solver& solver,
                                         const typename Solver::Solution& solution, std::size_t f, std::size_t v0)
{
  const auto& tm = idx.mesh();
  std::array<Eigen::Vector2d, 4> beta;
  beta[0] = solution.alpha[v0];
  Eigen::Matrix2d M = Eigen::Matrix2d::Identity();
  std::size_t t = 0;
  for(auto h : halfedges_around_face(halfedge(idx.face(f), tm), tm))
  {
    const std::size_t hi = idx.index(h);
    beta[t + 1] = beta[t] + M * solver.along(solution.y, hi);
    M = M * solver.transition_along(hi);
    ++t;
  }
  return beta;
}

/// The value at the branch point of face f: the fixed point of x -> M x + t, where the walk
/// (`face_walk()`) returns to the first corner's values transformed by M (the product of the
/// transitions) and shifted by t; the first `d` values.
template <class Indices, class Solver>
Eigen::Vector2d branch_point_value(const Indices& idx, const Solver& solver, const typename Solver::Solution& solution,
                                   std::size_t f, std::size_t v0, int d)
{
  const auto& tm = idx.mesh();
  const auto beta = face_walk(idx, solver, solution, f, v0);
  Eigen::Matrix2d M = Eigen::Matrix2d::Identity();
  for(auto h : halfedges_around_face(halfedge(idx.face(f), tm), tm))
    M = M * solver.transition_along(idx.index(h));
  // beta[3] are the values of the sheets M maps to: beta[3] = M alpha_v0 + t
  const Eigen::Vector2d t = beta[3] - M * beta[0];
  const Eigen::MatrixXd A = Eigen::MatrixXd::Identity(d, d) - M.topLeftCorner(d, d);
  Eigen::Vector2d c = Eigen::Vector2d::Zero();
  c.head(d) = A.fullPivLu().solve(Eigen::VectorXd(t.head(d)));
  return c;
}

} // namespace internal
} // namespace Surface_design
} // namespace CGAL

#endif // CGAL_SURFACE_DESIGN_INTERNAL_FIELD_ALIGNED_PARAMETERIZATION_STRIPE_INTERPOLATION_H
