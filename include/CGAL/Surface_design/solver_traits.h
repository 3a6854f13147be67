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
#include <Eigen/SparseLU>

#if defined(CGAL_SURFACE_DESIGN_HAS_CHOLMOD)
#include <Eigen/CholmodSupport>
#endif

#if defined(CGAL_SURFACE_DESIGN_HAS_METIS)
#include <Eigen/MetisSupport>
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
/// Eigen's `CholmodSupernodalLLT` with CHOLMOD's fill-reducing ordering fixed to AMD. CHOLMOD's
/// default tries AMD and then, when AMD's fill looks high (it always does on mesh Laplacians),
/// METIS too, keeping the better: on a 1M-vertex mesh Laplacian that analysis took 5.9 s for a
/// factorization of 3.1 s, whereas AMD alone analyses in 0.7 s and factors in 3.5 s (measured on
/// the 2-core development machine with OpenBLAS). AMD-only is the better total for a
/// factor-once, solve-many use at every size we measured.
template <class MatrixType>
class Cholmod_amd_supernodal_llt : public Eigen::CholmodSupernodalLLT<MatrixType>
{
public:
  Cholmod_amd_supernodal_llt()
  {
    this->cholmod().nmethods = 1;
    this->cholmod().method[0].ordering = CHOLMOD_AMD;
  }
};

/// \ingroup PkgSurfaceDesignRef
/// SuiteSparse CHOLMOD's supernodal Cholesky factorization (AMD ordering, see
/// `Cholmod_amd_supernodal_llt`) behind `CGAL::Eigen_solver_traits`. Defined when the library was
/// configured with CHOLMOD (macro `CGAL_SURFACE_DESIGN_HAS_CHOLMOD`, set by the CMake target). Its
/// supernodal kernels call BLAS: with an optimized BLAS (Debian: `libopenblas-dev`) the
/// factorization of large Laplacians is several times faster than with the reference BLAS.
using Cholmod_solver_traits =
  CGAL::Eigen_solver_traits<Cholmod_amd_supernodal_llt<CGAL::Eigen_sparse_matrix<double>::EigenType>>;
#endif

#if defined(CGAL_SURFACE_DESIGN_HAS_METIS) || defined(DOXYGEN_RUNNING)
/// \ingroup PkgSurfaceDesignRef
/// Eigen's `SimplicialLDLT` as in `Default_solver_traits`, but with the nested-dissection
/// fill-reducing ordering of METIS (`METIS_NodeND`) instead of AMD. Nested dissection targets the
/// fill-in of large 2D-like graphs such as mesh Laplacians, where AMD's fill grows faster; the
/// factorization itself stays simplicial, single-threaded and BLAS-free. Its LDLT pivots are
/// exposed as for the default, so `Factored_system` checks positive definiteness the same way.
/// Defined when the library was configured with METIS (macro `CGAL_SURFACE_DESIGN_HAS_METIS`, set
/// by the CMake target; Debian: `libmetis-dev`) built with 32-bit indices (`IDXTYPEWIDTH` 32, the
/// default): Eigen's `MetisOrdering<int>` passes `int` arrays to METIS.
using Metis_ldlt_solver_traits =
  CGAL::Eigen_solver_traits<Eigen::SimplicialLDLT<CGAL::Eigen_sparse_matrix<double>::EigenType,
                                                  Eigen::Lower, Eigen::MetisOrdering<int>>>;
#endif

/// \ingroup PkgSurfaceDesignRef
/// Eigen's sparse LU factorization (`SparseLU`, COLAMD ordering) behind `CGAL::Eigen_solver_traits`:
/// for the systems of the library that are not symmetric (e.g. barycentric embeddings with
/// mean-value weights). Header-only, like the default.
using Sparse_lu_solver_traits =
  CGAL::Eigen_solver_traits<Eigen::SparseLU<CGAL::Eigen_sparse_matrix<double>::EigenType,
                                            Eigen::COLAMDOrdering<int>>>;

} // namespace Surface_design
} // namespace CGAL

#endif // CGAL_SURFACE_DESIGN_SOLVER_TRAITS_H
