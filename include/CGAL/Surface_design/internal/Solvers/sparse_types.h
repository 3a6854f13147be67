// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The sparse matrix types of the library's systems (Eigen, column-major).

#ifndef CGAL_SURFACE_DESIGN_INTERNAL_SOLVERS_SPARSE_TYPES_H
#define CGAL_SURFACE_DESIGN_INTERNAL_SOLVERS_SPARSE_TYPES_H

#include <Eigen/SparseCore>

#include <complex>

namespace CGAL {
namespace Surface_design {
namespace internal {

using Sparse_matrix = Eigen::SparseMatrix<double>;
using Complex_sparse_matrix = Eigen::SparseMatrix<std::complex<double>>;

} // namespace internal
} // namespace Surface_design
} // namespace CGAL

#endif // CGAL_SURFACE_DESIGN_INTERNAL_SOLVERS_SPARSE_TYPES_H
