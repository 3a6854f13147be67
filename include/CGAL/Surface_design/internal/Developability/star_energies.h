// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Developability energies of one vertex star and their exact (sub)gradients, and their sum over a
// mesh (Stein, Grinspun & Crane 2018, "Developability of triangle meshes", sections 3 and 4.1,
// appendix B). Equation numbers below are the paper's.
//
// ----------------------------------------------------------------------------------------------
// Design note
// ----------------------------------------------------------------------------------------------
// A star is a centre x_0 and its ring x_1, ..., x_d, counter-clockwise (vertex_stars.h). Face k is
// the triangle (x_0, x_{1+k}, x_{1+(k+1) mod d}): k = 0..d-1 on a closed star (interior vertex),
// k = 0..d-2 on an open fan (boundary vertex). N_k is its unit normal, theta_k its corner angle at
// the centre, n_k = (x_{1+k} - x_0) x (x_{2+k} - x_0) = 2 A_k N_k its area vector. Every energy is
// a function of the N_k, theta_k and n_k only, hence invariant under rigid motions and scaling.
//
// combinatorial (E^P, eqs. 1-2). The minimum, over the splittings P = {F_1, F_2} of the star's
//   faces into two contiguous (edge-connected) regions, of
//       pi(P) = sum_p (1/n_p) sum_{f in F_p} |N_f - Nbar_p|^2,   Nbar_p the mean normal of F_p.
//   This is the first expression of eq. 1, which we implement. It equals 1/n_p^2 times the sum
//   over the UNORDERED pairs of F_p of |N_a - N_b|^2; the second expression of eq. 1 as printed
//   sums over ordered pairs, which is twice as much. (The reference code normalizes differently
//   again: half the unordered pair sum over the total number of pairs.) The deviations are summed
//   directly, not as 1 - |Nbar_p|^2, which cancels catastrophically near a hinge.
//   Closed star: the regions are the arcs between two distinct spokes (d(d-1)/2 splittings). Open
//   fan: the two pieces on either side of one interior spoke (d-2 splittings).
//   A region MAY be a single face; the reference code requires two. Our reasons: (i) eq. 2
//   minimizes over all edge-connected 2-splittings, and Definition 3.1 puts no size on the
//   regions; (ii) on an open fan, a fold at the first or last interior spoke is a genuine hinge
//   one of whose regions is one face: "two faces at least" gives it positive energy, and leaves a
//   fan of 2 or 3 faces (and a closed valence-3 star) without any splitting at all; (iii) on a
//   closed star it creates no new zero: a single face whose two spokes lie in the plane of the
//   other region lies in that plane, so the star is flat, and a flat star is a zero anyway.
//   Single-face regions do lower the value on curved stars (a round star often prefers a
//   1 + (d - 1) splitting).
// combinatorial_max (eq. 5). The same splittings; pi^max(P) is the larger, over the two regions,
//   of the largest |N_a - N_b|^2 in the region (0 for a single face).
// covariance (E^lambda, eqs. 3-4). lambda_min(A), A = sum_f theta_f N_f N_f^T. The unit
//   eigenvector u comes from Eigen::SelfAdjointEigenSolver (iterative, accurate; not the closed
//   form computeDirect: section 4.3 stresses the need for an accurate 3x3 solver); lambda is then
//   the Rayleigh quotient sum_f theta_f <u, N_f>^2, a sum of non-negative terms accurate RELATIVE
//   to lambda, where any computed eigenvalue is only accurate to about 1e-16 ||A||. Near a hinge
//   lambda is tiny, and its differences (line searches, finite differences) need those digits.
//   Gradient: eq. 10 (Hellmann-Feynman, d lambda = u^T dA u).
// covariance_max (eq. 6, appendix B.4). min over unit u of phi(u) = max_f <u, N_f>^2 (eq. 6 as
//   printed; the reference code uses 1/2 <u, N>^2). phi is smallest at a vertex of the spherical
//   Voronoi diagram of the sites {+-N_f}: the circumcentre w = (q_b - q_a) x (q_c - q_a) / |.| of
//   three sites. We evaluate phi at the circumcentres of the sites of every three distinct faces
//   (first site positive: 4 sign patterns per triple, as in B.4) and keep the smallest. A star
//   with fewer than three faces, or with all normals parallel, has none and energy 0 (phi = 0 at
//   u = N_a x N_b). Triples such as (N_a, -N_a, N_b) are not needed: their circumcentre, at 90
//   degrees from the three, is a Voronoi vertex only when every normal lies on that great circle,
//   and then three distinct faces have the same circumcentre.
// intrinsic (appendix B.5). N_v = n / |n|, n = sum_f n_f (the area-weighted vertex normal). The
//   log map of the sphere at N_v sends N_f to Ntilde_f = phi_f (N_f - c_f N_v) / sin(phi_f),
//   c_f = <N_v, N_f> = cos(phi_f); the energy is the smallest eigenvalue of the 2x2 tangent matrix
//   sum_f theta_f Ntilde_f Ntilde_f^T, evaluated as a Rayleigh quotient like covariance (value and
//   gradient do not depend on the tangent basis). We write Ntilde_f = g(c_f) (N_f - c_f N_v) with
//   g(c) = phi / sin(phi), smooth on phi in [0, pi), with Taylor series for small phi: nothing
//   divides by sin(phi) or tan(phi) (our notes report that the reference code's gradient divides
//   by <N_v, N_f>), and faces with N_f = N_v need no special case. Its Jacobians are eq. 11.
// intrinsic_width (appendix B.5.1). min over tangent unit u of max_f <u, Ntilde_f>^2, the squared
//   HALF minimum width of the convex hull of {+-Ntilde_f}. Scale: half the width, so that the
//   value is the intrinsic analogue of eq. 6 (the two agree to first order for a small Gauss
//   image); the reference code's squared full width is 4 times larger. The minimum width of a
//   convex polygon is attained perpendicular to one of its edges (rotating calipers), so the
//   candidates are u = N_v x (x_a - x_b) / |x_a - x_b| for x_a = +Ntilde_a, x_b = +-Ntilde_b of
//   distinct faces (an edge from x_a to -x_a would pass through the centre of the symmetric hull,
//   i.e. the hull is a segment, whose direction distinct faces give too; one face: energy 0).
// squared_angle_defect (the baseline of Fig. 7). Omega^2, Omega = 2 pi - sum_f theta_f on a
//   closed star, pi - sum_f theta_f on an open fan. NOT divided by the vertex area as in the
//   reference code: Omega^2 is dimensionless like every other energy here (one scale contract,
//   one set of optimizer tolerances for all), has the same zero set, and does not weigh tiny
//   triangles enormously (the sliver trouble of section 4.3); Omega^2 / A_i is 1/length^2.
// absolute_angle_defect (the L1 variant of Fig. 11). |Omega|: summed over the vertices, the L1
//   norm of the discrete Gaussian curvature, the sparsity-inducing norm the paper contrasts with
//   its energies (it yields piecewise flat, not piecewise developable, surfaces). Subgradient
//   -sign(Omega) per angle, 0 where Omega is 0 to rounding.
//
// Gradients. Every energy computes dE/dN_f, dE/dtheta_f and (the intrinsic ones) dE/dn, and one
// function, pull_back(), applies the chain rule of appendix B.1: eq. 7 (area vector), eq. 8
// (normal: grad_{x_p} <w, N> = <w, e_p x N> / (2A) N, e_p the edge opposite p), eq. 9 (angle).
//
// Nonsmooth points. Where the minimizing splitting or candidate, or the face attaining a max, is
// not unique, the first in enumeration order is used: the gradient of one smooth piece active at
// the point, a (Clarke) subgradient, which is what the paper's optimizer uses (section 4.3). At a
// repeated eigenvalue any unit eigenvector gives a subgradient.
//
// Degenerate stars. A face is degenerate when 2A <= degenerate_face_tolerance (longest edge)^2
// (the ratio of validation.h): its normal is set to 0 (it aligns with nothing), the energy is
// evaluated with it and finite, and the star's gradient is ZERO (the normal of a vanishing
// triangle has no limit). The intrinsic energies also need a vertex normal (|n| > 0) and a log map
// defined at every face (N_f not antipodal to N_v); otherwise the largest face's normal is the base
// point, faces on the cut locus map to 0, and the gradient is zero. No division by zero: finite
// input gives finite output.

#ifndef CGAL_SURFACE_DESIGN_INTERNAL_DEVELOPABILITY_STAR_ENERGIES_H
#define CGAL_SURFACE_DESIGN_INTERNAL_DEVELOPABILITY_STAR_ENERGIES_H

#include <CGAL/Surface_design/developability_energy.h>
#include <CGAL/Surface_design/internal/Core/angles.h>
#include <CGAL/Surface_design/internal/Solvers/parallel.h>
#include <CGAL/Surface_design/internal/Developability/vertex_stars.h>

#include <CGAL/assertions.h>

#include <Eigen/Core>
#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

#include <boost/container/small_vector.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace CGAL {
namespace Surface_design {
namespace internal {

/// \name Tolerances of the star energies (all dimensionless)
/// @{
/// A star face is degenerate when twice its area is at most this times its longest edge squared
/// (about the sine of its smallest angle; the same test as `Validation_options`).
constexpr double degenerate_face_tolerance = 1e-12;
/// covariance_max: triples of sites (unit vectors) spanning a triangle of doubled area at most
/// this are skipped (two coincident sites: no circumcentre).
constexpr double site_triangle_tolerance = 1e-14;
/// intrinsic_width: pairs of log-mapped normals closer than this (radians) are skipped (no edge
/// direction).
constexpr double tangent_segment_tolerance = 1e-14;
/// intrinsic energies: the vertex normal is undefined when the star's area vector is at most this
/// times the sum of its faces' area vectors' norms (a star folded onto itself).
constexpr double vertex_normal_tolerance = 1e-12;
/// intrinsic energies: a face normal whose sine with the vertex normal is below this while their
/// cosine is negative is on the cut locus of the log map (antipodal to the vertex normal).
constexpr double cut_locus_tolerance = 1e-12;
/// Below this angle (radians) the log map factors phi / sin(phi) and its derivative use their
/// Taylor series (relative truncation error < 1e-13); above, the closed forms lose < 1e-11.
constexpr double log_map_series_angle = 1e-2;
/// @}

/// Buffer of per-face or per-point values of one star: no heap allocation up to valence 16.
template <class T>
using Star_buffer = boost::container::small_vector<T, 17>;

// ----------------------------------------------------------------------------------------------
// Geometry of a star and the chain rule of appendix B.1
// ----------------------------------------------------------------------------------------------

/// The faces of one star with their normals, corner angles at the centre and area vectors.
/// Star points: 0 is the centre, 1 + k is ring vertex k.
class Star_geometry
{
public:
  struct Face
  {
    std::array<std::size_t, 3> corner; ///< star points (centre, ring k, ring k + 1)
    Eigen::Vector3d area_vector;       ///< n_f = (x_1 - x_0) x (x_2 - x_0) = 2 A_f N_f
    Eigen::Vector3d normal;            ///< N_f, or 0 if the face is degenerate
    double double_area;                ///< 2 A_f = |n_f|
    double angle;                      ///< theta_f, corner angle at the centre
  };

  Star_geometry(const Eigen::Vector3d& center, const Eigen::Vector3d* ring, std::size_t degree, bool closed)
    : m_center(center), m_ring(ring), m_closed(closed)
  {
    const std::size_t nf = closed || degree == 0 ? degree : degree - 1;
    m_faces.resize(nf);
    for(std::size_t k = 0; k < nf; ++k)
    {
      Face& f = m_faces[k];
      f.corner = {0, 1 + k, 1 + (k + 1) % degree};
      const Eigen::Vector3d a = point(f.corner[1]) - center, b = point(f.corner[2]) - center;
      f.area_vector = a.cross(b);
      f.double_area = f.area_vector.norm();
      f.angle = std::atan2(f.double_area, a.dot(b));
      const double longest2 = (std::max)({a.squaredNorm(), b.squaredNorm(), (b - a).squaredNorm()});
      if(f.double_area > degenerate_face_tolerance * longest2)
        f.normal = f.area_vector / f.double_area;
      else
      {
        f.normal.setZero();
        m_degenerate = true;
      }
    }
  }

  bool closed() const { return m_closed; }
  std::size_t number_of_faces() const { return m_faces.size(); }
  const Face& face(std::size_t k) const { return m_faces[k]; }
  const Eigen::Vector3d& normal(std::size_t k) const { return m_faces[k].normal; }
  double angle(std::size_t k) const { return m_faces[k].angle; }
  const Eigen::Vector3d& point(std::size_t i) const { return i == 0 ? m_center : m_ring[i - 1]; }
  /// Some face is degenerate: the star's gradient is zero.
  bool degenerate() const { return m_degenerate; }

private:
  Eigen::Vector3d m_center;
  const Eigen::Vector3d* m_ring;
  bool m_closed;
  bool m_degenerate = false;
  Star_buffer<Face> m_faces;
};

/// What an energy computes for the chain rule: dE/dN_f and dE/dtheta_f per face, and dE/dn for
/// the star's total area vector n = sum_f n_f (used by the intrinsic energies).
struct Star_sensitivities
{
  explicit Star_sensitivities(std::size_t number_of_faces)
    : normal(number_of_faces, Eigen::Vector3d::Zero()), angle(number_of_faces, 0.)
  {}

  Star_buffer<Eigen::Vector3d> normal;
  Star_buffer<double> angle;
  Eigen::Vector3d area_vector = Eigen::Vector3d::Zero();
  /// Set by an energy that cannot differentiate at this star (see the design note).
  bool zero_gradient = false;
};

/// The chain rule of appendix B.1: adds the gradient with respect to the star's points
/// (`gradient[0]` the centre, `gradient[1 + k]` ring vertex k) of an energy with sensitivities
/// `s`. Per face with corners p = i (centre), j, k and opposite edges e_i = x_k - x_j,
/// e_j = x_i - x_k, e_k = x_j - x_i:
///  - eq. 8:  grad_{x_p} <w, N> = (<w, e_p x N> / 2A) N   with w = dE/dN;
///  - eq. 9:  grad_{x_j} theta_i = -N x e_k / |e_k|^2, grad_{x_k} theta_i = -N x e_j / |e_j|^2,
///            grad_{x_i} theta_i = minus their sum;
///  - eq. 7 in vector form: d n_f = e_p x dx_p for each corner, so grad_{x_p} <q, n_f> = q x e_p
///    with q = dE/dn.
/// \pre the star is not degenerate
inline void pull_back(const Star_geometry& g, const Star_sensitivities& s, Eigen::Vector3d* gradient)
{
  for(std::size_t f = 0; f < g.number_of_faces(); ++f)
  {
    const Star_geometry::Face& face = g.face(f);
    const Eigen::Vector3d& N = face.normal;
    const std::array<Eigen::Vector3d, 3> x = {g.point(face.corner[0]), g.point(face.corner[1]),
                                              g.point(face.corner[2])};
    const std::array<Eigen::Vector3d, 3> e = {x[2] - x[1], x[0] - x[2], x[1] - x[0]};
    Eigen::Vector3d grad[3] = {Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()};
    for(int p = 0; p < 3; ++p)
      grad[p] += (s.normal[f].dot(e[p].cross(N)) / face.double_area) * N + s.area_vector.cross(e[p]);
    // eq. 9 at the centre (corner 0): e_k = e[2] = x_1 - x_0, e_j = e[1] = x_0 - x_2
    const Eigen::Vector3d d1 = -s.angle[f] * N.cross(e[2]) / e[2].squaredNorm();
    const Eigen::Vector3d d2 = -s.angle[f] * N.cross(e[1]) / e[1].squaredNorm();
    grad[1] += d1;
    grad[2] += d2;
    grad[0] -= d1 + d2;
    for(int p = 0; p < 3; ++p)
      gradient[face.corner[p]] += grad[p];
  }
}

// ----------------------------------------------------------------------------------------------
// Shared pieces of the energies
// ----------------------------------------------------------------------------------------------

/// The smallest eigenvalue of A = sum_f theta_f v_f v_f^T (eqs. 3-4), given a unit eigenvector
/// u of it, as the Rayleigh quotient lambda = sum_f theta_f <u, v_f>^2. This sum of non-negative
/// terms is accurate RELATIVE to lambda, where the eigensolver's eigenvalue is only accurate to
/// about 1e-16 ||A||: near a hinge lambda is tiny and its finite differences, or the comparison of
/// two nearly developable stars, need the digits. (An error du in u changes it by O(||A|| du^2).)
/// If `d_angle` is not null, also eq. 10: d lambda = sum_f ( <u, v_f>^2 d theta_f +
/// 2 theta_f <u, v_f> <u, d v_f> ) (Hellmann-Feynman), added to `d_angle[f]` and `d_vector[f]`.
inline double smallest_eigenvalue(const Star_geometry& g, const Eigen::Vector3d* v, const Eigen::Vector3d& u,
                                  double* d_angle = nullptr, Eigen::Vector3d* d_vector = nullptr)
{
  double lambda = 0.;
  for(std::size_t f = 0; f < g.number_of_faces(); ++f)
  {
    const double a = u.dot(v[f]);
    lambda += g.angle(f) * a * a;
    if(d_angle)
    {
      d_angle[f] += a * a;
      d_vector[f] += 2. * g.angle(f) * a * u;
    }
  }
  return lambda;
}

/// max_f <u, v_f>^2 and the first face attaining it. Stops as soon as a value exceeds `bound`
/// (the caller keeps the smallest maximum seen: a larger one is of no use).
struct Largest_alignment
{
  double value = 0.;
  std::size_t face = 0;
};
inline Largest_alignment largest_squared_alignment(const Eigen::Vector3d& u, const Eigen::Vector3d* v, std::size_t m,
                                                   double bound)
{
  Largest_alignment best;
  for(std::size_t f = 0; f < m; ++f)
  {
    const double a = u.dot(v[f]);
    if(a * a > best.value)
    {
      best.value = a * a;
      best.face = f;
      if(best.value > bound)
        break;
    }
  }
  return best;
}

/// A splitting of the star's faces into two contiguous regions; region r is the faces
/// first[r], first[r] + 1, ..., first[r] + count[r] - 1 (mod the number of faces).
struct Splitting
{
  std::array<std::size_t, 2> first{}, count{};
};

/// min over the splittings of (cost(region 0) + cost(region 1)) (`use_max` false, eq. 1) or
/// max(cost(region 0), cost(region 1)) (eq. 5). `region_cost(first, count)` is the cost of one
/// region. Returns the value and the first minimizing splitting; 0 and no splitting when the star
/// has fewer than two faces.
template <class RegionCost>
double smallest_over_splittings(const Star_geometry& g, bool use_max, const RegionCost& region_cost, Splitting& best,
                                bool& found)
{
  const std::size_t m = g.number_of_faces();
  double best_value = std::numeric_limits<double>::infinity();
  found = false;
  auto consider = [&](std::size_t first0, std::size_t count0, std::size_t first1, std::size_t count1) {
    const double c0 = region_cost(first0, count0), c1 = region_cost(first1, count1);
    const double value = use_max ? (std::max)(c0, c1) : c0 + c1;
    if(value < best_value)
    {
      best_value = value;
      best.first = {first0, first1};
      best.count = {count0, count1};
      found = true;
    }
  };
  if(g.closed())
  {
    // cut at spokes i < j: arcs [i, j) and [j, i + m)
    for(std::size_t i = 0; i < m; ++i)
      for(std::size_t j = i + 1; j < m; ++j)
        consider(i, j - i, j, m - (j - i));
  }
  else
  {
    // cut at interior spoke k: [0, k) and [k, m)
    for(std::size_t k = 1; k < m; ++k)
      consider(0, k, k, m - k);
  }
  return found ? best_value : 0.;
}

/// Face i of the region that starts at face `first` (indices mod the number of faces).
inline std::size_t region_face(const Star_geometry& g, std::size_t first, std::size_t i)
{
  return (first + i) % g.number_of_faces();
}

/// The log map at the area-weighted vertex normal (appendix B.5), face by face:
/// Ntilde_f = g(c_f) w_f with w_f = N_f - c_f N_v, c_f = <N_v, N_f>, g(c) = phi / sin(phi).
class Log_mapped_normals
{
public:
  explicit Log_mapped_normals(const Star_geometry& g)
  {
    const std::size_t m = g.number_of_faces();
    m_area_vector.setZero();
    double sum_of_norms = 0.;
    std::size_t largest = 0;
    for(std::size_t f = 0; f < m; ++f)
    {
      m_area_vector += g.face(f).area_vector;
      sum_of_norms += g.face(f).double_area;
      if(g.face(f).double_area > g.face(largest).double_area)
        largest = f;
    }
    m_area_vector_norm = m_area_vector.norm();
    if(m_area_vector_norm > vertex_normal_tolerance * sum_of_norms)
      m_normal = m_area_vector / m_area_vector_norm;
    else
    {
      // the star is folded onto itself: no vertex normal; any unit base point gives a finite value
      m_defined = false;
      m_normal = m > 0 && g.normal(largest).squaredNorm() > 0. ? g.normal(largest) : Eigen::Vector3d::UnitZ();
    }

    m_faces.resize(m);
    for(std::size_t f = 0; f < m; ++f)
    {
      Face& face = m_faces[f];
      const Eigen::Vector3d& N = g.normal(f);
      face.normal = N;
      face.cosine = m_normal.dot(N);
      const double sine = m_normal.cross(N).norm();
      if(sine < cut_locus_tolerance && face.cosine < 0.)
      {
        m_defined = false; // N = -N_v: every tangent direction is a shortest way there
        face.factor = face.factor_derivative = 0.;
        face.tangent.setZero();
        face.image.setZero();
        continue;
      }
      const double phi = std::atan2(sine, face.cosine);
      // g(c) = phi / sin(phi) and g'(c) = dg/dc = -(sin(phi) - phi cos(phi)) / sin(phi)^3
      if(phi < log_map_series_angle)
      {
        const double p2 = phi * phi;
        face.factor = 1. + p2 / 6. + 7. * p2 * p2 / 360.;
        face.factor_derivative = -(1. / 3. + 2. * p2 / 15. + 2. * p2 * p2 / 63.);
      }
      else
      {
        face.factor = phi / sine;
        face.factor_derivative = -(sine - phi * face.cosine) / (sine * sine * sine);
      }
      face.tangent = N - face.cosine * m_normal;
      face.image = face.factor * face.tangent;
    }
  }

  /// False when the star has no vertex normal or a face normal is antipodal to it: the images
  /// are finite but the energy is not differentiable (zero gradient).
  bool defined() const { return m_defined; }
  const Eigen::Vector3d& vertex_normal() const { return m_normal; }
  const Eigen::Vector3d& image(std::size_t f) const { return m_faces[f].image; }
  const Eigen::Vector3d* images(Star_buffer<Eigen::Vector3d>& buffer) const
  {
    buffer.resize(m_faces.size());
    for(std::size_t f = 0; f < m_faces.size(); ++f)
      buffer[f] = m_faces[f].image;
    return buffer.data();
  }

  /// Chain rule through the log map (the Jacobians of eq. 11) and the vertex normal: given
  /// z_f = dE/dNtilde_f, adds dE/dN_f to `s.normal` and dE/dn to `s.area_vector`. With
  /// dNtilde = g'(c) dc w + g (dN_f - dc N_v - c dN_v), dc = <N_f, dN_v> + <N_v, dN_f>:
  ///   dE/dN_f += g z + a N_v,   dE/dN_v += -g c z + a N_f,   a = g' <z, w> - g <z, N_v>,
  /// and dN_v = (I - N_v N_v^T) dn / |n|. (These derivatives are valid for variations tangent to
  /// the unit sphere, the only ones the normal Jacobians produce.)
  void pull_back(const Eigen::Vector3d* z, Star_sensitivities& s) const
  {
    Eigen::Vector3d d_vertex_normal = Eigen::Vector3d::Zero();
    for(std::size_t f = 0; f < m_faces.size(); ++f)
    {
      const Face& face = m_faces[f];
      const double a = face.factor_derivative * z[f].dot(face.tangent) - face.factor * z[f].dot(m_normal);
      s.normal[f] += face.factor * z[f] + a * m_normal;
      d_vertex_normal += -face.factor * face.cosine * z[f] + a * face.normal;
    }
    s.area_vector += (d_vertex_normal - m_normal.dot(d_vertex_normal) * m_normal) / m_area_vector_norm;
  }

private:
  struct Face
  {
    Eigen::Vector3d normal, tangent, image;
    double cosine, factor, factor_derivative;
  };
  Eigen::Vector3d m_area_vector, m_normal;
  double m_area_vector_norm = 0.;
  bool m_defined = true;
  Star_buffer<Face> m_faces;
};

// ----------------------------------------------------------------------------------------------
// The energies: each returns E and, if `s` is given, fills the sensitivities
// ----------------------------------------------------------------------------------------------

/// E^P, eqs. 1-2 (first expression of eq. 1), and eq. 5 (`use_max`).
inline double combinatorial_energy(const Star_geometry& g, bool use_max, Star_sensitivities* s)
{
  // eq. 1: (1/n) sum_{f in region} |N_f - Nbar|^2
  auto mean_squared_deviation = [&g](std::size_t first, std::size_t count, Eigen::Vector3d* mean) {
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    for(std::size_t i = 0; i < count; ++i)
      sum += g.normal(region_face(g, first, i));
    const Eigen::Vector3d average = sum / double(count);
    double deviation = 0.;
    for(std::size_t i = 0; i < count; ++i)
      deviation += (g.normal(region_face(g, first, i)) - average).squaredNorm();
    if(mean)
      *mean = average;
    return deviation / double(count);
  };
  // eq. 5: max_{a, b in region} |N_a - N_b|^2 and the first pair attaining it
  auto largest_squared_difference = [&g](std::size_t first, std::size_t count, std::size_t* pair) {
    double largest = 0.;
    for(std::size_t i = 0; i < count; ++i)
      for(std::size_t j = i + 1; j < count; ++j)
      {
        const std::size_t a = region_face(g, first, i), b = region_face(g, first, j);
        const double d = (g.normal(a) - g.normal(b)).squaredNorm();
        if(d > largest)
        {
          largest = d;
          if(pair)
          {
            pair[0] = a;
            pair[1] = b;
          }
        }
      }
    return largest;
  };

  Splitting best;
  bool found = false;
  const double energy =
    use_max ? smallest_over_splittings(
                g, true, [&](std::size_t f, std::size_t c) { return largest_squared_difference(f, c, nullptr); },
                best, found)
            : smallest_over_splittings(
                g, false, [&](std::size_t f, std::size_t c) { return mean_squared_deviation(f, c, nullptr); },
                best, found);
  if(!s || !found)
    return energy;

  if(use_max)
  {
    // the region attaining the max (the first on ties) and its largest pair:
    // d|N_a - N_b|^2 = 2 (N_a - N_b) . (dN_a - dN_b)
    std::size_t pair[2][2] = {{0, 0}, {0, 0}};
    const double c0 = largest_squared_difference(best.first[0], best.count[0], pair[0]);
    const double c1 = largest_squared_difference(best.first[1], best.count[1], pair[1]);
    const int r = c1 > c0 ? 1 : 0;
    if((r == 0 ? c0 : c1) > 0.)
    {
      const std::size_t a = pair[r][0], b = pair[r][1];
      const Eigen::Vector3d d = 2. * (g.normal(a) - g.normal(b));
      s->normal[a] += d;
      s->normal[b] -= d;
    }
  }
  else
  {
    // d/dN_f of (1/n) sum_g |N_g - Nbar|^2 = (2/n) (N_f - Nbar): the terms through Nbar cancel,
    // since the deviations sum to zero
    for(int r = 0; r < 2; ++r)
    {
      Eigen::Vector3d average;
      mean_squared_deviation(best.first[r], best.count[r], &average);
      for(std::size_t i = 0; i < best.count[r]; ++i)
      {
        const std::size_t f = region_face(g, best.first[r], i);
        s->normal[f] += (2. / double(best.count[r])) * (g.normal(f) - average);
      }
    }
  }
  return energy;
}

/// E^lambda, eqs. 3-4 and 10. `eigenvector`, if given, receives the unit eigenvector of the
/// smallest eigenvalue (the ruling direction: the normal of the plane the face normals are
/// closest to).
inline double covariance_energy(const Star_geometry& g, Star_sensitivities* s, Eigen::Vector3d* eigenvector = nullptr)
{
  Eigen::Matrix3d A = Eigen::Matrix3d::Zero();
  Star_buffer<Eigen::Vector3d> normals(g.number_of_faces());
  for(std::size_t f = 0; f < g.number_of_faces(); ++f)
  {
    normals[f] = g.normal(f);
    A += g.angle(f) * normals[f] * normals[f].transpose();
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(A);
  const Eigen::Vector3d u = eigen.eigenvectors().col(0);
  if(eigenvector)
    *eigenvector = u;
  return s ? smallest_eigenvalue(g, normals.data(), u, s->angle.data(), s->normal.data())
           : smallest_eigenvalue(g, normals.data(), u);
}

/// Eq. 6, appendix B.4: min over unit u of max_f <u, N_f>^2 by the circumcentres of triples of
/// sites {+-N_f}.
inline double covariance_max_energy(const Star_geometry& g, Star_sensitivities* s)
{
  const std::size_t m = g.number_of_faces();
  Star_buffer<Eigen::Vector3d> normals(m), sites(2 * m);
  for(std::size_t f = 0; f < m; ++f)
  {
    normals[f] = g.normal(f);
    sites[2 * f] = normals[f]; // site 2f is +N_f, site 2f + 1 is -N_f
    sites[2 * f + 1] = -normals[f];
  }

  double best = std::numeric_limits<double>::infinity();
  std::array<std::size_t, 3> best_sites{};
  // Sites of three distinct faces; a triple and its opposite have the same circumcentre (up to
  // sign), so the first site is positive: 4 sign patterns per triple of faces.
  for(std::size_t a = 0; a < 2 * m; a += 2)
    for(std::size_t b = a + 2; b < 2 * m; ++b)
      for(std::size_t c = (b | 1) + 1; c < 2 * m; ++c)
      {
        const Eigen::Vector3d n = (sites[b] - sites[a]).cross(sites[c] - sites[a]);
        const double length = n.norm();
        if(length <= site_triangle_tolerance)
          continue;
        const Eigen::Vector3d w = n / length;
        // phi(w) >= <w, q_a>^2, the squared cosine of the circumradius: prune small circles
        if(w.dot(sites[a]) * w.dot(sites[a]) >= best)
          continue;
        const Largest_alignment phi = largest_squared_alignment(w, normals.data(), m, best);
        if(phi.value < best)
        {
          best = phi.value;
          best_sites = {a, b, c};
        }
      }
  if(best == std::numeric_limits<double>::infinity())
    return 0.; // fewer than 3 faces, or all normals parallel: phi = 0 at u = N_a x N_b (or u _|_ N)

  if(s)
  {
    // E = <w, N_mu>^2, w = n / |n|, n = (q_b - q_a) x (q_c - q_a), q = sigma N_f:
    //   dE/dN_mu += 2 <w, N_mu> w;
    //   <N_mu, dw> = <t, dn>, t = (I - w w^T) N_mu / |n|, and <t, dn> = sum_s <dq_s, (q_{s+1} - q_{s+2}) x t>
    //   (cyclic in a, b, c), so dE/dN_{f_s} += 2 <w, N_mu> sigma_s (q_{s+1} - q_{s+2}) x t.
    const std::array<Eigen::Vector3d, 3> q = {sites[best_sites[0]], sites[best_sites[1]], sites[best_sites[2]]};
    const Eigen::Vector3d n = (q[1] - q[0]).cross(q[2] - q[0]);
    const double length = n.norm();
    const Eigen::Vector3d w = n / length;
    const Largest_alignment phi = largest_squared_alignment(w, normals.data(), m, std::numeric_limits<double>::infinity());
    const Eigen::Vector3d& M = normals[phi.face];
    const double alignment = w.dot(M);
    s->normal[phi.face] += 2. * alignment * w;
    const Eigen::Vector3d t = (M - alignment * w) / length;
    for(int i = 0; i < 3; ++i)
    {
      const double sigma = best_sites[i] % 2 == 0 ? 1. : -1.;
      s->normal[best_sites[i] / 2] += (2. * alignment * sigma) * (q[(i + 1) % 3] - q[(i + 2) % 3]).cross(t);
    }
  }
  return best;
}

/// Appendix B.5: smallest eigenvalue of sum_f theta_f Ntilde_f Ntilde_f^T in the tangent plane.
inline double intrinsic_energy(const Star_geometry& g, Star_sensitivities* s)
{
  const Log_mapped_normals log_map(g);
  const std::size_t m = g.number_of_faces();
  // 2x2 matrix in an orthonormal basis (t_1, t_2) of the tangent plane; lambda and the 3D
  // eigenvector u = T u_2 do not depend on the choice of basis, nor does d lambda = u^T dA u
  // (the basis terms give 2 lambda u_2^T T^T dT u_2 = 0, T^T dT being antisymmetric).
  Eigen::Matrix<double, 3, 2> T;
  T.col(0) = log_map.vertex_normal().unitOrthogonal();
  T.col(1) = log_map.vertex_normal().cross(T.col(0));
  Eigen::Matrix2d A = Eigen::Matrix2d::Zero();
  for(std::size_t f = 0; f < m; ++f)
  {
    const Eigen::Vector2d t = T.transpose() * log_map.image(f);
    A += g.angle(f) * t * t.transpose();
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eigen(A);
  const Eigen::Vector3d u = T * eigen.eigenvectors().col(0);
  Star_buffer<Eigen::Vector3d> buffer;
  const Eigen::Vector3d* images = log_map.images(buffer);
  if(!s)
    return smallest_eigenvalue(g, images, u);
  if(!log_map.defined())
  {
    s->zero_gradient = true;
    return smallest_eigenvalue(g, images, u);
  }
  Star_buffer<Eigen::Vector3d> d_images(m, Eigen::Vector3d::Zero());
  const double lambda = smallest_eigenvalue(g, images, u, s->angle.data(), d_images.data());
  log_map.pull_back(d_images.data(), *s);
  return lambda;
}

/// Appendix B.5.1: min over tangent unit u of max_f <u, Ntilde_f>^2, over the directions
/// perpendicular to the segments between points of {+-Ntilde_f}.
inline double intrinsic_width_energy(const Star_geometry& g, Star_sensitivities* s)
{
  const Log_mapped_normals log_map(g);
  const std::size_t m = g.number_of_faces();
  const Eigen::Vector3d& N_v = log_map.vertex_normal();
  Star_buffer<Eigen::Vector3d> buffer;
  const Eigen::Vector3d* images = log_map.images(buffer);

  // pairs x_a = +Ntilde_a, x_b = sign * Ntilde_b of distinct faces a < b (a pair and its
  // opposite give the same direction)
  double best = std::numeric_limits<double>::infinity();
  std::size_t best_a = 0, best_b = 0;
  double best_sign = 1.;
  for(std::size_t a = 0; a < m; ++a)
    for(std::size_t b = a + 1; b < m; ++b)
      for(double sign : {1., -1.})
      {
        const Eigen::Vector3d d = images[a] - sign * images[b];
        const double length = d.norm();
        if(length <= tangent_segment_tolerance)
          continue;
        const Eigen::Vector3d u = N_v.cross(d) / length;
        // phi(u) >= <u, x_a>^2, the squared distance of the line (x_a, x_b) to the origin
        if(u.dot(images[a]) * u.dot(images[a]) >= best)
          continue;
        const Largest_alignment phi = largest_squared_alignment(u, images, m, best);
        if(phi.value < best)
        {
          best = phi.value;
          best_a = a;
          best_b = b;
          best_sign = sign;
        }
      }
  if(best == std::numeric_limits<double>::infinity())
    return 0.; // a single face, or every image is 0 (a flat star): phi = 0 at u _|_ Ntilde

  if(s)
  {
    if(!log_map.defined())
      s->zero_gradient = true;
    else
    {
      // E = <u, y>^2, y = Ntilde_mu, u = N_v x d / |d|, d = x_a - x_b:
      //   dE/dNtilde_mu += 2 <u, y> u;
      //   <y, du> = <dd, y x N_v - <u, y> d / |d|> / |d|  (the explicit dependence of u on N_v
      //   gives <dN_v, d x y> / |d| = 0, as d x y is parallel to N_v and dN_v is tangent).
      const Eigen::Vector3d d = images[best_a] - best_sign * images[best_b];
      const double length = d.norm();
      const Eigen::Vector3d u = N_v.cross(d) / length;
      const Largest_alignment phi = largest_squared_alignment(u, images, m, std::numeric_limits<double>::infinity());
      const Eigen::Vector3d& y = images[phi.face];
      const double alignment = u.dot(y);
      Star_buffer<Eigen::Vector3d> d_images(m, Eigen::Vector3d::Zero());
      d_images[phi.face] += 2. * alignment * u;
      const Eigen::Vector3d d_d = (2. * alignment / length) * (y.cross(N_v) - alignment * d / length);
      d_images[best_a] += d_d;
      d_images[best_b] -= best_sign * d_d;
      log_map.pull_back(d_images.data(), *s);
    }
  }
  return best;
}

/// Omega = 2 pi (closed) or pi (open) minus the angle sum of the star.
inline double angle_defect(const Star_geometry& g)
{
  double defect = g.closed() ? two_pi : pi;
  for(std::size_t f = 0; f < g.number_of_faces(); ++f)
    defect -= g.angle(f);
  return defect;
}

/// Omega^2; dE/dtheta_f = -2 Omega.
inline double squared_angle_defect_energy(const Star_geometry& g, Star_sensitivities* s)
{
  const double defect = angle_defect(g);
  if(s)
    for(std::size_t f = 0; f < g.number_of_faces(); ++f)
      s->angle[f] = -2. * defect;
  return defect * defect;
}

/// |Omega| (the L1 variant of Fig. 11); dE/dtheta_f = -sign(Omega), and 0 (a subgradient) where
/// |Omega| is within the rounding of the angle sum (4 pi 2^-40, about 1e-11): a flat or hinge
/// star is a minimum whose gradient vanishes, as for the other energies.
inline double absolute_angle_defect_energy(const Star_geometry& g, Star_sensitivities* s)
{
  const double defect = angle_defect(g);
  if(s)
  {
    const double rounding = 4. * pi * std::ldexp(1., -40);
    const double sign = defect > rounding ? 1. : (defect < -rounding ? -1. : 0.);
    for(std::size_t f = 0; f < g.number_of_faces(); ++f)
      s->angle[f] = -sign;
  }
  return std::abs(defect);
}

// ----------------------------------------------------------------------------------------------
// One star, and the sum over a mesh
// ----------------------------------------------------------------------------------------------

/// The energy `e` of the star with centre `center` and ring `ring[0..degree)` (counter-clockwise;
/// `closed`: interior vertex, else an open fan starting and ending at the boundary). If
/// `gradient` is not null it receives degree + 1 vectors: the gradient with respect to the
/// centre, then to each ring vertex (zero for a degenerate star, see the design note). A star
/// with no face has energy 0.
inline double star_energy(Developability_energy e, const Eigen::Vector3d& center, const Eigen::Vector3d* ring,
                          std::size_t degree, bool closed, Eigen::Vector3d* gradient)
{
  const Star_geometry g(center, ring, degree, closed);
  if(gradient)
    std::fill(gradient, gradient + degree + 1, Eigen::Vector3d::Zero());
  if(g.number_of_faces() == 0)
    return 0.;

  Star_sensitivities sensitivities(g.number_of_faces());
  Star_sensitivities* s = gradient && !g.degenerate() ? &sensitivities : nullptr;
  double energy = 0.;
  switch(e)
  {
    case Developability_energy::combinatorial: energy = combinatorial_energy(g, false, s); break;
    case Developability_energy::combinatorial_max: energy = combinatorial_energy(g, true, s); break;
    case Developability_energy::covariance: energy = covariance_energy(g, s); break;
    case Developability_energy::covariance_max: energy = covariance_max_energy(g, s); break;
    case Developability_energy::intrinsic: energy = intrinsic_energy(g, s); break;
    case Developability_energy::intrinsic_width: energy = intrinsic_width_energy(g, s); break;
    case Developability_energy::squared_angle_defect: energy = squared_angle_defect_energy(g, s); break;
    case Developability_energy::absolute_angle_defect: energy = absolute_angle_defect_energy(g, s); break;
  }
  if(s && !s->zero_gradient)
    pull_back(g, *s, gradient);
  return energy;
}

/// The star of vertex v, its ring positions gathered from `x`.
inline Star_buffer<Eigen::Vector3d> ring_positions(const Vertex_stars& stars, const std::vector<Eigen::Vector3d>& x,
                                                   std::size_t v)
{
  Star_buffer<Eigen::Vector3d> ring(stars.degree(v));
  const std::size_t* r = stars.ring_of(v);
  for(std::size_t k = 0; k < ring.size(); ++k)
    ring[k] = x[r[k]];
  return ring;
}

/// The sum of the energy `e` over the active stars, at vertex positions `x` (indexed like the
/// stars). If `gradient` is not null it receives its gradient per vertex; `per_vertex`, if not
/// null, the energy of every star (0 for inactive ones).
///
/// Two passes: every active star's energy and gradient block (vertex_stars.h), then, per vertex,
/// the sum of its slots in the fixed order of the gather lists; the total is summed over the
/// stars in vertex order. With `parallel` and TBB linked (CGAL_LINKED_WITH_TBB) both passes run
/// with tbb::parallel_for; the results are bitwise identical to the sequential ones, whatever
/// the number of threads.
/// \pre `x.size() == stars.number_of_vertices()`
inline double developability_energy(const Vertex_stars& stars, const std::vector<Eigen::Vector3d>& x,
                                    Developability_energy e, std::vector<Eigen::Vector3d>* gradient,
                                    std::vector<double>* per_vertex, bool parallel)
{
  const std::size_t nv = stars.number_of_vertices();
  CGAL_precondition(x.size() == nv);
  std::vector<double> energy(nv, 0.);
  std::vector<Eigen::Vector3d> blocks(gradient ? stars.number_of_slots() : 0);

  const std::vector<std::size_t>& active = stars.active_vertices;
  for_each_index(active.size(), parallel, [&](std::size_t i) {
    const std::size_t v = active[i];
    const Star_buffer<Eigen::Vector3d> ring = ring_positions(stars, x, v);
    energy[v] = star_energy(e, x[v], ring.data(), ring.size(), stars.closed[v],
                            gradient ? blocks.data() + stars.block_begin(v) : nullptr);
  });

  if(gradient)
  {
    gradient->resize(nv);
    for_each_index(nv, parallel, [&](std::size_t p) {
      Eigen::Vector3d sum = Eigen::Vector3d::Zero();
      for(std::size_t j = stars.gather_begin[p]; j < stars.gather_begin[p + 1]; ++j)
        sum += blocks[stars.gather_slot[j]];
      (*gradient)[p] = sum;
    });
  }

  double total = 0.;
  for(std::size_t v : active)
    total += energy[v];
  if(per_vertex)
    *per_vertex = std::move(energy);
  return total;
}

/// What the cut and the metrics of a developable design need at every vertex.
struct Vertex_star_descriptors
{
  /// Unit eigenvector of the smallest eigenvalue of the covariance A_i (eq. 4): the normal of the
  /// plane closest to the face normals, i.e. the estimated ruling direction (section 4.4); sign
  /// arbitrary; 0 for a vertex without face.
  std::vector<Eigen::Vector3d> ruling_direction;
  /// The intrinsic energy lambda_i of the star (appendix B.5; section 4.4 cuts where it exceeds a
  /// tolerance).
  std::vector<double> intrinsic_lambda;
};

/// The descriptors of every vertex star, active or not (an inactive star's values are computed
/// the same way).
inline Vertex_star_descriptors vertex_star_descriptors(const Vertex_stars& stars, const std::vector<Eigen::Vector3d>& x,
                                                       bool parallel)
{
  const std::size_t nv = stars.number_of_vertices();
  CGAL_precondition(x.size() == nv);
  Vertex_star_descriptors d;
  d.ruling_direction.assign(nv, Eigen::Vector3d::Zero());
  d.intrinsic_lambda.assign(nv, 0.);
  for_each_index(nv, parallel, [&](std::size_t v) {
    const Star_buffer<Eigen::Vector3d> ring = ring_positions(stars, x, v);
    const Star_geometry g(x[v], ring.data(), ring.size(), stars.closed[v]);
    if(g.number_of_faces() == 0)
      return;
    covariance_energy(g, nullptr, &d.ruling_direction[v]);
    d.intrinsic_lambda[v] = intrinsic_energy(g, nullptr);
  });
  return d;
}

} // namespace internal
} // namespace Surface_design
} // namespace CGAL

#endif // CGAL_SURFACE_DESIGN_INTERNAL_DEVELOPABILITY_STAR_ENERGIES_H
