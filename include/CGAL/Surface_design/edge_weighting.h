// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The choice of edge weights shared by every algorithm built on a weighted graph Laplacian.

#ifndef CGAL_SURFACE_DESIGN_EDGE_WEIGHTING_H
#define CGAL_SURFACE_DESIGN_EDGE_WEIGHTING_H

namespace CGAL {
namespace Surface_design {

/// \ingroup PkgSurfaceDesignRef
/// The weights w_ij of the edges of a mesh in the weighted graph Laplacian
/// (L u)_i = sum_j w_ij (u_i - u_j) that an algorithm builds on: the least-squares energy of the
/// stripes (named parameter `weighting` of `Field_aligned_parameterizer`) or the barycentres of
/// the embedding (`weighting` of `Barycentric_embedder`). Each algorithm documents which of them
/// it accepts.
enum class Edge_weighting
{
  /// w_ij = 1: only the connectivity matters (the graph Laplacian).
  uniform,
  /// w_ij = (cot a_ij + cot b_ij) / 2 over the two angles opposite the edge (one term on a
  /// border edge): the cotangent Laplacian, i.e. the P1 finite-element stiffness matrix.
  /// Symmetric; negative on non-Delaunay edges. Triangle meshes only.
  cotangent,
  /// w_ij = (tan(alpha/2) + tan(beta/2)) / |x_j - x_i| (Floater's mean-value weights), alpha and
  /// beta the angles at i between edge ij and its neighbouring edges in the two incident faces.
  /// Positive but not symmetric (w_ij != w_ji). Any polygon faces.
  mean_value
};

/// \ingroup PkgSurfaceDesignRef
/// Name of an `Edge_weighting` ("uniform", "cotangent", "mean-value").
inline const char* to_string(Edge_weighting w)
{
  switch(w)
  {
    case Edge_weighting::uniform: return "uniform";
    case Edge_weighting::cotangent: return "cotangent";
    case Edge_weighting::mean_value: return "mean-value";
  }
  return "unknown";
}

} // namespace Surface_design
} // namespace CGAL

#endif // CGAL_SURFACE_DESIGN_EDGE_WEIGHTING_H
