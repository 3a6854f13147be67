// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// developable: drives a triangle mesh towards a piecewise-developable shape (Stein, Grinspun &
// Crane 2018) and prints the figures of the result. Run without arguments for the usage.

#include "common/option_parser.h"
#include "common/program_support.h"

#include <CGAL/Surface_design/developability.h>
#include <CGAL/Surface_design/developable_cutting.h>

#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>

#include <cmath>
#include <cstdio>
#include <iostream>
#include <map>
#include <string>
#include <vector>

namespace SD = CGAL::Surface_design;
namespace P = CGAL::Surface_design::parameters;
using program::Mesh;
using program::Point;

namespace {

const char* usage =
  "usage: developable INPUT --output OUT.off [options]\n"
  "  Moves the vertices of a triangle mesh (any number of components, with or without boundary)\n"
  "  to make every vertex star a hinge, except along a sparse set of seam curves: a piecewise\n"
  "  developable design that bends from flat sheets. Between levels the mesh is subdivided 4-1.\n"
  "options:\n"
  "  --energy E            intrinsic-width (default: of all energies the one that moves the\n"
  "                        shape least), intrinsic, covariance, max-covariance, combinatorial,\n"
  "                        combinatorial-max, angle-defect (the crumpling baseline of Fig. 7),\n"
  "                        l1-angle-defect (|Omega|, Fig. 11: piecewise flat, not developable)\n"
  "  --subdivisions N      4-1 subdivisions, 0..4 (default 2: for a coarse mesh of about 1k faces)\n"
  "  --iterations N        largest number of descent iterations per level (default 10000); a level\n"
  "                        ends before when it has converged: over 300 iterations the energy fell\n"
  "                        by less than 1% and the vertices above the target by at most 0.5%\n"
  "  --target L            lambda (covariance, eq. 3) that counts as developable (default 2pi 1e-4,\n"
  "                        a hinge): a level also ends as soon as every vertex is at most L (with\n"
  "                        the default too: nothing is left to do); at the end the vertices above\n"
  "                        L are the seams (flatten --epsilon L cuts through them); given, the\n"
  "                        program exits 1 without output if the flow did not converge\n"
  "  --descent lbfgs|gradient   L-BFGS with the Lewis-Overton line search (default) or gradient descent\n"
  "  --minimum-angle DEG   corner angles below this are removed by flips and collapses after\n"
  "                        every step (default 0.573 = 0.01 rad; 0 turns it off)\n"
  "  --keep-valence-3      let valence-3 vertices carry energy too (default: omitted, triple points)\n"
  "  --progress N          a progress line every N iterations (default 100; 0: none)\n"
  "  --cut-report E        on every progress line, the tree that flatten --epsilon E\n"
  "                        --distortion-bound 0 would cut in the design so far (terminals, edges,\n"
  "                        length; the paper's Fig. 20, bottom); needs progress lines\n"
  "  --output OUT.off      the design (.off, .obj, .ply, .stl); required\n"
  "  --picture OUT.png     faces flat-shaded, edges darker the more they bend, vertices far from\n"
  "                        hinges (lambda >= 2pi 1e-3) red\n"
  "  --up +Y|+Z|...        up direction of the picture (default +Y)\n";

struct Options
{
  std::string input, output, picture, up = "+Y";
  SD::Developability_energy energy = SD::Developability_energy::intrinsic_width;
  std::size_t subdivisions = 2, iterations = 10000, progress = 100;
  double target = 2. * CGAL_PI * 1e-4;
  double cut_report = 0.; // 0: none
  bool target_given = false;
  SD::Developability_descent descent = SD::Developability_descent::lbfgs;
  double minimum_angle = 0.01;
  bool keep_valence_3 = false;
};

Options parse(int argc, char** argv)
{
  Options o;
  const std::map<std::string, SD::Developability_energy> energies{
    {"intrinsic", SD::Developability_energy::intrinsic},
    {"covariance", SD::Developability_energy::covariance},
    {"max-covariance", SD::Developability_energy::covariance_max},
    {"intrinsic-width", SD::Developability_energy::intrinsic_width},
    {"combinatorial", SD::Developability_energy::combinatorial},
    {"combinatorial-max", SD::Developability_energy::combinatorial_max},
    {"angle-defect", SD::Developability_energy::squared_angle_defect},
    {"l1-angle-defect", SD::Developability_energy::absolute_angle_defect}};
  program::Option_parser p;
  p.input(o.input)
    .value("--energy",
           [&](const std::string& v) {
             std::vector<std::string> names;
             for(const auto& [name, e] : energies)
               names.push_back(name);
             o.energy = energies.at(program::parse_choice(v, "--energy", names));
           })
    .value("--subdivisions",
           [&](const std::string& v) { o.subdivisions = std::size_t(program::parse_integer(v, "--subdivisions", 0, 4)); })
    .value("--iterations",
           [&](const std::string& v) { o.iterations = std::size_t(program::parse_integer(v, "--iterations", 0, 10000000)); })
    .value("--target",
           [&](const std::string& v) {
             o.target = program::parse_positive(v, "--target");
             if(o.target > 2. * CGAL_PI / 3.)
               throw program::Usage_error("--target must be at most 2pi/3 = 2.0944 (the largest lambda of a star), not " + v);
             o.target_given = true;
           })
    .value("--descent",
           [&](const std::string& v) {
             o.descent = program::parse_choice(v, "--descent", {"lbfgs", "gradient"}) == "lbfgs"
                           ? SD::Developability_descent::lbfgs
                           : SD::Developability_descent::gradient_descent;
           })
    .value("--minimum-angle",
           [&](const std::string& v) { o.minimum_angle = program::parse_double(v, "--minimum-angle", 0., 30.) * CGAL_PI / 180.; })
    .flag("--keep-valence-3", [&] { o.keep_valence_3 = true; })
    .value("--cut-report", [&](const std::string& v) { o.cut_report = program::parse_positive(v, "--cut-report"); })
    .value("--progress",
           [&](const std::string& v) { o.progress = std::size_t(program::parse_integer(v, "--progress", 0, 100000000)); })
    .output("--output", o.output, {".off", ".obj", ".ply", ".stl"})
    .picture(o.picture, o.up)
    .parse(argc, argv);
  if(o.output.empty())
    throw program::Usage_error("--output OUT.off is required");
  if(o.cut_report > 0. && o.progress == 0)
    throw program::Usage_error("--cut-report prints on the progress lines: not with --progress 0");
  program::check_paths_and_picture({{"INPUT", o.input}, {"--output", o.output}}, o.picture, p.given("--up"));
  return o;
}

Eigen::Vector3d eigen(const Point& p) { return Eigen::Vector3d(p.x(), p.y(), p.z()); }

// Faces flat-shaded (scalar 0..1 from the face normal: pieces of one developable surface shade
// smoothly, seams show as jumps), every edge a thin dark ribbon whose darkness grows with its
// dihedral angle (scalar 1..2: rulings faint, seams dark, as in the paper's Fig. 26), seam
// vertices as small red triangles (scalar 3).
void write_picture(const Mesh& mesh, const std::vector<double>& lambda, const Options& o, program::Output_files& outputs)
{
  program::Vtk_surface vtk;
  vtk.scalar_name = "shade";
  const Eigen::Vector3d light = Eigen::Vector3d(0.3, 0.6, 0.75).normalized();
  std::map<Mesh::Face_index, Eigen::Vector3d> normal;
  double mean_edge = 0.;
  for(auto e : edges(mesh))
    mean_edge += std::sqrt(CGAL::to_double(CGAL::squared_distance(mesh.point(source(halfedge(e, mesh), mesh)),
                                                                   mesh.point(target(halfedge(e, mesh), mesh))))) /
                 double(num_edges(mesh));
  for(auto f : faces(mesh))
  {
    std::vector<Eigen::Vector3d> p;
    for(auto v : vertices_around_face(halfedge(f, mesh), mesh))
      p.push_back(eigen(mesh.point(v)));
    const Eigen::Vector3d n = (p[1] - p[0]).cross(p[2] - p[0]).normalized();
    normal[f] = n;
    const double shade = 0.5 + 0.5 * n.dot(light);
    vtk.triangles.push_back({vtk.add(p[0], n, shade), vtk.add(p[1], n, shade), vtk.add(p[2], n, shade)});
  }
  const double width = 0.06 * mean_edge;
  for(auto e : edges(mesh))
  {
    const auto h = halfedge(e, mesh);
    if(is_border_edge(h, mesh))
      continue;
    const Eigen::Vector3d n1 = normal[face(h, mesh)], n2 = normal[face(opposite(h, mesh), mesh)];
    const double dihedral = std::atan2(n1.cross(n2).norm(), n1.dot(n2));
    if(dihedral < 0.5 * CGAL_PI / 180.)
      continue; // flat: no line
    const Eigen::Vector3d a = eigen(mesh.point(source(h, mesh))), b = eigen(mesh.point(target(h, mesh)));
    const Eigen::Vector3d n = (n1 + n2).normalized(), side = n.cross(b - a).normalized() * width;
    const double s = 1. + (std::min)(1., dihedral / (15. * CGAL_PI / 180.)); // 15 degrees: darkest
    const Eigen::Vector3d lift = n * (0.02 * mean_edge);
    const std::size_t i0 = vtk.add(a - side + lift, n, s), i1 = vtk.add(b - side + lift, n, s), i2 = vtk.add(b + side + lift, n, s),
                      i3 = vtk.add(a + side + lift, n, s);
    vtk.triangles.push_back({i0, i1, i2});
    vtk.triangles.push_back({i0, i2, i3});
  }
  for(auto v : vertices(mesh))
  {
    if(lambda[std::size_t(v)] < 2. * CGAL_PI * 1e-3 || is_border(v, mesh))
      continue;
    Eigen::Vector3d n = Eigen::Vector3d::Zero();
    for(auto f : faces_around_target(halfedge(v, mesh), mesh))
      if(f != Mesh::null_face())
        n += normal[f];
    n.normalize();
    const Eigen::Vector3d c = eigen(mesh.point(v)) + n * (0.05 * mean_edge);
    const Eigen::Vector3d u = n.unitOrthogonal() * (0.35 * mean_edge), w = n.cross(u);
    vtk.triangles.push_back({vtk.add(c + u, n, 3.), vtk.add(c - 0.5 * u + 0.87 * w, n, 3.), vtk.add(c - 0.5 * u - 0.87 * w, n, 3.)});
  }
  const std::string vtk_path = outputs.stage(o.picture + ".vtk");
  vtk.write(vtk_path);
  // 0..1 grey to white (faces), 1..2 light to dark grey (edges), 3 red (vertices far from hinges)
  const std::string colormap = "0,0.55,0.58,0.62,0.333,0.97,0.97,0.96,0.334,0.72,0.72,0.72,0.666,0.08,0.08,0.1,1,0.85,0.1,0.1";
  program::render_png(vtk_path, outputs.stage(o.picture), "shade", 0., 3., o.up, colormap);
}

void print_metrics(const SD::Developability_metrics& m)
{
  std::printf("result: %zu vertices, %zu faces; energy %.6g\n", m.vertices, m.faces, m.energy);
  std::printf("  lambda (covariance, eq. 3) over %zu measured vertices: max %.3g mean %.3g p95 %.3g\n",
              m.measured_vertices, m.lambda_max, m.lambda_mean, m.lambda_p95);
  std::printf("  hinges: %.1f%% (lambda < 2pi 1e-4), %.1f%% (< 2pi 1e-3)\n", 100. * m.hinge_share_1e4,
              100. * m.hinge_share_1e3);
  std::printf("  angle defect |Omega|: max %.3g mean %.3g rad; %zu seam vertices carry %.1f%% of it\n",
              m.angle_defect_max, m.angle_defect_mean, m.seam_vertices, 100. * m.seam_curvature_share);
  std::printf("  seams: %zu curves, length %.4g; smallest angle %.3g deg\n", m.seam_curves, m.seam_length,
              m.minimum_angle * 180. / CGAL_PI);
  std::printf("  distance to the input / bbox diagonal: Hausdorff %.4f, mean %.5f\n", m.hausdorff_distance,
              m.mean_distance);
}

// The vertices whose lambda exceeds the target, grouped by edges: where the flow left the
// curvature (seam curves and cone points), and the share of sum |Omega| they carry.
void print_target_report(const Mesh& mesh, double target)
{
  std::map<Mesh::Vertex_index, double> lambda, defect;
  SD::developability_energy(mesh, P::developability_energy(SD::Developability_energy::covariance,
                                                           P::vertex_energy_map(boost::make_assoc_property_map(lambda))));
  SD::developability_energy(mesh, P::developability_energy(SD::Developability_energy::absolute_angle_defect,
                                                           P::omit_valence_three_vertices(false,
                                                             P::vertex_energy_map(boost::make_assoc_property_map(defect)))));
  std::map<Mesh::Vertex_index, bool> seen;
  std::size_t above = 0, groups = 0;
  double above_defect = 0., all_defect = 0.;
  for(auto v : vertices(mesh))
  {
    all_defect += defect[v];
    if(lambda[v] <= target || seen[v])
      continue;
    ++groups;
    std::vector<Mesh::Vertex_index> stack{v};
    seen[v] = true;
    while(!stack.empty())
    {
      const auto w = stack.back();
      stack.pop_back();
      ++above;
      above_defect += defect[w];
      for(auto u : vertices_around_target(halfedge(w, mesh), mesh))
        if(lambda[u] > target && !seen[u])
        {
          seen[u] = true;
          stack.push_back(u);
        }
    }
  }
  std::printf("  target lambda <= %.3g: %zu vertices above it, in %zu groups (seams and cone points), carrying "
              "%.1f%% of sum |Omega|; flatten --epsilon %.3g cuts through them\n",
              target, above, groups, all_defect > 0. ? 100. * above_defect / all_defect : 0., target);
}

int run(const Options& o)
{
  program::Stopwatch clock;
  Mesh mesh = program::read_mesh(o.input);
  const Mesh input = mesh;
  std::cout << "read " << o.input << ": " << num_vertices(mesh) << " vertices, " << num_faces(mesh) << " faces\n";
  const long euler = long(num_vertices(mesh)) - long(num_edges(mesh)) + long(num_faces(mesh));

  const SD::Developability_flow_result r = SD::make_piecewise_developable(
    mesh, P::developability_energy(
            o.energy, P::number_of_subdivisions(
                        o.subdivisions, P::minimum_angle(
                                          o.minimum_angle, P::descent_method(
                                                             o.descent, P::omit_valence_three_vertices(
                                                                            !o.keep_valence_3, P::developability_target(o.target))))))
            .number_of_iterations(o.iterations)
            .visitor([&o, &mesh](const SD::Developability_iteration& it) {
              if(o.progress > 0 && (it.level_iteration % o.progress == 0 || it.level_iteration == 1))
              {
                std::printf("level %zu iteration %5zu: energy %.6g, gradient %.3g, step %.3g, %zu faces%s", it.level,
                            it.level_iteration, it.energy, it.gradient_norm, it.step, it.faces,
                            it.flips + it.collapses > 0 ? " (small angles removed)" : "");
                if(o.cut_report > 0.)
                {
                  // the mesh holds the positions of this iteration; a report that fails (a face the
                  // flow made degenerate, without small-angle handling) does not stop the flow
                  try
                  {
                    std::vector<Mesh::Edge_index> cut;
                    const SD::Developable_cut_result c =
                      SD::compute_developable_cut(mesh, std::back_inserter(cut), P::cut_tolerance(o.cut_report));
                    std::printf("; cut at %.3g: %zu terminals, %zu edges, length %.4g", o.cut_report, c.terminals,
                                c.cut_edges, c.cut_length);
                  }
                  catch(const std::exception& e)
                  {
                    std::printf("; no cut at this iteration (%s)", e.what());
                  }
                }
                std::printf("\n");
              }
              std::fflush(stdout);
              return true;
            }));
  for(std::size_t l = 0; l < r.levels.size(); ++l)
    std::printf("level %zu: %zu iterations, energy %.6g -> %.6g, %zu faces, %zu of %zu vertices above the target: %s\n",
                l, r.levels[l].iterations, r.levels[l].initial_energy, r.levels[l].final_energy, r.levels[l].faces,
                r.levels[l].vertices_above_target, r.levels[l].measured_vertices, r.levels[l].end.c_str());
  std::printf("%zu iterations, %zu evaluations, %zu flips, %zu collapses, %zu subdivisions; %.2f s (evaluation %.2f, "
              "small angles %.2f, subdivision %.2f)\n",
              r.iterations, r.evaluations, r.flips, r.collapses, r.subdivisions, r.total_seconds, r.evaluation_seconds,
              r.remeshing_seconds, r.subdivision_seconds);
  const long euler_after = long(num_vertices(mesh)) - long(num_edges(mesh)) + long(num_faces(mesh));
  if(euler_after != euler)
    throw std::logic_error("the Euler characteristic changed from " + std::to_string(euler) + " to " +
                           std::to_string(euler_after));

  if(!r.converged)
  {
    const std::string why = "the last level ended with \"" + r.levels.back().end + "\" before converging (" +
                            std::to_string(r.levels.back().vertices_above_target) + " vertices above the target)";
    const bool capped = r.levels.back().end == "iteration limit";
    const std::string advice = capped ? "raise --iterations (now " + std::to_string(o.iterations) + ")"
                                      : "the descent cannot pass a kink here; try another --energy or --descent";
    if(o.target_given)
      throw std::runtime_error(why + ": no output written; " + advice);
    std::printf("note: %s; %s\n", why.c_str(), advice.c_str());
  }
  print_metrics(SD::developability_metrics(mesh, input, P::developability_energy(o.energy)));
  print_target_report(mesh, o.target);
  program::Output_files outputs;
  if(!CGAL::IO::write_polygon_mesh(outputs.stage(o.output), mesh, CGAL::parameters::stream_precision(17)))
    throw std::runtime_error("cannot write " + o.output);
  if(!o.picture.empty())
  {
    std::map<Mesh::Vertex_index, double> lambda;
    SD::developability_energy(mesh, P::developability_energy(SD::Developability_energy::covariance,
                                                             P::omit_valence_three_vertices(false,
                                                               P::vertex_energy_map(boost::make_assoc_property_map(lambda)))));
    std::vector<double> values(num_vertices(mesh), 0.);
    for(const auto& [v, l] : lambda)
      values[std::size_t(v)] = l;
    write_picture(mesh, values, o, outputs);
  }
  outputs.commit();
  std::cout << "total " << clock.lap() / 1000. << " s\n";
  return 0;
}

} // namespace

int main(int argc, char** argv)
{
  return program::run_main("developable", usage, argc, [&] {
    return run(parse(argc, argv));
  });
}
