// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Helpers of the barycentric-embedding examples: a picture of a polygon mesh coloured by a vertex
// scalar (faces fanned into triangles for VTK), surface area, strict number parsing.

#ifndef CGAL_SURFACE_DESIGN_EXAMPLES_EMBEDDING_SUPPORT_H
#define CGAL_SURFACE_DESIGN_EXAMPLES_EMBEDDING_SUPPORT_H

#include "program_support.h"

#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>

#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

namespace program {

/// Writes `png` + ".vtk" (faces fanned into triangles, vertex normals, the scalar `values`) and
/// renders it to `png` with f3d, coloured over [lo, hi], both through `outputs` (renamed when the
/// whole run succeeded). \throws std::runtime_error if f3d cannot render
inline void picture(const Mesh& mesh, const std::vector<double>& values, const std::string& name, double lo, double hi,
                    const std::string& png, Output_files& outputs, const std::string& up = "+Z")
{
  Vtk_surface s;
  s.scalar_name = name;
  s.scalars = values;
  for(auto v : vertices(mesh))
  {
    const Point& p = mesh.point(v);
    s.points.push_back({p.x(), p.y(), p.z()});
    const Vector n = CGAL::Polygon_mesh_processing::compute_vertex_normal(v, mesh);
    s.normals.push_back({n.x(), n.y(), n.z()});
  }
  for(auto f : faces(mesh))
  {
    std::vector<std::size_t> cycle;
    for(auto v : vertices_around_face(halfedge(f, mesh), mesh))
      cycle.push_back(std::size_t(v));
    for(std::size_t k = 1; k + 1 < cycle.size(); ++k)
      s.triangles.push_back({cycle[0], cycle[k], cycle[k + 1]});
  }
  const std::string vtk = outputs.stage(png + ".vtk");
  s.write(vtk);
  render_png(vtk, outputs.stage(png), name, lo, hi, up);
}

/// Sum of the face areas (faces fanned into triangles).
inline double surface_area(const Mesh& mesh)
{
  double area = 0.;
  for(auto f : faces(mesh))
  {
    std::vector<Point> p;
    for(auto v : vertices_around_face(halfedge(f, mesh), mesh))
      p.push_back(mesh.point(v));
    for(std::size_t k = 1; k + 1 < p.size(); ++k)
      area += std::sqrt(CGAL::squared_area(p[0], p[k], p[k + 1]));
  }
  return area;
}

/// Writes a polygon mesh (format by extension) through `outputs`.
inline void write_mesh(const std::string& path, const Mesh& mesh, Output_files& outputs)
{
  if(!CGAL::IO::write_polygon_mesh(outputs.stage(path), mesh, CGAL::parameters::stream_precision(17)))
    throw std::runtime_error("cannot write " + path);
}

/// Parses the whole of `text` as an integer >= 1.
inline std::size_t parse_count(const std::string& text, const std::string& option, long largest = 1000000000L)
{
  return std::size_t(parse_integer(text, option, 1, largest));
}

} // namespace program

#endif // CGAL_SURFACE_DESIGN_EXAMPLES_EMBEDDING_SUPPORT_H
