// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Workload `editor`: the server side of the stripe editor (examples/Programs/Editor), edit by edit, as the
// HTTP handler runs it: parse the JSON request, change the singularities, re-solve (one
// back-substitution), write the per-corner state. Compiled when nlohmann-json is available.

#ifndef CGAL_SURFACE_DESIGN_BENCHMARK_WORKLOAD_EDITOR_H
#define CGAL_SURFACE_DESIGN_BENCHMARK_WORKLOAD_EDITOR_H

#include "harness.h"

#include <string>

namespace benchmark {

/// Phases: open (validate, factor, first solve), add pair (+1 and -1 at faces 20 steps apart),
/// drag step (the mean of 20 moves of the -1 to an adjacent face, each parsed, re-solved and
/// serialized), frequency (new stripe count: new target 1-form, one solve), state (serialization
/// alone). Defined in workload_editor.cpp (its own translation unit: it compiles the editor).
void editor_workload(const Mesh& mesh, const std::string& solver, Run& run);

} // namespace benchmark

#endif // CGAL_SURFACE_DESIGN_BENCHMARK_WORKLOAD_EDITOR_H
