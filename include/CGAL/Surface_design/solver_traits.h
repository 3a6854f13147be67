// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The sparse solvers of the library, as models of CGAL's `SparseLinearAlgebraWithFactorTraits_d`
// concept, to pass as `sparse_linear_solver` to every function and class that solves:
// - `Default_solver_traits`: `Size_switched_cholesky`, the simplicial LDLT with AMD for small
//   systems, the library's supernodal Cholesky with nested dissection for large ones;
// - `Simplicial_ldlt_solver_traits`, `Supernodal_solver_traits`: one of the two, always;
// - `Nested_dissection_ldlt_solver_traits`: the simplicial LDLT with the library's ordering;
// - `Cholmod_solver_traits` (with CHOLMOD), `Metis_ldlt_solver_traits` (with METIS);
// - `Sparse_lu_solver_traits`: for the systems that are not symmetric.
// Any other model of the concept works too (Hermitian systems then go through their real form of
// twice the size). The definitions live in the solver wing, `internal/Solvers/`.

#ifndef CGAL_SURFACE_DESIGN_SOLVER_TRAITS_H
#define CGAL_SURFACE_DESIGN_SOLVER_TRAITS_H

#include <CGAL/Surface_design/internal/Solvers/solver_traits.h>

#endif // CGAL_SURFACE_DESIGN_SOLVER_TRAITS_H
