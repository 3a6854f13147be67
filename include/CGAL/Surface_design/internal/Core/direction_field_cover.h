// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The branched cover of an n-direction field (n = 1, 2, 4), stored on the base mesh: per edge the
// matching of the field's sheets, per face whether the sheets close up (regular) or branch.

#ifndef CGAL_SURFACE_DESIGN_INTERNAL_CORE_DIRECTION_FIELD_COVER_H
#define CGAL_SURFACE_DESIGN_INTERNAL_CORE_DIRECTION_FIELD_COVER_H

#include <CGAL/Surface_design/exceptions.h>
#include <CGAL/Surface_design/internal/Core/angles.h>
#include <CGAL/Surface_design/internal/Core/discrete_connection.h>
#include <CGAL/Surface_design/internal/Core/topology.h>

#include <Eigen/Core>

#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

namespace CGAL {
namespace Surface_design {
namespace internal {

/// Number of values per vertex of a stripe function on the cover of an n-direction field: the
/// sheets 0 .. n/2 - 1 (one for n = 1 and n = 2, two for n = 4). Sheet a + n/2 carries the
/// opposite direction, hence the opposite value: it needs no unknown of its own.
inline int sheet_values(int n) { return n == 4 ? 2 : 1; }

inline void check_cover_order(int n, const char* parameter)
{
  if(n != 1 && n != 2 && n != 4)
    throw Invalid_parameter(parameter, "the symmetry order of a stripe pattern's field must be 1 (vector field), 2 "
                                       "(line field) or 4 (cross field), got " + std::to_string(n));
}

/// The transition of the sheet values along an edge whose matching is r: sheet a at the source
/// continues as sheet a + r (mod n) at the target, so that (P x)[a] = the value of sheet a + r
/// of the target's values x, i.e. x[a + r] if a + r < n/2 (mod n), else -x[a + r - n/2]. A signed
/// permutation; for d = 1 the unused second row and column are the identity's.
inline Eigen::Matrix2d sheet_transition(int n, int r)
{
  Eigen::Matrix2d P = Eigen::Matrix2d::Identity();
  if(n == 2)
    P(0, 0) = r % 2 == 0 ? 1. : -1.;
  else if(n == 4)
  {
    P.setZero();
    for(int a = 0; a < 2; ++a)
    {
      const int c = (a + r) % 4;
      if(c < 2)
        P(a, c) = 1.;
      else
        P(a, c - 2) = -1.;
    }
  }
  return P;
}

/// The cover of a vertex-based n-direction field, gauged along the primal spanning tree of the
/// topology: every vertex's representative direction (sheet 0) is the one of its n directions
/// that continues the parent's across the tree edge, so that tree edges match sheet 0 to sheet 0.
struct Direction_field_cover
{
  int n = 1;
  int d = 1;                        ///< values per vertex: sheet_values(n)
  std::vector<double> angle;        ///< per vertex: the representative's rescaled angle in the vertex frame
  std::vector<int> matching;        ///< per edge, along its orientation i -> j: r in [0, n)
  std::vector<int> index_numerator; ///< per face: n times the field's index
  std::vector<bool> regular;        ///< per face: the sheets close up around it (numerator = 0 mod n)

  std::size_t number_of_branch_faces() const
  {
    std::size_t b = 0;
    for(bool r : regular)
      b += r ? 0 : 1;
    return b;
  }
};

/// The matching of the n directions along halfedge index h (source i, target j): the r for which
/// the representative at i, carried by the connection, is closest to the representative at j
/// turned by 2 pi r / n.
template <class Indices>
int field_matching(const Indices& idx, const Discrete_connection& c, const std::vector<double>& angle, int n,
                   std::size_t h)
{
  const auto hd = idx.halfedge(h);
  const double turn = angle[idx.source_index(hd)] + c.transport(idx, h) - angle[idx.target_index(hd)];
  const long r = std::lround(double(n) * turn / two_pi);
  return int(((r % n) + n) % n);
}

/// Builds the cover of the field whose representative at vertex v has rescaled angle `angle[v]`.
/// The matchings use the connection `c`, the same transport as the field's face indices, so that
/// a face is regular exactly when its index is a multiple of 1 (pitfall: two transports would
/// classify branch faces differently).
template <class Indices>
Direction_field_cover direction_field_cover(const Indices& idx, const Discrete_connection& c, const Tree_cotree& tree,
                                            std::vector<double> angle, int n)
{
  check_cover_order(n, "symmetry_order");
  Direction_field_cover cover;
  cover.n = n;
  cover.d = sheet_values(n);
  // gauge: turn every representative to continue its parent's
  for(std::size_t v : tree.vertex_order)
    if(tree.parent_halfedge[v] != npos)
      angle[v] += two_pi * field_matching(idx, c, angle, n, tree.parent_halfedge[v]) / double(n);
  cover.angle = std::move(angle);
  cover.matching.resize(idx.number_of_edges());
  for(std::size_t e = 0; e < cover.matching.size(); ++e)
    cover.matching[e] = field_matching(idx, c, cover.angle, n, idx.index(idx.oriented_halfedge(e)));
  cover.index_numerator = field_index_numerators(idx, c, cover.angle, n);
  cover.regular.resize(idx.number_of_faces());
  for(std::size_t f = 0; f < cover.regular.size(); ++f)
    cover.regular[f] = ((cover.index_numerator[f] % n) + n) % n == 0;
  return cover;
}

} // namespace internal
} // namespace Surface_design
} // namespace CGAL

#endif // CGAL_SURFACE_DESIGN_INTERNAL_CORE_DIRECTION_FIELD_COVER_H
