// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Sparse one-forms with two sheet values per edge (the stripes' directions on a branched cover):
// the (edge, value) pairs of their nonzero edges, sorted by edge.

#ifndef CGAL_SURFACE_DESIGN_INTERNAL_CORE_SPARSE_ONE_FORMS_H
#define CGAL_SURFACE_DESIGN_INTERNAL_CORE_SPARSE_ONE_FORMS_H

#include <Eigen/Core>

#include <algorithm>
#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_design {
namespace internal {

using Sparse_one_form = std::vector<std::pair<std::size_t, Eigen::Vector2d>>;

/// The value on edge e (zero off the support).
inline Eigen::Vector2d sparse_value(const Sparse_one_form& y, std::size_t e)
{
  const auto it = std::lower_bound(y.begin(), y.end(), e, [](const auto& entry, std::size_t x) { return entry.first < x; });
  return it != y.end() && it->first == e ? it->second : Eigen::Vector2d(Eigen::Vector2d::Zero());
}

/// Sorts the pairs by edge and sums those of one edge.
inline void sort_and_merge(Sparse_one_form& y)
{
  if(y.empty())
    return;
  std::stable_sort(y.begin(), y.end(), [](const auto& p, const auto& q) { return p.first < q.first; });
  std::size_t last = 0;
  for(std::size_t i = 1; i < y.size(); ++i)
    if(y[i].first == y[last].first)
      y[last].second += y[i].second;
    else
      y[++last] = y[i];
  y.resize(last + 1);
}

/// <x, y> of a sparse form and a form on every edge.
inline double sparse_dot(const Sparse_one_form& x, const std::vector<Eigen::Vector2d>& y)
{
  double s = 0.;
  for(const auto& [e, v] : x)
    s += v.dot(y[e]);
  return s;
}

/// <x, y> of two sparse forms.
inline double sparse_dot(const Sparse_one_form& x, const Sparse_one_form& y)
{
  double s = 0.;
  for(std::size_t i = 0, j = 0; i < x.size() && j < y.size();)
    if(x[i].first < y[j].first)
      ++i;
    else if(y[j].first < x[i].first)
      ++j;
    else
      s += x[i++].second.dot(y[j++].second);
  return s;
}

} // namespace internal
} // namespace Surface_design
} // namespace CGAL

#endif // CGAL_SURFACE_DESIGN_INTERNAL_CORE_SPARSE_ONE_FORMS_H
