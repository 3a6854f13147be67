// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// flatten: cuts a (piecewise-)developable design into disks, flattens them by Boundary First
// Flattening and lays them out as a cutting pattern (Stein, Grinspun & Crane 2018, sec. 4.4).
// Run without arguments for the usage.

#include "common/option_parser.h"
#include "common/program_support.h"

#include <CGAL/Surface_design/Boundary_first_flattener.h>
#include <CGAL/Surface_design/developable_cutting.h>
#include <CGAL/Surface_design/fabrication_pattern.h>
#include <CGAL/Surface_design/flattening_distortion.h>
#include <CGAL/Surface_design/overlap_splitting_cut.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <string>
#include <vector>

namespace SD = CGAL::Surface_design;
namespace P = CGAL::Surface_design::parameters;
using program::Mesh;
using program::Point;

namespace {

const char* usage =
  "usage: flatten INPUT --output PIECES.obj --pattern PATTERN.svg [options]\n"
  "  Cuts a triangle mesh (normally a design made by `developable`) into pieces that are\n"
  "  topological disks, through every vertex whose star is far from developable (covariance\n"
  "  lambda > epsilon), along short paths that follow the rulings; flattens every piece by\n"
  "  Boundary First Flattening (boundary lengths kept) and lays the pieces out on sheets.\n"
  "options:\n"
  "  --epsilon E           cut tolerance on lambda (default 0.001; the paper uses .01 to .001:\n"
  "                        smaller cuts more and distorts less)\n"
  "  --distortion-bound B  also cut through the curvature left under epsilon until the flattening\n"
  "                        distorts no area by more than B (|log area scale|; default 10 epsilon;\n"
  "                        0: cut only through the vertices above epsilon)\n"
  "  --alignment W         weight of the alignment of cuts with the rulings (default 1; 0: shortest)\n"
  "  --cut-cost C          ruling (default: |e| (1 + W misalignment), cuts along the rulings) or\n"
  "                        paper (|e| times the alignment, sec. 4.4 literally: cuts across them)\n"
  "  --glue-cracks DEG     glue the cracks of the cut: its dangling branches whose two sides open by\n"
  "                        at most DEG degrees in the flattening (sec. 4.4, Fig. 19), as long as the\n"
  "                        distortion bound holds, and flatten again (default: none glued)\n"
  "  --no-cut              flatten the input as it is: every component must be a disk\n"
  "  --no-split            keep pieces whose flattening overlaps itself (default: split them in\n"
  "                        two between the overlapping parts and flatten again, until none does)\n"
  "  --sheet WxH           sheet size in mm (default 210x297, A4)\n"
  "  --scale S             mm on the sheet per model unit (default: the largest round scale at\n"
  "                        which every piece fits on a sheet)\n"
  "  --margin M            sheet margin in mm (default 10)\n"
  "  --fold-angle DEG      draw edges bent by more than this as fold lines (default 5; 180: none)\n"
  "  --glue-tabs W         glue tabs W mm wide along one side of every seam, numbered like it\n"
  "                        (default 0: none; narrowed or left out where they would overlap)\n"
  "  --solver S            sparse solver: default (simplicial LDLT below 20k\n"
  "                        unknowns, supernodal Cholesky above), ldlt, supernodal, cholmod\n"
  "  --output PIECES.obj   the cut mesh: v = 3-D positions of the input's vertices, vt = the laid-out\n"
  "                        2-D positions (model units) of every corner, f v/vt; required\n"
  "  --pattern PATTERN.svg the cutting pattern in mm: cut lines, fold lines, seam numbers matching\n"
  "                        across pieces, a scale bar per sheet; PATTERN.pdf: the same, one page per\n"
  "                        sheet, to print at 100%; required\n"
  "  --picture OUT.png     the design with its cuts (left) and the pattern coloured by the log of\n"
  "                        the area scale, blue -0.05 .. white 0 .. red +0.05 (right)\n"
  "  --up +Y|+Z|...        up direction of the design in the picture (default +Y)\n";

struct Options
{
  std::string input, output, pattern, picture, up = "+Y", solver = "default";
  double epsilon = 1e-3, alignment = 1., margin = 10., fold_angle = 5., scale = 0.;
  double distortion_bound = -1.; // -1: 10 epsilon
  double glue_tabs = 0.;
  double crack_opening = -1.; // degrees; < 0: no gluing
  SD::Developable_cut_cost cut_cost = SD::Developable_cut_cost::ruling_alignment;
  double sheet_width = 210., sheet_height = 297.;
  bool cut = true, split = true;
};

Options parse(int argc, char** argv)
{
  Options o;
  program::Option_parser p;
  p.input(o.input)
    .value("--epsilon", [&](const std::string& v) { o.epsilon = program::parse_double(v, "--epsilon", 0., 10.); })
    .value("--distortion-bound",
           [&](const std::string& v) { o.distortion_bound = program::parse_double(v, "--distortion-bound", 0., 10.); })
    .value("--cut-cost",
           [&](const std::string& v) {
             o.cut_cost = program::parse_choice(v, "--cut-cost", {"ruling", "paper"}) == "paper"
                            ? SD::Developable_cut_cost::paper
                            : SD::Developable_cut_cost::ruling_alignment;
           })
    .value("--alignment", [&](const std::string& v) { o.alignment = program::parse_double(v, "--alignment", 0., 1e3); })
    .value("--glue-cracks",
           [&](const std::string& v) { o.crack_opening = program::parse_double(v, "--glue-cracks", 0., 90.); })
    .flag("--no-cut", [&] { o.cut = false; })
    .flag("--no-split", [&] { o.split = false; })
    .value("--sheet",
           [&](const std::string& v) {
             const std::size_t x = v.find('x');
             if(x == std::string::npos)
               throw program::Usage_error("--sheet takes WIDTHxHEIGHT in mm, e.g. 210x297 (got \"" + v + "\")");
             o.sheet_width = program::parse_double(v.substr(0, x), "--sheet (width)", 10., 1e5);
             o.sheet_height = program::parse_double(v.substr(x + 1), "--sheet (height)", 10., 1e5);
           })
    .value("--scale", [&](const std::string& v) { o.scale = program::parse_double(v, "--scale", 1e-9, 1e9); })
    .value("--margin", [&](const std::string& v) { o.margin = program::parse_double(v, "--margin", 0., 1e4); })
    .value("--glue-tabs", [&](const std::string& v) { o.glue_tabs = program::parse_double(v, "--glue-tabs", 0., 50.); })
    .value("--fold-angle", [&](const std::string& v) { o.fold_angle = program::parse_double(v, "--fold-angle", 0., 180.); })
    .solver(o.solver)
    .output("--output", o.output, {".obj"})
    .output("--pattern", o.pattern, {".svg", ".pdf"})
    .picture(o.picture, o.up)
    .parse(argc, argv);
  if(o.output.empty())
    throw program::Usage_error("--output PIECES.obj is required");
  if(o.pattern.empty())
    throw program::Usage_error("--pattern PATTERN.svg (or .pdf) is required");
  if(!o.cut && (p.given("--epsilon") || p.given("--alignment") || p.given("--no-split") || p.given("--distortion-bound") ||
                 p.given("--cut-cost") || p.given("--glue-cracks")))
    throw program::Usage_error("--epsilon, --distortion-bound, --alignment, --cut-cost, --glue-cracks and --no-split "
                               "apply to the cut, not to --no-cut");
  if(p.given("--alignment") && o.cut_cost == SD::Developable_cut_cost::paper)
    throw program::Usage_error("--alignment weighs the ruling cost; --cut-cost paper has no weight");
  if(o.distortion_bound < 0.)
    o.distortion_bound = 10. * o.epsilon;
  if(!(2. * o.margin < std::min(o.sheet_width, o.sheet_height)))
    throw program::Usage_error("--margin " + program::text(o.margin) + " leaves no room on a " +
                               program::text(o.sheet_width) + " x " + program::text(o.sheet_height) + " mm sheet");
  program::check_paths_and_picture({{"INPUT", o.input}, {"--output", o.output}, {"--pattern", o.pattern}}, o.picture,
                                   p.given("--up"));
  return o;
}

Eigen::Vector3d eigen(const Point& p) { return Eigen::Vector3d(p.x(), p.y(), p.z()); }

using Uv = CGAL::Simple_cartesian<double>::Point_2;

void write_obj(const std::string& path, const Mesh& input, const Mesh& pieces,
               const std::vector<Mesh::Vertex_index>& original, const Mesh::Property_map<Mesh::Vertex_index, Uv>& uv)
{
  std::ofstream out(path);
  if(!out)
    throw std::runtime_error("cannot write " + path);
  out << "# cut and flattened by CGAL Surface Design `flatten`: v = 3-D positions, vt = 2-D positions\n"
      << "# (model units, pieces laid out on sheets), f v/vt\n"
      << std::setprecision(17);
  for(auto v : vertices(input))
    out << "v " << input.point(v).x() << ' ' << input.point(v).y() << ' ' << input.point(v).z() << '\n';
  for(auto v : vertices(pieces))
    out << "vt " << uv[v].x() << ' ' << uv[v].y() << '\n';
  for(auto f : faces(pieces))
  {
    out << 'f';
    for(auto v : vertices_around_face(halfedge(f, pieces), pieces))
      out << ' ' << std::size_t(original[std::size_t(v)]) + 1 << '/' << std::size_t(v) + 1;
    out << '\n';
  }
  out.flush();
  if(!out)
    throw std::runtime_error("writing " + path + " failed (disk full?)");
}

// The design (flat-shaded grey, cut edges as dark red ribbons) and, to its right in the plane
// z = min z, the laid-out pattern coloured by the log of the area scale.
void write_picture(const Mesh& input, const std::vector<bool>& cut_edge, const Mesh& pieces,
                   const Mesh::Property_map<Mesh::Vertex_index, Uv>& uv, const std::vector<double>& face_log_area,
                   const Options& o, program::Output_files& outputs)
{
  program::Vtk_surface vtk;
  vtk.scalar_name = "shade";
  // the design, turned so that `up` is +Y and the view is along -Z
  Eigen::Matrix3d turn = Eigen::Matrix3d::Identity();
  const int axis = o.up[1] - 'X';
  const double sign = o.up[0] == '-' ? -1. : 1.;
  if(axis != 1)
  {
    Eigen::Vector3d from = Eigen::Vector3d::Zero();
    from[axis] = sign;
    turn = Eigen::Quaterniond::FromTwoVectors(from, Eigen::Vector3d::UnitY()).toRotationMatrix();
  }
  else if(sign < 0.)
    turn = Eigen::AngleAxisd(CGAL_PI, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  std::vector<Eigen::Vector3d> x(num_vertices(input));
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(1e300), hi = -lo;
  for(auto v : vertices(input))
  {
    x[std::size_t(v)] = turn * eigen(input.point(v));
    lo = lo.cwiseMin(x[std::size_t(v)]);
    hi = hi.cwiseMax(x[std::size_t(v)]);
  }
  double mean_edge = 0.;
  for(auto e : edges(input))
    mean_edge += (x[std::size_t(source(halfedge(e, input), input))] - x[std::size_t(target(halfedge(e, input), input))]).norm();
  mean_edge /= double(num_edges(input));
  const Eigen::Vector3d light = Eigen::Vector3d(0.3, 0.6, 0.75).normalized();
  std::vector<Eigen::Vector3d> normal(num_faces(input));
  for(auto f : faces(input))
  {
    std::vector<Eigen::Vector3d> p;
    for(auto v : vertices_around_face(halfedge(f, input), input))
      p.push_back(x[std::size_t(v)]);
    const Eigen::Vector3d n = (p[1] - p[0]).cross(p[2] - p[0]).normalized();
    normal[std::size_t(f)] = n;
    const double shade = 2. + 0.5 * (1. + n.dot(light));
    vtk.triangles.push_back({vtk.add(p[0], n, shade), vtk.add(p[1], n, shade), vtk.add(p[2], n, shade)});
  }
  const double width = 0.12 * mean_edge;
  for(auto e : edges(input))
  {
    if(!cut_edge[std::size_t(e)])
      continue;
    const auto h = halfedge(e, input);
    Eigen::Vector3d n = normal[std::size_t(face(h, input))] + normal[std::size_t(face(opposite(h, input), input))];
    n.normalize();
    const Eigen::Vector3d a = x[std::size_t(source(h, input))], b = x[std::size_t(target(h, input))];
    const Eigen::Vector3d side = n.cross(b - a).normalized() * width, lift = n * (0.03 * mean_edge);
    const std::size_t i0 = vtk.add(a - side + lift, n, 1.5), i1 = vtk.add(b - side + lift, n, 1.5),
                      i2 = vtk.add(b + side + lift, n, 1.5), i3 = vtk.add(a + side + lift, n, 1.5);
    vtk.triangles.push_back({i0, i1, i2});
    vtk.triangles.push_back({i0, i2, i3});
  }
  // the pattern, scaled to the height of the design
  Eigen::Vector2d plo(1e300, 1e300), phi(-1e300, -1e300);
  for(auto v : vertices(pieces))
  {
    plo = plo.cwiseMin(Eigen::Vector2d(uv[v].x(), uv[v].y()));
    phi = phi.cwiseMax(Eigen::Vector2d(uv[v].x(), uv[v].y()));
  }
  const double k = (hi.y() - lo.y()) / std::max(phi.y() - plo.y(), 1e-300);
  const Eigen::Vector3d offset(hi.x() + 0.15 * (hi.x() - lo.x()) + 0.05 * (hi.y() - lo.y()), lo.y(), lo.z());
  const Eigen::Vector3d up = Eigen::Vector3d::UnitZ();
  for(auto f : faces(pieces))
  {
    const double value = 0.5 + 0.5 * std::max(-1., std::min(1., face_log_area[std::size_t(f)] / 0.05));
    std::array<std::size_t, 3> t;
    std::size_t i = 0;
    for(auto v : vertices_around_face(halfedge(f, pieces), pieces))
      t[i++] = vtk.add(offset + k * Eigen::Vector3d(uv[v].x() - plo.x(), uv[v].y() - plo.y(), 0.), up, value);
    vtk.triangles.push_back(t);
  }
  const std::string vtk_path = outputs.stage(o.picture + ".vtk");
  vtk.write(vtk_path);
  // 0..1 distortion blue - white - red, 1.5 cut ribbons dark red, 2..3 grey shading
  const std::string colormap =
    "0,0.15,0.3,0.75,0.1667,1,1,1,0.3333,0.75,0.1,0.1,0.34,0.45,0.05,0.05,0.6,0.45,0.05,0.05,0.6667,0.5,0.52,0.56,1,0.97,0.97,0.96";
  program::render_png(vtk_path, outputs.stage(o.picture), "shade", 0., 3., "+Y", colormap);
}

template <class Traits>
int run(const Options& o, Traits traits)
{
  program::Stopwatch clock, total;
  const Mesh input = program::read_mesh(o.input);
  std::cout << "read " << o.input << ": " << num_vertices(input) << " vertices, " << num_faces(input) << " faces\n";

  Mesh pieces;
  std::vector<Mesh::Vertex_index> original;
  std::vector<bool> cut_edge(num_edges(input), false);
  if(o.cut)
  {
    std::vector<Mesh::Edge_index> cut;
    const SD::Developable_cut_result r = SD::compute_developable_cut(
      input, std::back_inserter(cut),
      P::cut_tolerance(o.epsilon, P::ruling_alignment_weight(o.alignment, P::distortion_bound(o.distortion_bound, P::cut_edge_cost(o.cut_cost))))
        .sparse_linear_solver(traits));
    std::printf("cut (epsilon %.3g): %zu terminals (largest lambda %.3g), %zu boundary loops, %zu generator loops; "
                "%zu edges, length %.4g -> %zu pieces (%.3f s)\n",
                o.epsilon, r.terminals, r.lambda_max, r.boundary_loops, r.generator_loops, r.cut_edges, r.cut_length,
                r.pieces, clock.lap() / 1000.);
    if(o.distortion_bound > 0.)
    {
      std::printf("  distortion bound %.3g: %zu terminals added in %zu rounds; largest |log area scale| of the "
                  "conformal flattening %.3g\n",
                  o.distortion_bound, r.distortion_terminals, r.distortion_rounds, r.largest_log_area_scale);
      if(r.largest_log_area_scale > o.distortion_bound)
        throw std::runtime_error("the cut did not bring the distortion under --distortion-bound " +
                                 program::text(o.distortion_bound) + " in " + std::to_string(r.distortion_rounds) +
                                 " rounds (largest |log area scale| " + program::text(r.largest_log_area_scale) +
                                 "); no output written");
    }
    if(o.crack_opening >= 0.)
    {
      std::vector<Mesh::Edge_index> glued;
      const SD::Crack_gluing_result g = SD::glue_flattening_cracks(
        input, cut, std::back_inserter(glued),
        P::crack_opening_bound(o.crack_opening * CGAL_PI / 180., P::distortion_bound(o.distortion_bound))
          .sparse_linear_solver(traits));
      std::printf("glued %zu edges, %zu cracks closed in %zu rounds%s: cut %zu edges, length %.4g; largest |log "
                  "area scale| %.3g (%.3g before) (%.3f s)\n",
                  g.glued_edges, g.cracks, g.rounds, g.converged ? "" : " (the round limit: cracks left)", g.cut_edges,
                  g.cut_length, g.largest_log_area_scale, g.largest_log_area_scale_before, clock.lap() / 1000.);
      cut = std::move(glued);
    }
    for(auto e : cut)
      cut_edge[std::size_t(e)] = true;
    std::vector<std::pair<Mesh::Vertex_index, Mesh::Vertex_index>> pairs;
    SD::cut_mesh_along_edges(input, cut, pieces, CGAL::parameters::vertex_to_vertex_output_iterator(std::back_inserter(pairs)));
    original.resize(num_vertices(pieces));
    for(const auto& [in, out] : pairs)
      original[std::size_t(out)] = in;
  }
  else
  {
    pieces = input;
    for(auto v : vertices(pieces))
      original.push_back(v);
  }

  auto uv = pieces.add_property_map<Mesh::Vertex_index, Uv>("v:uv").first;
  // flatten; while a piece overlaps itself in the plane, split it and flatten again (a design
  // needs a few rounds; a tree of thin strips, such as a minimal surface cut through every
  // vertex, about log2 of its length)
  const std::size_t max_split_rounds = 64;
  for(std::size_t round = 0;; ++round)
  {
    {
      SD::Boundary_first_flattener flattener(pieces, CGAL::parameters::sparse_linear_solver(traits));
      const double factor_ms = clock.lap();
      flattener.flatten(uv);
      std::printf("flattened %zu pieces by BFF: %zu interior and %zu boundary vertices (factorization %.1f ms, "
                  "solves %.1f ms)\n",
                  flattener.number_of_pieces(), flattener.number_of_interior_vertices(),
                  flattener.number_of_boundary_vertices(), factor_ms, clock.lap());
    }
    if(!o.split)
      break;
    std::vector<Mesh::Edge_index> split_cut;
    const SD::Overlap_splitting_result r = SD::compute_overlap_splitting_cut(pieces, uv, std::back_inserter(split_cut));
    if(r.overlapping_pieces == 0)
      break;
    if(r.split_pieces == 0 || round == max_split_rounds)
    {
      std::printf("  %zu piece(s) overlap themselves and %s\n", r.overlapping_pieces,
                  r.split_pieces == 0 ? "cannot be split into disks" : "are left after the last round of splitting");
      break;
    }
    for(auto e : split_cut)
    {
      const auto h = halfedge(e, pieces);
      cut_edge[std::size_t(edge(halfedge(original[std::size_t(source(h, pieces))],
                                         original[std::size_t(target(h, pieces))], input).first, input))] = true;
    }
    Mesh split;
    std::vector<std::pair<Mesh::Vertex_index, Mesh::Vertex_index>> pairs;
    SD::cut_mesh_along_edges(pieces, split_cut, split,
                             CGAL::parameters::vertex_to_vertex_output_iterator(std::back_inserter(pairs)));
    std::vector<Mesh::Vertex_index> split_original(num_vertices(split));
    for(const auto& [in, out] : pairs)
      split_original[std::size_t(out)] = original[std::size_t(in)];
    std::printf("split %zu of %zu overlapping piece(s) along %zu edges (%.1f ms)\n", r.split_pieces,
                r.overlapping_pieces, r.cut_edges, clock.lap());
    pieces = std::move(split);
    original = std::move(split_original);
    uv = pieces.add_property_map<Mesh::Vertex_index, Uv>("v:uv").first;
  }

  auto log_area = pieces.add_property_map<Mesh::Face_index, double>("f:log_area", 0.).first;
  const SD::Flattening_distortion d = SD::flattening_distortion(pieces, uv, P::face_log_area_scale_map(log_area));
  std::vector<double> face_log_area(num_faces(pieces));
  for(auto f : faces(pieces))
    face_log_area[std::size_t(f)] = log_area[f];
  std::printf("distortion: |log area scale| mean %.3g max %.3g; log(s1/s2) mean %.3g max %.3g; largest stretch "
              "%.4g; area ratio %.6f\n",
              d.area_log_mean, d.area_log_max, d.conformal_log_mean, d.conformal_log_max, d.stretch_max, d.area_ratio);
  std::printf("  %zu flipped faces; boundary length error %.2g (largest %.2g); %zu piece(s) overlapping themselves%s\n",
              d.flipped_faces, d.boundary_length_error, d.boundary_length_error_max, d.self_overlapping_pieces,
              d.self_overlapping_pieces > 0 ? " (cut by hand before cutting material: see the manual)" : "");

  std::map<Mesh::Vertex_index, std::size_t> seam_index;
  for(auto v : vertices(pieces))
    seam_index[v] = std::size_t(original[std::size_t(v)]);
  const SD::Fabrication_layout layout = SD::lay_out_flattened_pieces(
    pieces, uv,
    P::sheet_size(std::make_pair(o.sheet_width, o.sheet_height),
                  P::pattern_scale(o.scale, P::sheet_margin(o.margin, P::glue_tab_width(o.glue_tabs)))));
  std::printf("pattern: %zu sheet(s) of %g x %g mm at %g mm per model unit\n", layout.sheets, layout.sheet_width,
              layout.sheet_height, layout.scale);

  program::Output_files outputs;
  write_obj(outputs.stage(o.output), input, pieces, original, uv);
  {
    std::ofstream pattern(outputs.stage(o.pattern), std::ios::binary);
    const auto np =
      P::seam_vertex_index_map(boost::make_assoc_property_map(seam_index), P::fold_angle(o.fold_angle * CGAL_PI / 180.));
    const bool pdf = o.pattern.size() >= 4 && o.pattern.compare(o.pattern.size() - 4, 4, ".pdf") == 0;
    const SD::Fabrication_pattern_report drawn = pdf ? SD::write_fabrication_pattern_pdf(pattern, pieces, uv, layout, np)
                                                     : SD::write_fabrication_pattern_svg(pattern, pieces, uv, layout, np);
    pattern.flush();
    if(!pattern)
      throw std::runtime_error("writing " + o.pattern + " failed (disk full?)");
    if(o.glue_tabs > 0.)
      std::printf("glue tabs: %zu of %zu seams (%zu narrowed to fit, %zu left out: no room)\n", drawn.glue_tabs,
                  drawn.seams, drawn.narrowed_glue_tabs, drawn.omitted_glue_tabs);
  }
  if(!o.picture.empty())
    write_picture(input, cut_edge, pieces, uv, face_log_area, o, outputs);
  outputs.commit();
  std::cout << "wrote " << o.output << ", " << o.pattern << (o.picture.empty() ? "" : ", " + o.picture) << "\ntotal "
            << total.lap() / 1000. << " s\n";
  return 0;
}

} // namespace

int main(int argc, char** argv)
{
  return program::run_main("flatten", usage, argc, [&] {
    const Options o = parse(argc, argv);
    return program::with_solver(o.solver, [&](auto traits) { return run(o, traits); });
  });
}
