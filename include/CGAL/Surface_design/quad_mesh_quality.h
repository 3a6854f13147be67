// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Quality of a quad-dominant polygon mesh and its fidelity to a reference triangle mesh.

#ifndef CGAL_SURFACE_DESIGN_QUAD_MESH_QUALITY_H
#define CGAL_SURFACE_DESIGN_QUAD_MESH_QUALITY_H

#include <CGAL/Surface_design/exceptions.h>
#include <CGAL/Surface_design/internal/Core/geometry.h>
#include <CGAL/Surface_design/internal/Core/hausdorff_distance.h>
#include <CGAL/Surface_design/internal/Core/named_parameters.h>
#include <CGAL/Surface_design/parameters.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/Polygon_mesh_processing/border.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <map>
#include <vector>

namespace CGAL {
namespace Surface_design {

/// \ingroup PkgHarmonicQuadRemeshingRef
/// Measures of a quad-dominant mesh (see `quad_mesh_quality()`). Angles in degrees.
struct Quad_mesh_quality
{
  std::size_t vertices = 0, edges = 0, faces = 0;
  /// faces by number of sides: [0] triangles, [1] quads, [2] pentagons, [3] hexagons, [4] more
  std::array<std::size_t, 5> faces_by_sides{};
  double quad_fraction = 0.;      ///< quads / faces
  double quad_area_fraction = 0.; ///< area of the quads / total area (faces fanned from a corner)
  /// interior vertices of valence other than 4 and boundary vertices of valence other than 3
  std::size_t irregular_vertices = 0;
  /// vertices where a face has a corner wider than 160 degrees (a T-junction: the vertex lies on a
  /// straight side of that face)
  std::size_t t_junctions = 0;
  double angle_deviation_mean = 0., angle_deviation_rms = 0., angle_deviation_max = 0.; ///< |quad corner - 90|
  double edge_length_mean = 0., edge_length_min = 0., edge_length_max = 0.;
  double edge_length_variation = 0.; ///< standard deviation / mean
  /// edges whose two vertices (nearly) coincide, no longer than 10^-9 times the mean edge length:
  /// the faces on their sides are degenerate (a remesher's output should have none)
  std::size_t degenerate_edges = 0;
  /// two-sided Hausdorff distance to the reference (the faces fanned into triangles), an upper
  /// bound within `hausdorff_error_bound` of the exact value (certified: no more than that above a
  /// distance found between the surfaces); and relative to the diagonal of the reference's
  /// bounding box. Infinite when only one of the two has faces.
  double hausdorff_distance = 0., relative_hausdorff_distance = 0.;
  long euler_characteristic = 0;
  std::size_t boundary_loops = 0, connected_components = 0;
  bool valid = false;         ///< a valid polygon mesh (CGAL::is_valid_polygon_mesh)
  bool same_topology = false; ///< same Euler characteristic, boundary loops and components as the reference
};

namespace internal {

template <class Mesh>
void topology_counts(const Mesh& m, long& chi, std::size_t& loops, std::size_t& components)
{
  chi = long(num_vertices(m)) - long(num_edges(m)) + long(num_faces(m));
  std::vector<typename boost::graph_traits<Mesh>::halfedge_descriptor> border;
  CGAL::Polygon_mesh_processing::extract_boundary_cycles(m, std::back_inserter(border));
  loops = border.size();
  std::size_t k = 0;
  std::map<typename boost::graph_traits<Mesh>::face_descriptor, std::size_t> fid;
  for(auto f : faces(m))
    fid[f] = k++;
  components = CGAL::Polygon_mesh_processing::connected_components(
    m, boost::make_assoc_property_map(fid), CGAL::parameters::face_index_map(boost::make_assoc_property_map(fid)));
}

} // namespace internal

/// \ingroup PkgHarmonicQuadRemeshingRef
///
/// Measures a polygon mesh `pm` (typically the output of `harmonic_quad_remeshing()`) against
/// the triangle mesh `reference` it approximates.
///
/// \param np1 an optional sequence of named parameters of `pm` among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{a property map associating points to the vertices of `pm`}
///     \cgalParamType{a class model of `ReadablePropertyMap` with
///                    `boost::graph_traits<PolygonMesh>::%vertex_descriptor` as key type and `%Point_3` as
///                    value type}
///     \cgalParamDefault{`boost::get(CGAL::vertex_point, pm)`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \param np2 an optional sequence of named parameters of `reference` among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{a property map associating points to the vertices of `reference`}
///     \cgalParamType{a class model of `ReadablePropertyMap` with
///                    `boost::graph_traits<TriangleMesh>::%vertex_descriptor` as key type and `%Point_3` as
///                    value type}
///     \cgalParamDefault{`boost::get(CGAL::vertex_point, reference)`}
///   \cgalParamNEnd
///   \cgalParamNBegin{hausdorff_error_bound}
///     \cgalParamDescription{the accuracy of the Hausdorff distance, relative to the bounding-box diagonal of
///                           `reference`: the distance reported is an upper bound within this times that
///                           diagonal of the exact value}
///     \cgalParamType{`double`}
///     \cgalParamDefault{`1e-3`}
///     \cgalParamExtra{throws `Invalid_parameter` if it is not in (0, 1]}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// Complexity: linear in the size of `pm`, plus the certified Hausdorff distance: an AABB tree on
/// each mesh and a closest-point query per vertex, then per midpoint of the triangles refined until
/// the upper bound is within the error bound of the largest distance found.
/// \throws Invalid_parameter `hausdorff_error_bound` not in (0, 1]
template <class PolygonMesh, class TriangleMesh, class NamedParameters1 = CGAL::parameters::Default_named_parameters,
          class NamedParameters2 = CGAL::parameters::Default_named_parameters>
Quad_mesh_quality quad_mesh_quality(const PolygonMesh& pm, const TriangleMesh& reference,
                                    const NamedParameters1& np1 = CGAL::parameters::default_values(),
                                    const NamedParameters2& np2 = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  Quad_mesh_quality q;
  const auto vpm = CGAL::parameters::choose_parameter(get_parameter(np1, CGAL::internal_np::vertex_point),
                                                      get_const_property_map(CGAL::vertex_point, pm));
  const auto rvpm = CGAL::parameters::choose_parameter(get_parameter(np2, CGAL::internal_np::vertex_point),
                                                       get_const_property_map(CGAL::vertex_point, reference));
  const double bound = choose_parameter(get_parameter(np2, internal_np::hausdorff_error_bound), 1e-3);
  internal::require_in_range("hausdorff_error_bound", bound, 0., 1., true);

  q.vertices = num_vertices(pm);
  q.edges = num_edges(pm);
  q.faces = num_faces(pm);
  q.valid = CGAL::is_valid_polygon_mesh(pm);
  constexpr double deg = 180. / 3.14159265358979323846;
  double quad_area = 0., total_area = 0., dev_sum = 0., dev_sq = 0.;
  std::size_t quad_corners = 0;
  std::map<typename boost::graph_traits<PolygonMesh>::vertex_descriptor, char> is_t;
  for(auto f : faces(pm))
  {
    std::vector<Eigen::Vector3d> p;
    std::vector<typename boost::graph_traits<PolygonMesh>::vertex_descriptor> vs;
    for(auto v : vertices_around_face(halfedge(f, pm), pm))
    {
      p.push_back(internal::position(vpm, v));
      vs.push_back(v);
    }
    const std::size_t n = p.size();
    ++q.faces_by_sides[std::min<std::size_t>(n < 3 ? 0 : n - 3, 4)];
    double area = 0.;
    for(std::size_t k = 1; k + 1 < n; ++k)
      area += 0.5 * (p[k] - p[0]).cross(p[k + 1] - p[0]).norm();
    total_area += area;
    if(n == 4)
      quad_area += area;
    for(std::size_t k = 0; k < n; ++k)
    {
      const Eigen::Vector3d a = p[(k + n - 1) % n] - p[k], b = p[(k + 1) % n] - p[k];
      const double angle = std::atan2(a.cross(b).norm(), a.dot(b)) * deg;
      if(angle > 160.)
        is_t[vs[k]] = 1;
      if(n == 4)
      {
        const double d = std::abs(angle - 90.);
        dev_sum += d;
        dev_sq += d * d;
        q.angle_deviation_max = (std::max)(q.angle_deviation_max, d);
        ++quad_corners;
      }
    }
  }
  q.t_junctions = is_t.size();
  q.quad_fraction = q.faces > 0 ? double(q.faces_by_sides[1]) / double(q.faces) : 0.;
  q.quad_area_fraction = total_area > 0. ? quad_area / total_area : 0.;
  if(quad_corners > 0)
  {
    q.angle_deviation_mean = dev_sum / double(quad_corners);
    q.angle_deviation_rms = std::sqrt(dev_sq / double(quad_corners));
  }
  for(auto v : vertices(pm))
  {
    std::size_t valence = 0;
    bool border = false;
    for(auto h : halfedges_around_target(halfedge(v, pm), pm))
    {
      ++valence;
      border = border || is_border(h, pm) || is_border(opposite(h, pm), pm);
    }
    q.irregular_vertices += valence != (border ? 3u : 4u);
  }
  double sum = 0., sq = 0.;
  q.edge_length_min = std::numeric_limits<double>::infinity();
  for(auto e : edges(pm))
  {
    const double l = (internal::position(vpm, source(e, pm)) - internal::position(vpm, target(e, pm))).norm();
    sum += l;
    sq += l * l;
    q.edge_length_min = (std::min)(q.edge_length_min, l);
    q.edge_length_max = (std::max)(q.edge_length_max, l);
  }
  if(q.edges > 0)
  {
    q.edge_length_mean = sum / double(q.edges);
    q.edge_length_variation =
      std::sqrt((std::max)(0., sq / double(q.edges) - q.edge_length_mean * q.edge_length_mean)) / q.edge_length_mean;
    for(auto e : edges(pm))
      q.degenerate_edges += (internal::position(vpm, source(e, pm)) - internal::position(vpm, target(e, pm))).norm() <=
                            1e-9 * q.edge_length_mean;
  }
  else
    q.edge_length_min = 0.;

  if(q.valid && q.faces > 0)
  {
    internal::topology_counts(pm, q.euler_characteristic, q.boundary_loops, q.connected_components);
    long chi = 0;
    std::size_t loops = 0, comps = 0;
    internal::topology_counts(reference, chi, loops, comps);
    q.same_topology = chi == q.euler_characteristic && loops == q.boundary_loops && comps == q.connected_components;
    // Hausdorff distance between the surfaces, the faces fanned into triangles
    Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
    for(auto v : vertices(reference))
    {
      const Eigen::Vector3d p = internal::position(rvpm, v);
      lo = lo.cwiseMin(p);
      hi = hi.cwiseMax(p);
    }
    const double diagonal = (hi - lo).norm();
    const internal::Triangle_soup a = internal::fanned_triangle_soup(pm, vpm);
    const internal::Triangle_soup b = internal::fanned_triangle_soup(reference, rvpm);
    if(!a.triangles.empty() && !b.triangles.empty())
    {
      q.hausdorff_distance = internal::bounded_hausdorff_distance(a, b, bound * diagonal).upper;
      q.relative_hausdorff_distance =
        diagonal > 0. ? q.hausdorff_distance / diagonal : std::numeric_limits<double>::infinity();
    }
    else if(!b.triangles.empty() || !a.triangles.empty()) // one surface and nothing to be near
      q.hausdorff_distance = q.relative_hausdorff_distance = std::numeric_limits<double>::infinity();
  }
  return q;
}

/// \ingroup PkgHarmonicQuadRemeshingRef
/// Number of faces of `pm` with other than four sides whose centroid lies within `radius` of one
/// of `points` (a range of `Point_3`, e.g. the saddles of the harmonic function).
template <class PolygonMesh, class PointRange>
std::size_t count_non_quads_near(const PolygonMesh& pm, const PointRange& points, double radius)
{
  const auto vpm = get_const_property_map(CGAL::vertex_point, pm);
  std::size_t n = 0;
  for(auto f : faces(pm))
  {
    Eigen::Vector3d c = Eigen::Vector3d::Zero();
    std::size_t sides = 0;
    for(auto v : vertices_around_face(halfedge(f, pm), pm))
    {
      c += internal::position(vpm, v);
      ++sides;
    }
    if(sides == 4)
      continue;
    c /= double(sides);
    for(const auto& p : points)
      if((Eigen::Vector3d(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())) - c).norm() <= radius)
      {
        ++n;
        break;
      }
  }
  return n;
}

} // namespace Surface_design
} // namespace CGAL

#endif // CGAL_SURFACE_DESIGN_QUAD_MESH_QUALITY_H
