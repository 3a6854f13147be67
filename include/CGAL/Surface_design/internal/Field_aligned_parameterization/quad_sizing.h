// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Curvature-adapted sizing of field-aligned quads: a per-vertex scale of the stripes' frequency
// that makes the quads smaller where the surface bends, for an even chord error at the same
// number of quads.

#ifndef CGAL_SURFACE_DESIGN_INTERNAL_FIELD_ALIGNED_PARAMETERIZATION_QUAD_SIZING_H
#define CGAL_SURFACE_DESIGN_INTERNAL_FIELD_ALIGNED_PARAMETERIZATION_QUAD_SIZING_H

#include <CGAL/Surface_design/internal/Core/geometry.h>

#include <Eigen/Core>
#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <functional>
#include <numeric>
#include <queue>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_design {
namespace internal {

/// Per vertex, the largest absolute principal curvature, from the edge-based curvature tensor
/// (Cohen-Steiner & Morvan: an edge of length l and signed dihedral angle beta bends the surface
/// across itself by beta l), integrated over a ball of radius about `radius`: the tensors and the
/// areas are summed, then averaged over the one-ring (radius / mean edge length / 2)^2 times
/// (rounded, at most 64), so that the signs of a scan's noise cancel before the magnitude is
/// taken. The tensor is projected onto the tangent plane of the vertex (angle-weighted
/// normal); boundary edges bend nothing.
template <class Indices, class VertexPointMap>
std::vector<double> largest_curvature_magnitudes(const Indices& idx, const VertexPointMap& vpm, double radius)
{
  const auto& tm = idx.mesh();
  const std::size_t nv = idx.number_of_vertices();
  const std::vector<Eigen::Vector3d> p = vertex_positions(idx, vpm);
  const std::vector<Eigen::Vector3d> fn = face_normals(idx, vpm);
  std::vector<Eigen::Matrix3d> tensor(nv, Eigen::Matrix3d::Zero());
  std::vector<double> area = vertex_areas(idx, face_areas(idx, vpm));
  double total_length = 0.;
  for(std::size_t e = 0; e < idx.number_of_edges(); ++e)
  {
    const auto h = idx.oriented_halfedge(e), o = opposite(h, tm);
    const std::size_t i = idx.source_index(h), j = idx.target_index(h);
    const Eigen::Vector3d d = p[j] - p[i];
    const double l = d.norm();
    total_length += l;
    if(idx.is_border(h) || idx.is_border(o) || !(l > 0.))
      continue;
    const Eigen::Vector3d& n1 = fn[idx.index(face(h, tm))];
    const Eigen::Vector3d& n2 = fn[idx.index(face(o, tm))];
    const Eigen::Vector3d u = d / l;
    const double beta = std::atan2(n1.cross(n2).dot(u), n1.dot(n2));
    const Eigen::Matrix3d c = (0.5 * beta * l) * (u * u.transpose());
    tensor[i] += c;
    tensor[j] += c;
  }
  // the rings, with the vertices' neighbours in one flat array
  std::vector<std::size_t> first(nv + 1, 0), ring(2 * idx.number_of_edges());
  for(std::size_t e = 0; e < idx.number_of_edges(); ++e)
  {
    const auto ij = idx.edge_vertices(e);
    ++first[ij.first + 1];
    ++first[ij.second + 1];
  }
  std::partial_sum(first.begin(), first.end(), first.begin());
  {
    std::vector<std::size_t> fill(first.begin(), first.end() - 1);
    for(std::size_t e = 0; e < idx.number_of_edges(); ++e)
    {
      const auto ij = idx.edge_vertices(e);
      ring[fill[ij.first]++] = ij.second;
      ring[fill[ij.second]++] = ij.first;
    }
  }
  const double mean_length = total_length / double((std::max)(idx.number_of_edges(), std::size_t(1)));
  const int rounds = int((std::min)(std::round(std::pow(radius / (2. * mean_length), 2)), 64.));
  std::vector<Eigen::Matrix3d> next_tensor(nv);
  std::vector<double> next_area(nv);
  for(int r = 0; r < rounds; ++r)
  {
    for(std::size_t v = 0; v < nv; ++v)
    {
      Eigen::Matrix3d t = tensor[v];
      double a = area[v];
      for(std::size_t k = first[v]; k < first[v + 1]; ++k)
      {
        t += tensor[ring[k]];
        a += area[ring[k]];
      }
      const double w = 1. / double(first[v + 1] - first[v] + 1);
      next_tensor[v] = w * t;
      next_area[v] = w * a;
    }
    std::swap(tensor, next_tensor);
    std::swap(area, next_area);
  }
  const std::vector<Eigen::Vector3d> normal = vertex_normals(idx, vpm);
  std::vector<double> kappa(nv, 0.);
  for(std::size_t v = 0; v < nv; ++v)
  {
    if(!(area[v] > 0.))
      continue;
    const Eigen::Matrix3d P = Eigen::Matrix3d::Identity() - normal[v] * normal[v].transpose();
    const Eigen::Matrix3d k = P * (tensor[v] / area[v]) * P;
    const Eigen::Vector3d ev = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(k, Eigen::EigenvaluesOnly).eigenvalues();
    kappa[v] = ev.cwiseAbs().maxCoeff();
  }
  return kappa;
}

/// What `curvature_adapted_frequency_scale()` made.
struct Quad_sizing
{
  std::vector<double> scale;             ///< per vertex: the local frequency over the mean one
  double smallest = 1., largest = 1.;    ///< the spacing's range, over h
};

/// A per-vertex scale s of the frequency 1 / h of field-aligned quads that equalizes their chord
/// error: the local spacing h / s follows 1 / sqrt(kappa) (kappa: the largest absolute principal
/// curvature at the scale of h, `largest_curvature_magnitudes()`), the sagitta of a quad edge of
/// length l on a curve of curvature kappa being kappa l^2 / 8. The spacing is bounded to `ratio`
/// times the finest (the finest: at the area-weighted 98th percentile of the curvature, so that a
/// few spikes do not set it), graded so that it grows by at most `grading` per unit length
/// (h_u <= h_v + grading |uv|: no abrupt change for the map to absorb), and the scale normalized
/// so that sum_v A_v s_v^2 = area: about as many quads as with h everywhere (h is then the
/// uniform spacing of the same count, not the mean spacing, which is larger). A surface with no
/// curvature at the scale of h, or `ratio` 1, gives 1 everywhere.
template <class Indices, class VertexPointMap>
Quad_sizing curvature_adapted_frequency_scale(const Indices& idx, const VertexPointMap& vpm, double h, double ratio,
                                              double grading = 0.25)
{
  const std::size_t nv = idx.number_of_vertices();
  Quad_sizing out;
  out.scale.assign(nv, 1.);
  if(!(ratio > 1.))
    return out;
  const std::vector<double> kappa = largest_curvature_magnitudes(idx, vpm, h);
  const std::vector<double> area = vertex_areas(idx, face_areas(idx, vpm));
  const double total_area = std::accumulate(area.begin(), area.end(), 0.);
  std::vector<std::size_t> order(nv);
  std::iota(order.begin(), order.end(), std::size_t(0));
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return kappa[a] < kappa[b]; });
  double cumulated = 0., top = 0.;
  for(std::size_t v : order)
  {
    cumulated += area[v];
    top = kappa[v];
    if(cumulated >= 0.98 * total_area)
      break;
  }
  // no curvature at the scale of h (a sagitta below 1e-7 h: a plane, tilted or not, whose
  // dihedral angles are rounding noise): uniform spacing
  if(!(top * h > 1e-6))
    return out;
  // relative density g = sqrt(kappa / top), in [1 / ratio, 1]
  std::vector<double> s(nv);
  for(std::size_t v = 0; v < nv; ++v)
    s[v] = (std::max)(std::sqrt((std::min)(kappa[v], top) / top), 1. / ratio);
  // returns the factor by which the spacing grew
  auto normalize = [&]() {
    double sum = 0.;
    for(std::size_t v = 0; v < nv; ++v)
      sum += area[v] * s[v] * s[v];
    const double c = std::sqrt(total_area / sum);
    for(double& x : s)
      x *= c;
    return 1. / c;
  };
  const std::vector<Eigen::Vector3d> p = vertex_positions(idx, vpm);
  // the grading, in spacings: Dijkstra's sweep from the finest vertices
  auto grade = [&]() {
    std::vector<double> spacing(nv);
    for(std::size_t v = 0; v < nv; ++v)
      spacing[v] = h / s[v];
    using Entry = std::pair<double, std::size_t>;
    std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> queue;
    for(std::size_t v = 0; v < nv; ++v)
      queue.emplace(spacing[v], v);
    const auto& tm = idx.mesh();
    while(!queue.empty())
    {
      const auto [value, v] = queue.top();
      queue.pop();
      if(value > spacing[v])
        continue;
      for(auto hd : halfedges_around_source(idx.vertex(v), tm))
      {
        const std::size_t u = idx.target_index(hd);
        const double bound = spacing[v] + grading * (p[u] - p[v]).norm();
        if(bound < spacing[u])
        {
          spacing[u] = bound;
          queue.emplace(bound, u);
        }
      }
    }
    for(std::size_t v = 0; v < nv; ++v)
      s[v] = h / spacing[v];
  };
  // the normalization after the grading coarsens everything a little, and the grading may then
  // bind again: alternate until the normalization changes the spacing by less than 0.1% (the
  // slope of the spacing is then at most 1.001 times `grading`); after 20 rounds, the last
  // normalization stands (the count of quads is the promise, the slope a little steeper)
  for(int round = 0;; ++round)
  {
    const double grown = normalize();
    if((round > 0 && grown < 1.001) || round == 20)
      break;
    grade();
  }
  out.scale = s;
  const auto [lo, hi] = std::minmax_element(s.begin(), s.end());
  out.smallest = 1. / *hi;
  out.largest = 1. / *lo;
  return out;
}

} // namespace internal
} // namespace Surface_design
} // namespace CGAL

#endif // CGAL_SURFACE_DESIGN_INTERNAL_FIELD_ALIGNED_PARAMETERIZATION_QUAD_SIZING_H
