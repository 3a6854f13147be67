// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// quad_remesh: quad remeshing from the isolines and gradient lines of a harmonic
// function (Dong, Kircher & Garland 2005; Nagano & Imai), or from the lines of a cross field's
// two stripe families (--method field). Run without arguments for the usage.

#include "common/option_parser.h"
#include "common/program_support.h"

#include <CGAL/Surface_design/Harmonic_quad_remesher.h>
#include <CGAL/Surface_design/Trivial_connection.h>
#include <CGAL/Surface_design/direction_fields.h>
#include <CGAL/Surface_design/field_aligned_quad_remeshing.h>
#include <CGAL/Surface_design/quad_mesh_quality.h>

#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/remesh.h>
#include <CGAL/boost/graph/Face_filtered_graph.h>
#include <CGAL/boost/graph/copy_face_graph.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <cmath>
#include <cstdio>
#include <future>
#include <iostream>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace SD = CGAL::Surface_design;
namespace P = CGAL::Surface_design::parameters;
using program::Mesh;
using program::Point;

namespace {

const char* usage =
  "usage: quad_remesh INPUT --output OUT.off [options]\n"
  "  Remeshes a manifold triangle mesh into a quad mesh with the input's topology (Euler\n"
  "  characteristic, boundary loops, components), or fails (exit 1, no file).\n"
  "  --method auto (default): the field method's quads (below) where it gives them, component by\n"
  "  component, and the harmonic method's at the same h on a component where it does not, after all\n"
  "  its repairs (the report names the method of each): the field's quads have several times fewer\n"
  "  irregular vertices, the harmonic net takes every manifold mesh.\n"
  "  --method harmonic: the net of the isolines and gradient lines of a harmonic function\n"
  "  (Dong, Kircher & Garland 2005), its odd faces paired into quads; any manifold mesh. When the\n"
  "  net comes out with another topology, the program falls back (without spectacles, the intrinsic\n"
  "  Delaunay Laplacian, h / 2 near the saddles, h / sqrt 2, h / 2).\n"
  "  --method field: the lines of the two stripe families of a cross field with its cones on the\n"
  "  lattice: pure quads whose irregular vertices are exactly the field's cones (valence 3 at +1/4,\n"
  "  5 at -1/4). On a mesh with a boundary the field follows it and every boundary loop is a line of\n"
  "  the quads (valence 3 along it; 2 at a convex corner, 4 at a concave one), its direction\n"
  "  smoothed at 2h (--boundary-smoothing). Where the lines do not form such a mesh, h is tried 5%\n"
  "  smaller and 5% larger, then the input is remeshed isotropically at edge length h (its triangles'\n"
  "  shapes can fold the map: decimated meshes) and the whole tried again, before the program fails\n"
  "  (auto: the harmonic method instead).\n"
  "  Several connected components (without --singularity) are remeshed one by one, each with its own\n"
  "  field and cones; one that gives no quads at h is tried at h / 1.25, h / 1.25^2, ... while that\n"
  "  adds at most 5% to the mesh's quads (components smaller than a few quads).\n"
  "options of every method:\n"
  "  --method auto|field|harmonic\n"
  "  --edge-length H       target edge length (default: sqrt(area / 3000): about 3000 faces with the\n"
  "                        field method and auto, 1.5 to 4 times as many with --method harmonic)\n"
  "  --target-faces N      about N faces (not with --edge-length): from the edge length sqrt(area / N),\n"
  "                        the field method's spacing calibrated on its map's area, the harmonic\n"
  "                        method's net made again at h sqrt(faces / N) until within 10% (4 nets at most)\n"
  "options of --method field (and auto, where it uses the field method; --singularity: field only):\n"
  "  --field auto|smoothest|principal  the cross field: the smoothest one (Knoeppel et al. 2013), the\n"
  "                        smoothest one aligned with the principal curvature directions, or (auto,\n"
  "                        default) of these two the one with fewer cones once they are apart\n"
  "  --cone-distance D     automatic cones at least D h apart (default 1; 0 keeps the field's): closer\n"
  "                        pairs of opposite index are removed, others moved apart, and the field is\n"
  "                        the trivial connection with those cones (Crane et al. 2010); a cone of -1/4\n"
  "                        in a face with an angle of 120 degrees or more is moved into a neighbour\n"
  "                        (with a boundary, the trivial connection follows it too)\n"
  "  --singularity FACE:K/4  a cone of index K/4 (K = 1 or -1) in FACE (repeatable): the field is the\n"
  "                        trivial connection with exactly these cones (they must sum to the Euler\n"
  "                        characteristic; with a boundary, less its corners: the message says how\n"
  "                        much; not in a face with an edge on the boundary)\n"
  "  --boundary-smoothing S  with a boundary, the field and the quads follow its direction smoothed\n"
  "                        at S h (default 2, S in [0, 10]; 0: every boundary edge): a boundary that\n"
  "                        zigzags finer than that is straightened, corners where it turns by 67.5\n"
  "                        degrees or more within S h are kept\n"
  "  --edge-length-ratio R curvature-adapted sizing: the spacing follows 1 / sqrt(curvature), an even\n"
  "                        chord error, with the largest R times the smallest (R in [1, 100]; default\n"
  "                        1: uniform), as many faces as h everywhere would give\n"
  "  --stiffening-rounds R rounds of local stiffening where the map folds (default 10, R in [0, 64])\n"
  "  --no-input-remeshing  fail (auto: the harmonic method) where the input's own triangles do not give\n"
  "                        the quads (without it, given cones go, on the remeshed input, to the faces\n"
  "                        nearest theirs)\n"
  "  --sharp-angle DEG     the quads follow the creases, the edges whose faces' normals differ by more\n"
  "                        than DEG degrees (0 < DEG < 180): the field follows them (its own cones,\n"
  "                        not separated), a cone next to a corner of them moves onto it, and the row\n"
  "                        of vertices next to each crease onto the crease (not with --singularity\n"
  "                        or --cone-distance; a remeshed input keeps the creases)\n"
  "options of --method harmonic:\n"
  "  --min V               vertex V is a minimum of the function (value 0); repeatable\n"
  "  --max V               vertex V is a maximum (value 1); repeatable. Without --min/--max:\n"
  "                        a minimum and a maximum at the ends of a geodesic diameter of every\n"
  "                        component, and a maximum at every tip of the shape\n"
  "  --no-protrusions      default constraints without the maxima at the tips\n"
  "  --curvature-adaptation A  spacing h / (1 + A h kappa), at least h / 4, kappa the curvature\n"
  "                        across the input's edges: finer where the surface bends (default 0: uniform;\n"
  "                        A in [0, 1000])\n"
  "  --intrinsic-delaunay  Laplacian of the intrinsic Delaunay triangulation (no spurious extrema)\n"
  "  --triangle-poles      fans of triangles around the extrema (default: fans of quads)\n"
  "  --no-spectacles       no spectacles around the saddles (default: spectacles, Nagano & Imai: the\n"
  "                        function re-solved with a curve through each saddle held at one value;\n"
  "                        saddles where they do not fit are reported and left as they are)\n"
  "  --quad-dominant       keep the net as it is: pentagons where lines end (T-junctions), triangles\n"
  "                        (default: quads only; odd faces are paired by paths across the net whose\n"
  "                        edges get a vertex, and every face is split into quads)\n"
  "common options:\n"
  "  --no-feature-snapping keep the positions of the net or of the lines' crossings (default:\n"
  "                        interior input vertices and points along its creases farther than h / 4\n"
  "                        from the result, a pit, a spike or a crease narrower than h, pull the\n"
  "                        nearest vertex onto them; the creases: --sharp-angle's, else 30 degrees)\n"
  "  --solver S            sparse solver: default (simplicial LDLT below 20k\n"
  "                        unknowns, supernodal Cholesky above), ldlt, supernodal, cholmod\n"
  "  --output OUT          the quad mesh (.off, .obj or .ply); required\n"
  "  --picture OUT.png     the new mesh's edges over the input; faces other than quads in orange\n"
  "  --up +Y|+Z|...        up direction in the picture (default +Y)\n";

struct Options
{
  std::string input, output, picture, up = "+Y", solver = "default", method = "auto", field = "auto";
  std::vector<long> minima, maxima;
  std::map<long, int> cones; // --singularity FACE:K/4
  double edge_length = 0., target_faces = 0., curvature_adaptation = 0., cone_distance = 1., sharp_angle = 0.,
         boundary_smoothing = 2., edge_length_ratio = 1.;
  int stiffening_rounds = 10;
  bool protrusions = true, intrinsic_delaunay = false, quad_poles = true, spectacles = true,
       all_quads = true, feature_snapping = true, input_remeshing = true;
};

Options parse(int argc, char** argv)
{
  Options o;
  auto vertex = [](std::vector<long>& into, const char* name) {
    return [&into, name](const std::string& v) { into.push_back(program::parse_integer(v, name, 0, 1L << 40)); };
  };
  program::Option_parser p;
  p.input(o.input)
    .value("--method", [&](const std::string& v) { o.method = program::parse_choice(v, "--method", {"auto", "field", "harmonic"}); })
    .value("--target-faces",
           [&](const std::string& v) { o.target_faces = double(program::parse_integer(v, "--target-faces", 1, 10000000)); })
    .value("--field", [&](const std::string& v) { o.field = program::parse_choice(v, "--field", {"auto", "smoothest", "principal"}); })
    .value("--cone-distance", [&](const std::string& v) { o.cone_distance = program::parse_double(v, "--cone-distance", 0., 100.); })
    .repeated("--singularity",
              [&](const std::string& v) {
                const char* what = "--singularity FACE:K/4";
                const auto slash = v.rfind("/4");
                if(slash == std::string::npos || slash + 2 != v.size())
                  throw program::Usage_error(std::string("expected ") + what + " (K = 1 or -1), got '" + v + "'");
                const auto [f, k] = program::parse_pair(v.substr(0, slash), what);
                if(f < 0)
                  throw program::Usage_error("--singularity: face numbers start at 0, got " + std::to_string(f));
                if(k != 1 && k != -1)
                  throw program::Usage_error("--singularity: a cone of a quad mesh has index 1/4 or -1/4, got " +
                                             std::to_string(k) + "/4");
                if(!o.cones.emplace(f, int(k)).second)
                  throw program::Usage_error("--singularity: face " + std::to_string(f) + " is given more than once");
              })
    .value("--boundary-smoothing",
           [&](const std::string& v) { o.boundary_smoothing = program::parse_double(v, "--boundary-smoothing", 0., 10.); })
    .value("--sharp-angle", [&](const std::string& v) { o.sharp_angle = program::parse_double(v, "--sharp-angle", 0., 180.); })
    .value("--edge-length-ratio",
           [&](const std::string& v) { o.edge_length_ratio = program::parse_double(v, "--edge-length-ratio", 1., 100.); })
    .value("--stiffening-rounds",
           [&](const std::string& v) { o.stiffening_rounds = int(program::parse_integer(v, "--stiffening-rounds", 0, 64)); })
    .flag("--no-input-remeshing", [&] { o.input_remeshing = false; })
    .repeated("--min", vertex(o.minima, "--min"))
    .repeated("--max", vertex(o.maxima, "--max"))
    .flag("--no-protrusions", [&] { o.protrusions = false; })
    .value("--edge-length", [&](const std::string& v) { o.edge_length = program::parse_positive(v, "--edge-length"); })
    .value("--curvature-adaptation",
           [&](const std::string& v) { o.curvature_adaptation = program::parse_double(v, "--curvature-adaptation", 0., 1000.); })
    .flag("--intrinsic-delaunay", [&] { o.intrinsic_delaunay = true; })
    .flag("--triangle-poles", [&] { o.quad_poles = false; })
    .flag("--no-spectacles", [&] { o.spectacles = false; })
    .flag("--quad-dominant", [&] { o.all_quads = false; })
    .flag("--no-feature-snapping", [&] { o.feature_snapping = false; })
    .solver(o.solver)
    .output("--output", o.output, {".off", ".obj", ".ply"})
    .picture(o.picture, o.up)
    .parse(argc, argv);
  if(o.output.empty())
    throw program::Usage_error("--output OUT.off is required");
  if(p.given("--edge-length") && p.given("--target-faces"))
    throw program::Usage_error("give --edge-length or --target-faces, not both");
  for(const char* option :
      {"--field", "--cone-distance", "--stiffening-rounds", "--no-input-remeshing", "--sharp-angle",
       "--boundary-smoothing", "--edge-length-ratio"})
    if(p.given(option) && o.method == "harmonic")
      throw program::Usage_error(std::string(option) + " applies to --method field (or auto)");
  // auto may remesh a component with the harmonic method, whose irregular vertices are not the given cones
  if(!o.cones.empty() && o.method != "field")
    throw program::Usage_error("--singularity applies to --method field (with auto, a component without field quads "
                               "would get the harmonic net's irregular vertices instead of these cones)");
  for(const char* option : {"--min", "--max", "--no-protrusions", "--curvature-adaptation", "--intrinsic-delaunay",
                            "--triangle-poles", "--no-spectacles", "--quad-dominant"})
    if(p.given(option) && o.method != "harmonic")
      throw program::Usage_error(std::string(option) + " applies to --method harmonic");
  if(!o.cones.empty() && (p.given("--field") || p.given("--cone-distance")))
    throw program::Usage_error("--singularity sets the cones of the field: not with --field or --cone-distance");
  if(p.given("--sharp-angle"))
  {
    if(!(o.sharp_angle > 0. && o.sharp_angle < 180.))
      throw program::Usage_error("--sharp-angle: must lie strictly between 0 and 180 degrees");
    if(!o.cones.empty() || p.given("--cone-distance"))
      throw program::Usage_error("--sharp-angle: the field follows the creases with the cones it chooses itself: not "
                                 "with --singularity or --cone-distance (the trivial connection does not follow creases)");
  }
  if(o.minima.empty() != o.maxima.empty())
    throw program::Usage_error("give both --min and --max vertices (constraints on one value only leave the "
                               "function constant), or neither for the default constraints");
  if(!o.minima.empty() && !o.protrusions)
    throw program::Usage_error("--no-protrusions applies to the default constraints, not to --min/--max");
  program::check_paths_and_picture({{"INPUT", o.input}, {"--output", o.output}}, o.picture, p.given("--up"));
  return o;
}

Eigen::Vector3d eigen(const Point& p) { return Eigen::Vector3d(p.x(), p.y(), p.z()); }

// The input flat-shaded in grey, the new mesh's faces other than quads in orange just above it,
// and its edges as dark ribbons.
void write_picture(const Mesh& input, const Mesh& quads, const Options& o, program::Output_files& outputs)
{
  program::Vtk_surface vtk;
  vtk.scalar_name = "shade";
  const Eigen::Vector3d light = Eigen::Vector3d(0.3, 0.6, 0.75).normalized();
  for(auto f : faces(input))
  {
    std::vector<Eigen::Vector3d> p;
    for(auto v : vertices_around_face(halfedge(f, input), input))
      p.push_back(eigen(input.point(v)));
    const Eigen::Vector3d n = (p[1] - p[0]).cross(p[2] - p[0]).normalized();
    const double shade = 2. + 0.5 * (1. + n.dot(light));
    vtk.triangles.push_back({vtk.add(p[0], n, shade), vtk.add(p[1], n, shade), vtk.add(p[2], n, shade)});
  }
  double mean_edge = 0.;
  for(auto e : edges(quads))
    mean_edge += (eigen(quads.point(source(e, quads))) - eigen(quads.point(target(e, quads)))).norm();
  mean_edge /= double((std::max)(std::size_t(num_edges(quads)), std::size_t(1)));
  std::vector<Eigen::Vector3d> normal(num_faces(quads));
  for(auto f : faces(quads))
  {
    std::vector<Eigen::Vector3d> p;
    for(auto v : vertices_around_face(halfedge(f, quads), quads))
      p.push_back(eigen(quads.point(v)));
    Eigen::Vector3d n = Eigen::Vector3d::Zero();
    for(std::size_t k = 1; k + 1 < p.size(); ++k)
      n += (p[k] - p[0]).cross(p[k + 1] - p[0]);
    n.normalize();
    normal[std::size_t(f)] = n;
    if(p.size() == 4)
      continue;
    const Eigen::Vector3d lift = 0.04 * mean_edge * n;
    const std::size_t first = vtk.add(p[0] + lift, n, 1.);
    for(std::size_t k = 1; k + 1 < p.size(); ++k)
      vtk.triangles.push_back({first, vtk.add(p[k] + lift, n, 1.), vtk.add(p[k + 1] + lift, n, 1.)});
  }
  const double width = 0.06 * mean_edge;
  for(auto e : edges(quads))
  {
    const auto h = halfedge(e, quads);
    Eigen::Vector3d n = Eigen::Vector3d::Zero();
    if(!is_border(h, quads))
      n += normal[std::size_t(face(h, quads))];
    if(!is_border(opposite(h, quads), quads))
      n += normal[std::size_t(face(opposite(h, quads), quads))];
    n.normalize();
    const Eigen::Vector3d a = eigen(quads.point(source(h, quads))), b = eigen(quads.point(target(h, quads)));
    const Eigen::Vector3d side = n.cross(b - a).normalized() * width, lift = n * (0.08 * mean_edge);
    const std::size_t i0 = vtk.add(a - side + lift, n, 0.), i1 = vtk.add(b - side + lift, n, 0.),
                      i2 = vtk.add(b + side + lift, n, 0.), i3 = vtk.add(a + side + lift, n, 0.);
    vtk.triangles.push_back({i0, i1, i2});
    vtk.triangles.push_back({i0, i2, i3});
  }
  const std::string vtk_path = outputs.stage(o.picture + ".vtk");
  vtk.write(vtk_path);
  // 0 edges dark blue, 1 non-quads orange, 2..3 grey shading
  const std::string colormap =
    "0,0.05,0.1,0.35,0.3,0.05,0.1,0.35,0.32,0.95,0.55,0.1,0.62,0.95,0.55,0.1,0.6667,0.55,0.56,0.58,1,0.97,0.97,0.96";
  program::render_png(vtk_path, outputs.stage(o.picture), "shade", 0., 3., o.up, colormap);
}

// The quality report of the result, then the files; fails if the result is not valid or has
// another topology than the input.
int report_and_write(const Mesh& input, const Mesh& quads, const Options& o, program::Stopwatch& clock)
{
  const SD::Quad_mesh_quality q = SD::quad_mesh_quality(quads, input);
  std::printf("output: %zu vertices, %zu faces: %zu triangles, %zu quads, %zu pentagons, %zu hexagons, %zu larger; "
              "%.1f%% quads (%.1f%% of the area)\n",
              q.vertices, q.faces, q.faces_by_sides[0], q.faces_by_sides[1], q.faces_by_sides[2], q.faces_by_sides[3],
              q.faces_by_sides[4], 100. * q.quad_fraction, 100. * q.quad_area_fraction);
  std::printf("  %zu irregular vertices, %zu T-junctions; quad corners |angle - 90| mean %.1f rms %.1f max %.1f deg; "
              "edge length %.4g (variation %.2f)\n",
              q.irregular_vertices, q.t_junctions, q.angle_deviation_mean, q.angle_deviation_rms,
              q.angle_deviation_max, q.edge_length_mean, q.edge_length_variation);
  std::printf("  Hausdorff distance %.3g%% of the bounding-box diagonal; %s, Euler characteristic %ld, %zu boundary "
              "loops, %zu components (%s the input's)\n",
              100. * q.relative_hausdorff_distance, q.valid ? "valid" : "INVALID", q.euler_characteristic,
              q.boundary_loops, q.connected_components, q.same_topology ? "as" : "NOT as");

  if(q.degenerate_edges > 0)
    std::printf("  %zu edges of length 0 (two vertices at one point)\n", q.degenerate_edges);
  // (the remeshers check the validity and the topology: a second look; edges of length 0 only here)
  if(!q.valid || !q.same_topology || q.degenerate_edges > 0)
    throw std::runtime_error("the quad mesh is not a valid mesh with the input's topology and no degenerate face (a "
                             "bug: please report it with the input mesh); nothing written");
  program::Output_files outputs;
  if(!CGAL::IO::write_polygon_mesh(outputs.stage(o.output), quads, CGAL::parameters::stream_precision(17)))
    throw std::runtime_error("cannot write " + o.output);
  if(!o.picture.empty())
    write_picture(input, quads, o, outputs);
  outputs.commit();
  std::printf("total %.3f s\n", clock.lap() / 1000.);
  return 0;
}

// What feature snapping did (either method's result).
template <class Result>
void print_snapping(const Result& r)
{
  std::printf("feature snapping: %zu of %zu input vertices and crease points farther than h / 4 from the result "
              "pulled a vertex onto them (the farthest was %.3g away)\n",
              r.snapped_vertices, r.far_input_vertices, r.largest_input_distance);
}

long euler_characteristic(const Mesh& m) { return long(num_vertices(m)) - long(num_edges(m)) + long(num_faces(m)); }

// The input mesh, with its counts printed.
Mesh read_input(const Options& o)
{
  Mesh input = program::read_mesh(o.input);
  const long chi = euler_characteristic(input);
  std::cout << "read " << o.input << ": " << num_vertices(input) << " vertices, " << num_faces(input)
            << " faces, Euler characteristic " << chi << '\n';
  return input;
}

// The surface area of a triangle mesh.
double area(const Mesh& m)
{
  double a = 0.;
  for(auto f : faces(m))
  {
    const auto hd = halfedge(f, m);
    const Eigen::Vector3d p = eigen(m.point(source(hd, m))), q = eigen(m.point(target(hd, m))),
                          r = eigen(m.point(target(next(hd, m), m)));
    a += 0.5 * (q - p).cross(r - p).norm();
  }
  return a;
}

// --edge-length, or sqrt(area / N) with --target-faces N; 0 without either (the default).
double edge_length(const Mesh& input, const Options& o)
{
  if(o.edge_length > 0.)
    return o.edge_length;
  if(!(o.target_faces > 0.))
    return 0.;
  return std::sqrt(area(input) / o.target_faces);
}

// The harmonic method's quads of `input` at h (0: its default, sqrt(area / 3000)), what it did
// printed; with target_faces > 0, about so many (the spacing calibrated from h).
template <class Traits>
void harmonic_quads(const Mesh& input, double h, double target_faces, const Options& o, Traits traits, Mesh& quads)
{
  const SD::Harmonic_weights weights =
    o.intrinsic_delaunay ? SD::Harmonic_weights::intrinsic_delaunay : SD::Harmonic_weights::cotangent;
  SD::Harmonic_quad_remesher<Mesh, Mesh::Property_map<Mesh::Vertex_index, Point>, Traits> remesher(
    input, P::harmonic_weights(weights, P::protrusion_maxima(o.protrusions, CGAL::parameters::sparse_linear_solver(traits))));
  if(!o.minima.empty())
  {
    std::vector<std::pair<Mesh::Vertex_index, double>> c;
    for(const auto& [list, value] : {std::make_pair(&o.minima, 0.), std::make_pair(&o.maxima, 1.)})
      for(long v : *list)
      {
        if(std::size_t(v) >= num_vertices(input)) // checked before the index is narrowed
          throw program::Usage_error((value == 0. ? "--min " : "--max ") + std::to_string(v) + ": the mesh has " +
                                     std::to_string(num_vertices(input)) + " vertices");
        c.emplace_back(Mesh::Vertex_index(Mesh::size_type(v)), value);
      }
    remesher.set_constraints(c);
  }
  const SD::Harmonic_critical_points cp = remesher.critical_points();
  std::printf("harmonic function: %zu constraints, %s weights (%zu negative, %zu flips); %zu minima, %zu maxima, "
              "%zu saddles (multiplicity %d), %zu of them on the boundary; %zu spurious extrema\n",
              remesher.constraints().size(), o.intrinsic_delaunay ? "intrinsic Delaunay" : "cotangent",
              remesher.number_of_negative_weights(), remesher.number_of_flips(), cp.minima.size(), cp.maxima.size(),
              cp.saddles.size(), cp.saddle_multiplicity(), cp.on_boundary, cp.spurious_extrema);
  if(CGAL::is_closed(input))
    std::printf("  %zu + %zu - %d = %ld = Euler characteristic\n", cp.minima.size(), cp.maxima.size(),
                cp.saddle_multiplicity(), long(cp.minima.size() + cp.maxima.size()) - cp.saddle_multiplicity());
  else
    std::printf("  sum of the indices 1 - chi(lower link) = %ld = Euler characteristic\n", cp.index_sum);

  const auto options = P::quad_poles(
    o.quad_poles,
    P::spectacles(o.spectacles,
                  P::all_quads(o.all_quads, P::curvature_adaptation(o.curvature_adaptation,
                                                                    P::feature_snapping(o.feature_snapping)))));
  // at h, and with a face count asked for, again at the spacing scaled by sqrt(faces / asked) until
  // the net lands within 10% of it (three more nets at most, the closest kept): the net's splits
  // into quads make 1.5 to 4 times the faces of sqrt(area / N) on the shared meshes
  auto print = [&o](const SD::Harmonic_quad_remeshing_result& r) {
    if(o.spectacles)
    {
      std::printf("spectacles: %zu of %zu saddles (%zu lines from bridges and junctions)\n", r.spectacles, r.saddles,
                  r.spectacles_lines);
      for(const auto& [v, why] : r.skipped_saddles)
        std::printf("  saddle at vertex %zu skipped: %s\n", v, why.c_str());
    }
    for(const auto& f : r.fallbacks)
      std::printf("fall-back: %s\n", f.c_str());
    if(r.repaired_cells > 0)
      std::printf("%zu cells of the net whose boundary ran through a node twice were cut by a chord\n", r.repaired_cells);
    std::printf("net (h = %.4g): %zu levels, %zu isolines (%zu between saddles), %zu gradient lines (%zu started, %zu "
                "stopped, %zu met another), %zu vertices on boundary detail\n",
                r.spacing, r.levels, r.isolines, r.saddle_levels, r.gradient_lines, r.started_lines,
                r.stopped_lines, r.merged_lines, r.boundary_detail_vertices);
    if(o.all_quads)
      std::printf("quads only: %zu faces with an odd number of sides paired by %zu paths, %zu edges split\n",
                  r.odd_faces, r.odd_face_paths, r.split_edges);
    if(o.feature_snapping)
      print_snapping(r);
    std::printf("times: harmonic %.3f s, spectacles (re-solve) %.3f s, curves %.3f s, meshing %.3f s (quads only %.3f s, "
                "snapping %.3f s)\n",
                r.harmonic_seconds, r.spectacles_seconds, r.curves_seconds, r.meshing_seconds, r.all_quads_seconds,
                r.snapping_seconds);
  };
  if(!(h > 0.))
  {
    print(remesher.remesh(quads, options));
    return;
  }
  double spacing = h, best = std::numeric_limits<double>::infinity();
  for(int net = 0;; ++net)
  {
    Mesh out;
    try
    {
      print(remesher.remesh(out, P::target_edge_length(spacing, options)));
    }
    catch(const std::exception& e) // (a later net: Remeshing_failure, a solver's failure, too many faces)
    {
      if(net == 0 || !(dynamic_cast<const std::runtime_error*>(&e) || dynamic_cast<const SD::Invalid_parameter*>(&e)))
        throw;
      std::printf("  no net at h = %.4g (%s): the closest one kept\n", spacing, e.what());
      break;
    }
    const double faces = double(num_faces(out)), off = std::abs(faces - target_faces);
    if(off < best)
    {
      best = off;
      quads = std::move(out);
    }
    if(!(target_faces > 0.) || off <= 0.1 * target_faces || net == 3 || faces == 0.)
      break;
    spacing *= std::sqrt(faces / target_faces);
    std::printf("  %.0f faces for about %.0f asked: the net again at h = %.4g\n", faces, target_faces, spacing);
  }
}

template <class Traits>
int run_harmonic(const Options& o, Traits traits)
{
  program::Stopwatch clock;
  const Mesh input = read_input(o);
  Mesh quads;
  harmonic_quads(input, edge_length(input, o), o.target_faces, o, traits, quads);
  return report_and_write(input, quads, o, clock);
}


// A face where the field turns by two quarter turns or more (two cones in one triangle: seen on
// remeshed inputs, the triceratops and bones) is no vertex of a quad mesh, and no vertex-based
// trivial connection has it, so the cones could not be separated. Its extra cones, of the same
// sign, go one by one to the nearest face (across edges) without a cone and without a boundary
// edge; the index sum, hence the trivial connection's existence, is kept. Returns the moves.
template <class FaceIndexMap>
std::size_t split_multiple_cones(const Mesh& mesh, FaceIndexMap index)
{
  std::size_t moved = 0;
  for(auto f : faces(mesh))
  {
    int k = get(index, f);
    if(std::abs(k) < 2)
      continue;
    const int sign = k > 0 ? 1 : -1;
    std::vector<Mesh::Face_index> queue{f};
    std::vector<bool> seen(num_faces(mesh), false);
    seen[f] = true;
    for(std::size_t next = 0; next < queue.size() && std::abs(k) >= 2; ++next)
      for(auto hd : halfedges_around_face(halfedge(queue[next], mesh), mesh))
      {
        const auto g = face(opposite(hd, mesh), mesh);
        if(g == Mesh::null_face() || seen[g])
          continue;
        seen[g] = true;
        queue.push_back(g);
        bool on_boundary = false;
        for(auto gh : halfedges_around_face(halfedge(g, mesh), mesh))
          on_boundary = on_boundary || CGAL::is_border(opposite(gh, mesh), mesh);
        if(get(index, g) == 0 && !on_boundary && std::abs(k) >= 2)
        {
          put(index, g, sign);
          k -= sign;
          ++moved;
        }
      }
    put(index, f, k);
  }
  return moved;
}

// The cross field on `surface` (with the given cones, or automatic) and its field-aligned quads at h,
// then at h - 5% and h + 5%, into `quads`; throws the last attempt's Remeshing_failure.
template <class Traits>
void field_aligned_quads(const Mesh& surface, const std::map<long, int>& given_cones, double h, const Options& o,
                         Traits traits, Mesh& quads)
{
  // the cross field
  program::Stopwatch field_clock;
  // one ordering and analysis for the systems of this mesh's pattern (the smoothest field's, the
  // trivial connection's, the stripes' and their stiffening rounds', in 2 x 2 blocks)
  program::solver_sharing_analysis(traits);
  Mesh mesh = surface; // with the field as a property
  auto field = mesh.add_property_map<Mesh::Vertex_index, program::Vector>("v:cross_field").first;
  auto index = mesh.add_property_map<Mesh::Face_index, int>("f:cone", 0).first;
  // a cross field (curvature-aligned or not) and its cones (`out_cones`: the count returned); on
  // a mesh with a boundary, along it (then a line of the quads), its cones kept apart by the flow
  const bool closed = CGAL::is_closed(mesh);
  auto sharp = mesh.add_property_map<Mesh::Edge_index, bool>("e:sharp", false).first;
  if(o.sharp_angle > 0.)
    std::printf("creases: %zu edges\n", program::detect_creases(mesh, o.sharp_angle, sharp));
  // with a boundary, the field follows its direction smoothed at 2h: what zigzags finer than the
  // quads is straightened, its corners are kept (the stripes read it at the same length; at h the
  // camel head's neck cut, whose teeth are about h long, keeps corners at most targets)
  const double smoothing = o.boundary_smoothing * h;
  if(!closed)
    std::printf("boundary: the field and the quads follow its direction smoothed at %.4g (%g h)\n", smoothing,
                o.boundary_smoothing);
  auto compute = [&mesh, closed, sharp, smoothing](bool aligned, auto out, auto out_cones, auto solver) {
    SD::smoothest_direction_field(
      mesh, out,
      P::symmetry_order(4, P::curvature_alignment_weight(
                             aligned ? 0.1 : 0.,
                             P::field_boundary_condition(
                               closed ? SD::Direction_field_boundary::free : SD::Direction_field_boundary::tangent,
                               P::boundary_smoothing_length(smoothing,
                               P::unit_length_iterations(30, CGAL::parameters::sparse_linear_solver(solver).edge_is_constrained_map(sharp)))))));
    return SD::direction_field_singularities(mesh, out, out_cones, P::symmetry_order(4));
  };
  // --field auto: the principal field is independent of the rest, made on a second thread with a
  // solver of its own while this one makes the smoothest field (the mesh is only read meanwhile)
  auto principal = mesh.add_property_map<Mesh::Vertex_index, program::Vector>("v:principal_cross_field").first;
  auto principal_index = mesh.add_property_map<Mesh::Face_index, int>("f:principal_cone", 0).first;
  std::future<std::size_t> principal_raw;
  if(given_cones.empty() && o.field == "auto")
    principal_raw = std::async(std::launch::async, [&, solver = program::independent_solver(traits)] {
      return compute(true, principal, principal_index, solver);
    });
  // with a boundary, the field of the cones (given or separated) follows it too
  SD::Trivial_connection tc(
    mesh, P::symmetry_order(4, P::field_boundary_condition(closed ? SD::Direction_field_boundary::free
                                                                  : SD::Direction_field_boundary::tangent,
                                                           P::boundary_smoothing_length(smoothing,
                                                           CGAL::parameters::sparse_linear_solver(traits)))));
  if(!given_cones.empty())
  {
    for(const auto& [f, k] : given_cones)
      tc.set_index(std::size_t(f), k);
    tc.solve();
    tc.field(field);
    std::printf("cross field: trivial connection with the %zu prescribed cones (largest adjustment %.3g rad)\n",
                given_cones.size(), tc.largest_adjustment());
  }
  else
  {
    // the cones closer than the cone distance removed or moved apart: the number of cones left
    // (the irregular vertices of the quads)
    auto separate = [&](bool aligned, std::size_t cones, auto out, auto cone_map) {
      std::printf("cross field: %s, %zu cones\n",
                  aligned ? "smoothest aligned with the principal curvature directions" : "smoothest", cones);
      if(o.cone_distance <= 0. || o.sharp_angle > 0.)
        return cones;
      const std::size_t split = split_multiple_cones(mesh, cone_map);
      if(split > 0)
        std::printf("  %zu cones moved out of faces holding two quarter turns or more into the nearest faces without one\n",
                    split);
      cones += split;
      tc.set_indices(cone_map);
      try
      {
        const SD::Singularity_separation s = tc.separate_singularities(o.cone_distance * h);
        std::printf("  cones at least %.3g apart (%.3g h): %zu pairs removed, %zu cones moved, %zu close pairs kept\n",
                    o.cone_distance * h, o.cone_distance, s.removed_pairs, s.moved, s.kept_pairs);
        const std::size_t moved = tc.move_singularities_from_wide_faces(); // of -1/4, see the manual
        if(moved > 0)
          std::printf("  %zu cones of -1/4 moved out of faces with an angle of 120 degrees or more\n", moved);
        if(split + s.removed_pairs + s.moved + moved > 0) // a split alone moves cones too
        {
          tc.field(out);
          std::printf("  the field is now the trivial connection with these %zu cones\n", cones - 2 * s.removed_pairs);
        }
        return cones - 2 * s.removed_pairs;
      }
      catch(const SD::Invalid_constraints& e)
      {
        std::printf("  cones kept where the field has them: no vertex-based trivial connection has them (%s)\n",
                    e.what());
        return cones - split; // the field is unchanged
      }
    };
    if(o.field != "auto")
      separate(o.field == "principal", compute(o.field == "principal", field, index, traits), field, index);
    else
    {
      // both; the one with fewer cones (the smoothest on a tie): the principal directions give
      // none on a torus or a knotted tube, where the smoothest field has dozens, and many more
      // than it on a scan (bunny_60k: 182 against 36)
      const std::size_t smoothest_raw = compute(false, field, index, traits);
      std::optional<std::size_t> principal_count;
      try
      {
        principal_count = principal_raw.get();
      }
      catch(const SD::Invalid_parameter& e) // no principal directions (a planar surface)
      {
        std::printf("cross field: no principal one (%s)\n", e.what());
      }
      const std::size_t smoothest_cones = separate(false, smoothest_raw, field, index);
      // the separation removes at most 38% of a field's cones on the shared meshes (blobby_3cc's
      // principal field, 52 -> 32; the kitten's 102 -> 76): a principal field with twice the
      // smoothest one's cones or more is not separated, it would not win (the kitten: 80 ms less);
      // not with few cones, where close pairs can be most of them
      const bool hopeless = principal_count && smoothest_cones >= 16 && *principal_count >= 2 * smoothest_cones;
      if(hopeless)
        std::printf("cross field: smoothest aligned with the principal curvature directions, %zu cones (not "
                    "separated: twice the smoothest field's or more)\n", *principal_count);
      const std::size_t principal_cones =
        !principal_count ? smoothest_cones
        : hopeless       ? *principal_count
                         : separate(true, *principal_count, principal, principal_index);
      if(principal_cones < smoothest_cones)
        for(auto v : vertices(mesh))
          put(field, v, get(principal, v));
      std::printf("  auto: the %s field (%zu cones against %zu)\n",
                  principal_cones < smoothest_cones ? "principal" : "smoothest",
                  (std::min)(smoothest_cones, principal_cones), (std::max)(smoothest_cones, principal_cones));
    }
  }

  const double field_seconds = field_clock.lap() / 1000.;
  const double scales[] = {1., 0.95, 1.05};
  for(std::size_t attempt = 0;; ++attempt)
  {
    const double spacing = scales[attempt] * h;
    std::printf("remeshing at h = %.4g (stripes, stiffening where the map folds, extraction)...\n", spacing);
    std::fflush(stdout); // progress: the stiffening rounds can take seconds
    try
    {
      const auto np =
        P::target_edge_length(spacing, P::edge_length_ratio(o.edge_length_ratio,
                              P::stiffening_rounds(o.stiffening_rounds,
                                                   P::feature_snapping(o.feature_snapping,
                                                                       P::boundary_smoothing_length(smoothing,
                                                                       CGAL::parameters::sparse_linear_solver(traits))))))
          .visitor([](const SD::Field_aligned_quads_round& round) {
            // progress: on a large mesh a round takes seconds
            std::printf("  %s %zu: folds in %zu faces; %s (%.2f s)\n", round.round == 0 ? "first map," : "round",
                        round.round, round.folded_faces,
                        round.problem.empty() ? "its lines are the quad mesh" : round.problem.c_str(), round.seconds);
            std::fflush(stdout);
            return true;
          });
      // the creases of --sharp-angle (without it, the snapping's own: 30 degrees)
      const SD::Field_aligned_quad_remeshing_result r =
        o.sharp_angle > 0. ? SD::field_aligned_quad_remeshing(mesh, field, quads, np.edge_is_constrained_map(sharp))
                           : SD::field_aligned_quad_remeshing(mesh, field, quads, np);
      std::printf("field-aligned quads (h = %.4g, lines %.4g apart): %zu cones, %zu faces folded in the first map, "
                  "%zu rounds of stiffening, %zu folded at the end\n",
                  spacing, r.edge_length, r.cones, r.initially_folded, r.stiffening_rounds, r.folded_faces);
      if(o.edge_length_ratio > 1.)
        std::printf("curvature-adapted sizing: local spacing from %.4g to %.4g\n", r.smallest_edge_length,
                    r.largest_edge_length);
      if(o.sharp_angle > 0. && o.feature_snapping)
        std::printf("creases: %zu vertices of the quads moved onto them, %zu of the %zu cones onto their corners\n",
                    r.crease_vertices, r.cones_on_corners, r.cones);
      if(o.feature_snapping)
        print_snapping(r);
      std::printf("times: field %.3f s, stripes %.3f s, extraction %.3f s (snapping %.3f s)\n", field_seconds,
                  r.stripes_seconds, r.extraction_seconds, r.snapping_seconds);
      break;
    }
    catch(const SD::Remeshing_failure& e)
    {
      if(attempt + 1 == std::size(scales))
        throw;
      std::printf("  failed: %s\n", e.what());
    }
  }
}

// A copy of `input` remeshed isotropically at edge length h (CGAL's isotropic_remeshing, its
// points on the input's surface, the creases of --sharp-angle kept): the triangles of a
// decimated or badly shaped input can leave the stripes' map folded where these do not
// (measured on four meshes decimated to 2k, 4k and 6k faces, at 500 to 3000 quads: 13 of 48 runs
// succeed on the input's triangles, 44 with this).
Mesh isotropically_remeshed(const Mesh& input, double h, double sharp_angle)
{
  Mesh remeshed = input;
  // the creases of --sharp-angle kept (constrained edges: the remeshing keeps its vertices on them)
  auto sharp = remeshed.add_property_map<Mesh::Edge_index, bool>("e:remeshing_sharp", false).first;
  if(sharp_angle > 0.)
    program::detect_creases(remeshed, sharp_angle, sharp);
  CGAL::Polygon_mesh_processing::isotropic_remeshing(
    faces(remeshed), h, remeshed, CGAL::parameters::number_of_iterations(5).edge_is_constrained_map(sharp));
  remeshed.remove_property_map(sharp);
  remeshed.collect_garbage();
  const long before = euler_characteristic(input), after = euler_characteristic(remeshed);
  if(after != before || CGAL::is_closed(remeshed) != CGAL::is_closed(input))
    throw std::runtime_error("the isotropic remeshing of the input changed its topology (Euler characteristic " +
                             std::to_string(before) + " -> " + std::to_string(after) + "); nothing written");
  return remeshed;
}

// The cones of --singularity carried to `to`: each into the face of `to` whose centroid is
// nearest the centroid of its face of `from`.
std::map<long, int> carried_cones(const Mesh& from, const Mesh& to, const std::map<long, int>& cones)
{
  auto centroid = [](const Mesh& m, Mesh::Face_index f) {
    Eigen::Vector3d c = Eigen::Vector3d::Zero();
    for(auto v : vertices_around_face(halfedge(f, m), m))
      c += eigen(m.point(v)) / 3.;
    return c;
  };
  std::vector<Eigen::Vector3d> centroids;
  if(!cones.empty())
    for(auto g : faces(to))
      centroids.push_back(centroid(to, g));
  std::map<long, int> carried;
  for(const auto& [f, k] : cones)
  {
    const Eigen::Vector3d c = centroid(from, Mesh::Face_index(Mesh::size_type(f)));
    long nearest = -1;
    double best = std::numeric_limits<double>::infinity();
    for(std::size_t g = 0; g < centroids.size(); ++g)
      if(const double d = (centroids[g] - c).squaredNorm(); d < best)
      {
        best = d;
        nearest = long(g);
      }
    if(!carried.emplace(nearest, k).second)
      throw std::runtime_error("two of the given cones fall into face " + std::to_string(nearest) +
                               " of the remeshed input; nothing written");
    std::printf("  the cone of face %ld is in face %ld of the remeshed input\n", f, nearest);
  }
  return carried;
}

// The field method's failure after its repairs: no quad mesh of the field (the message says why)
struct No_field_quads : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

// The field-aligned quads of `surface` (the input or one of its connected components) at h: on its
// own triangles (at h and h +- 5%), then, unless --no-input-remeshing, on the surface remeshed
// isotropically at h; throws the last attempt's failure.
template <class Traits>
void quads_with_repair(const Mesh& input, const std::map<long, int>& cones, double h, const Options& o, Traits traits,
                       Mesh& quads)
{
  try
  {
    field_aligned_quads(input, cones, h, o, traits, quads);
  }
  catch(const SD::Remeshing_failure& e)
  {
    if(!o.input_remeshing)
      throw;
    std::printf("  failed: %s\n", e.what());
    std::printf("no quads on the input's triangles at h and h +- 5%%: the input remeshed isotropically at edge length "
                "%.4g, and the field and the quads made again on it (--no-input-remeshing: fail instead)\n",
                h);
    std::fflush(stdout);
    const Mesh remeshed = isotropically_remeshed(input, h, o.sharp_angle);
    std::printf("  remeshed input: %zu vertices, %zu faces\n", std::size_t(num_vertices(remeshed)),
                std::size_t(num_faces(remeshed)));
    try
    {
      field_aligned_quads(remeshed, carried_cones(input, remeshed, cones), h, o, traits, quads);
    }
    catch(const SD::Remeshing_failure& again)
    {
      throw No_field_quads(std::string("on the remeshed input too: ") + again.what());
    }
    // (the same kinds, so that auto falls back on failures only, not on bad input or internal errors)
    catch(const std::runtime_error& again)
    {
      throw std::runtime_error(std::string("on the remeshed input too: ") + again.what());
    }
    catch(const std::invalid_argument& again)
    {
      throw std::invalid_argument(std::string("on the remeshed input too: ") + again.what());
    }
    catch(const std::logic_error& again)
    {
      throw std::logic_error(std::string("on the remeshed input too: ") + again.what());
    }
  }
}

// The connected components of `input`, each a mesh of its own.
std::vector<Mesh> connected_components(Mesh input)
{
  auto component = input.add_property_map<Mesh::Face_index, std::size_t>("f:quad_remesh_component", 0).first;
  const std::size_t count = CGAL::Polygon_mesh_processing::connected_components(input, component);
  std::vector<Mesh> parts(count);
  if(count > 1)
    for(std::size_t c = 0; c < count; ++c)
      CGAL::copy_face_graph(CGAL::Face_filtered_graph<Mesh>(input, c, component), parts[c]);
  return parts;
}

// Several connected components: each is remeshed on its own, with its own field and cones, so that
// one component's failure at h does not fail the others (bones: 26 components, 21 give quads at
// the h of 3000 quads, the 5 smallest only at a finer one). A component that gives no quads at h
// (with its h +- 5% and its remeshed triangles) is tried at h / 1.25, h / 1.25^2, ... while that adds
// at most 5% to the whole mesh's quads at h, so the face count stays near the target. With --method
// auto, a component that gives no field quads then gets the harmonic method's at h (about its share
// by area of target_faces, when that is not 0). Returns the components remeshed so (numbered from 1).
template <class Traits>
std::vector<std::size_t> quads_by_component(const std::vector<Mesh>& parts, double h, double target_faces,
                                            const Options& o, Traits traits, Mesh& quads)
{
  std::vector<std::size_t> harmonic;
  double total_area = 0.;
  for(const Mesh& part : parts)
    total_area += area(part);
  const double total_quads = total_area / (h * h);
  std::printf("%zu connected components, each remeshed on its own (its own field and cones)\n", parts.size());
  for(std::size_t c = 0; c < parts.size(); ++c)
  {
    const double a = area(parts[c]);
    std::printf("component %zu of %zu: %zu faces, about %.0f quads at h\n", c + 1, parts.size(),
                std::size_t(num_faces(parts[c])), a / (h * h));
    std::fflush(stdout);
    Mesh part_quads;
    for(double spacing = h;;)
    {
      try
      {
        quads_with_repair(parts[c], {}, spacing, o, traits, part_quads);
        break;
      }
      catch(const std::exception& e)
      {
        const double finer = spacing / 1.25, added = a / (finer * finer) - a / (h * h);
        if(added > 0.05 * total_quads && o.method == "auto" && dynamic_cast<const std::runtime_error*>(&e))
        {
          std::printf("component %zu: no field quads (%s); the harmonic method's quads at h = %.4g instead (the field "
                      "method's options do not apply to them)\n", c + 1, e.what(), h);
          part_quads = Mesh();
          try
          {
            harmonic_quads(parts[c], h, target_faces * a / total_area, o, traits, part_quads);
          }
          catch(const std::runtime_error& again)
          {
            throw std::runtime_error("component " + std::to_string(c + 1) + " of " + std::to_string(parts.size()) +
                                     ": no quads from the field method (" + e.what() + ") nor from the harmonic method (" +
                                     again.what() + ")");
          }
          harmonic.push_back(c + 1);
          break;
        }
        if(added > 0.05 * total_quads)
        {
          const std::string what = "component " + std::to_string(c + 1) + " of " + std::to_string(parts.size()) +
                                   " (" + std::to_string(num_faces(parts[c])) + " faces) gives no quads: " + e.what();
          if(dynamic_cast<const SD::Remeshing_failure*>(&e) || dynamic_cast<const No_field_quads*>(&e))
            throw No_field_quads(what);
          throw std::runtime_error(what);
        }
        std::printf("  component %zu: no quads at h = %.4g (%s); tried at %.4g (%.2f h), which adds about %.0f quads "
                    "(at most 5%% of the mesh's)\n",
                    c + 1, spacing, e.what(), finer, finer / h, added);
        spacing = finer;
      }
    }
    CGAL::copy_face_graph(part_quads, quads);
  }
  return harmonic;
}

template <class Traits>
int run_field(const Options& o, Traits traits)
{
  program::Stopwatch clock;
  const Mesh input = read_input(o);
  double h = edge_length(input, o);
  if(!(h > 0.))
  {
    Options with_default = o;
    with_default.target_faces = 3000.;
    h = edge_length(input, with_default);
  }
  for(const auto& [f, k] : o.cones)
  {
    if(std::size_t(f) >= num_faces(input))
      throw program::Usage_error("--singularity " + std::to_string(f) + ":" + std::to_string(k) + "/4: the mesh has " +
                                 std::to_string(num_faces(input)) + " faces");
    // the boundary is a line of the quads: a cone next to it would be one of its vertices
    for(auto hd : halfedges_around_face(halfedge(Mesh::Face_index(Mesh::size_type(f)), input), input))
      if(CGAL::is_border(opposite(hd, input), input))
        throw program::Usage_error("--singularity " + std::to_string(f) + ":" + std::to_string(k) +
                                   "/4: the face has an edge on the boundary, which is a line of the quads; choose a "
                                   "face inside");
  }

  // the faces asked for, which a harmonic fall-back (auto) is calibrated to: --target-faces, or the
  // default's 3000 (not with --edge-length)
  const double target_faces = o.target_faces > 0. ? o.target_faces : o.edge_length > 0. ? 0. : 3000.;
  Mesh quads;
  // with given cones, one field over all the components (the cones are the whole mesh's)
  const std::vector<Mesh> parts = o.cones.empty() ? connected_components(input) : std::vector<Mesh>{};
  std::vector<std::size_t> harmonic; // the components (from 1) remeshed by the harmonic method (auto)
  try
  {
    if(parts.size() > 1)
      harmonic = quads_by_component(parts, h, target_faces, o, traits, quads);
    else
      quads_with_repair(input, o.cones, h, o, traits, quads);
  }
  catch(const std::runtime_error& e)
  {
    if(o.method == "auto" && parts.size() <= 1) // (several components fall back one by one)
    {
      std::printf("no field quads (%s); the harmonic method's quads at h = %.4g instead (the field method's options do "
                  "not apply to them)\n", e.what(), h);
      quads = Mesh();
      try
      {
        harmonic_quads(input, h, target_faces, o, traits, quads);
      }
      catch(const std::runtime_error& again)
      {
        throw std::runtime_error(std::string("no quads from the field method (") + e.what() +
                                 ") nor from the harmonic method (" + again.what() + ")");
      }
      harmonic.push_back(1);
    }
    else
    {
      // no quads after every repair (h +- 5%, the remeshed input, finer components): what still works
      if(!dynamic_cast<const SD::Remeshing_failure*>(&e) && !dynamic_cast<const No_field_quads*>(&e))
        throw;
      throw No_field_quads(std::string(e.what()) + "; --method harmonic (or auto, the default) takes every manifold "
                           "mesh, with irregular vertices of its own");
    }
  }
  if(o.method == "auto")
  {
    const std::size_t components = (std::max)(parts.size(), std::size_t(1));
    std::string which;
    for(std::size_t c : harmonic)
      which += (which.empty() ? " " : ", ") + std::to_string(c);
    if(harmonic.empty())
      std::printf("method: field (auto: the field gave quads%s)\n", components > 1 ? " on every component" : "");
    else if(components == 1)
      std::printf("method: harmonic (auto: the field gave no quads)\n");
    else
      std::printf("method: field on %zu of %zu components, harmonic on component%s%s (auto: the field gave no quads "
                  "there)\n",
                  components - harmonic.size(), components, harmonic.size() > 1 ? "s" : "", which.c_str());
  }
  return report_and_write(input, quads, o, clock);
}

} // namespace

int main(int argc, char** argv)
{
  return program::run_main("quad_remesh", usage, argc, [&] {
    const Options o = parse(argc, argv);
    return program::with_solver(o.solver,
                                [&](auto traits) { return o.method == "harmonic" ? run_harmonic(o, traits) : run_field(o, traits); });
  });
}
