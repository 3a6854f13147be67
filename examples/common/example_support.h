// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Helpers shared by the example programs: reading a mesh in input order, writing PLY with extra
// properties, writing a legacy VTK file, rendering it to PNG with f3d, timing.

#ifndef CGAL_SURFACE_DESIGN_EXAMPLE_SUPPORT_H
#define CGAL_SURFACE_DESIGN_EXAMPLE_SUPPORT_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_design/solver_traits.h>

#include <sys/stat.h>
#include <unistd.h>

#include <array>
#include <cmath>
#include <limits>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace example {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Vector = Kernel::Vector_3;
using Mesh = CGAL::Surface_mesh<Point>;

/// A command-line error: the program prints the message and exits with status 1, writing nothing.
struct Usage_error : std::invalid_argument
{
  using std::invalid_argument::invalid_argument;
};


/// Reads OFF, OBJ, PLY, STL... into a Surface_mesh whose vertices and faces keep the file's order
/// (vertex i and face i of the file are Mesh::Vertex_index(i) and Mesh::Face_index(i)).
/// Refuses, with a clear message, inputs that are not already a valid polygon mesh rather than
/// repairing them silently (repairs would renumber the faces).
inline Mesh read_mesh(const std::string& path)
{
  std::vector<Point> points;
  std::vector<std::vector<std::size_t>> polygons;
  if(!CGAL::IO::read_polygon_soup(path, points, polygons))
    throw std::runtime_error("cannot read " + path + " (unknown format or unreadable file)");
  if(!CGAL::Polygon_mesh_processing::is_polygon_soup_a_polygon_mesh(polygons))
    throw std::runtime_error(path + " is not a manifold, consistently oriented polygon mesh; "
                                    "repair it first (e.g. CGAL::Polygon_mesh_processing::repair_polygon_soup "
                                    "and orient_polygon_soup)");
  Mesh mesh;
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, polygons, mesh);
  if(num_vertices(mesh) != points.size())
    throw std::runtime_error(path + " has vertices used by no face; remove them first");
  return mesh;
}

/// Milliseconds since construction or the last lap.
class Stopwatch
{
public:
  double lap()
  {
    const auto now = std::chrono::steady_clock::now();
    const double ms = std::chrono::duration<double, std::milli>(now - m_start).count();
    m_start = now;
    return ms;
  }

private:
  std::chrono::steady_clock::time_point m_start = std::chrono::steady_clock::now();
};

/// Calls `f(traits)` with a default-constructed solver traits object of the solver named `name`
/// ("ldlt", or "cholmod" when the library was built with CHOLMOD) and returns what it returns.
template <class F>
decltype(auto) with_solver(const std::string& name, F&& f)
{
  if(name == "ldlt")
    return f(CGAL::Surface_design::Default_solver_traits());
#if defined(CGAL_SURFACE_DESIGN_HAS_CHOLMOD)
  if(name == "cholmod")
    return f(CGAL::Surface_design::Cholmod_solver_traits());
#endif
  throw Usage_error("unknown or unavailable solver \"" + name + "\" (ldlt, or cholmod when built with CHOLMOD)");
}

/// The value of option argv[i] (argv[i + 1]), advancing i; throws if it is missing.
inline std::string option_value(int argc, char** argv, int& i)
{
  if(i + 1 >= argc)
    throw Usage_error(std::string(argv[i]) + " needs a value");
  return argv[++i];
}

/// Parses the whole of `text` as a finite number in [lo, hi], or throws naming the option.
inline double parse_double(const std::string& text, const std::string& option,
                           double lo = -std::numeric_limits<double>::max(),
                           double hi = std::numeric_limits<double>::max())
{
  std::size_t used = 0;
  double value = 0.;
  try
  {
    value = std::stod(text, &used);
  }
  catch(const std::exception&)
  {
    used = 0;
  }
  if(used == 0 || used != text.size() || !std::isfinite(value))
    throw Usage_error(option + " expects a finite number, not \"" + text + "\"");
  if(value < lo || value > hi)
  {
    std::ostringstream s;
    s << option << " must lie in [" << lo << ", " << hi << "], not " << text;
    throw Usage_error(s.str());
  }
  return value;
}

/// Parses the whole of `text` as a number > 0 (finite).
inline double parse_positive(const std::string& text, const std::string& option)
{
  const double value = parse_double(text, option);
  if(!(value > 0.))
    throw Usage_error(option + " must be positive, not " + text);
  return value;
}

/// Parses the whole of `text` as an integer in [lo, hi], or throws naming the option.
inline long parse_integer(const std::string& text, const std::string& option, long lo, long hi)
{
  std::size_t used = 0;
  long value = 0;
  try
  {
    value = std::stol(text, &used);
  }
  catch(const std::exception&)
  {
    used = 0;
  }
  if(used == 0 || used != text.size())
    throw Usage_error(option + " expects an integer, not \"" + text + "\"");
  if(value < lo || value > hi)
    throw Usage_error(option + " must lie in [" + std::to_string(lo) + ", " + std::to_string(hi) + "], not " + text);
  return value;
}

/// Parses "A:B" into two integers; throws naming `what` otherwise.
inline std::pair<long, long> parse_pair(const std::string& s, const char* what)
{
  const auto colon = s.find(':');
  if(colon == std::string::npos)
    throw Usage_error(std::string("expected ") + what + ", got '" + s + "'");
  const long lim = std::numeric_limits<int>::max();
  return {parse_integer(s.substr(0, colon), what, -lim, lim), parse_integer(s.substr(colon + 1), what, -lim, lim)};
}

/// Parses one of `words`, or throws listing them.
inline std::string parse_choice(const std::string& text, const std::string& option,
                                const std::vector<std::string>& words)
{
  for(const std::string& w : words)
    if(w == text)
      return text;
  std::string list;
  for(const std::string& w : words)
    list += (list.empty() ? "" : ", ") + w;
  throw Usage_error(option + " is one of " + list + ", not \"" + text + "\"");
}

/// Throws unless `path` can be created: its folder exists (so that a run never computes for
/// minutes and then fails to write, and never leaves a partial set of outputs).
inline void check_output_path(const std::string& path, const std::string& option,
                              const std::vector<std::string>& extensions = {})
{
  if(path.empty())
    throw Usage_error(option + " needs a file name");
  const auto slash = path.rfind('/');
  const std::string folder = slash == std::string::npos ? "." : (slash == 0 ? "/" : path.substr(0, slash));
  struct stat info;
  if(stat(folder.c_str(), &info) != 0 || !S_ISDIR(info.st_mode) || access(folder.c_str(), W_OK) != 0)
    throw Usage_error(option + ": the folder \"" + folder + "\" of " + path + " does not exist or is not writable");
  if(!extensions.empty())
  {
    const auto dot = path.rfind('.');
    const std::string ext = dot == std::string::npos ? "" : path.substr(dot);
    bool known = false;
    for(const std::string& e : extensions)
      known = known || e == ext;
    if(!known)
    {
      std::string list;
      for(const std::string& e : extensions)
        list += (list.empty() ? "" : ", ") + e;
      throw Usage_error(option + " expects a file ending in " + list + ", not " + path);
    }
  }
}

/// A named per-element column of a PLY element.
struct Ply_property
{
  std::string name;
  std::string type; // "double" (float64) or "int"
  std::vector<double> values;
};

/// Writes an ASCII PLY: vertices (x y z + extra properties), faces (vertex_indices + extras) and,
/// if `edges` is not empty, an `edge` element with vertex1, vertex2 and extras.
inline void write_ply(const std::string& path, const Mesh& mesh, const std::vector<Ply_property>& vertex_props,
                      const std::vector<Ply_property>& face_props,
                      const std::vector<std::array<std::size_t, 2>>& edges = {},
                      const std::vector<Ply_property>& edge_props = {})
{
  std::ofstream out(path);
  if(!out)
    throw std::runtime_error("cannot write " + path);
  out << "ply\nformat ascii 1.0\ncomment written by CGAL Surface Design\n";
  out << "element vertex " << num_vertices(mesh) << "\nproperty double x\nproperty double y\nproperty double z\n";
  for(const auto& p : vertex_props)
    out << "property " << p.type << ' ' << p.name << '\n';
  out << "element face " << num_faces(mesh) << "\nproperty list uchar int vertex_indices\n";
  for(const auto& p : face_props)
    out << "property " << p.type << ' ' << p.name << '\n';
  if(!edges.empty())
  {
    out << "element edge " << edges.size() << "\nproperty int vertex1\nproperty int vertex2\n";
    for(const auto& p : edge_props)
      out << "property " << p.type << ' ' << p.name << '\n';
  }
  out << "end_header\n" << std::setprecision(17);
  auto value = [&out](const Ply_property& p, std::size_t i) {
    out << ' ';
    if(p.type == "int")
      out << static_cast<long>(p.values[i]);
    else
      out << p.values[i];
  };
  for(auto v : vertices(mesh))
  {
    const Point& p = mesh.point(v);
    out << p.x() << ' ' << p.y() << ' ' << p.z();
    for(const auto& prop : vertex_props)
      value(prop, std::size_t(v));
    out << '\n';
  }
  for(auto f : faces(mesh))
  {
    out << mesh.degree(f);
    for(auto v : vertices_around_face(halfedge(f, mesh), mesh))
      out << ' ' << std::size_t(v);
    for(const auto& prop : face_props)
      value(prop, std::size_t(f));
    out << '\n';
  }
  for(std::size_t e = 0; e < edges.size(); ++e)
  {
    out << edges[e][0] << ' ' << edges[e][1];
    for(const auto& prop : edge_props)
      value(prop, e);
    out << '\n';
  }
}

/// A triangle soup with per-point scalars and normals, written as legacy VTK (POLYDATA).
struct Vtk_surface
{
  std::vector<std::array<double, 3>> points, normals;
  std::vector<std::array<std::size_t, 3>> triangles;
  std::string scalar_name = "value";
  std::vector<double> scalars;

  void write(const std::string& path) const
  {
    std::ofstream out(path);
    if(!out)
      throw std::runtime_error("cannot write " + path);
    out << "# vtk DataFile Version 3.0\nCGAL Surface Design\nASCII\nDATASET POLYDATA\n";
    out << "POINTS " << points.size() << " float\n" << std::setprecision(7);
    for(const auto& p : points)
      out << p[0] << ' ' << p[1] << ' ' << p[2] << '\n';
    out << "POLYGONS " << triangles.size() << ' ' << 4 * triangles.size() << '\n';
    for(const auto& t : triangles)
      out << "3 " << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
    out << "POINT_DATA " << points.size() << '\n';
    if(!scalars.empty())
    {
      out << "SCALARS " << scalar_name << " float 1\nLOOKUP_TABLE default\n";
      for(double s : scalars)
        out << s << '\n';
    }
    if(!normals.empty())
    {
      out << "NORMALS normals float\n";
      for(const auto& n : normals)
        out << n[0] << ' ' << n[1] << ' ' << n[2] << '\n';
    }
  }
};

/// Renders a VTK file to PNG headlessly with f3d (Debian package `f3d`, run under `xvfb-run`
/// when there is no display; f3d 1.3 has no offscreen mode of its own). Colours by the point
/// scalar `scalar` in [lo, hi] with a two-colour map when `scalar` is not empty; `--dry-run`
/// ignores any user configuration of f3d. f3d's exit code does not tell whether it rendered, so
/// success is judged by the PNG file. Returns false, with a message, if f3d is unavailable or fails.
inline bool render_png(const std::string& vtk, const std::string& png, const std::string& scalar = "",
                       double lo = -1., double hi = 1., const std::string& up = "+Y",
                       const std::string& colormap =
                         "0,0.1,0.18,0.42,0.4,0.1,0.18,0.42,0.6,0.96,0.9,0.78,1,0.96,0.9,0.78")
{
  const bool has_display = std::getenv("DISPLAY") != nullptr;
  if(std::system("command -v f3d >/dev/null 2>&1") != 0 ||
     (!has_display && std::system("command -v xvfb-run >/dev/null 2>&1") != 0))
  {
    std::cerr << "note: the picture needs f3d and xvfb (Debian: apt-get install f3d xvfb xauth); "
              << "the surface is in " << vtk << "\n";
    return false;
  }
  std::ostringstream cmd;
  cmd << (has_display ? "" : "xvfb-run -a ") << "f3d '" << vtk << "' --output='" << png
      << "' --dry-run --quiet --resolution=1200,900 --bg-color=1,1,1 --camera-view-angle=20"
      << " --roughness=0.8 --up=" << up << " -a";
  if(!scalar.empty())
    cmd << " --scalars=" << scalar << " --range=" << lo << ',' << hi
        << " --colormap=" << colormap;
  cmd << " >/dev/null 2>&1";
  std::remove(png.c_str());
  // xvfb-run can lose a race for a display number: try once more before giving up
  for(int attempt = 0; attempt < 2 && !std::ifstream(png).good(); ++attempt)
    (void)std::system(cmd.str().c_str());
  if(!std::ifstream(png).good())
  {
    std::cerr << "warning: f3d could not render " << png << " (command: " << cmd.str() << ")\n";
    return false;
  }
  return true;
}

} // namespace example

#endif // CGAL_SURFACE_DESIGN_EXAMPLE_SUPPORT_H
