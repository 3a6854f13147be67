// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// stripes: field-aligned stripe patterns with prescribed singularities on any triangle mesh.
// Run without arguments for the usage.

#include "common/option_parser.h"
#include "common/program_support.h"
#include "common/stripe_fields.h"

#include <CGAL/Surface_design/Branched_stripe_parameterizer.h>
#include <CGAL/Surface_design/direction_fields.h>
#include <CGAL/Surface_design/field_aligned_parameterization.h>
#include <CGAL/Surface_design/Field_aligned_parameterizer.h>
#include <CGAL/Surface_design/Trivial_connection.h>

#include <CGAL/Polygon_mesh_processing/connected_components.h>

#include <algorithm>
#include <array>
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
  "  Stripe pattern (circle-valued function alpha) whose gradient follows a vector, line or cross\n"
  "  field, with singularities exactly at the given faces (faces numbered in the input file's\n"
  "  order). On line and cross fields the stripes branch at the field's singularities.\n"
  "options:\n"
  "  --field axis:X,Y,Z        constant direction projected on the surface (default axis:0,1,0)\n"
  "  --field heat:V[:DEGREES]  gradient of the geodesic distance from vertex V (heat method),\n"
  "                            rotated by DEGREES in the tangent plane: 0 rings, 90 spokes, else\n"
  "                            spirals (spokes and spirals need --singularity at a face next to V;\n"
  "                            the faces around V are printed)\n"
  "  --field smoothest[:N]     smoothest N-direction field (Knöppel et al. 2013): N = 1 vector\n"
  "                            field (the default), 2 line field, 4 cross field (two families of\n"
  "                            stripes, the second along the field turned by 90 degrees)\n"
  "  --field principal[:W]     line field along the principal curvature directions, smoothed\n"
  "                            (smoothest line field with curvature alignment weight W, default 0.1)\n"
  "  --field trivial:FACE:INDEX,...   vector field with exactly these singularities (trivial\n"
  "                            connection, Crane et al. 2010; indices sum to the Euler characteristic\n"
  "                            on a closed surface)\n"
  "  --field trivial2:FACE:K,... / trivial4:FACE:K,...   line / cross field with exactly these\n"
  "                            singularities, of index K/2 / K/4 (they sum to 2 / 4 times the Euler\n"
  "                            characteristic on a closed surface)\n"
  "  --scale S                 stripes per unit length (default: 10 stripes across the bounding box)\n"
  "  --singularity FACE:INDEX[:FAMILY]  prescribe a stripe singularity (repeatable); on a closed\n"
  "                            surface whose field has no singularity the indices must sum to 0\n"
  "                            (boundary windings absorb the sum otherwise); not in a face with an\n"
  "                            edge on the boundary, nor in a branch face of a line or cross field.\n"
  "                            On line and cross fields the sign refers to the face's field vector\n"
  "                            (field_x, y, z in the output), FAMILY 1 is a cross field's second\n"
  "                            family. Without --singularity, the stripe singularities of line and\n"
  "                            cross fields are placed automatically (where they lower the energy)\n"
  "  --no-automatic            no automatic singularities on line and cross fields\n"
  "  --lattice-cones           line and cross fields: every branch point on the lattice (all stripe\n"
  "                            angles 0 there): a line field's stripes run through its branch\n"
  "                            points, a cross field's cones become crossings of both families\n"
  "                            (valence 4 - k at a cone of index k/4), as a quad mesh needs\n"
  "  --winding LOOP:N          prescribe the winding of a loop (repeatable; others automatic;\n"
  "                            vector fields only)\n"
  "  --solver S                sparse solver: default (simplicial LDLT below 20k\n"
  "                            unknowns, supernodal Cholesky above), ldlt, supernodal, cholmod\n"
  "  --convention projected|angle_rescaled   how omega is computed from the field\n"
  "  --output OUT.ply          mesh with, per face: corner_alpha (the stripe angle at its corners,\n"
  "                            linear inside a regular face), stripe_index, field_x/y/z (the\n"
  "                            field's direction in the face), field_index (the field's index);\n"
  "                            cross fields: also corner_beta, stripe_index_beta (second family);\n"
  "                            vector fields: also vertex alpha, face index, edge omega/dalpha\n"
  "  --isolines OUT.obj        the isolines at 0 and pi (the centre lines of the dark and light\n"
  "                            stripes) as OBJ polylines, groups level_0 and level_pi\n"
  "  --picture OUT.png         picture of the stripes (cos alpha), rendered with f3d\n"
  "  --up +Y|+Z|...            up direction of the picture (default +Y)\n";

struct Options
{
  std::string input, field = "axis:0,1,0", output, isolines, picture, up = "+Y", solver = "default";
  std::optional<double> scale;
  std::vector<std::array<long, 3>> singularities; // face, index, family
  bool automatic = true, lattice = false;
  std::map<std::size_t, int> windings;
  SD::One_form_convention convention = SD::One_form_convention::projected;
};

using program::parse_pair;

// The symmetry order N of the field a --field spec gives (1, 2 or 4).
int field_order(const std::string& spec)
{
  if(spec == "smoothest:1" || spec == "smoothest:2" || spec == "smoothest:4")
    return spec.back() - '0';
  if(spec.rfind("smoothest:", 0) == 0)
    throw program::Usage_error("--field smoothest:N takes N = 1 (vector field), 2 (line field) or 4 (cross field), got " +
                               spec.substr(10));
  if(spec == "principal" || spec.rfind("principal:", 0) == 0)
    return 2;
  if(spec.rfind("trivial2:", 0) == 0)
    return 2;
  if(spec.rfind("trivial4:", 0) == 0)
    return 4;
  return 1;
}


Options parse(int argc, char** argv)
{
  Options o;
  program::Option_parser p;
  p.input(o.input)
    .value("--field", [&](const std::string& v) { o.field = v; })
    .value("--scale", [&](const std::string& v) { o.scale = program::parse_positive(v, "--scale"); })
    .repeated("--singularity",
              [&](const std::string& v) {
                // FACE:INDEX or FACE:INDEX:FAMILY
                const auto last = v.rfind(':');
                long family = 0;
                std::string pair = v;
                if(last != std::string::npos && v.find(':') != last)
                {
                  family = program::parse_integer(v.substr(last + 1), "--singularity FACE:INDEX:FAMILY (FAMILY)", 0, 1);
                  pair = v.substr(0, last);
                }
                const auto [f, k] = parse_pair(pair, "--singularity FACE:INDEX[:FAMILY]");
                if(f < 0)
                  throw program::Usage_error("face numbers start at 0");
                if(k == 0)
                  throw program::Usage_error("--singularity " + v + " prescribes nothing");
                for(const auto& g : o.singularities)
                  if(g[0] == f && g[2] == family)
                    throw program::Usage_error("--singularity: face " + std::to_string(f) + " is given more than once");
                o.singularities.push_back({long(f), long(k), family});
              })
    .flag("--no-automatic", [&] { o.automatic = false; })
    .flag("--lattice-cones", [&] { o.lattice = true; })
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
    .output("--isolines", o.isolines, {".obj"})
    .picture(o.picture, o.up)
    .parse(argc, argv);
  program::check_paths_and_picture({{"INPUT", o.input}, {"--output", o.output}, {"--isolines", o.isolines}}, o.picture,
                                   p.given("--up"));
  if(!o.automatic && !o.singularities.empty())
    throw program::Usage_error("--no-automatic with --singularity: prescribed singularities are never automatic");
  if(o.lattice && field_order(o.field) == 1)
    throw program::Usage_error("--lattice-cones applies to line and cross fields (--field smoothest:2, smoothest:4, "
                               "principal, trivial2:, trivial4:): a vector field has no branch points");
  if(!o.automatic && field_order(o.field) == 1)
    throw program::Usage_error("--no-automatic applies to line and cross fields (--field smoothest:2, smoothest:4, "
                               "principal, trivial2:, trivial4:): a vector field's singularities are never automatic");
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

// The field the stripes follow, one vector per vertex (any of the N directions); `solver` for
// the fields that solve.
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
  const int n = field_order(spec);
  const char* kind = n == 1 ? "vector" : n == 2 ? "line" : "cross";
  if(spec == "smoothest" || spec.rfind("smoothest:", 0) == 0)
  {
    const auto info = SD::smoothest_direction_field(mesh, CGAL::make_property_map(field),
                                                    SD::parameters::symmetry_order(n).sparse_linear_solver(solver));
    std::cout << "smoothest " << kind << " field: eigenvalue " << info.eigenvalues.front() << ", " << info.iterations
              << " Lanczos steps" << (info.weights_clamped ? " (negative cotangent weights clamped)" : "") << '\n';
    return field;
  }
  if(spec == "principal" || spec.rfind("principal:", 0) == 0)
  {
    const double weight =
      spec == "principal" ? 0.1 : program::parse_double(spec.substr(10), "--field principal:W (W)", 1e-6, 1e6);
    SD::smoothest_direction_field(mesh, CGAL::make_property_map(field),
                                  SD::parameters::symmetry_order(
                                    2, SD::parameters::curvature_alignment_weight(
                                         weight, SD::parameters::sparse_linear_solver(solver))));
    std::cout << "principal curvature line field (curvature alignment weight " << weight << ")\n";
    return field;
  }
  for(const std::string prefix : {"trivial:", "trivial2:", "trivial4:"})
    if(spec.rfind(prefix, 0) == 0)
    {
      // trivialN:FACE:INDEX,FACE:INDEX,...
      const std::string what = "--field " + prefix + "FACE:INDEX,FACE:INDEX,...";
      SD::Trivial_connection tc(mesh, SD::parameters::symmetry_order(n).sparse_linear_solver(solver));
      std::map<std::size_t, int> indices;
      for(const std::string& item : split_list(spec.substr(prefix.size()), what))
      {
        const auto [f, k] = parse_pair(item, what.c_str());
        if(f < 0)
          throw program::Usage_error("face numbers start at 0");
        if(k == 0)
          throw program::Usage_error("--field " + prefix + " index 0 at face " + std::to_string(f) + " prescribes nothing");
        if(!indices.emplace(std::size_t(f), int(k)).second)
          throw program::Usage_error("--field " + prefix + " face " + std::to_string(f) + " is given more than once");
      }
      for(const auto& [f, k] : indices)
        tc.set_index(f, k);
      tc.solve();
      tc.field(CGAL::make_property_map(field));
      std::cout << "trivial-connection " << kind << " field: largest adjustment " << tc.largest_adjustment() << " rad\n";
      return field;
    }
  throw program::Usage_error("unknown field " + spec +
                             " (axis:X,Y,Z, heat:V[:DEGREES], smoothest[:N], principal[:W], trivial:..., trivial2:..., "
                             "trivial4:...)");
}

// The picture: every face split into sub-triangles whose points carry `scalar(face, b)` (b the
// barycentric coordinates of the corners source(h), target(h), target(next(h)), h = halfedge(f)).
// A face for which `split(f)` gives a point (a branch face: its branch point, in barycentric
// coordinates) is drawn as the three triangles around that point, each sampled from its own
// inside, so that the pattern is evaluated on the sheet of that triangle at the corners too.
template <class Scalar, class Split>
void write_picture(const Mesh& mesh, std::size_t n, const Scalar& scalar, const Split& split,
                   program::Output_files& outputs, const Options& o)
{
  const std::vector<Eigen::Vector3d> normal = vertex_normals(mesh);
  program::Vtk_surface vtk;
  vtk.scalar_name = "stripes";
  using Bary = std::array<double, 3>;
  for(auto f : faces(mesh))
  {
    const auto h0 = halfedge(f, mesh);
    const Mesh::Vertex_index corner[3] = {source(h0, mesh), target(h0, mesh), target(next(h0, mesh), mesh)};
    Eigen::Vector3d p[3], nn[3];
    for(int i = 0; i < 3; ++i)
    {
      p[i] = eigen(mesh.point(corner[i]));
      nn[i] = normal[std::size_t(corner[i])];
    }
    const std::optional<Bary> branch_point = split(f);
    const Bary c0{1., 0., 0.}, c1{0., 1., 0.}, c2{0., 0., 1.}, centre = branch_point ? *branch_point : Bary{};
    const bool three = branch_point.has_value();
    const std::array<std::array<Bary, 3>, 3> pieces{
      {{c0, c1, three ? centre : c2}, {c1, c2, centre}, {c2, c0, centre}}};
    for(std::size_t k_piece = 0; k_piece < (three ? 3u : 1u); ++k_piece)
    {
      const auto& piece = pieces[k_piece];
      const std::size_t base = vtk.points.size();
      auto id = [&](std::size_t i, std::size_t j) { return base + j * (n + 1) - j * (j - 1) / 2 + i; };
      for(std::size_t j = 0; j <= n; ++j)
        for(std::size_t i = 0; i + j <= n; ++i)
        {
          const double wb = double(i) / double(n), wc = double(j) / double(n), wa = 1. - wb - wc;
          Bary b{}, inside{};
          for(std::size_t k = 0; k < 3; ++k)
          {
            b[k] = wa * piece[0][k] + wb * piece[1][k] + wc * piece[2][k];
            // evaluated a hair inside the piece: its corners are shared with the other sheet
            inside[k] = (1. - 1e-7) * b[k] + 1e-7 * (piece[0][k] + piece[1][k] + piece[2][k]) / 3.;
          }
          const Eigen::Vector3d q = b[0] * p[0] + b[1] * p[1] + b[2] * p[2];
          const Eigen::Vector3d m = (b[0] * nn[0] + b[1] * nn[1] + b[2] * nn[2]).normalized();
          vtk.add(q, m, scalar(f, inside));
        }
      for(std::size_t j = 0; j < n; ++j)
        for(std::size_t i = 0; i + j < n; ++i)
        {
          vtk.triangles.push_back({id(i, j), id(i + 1, j), id(i, j + 1)});
          if(i + j + 1 < n)
            vtk.triangles.push_back({id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
        }
    }
  }
  const std::string vtk_path = outputs.stage(o.picture + ".vtk");
  vtk.write(vtk_path);
  program::render_png(vtk_path, outputs.stage(o.picture), "stripes", -1., 1., o.up);
}

// Sub-triangles per face edge for the picture: enough that the largest change of the stripe
// angle inside one is about 0.6 rad, within a budget of 3 million points.
std::size_t picture_subdivision(const Mesh& mesh, double largest_step)
{
  const std::size_t budget = 3000000 / (std::max<std::size_t>)(num_faces(mesh), 1);
  const std::size_t n = std::size_t(std::ceil(largest_step / 0.6));
  return (std::max)(std::size_t(1), (std::min)(n, (std::min<std::size_t>)(8, std::size_t(std::sqrt(double(budget))))));
}

// The field vector of a face for the output: at the first vertex of the face in the file.
Eigen::Vector3d first_corner_field(const Mesh& mesh, const std::vector<Vector>& field, Mesh::Face_index f)
{
  const Vector& x = field[std::size_t(target(halfedge(f, mesh), mesh))];
  const Eigen::Vector3d v(x.x(), x.y(), x.z());
  return v.norm() > 0. ? Eigen::Vector3d(v.normalized()) : v;
}

template <class Solver>
int run_vector_field(const Options& o, Mesh& mesh, const std::vector<Vector>& field, double scale,
                     SD::Field_aligned_parameterizer<Mesh, Mesh::Property_map<Mesh::Vertex_index, Point>, Solver>& fap,
                     program::Stopwatch& clock, program::Output_files& outputs)
{
  fap.set_field(CGAL::make_property_map(field), scale, o.convention);
  std::cout << "field " << o.field << ", " << scale << " stripes per unit length: " << clock.lap() << " ms\n";

  for(const auto& g : o.singularities)
  {
    if(g[2] != 0)
      throw program::Usage_error("--singularity " + std::to_string(g[0]) + ":" + std::to_string(g[1]) + ":" +
                                 std::to_string(g[2]) + ": a vector field has one family of stripes (family 0)");
    fap.set_index(std::size_t(g[0]), int(g[1]));
  }
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

  auto corner = mesh.add_property_map<Mesh::Halfedge_index, double>("h:corner", 0.).first;
  fap.corner_coordinates(corner);
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
    std::map<Mesh::Face_index, int> field_index;
    SD::direction_field_singularities(mesh, CGAL::make_property_map(field), boost::make_assoc_property_map(field_index));
    program::Ply_property corner_alpha{"corner_alpha", "float", {}, 3}, stripe_index{"stripe_index", "float", {}},
      fx{"field_x", "float", {}}, fy{"field_y", "float", {}}, fz{"field_z", "float", {}},
      findex{"field_index", "float", {}};
    for(auto f : faces(mesh))
    {
      index_prop.values.push_back(detected[f]);
      for(auto h : halfedges_around_face(halfedge(f, mesh), mesh)) // the corners in the file's order
        corner_alpha.values.push_back(corner[h]);
      stripe_index.values.push_back(fap.index(f));
      const Eigen::Vector3d x = first_corner_field(mesh, field, f);
      fx.values.push_back(x.x());
      fy.values.push_back(x.y());
      fz.values.push_back(x.z());
      findex.values.push_back(field_index.at(f));
    }
    program::write_ply(outputs.stage(o.output), mesh, {alpha_prop},
                       {index_prop, corner_alpha, stripe_index, fx, fy, fz, findex}, edge_vertices, {omega, dalpha});
  }

  isoline_output(o, fap, clock, outputs);
  if(!o.picture.empty())
  {
    double largest = 0.;
    for(auto h : halfedges(mesh))
      largest = (std::max)(largest, std::abs(fap.dalpha(h)));
    write_picture(
      mesh, picture_subdivision(mesh, largest),
      [&](Mesh::Face_index f, const std::array<double, 3>& b) {
        const auto h0 = halfedge(f, mesh); // corners at source(h0), target(h0), target(next(h0))
        return std::cos(b[0] * corner[prev(h0, mesh)] + b[1] * corner[h0] + b[2] * corner[next(h0, mesh)]);
      },
      [](Mesh::Face_index) { return std::optional<std::array<double, 3>>(); }, outputs, o);
  }
  return 0;
}

// The isolines as OBJ polylines (a closed line repeats its first vertex), in two groups by level.
template <class Lines>
void write_isolines(const std::string& path, const Lines& lines)
{
  std::ofstream out(path);
  out << "# stripe isolines: " << lines.size() << " polylines; level_0 and level_pi: the stripe angle modulo 2 pi\n";
  out.precision(17);
  for(const auto& line : lines)
    for(const auto& q : line.points)
      out << "v " << q.x() << ' ' << q.y() << ' ' << q.z() << '\n';
  for(const bool zero : {true, false})
  {
    out << "g " << (zero ? "level_0" : "level_pi") << '\n';
    std::size_t first = 1;
    for(const auto& line : lines)
    {
      if((line.level == 0.) == zero)
      {
        out << 'l';
        for(std::size_t i = 0; i < line.points.size(); ++i)
          out << ' ' << first + i;
        if(line.closed)
          out << ' ' << first;
        out << '\n';
      }
      first += line.points.size();
    }
  }
  if(!out)
    throw std::runtime_error("cannot write " + path);
}

// Reports and writes the isolines of a solved pattern (vector or branched stripes).
template <class Parameterizer>
void isoline_output(const Options& o, const Parameterizer& p, program::Stopwatch& clock, program::Output_files& outputs)
{
  if(o.isolines.empty())
    return;
  const auto lines = p.isolines();
  std::size_t closed = 0, points = 0;
  for(const auto& line : lines)
  {
    closed += line.closed ? 1 : 0;
    points += line.points.size();
  }
  write_isolines(outputs.stage(o.isolines), lines);
  std::cout << "isolines: " << lines.size() << " polylines (" << closed << " closed), " << points << " points ("
            << clock.lap() << " ms)\n";
}

template <class Solver>
int run_branched(const Options& o, const Mesh& mesh, const std::vector<Vector>& field, int n, double scale,
                 const Solver& solver, program::Stopwatch& clock, program::Output_files& outputs)
{
  if(!o.windings.empty())
    throw program::Usage_error("--winding applies to vector fields: the windings of line and cross field stripes "
                               "are chosen automatically");
  SD::Branched_stripe_parameterizer bsp(mesh, SD::parameters::symmetry_order(n).sparse_linear_solver(solver));
  bsp.set_lattice_branch_points(o.lattice); // before the field: one factorization
  bsp.set_field(CGAL::make_property_map(field), scale, o.convention);
  const std::vector<std::size_t> branch = bsp.branch_faces();
  std::cout << (n == 2 ? "line" : "cross") << " field " << o.field << ", " << scale << " stripes per unit length: "
            << branch.size() << " branch face(s) (the field's singularities of index k/" << n
            << " with k not a multiple of " << n << "); cover, weights, factorization: " << clock.lap() << " ms\n";
  for(const auto& g : o.singularities)
    if(g[2] >= bsp.number_of_families())
      throw program::Usage_error("--singularity " + std::to_string(g[0]) + ":" + std::to_string(g[1]) + ":" +
                                 std::to_string(g[2]) + ": a line field has one family of stripes (family 0)");
  for(const auto& g : o.singularities)
    bsp.set_index(std::size_t(g[0]), int(g[1]), int(g[2]));
  if(o.singularities.empty() && o.automatic)
  {
    const std::size_t count = bsp.place_automatic_singularities();
    std::cout << "automatic stripe singularities: " << count << " (" << clock.lap() << " ms)\n";
  }
  bsp.solve();
  std::cout << "solve: " << clock.lap() << " ms (energy " << bsp.energy() << ", " << bsp.number_of_free_windings()
            << " free windings)\n";

  // the promise: exactly the prescribed singularities, read back from the solution
  std::size_t singular = 0;
  std::ostringstream listed;
  for(auto f : faces(mesh))
    for(int a = 0; a < bsp.number_of_families(); ++a)
    {
      if(bsp.stripe_index(f, a) != bsp.index(f, a))
        throw std::runtime_error("internal error: face " + std::to_string(std::size_t(f)) + " has stripe index " +
                                 std::to_string(bsp.stripe_index(f, a)) + " instead of " + std::to_string(bsp.index(f, a)));
      if(bsp.index(f, a) != 0)
      {
        ++singular;
        if(singular <= 40)
          listed << ' ' << std::size_t(f) << ':' << bsp.index(f, a) << (n == 4 ? ":" + std::to_string(a) : "");
      }
    }
  std::cout << "stripe singularities (" << singular << ", face:index" << (n == 4 ? ":family" : "")
            << "):" << listed.str() << (singular > 40 ? " ..." : "") << '\n';
  if(o.lattice)
  {
    // the promise: every branch point at 0 modulo 2 pi, read back
    for(std::size_t f : branch)
    {
      const auto c = bsp.branch_point_value(Mesh::Face_index(Mesh::size_type(f)));
      for(int a = 0; a < bsp.number_of_families(); ++a)
        if(std::abs(std::remainder(c[std::size_t(a)], 2. * CGAL_PI)) > 1e-8)
          throw std::runtime_error("internal error: the branch point of face " + std::to_string(f) +
                                   " is off the lattice (" + std::to_string(c[std::size_t(a)]) + ")");
    }
    std::cout << "branch points on the lattice: " << branch.size() << '\n';
  }

  if(!o.output.empty())
  {
    const int families = bsp.number_of_families();
    std::vector<program::Ply_property> props;
    program::Ply_property corner_alpha{"corner_alpha", "float", {}, 3}, corner_beta{"corner_beta", "float", {}, 3},
      stripe_index{"stripe_index", "float", {}}, stripe_index_beta{"stripe_index_beta", "float", {}},
      fx{"field_x", "float", {}}, fy{"field_y", "float", {}}, fz{"field_z", "float", {}},
      findex{"field_index", "float", {}};
    for(auto f : faces(mesh))
    {
      for(int a = 0; a < families; ++a)
      {
        const auto c = bsp.corner_values(f, a); // source(h), target(h), target(next(h)); the file: target(h) first
        auto& list = a == 0 ? corner_alpha : corner_beta;
        list.values.insert(list.values.end(), {c[1], c[2], c[0]});
        (a == 0 ? stripe_index : stripe_index_beta).values.push_back(bsp.index(f, a));
      }
      const auto d = bsp.field_direction(f);
      fx.values.push_back(d.x());
      fy.values.push_back(d.y());
      fz.values.push_back(d.z());
      findex.values.push_back(double(bsp.field_index_numerator(f)) / n);
    }
    props = {corner_alpha, stripe_index, fx, fy, fz, findex};
    if(families == 2)
    {
      props.push_back(corner_beta);
      props.push_back(stripe_index_beta);
    }
    program::write_ply(outputs.stage(o.output), mesh, {}, props);
  }

  isoline_output(o, bsp, clock, outputs);
  if(!o.picture.empty())
  {
    double largest = 0.;
    for(auto f : faces(mesh))
      for(int a = 0; a < bsp.number_of_families(); ++a)
      {
        const auto c = bsp.corner_values(f, a);
        largest = (std::max)({largest, std::abs(c[1] - c[0]), std::abs(c[2] - c[1]), std::abs(c[2] - c[0])});
      }
    // line field: cos alpha; cross field: the brighter of the two families, a grid of stripes
    write_picture(
      mesh, picture_subdivision(mesh, largest),
      [&](Mesh::Face_index f, const std::array<double, 3>& b) {
        const double u = std::cos(bsp.value(f, b, 0));
        return n == 4 ? (std::max)(u, std::cos(bsp.value(f, b, 1))) : u;
      },
      [&](Mesh::Face_index f) {
        return bsp.is_branch_face(f) ? std::optional<std::array<double, 3>>(bsp.branch_point(f)) : std::nullopt;
      },
      outputs, o);
  }
  return 0;
}

template <class Solver>
int run(const Options& o, const Solver& solver)
{
  program::Stopwatch clock, total;
  Mesh mesh = program::read_mesh(o.input);
  std::cout << "read " << o.input << ": " << num_vertices(mesh) << " vertices, " << num_faces(mesh)
            << " faces (" << clock.lap() << " ms)\n";
  const int n = field_order(o.field);

  // the field's system (smoothest or trivial connection) has the pattern of the stripes' one: with
  // the default solver, one ordering and analysis serves both on large meshes
  Solver stripe_solver = solver;
  const Solver field_solver = program::solver_sharing_analysis(stripe_solver);
  std::optional<SD::Field_aligned_parameterizer<Mesh, Mesh::Property_map<Mesh::Vertex_index, Point>, Solver>> fap;
  if(n == 1)
  {
    fap.emplace(mesh, SD::parameters::sparse_linear_solver(stripe_solver));
    std::cout << "validate, topology, weights, factorization: " << clock.lap() << " ms\n";
    std::cout << "  " << fap->number_of_connected_components() << " component(s), genus";
    for(std::size_t c = 0; c < fap->number_of_connected_components(); ++c)
      std::cout << ' ' << fap->genus(c);
    std::cout << ", " << fap->number_of_generator_loops() << " generator loop(s), "
              << fap->number_of_boundary_loops() << " boundary loop(s)\n";
  }

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

  program::Output_files outputs;
  if(n == 1)
    run_vector_field(o, mesh, field, scale, *fap, clock, outputs);
  else
    run_branched(o, mesh, field, n, scale, stripe_solver, clock, outputs);
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
