// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A fill-reducing ordering built for the systems of surface meshes (`Nested_dissection_ordering`,
// defined with the supernodal Cholesky factorization that uses it), and the simplicial solver
// traits that use it.

#ifndef CGAL_SURFACE_DESIGN_NESTED_DISSECTION_ORDERING_H
#define CGAL_SURFACE_DESIGN_NESTED_DISSECTION_ORDERING_H

#include <CGAL/Surface_design/solver_traits.h>
#include <CGAL/Surface_design/internal/Core/Hermitian_system.h>
#include <CGAL/Surface_design/internal/Core/nested_dissection.h>

#include <CGAL/Eigen_solver_traits.h>
#include <CGAL/Eigen_matrix.h>

#include <Eigen/SparseCholesky>

namespace CGAL {
namespace Surface_design {

// `Nested_dissection_ordering` is defined in supernodal_cholesky.h, included by solver_traits.h.

/// \ingroup PkgSurfaceDesignRef
/// Eigen's `SimplicialLDLT` (as `Simplicial_ldlt_solver_traits`) with `Nested_dissection_ordering`
/// instead of AMD, behind `CGAL::Eigen_solver_traits`: header-only, single-threaded, BLAS-free;
/// faster than AMD for meshes of more than about 30k vertices, slower than `Supernodal_solver_traits`
/// (which the default uses there). Its LDLT pivots are exposed, so positive definiteness is checked
/// the same way. The first solve of a 30k-vertex Laplacian is 1.3 times faster than with
/// `Simplicial_ldlt_solver_traits`, of a 480k-vertex one 2.3 times.
using Nested_dissection_ldlt_solver_traits =
  CGAL::Eigen_solver_traits<Eigen::SimplicialLDLT<CGAL::Eigen_sparse_matrix<double>::EigenType, Eigen::Lower,
                                                  Nested_dissection_ordering<int>>>;

namespace internal {

// Hermitian systems (the smoothest direction fields) factor with the same ordering in complex
// arithmetic, as with the library's other traits, rather than in the real form of twice the size.
template <>
struct Complex_solver_of<Nested_dissection_ldlt_solver_traits>
{
  using type = Eigen::SimplicialLDLT<Complex_sparse_matrix, Eigen::Lower, Nested_dissection_ordering<int>>;
};

} // namespace internal

} // namespace Surface_design
} // namespace CGAL

#endif // CGAL_SURFACE_DESIGN_NESTED_DISSECTION_ORDERING_H
