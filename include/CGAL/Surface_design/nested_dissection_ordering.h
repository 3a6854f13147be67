// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A fill-reducing ordering built for the systems of surface meshes, and the solver traits that use
// it. A header of its own (not `solver_traits.h`) so that code that keeps the default solver does
// not compile the ordering.

#ifndef CGAL_SURFACE_DESIGN_NESTED_DISSECTION_ORDERING_H
#define CGAL_SURFACE_DESIGN_NESTED_DISSECTION_ORDERING_H

#include <CGAL/Surface_design/solver_traits.h>
#include <CGAL/Surface_design/internal/Core/nested_dissection.h>

#include <CGAL/Eigen_solver_traits.h>
#include <CGAL/Eigen_matrix.h>

#include <Eigen/SparseCholesky>

namespace CGAL {
namespace Surface_design {

/// \ingroup PkgSurfaceDesignRef
/// Nested-dissection fill-reducing ordering of the symmetric pattern of a sparse matrix, as an
/// Eigen ordering functor (the `Ordering` parameter of `Eigen::SimplicialLDLT`,
/// `Eigen::SimplicialLLT`, like `Eigen::AMDOrdering`): breadth-first level-set separators from a
/// pseudo-peripheral vertex, refined by Fiduccia-Mattheyses moves, recursively, with exact minimum
/// degree on parts of at most 64 vertices. Built for the graphs of surface meshes (level sets are
/// short rings), it needs no coordinates and works on any pattern (real or complex matrices, one
/// triangle or both stored, several components).
///
/// Complexity: O(n log n) time, O(n + nnz) memory. On the cotangent Laplacians of large meshes its
/// factors need 1.5-2 times fewer flops than AMD's, at about the cost of AMD; METIS's orderings
/// need fewer still but cost several times more (see the benchmark's `ordering` workload).
template <class StorageIndex>
using Nested_dissection_ordering = internal::Nested_dissection_ordering<StorageIndex>;

/// \ingroup PkgSurfaceDesignRef
/// Eigen's `SimplicialLDLT` (as `Default_solver_traits`) with `Nested_dissection_ordering`
/// instead of AMD, behind `CGAL::Eigen_solver_traits`: header-only, single-threaded, BLAS-free;
/// the better choice for large meshes (see the manual's performance section). Its LDLT pivots are
/// exposed as for the default, so positive definiteness is checked the same way.
using Nested_dissection_ldlt_solver_traits =
  CGAL::Eigen_solver_traits<Eigen::SimplicialLDLT<CGAL::Eigen_sparse_matrix<double>::EigenType, Eigen::Lower,
                                                  Nested_dissection_ordering<int>>>;

} // namespace Surface_design
} // namespace CGAL

#endif // CGAL_SURFACE_DESIGN_NESTED_DISSECTION_ORDERING_H
