// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// stripes: field-aligned stripe patterns with prescribed singularities on any triangle mesh.
// Run without arguments for the usage.

#include "common/option_parser.h"
#include "common/program_support.h"
#include "common/stripe_fields.h"

#include <CGAL/Surface_design/direction_fields.h>
#include <CGAL/Surface_design/field_aligned_parameterization.h>
#include <CGAL/Surface_design/Field_aligned_parameterizer.h>
#include <CGAL/Surface_design/Trivial_connection.h>

#include <CGAL/Polygon_mesh_processing/connected_components.h>

#include <cmath>
#include <iostream>
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace SD = CGAL::Surface_design;
using program::Mesh;
using program::Point;
using program::Vector;

namespace {

const char* usage =
  "usage: stripes INPUT [options]\n"
  "  Stripe pattern (circle-valued function alpha) whose gradient follows a vector field, with\n"
  "  singularities exactly at the given faces (faces numbered in the input file's order).\n"
  "options:\n"
  "  --field axis:X,Y,Z        constant direction projected on the surface (default axis:0,1,0)\n"
  "  --field heat:V[:DEGREES]  gradient of the geodesic distance from vertex V (heat method),\n"
  "                            rotated by DEGREES in the tangent plane: 0 rings, 90 spokes, else\n"
  "                            spirals (spokes and spirals need --singularity at a face next to V;\n"
  "                            the faces around V are printed)\n"
  "  --field smoothest         smoothest vector field (Knöppel et al. 2013)\n"
  "  --field trivial:FACE:INDEX,...   vector field with exactly these singularities (trivial\n"
  "                            connection, Crane et al. 2010; indices sum to the Euler characteristic\n"
  "                            on a closed surface)\n"
  "  --scale S                 stripes per unit length (default: 10 stripes across the bounding box)\n"
  "  --singularity FACE:INDEX  prescribe a singularity (repeatable); on a closed surface the\n"
  "                            indices must sum to 0 (boundary windings absorb the sum otherwise);\n"
  "                            not in a face with an edge on the boundary (prescribe the winding\n"
  "                            of that loop instead)\n"
  "  --winding LOOP:N          prescribe the winding of a loop (repeatable; others automatic)\n"
  "  --solver S                sparse solver: default (simplicial LDLT below 20k\n"
  "                            unknowns, supernodal Cholesky above), ldlt, supernodal, cholmod\n"
  "  --convention projected|angle_rescaled   how omega is computed from the field\n"
  "  --output OUT.ply          mesh with vertex alpha, face index, edge omega/dalpha\n"
  "  --picture OUT.png         picture of the stripes (cos alpha), rendered with f3d\n"
  "  --up +Y|+Z|...            up direction of the picture (default +Y)\n";

struct Options
{
  std::string input, field = "axis:0,1,0", output, picture, up = "+Y", solver = "default";
  std::optional<double> scale;
  std::vector<std::pair<std::size_t, int>> singularities;
  std::map<std::size_t, int> windings;
  SD::One_form_convention convention = SD::One_form_convention::projected;
};

using program::parse_pair;

Options parse(int argc, char** argv)
{
  Options o;
  program::Option_parser p;
  p.input(o.input)
    .value("--field", [&](const std::string& v) { o.field = v; })
    .value("--scale", [&](const std::string& v) { o.scale = program::parse_positive(v, "--scale"); })
    .repeated("--singularity",
              [&](const std::string& v) {
                const auto [f, k] = parse_pair(v, "--singularity FACE:INDEX");
                if(f < 0)
                  throw program::Usage_error("face numbers start at 0");
                if(k == 0)
                  throw program::Usage_error("--singularity " + std::to_string(f) + ":0 prescribes nothing");
                for(const auto& [g, l] : o.singularities)
                  if(g == std::size_t(f))
                    throw program::Usage_error("--singularity: face " + std::to_string(f) + " is given more than once");
                o.singularities.emplace_back(std::size_t(f), int(k));
              })
    .repeated("--winding",
              [&](const std::string& v) {
                const auto [l, n] = parse_pair(v, "--winding LOOP:N");
                if(l < 0)
                  throw program::Usage_error("loop numbers start at 0");
                if(o.windings.count(std::size_t(l)))
                  throw program::Usage_error("--winding: loop " + std::to_string(l) + " is given more than once");
                o.windings[std::size_t(l)] = int(n);
              })
    .solver(o.solver)
    .value("--convention",
           [&](const std::string& v) {
             o.convention = program::parse_choice(v, "--convention", {"projected", "angle_rescaled"}) == "projected"
                              ? SD::One_form_convention::projected
                              : SD::One_form_convention::angle_rescaled;
           })
    .output("--output", o.output, {".ply"})
    .picture(o.picture, o.up)
    .parse(argc, argv);
  program::check_paths_and_picture({{"INPUT", o.input}, {"--output", o.output}}, o.picture, p.given("--up"));
  return o;
}

// The items of a comma-separated list; an empty item (e.g. a trailing comma) is an error.
std::vector<std::string> split_list(const std::string& list, const std::string& what)
{
  std::vector<std::string> items;
  std::size_t start = 0;
  while(true)
  {
    const std::size_t comma = list.find(',', start);
    items.push_back(list.substr(start, comma == std::string::npos ? std::string::npos : comma - start));
    if(items.back().empty())
      throw program::Usage_error("expected " + what + " (no empty item), got '" + list + "'");
    if(comma == std::string::npos)
      return items;
    start = comma + 1;
  }
}

using program::eigen;
using program::vertex_normals;

// The vector field the stripes follow, one vector per vertex; `solver` for the fields that solve.
template <class Solver>
std::vector<Vector> make_field(const Mesh& mesh, const std::string& spec, const Solver& solver)
{
  if(spec.rfind("axis:", 0) == 0)
  {
    std::vector<double> xyz;
    for(const std::string& item : split_list(spec.substr(5), "--field axis:X,Y,Z"))
      xyz.push_back(program::parse_double(item, "--field axis:X,Y,Z"));
    if(xyz.size() != 3)
      throw program::Usage_error("expected --field axis:X,Y,Z, got " + spec);
    const double largest = (std::max)({std::abs(xyz[0]), std::abs(xyz[1]), std::abs(xyz[2])});
    if(largest == 0.)
      throw program::Usage_error("--field axis:0,0,0 has no direction");
    // only the direction matters: scaled to a largest coordinate of 1, so that no square overflows
    return std::vector<Vector>(num_vertices(mesh), Vector(xyz[0] / largest, xyz[1] / largest, xyz[2] / largest));
  }
  if(spec.rfind("heat:", 0) == 0)
  {
    const std::string rest = spec.substr(5);
    const auto colon = rest.find(':');
    const long v = program::parse_integer(rest.substr(0, colon), "--field heat:VERTEX[:DEGREES] (VERTEX)", 0,
                                          long(num_vertices(mesh)) - 1);
    const double degrees = colon == std::string::npos
                             ? 0.
                             : program::parse_double(rest.substr(colon + 1), "--field heat:VERTEX:DEGREES (DEGREES)",
                                                     -360., 360.);
    std::map<Mesh::Face_index, std::size_t> component;
    if(CGAL::Polygon_mesh_processing::connected_components(mesh, boost::make_assoc_property_map(component)) > 1)
      throw program::Usage_error("--field heat:V covers only the connected component of vertex V, and this mesh has "
                                 "several: use --field axis, smoothest or trivial");
    const Mesh::Vertex_index source_vertex(static_cast<std::uint32_t>(v));
    // the faces where a singularity centres the rings, spokes or spiral
    // (a face with an edge on the boundary cannot hold one)
    std::cout << "faces around vertex " << v << ":";
    std::string on_boundary;
    for(auto f : faces_around_target(halfedge(source_vertex, mesh), mesh))
      if(f != Mesh::null_face())
      {
        bool boundary_edge = false;
        for(auto h : halfedges_around_face(halfedge(f, mesh), mesh))
          boundary_edge = boundary_edge || is_border(opposite(h, mesh), mesh);
        if(boundary_edge)
          on_boundary += ' ' + std::to_string(std::size_t(f));
        else
          std::cout << ' ' << std::size_t(f);
      }
    if(!on_boundary.empty())
      std::cout << " (with an edge on the boundary, cannot hold a singularity:" << on_boundary << ")";
    std::cout << '\n';
    return program::heat_field(mesh, source_vertex, degrees);
  }
  std::vector<Vector> field(num_vertices(mesh));
  if(spec == "smoothest")
  {
    const auto info = SD::smoothest_direction_field(mesh, CGAL::make_property_map(field),
                                                    SD::parameters::sparse_linear_solver(solver));
    std::cout << "smoothest vector field: eigenvalue " << info.eigenvalues.front() << ", " << info.iterations
              << " Lanczos steps\n";
    return field;
  }
  if(spec.rfind("trivial:", 0) == 0)
  {
    // trivial:FACE:INDEX,FACE:INDEX,...
    SD::Trivial_connection tc(mesh, SD::parameters::sparse_linear_solver(solver));
    std::map<std::size_t, int> indices;
    for(const std::string& item : split_list(spec.substr(8), "--field trivial:FACE:INDEX,FACE:INDEX,..."))
    {
      const auto [f, k] = parse_pair(item, "--field trivial:FACE:INDEX,FACE:INDEX,...");
      if(f < 0)
        throw program::Usage_error("face numbers start at 0");
      if(k == 0)
        throw program::Usage_error("--field trivial: index 0 at face " + std::to_string(f) + " prescribes nothing");
      if(!indices.emplace(std::size_t(f), int(k)).second)
        throw program::Usage_error("--field trivial: face " + std::to_string(f) + " is given more than once");
    }
    for(const auto& [f, k] : indices)
      tc.set_index(f, k);
    tc.solve();
    tc.field(CGAL::make_property_map(field));
    std::cout << "trivial-connection vector field: largest adjustment " << tc.largest_adjustment() << " rad\n";
    return field;
  }
  throw program::Usage_error("unknown field " + spec + " (axis:X,Y,Z, heat:V[:DEGREES], smoothest or trivial:...)");
}

template <class Solver>
int run(const Options& o, const Solver& solver)
{
  program::Stopwatch clock, total;
  Mesh mesh = program::read_mesh(o.input);
  std::cout << "read " << o.input << ": " << num_vertices(mesh) << " vertices, " << num_faces(mesh)
            << " faces (" << clock.lap() << " ms)\n";

  // the field's system (smoothest or trivial connection) has the pattern of the stripes' one: with
  // the default solver, one ordering and analysis serves both on large meshes
  Solver stripe_solver = solver;
  const Solver field_solver = program::solver_sharing_analysis(stripe_solver);
  SD::Field_aligned_parameterizer fap(mesh, SD::parameters::sparse_linear_solver(stripe_solver));
  std::cout << "validate, topology, weights, factorization: " << clock.lap() << " ms\n";
  std::cout << "  " << fap.number_of_connected_components() << " component(s), genus";
  for(std::size_t c = 0; c < fap.number_of_connected_components(); ++c)
    std::cout << ' ' << fap.genus(c);
  std::cout << ", " << fap.number_of_generator_loops() << " generator loop(s), "
            << fap.number_of_boundary_loops() << " boundary loop(s)\n";

  const std::vector<Vector> field = make_field(mesh, o.field, field_solver);
  CGAL::Bbox_3 box;
  for(const Point& p : mesh.points())
    box += p.bbox();
  const double diagonal = std::sqrt(CGAL::square(box.xmax() - box.xmin()) + CGAL::square(box.ymax() - box.ymin()) +
                                    CGAL::square(box.zmax() - box.zmin()));
  double mean_edge = 0.;
  for(auto e : edges(mesh))
    mean_edge += std::sqrt(CGAL::squared_distance(mesh.point(source(halfedge(e, mesh), mesh)),
                                                  mesh.point(target(halfedge(e, mesh), mesh)))) / double(num_edges(mesh));
  // The stripes must be resolved: alpha advances by 2 pi s l along an edge of length l, which
  // must stay well below pi. The default is 10 stripes across the bounding box, or fewer, so
  // that an average edge carries at most 1/10 of a stripe.
  const double resolved = 0.5 / mean_edge; // one stripe per two average edges: the Nyquist limit
  const double scale = o.scale ? *o.scale : (std::min)(10. / diagonal, 0.1 / mean_edge);
  if(scale >= resolved)
    throw program::Usage_error("--scale " + program::text(scale) + ": the mesh cannot resolve that many stripes (its "
                               "average edge would carry " + program::text(scale * mean_edge) +
                               " stripes; the limit is 0.5; keep below " + program::text(0.15 / mean_edge) +
                               " for clean stripes)");
  if(scale * diagonal < 1e-6)
    throw program::Usage_error("--scale " + program::text(scale) + " gives no visible stripe on a mesh of diagonal " +
                               program::text(diagonal));
  fap.set_field(CGAL::make_property_map(field), scale, o.convention);
  std::cout << "field " << o.field << ", " << scale << " stripes per unit length: " << clock.lap() << " ms\n";

  for(const auto& [f, k] : o.singularities)
    fap.set_index(f, k);
  for(const auto& [l, n] : o.windings)
  {
    fap.set_loop_winding(l, n); // checks that the loop exists
    const std::size_t length = fap.loop(l).size();
    if(2 * std::size_t(std::abs(n)) >= length)
      throw program::Usage_error("--winding " + std::to_string(l) + ":" + std::to_string(n) + ": loop " + std::to_string(l) +
                                 " has " + std::to_string(length) + " edges, which can carry at most " +
                                 std::to_string((length - 1) / 2) + " turns of alpha (less than pi per edge)");
  }
  fap.solve();
  std::cout << "solve: " << clock.lap() << " ms (energy " << fap.energy() << ")\n";
  for(std::size_t l = 0; l < fap.number_of_loops(); ++l)
    std::cout << "  loop " << l << (fap.is_boundary_loop(l) ? " (boundary)" : " (generator)") << ": "
              << fap.loop(l).size() << " edges, winding " << fap.loop_winding(l)
              << (o.windings.count(l) ? " (prescribed)" : " (automatic)") << '\n';
  if(o.field.rfind("heat:", 0) == 0 && o.field.find(':', 5) != std::string::npos && o.singularities.empty())
    std::cout << "note: spokes and spirals turn around vertex V: without a --singularity in a face next to V "
                 "the stripes bend around it instead\n";

  // detected singularities of alpha
  auto alpha = mesh.add_property_map<Mesh::Vertex_index, double>("v:alpha", 0.).first;
  auto detected = mesh.add_property_map<Mesh::Face_index, int>("f:index", 0).first;
  fap.alpha(alpha);
  const std::size_t found = SD::stripe_singularities(mesh, alpha, detected);
  std::cout << "singularities of alpha (" << found << "):";
  for(auto f : faces(mesh))
    if(detected[f] != 0)
      std::cout << ' ' << std::size_t(f) << ':' << detected[f];
  std::cout << '\n';
  for(auto f : faces(mesh))
    if(detected[f] != fap.index(f))
    {
      std::cout << "  note: some faces next to a singularity carry |dalpha| >= pi on an edge, so the\n"
                   "  wrapped alpha shows their winding differently (refine the mesh or lower --scale)\n";
      break;
    }

  program::Output_files outputs;
  if(!o.output.empty())
  {
    std::vector<std::array<std::size_t, 2>> edge_vertices;
    program::Ply_property omega{"omega", "double", {}}, dalpha{"dalpha", "double", {}};
    for(auto e : edges(mesh))
    {
      const auto h = halfedge(e, mesh); // omega and dalpha along h: from vertex1 to vertex2
      edge_vertices.push_back({std::size_t(source(h, mesh)), std::size_t(target(h, mesh))});
      omega.values.push_back(fap.omega(h));
      dalpha.values.push_back(fap.dalpha(h));
    }
    program::Ply_property alpha_prop{"alpha", "double", {}}, index_prop{"index", "int", {}};
    for(auto v : vertices(mesh))
      alpha_prop.values.push_back(alpha[v]);
    for(auto f : faces(mesh))
      index_prop.values.push_back(detected[f]);
    program::write_ply(outputs.stage(o.output), mesh, {alpha_prop}, {index_prop}, edge_vertices, {omega, dalpha});
  }

  if(!o.picture.empty())
  {
    // Each triangle is split into n^2 sub-triangles carrying the unwrapped per-corner alpha, so
    // the rendered stripes cos(alpha) are crisp and seamless.
    auto corner = mesh.add_property_map<Mesh::Halfedge_index, double>("h:corner", 0.).first;
    fap.corner_coordinates(corner);
    const std::vector<Eigen::Vector3d> normal = vertex_normals(mesh);
    double largest = 0.;
    for(auto h : halfedges(mesh))
      largest = (std::max)(largest, std::abs(fap.dalpha(h)));
    const std::size_t budget = 3000000 / (std::max<std::size_t>)(num_faces(mesh), 1);
    std::size_t n = std::size_t(std::ceil(largest / 0.6));
    n = (std::max<std::size_t>)(1, (std::min)(n, (std::min<std::size_t>)(8, std::size_t(std::sqrt(double(budget))))));
    program::Vtk_surface vtk;
    vtk.scalar_name = "stripes";
    for(auto f : faces(mesh))
    {
      const auto h0 = halfedge(f, mesh);
      const Mesh::Halfedge_index hs[3] = {prev(h0, mesh), h0, next(h0, mesh)}; // corners at a, b, c
      Eigen::Vector3d p[3], nn[3];
      double u[3];
      for(int i = 0; i < 3; ++i)
      {
        const auto v = target(hs[i], mesh);
        p[i] = eigen(mesh.point(v));
        nn[i] = normal[std::size_t(v)];
        u[i] = corner[hs[i]];
      }
      const std::size_t base = vtk.points.size();
      auto id = [&](std::size_t i, std::size_t j) { return base + j * (n + 1) - j * (j - 1) / 2 + i; };
      for(std::size_t j = 0; j <= n; ++j)
        for(std::size_t i = 0; i + j <= n; ++i)
        {
          const double b = double(i) / double(n), c = double(j) / double(n), a = 1. - b - c;
          const Eigen::Vector3d q = a * p[0] + b * p[1] + c * p[2];
          const Eigen::Vector3d m = (a * nn[0] + b * nn[1] + c * nn[2]).normalized();
          vtk.points.push_back({q.x(), q.y(), q.z()});
          vtk.normals.push_back({m.x(), m.y(), m.z()});
          vtk.scalars.push_back(std::cos(a * u[0] + b * u[1] + c * u[2]));
        }
      for(std::size_t j = 0; j < n; ++j)
        for(std::size_t i = 0; i + j < n; ++i)
        {
          vtk.triangles.push_back({id(i, j), id(i + 1, j), id(i, j + 1)});
          if(i + j + 1 < n)
            vtk.triangles.push_back({id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
        }
    }
    const std::string vtk_path = outputs.stage(o.picture + ".vtk");
    vtk.write(vtk_path);
    program::render_png(vtk_path, outputs.stage(o.picture), "stripes", -1., 1., o.up);
  }
  outputs.commit();
  std::cout << "total " << total.lap() << " ms\n";
  return 0;
}

} // namespace

int main(int argc, char** argv)
{
  return program::run_main("stripes", usage, argc, [&] {
    const Options o = parse(argc, argv);
    return program::with_solver(o.solver, [&o](auto traits) { return run(o, traits); });
  });
}
