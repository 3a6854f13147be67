// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Topology of a FaceGraph: connected components, boundary loops, tree-cotree decomposition with
// homology generators, and integration of a 1-form along a spanning tree.

#ifndef CGAL_SURFACE_DESIGN_INTERNAL_CORE_TOPOLOGY_H
#define CGAL_SURFACE_DESIGN_INTERNAL_CORE_TOPOLOGY_H

#include <CGAL/Surface_design/internal/Core/Mesh_indices.h>

#include <algorithm>
#include <cstddef>
#include <limits>
#include <numeric>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_design {
namespace internal {

/// Union-find over [0, n) with path halving; a union keeps the smaller root (so roots are the
/// smallest elements of their sets).
struct Union_find
{
  std::vector<std::size_t> parent;
  explicit Union_find(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), std::size_t(0)); }
  std::size_t find(std::size_t x)
  {
    while(parent[x] != x)
      x = parent[x] = parent[parent[x]];
    return x;
  }
  /// Joins the sets of a and b; false if they were one already.
  bool unite(std::size_t a, std::size_t b)
  {
    a = find(a);
    b = find(b);
    if(a == b)
      return false;
    parent[(std::max)(a, b)] = (std::min)(a, b);
    return true;
  }
};

/// Counts of one connected component.
struct Component_info
{
  std::size_t root_vertex = npos; ///< smallest vertex index of the component
  std::size_t root_face = npos;   ///< smallest face index of the component
  std::size_t vertices = 0, edges = 0, faces = 0, boundary_loops = 0;

  long euler_characteristic() const { return long(vertices) - long(edges) + long(faces); }
  /// Genus from chi = 2 - 2g - b (requires a manifold component).
  long genus() const { return (2 - long(boundary_loops) - euler_characteristic()) / 2; }
  bool is_closed() const { return boundary_loops == 0; }
};

/// Boundary loops: ordered cycles of border halfedges (face(h) == null_face()), each running
/// along next(). Loops are numbered by their smallest halfedge index, i.e. deterministically.
struct Boundary_loops
{
  std::vector<std::vector<std::size_t>> loops; ///< halfedge indices, in next() order
  std::vector<std::size_t> loop_of_halfedge;   ///< loop index of a border halfedge, else npos

  std::size_t size() const { return loops.size(); }
};

template <class Indices>
Boundary_loops boundary_loops(const Indices& idx)
{
  const auto& tm = idx.mesh();
  Boundary_loops b;
  b.loop_of_halfedge.assign(idx.number_of_halfedges(), npos);
  for(std::size_t i = 0; i < idx.number_of_halfedges(); ++i)
  {
    if(b.loop_of_halfedge[i] != npos || !idx.is_border(idx.halfedge(i)))
      continue;
    const std::size_t loop = b.loops.size();
    b.loops.emplace_back();
    auto h = idx.halfedge(i);
    do
    {
      b.loop_of_halfedge[idx.index(h)] = loop;
      b.loops.back().push_back(idx.index(h));
      h = next(h, tm);
    } while(idx.index(h) != i);
  }
  return b;
}

/// Connected components (of the vertex-edge graph; equal to the face-connected components on a
/// manifold mesh without isolated vertices). Components are numbered in the order of their
/// smallest vertex index.
struct Components
{
  std::vector<std::size_t> vertex_component;
  std::vector<std::size_t> face_component;
  std::vector<Component_info> info;

  std::size_t size() const { return info.size(); }
};

template <class Indices>
Components connected_components(const Indices& idx, const Boundary_loops& loops)
{
  const std::size_t nv = idx.number_of_vertices();
  Union_find sets(nv); // roots = smallest vertex index of each set
  for(std::size_t e = 0; e < idx.number_of_edges(); ++e)
  {
    const auto ij = idx.edge_vertices(e);
    sets.unite(ij.first, ij.second);
  }

  Components c;
  c.vertex_component.assign(nv, npos);
  std::vector<std::size_t> component_of_root(nv, npos);
  for(std::size_t v = 0; v < nv; ++v)
  {
    const std::size_t r = sets.find(v);
    if(component_of_root[r] == npos)
    {
      component_of_root[r] = c.info.size();
      c.info.emplace_back();
      c.info.back().root_vertex = v;
    }
    c.vertex_component[v] = component_of_root[r];
    ++c.info[c.vertex_component[v]].vertices;
  }
  for(std::size_t e = 0; e < idx.number_of_edges(); ++e)
    ++c.info[c.vertex_component[idx.edge_vertices(e).first]].edges;

  const auto& tm = idx.mesh();
  c.face_component.assign(idx.number_of_faces(), npos);
  for(std::size_t f = 0; f < idx.number_of_faces(); ++f)
  {
    const std::size_t k = c.vertex_component[idx.target_index(halfedge(idx.face(f), tm))];
    c.face_component[f] = k;
    Component_info& info = c.info[k];
    if(info.faces++ == 0)
      info.root_face = f;
  }
  for(const auto& loop : loops.loops)
    ++c.info[c.vertex_component[idx.target_index(idx.halfedge(loop.front()))]].boundary_loops;
  return c;
}

/// Tree-cotree decomposition (Eppstein 2003; Erickson & Whittlesey 2005), per connected component,
/// of the closed surface obtained by capping every boundary loop with one *virtual face*:
/// - a primal spanning tree T of the vertices (breadth-first from each component's root vertex);
/// - a dual spanning tree T* of the faces and virtual faces through edges not in T (breadth-first
///   from each component's root face);
/// - the remaining edges, exactly 2g per component of genus g. Each closes a cycle in T: these
///   2g cycles are a basis of the first homology of the capped surface.
///
/// Dual nodes are numbered: real faces 0..|F|-1, then virtual face |F| + l for boundary loop l.
///
/// With `boundary_first`, the breadth-first primal tree walks a whole boundary loop as soon as it
/// reaches one of its vertices: T then holds every edge of every boundary loop but one, so that
/// each virtual face is a leaf of the dual graph (joined through that one edge). A 1-form that
/// vanishes on T then vanishes on the boundary but for one edge per loop (used where the
/// boundary must lie on a level line of a stripe function).
struct Tree_cotree
{
  // primal tree
  std::vector<std::size_t> vertex_order;    ///< breadth-first order; a root precedes its tree
  std::vector<std::size_t> parent_halfedge; ///< per vertex: halfedge from parent to it (npos at roots)
  std::vector<bool> edge_in_tree;           ///< per edge: in T

  // dual tree
  std::vector<std::size_t> dual_order;          ///< breadth-first order of the dual nodes
  std::vector<std::size_t> dual_parent_halfedge; ///< per dual node: its own halfedge whose edge joins it to its parent (npos at roots)
  std::vector<bool> edge_in_cotree;             ///< per edge: in T*

  // homology generators
  std::vector<std::size_t> generator_edges;           ///< edges in neither T nor T*
  std::vector<std::vector<std::size_t>> generator_loops; ///< closed halfedge cycles, one per generator edge
  std::vector<std::size_t> generator_component;       ///< component of each generator

  std::size_t number_of_faces = 0; ///< |F|: the first virtual dual node
};

template <class Indices>
Tree_cotree tree_cotree(const Indices& idx, const Components& comps, const Boundary_loops& loops,
                        bool boundary_first = false)
{
  const auto& tm = idx.mesh();
  const std::size_t nv = idx.number_of_vertices(), ne = idx.number_of_edges(),
                    nf = idx.number_of_faces(), nd = nf + loops.size();
  Tree_cotree t;
  t.number_of_faces = nf;

  // --- primal spanning tree, breadth-first
  t.parent_halfedge.assign(nv, npos);
  t.edge_in_tree.assign(ne, false);
  t.vertex_order.reserve(nv);
  std::vector<bool> reached(nv, false);
  // boundary_first: the loop and position of every boundary vertex (as the source of a border
  // halfedge), and whether its loop was walked
  std::vector<std::pair<std::size_t, std::size_t>> on_loop;
  std::vector<bool> walked;
  if(boundary_first)
  {
    on_loop.assign(nv, {npos, 0});
    walked.assign(loops.size(), false);
    for(std::size_t l = 0; l < loops.size(); ++l)
      for(std::size_t k = 0; k < loops.loops[l].size(); ++k)
        on_loop[idx.source_index(idx.halfedge(loops.loops[l][k]))] = {l, k};
  }
  // from v, reached, the rest of its boundary loop along the border halfedges
  auto walk_loop = [&](std::size_t v) {
    if(!boundary_first || on_loop[v].first == npos || walked[on_loop[v].first])
      return;
    const auto [l, k] = on_loop[v];
    walked[l] = true;
    const std::vector<std::size_t>& loop = loops.loops[l];
    for(std::size_t m = 0; m + 1 < loop.size(); ++m)
    {
      const std::size_t h = loop[(k + m) % loop.size()], w = idx.target_index(idx.halfedge(h));
      if(reached[w]) // a vertex twice on the loop (not on a manifold mesh): its first visit stands
        continue;
      reached[w] = true;
      t.parent_halfedge[w] = h;
      t.edge_in_tree[idx.edge_index(idx.halfedge(h))] = true;
      t.vertex_order.push_back(w);
    }
  };
  for(const Component_info& c : comps.info)
  {
    std::size_t head = t.vertex_order.size();
    t.vertex_order.push_back(c.root_vertex);
    reached[c.root_vertex] = true;
    walk_loop(c.root_vertex);
    while(head < t.vertex_order.size())
    {
      const auto v = idx.vertex(t.vertex_order[head++]);
      for(auto h : halfedges_around_source(v, tm))
      {
        const std::size_t w = idx.target_index(h);
        if(reached[w])
          continue;
        reached[w] = true;
        t.parent_halfedge[w] = idx.index(h);
        t.edge_in_tree[idx.edge_index(h)] = true;
        t.vertex_order.push_back(w);
        walk_loop(w);
      }
    }
  }

  // --- dual spanning tree over faces and virtual faces, through edges not in T
  auto dual_node = [&](std::size_t h) {
    const auto hd = idx.halfedge(h);
    return idx.is_border(hd) ? nf + loops.loop_of_halfedge[h] : idx.index(face(hd, tm));
  };
  auto for_each_halfedge_of_node = [&](std::size_t node, auto&& fn) {
    if(node < nf)
    {
      for(auto h : halfedges_around_face(halfedge(idx.face(node), tm), tm))
        fn(idx.index(h));
    }
    else
    {
      for(std::size_t h : loops.loops[node - nf])
        fn(h);
    }
  };
  t.dual_parent_halfedge.assign(nd, npos);
  t.edge_in_cotree.assign(ne, false);
  t.dual_order.reserve(nd);
  std::vector<bool> dual_reached(nd, false);
  for(const Component_info& c : comps.info)
  {
    if(c.root_face == npos)
      continue;
    std::size_t head = t.dual_order.size();
    t.dual_order.push_back(c.root_face);
    dual_reached[c.root_face] = true;
    while(head < t.dual_order.size())
    {
      const std::size_t node = t.dual_order[head++];
      for_each_halfedge_of_node(node, [&](std::size_t h) {
        const std::size_t e = idx.edge_index(idx.halfedge(h));
        if(t.edge_in_tree[e])
          return;
        const std::size_t oh = idx.index(opposite(idx.halfedge(h), tm));
        const std::size_t other = dual_node(oh);
        if(dual_reached[other])
          return;
        dual_reached[other] = true;
        t.dual_parent_halfedge[other] = oh;
        t.edge_in_cotree[e] = true;
        t.dual_order.push_back(other);
      });
    }
  }

  // --- generators: each leftover edge closes a cycle in T
  std::vector<std::size_t> depth(nv, 0);
  for(std::size_t v : t.vertex_order)
    if(t.parent_halfedge[v] != npos)
      depth[v] = depth[idx.source_index(idx.halfedge(t.parent_halfedge[v]))] + 1;
  auto parent_of = [&](std::size_t v) { return idx.source_index(idx.halfedge(t.parent_halfedge[v])); };

  for(std::size_t e = 0; e < ne; ++e)
  {
    if(t.edge_in_tree[e] || t.edge_in_cotree[e])
      continue;
    t.generator_edges.push_back(e);
    const auto h = idx.oriented_halfedge(e);
    // cycle: source a --h--> target b, then up from b to the lowest common ancestor, then down to a
    std::size_t a = idx.source_index(h), b = idx.target_index(h);
    std::vector<std::size_t> up_from_b, down_to_a;
    while(depth[b] > depth[a])
    {
      up_from_b.push_back(idx.index(opposite(idx.halfedge(t.parent_halfedge[b]), tm)));
      b = parent_of(b);
    }
    while(depth[a] > depth[b])
    {
      down_to_a.push_back(t.parent_halfedge[a]);
      a = parent_of(a);
    }
    while(a != b)
    {
      up_from_b.push_back(idx.index(opposite(idx.halfedge(t.parent_halfedge[b]), tm)));
      b = parent_of(b);
      down_to_a.push_back(t.parent_halfedge[a]);
      a = parent_of(a);
    }
    std::vector<std::size_t> loop;
    loop.reserve(1 + up_from_b.size() + down_to_a.size());
    loop.push_back(idx.index(h));
    loop.insert(loop.end(), up_from_b.begin(), up_from_b.end());
    loop.insert(loop.end(), down_to_a.rbegin(), down_to_a.rend());
    t.generator_loops.push_back(std::move(loop));
    t.generator_component.push_back(comps.vertex_component[idx.source_index(h)]);
  }
  return t;
}

/// Integrates a 1-form (per edge, along the edge orientation of Mesh_indices) along the primal
/// spanning tree: u[root] = root_value, u[v] = u[parent] + y(parent -> v). O(|V|), no solve. If
/// the 1-form is exact (y = d0 g) the result equals g up to a constant per component.
template <class Indices>
std::vector<double> integrate_along_tree(const Indices& idx, const Tree_cotree& t,
                                         const std::vector<double>& one_form,
                                         double root_value = 0.)
{
  std::vector<double> u(idx.number_of_vertices(), root_value);
  for(std::size_t v : t.vertex_order)
  {
    const std::size_t ph = t.parent_halfedge[v];
    if(ph == npos)
      continue;
    const auto h = idx.halfedge(ph);
    u[v] = u[idx.source_index(h)] + idx.orientation_sign(h) * one_form[idx.edge_index(h)];
  }
  return u;
}

/// Sum of a 1-form along a chain of halfedges (e.g. a generator or boundary loop).
template <class Indices>
double integrate_along_loop(const Indices& idx, const std::vector<std::size_t>& halfedge_loop,
                            const std::vector<double>& one_form)
{
  double sum = 0.;
  for(std::size_t h : halfedge_loop)
  {
    const auto hd = idx.halfedge(h);
    sum += idx.orientation_sign(hd) * one_form[idx.edge_index(hd)];
  }
  return sum;
}

/// Everything topological about a mesh, computed once.
struct Topology
{
  Boundary_loops boundary;
  Components components;
  Tree_cotree tree;
};

/// With `boundary_first`, the primal tree holds every boundary edge but one per loop (see
/// `Tree_cotree`).
template <class Indices>
Topology compute_topology(const Indices& idx, bool boundary_first = false)
{
  Topology t;
  t.boundary = boundary_loops(idx);
  t.components = connected_components(idx, t.boundary);
  t.tree = tree_cotree(idx, t.components, t.boundary, boundary_first);
  return t;
}

} // namespace internal
} // namespace Surface_design
} // namespace CGAL

#endif // CGAL_SURFACE_DESIGN_INTERNAL_CORE_TOPOLOGY_H
