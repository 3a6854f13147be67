// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Parallel loops over indices: oneTBB when CGAL is linked with it, a plain loop otherwise.

#ifndef CGAL_SURFACE_DESIGN_INTERNAL_SOLVERS_PARALLEL_H
#define CGAL_SURFACE_DESIGN_INTERNAL_SOLVERS_PARALLEL_H

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#endif

#include <cstddef>

namespace CGAL {
namespace Surface_design {
namespace internal {

/// Runs `f(i)` for i in [0, n), with tbb::parallel_for when `parallel` and TBB is linked.
/// `f` must only write to data owned by index i.
template <class Function>
void for_each_index(std::size_t n, bool parallel, const Function& f)
{
#ifdef CGAL_LINKED_WITH_TBB
  if(parallel)
  {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n), [&f](const tbb::blocked_range<std::size_t>& r) {
      for(std::size_t i = r.begin(); i != r.end(); ++i)
        f(i);
    });
    return;
  }
#else
  (void)parallel;
#endif
  for(std::size_t i = 0; i < n; ++i)
    f(i);
}

} // namespace internal
} // namespace Surface_design
} // namespace CGAL

#endif // CGAL_SURFACE_DESIGN_INTERNAL_SOLVERS_PARALLEL_H
