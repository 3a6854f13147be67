// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The net of isolines and gradient lines of a harmonic function, and its faces (Dong et al.
// 2005): `Quad_net_builder` (quad_net_builder.h) with its four phases, levels, crossings and
// spacing, tracing, assembly.

#ifndef CGAL_SURFACE_DESIGN_INTERNAL_HARMONIC_QUAD_REMESHING_QUAD_NET_H
#define CGAL_SURFACE_DESIGN_INTERNAL_HARMONIC_QUAD_REMESHING_QUAD_NET_H

#include <CGAL/Surface_design/internal/Harmonic_quad_remeshing/quad_net_builder.h>
#include <CGAL/Surface_design/internal/Harmonic_quad_remeshing/quad_net_levels.h>
#include <CGAL/Surface_design/internal/Harmonic_quad_remeshing/quad_net_crossings.h>
#include <CGAL/Surface_design/internal/Harmonic_quad_remeshing/quad_net_tracing.h>
#include <CGAL/Surface_design/internal/Harmonic_quad_remeshing/quad_net_assembly.h>

#endif // CGAL_SURFACE_DESIGN_INTERNAL_HARMONIC_QUAD_REMESHING_QUAD_NET_H
