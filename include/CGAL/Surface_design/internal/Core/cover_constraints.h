// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The values of the stripe problem on a direction field's cover that are fixed rather than solved:
// boundary loops on level-0 lines (their values, and one integer offset per chain of them) and
// the pins of the pieces whose transport is trivial.

#ifndef CGAL_SURFACE_DESIGN_INTERNAL_CORE_COVER_CONSTRAINTS_H
#define CGAL_SURFACE_DESIGN_INTERNAL_CORE_COVER_CONSTRAINTS_H

#include <CGAL/Surface_design/exceptions.h>
#include <CGAL/Surface_design/internal/Core/angles.h>
#include <CGAL/Surface_design/internal/Core/direction_field_cover.h>
#include <CGAL/Surface_design/internal/Core/vertex_frames.h>
#include <CGAL/Surface_design/internal/Core/topology.h>

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_design {
namespace internal {

/// Boundary loops on level-0 lines of the stripes (`Branched_one_form_solver`): the loops and
/// components they constrain, the values they fix (vertex, sheet: alpha = 0 modulo 2 pi), and one
/// integer direction per chain of such values linked along the loops' edges, 2 pi d_P(1_chain)
/// (sparse, per edge): the chain's offset 2 pi N. A chain whose transport around a loop negates
/// it has no offset (N = -N).
struct Boundary_level_lines
{
  std::vector<bool> loop, component;
  std::vector<std::pair<std::size_t, int>> values;
  std::vector<std::vector<std::pair<std::size_t, Eigen::Vector2d>>> chain_eta;
};

/// Per connected component, whether it is twisted: the transport of the sheets around some cycle
/// is not the identity. With the accumulated transition G_v along the primal tree, the cycle of a
/// non-tree edge e = (i -> j) transports by G_i P_e G_j^T.
template <class Indices>
std::vector<bool> twisted_components(const Indices& idx, const Topology& topology, const std::vector<Eigen::Matrix2d>& P,
                                     const std::vector<std::pair<std::size_t, std::size_t>>& ends)
{
  const Tree_cotree& t = topology.tree;
  std::vector<Eigen::Matrix2d> G(idx.number_of_vertices(), Eigen::Matrix2d::Identity());
  for(std::size_t v : t.vertex_order)
    if(t.parent_halfedge[v] != npos)
    {
      const auto hd = idx.halfedge(t.parent_halfedge[v]);
      const Eigen::Matrix2d& Pe = P[idx.edge_index(hd)];
      G[v] = G[idx.source_index(hd)] * (idx.orientation_sign(hd) > 0 ? Pe : Eigen::Matrix2d(Pe.transpose()));
    }
  std::vector<bool> twisted(topology.components.size(), false);
  for(std::size_t e = 0; e < P.size(); ++e)
  {
    const auto [i, j] = ends[e];
    if(!(G[i] * P[e] * G[j].transpose() - Eigen::Matrix2d::Identity()).isZero(1e-12))
      twisted[topology.components.vertex_component[i]] = true;
  }
  return twisted;
}

/// `level_sheets`: per edge, empty or the bit mask of its sheets (in the frame of its source,
/// `ends[e].first`) on a level line; P the sheet transitions, d the values per vertex.
/// \throws Invalid_constraints for a loop with some but not all edges on level lines, or whose
///         edges the tree does not all hold but one
template <class Indices>
Boundary_level_lines boundary_level_lines(const Indices& idx, const Topology& topology,
                                          const std::vector<Eigen::Matrix2d>& P,
                                          const std::vector<std::pair<std::size_t, std::size_t>>& ends,
                                          const std::vector<std::uint8_t>& level_sheets, int d_values)
{
  Boundary_level_lines out;
  const std::size_t nl = topology.boundary.size(), d = std::size_t(d_values), nv = idx.number_of_vertices();
  out.loop.assign(nl, false);
  out.component.assign(topology.components.size(), false);
  if(level_sheets.empty())
    return out;
  std::vector<std::size_t> chain(nv * d, npos);
  std::vector<double> sign(nv * d, 0.);
  std::vector<std::vector<std::pair<std::size_t, std::size_t>>> link(nv * d); // (value, edge)
  for(std::size_t l = 0; l < nl; ++l)
  {
    const std::vector<std::size_t>& loop = topology.boundary.loops[l];
    std::size_t level = 0, off_tree = 0;
    for(std::size_t h : loop)
    {
      const std::size_t e = idx.edge_index(idx.halfedge(h));
      level += level_sheets[e] != 0 ? 1 : 0;
      off_tree += topology.tree.edge_in_tree[e] ? 0 : 1;
    }
    if(level == 0)
      continue;
    if(level != loop.size())
      throw Invalid_constraints("boundary loop " + std::to_string(l) + ": " + std::to_string(level) + " of its " +
                                std::to_string(loop.size()) + " edges lie on a level line, not all");
    if(off_tree != 1)
      throw Invalid_constraints("boundary loop " + std::to_string(l) + " on level lines: the spanning tree must hold "
                                "all its edges but one (compute_topology(idx, true)), not all but " +
                                std::to_string(off_tree));
    out.loop[l] = true;
    out.component[topology.components.vertex_component[idx.source_index(idx.halfedge(loop.front()))]] =
      true;
    for(std::size_t h : loop)
    {
      const std::size_t e = idx.edge_index(idx.halfedge(h));
      const auto [i, j] = ends[e];
      for(std::size_t a = 0; a < d; ++a)
        if((level_sheets[e] >> a) & 1)
          for(std::size_t b = 0; b < d; ++b)
            if(P[e](Eigen::Index(a), Eigen::Index(b)) != 0.)
            {
              link[i * d + a].emplace_back(j * d + b, e);
              link[j * d + b].emplace_back(i * d + a, e);
            }
    }
  }
  // chains: breadth-first over the linked values, 1_chain transported so that d_P 1_chain = 0
  // on the chain's edges (P_e(a, b) s_j = s_i); a chain whose transport around a loop negates
  // it has no offset (N = -N)
  std::vector<std::vector<std::size_t>> members;
  std::vector<bool> consistent;
  for(std::size_t start = 0; start < nv * d; ++start)
  {
    if(link[start].empty() || chain[start] != npos)
      continue;
    const std::size_t c = members.size();
    members.emplace_back(1, start);
    consistent.push_back(true);
    chain[start] = c;
    sign[start] = 1.;
    for(std::size_t head = 0; head < members[c].size(); ++head)
    {
      const std::size_t x = members[c][head];
      for(const auto& [y, e] : link[x])
      {
        // x and y are (i, a) and (j, b) of edge e in some order: s_(i, a) = P_e(a, b) s_(j, b)
        const std::size_t xv = x / d, yv = y / d;
        const bool x_is_source = ends[e].first == xv && ends[e].second == yv;
        const double p = x_is_source ? P[e](Eigen::Index(x % d), Eigen::Index(y % d))
                                     : P[e](Eigen::Index(y % d), Eigen::Index(x % d));
        const double s_y = p * sign[x]; // p = +-1
        if(chain[y] == npos)
        {
          chain[y] = c;
          sign[y] = s_y;
          members[c].push_back(y);
        }
        else if(sign[y] != s_y)
          consistent[c] = false;
      }
    }
  }
  for(std::size_t x = 0; x < nv * d; ++x)
    if(chain[x] != npos)
      out.values.emplace_back(x / d, int(x % d));
  std::vector<std::size_t> direction(members.size(), npos);
  for(std::size_t c = 0; c < members.size(); ++c)
    if(consistent[c])
    {
      direction[c] = out.chain_eta.size();
      out.chain_eta.emplace_back();
    }
  // 2 pi d_P(1_chain) on every edge with an end in the chain
  for(std::size_t e = 0; e < ends.size(); ++e)
  {
    const auto [i, j] = ends[e];
    std::array<std::size_t, 4> touched{npos, npos, npos, npos};
    for(std::size_t a = 0; a < d; ++a)
    {
      touched[a] = chain[i * d + a];
      touched[2 + a] = chain[j * d + a];
    }
    for(std::size_t k = 0; k < 4; ++k)
    {
      const std::size_t c = touched[k];
      if(c == npos || direction[c] == npos || std::find(touched.begin(), touched.begin() + k, c) != touched.begin() + k)
        continue;
      Eigen::Vector2d fi = Eigen::Vector2d::Zero(), fj = Eigen::Vector2d::Zero();
      for(std::size_t a = 0; a < d; ++a)
      {
        if(chain[i * d + a] == c)
          fi[Eigen::Index(a)] = sign[i * d + a];
        if(chain[j * d + a] == c)
          fj[Eigen::Index(a)] = sign[j * d + a];
      }
      const Eigen::Vector2d v = two_pi * (P[e] * fj - fi);
      if(!v.isZero())
        out.chain_eta[direction[c]].emplace_back(e, v);
    }
  }
  return out;
}

/// Per boundary edge i -> j (its orientation), the bit mask of the sheets whose direction at i is
/// within 45 degrees of the edge's normal: the sheets whose level lines can follow the boundary.
/// With `offset` (`Smoothed_boundary::offset`, per vertex), the normal of the smoothed boundary
/// instead, at the edge's first vertex along the boundary (the surface on the left), whose
/// sheets are those of i through the matching.
/// \throws Invalid_constraints where no sheet is (the field runs along the boundary)
template <class Indices>
std::vector<std::uint8_t> boundary_normal_sheets(const Indices& idx, const Topology& topology,
                                                 const Vertex_frames& frames, const Direction_field_cover& cover,
                                                 const std::vector<double>& offset = {})
{
  std::vector<std::uint8_t> mask(idx.number_of_edges(), 0);
  for(const auto& loop : topology.boundary.loops)
    for(std::size_t h : loop)
    {
      const std::size_t e = idx.edge_index(idx.halfedge(h));
      const auto oriented = idx.oriented_halfedge(e);
      // the vertex and angle the sheets are read at, and the shift of their numbering from i's
      std::size_t v = idx.source_index(oriented);
      double edge_angle = frames.angle[idx.index(oriented)];
      int shift = 0;
      if(!offset.empty())
      {
        const auto inner = opposite(idx.halfedge(h), idx.mesh()); // leaving v along the boundary
        v = idx.source_index(inner);
        edge_angle = frames.angle[idx.index(inner)] + offset[v];
        shift = v == idx.source_index(oriented) ? 0 : cover.matching[e];
      }
      for(int a = 0; a < cover.d; ++a)
      {
        const double direction = cover.angle[v] + double((a + shift) % cover.n) * two_pi / double(cover.n);
        if(std::abs(std::sin(direction - edge_angle)) > std::sqrt(0.5))
          mask[e] = std::uint8_t(mask[e] | (1u << a));
      }
      if(mask[e] == 0)
        throw Invalid_constraints("boundary edge " + std::to_string(e) + ": the field runs along the boundary there "
                                  "(within 45 degrees), so no level line of its stripes can follow the boundary; "
                                  "give a field normal to the boundary");
    }
  return mask;
}

/// The boundary vertices where the family normal to the boundary switches between the vertex's
/// two boundary edges (`mask` from `boundary_normal_sheets()`, families: sheets modulo d): the
/// corners, where the level lines of both families meet the boundary and alpha = 0 on both.
template <class Indices>
std::vector<std::size_t> boundary_family_switches(const Indices& idx, const Topology& topology,
                                                  const Direction_field_cover& cover, const std::vector<std::uint8_t>& mask)
{
  // the families (bit mask) normal to boundary edge e, in the frame of its end v
  auto families_at = [&](std::size_t e, std::size_t v) {
    const auto oriented = idx.oriented_halfedge(e);
    const int shift = idx.source_index(oriented) == v ? 0 : cover.matching[e];
    unsigned bits = 0;
    for(int a = 0; a < cover.d; ++a)
      if((mask[e] >> a) & 1)
        bits |= 1u << ((a + shift) % cover.n % cover.d);
    return bits;
  };
  std::vector<std::size_t> corners;
  for(const auto& loop : topology.boundary.loops)
    for(std::size_t k = 0; k < loop.size(); ++k)
    {
      // border halfedges in next() order: the target of one is the source of the next
      const auto h = idx.halfedge(loop[k]), g = idx.halfedge(loop[(k + 1) % loop.size()]);
      const std::size_t v = idx.target_index(h);
      if(families_at(idx.edge_index(h), v) != families_at(idx.edge_index(g), v))
        corners.push_back(v);
    }
  return corners;
}

/// A cross field without branch face on component c, whose boundary loops all lie on level lines:
/// the dual forest has no root there, and one face's closure must follow from the others'. By
/// Stokes the curls of all faces sum to the sums of y along the loops, sheet by sheet (their
/// transport is trivial: the component is not twisted). Each loop has all its edges in the tree
/// but one, e_L, and that sum is 2 pi m_L on e_L's sheet that is not on a level line: the root's
/// closure holds when the windings m_L of the loops whose free sheet is the same (as seen from the
/// root) cancel. Returns the e_L of the component's loops (see `stokes_loop_directions()`).
template <class Indices>
std::vector<std::size_t> stokes_loop_edges(const Indices& idx, const Topology& topology, std::size_t c)
{
  std::vector<std::size_t> edges;
  for(const auto& loop : topology.boundary.loops)
    if(topology.components.vertex_component[idx.target_index(idx.halfedge(loop.front()))] == c)
      for(std::size_t h : loop)
        if(!topology.tree.edge_in_tree[idx.edge_index(idx.halfedge(h))])
          edges.push_back(idx.edge_index(idx.halfedge(h)));
  return edges;
}

/// The free directions of the windings of `stokes_loop_edges()` (pairs (root face, loop edge)):
/// `root_curl(f, e, a)` is the root face f's curl left by 2 pi on sheet a of e alone, after the
/// peeling: a signed unit vector times 2 pi, or 0. Of the candidates (e, a) with `free_sheet(e,
/// a)` that move the same sheet of their root, the first is fixed (its winding follows from the
/// others', 0 if alone) and each other is free together with it, at `sign` times its winding, so
/// that the root's closure holds; a candidate that leaves the root's curl as it is is free alone
/// (`partner` npos).
/// \throws Invalid_constraints if a candidate moves both sheets of its root
struct Stokes_loop_direction
{
  std::size_t edge;
  int sheet;
  std::size_t partner = npos;
  int partner_sheet = 0;
  double sign = 0.;
};
/// The edges that carry free windings, those with `off` (in neither the tree nor the dual forest),
/// one of odd matching per component last (cross fields): the global shifts c of alpha with
/// (P_e - I) c in 2 pi Z^d make some directions integer combinations of the others, and the
/// solver drops the last dependent ones. On a cross field the relations are generated by
/// c = pi (1, 1) and pi (1, -1); on the two sheets of an edge with odd matching they form a
/// unimodular block, so dropping that edge keeps the whole lattice, while dropping an edge with
/// matching 2 (block of determinant 2) would lose half of it.
inline std::vector<std::size_t> free_winding_edges(const Components& components,
                                                   const std::vector<std::pair<std::size_t, std::size_t>>& ends,
                                                   const Direction_field_cover& cover, const std::vector<bool>& off)
{
  std::vector<std::size_t> free_edges, last;
  std::vector<bool> component_has_last(components.size(), false);
  for(std::size_t e = 0; e < off.size(); ++e)
    if(off[e])
    {
      const std::size_t c = components.vertex_component[ends[e].first];
      if(cover.n == 4 && cover.matching[e] % 2 == 1 && !component_has_last[c])
      {
        component_has_last[c] = true;
        last.push_back(e);
      }
      else
        free_edges.push_back(e);
    }
  free_edges.insert(free_edges.end(), last.begin(), last.end());
  return free_edges;
}

template <class FreeSheet, class RootCurl>
std::vector<Stokes_loop_direction> stokes_loop_directions(const std::vector<std::pair<std::size_t, std::size_t>>& loops,
                                                          int d, const FreeSheet& free_sheet, const RootCurl& root_curl)
{
  std::vector<Stokes_loop_direction> out;
  std::map<std::pair<std::size_t, int>, std::pair<Stokes_loop_direction, double>> first; // (root, sheet) ->
  for(const auto& [f, e] : loops)
    for(int a = 0; a < d; ++a)
    {
      if(!free_sheet(e, a))
        continue;
      const Eigen::Vector2d c = root_curl(f, e, a);
      const bool moves0 = std::abs(c[0]) > 1e-6, moves1 = std::abs(c[1]) > 1e-6;
      if(moves0 && moves1)
        throw Invalid_constraints("the windings of the boundary loops on level lines move both stripe families at "
                                  "once: not supported");
      if(!moves0 && !moves1)
      {
        out.push_back({e, a});
        continue;
      }
      const int b = moves0 ? 0 : 1;
      const auto it = first.find({f, b});
      if(it == first.end())
        first[{f, b}] = {Stokes_loop_direction{e, a}, c[b]};
      else
        out.push_back({e, a, it->second.first.edge, it->second.first.sheet, -c[b] / it->second.second});
    }
  return out;
}

/// Stokes' theorem on the components without singularity, twist or free boundary
/// (`stokes_component`): the stripe indices k of their regular faces must sum to 0, family by
/// family (`d` of them). \throws Invalid_constraints otherwise
inline void check_stokes_sums(const Components& components, const std::vector<bool>& regular,
                              const std::vector<bool>& stokes_component, int d,
                              const std::vector<Eigen::Vector2i>& k)
{
  std::vector<Eigen::Vector2i> sum(components.size(), Eigen::Vector2i::Zero());
  for(std::size_t f = 0; f < k.size(); ++f)
    if(regular[f])
      sum[components.face_component[f]] += k[f];
  for(std::size_t c = 0; c < sum.size(); ++c)
    if(stokes_component[c] && !sum[c].head(d).isZero())
    {
      std::string s = "on connected component " + std::to_string(c) +
                      " (its field without singularity or twist, no free boundary) the stripe indices" +
                      (d == 2 ? " of each of the two stripe families" : "") +
                      " must sum to 0 (Stokes' theorem), got " + std::to_string(sum[c][0]);
      if(d == 2)
        s += " and " + std::to_string(sum[c][1]);
      throw Invalid_constraints(s);
    }
}

/// Pins one value per free component of every piece of the graph of edges of non-zero weight
/// whose transport is trivial: there the stripes are free up to a constant c transported along
/// the piece (f_v = G_v^T c), but for the components of c that the values already fixed (on
/// level lines) determine; the root (G = I) is pinned on the others (`fixed`, per value v d + a).
/// Returns per vertex the generic lattice offset of its piece (0.5 on the free components of c,
/// transported; 0 on twisted pieces).
inline std::vector<Eigen::Vector2d> pin_untwisted_pieces(const std::vector<double>& weight,
                                                         const std::vector<Eigen::Matrix2d>& transition,
                                                         const std::vector<std::pair<std::size_t, std::size_t>>& ends,
                                                         int d, std::vector<bool>& fixed)
{
  const std::size_t nv = fixed.size() / std::size_t(d);
  std::vector<Eigen::Vector2d> offset(nv, Eigen::Vector2d::Zero());
  {
    std::vector<std::vector<std::pair<std::size_t, std::size_t>>> adjacent(nv); // (vertex, edge)
    for(std::size_t e = 0; e < weight.size(); ++e)
      if(weight[e] != 0.)
      {
        adjacent[ends[e].first].emplace_back(ends[e].second, e);
        adjacent[ends[e].second].emplace_back(ends[e].first, e);
      }
    // breadth-first over each piece, G_v the transport from its root; an edge (i -> j) closes a
    // loop with transport G_i P_e G_j^T
    std::vector<Eigen::Matrix2d> G(nv, Eigen::Matrix2d::Identity());
    std::vector<bool> reached(nv, false);
    std::vector<std::size_t> queue;
    for(std::size_t root = 0; root < nv; ++root)
    {
      if(reached[root])
        continue;
      reached[root] = true;
      queue.assign(1, root);
      bool twisted = false;
      for(std::size_t head = 0; head < queue.size(); ++head)
      {
        const std::size_t v = queue[head];
        for(const auto& [w, e] : adjacent[v])
        {
          // the transition from v to w along e
          const Eigen::Matrix2d P = ends[e].first == v ? transition[e] : Eigen::Matrix2d(transition[e].transpose());
          if(!reached[w])
          {
            reached[w] = true;
            G[w] = G[v] * P;
            queue.push_back(w);
          }
          else if(!(G[v] * P * G[w].transpose() - Eigen::Matrix2d::Identity()).isZero(1e-12))
            twisted = true;
        }
      }
      if(!twisted)
      {
        // the stripes of this piece are free up to a constant c transported along it (f_v =
        // G_v^T c), but for the components of c that its values on level lines fix: the root
        // (G = I) pinned on the others
        Eigen::Vector2d free_part(1., 1.);
        for(std::size_t v : queue)
          for(int a = 0; a < d; ++a)
            if(fixed[v * std::size_t(d) + std::size_t(a)])
              for(int b = 0; b < d; ++b)
                if(G[v](b, a) != 0.)
                  free_part[b] = 0.;
        for(int a = 0; a < d; ++a)
          if(free_part[a] != 0.)
            fixed[root * std::size_t(d) + std::size_t(a)] = true;
        // with lattice branch points, a generic constant (not the pin's 0, where both families'
        // level-0 lines would cross at a mesh vertex, a degenerate crossing for the quads'
        // extraction)
        for(std::size_t v : queue)
          offset[v] = G[v].transpose() * Eigen::Vector2d(0.5 * free_part[0], 0.5 * free_part[1]);
      }
    }
  }
  return offset;
}

} // namespace internal
} // namespace Surface_design
} // namespace CGAL

#endif // CGAL_SURFACE_DESIGN_INTERNAL_CORE_COVER_CONSTRAINTS_H
