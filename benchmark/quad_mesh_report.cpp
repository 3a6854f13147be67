// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// quad_mesh_report REFERENCE POLYGONS: the quality of any polygon mesh against the triangle mesh
// it approximates (quad_mesh_quality()), as one JSON object on standard output. Used by
// quad_peer_comparison.py to measure a peer's output and ours with the same code. The polygons are
// read as a soup, repaired and oriented consistently first (gmsh orients its patches one by one);
// "reoriented_faces" tells how many faces had to be flipped.

// (Surface_mesh first: the library's index maps call CGAL::halfedge() by its qualified name)
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Surface_design/quad_mesh_quality.h>

#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/repair_polygon_soup.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <cstdio>
#include <exception>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;
namespace PMP = CGAL::Polygon_mesh_processing;

int run(const std::string& reference_file, const std::string& polygons_file)
{
  Mesh reference;
  if(!CGAL::IO::read_polygon_mesh(reference_file, reference) || num_faces(reference) == 0)
  {
    std::fprintf(stderr, "quad_mesh_report: cannot read the triangle mesh %s\n", reference_file.c_str());
    return 1;
  }
  std::vector<Point> points;
  std::vector<std::vector<std::size_t>> polygons;
  if(!CGAL::IO::read_polygon_soup(polygons_file, points, polygons) || polygons.empty())
  {
    std::fprintf(stderr, "quad_mesh_report: cannot read the polygons %s\n", polygons_file.c_str());
    return 1;
  }
  PMP::repair_polygon_soup(points, polygons);
  // a face is flipped when its first directed edge was not a directed edge before
  std::set<std::pair<std::size_t, std::size_t>> before;
  for(const auto& p : polygons)
    for(std::size_t k = 0; k < p.size(); ++k)
      before.insert({p[k], p[(k + 1) % p.size()]});
  const bool orientable = PMP::orient_polygon_soup(points, polygons);
  std::size_t flipped = 0;
  for(const auto& p : polygons)
    flipped += before.count({p[0], p[1]}) == 0;
  Mesh mesh;
  PMP::polygon_soup_to_polygon_mesh(points, polygons, mesh);
  const CGAL::Surface_design::Quad_mesh_quality q = CGAL::Surface_design::quad_mesh_quality(mesh, reference);
  std::printf("{\"faces\": %zu, \"triangles\": %zu, \"quads\": %zu, \"quad_fraction\": %.5f, "
              "\"quad_area_fraction\": %.5f, \"irregular_vertices\": %zu, \"t_junctions\": %zu, "
              "\"angle_deviation_mean\": %.3f, \"angle_deviation_rms\": %.3f, \"angle_deviation_max\": %.3f, "
              "\"relative_hausdorff_distance\": %.6f, \"valid\": %s, \"same_topology\": %s, "
              "\"orientable_without_duplication\": %s, \"reoriented_faces\": %zu}\n",
              q.faces, q.faces_by_sides[0], q.faces_by_sides[1], q.quad_fraction, q.quad_area_fraction,
              q.irregular_vertices, q.t_junctions, q.angle_deviation_mean, q.angle_deviation_rms,
              q.angle_deviation_max, q.relative_hausdorff_distance, q.valid ? "true" : "false",
              q.same_topology ? "true" : "false", orientable ? "true" : "false", flipped);
  return 0;
}

} // namespace

int main(int argc, char** argv)
{
  if(argc != 3)
  {
    std::fprintf(stderr, "usage: quad_mesh_report REFERENCE_TRIANGLES.(off|obj|ply) POLYGONS.(off|obj|ply)\n");
    return 1;
  }
  try
  {
    return run(argv[1], argv[2]);
  }
  catch(const std::exception& e)
  {
    std::fprintf(stderr, "quad_mesh_report: %s\n", e.what());
    return 1;
  }
}
