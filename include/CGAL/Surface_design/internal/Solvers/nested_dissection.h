// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A nested-dissection fill-reducing ordering for the sparse symmetric systems of surface meshes.
//
// Why: on the graph of a surface mesh (a planar-like graph of bounded degree) nested dissection
// gives a Cholesky factor with O(n log n) entries and O(n^1.5) flops (Lipton, Rose & Tarjan 1979),
// against visibly more for minimum-degree orderings on large meshes; METIS computes better
// separators still, but its multilevel partitioner costs 2 to 5 times this ordering (measured by
// the benchmark's `factorization` workload). The graphs met here are meshes, whose breadth-first
// level sets are rings of O(sqrt n) vertices around the root, so George's level-structure
// separators (George & Liu 1981, ch. 8) are small and take O(n) to find.
//
// The algorithm, for a connected part of the graph:
//  1. root: a pseudo-peripheral vertex (breadth-first sweeps from the part's first vertex, each
//     from a vertex of least degree in the last level, while the eccentricity grows);
//  2. separator: the smallest level set of the root's level structure among those that leave at
//     least a third of the rest of the part on each side (if none does, the smallest per vertex
//     on its smaller side);
//  3. thinning: a separator vertex with no neighbour on one side is moved to the other side (it is
//     not needed to separate them); then Fiduccia-Mattheyses passes move separator vertices into
//     the lighter side where that shrinks the separator (refine_separator());
//  4. the two sides are ordered recursively, then the separator; disconnected parts are split into
//     their components first; parts of at most 64 vertices are ordered by exact minimum degree on
//     their elimination graph (bit sets), counting the neighbours outside the part (the ancestors'
//     separators) as a lower bound on the external degree.
// Everything is O(n log n) time and O(n + nnz) memory; no recursion on the call stack.

#ifndef CGAL_SURFACE_DESIGN_INTERNAL_SOLVERS_NESTED_DISSECTION_H
#define CGAL_SURFACE_DESIGN_INTERNAL_SOLVERS_NESTED_DISSECTION_H

#include <CGAL/Surface_design/internal/Solvers/parallel.h>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <algorithm>
#include <cstdlib>
#include <cstdint>
#include <deque>
#include <numeric>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_design {
namespace internal {

/// The adjacency of a symmetric sparse pattern in compressed rows, without the diagonal.
struct Adjacency_graph
{
  std::vector<int> offsets;   // size n + 1
  std::vector<int> neighbors; // neighbors[offsets[v] .. offsets[v+1]) of vertex v, sorted

  int size() const { return int(offsets.size()) - 1; }
  int degree(int v) const { return offsets[std::size_t(v) + 1] - offsets[std::size_t(v)]; }
};

/// The adjacency graph of the symmetric pattern A + A^T of any Eigen sparse matrix (one triangle
/// or both may be stored; explicit zeros count as entries).
template <class SparseMatrixType>
Adjacency_graph symmetric_adjacency(const SparseMatrixType& a)
{
  const int n = int(a.rows());
  Adjacency_graph g;
  g.offsets.assign(std::size_t(n) + 1, 0);
  for(int k = 0; k < a.outerSize(); ++k)
    for(typename SparseMatrixType::InnerIterator it(a, k); it; ++it)
      if(it.row() != it.col())
      {
        ++g.offsets[std::size_t(it.row()) + 1];
        ++g.offsets[std::size_t(it.col()) + 1];
      }
  for(int v = 0; v < n; ++v)
    g.offsets[std::size_t(v) + 1] += g.offsets[std::size_t(v)];
  g.neighbors.resize(std::size_t(g.offsets[std::size_t(n)]));
  std::vector<int> fill(g.offsets.begin(), g.offsets.end() - 1);
  for(int k = 0; k < a.outerSize(); ++k)
    for(typename SparseMatrixType::InnerIterator it(a, k); it; ++it)
      if(it.row() != it.col())
      {
        g.neighbors[std::size_t(fill[std::size_t(it.row())]++)] = int(it.col());
        g.neighbors[std::size_t(fill[std::size_t(it.col())]++)] = int(it.row());
      }
  // sort and remove duplicates (both triangles stored: every edge came twice per row)
  int write = 0;
  for(int v = 0; v < n; ++v)
  {
    const auto first = g.neighbors.begin() + g.offsets[std::size_t(v)];
    const auto last = g.neighbors.begin() + g.offsets[std::size_t(v) + 1];
    std::sort(first, last);
    const auto unique_end = std::unique(first, last);
    g.offsets[std::size_t(v)] = write;
    for(auto it = first; it != unique_end; ++it)
      g.neighbors[std::size_t(write++)] = *it;
  }
  g.offsets[std::size_t(n)] = write;
  g.neighbors.resize(std::size_t(write));
  return g;
}

namespace nested_dissection_detail {

constexpr int leaf_size = 64;   // parts this small are ordered by minimum degree (one 64-bit set)
constexpr int max_sweeps = 2;   // breadth-first sweeps in search of a pseudo-peripheral root
constexpr int max_refinement_passes = 4;  // separator refinement passes per dissection
constexpr int max_losing_moves = 50;      // moves without a new best before a pass stops
constexpr int locked = -2;                // level mark of a vertex moved in the current pass
constexpr int parallel_parts = 4;         // parts dissected concurrently (see run_parallel)
constexpr int parallel_from = 50000;      // vertices from which the parts are dissected concurrently

class Dissector
{
public:
  /// `outside[v]` (optional): neighbours of v outside `g` that are ordered after it (the
  /// separators of a larger graph `g` was cut from), counted in the leaves' external degrees.
  explicit Dissector(const Adjacency_graph& g, std::vector<int> outside = {})
    : m_g(g), m_outside(std::move(outside)), m_part(std::size_t(g.size()), 0), m_level(std::size_t(g.size()), -1),
      m_local(std::size_t(g.size()), -1)
  {}

  /// The same order as a set of independent parts dissected concurrently (TBB): the first levels
  /// are dissected here, breadth first, until `parallel_parts` parts remain; each is then copied
  /// as a graph of its own (with the count of its vertices' neighbours in the separators above)
  /// and ordered by its own Dissector in a task. Deterministic: the parts own disjoint slots.
  std::vector<int> run_parallel()
  {
    std::vector<Range> pushed;
    std::vector<int> order = start(pushed);
    std::deque<Range> queue(pushed.begin(), pushed.end());
    while(!queue.empty() && int(queue.size()) < parallel_parts)
    {
      const Range r = queue.front();
      queue.pop_front();
      pushed.clear();
      order_part(order, r, pushed);
      queue.insert(queue.end(), pushed.begin(), pushed.end());
    }
    const std::vector<Range> parts(queue.begin(), queue.end());
    const int n = m_g.size();
    std::vector<int> local(std::size_t(n), -1); // each task writes the entries of its own vertices
    for_each_index(parts.size(), true, [&](std::size_t i) {
      const Range& r = parts[i];
      const int m = r.end - r.begin;
      for(int k = 0; k < m; ++k)
        local[std::size_t(order[std::size_t(r.begin + k)])] = k;
      Adjacency_graph sub;
      sub.offsets.assign(std::size_t(m) + 1, 0);
      std::vector<int> outside(std::size_t(m), 0);
      for(int k = 0; k < m; ++k)
      {
        const int v = order[std::size_t(r.begin + k)];
        for_each_neighbor(v, [&](int w) {
          if(m_part[std::size_t(w)] == r.part)
            sub.neighbors.push_back(local[std::size_t(w)]);
          else if(m_part[std::size_t(w)] < 0)
            ++outside[std::size_t(k)];
        });
        if(!m_outside.empty())
          outside[std::size_t(k)] += m_outside[std::size_t(v)];
        sub.offsets[std::size_t(k) + 1] = int(sub.neighbors.size());
        std::sort(sub.neighbors.begin() + sub.offsets[std::size_t(k)], sub.neighbors.end());
      }
      const std::vector<int> sub_order = Dissector(sub, std::move(outside)).run();
      std::vector<int> members(order.begin() + r.begin, order.begin() + r.end);
      for(int k = 0; k < m; ++k)
        order[std::size_t(r.begin + k)] = members[std::size_t(sub_order[std::size_t(k)])];
    });
    return order;
  }

  /// Returns the elimination order: order[k] is the vertex eliminated k-th.
  std::vector<int> run()
  {
    std::vector<Range> stack;
    std::vector<int> order = start(stack);
    while(!stack.empty())
    {
      const Range r = stack.back();
      stack.pop_back();
      order_part(order, r, stack);
    }
    return order;
  }

private:
  struct Range { int begin, end, part; };

  /// The identity order and the whole graph as the first part. Every part owns the slots
  /// [begin, end) of the order: its vertices are kept there and end up in their final positions
  /// (separators are placed last, the sides before them).
  std::vector<int> start(std::vector<Range>& parts)
  {
    const int n = m_g.size();
    std::vector<int> order(static_cast<std::size_t>(n));
    std::iota(order.begin(), order.end(), 0);
    m_next_part = 1;
    if(n > 0)
      parts.push_back({0, n, 0});
    return order;
  }

  /// Orders a leaf part, or dissects a larger one and appends its sub-parts to `parts`.
  void order_part(std::vector<int>& order, const Range& r, std::vector<Range>& parts)
  {
    if(r.end - r.begin <= leaf_size)
      order_leaf(order, r);
    else
      dissect(order, r, parts);
  }

  const Adjacency_graph& m_g;
  std::vector<int> m_outside; // neighbours outside the graph ordered after each vertex (or empty)
  std::vector<int> m_part;  // part label of each vertex still to be ordered; -1 once ordered
  std::vector<int> m_level; // breadth-first level, scratch (valid for the current part only)
  std::vector<int> m_local; // index within a leaf, scratch
  std::vector<int> m_queue;
  std::vector<std::pair<int, int>> m_moved; // (vertex, previous side) of a refinement pass
  int m_next_part = 1;

  template <class F>
  void for_each_neighbor(int v, const F& f) const
  {
    for(int k = m_g.offsets[std::size_t(v)]; k < m_g.offsets[std::size_t(v) + 1]; ++k)
      f(m_g.neighbors[std::size_t(k)]);
  }

  /// Breadth-first search from `root` inside part `p`; fills m_queue in visiting order and
  /// m_level; returns the eccentricity of the root (the last level).
  int bfs(int root, int p, const std::vector<int>& members)
  {
    for(int v : members)
      m_level[std::size_t(v)] = -1;
    m_queue.clear();
    m_queue.push_back(root);
    m_level[std::size_t(root)] = 0;
    for(std::size_t head = 0; head < m_queue.size(); ++head)
    {
      const int v = m_queue[head];
      const int next = m_level[std::size_t(v)] + 1;
      for_each_neighbor(v, [&](int w) {
        if(m_part[std::size_t(w)] == p && m_level[std::size_t(w)] < 0)
        {
          m_level[std::size_t(w)] = next;
          m_queue.push_back(w);
        }
      });
    }
    return m_level[std::size_t(m_queue.back())];
  }

  void relabel(const std::vector<int>& vertices, int p)
  {
    for(int v : vertices)
      m_part[std::size_t(v)] = p;
  }

  /// Writes `groups` one after the other into order[r.begin ...), pushes every group but the last
  /// (the separator, already final when `last_is_separator`) as a new part.
  void split(std::vector<int>& order, const Range& r, std::vector<std::vector<int>>& groups,
             bool last_is_separator, std::vector<Range>& stack)
  {
    int at = r.begin;
    for(std::size_t i = 0; i < groups.size(); ++i)
    {
      const std::vector<int>& group = groups[i];
      std::copy(group.begin(), group.end(), order.begin() + at);
      if(last_is_separator && i + 1 == groups.size())
        relabel(group, -1);
      else if(!group.empty())
      {
        const int p = m_next_part++;
        relabel(group, p);
        stack.push_back({at, at + int(group.size()), p});
      }
      at += int(group.size());
    }
  }

  void dissect(std::vector<int>& order, const Range& r, std::vector<Range>& stack)
  {
    const std::vector<int> members(order.begin() + r.begin, order.begin() + r.end);
    const int m = int(members.size());

    int root = members.front();
    int eccentricity = bfs(root, r.part, members);
    if(int(m_queue.size()) < m)
    {
      split_components(order, r, members, stack);
      return;
    }
    // pseudo-peripheral root: restart from a vertex of least degree in the last level while the
    // eccentricity grows
    for(int sweep = 1; sweep < max_sweeps; ++sweep)
    {
      int candidate = -1;
      for(auto it = m_queue.rbegin(); it != m_queue.rend() && m_level[std::size_t(*it)] == eccentricity; ++it)
        if(candidate < 0 || m_g.degree(*it) < m_g.degree(candidate))
          candidate = *it;
      const int root_level_count = eccentricity;
      const int new_eccentricity = bfs(candidate, r.part, members);
      if(new_eccentricity <= root_level_count)
      {
        if(new_eccentricity < root_level_count)
          eccentricity = bfs(root, r.part, members); // restore the better structure
        break;
      }
      root = candidate;
      eccentricity = new_eccentricity;
    }

    if(eccentricity < 2)
    {
      // a (nearly) complete graph: no level separates anything; order it as it is
      relabel(members, -1);
      return;
    }

    // level sizes and the separating level
    std::vector<int> level_size(std::size_t(eccentricity) + 1, 0);
    for(int v : members)
      ++level_size[std::size_t(m_level[std::size_t(v)])];
    // the smallest level that leaves at least a third of the rest on each side; if none does,
    // the smallest level per vertex on the smaller side
    int best = -1;
    bool best_balanced = false;
    double best_cost = 0.;
    int below = level_size[0];
    for(int l = 1; l < eccentricity; ++l)
    {
      const int s = level_size[std::size_t(l)];
      const int smaller = std::min(below, m - below - s);
      const bool balanced = 3 * smaller >= m - s;
      const double cost = balanced ? double(s) : double(s) / double(std::max(smaller, 1));
      if(best < 0 || (balanced && !best_balanced) || (balanced == best_balanced && cost < best_cost))
      {
        best = l;
        best_balanced = balanced;
        best_cost = cost;
      }
      below += s;
    }

    // sides: 0 below the level, 1 above, 2 the separator; then thin the separator
    std::vector<std::vector<int>> groups(3);
    std::vector<int>& side = m_local; // reuse as a side label
    for(int v : members)
    {
      const int l = m_level[std::size_t(v)];
      side[std::size_t(v)] = l < best ? 0 : (l > best ? 1 : 2);
    }
    for(int from_side = 0; from_side < 2; ++from_side)
    {
      // a separator vertex with no neighbour on side `other` is not needed to separate: it
      // joins side `from_side`
      const int other = 1 - from_side;
      for(int v : members)
      {
        if(side[std::size_t(v)] != 2)
          continue;
        bool touches_other = false;
        for_each_neighbor(v, [&](int w) {
          if(m_part[std::size_t(w)] == r.part && side[std::size_t(w)] == other)
            touches_other = true;
        });
        if(!touches_other)
          side[std::size_t(v)] = from_side;
      }
    }
    refine_separator(members, r.part);
    for(int v : members)
    {
      groups[std::size_t(side[std::size_t(v)])].push_back(v);
      side[std::size_t(v)] = -1;
    }
    split(order, r, groups, true, stack);
  }

  /// Two-sided Fiduccia-Mattheyses refinement of a vertex separator (sides in m_local: 0, 1, 2 =
  /// separator): moving separator vertex v to side s pulls its neighbours on the other side into
  /// the separator, so the separator shrinks by 1 - |N(v) on the other side|. Each pass moves every
  /// separator vertex at most once, best gain first, always into the lighter side (so balance
  /// only improves or stays within one move), accepts losing moves to climb out of local minima
  /// and rolls back to the smallest separator seen; passes stop when one no longer improves.
  void refine_separator(const std::vector<int>& members, int p)
  {
    std::vector<int>& side = m_local;
    int weight[3] = {0, 0, 0};
    for(int v : members)
      ++weight[side[std::size_t(v)]];
    const int m = int(members.size());
    for(int pass = 0; pass < max_refinement_passes; ++pass)
    {
      // gain of moving v into side s: 1 - (neighbours of v on side 1 - s)
      auto gain = [&](int v, int s) {
        int g = 1;
        for_each_neighbor(v, [&](int w) {
          if(m_part[std::size_t(w)] == p && side[std::size_t(w)] == 1 - s)
            --g;
        });
        return g;
      };
      using Entry = std::pair<int, int>; // (gain, vertex)
      std::vector<Entry> heap[2];
      auto push = [&](int v) {
        for(int s = 0; s < 2; ++s)
        {
          heap[s].push_back({gain(v, s), v});
          std::push_heap(heap[s].begin(), heap[s].end());
        }
      };
      m_moved.clear();
      for(int v : members)
        if(side[std::size_t(v)] == 2)
          push(v);
      const int initial_separator = weight[2];
      int best_separator = weight[2], best_imbalance = std::abs(weight[0] - weight[1]);
      std::size_t best_moves = 0;
      int moves_since_best = 0;
      while(moves_since_best < max_losing_moves)
      {
        const int to = weight[0] <= weight[1] ? 0 : 1;
        int v = -1;
        while(!heap[to].empty())
        {
          std::pop_heap(heap[to].begin(), heap[to].end());
          const Entry e = heap[to].back();
          heap[to].pop_back();
          // stale entries: moved or locked vertices, or gains changed since the push
          if(side[std::size_t(e.second)] == 2 && m_level[std::size_t(e.second)] != locked &&
             gain(e.second, to) == e.first)
          {
            v = e.second;
            break;
          }
        }
        if(v < 0)
          break;
        // keep both sides non-empty and the move from overshooting the balance
        const int from = 1 - to;
        int pulled = 0;
        for_each_neighbor(v, [&](int w) {
          if(m_part[std::size_t(w)] == p && side[std::size_t(w)] == from)
            ++pulled;
        });
        if(weight[from] - pulled < 1 || weight[to] + 1 > weight[from] - pulled + m / 4 + 1)
          continue;
        m_level[std::size_t(v)] = locked;
        m_moved.push_back({v, 2});
        side[std::size_t(v)] = to;
        ++weight[to];
        --weight[2];
        for_each_neighbor(v, [&](int w) {
          if(m_part[std::size_t(w)] == p && side[std::size_t(w)] == from)
          {
            m_moved.push_back({w, from});
            side[std::size_t(w)] = 2;
            --weight[from];
            ++weight[2];
            m_level[std::size_t(w)] = locked; // enters the separator: not moved again this pass
          }
        });
        // gains of the separator vertices around v and the pulled vertices changed
        for(std::size_t i = m_moved.size() - std::size_t(pulled) - 1; i < m_moved.size(); ++i)
          for_each_neighbor(m_moved[i].first, [&](int w) {
            if(m_part[std::size_t(w)] == p && side[std::size_t(w)] == 2 && m_level[std::size_t(w)] != locked)
              push(w);
          });
        const int imbalance = std::abs(weight[0] - weight[1]);
        if(weight[2] < best_separator || (weight[2] == best_separator && imbalance < best_imbalance))
        {
          best_separator = weight[2];
          best_imbalance = imbalance;
          best_moves = m_moved.size();
          moves_since_best = 0;
        }
        else
          ++moves_since_best;
      }
      // roll back to the best state, unlock
      while(m_moved.size() > best_moves)
      {
        const auto [v, old_side] = m_moved.back();
        m_moved.pop_back();
        --weight[side[std::size_t(v)]];
        ++weight[old_side];
        side[std::size_t(v)] = old_side;
      }
      for(int v : members)
        m_level[std::size_t(v)] = -1;
      if(best_separator >= initial_separator)
        break;
    }
  }

  /// A disconnected part: every connected component becomes a part of its own.
  void split_components(std::vector<int>& order, const Range& r, const std::vector<int>& members,
                        std::vector<Range>& stack)
  {
    std::vector<std::vector<int>> groups;
    const int visited_label = m_next_part++;
    for(int v : members)
    {
      if(m_part[std::size_t(v)] != r.part)
        continue; // already in a component
      std::vector<int> component{v};
      m_part[std::size_t(v)] = visited_label;
      for(std::size_t head = 0; head < component.size(); ++head)
        for_each_neighbor(component[head], [&](int w) {
          if(m_part[std::size_t(w)] == r.part)
          {
            m_part[std::size_t(w)] = visited_label;
            component.push_back(w);
          }
        });
      groups.push_back(std::move(component));
    }
    split(order, r, groups, false, stack);
  }

  /// Exact minimum degree on the elimination graph of a part of at most 64 vertices.
  void order_leaf(std::vector<int>& order, const Range& r)
  {
    const int k = r.end - r.begin;
    std::uint64_t adjacency[leaf_size];
    int external[leaf_size];
    for(int i = 0; i < k; ++i)
      m_local[std::size_t(order[std::size_t(r.begin + i)])] = i;
    for(int i = 0; i < k; ++i)
    {
      const int v = order[std::size_t(r.begin + i)];
      adjacency[i] = 0;
      external[i] = m_outside.empty() ? 0 : m_outside[std::size_t(v)];
      for_each_neighbor(v, [&](int w) {
        if(m_part[std::size_t(w)] == r.part)
          adjacency[i] |= std::uint64_t(1) << m_local[std::size_t(w)];
        else if(m_part[std::size_t(w)] < 0)
          ++external[i]; // an ancestor's separator vertex, ordered after this part
      });
    }
    std::uint64_t alive = k == 64 ? ~std::uint64_t(0) : ((std::uint64_t(1) << k) - 1);
    std::vector<int> eliminated;
    eliminated.reserve(std::size_t(k));
    for(int step = 0; step < k; ++step)
    {
      int best = -1, best_degree = 0;
      for(int i = 0; i < k; ++i)
        if(alive >> i & 1)
        {
          const int d = popcount(adjacency[i] & alive) + external[i];
          if(best < 0 || d < best_degree)
          {
            best = i;
            best_degree = d;
          }
        }
      const std::uint64_t bit = std::uint64_t(1) << best;
      alive &= ~bit;
      const std::uint64_t clique = adjacency[best] & alive;
      for(int j = 0; j < k; ++j)
        if(clique >> j & 1)
        {
          adjacency[j] |= clique;
          adjacency[j] &= ~(std::uint64_t(1) << j);
          external[j] = std::max(external[j], external[best]);
        }
      eliminated.push_back(order[std::size_t(r.begin + best)]);
    }
    for(int i = 0; i < k; ++i)
    {
      order[std::size_t(r.begin + i)] = eliminated[std::size_t(i)];
      m_local[std::size_t(eliminated[std::size_t(i)])] = -1;
      m_part[std::size_t(eliminated[std::size_t(i)])] = -1;
    }
  }

  static int popcount(std::uint64_t x)
  {
    int c = 0;
    for(; x; x &= x - 1)
      ++c;
    return c;
  }
};

} // namespace nested_dissection_detail

/// The nested-dissection elimination order of a graph: order[k] is the vertex eliminated k-th.
/// With TBB, graphs of at least 50k vertices are cut into 4 parts that are dissected concurrently.
inline std::vector<int> nested_dissection_order(const Adjacency_graph& g)
{
#if defined(CGAL_LINKED_WITH_TBB)
  if(g.size() >= nested_dissection_detail::parallel_from)
    return nested_dissection_detail::Dissector(g).run_parallel();
#endif
  return nested_dissection_detail::Dissector(g).run();
}

/// Eigen ordering functor (the `Ordering` parameter of `Eigen::SimplicialLDLT` and
/// `Eigen::SimplicialLLT`, like `Eigen::AMDOrdering`): the nested-dissection order of the
/// symmetric pattern of the matrix. `perm.indices()[k]` is the row eliminated k-th.
template <class StorageIndex>
class Nested_dissection_ordering
{
public:
  using PermutationType = Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, StorageIndex>;

  template <class MatrixType>
  void operator()(const MatrixType& a, PermutationType& perm) const
  {
    const std::vector<int> order = nested_dissection_order(symmetric_adjacency(a));
    perm.resize(Eigen::Index(order.size()));
    for(std::size_t k = 0; k < order.size(); ++k)
      perm.indices()[Eigen::Index(k)] = StorageIndex(order[k]);
  }
};

} // namespace internal
} // namespace Surface_design
} // namespace CGAL

#endif // CGAL_SURFACE_DESIGN_INTERNAL_SOLVERS_NESTED_DISSECTION_H
