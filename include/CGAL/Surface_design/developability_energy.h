// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The choice of developability energy (Stein, Grinspun & Crane 2018, "Developability of triangle
// meshes", section 4.1 and appendix B).

#ifndef CGAL_SURFACE_DESIGN_DEVELOPABILITY_ENERGY_H
#define CGAL_SURFACE_DESIGN_DEVELOPABILITY_ENERGY_H

namespace CGAL {
namespace Surface_design {

/// \ingroup PkgDevelopabilityRef
/// The measure of non-developability of one vertex star, summed over the stars that carry energy.
///
/// A star is a *hinge* (Definition 3.1) when its triangles split into two edge-connected regions of
/// constant normal; a mesh whose stars are all hinges is discretely developable. Every energy
/// except `squared_angle_defect` and `absolute_angle_defect` is zero exactly on hinge (and flat) stars. All are dimensionless:
/// invariant under rigid motions and under scaling of the mesh. The formulas, with the paper's
/// equation numbers and the choices made where the paper leaves room, are in
/// `internal/Developability/star_energies.h`.
enum class Developability_energy
{
  /// E^P (eqs. 1-2): the smallest, over the splittings of the star's faces into two contiguous
  /// regions, of the summed mean squared deviation of the face normals from their region's mean.
  combinatorial,
  /// Eq. 5: like `combinatorial`, with the largest squared difference of two normals in a region,
  /// maximized over the two regions (no branching of the rulings, section 4.1.4).
  combinatorial_max,
  /// E^lambda (eqs. 3-4): the smallest eigenvalue of the angle-weighted covariance of the face
  /// normals, sum_f theta_f N_f N_f^T.
  covariance,
  /// Eq. 6 (appendix B.4): min over unit u of max_f <u, N_f>^2, the squared half width of the
  /// star's Gauss image.
  covariance_max,
  /// Appendix B.5: `covariance` with the face normals mapped to the tangent plane of the
  /// area-weighted vertex normal by the logarithmic map of the sphere (no spikes).
  intrinsic,
  /// Appendix B.5.1: the intrinsic analogue of `covariance_max`, the squared half minimum width
  /// of the convex hull of the log-mapped normals and their opposites.
  intrinsic_width,
  /// The baseline of Fig. 7: the squared angle defect Omega_i^2 (Omega_i = 2 pi minus the angle
  /// sum at an interior vertex, pi minus it at a boundary vertex). Zero on every flattenable
  /// star, including crumpled ones: it measures flattenability, not developability.
  squared_angle_defect,
  /// The L1 variant of Fig. 11: the absolute angle defect |Omega_i|, whose sum is the L1 norm of
  /// the discrete Gaussian curvature. Sparsity-inducing: the flow concentrates the curvature on
  /// few vertices and leaves flat regions between them (a piecewise *flat* surface), where the
  /// other energies leave curved hinges (piecewise developable). Its subgradient at Omega_i = 0
  /// is taken as 0.
  absolute_angle_defect
};

/// \ingroup PkgDevelopabilityRef
/// The cost of an edge in the cut of `compute_developable_cut()`; u_a, u_b are the unit
/// eigenvectors of the smallest eigenvalue lambda at the edge's ends (the rulings of hinges), e^
/// the unit edge direction.
enum class Developable_cut_cost
{
  /// |e| (1 + w (|u_a x e^| + |u_b x e^|) / 2), w = `ruling_alignment_weight`: cuts run along the
  /// rulings (straight lines in space and in the pattern), as the reference code's cost does.
  ruling_alignment,
  /// |e| (|<u_a, e^>| + |<u_b, e^>|) / 2: the paper's words (sec. 4.4, "length times the inner
  /// product of the edge direction and the small eigenvector"); cuts run across the rulings,
  /// along the other principal direction, where an edge costs nothing.
  paper
};

/// \ingroup PkgDevelopabilityRef
/// The enumerator's name, as written in the code (e.g. "covariance_max").
inline const char* to_string(Developability_energy e)
{
  switch(e)
  {
    case Developability_energy::combinatorial: return "combinatorial";
    case Developability_energy::combinatorial_max: return "combinatorial_max";
    case Developability_energy::covariance: return "covariance";
    case Developability_energy::covariance_max: return "covariance_max";
    case Developability_energy::intrinsic: return "intrinsic";
    case Developability_energy::intrinsic_width: return "intrinsic_width";
    case Developability_energy::squared_angle_defect: return "squared_angle_defect";
    case Developability_energy::absolute_angle_defect: return "absolute_angle_defect";
  }
  return "unknown Developability_energy";
}

} // namespace Surface_design
} // namespace CGAL

#endif // CGAL_SURFACE_DESIGN_DEVELOPABILITY_ENERGY_H
