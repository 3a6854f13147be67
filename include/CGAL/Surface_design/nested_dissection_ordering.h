// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A fill-reducing ordering built for the systems of surface meshes, and the solver traits that use
// it. A header of its own (not `solver_traits.h`) so that code that keeps the default solver does
// not compile the ordering.

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

/// \ingroup PkgSurfaceDesignRef
/// Nested-dissection fill-reducing ordering of the symmetric pattern of a sparse matrix, as an
/// Eigen ordering functor (the `Ordering` parameter of `Eigen::SimplicialLDLT`,
/// `Eigen::SimplicialLLT`, like `Eigen::AMDOrdering`): breadth-first level-set separators from a
/// pseudo-peripheral vertex, refined by Fiduccia-Mattheyses moves, recursively, with exact minimum
/// degree on parts of at most 64 vertices. Built for the graphs of surface meshes (level sets are
/// short rings), it needs no coordinates and works on any pattern (real or complex matrices, one
/// triangle or both stored, several components).
///
/// Complexity: O(n log n) time, O(n + nnz) memory. On the cotangent Laplacians of meshes of 30k to
/// 480k vertices its factors need 1.5 to 2.3 times fewer flops than AMD's, for 1 to 2.5 times
/// AMD's ordering time; METIS's orderings need fewer flops still but cost 2 to 5 times more. Below
/// about 20k unknowns AMD is the better choice (see the benchmark's `factorization` workload and
/// the foundation manual, section Solvers).
template <class StorageIndex>
using Nested_dissection_ordering = internal::Nested_dissection_ordering<StorageIndex>;

/// \ingroup PkgSurfaceDesignRef
/// Eigen's `SimplicialLDLT` (as `Default_solver_traits`) with `Nested_dissection_ordering`
/// instead of AMD, behind `CGAL::Eigen_solver_traits`: header-only, single-threaded, BLAS-free;
/// the better choice for meshes of more than about 30k vertices. Its LDLT pivots are
/// exposed as for the default, so positive definiteness is checked the same way. The first solve
/// of a 30k-vertex Laplacian is 1.3 times faster than with the default, of a 480k-vertex one 2.3
/// times.
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
