// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Singularities at least a given distance apart: pairs of opposite indices closer than that are
// removed, others moved apart, each change kept only if a field with the new singularities exists.

#ifndef CGAL_SURFACE_DESIGN_INTERNAL_DIRECTION_FIELDS_SINGULARITY_SEPARATION_H
#define CGAL_SURFACE_DESIGN_INTERNAL_DIRECTION_FIELDS_SINGULARITY_SEPARATION_H

#include <Eigen/Core>

#include <algorithm>
#include <cstddef>
#include <limits>
#include <set>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_design {

/// \ingroup PkgDirectionFieldsRef
/// What `Trivial_connection::separate_singularities()` changed.
struct Singularity_separation
{
  std::size_t removed_pairs = 0; ///< pairs of opposite indices closer than the distance, removed
  std::size_t moved = 0;         ///< singularities moved away from a close one
  std::size_t kept_pairs = 0;    ///< close pairs left as they are: no field has the singularities otherwise
};

namespace internal {

/// Greedy separation of the singularities `index` (per face, 0: none) at the face centres
/// `centre`: while the closest pair not yet given up is closer than `distance`, removes it if its
/// indices cancel, else (or if no field exists without it) moves its second singularity to the face within 2 `distance` of it that is
/// farthest from all other singularities (given up when none is `distance` away). `exists()`
/// tells whether a field with the current indices exists; a change after which it does not is
/// undone and its pair given up. O(changes x (singularities² + faces)).
template <class Exists>
Singularity_separation separate_singularities(std::vector<int>& index, const std::vector<Eigen::Vector3d>& centre,
                                              double distance, Exists&& exists)
{
  Singularity_separation result;
  std::vector<std::size_t> cones;
  for(std::size_t f = 0; f < index.size(); ++f)
    if(index[f] != 0)
      cones.push_back(f);
  std::set<std::pair<std::size_t, std::size_t>> given_up; // by face, smaller first
  auto nearest_other = [&](const Eigen::Vector3d& x, std::size_t except_a, std::size_t except_b) {
    double d = std::numeric_limits<double>::infinity();
    for(std::size_t c : cones)
      if(c != except_a && c != except_b)
        d = (std::min)(d, (centre[c] - x).norm());
    return d;
  };
  for(std::size_t guard = 0; guard < 16 * (index.size() + 1); ++guard)
  {
    std::size_t bi = 0, bj = 0;
    double best = distance;
    for(std::size_t i = 0; i < cones.size(); ++i)
      for(std::size_t j = i + 1; j < cones.size(); ++j)
      {
        const double d = (centre[cones[i]] - centre[cones[j]]).norm();
        const auto key = std::make_pair((std::min)(cones[i], cones[j]), (std::max)(cones[i], cones[j]));
        if(d < best && !given_up.count(key))
        {
          best = d;
          bi = i;
          bj = j;
        }
      }
    if(!(best < distance))
      break;
    const std::size_t a = cones[bi], b = cones[bj];
    const auto key = std::make_pair((std::min)(a, b), (std::max)(a, b));
    const int ka = index[a], kb = index[b];
    if(ka + kb == 0)
    {
      index[a] = index[b] = 0;
      if(exists())
      {
        cones.erase(cones.begin() + std::ptrdiff_t(bj));
        cones.erase(cones.begin() + std::ptrdiff_t(bi));
        ++result.removed_pairs;
        continue;
      }
      index[a] = ka;
      index[b] = kb;
    }
    // move b to the free face near it that is farthest from every other singularity
    std::size_t target = b;
    double room = -1.;
    for(std::size_t f = 0; f < index.size(); ++f)
      if(index[f] == 0 && (centre[f] - centre[b]).norm() < 2. * distance)
      {
        const double d = nearest_other(centre[f], b, b);
        if(d > room)
        {
          room = d;
          target = f;
        }
      }
    if(room >= distance)
    {
      index[target] = kb;
      index[b] = 0;
      if(exists())
      {
        cones[bj] = target;
        ++result.moved;
        continue;
      }
      index[b] = kb;
      index[target] = 0;
    }
    given_up.insert(key);
    ++result.kept_pairs;
  }
  return result;
}

} // namespace internal
} // namespace Surface_design
} // namespace CGAL

#endif // CGAL_SURFACE_DESIGN_INTERNAL_DIRECTION_FIELDS_SINGULARITY_SEPARATION_H
