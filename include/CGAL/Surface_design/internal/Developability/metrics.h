// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The figures by which piecewise-developable designs are compared (Stein et al. 2018; Binninger
// et al. 2021): developability per vertex, hinge share, curvature concentration on seams, seams,
// mesh quality, distance to the input.

#ifndef CGAL_SURFACE_DESIGN_INTERNAL_DEVELOPABILITY_METRICS_H
#define CGAL_SURFACE_DESIGN_INTERNAL_DEVELOPABILITY_METRICS_H

#include <CGAL/Surface_design/internal/Core/angles.h>
#include <CGAL/Surface_design/internal/Core/geometry.h>
#include <CGAL/Surface_design/internal/Core/Mesh_indices.h>
#include <CGAL/Surface_design/internal/Developability/star_energies.h>
#include <CGAL/Surface_design/internal/Developability/vertex_stars.h>

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/Polygon_mesh_processing/distance.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <numeric>
#include <vector>

namespace CGAL {
namespace Surface_design {
namespace internal {

/// Per vertex: the covariance measure lambda_i (eq. 3) of every star with a face, and whether
/// the vertex is *measured*: interior, of valence >= 4 (the vertices the energy acts on).
struct Developability_per_vertex
{
  std::vector<double> lambda;
  std::vector<bool> measured, interior;
  std::vector<std::size_t> valence;
};

template <class Indices, class VertexPointMap>
Developability_per_vertex developability_per_vertex(const Indices& idx, const VertexPointMap& vpm, bool parallel)
{
  const Vertex_stars stars = vertex_stars(idx, false, 4);
  std::vector<Eigen::Vector3d> x(idx.number_of_vertices());
  for(std::size_t v = 0; v < x.size(); ++v)
    x[v] = position(vpm, idx.vertex(v));
  Developability_per_vertex d;
  d.lambda.assign(x.size(), 0.);
  for_each_index(x.size(), parallel, [&](std::size_t v) {
    if(stars.number_of_faces(v) == 0)
      return;
    const Star_buffer<Eigen::Vector3d> ring = ring_positions(stars, x, v);
    d.lambda[v] = star_energy(Developability_energy::covariance, x[v], ring.data(), ring.size(), stars.closed[v], nullptr);
  });
  d.measured = stars.active;
  d.interior = stars.closed;
  d.valence.resize(x.size());
  for(std::size_t v = 0; v < x.size(); ++v)
    d.valence[v] = stars.degree(v);
  return d;
}

/// Symmetric (approximate) Hausdorff distance and mean distance between two triangle meshes, each
/// read through its own vertex point map: points sampled on each (CGAL's grid sampling, about
/// `samples` points per mesh) and their distances to the other through an AABB tree.
template <class Mesh, class VertexPointMapA, class VertexPointMapB>
std::pair<double, double> surface_distances(const Mesh& a, const VertexPointMapA& vpm_a, const Mesh& b,
                                            const VertexPointMapB& vpm_b, std::size_t samples)
{
  namespace PMP = CGAL::Polygon_mesh_processing;
  using Point = typename boost::property_traits<VertexPointMapA>::value_type;
  using Kernel = typename CGAL::Kernel_traits<Point>::Kernel;
  double largest = 0., sum = 0.;
  std::size_t count = 0;
  auto one_way = [&](const Mesh& from, const auto& vpm_from, const Mesh& to, const auto& vpm_to) {
    using Primitive = CGAL::AABB_face_graph_triangle_primitive<Mesh, std::decay_t<decltype(vpm_to)>>;
    using Tree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive>>;
    Tree tree(faces(to).first, faces(to).second, to, vpm_to);
    tree.accelerate_distance_queries();
    const double area = CGAL::to_double(PMP::area(from, CGAL::parameters::vertex_point_map(vpm_from)));
    std::vector<Point> points;
    PMP::sample_triangle_mesh(from, std::back_inserter(points),
                              CGAL::parameters::vertex_point_map(vpm_from)
                                .use_grid_sampling(true)
                                .grid_spacing(std::sqrt(area / double((std::max)(samples, std::size_t(1))))));
    for(const Point& p : points)
    {
      const double d = std::sqrt(CGAL::to_double(tree.squared_distance(p)));
      largest = (std::max)(largest, d);
      sum += d;
      ++count;
    }
  };
  one_way(a, vpm_a, b, vpm_b);
  one_way(b, vpm_b, a, vpm_a);
  return {largest, count > 0 ? sum / double(count) : 0.};
}

} // namespace internal
} // namespace Surface_design
} // namespace CGAL

#endif // CGAL_SURFACE_DESIGN_INTERNAL_DEVELOPABILITY_METRICS_H
