// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Cotangent weights of a triangle mesh, optionally on its intrinsic Delaunay triangulation.

#ifndef CGAL_SURFACE_DESIGN_INTERNAL_CORE_INTRINSIC_DELAUNAY_H
#define CGAL_SURFACE_DESIGN_INTERNAL_CORE_INTRINSIC_DELAUNAY_H

#include <CGAL/Surface_design/internal/Core/geometry.h>
#include <CGAL/Surface_design/internal/Core/Mesh_indices.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Surface_design {
namespace internal {

/// One weighted edge (i, j, w) of a Laplacian L = sum_e w_e (e_i - e_j)(e_i - e_j)^T.
struct Weighted_edge
{
  std::size_t i, j;
  double w;
};

/// An intrinsic triangulation of a triangle mesh (halfedges with edge lengths), starting as the
/// mesh itself, and its cotangent weights w_ij = (cot a_ij + cot b_ij) / 2.
///
/// `make_delaunay()` flips edges *intrinsically* (only the edge lengths change; the vertex set and
/// the metric stay: Bobenko & Springborn 2007) until every interior edge is locally Delaunay
/// (a_ij + b_ij <= pi): every interior weight is then >= 0 up to rounding (the flips stop at
/// cot a_ij + cot b_ij >= -1e-12, so a few weights of needle triangles may be tiny negatives), so
/// the Laplacian satisfies the discrete maximum principle. Boundary edges are never flipped (an obtuse angle opposite one keeps
/// its weight negative), and the weights may join vertices that are not neighbours in the mesh.
class Intrinsic_triangulation
{
public:
  template <class Indices, class VertexPointMap>
  Intrinsic_triangulation(const Indices& idx, const VertexPointMap& vpm)
  {
    const auto& tm = idx.mesh();
    const std::size_t nf = idx.number_of_faces();
    m_next.resize(3 * nf);
    m_twin.assign(3 * nf, npos);
    m_source.resize(3 * nf);
    m_length.resize(3 * nf);
    std::vector<std::size_t> slot_of_halfedge(idx.number_of_halfedges(), npos);
    for(std::size_t f = 0; f < nf; ++f)
    {
      auto h = halfedge(idx.face(f), tm);
      for(int k = 0; k < 3; ++k, h = next(h, tm))
      {
        const std::size_t s = 3 * f + std::size_t(k);
        m_next[s] = 3 * f + std::size_t((k + 1) % 3);
        m_source[s] = idx.source_index(h);
        m_length[s] = (position(vpm, target(h, tm)) - position(vpm, source(h, tm))).norm();
        slot_of_halfedge[idx.index(h)] = s;
      }
    }
    for(std::size_t f = 0; f < nf; ++f)
    {
      auto h = halfedge(idx.face(f), tm);
      for(int k = 0; k < 3; ++k, h = next(h, tm))
      {
        const auto o = opposite(h, tm);
        if(!idx.is_border(o))
          m_twin[3 * f + std::size_t(k)] = slot_of_halfedge[idx.index(o)];
      }
    }
  }

  /// Flips non-Delaunay interior edges until none is left; returns the number of flips.
  std::size_t make_delaunay()
  {
    std::vector<std::size_t> stack;
    std::vector<char> queued(m_next.size(), 1);
    for(std::size_t h = 0; h < m_next.size(); ++h)
      if(m_twin[h] != npos && h < m_twin[h])
        stack.push_back(h);
      else
        queued[h] = 0;
    std::size_t flips = 0;
    const std::size_t limit = 100 * m_next.size() + 1000; // flips terminate; a guard against NaN
    while(!stack.empty() && flips < limit)
    {
      const std::size_t h = stack.back();
      stack.pop_back();
      queued[h] = 0;
      const std::size_t t = m_twin[h];
      if(t == npos || face_of(h) == face_of(t) || cot_sum(h) >= -1e-12)
        continue;
      flip(h);
      ++flips;
      for(std::size_t g : {m_next[h], m_next[m_next[h]], m_next[t], m_next[m_next[t]]})
      {
        const std::size_t key = m_twin[g] == npos ? npos : (std::min)(g, m_twin[g]);
        if(key != npos && !queued[key])
        {
          queued[key] = 1;
          stack.push_back(key);
        }
      }
    }
    return flips;
  }

  /// One weighted edge per edge of the (current) triangulation, with the cotangent weight.
  std::vector<Weighted_edge> cotangent_weights() const
  {
    std::vector<Weighted_edge> out;
    out.reserve(m_next.size() / 2 + 1);
    for(std::size_t h = 0; h < m_next.size(); ++h)
    {
      const std::size_t t = m_twin[h];
      if(t != npos && t < h)
        continue;
      const double w = 0.5 * (cot_opposite(h) + (t == npos ? 0. : cot_opposite(t)));
      out.push_back({m_source[h], m_source[m_next[h]], w});
    }
    return out;
  }

  /// Number of interior edges whose cotangent weight is negative.
  std::size_t number_of_negative_weights() const
  {
    std::size_t n = 0;
    for(const Weighted_edge& e : cotangent_weights())
      n += e.w < 0.;
    return n;
  }

private:
  std::size_t face_of(std::size_t h) const { return (std::min)({h, m_next[h], m_next[m_next[h]]}); }

  // Cotangent of the angle opposite halfedge h in its triangle, from the edge lengths.
  double cot_opposite(std::size_t h) const
  {
    const double a = m_length[h], b = m_length[m_next[h]], c = m_length[m_next[m_next[h]]];
    const double s = 0.5 * (a + b + c);
    const double area = std::sqrt((std::max)(0., s * (s - a) * (s - b) * (s - c)));
    return (b * b + c * c - a * a) / (4. * (std::max)(area, 1e-300));
  }

  double cot_sum(std::size_t h) const { return cot_opposite(h) + cot_opposite(m_twin[h]); }

  // Angle of the triangle of h at the source of h.
  double angle_at_source(std::size_t h) const
  {
    const double a = m_length[m_next[h]], b = m_length[h], c = m_length[m_next[m_next[h]]];
    const double x = (b * b + c * c - a * a) / (2. * b * c);
    return std::acos((std::max)(-1., (std::min)(1., x)));
  }

  // h: a -> b in (a, b, c), t: b -> a in (b, a, d); afterwards h: d -> c in (a, d, c) and
  // t: c -> d in (d, b, c).
  void flip(std::size_t h)
  {
    const std::size_t t = m_twin[h];
    const std::size_t hn = m_next[h], hnn = m_next[hn], tn = m_next[t], tnn = m_next[tn];
    // unfold at a: the angle c-a-d is the sum of the two angles at a
    const double alpha = angle_at_source(h) + angle_at_source(tn);
    const double ac = m_length[hnn], ad = m_length[tn];
    const double cd = std::sqrt((std::max)(0., ac * ac + ad * ad - 2. * ac * ad * std::cos(alpha)));
    const std::size_t c = m_source[hnn], d = m_source[tnn];
    m_source[h] = d;
    m_source[t] = c;
    m_length[h] = m_length[t] = cd;
    m_next[h] = hnn;
    m_next[hnn] = tn;
    m_next[tn] = h;
    m_next[t] = tnn;
    m_next[tnn] = hn;
    m_next[hn] = t;
  }

  std::vector<std::size_t> m_next, m_twin, m_source;
  std::vector<double> m_length; // per halfedge; twins always agree
};

} // namespace internal
} // namespace Surface_design
} // namespace CGAL

#endif // CGAL_SURFACE_DESIGN_INTERNAL_CORE_INTRINSIC_DELAUNAY_H
