// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The library's own supernodal Cholesky factorization: `Supernodal_cholesky` (an Eigen sparse
// solver, real or complex), `Supernodal_solver_traits` (the same behind CGAL's solver traits),
// `Nested_dissection_ordering` (its fill-reducing ordering, also usable as an Eigen ordering) and
// `Symbolic_analysis_cache` (analyses shared by the systems of one mesh). The definitions live in
// the solver wing, `internal/Solvers/`.

#ifndef CGAL_SURFACE_DESIGN_SUPERNODAL_CHOLESKY_H
#define CGAL_SURFACE_DESIGN_SUPERNODAL_CHOLESKY_H

#include <CGAL/Surface_design/internal/Solvers/Supernodal_cholesky.h>

#endif // CGAL_SURFACE_DESIGN_SUPERNODAL_CHOLESKY_H
