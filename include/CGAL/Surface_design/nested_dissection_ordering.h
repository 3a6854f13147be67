// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A fill-reducing ordering built for the systems of surface meshes, `Nested_dissection_ordering`
// (an Eigen ordering functor), and `Nested_dissection_ldlt_solver_traits`, Eigen's simplicial LDLT
// with that ordering. The definitions live in the solver wing, `internal/Solvers/`.

#ifndef CGAL_SURFACE_DESIGN_NESTED_DISSECTION_ORDERING_H
#define CGAL_SURFACE_DESIGN_NESTED_DISSECTION_ORDERING_H

#include <CGAL/Surface_design/internal/Solvers/solver_traits.h>

#endif // CGAL_SURFACE_DESIGN_NESTED_DISSECTION_ORDERING_H
