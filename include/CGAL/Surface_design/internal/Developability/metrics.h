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
#include <CGAL/Surface_design/internal/Core/validation.h>
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
  const std::vector<Eigen::Vector3d> x = vertex_positions(idx, vpm);
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

/// Fills `m` (a `Developability_metrics`: every field but `energy`) for the mesh `tm` read through
/// `vpm`, with the distances to `reference` when it is not null (read through its own point map),
/// relative to the reference's bounding-box diagonal.
/// \throws Invalid_mesh
template <class Metrics, class TriangleMesh, class VertexPointMap, class NamedParameters>
void measure_developability(Metrics& m, const TriangleMesh& tm, const VertexPointMap& vpm, const TriangleMesh* reference,
                            const NamedParameters& np, bool parallel)
{
  const Mesh_indices<TriangleMesh> idx(tm, np);
  validate_mesh(idx, vpm);
  m.vertices = idx.number_of_vertices();
  m.faces = idx.number_of_faces();
  const Developability_per_vertex d = developability_per_vertex(idx, vpm, parallel);
  std::vector<double> measured;
  for(std::size_t v = 0; v < d.lambda.size(); ++v)
    if(d.measured[v])
      measured.push_back(d.lambda[v]);
  m.measured_vertices = measured.size();
  if(!measured.empty())
  {
    const double tau4 = two_pi * 1e-4, tau3 = two_pi * 1e-3;
    m.lambda_max = *std::max_element(measured.begin(), measured.end());
    m.lambda_mean = std::accumulate(measured.begin(), measured.end(), 0.) / double(measured.size());
    std::vector<double> sorted = measured;
    std::sort(sorted.begin(), sorted.end());
    m.lambda_p95 = sorted[std::min(sorted.size() - 1, std::size_t(std::ceil(0.95 * double(sorted.size()))) - 1)];
    m.hinge_share_1e4 = double(std::count_if(measured.begin(), measured.end(), [&](double l) { return l < tau4; })) /
                        double(measured.size());
    m.hinge_share_1e3 = double(std::count_if(measured.begin(), measured.end(), [&](double l) { return l < tau3; })) /
                        double(measured.size());
  }
  // angle defects, seams
  const std::vector<double> corner = corner_angles(idx, vpm);
  const std::vector<double> angle_sum = vertex_angle_sums(idx, corner);
  std::vector<bool> seam(idx.number_of_vertices(), false);
  double defect_sum = 0., seam_defect = 0.;
  std::size_t interior = 0;
  for(std::size_t v = 0; v < seam.size(); ++v)
  {
    if(!d.interior[v])
      continue;
    const double omega = std::abs(two_pi - angle_sum[v]);
    ++interior;
    defect_sum += omega;
    m.angle_defect_max = (std::max)(m.angle_defect_max, omega);
    seam[v] = d.lambda[v] >= two_pi * 1e-4;
    if(seam[v])
    {
      ++m.seam_vertices;
      seam_defect += omega;
    }
  }
  m.angle_defect_mean = interior > 0 ? defect_sum / double(interior) : 0.;
  m.seam_curvature_share = defect_sum > 0. ? seam_defect / defect_sum : 1.;
  std::vector<std::size_t> parent(seam.size());
  std::iota(parent.begin(), parent.end(), std::size_t(0));
  auto find = [&parent](std::size_t x) {
    while(parent[x] != x)
      x = parent[x] = parent[parent[x]];
    return x;
  };
  std::vector<bool> on_seam_edge(seam.size(), false);
  for(std::size_t e = 0; e < idx.number_of_edges(); ++e)
  {
    const auto ij = idx.edge_vertices(e);
    if(!seam[ij.first] || !seam[ij.second])
      continue;
    m.seam_length += (position(vpm, idx.vertex(ij.first)) - position(vpm, idx.vertex(ij.second))).norm();
    on_seam_edge[ij.first] = on_seam_edge[ij.second] = true;
    parent[find(ij.first)] = find(ij.second);
  }
  for(std::size_t v = 0; v < seam.size(); ++v)
    m.seam_curves += on_seam_edge[v] && find(v) == v;
  m.minimum_angle = pi;
  for(std::size_t h = 0; h < corner.size(); ++h)
    if(!idx.is_border(idx.halfedge(h)))
      m.minimum_angle = (std::min)(m.minimum_angle, corner[h]);
  if(reference)
  {
    const auto ref_vpm = get(CGAL::vertex_point, *reference);
    CGAL::Bbox_3 box;
    for(auto v : vertices(*reference))
      box += get(ref_vpm, v).bbox();
    const double diagonal = std::sqrt(CGAL::square(box.xmax() - box.xmin()) + CGAL::square(box.ymax() - box.ymin()) +
                                      CGAL::square(box.zmax() - box.zmin()));
    const auto dist = surface_distances(tm, vpm, *reference, ref_vpm, 4 * (m.faces + num_faces(*reference)));
    m.hausdorff_distance = dist.first / diagonal;
    m.mean_distance = dist.second / diagonal;
  }
}

} // namespace internal
} // namespace Surface_design
} // namespace CGAL

#endif // CGAL_SURFACE_DESIGN_INTERNAL_DEVELOPABILITY_METRICS_H
