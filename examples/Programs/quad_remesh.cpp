// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// quad_remesh: quad remeshing from the isolines and gradient lines of a harmonic
// function (Dong, Kircher & Garland 2005; Nagano & Imai). Run without arguments for the usage.

#include "common/option_parser.h"
#include "common/program_support.h"

#include <CGAL/Surface_design/Harmonic_quad_remesher.h>
#include <CGAL/Surface_design/quad_mesh_quality.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <cmath>
#include <cstdio>
#include <iostream>
#include <string>
#include <vector>

namespace SD = CGAL::Surface_design;
namespace P = CGAL::Surface_design::parameters;
using program::Mesh;
using program::Point;

namespace {

const char* usage =
  "usage: quad_remesh INPUT --output OUT.off [options]\n"
  "  Remeshes a manifold triangle mesh into a quad mesh: the net of the isolines and gradient\n"
  "  lines of a harmonic function (Dong, Kircher & Garland 2005), its odd faces paired into quads.\n"
  "  The result has the input's topology (Euler characteristic, boundary loops, components): when\n"
  "  the net comes out otherwise, the program falls back (without spectacles, the intrinsic\n"
  "  Delaunay Laplacian, h / 2 near the saddles, h / sqrt 2, h / 2) and, if none works, fails\n"
  "  (exit 1, no file).\n"
  "options:\n"
  "  --min V               vertex V is a minimum of the function (value 0); repeatable\n"
  "  --max V               vertex V is a maximum (value 1); repeatable. Without --min/--max:\n"
  "                        a minimum and a maximum at the ends of a geodesic diameter of every\n"
  "                        component, and a maximum at every tip of the shape\n"
  "  --no-protrusions      default constraints without the maxima at the tips\n"
  "  --edge-length H       target edge length (default: sqrt(area / 3000), about 3000 faces)\n"
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
  "  --no-feature-snapping keep the net's positions (default: interior input vertices and points\n"
  "                        along its creases farther than h / 4 from the result, a pit, a spike or a\n"
  "                        crease narrower than h, pull the nearest vertex onto them)\n"
  "  --solver S            sparse solver: default (simplicial LDLT below 20k\n"
  "                        unknowns, supernodal Cholesky above), ldlt, supernodal, cholmod\n"
  "  --output OUT          the quad mesh (.off, .obj or .ply); required\n"
  "  --picture OUT.png     the new mesh's edges over the input; faces other than quads in orange\n"
  "  --up +Y|+Z|...        up direction in the picture (default +Y)\n";

struct Options
{
  std::string input, output, picture, up = "+Y", solver = "default";
  std::vector<long> minima, maxima;
  double edge_length = 0., curvature_adaptation = 0.;
  bool protrusions = true, intrinsic_delaunay = false, quad_poles = true, spectacles = true,
       all_quads = true, feature_snapping = true;
};

Options parse(int argc, char** argv)
{
  Options o;
  auto vertex = [](std::vector<long>& into, const char* name) {
    return [&into, name](const std::string& v) { into.push_back(program::parse_integer(v, name, 0, 1L << 40)); };
  };
  program::Option_parser p;
  p.input(o.input)
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

template <class Traits>
int run(const Options& o, Traits traits)
{
  program::Stopwatch clock;
  const Mesh input = program::read_mesh(o.input);
  const long chi = long(num_vertices(input)) - long(num_edges(input)) + long(num_faces(input));
  std::cout << "read " << o.input << ": " << num_vertices(input) << " vertices, " << num_faces(input)
            << " faces, Euler characteristic " << chi << '\n';
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

  Mesh quads;
  const auto options = P::quad_poles(
    o.quad_poles,
    P::spectacles(o.spectacles,
                  P::all_quads(o.all_quads, P::curvature_adaptation(o.curvature_adaptation,
                                                                    P::feature_snapping(o.feature_snapping)))));
  const SD::Harmonic_quad_remeshing_result r = o.edge_length > 0.
                                                 ? remesher.remesh(quads, P::target_edge_length(o.edge_length, options))
                                                 : remesher.remesh(quads, options);
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
    std::printf("feature snapping: %zu of %zu input vertices and crease points farther than h / 4 from the result "
                "pulled a vertex onto them (the farthest was %.3g away)\n",
                r.snapped_vertices, r.far_input_vertices, r.largest_input_distance);
  std::printf("times: harmonic %.3f s, spectacles (re-solve) %.3f s, curves %.3f s, meshing %.3f s (quads only %.3f s, "
              "snapping %.3f s)\n",
              r.harmonic_seconds, r.spectacles_seconds, r.curves_seconds, r.meshing_seconds, r.all_quads_seconds,
              r.snapping_seconds);

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

  if(!q.valid || !q.same_topology) // (the remesher checks this: a second look before writing)
    throw std::runtime_error("the quad mesh is not a valid mesh with the input's topology (a bug: please report it "
                             "with the input mesh); nothing written");
  program::Output_files outputs;
  if(!CGAL::IO::write_polygon_mesh(outputs.stage(o.output), quads, CGAL::parameters::stream_precision(17)))
    throw std::runtime_error("cannot write " + o.output);
  if(!o.picture.empty())
    write_picture(input, quads, o, outputs);
  outputs.commit();
  std::printf("total %.3f s\n", clock.lap() / 1000.);
  return 0;
}

} // namespace

int main(int argc, char** argv)
{
  return program::run_main("quad_remesh", usage, argc, [&] {
    const Options o = parse(argc, argv);
    return program::with_solver(o.solver, [&](auto traits) { return run(o, traits); });
  });
}
