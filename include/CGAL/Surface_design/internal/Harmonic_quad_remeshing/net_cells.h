// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The cells of the net as a polygon soup: the topology of a soup, the repair of cells whose
// boundary walk visits a node twice (a cell that is not a disk), and the finer spacing near the
// saddles that a fall-back uses.

#ifndef CGAL_SURFACE_DESIGN_INTERNAL_HARMONIC_QUAD_REMESHING_NET_CELLS_H
#define CGAL_SURFACE_DESIGN_INTERNAL_HARMONIC_QUAD_REMESHING_NET_CELLS_H

#include <CGAL/Surface_design/internal/Harmonic_quad_remeshing/harmonic_function.h>
#include <CGAL/Surface_design/internal/Harmonic_quad_remeshing/quad_net.h>
#include <CGAL/Surface_design/internal/Harmonic_quad_remeshing/trace_mesh.h>

#include <algorithm>
#include <cstddef>
#include <iterator>
#include <limits>
#include <map>
#include <numeric>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_design {
namespace internal {
namespace harmonic_quad {

/// Euler characteristic, boundary loops and connected components of a surface given by its
/// faces (vertex cycles); vertices used by no face are not counted.
struct Soup_topology
{
  long euler_characteristic = 0;
  std::size_t boundary_loops = 0;
  std::size_t components = 0;

  bool operator==(const Soup_topology& o) const
  {
    return euler_characteristic == o.euler_characteristic && boundary_loops == o.boundary_loops &&
           components == o.components;
  }
  bool operator!=(const Soup_topology& o) const { return !(*this == o); }

  std::string text() const
  {
    return "Euler characteristic " + std::to_string(euler_characteristic) + ", " + std::to_string(boundary_loops) +
           " boundary loop" + (boundary_loops == 1 ? "" : "s") + ", " + std::to_string(components) + " component" +
           (components == 1 ? "" : "s");
  }
};

/// The topology of faces over `number_of_points` points. Meant for valid polygon meshes (every
/// directed edge used once): a boundary loop is a cycle of directed edges without a twin.
template <class FaceRange>
Soup_topology soup_topology(const FaceRange& faces, std::size_t number_of_points)
{
  Soup_topology t;
  std::vector<std::size_t> parent(number_of_points);
  std::iota(parent.begin(), parent.end(), std::size_t(0));
  auto find = [&](std::size_t v) {
    while(parent[v] != v)
      v = parent[v] = parent[parent[v]];
    return v;
  };
  std::set<std::pair<std::size_t, std::size_t>> directed;
  std::vector<char> used(number_of_points, 0);
  std::size_t face_count = 0;
  for(const auto& f : faces)
  {
    ++face_count;
    const std::size_t n = std::size(f);
    for(std::size_t k = 0; k < n; ++k)
    {
      const std::size_t a = std::size_t(f[k]), b = std::size_t(f[(k + 1) % n]);
      used[a] = 1;
      directed.emplace(a, b);
      parent[find(a)] = find(b);
    }
  }
  std::size_t edges = 0, vertices = 0;
  std::map<std::size_t, std::size_t> boundary_next; // a -> b for directed edges without a twin
  for(const auto& [a, b] : directed)
  {
    const bool twin = directed.count({b, a}) > 0;
    edges += twin ? (a < b ? 1 : 0) : 1;
    if(!twin)
      boundary_next[b] = a; // the boundary walk, opposite to the face's direction
  }
  for(std::size_t v = 0; v < number_of_points; ++v)
    if(used[v])
    {
      ++vertices;
      t.components += find(v) == v;
    }
  std::set<std::size_t> seen;
  for(const auto& [start, next] : boundary_next)
  {
    if(seen.count(start))
      continue;
    ++t.boundary_loops;
    for(std::size_t v = start; seen.insert(v).second;)
    {
      const auto it = boundary_next.find(v);
      if(it == boundary_next.end())
        break;
      v = it->second;
    }
  }
  t.euler_characteristic = long(vertices) - long(edges) + long(face_count);
  return t;
}

/// A cell of the net whose boundary walk visits a node twice is not a disk: a band crossed by a
/// single gradient line leaves a slit (the walk runs along the line on both sides), two loops
/// of the net touching at a node pinch it. Such a face (not a valid polygon) is cut by a chord
/// between the two parts of its walk, the closest pair of nodes (one on each part, each visited
/// once, not yet joined by an edge) until every face is simple. Returns the number of chords.
inline std::size_t split_pinched_cells(Polygon_soup& soup)
{
  std::set<std::pair<std::size_t, std::size_t>> joined;
  auto key = [](std::size_t a, std::size_t b) { return std::make_pair((std::min)(a, b), (std::max)(a, b)); };
  for(const auto& f : soup.faces)
    for(std::size_t k = 0; k < f.size(); ++k)
      joined.insert(key(f[k], f[(k + 1) % f.size()]));
  std::size_t chords = 0;
  for(std::size_t fi = 0; fi < soup.faces.size(); ++fi)
    for(;;)
    {
      const std::vector<std::size_t> w = soup.faces[fi];
      const std::size_t n = w.size();
      std::map<std::size_t, std::size_t> count;
      for(std::size_t v : w)
        ++count[v];
      // the first node visited twice: w = v X v Y (cyclically)
      std::size_t i = n, j = n;
      for(std::size_t a = 0; a < n && i == n; ++a)
        for(std::size_t b = a + 1; b < n; ++b)
          if(w[a] == w[b])
          {
            i = a;
            j = b;
            break;
          }
      if(i == n)
        break;
      std::vector<std::size_t> x_part(w.begin() + std::ptrdiff_t(i) + 1, w.begin() + std::ptrdiff_t(j)), y_part;
      for(std::size_t k = j + 1; k < n + i; ++k)
        y_part.push_back(w[k % n]);
      double best = std::numeric_limits<double>::infinity();
      std::size_t bp = 0, bq = 0;
      for(std::size_t p = 0; p < x_part.size(); ++p)
        for(std::size_t q = 0; q < y_part.size(); ++q)
        {
          const std::size_t x = x_part[p], y = y_part[q];
          if(count[x] != 1 || count[y] != 1 || joined.count(key(x, y)))
            continue;
          const double d = (soup.points[x] - soup.points[y]).squaredNorm();
          if(d < best)
          {
            best = d;
            bp = p;
            bq = q;
          }
        }
      if(!(best < std::numeric_limits<double>::infinity()))
        break; // no chord: left as it is (the validity check reports it)
      // v X[0..p] Y[q..] and X[p..] v Y[0..q]: the chord x -> y in the first, y -> x in the second
      std::vector<std::size_t> first{w[i]}, second;
      first.insert(first.end(), x_part.begin(), x_part.begin() + std::ptrdiff_t(bp) + 1);
      first.insert(first.end(), y_part.begin() + std::ptrdiff_t(bq), y_part.end());
      second.assign(x_part.begin() + std::ptrdiff_t(bp), x_part.end());
      second.push_back(w[i]);
      second.insert(second.end(), y_part.begin(), y_part.begin() + std::ptrdiff_t(bq) + 1);
      joined.insert(key(x_part[bp], y_part[bq]));
      soup.faces[fi] = std::move(first);
      soup.faces.push_back(std::move(second));
      ++chords;
    }
  return chords;
}

/// A spacing scale per face for the fall-back "finer spacing near the saddles": `scale` on the
/// faces with a corner within `radius` of a saddle (distances along the mesh's edges, from
/// every saddle at once), 1 elsewhere.
inline std::vector<double> saddle_spacing_scale(const Trace_mesh& m, const std::vector<std::size_t>& saddles,
                                                double radius, double scale)
{
  const std::vector<double> distance = edge_distances(m, saddles, radius);
  std::vector<double> out(m.number_of_faces(), 1.);
  for(std::size_t f = 0; f < out.size(); ++f)
    for(std::size_t v : m.tri[f])
      if(distance[v] <= radius)
        out[f] = scale;
  return out;
}

} // namespace harmonic_quad
} // namespace internal
} // namespace Surface_design
} // namespace CGAL

#endif // CGAL_SURFACE_DESIGN_INTERNAL_HARMONIC_QUAD_REMESHING_NET_CELLS_H
