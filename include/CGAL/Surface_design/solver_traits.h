// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The sparse solvers the library is tested with, as models of CGAL's
// `SparseLinearAlgebraWithFactorTraits_d` concept.

#ifndef CGAL_SURFACE_DESIGN_SOLVER_TRAITS_H
#define CGAL_SURFACE_DESIGN_SOLVER_TRAITS_H

#include <CGAL/Eigen_solver_traits.h>
#include <CGAL/Eigen_matrix.h>

#include <Eigen/SparseCholesky>

#if defined(CGAL_SURFACE_DESIGN_HAS_CHOLMOD)
#include <Eigen/CholmodSupport>
#endif

namespace CGAL {
namespace Surface_design {

/// \ingroup PkgSurfaceDesignRef
/// Default solver of every algorithm: Eigen's `SimplicialLDLT` (with its AMD fill-reducing
/// ordering) behind `CGAL::Eigen_solver_traits`. Header-only, no dependency beyond Eigen.
using Default_solver_traits =
  CGAL::Eigen_solver_traits<Eigen::SimplicialLDLT<CGAL::Eigen_sparse_matrix<double>::EigenType>>;

#if defined(CGAL_SURFACE_DESIGN_HAS_CHOLMOD) || defined(DOXYGEN_RUNNING)
/// \ingroup PkgSurfaceDesignRef
/// SuiteSparse CHOLMOD's supernodal Cholesky factorization behind `CGAL::Eigen_solver_traits`.
/// Defined when the library was configured with CHOLMOD (macro `CGAL_SURFACE_DESIGN_HAS_CHOLMOD`,
/// set by the CMake target). Its supernodal kernels call BLAS: with an optimized BLAS (Debian:
/// `libopenblas-dev`) the factorization of large Laplacians is several times faster than with the
/// reference BLAS.
using Cholmod_solver_traits =
  CGAL::Eigen_solver_traits<Eigen::CholmodSupernodalLLT<CGAL::Eigen_sparse_matrix<double>::EigenType>>;
#endif

} // namespace Surface_design
} // namespace CGAL

#endif // CGAL_SURFACE_DESIGN_SOLVER_TRAITS_H
