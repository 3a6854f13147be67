// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// direction_field: smoothest or prescribed-singularity n-direction fields on any triangle mesh.
// Run without arguments for the usage.

#include "common/option_parser.h"
#include "common/program_support.h"

#include <CGAL/Surface_design/direction_fields.h>
#include <CGAL/Surface_design/Trivial_connection.h>

#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/Polygon_mesh_processing/measure.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <map>
#include <string>
#include <vector>

namespace SD = CGAL::Surface_design;
using program::Mesh;
using program::Point;
using program::Vector;

namespace {

const char* usage =
  "usage: direction_field INPUT --method smoothest|trivial --output OUT.ply [options]\n"
  "  Tangent n-direction field on a triangle mesh (faces numbered in the input file's order).\n"
  "options:\n"
  "  --method smoothest        smoothest field (Knöppel et al. 2013)\n"
  "  --method trivial          field with exactly the given singularities (trivial connection,\n"
  "                            Crane et al. 2010)\n"
  "  --n N                     symmetry: 1 vector field (default), 2 line field, 4 cross field\n"
  "  --singularity FACE:INDEX  trivial: singularity of index INDEX / N at FACE (repeatable; INDEX\n"
  "                            is -1 or 1; on a closed surface the indices sum to N times the Euler\n"
  "                            characteristic)\n"
  "  --curvature-weight W      smoothest: align with the principal curvature directions (N even)\n"
  "  --boundary free|tangent|normal   boundary condition (default free): the field follows the\n"
  "                            boundary (tangent) or its inward normal; trivial: then the indices\n"
  "                            sum to the Euler characteristic less the corners the field turns\n"
  "                            with (the message says how much)\n"
  "  --sharp-angle DEG         smoothest: the field follows the creases, the interior edges whose\n"
  "                            faces' normals differ by more than DEG degrees (0 < DEG < 180; a\n"
  "                            corner whose creases no n-direction follows at once stays free)\n"
  "  --solver S                sparse solver: default (simplicial LDLT below 20k\n"
  "                            unknowns, supernodal Cholesky above), ldlt, supernodal, cholmod\n"
  "  --output OUT.ply          mesh with vertex field_x, field_y, field_z and face field_index (k/N)\n"
  "                            and field_index_numerator (k)\n"
  "  --picture OUT.png         arrows (n = 1), segments (n = 2) or crosses (n = 4) on the surface,\n"
  "                            singular faces red (positive) and blue (negative), rendered with f3d\n"
  "  --up +Y|+Z|...            up direction of the picture (default +Y)\n";

struct Options
{
  std::string input, method, output, picture, up = "+Y", solver = "default";
  std::string boundary = "free";
  int n = 1;
  double curvature_weight = 0.;
  double sharp_angle = 0.; // 0: none
  std::map<std::size_t, int> singularities;
};

Options parse(int argc, char** argv)
{
  Options o;
  program::Option_parser p;
  p.input(o.input)
    .value("--method", [&](const std::string& v) { o.method = program::parse_choice(v, "--method", {"smoothest", "trivial"}); })
    .value("--n", [&](const std::string& v) { o.n = int(program::parse_integer(v, "--n", 1, 64)); })
    .repeated("--singularity",
              [&](const std::string& v) {
                const auto [f, k] = program::parse_pair(v, "--singularity FACE:INDEX");
                if(f < 0)
                  throw program::Usage_error("face numbers start at 0");
                if(k == 0)
                  throw program::Usage_error("--singularity " + std::to_string(f) + ":0 prescribes nothing");
                if(!o.singularities.emplace(std::size_t(f), int(k)).second)
                  throw program::Usage_error("--singularity: face " + std::to_string(f) + " is given more than once");
              })
    .value("--curvature-weight",
           [&](const std::string& v) { o.curvature_weight = program::parse_double(v, "--curvature-weight", 0., 1e12); })
    .value("--sharp-angle",
           [&](const std::string& v) {
             o.sharp_angle = program::parse_double(v, "--sharp-angle", 0., 180.);
             if(!(o.sharp_angle > 0. && o.sharp_angle < 180.))
               throw program::Usage_error("--sharp-angle " + v + ": must lie strictly between 0 and 180 degrees");
           })
    .value("--boundary",
           [&](const std::string& v) { o.boundary = program::parse_choice(v, "--boundary", {"free", "tangent", "normal"}); })
    .solver(o.solver)
    .output("--output", o.output, {".ply"})
    .picture(o.picture, o.up)
    .parse(argc, argv);
  if(!p.given("--method"))
    throw program::Usage_error("--method smoothest|trivial is required");
  if(o.output.empty())
    throw program::Usage_error("--output OUT.ply is required");
  if(o.method == "smoothest" && !o.singularities.empty())
    throw program::Usage_error("--singularity needs --method trivial (smoothest fields place their own)");
  if(o.method == "trivial" && o.curvature_weight != 0.)
    throw program::Usage_error("--curvature-weight applies to --method smoothest");
  if(o.method == "trivial" && p.given("--sharp-angle"))
    throw program::Usage_error("--sharp-angle applies to --method smoothest (the trivial connection does not follow "
                               "creases yet)");
  program::check_paths_and_picture({{"INPUT", o.input}, {"--output", o.output}}, o.picture, p.given("--up"));
  return o;
}

SD::Direction_field_boundary boundary_condition(const std::string& b)
{
  return b == "tangent" ? SD::Direction_field_boundary::tangent
         : b == "normal" ? SD::Direction_field_boundary::normal
                         : SD::Direction_field_boundary::free;
}

// Glyphs of an n-direction field, one per face (every stride-th face on big meshes), over the
// surface; scalar 0 surface, 1 glyphs, 2 / 3 faces of positive / negative index.
void write_picture(const Mesh& mesh, const std::vector<Vector>& field, const std::vector<int>& index, int n,
                   const Options& o, program::Output_files& outputs)
{
  namespace PMP = CGAL::Polygon_mesh_processing;
  auto eigen = [](const Vector& x) { return Eigen::Vector3d(x.x(), x.y(), x.z()); };
  std::vector<Eigen::Vector3d> normal, face_normal;
  std::vector<double> area;
  for(auto v : vertices(mesh))
    normal.push_back(eigen(PMP::compute_vertex_normal(v, mesh)));
  for(auto f : faces(mesh))
  {
    face_normal.push_back(eigen(PMP::compute_face_normal(f, mesh)));
    area.push_back(PMP::face_area(f, mesh));
  }
  program::Vtk_surface vtk;
  vtk.scalar_name = "field";
  double mean_area = 0.;
  for(double a : area)
    mean_area += a / double(area.size());
  const std::size_t stride = (std::max<std::size_t>)(1, num_faces(mesh) / 12000);
  const double length = 0.75 * std::sqrt(4. * mean_area * double(stride) / std::sqrt(3.));
  const double lift = 0.02 * length;
  for(auto f : faces(mesh))
  {
    const std::size_t fi = std::size_t(f);
    const double s = index[fi] > 0 ? 2. : index[fi] < 0 ? 3. : 0.;
    std::array<std::size_t, 3> t;
    int k = 0;
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();
    std::vector<Eigen::Vector3d> dirs;
    for(auto v : vertices_around_face(halfedge(f, mesh), mesh))
    {
      const Eigen::Vector3d p(mesh.point(v).x(), mesh.point(v).y(), mesh.point(v).z());
      centre += p / 3.;
      t[std::size_t(k++)] = vtk.add(p, normal[std::size_t(v)], s);
      const Vector& x = field[std::size_t(v)];
      dirs.emplace_back(x.x(), x.y(), x.z());
    }
    vtk.triangles.push_back(t);
    if(fi % stride != 0)
      continue;
    // the face's direction: the vertex directions in the face plane, each turned by the multiple
    // of 2 pi / n that brings it closest to the first, averaged
    const Eigen::Vector3d nf = face_normal[fi];
    Eigen::Vector3d d = Eigen::Vector3d::Zero(), first = Eigen::Vector3d::Zero();
    for(std::size_t i = 0; i < dirs.size(); ++i)
    {
      Eigen::Vector3d x = (dirs[i] - dirs[i].dot(nf) * nf).normalized(), best = x;
      for(int r = 1; r < n && i > 0; ++r)
      {
        const double a = 2. * CGAL_PI * r / n;
        const Eigen::Vector3d y = std::cos(a) * x + std::sin(a) * nf.cross(x);
        if(y.dot(first) > best.dot(first))
          best = y;
      }
      if(i == 0)
        first = best;
      d += best;
    }
    if(d.norm() == 0.)
      continue;
    d.normalize();
    const Eigen::Vector3d c = centre + lift * nf;
    for(int r = 0; r < (n == 4 ? 2 : 1); ++r)
    {
      const Eigen::Vector3d a = r == 0 ? d : Eigen::Vector3d(nf.cross(d));
      const Eigen::Vector3d side = nf.cross(a) * (length / 10.);
      // n = 1: an arrow (a slim triangle pointing along d); otherwise a diamond (no orientation)
      const Eigen::Vector3d tail = c - 0.5 * length * a, tip = c + 0.5 * length * a;
      const std::size_t i2 = vtk.add(tip, nf, 1.);
      if(n == 1)
        vtk.triangles.push_back({vtk.add(tail - side, nf, 1.), vtk.add(tail + side, nf, 1.), i2});
      else
      {
        const std::size_t i0 = vtk.add(tail, nf, 1.);
        vtk.triangles.push_back({i0, vtk.add(c + side, nf, 1.), i2});
        vtk.triangles.push_back({i0, i2, vtk.add(c - side, nf, 1.)});
      }
    }
  }
  const std::string vtk_path = outputs.stage(o.picture + ".vtk");
  vtk.write(vtk_path);
  // colours: light surface, dark glyphs, red / blue singular faces
  const std::string colormap = "0,0.93,0.9,0.84,0.333,0.12,0.16,0.3,0.667,0.85,0.15,0.1,1,0.15,0.35,0.85";
  program::render_png(vtk_path, outputs.stage(o.picture), "field", 0., 3., o.up, colormap);
}

template <class Solver>
int run(const Options& o, const Solver& solver)
{
  program::Stopwatch clock, total;
  Mesh mesh = program::read_mesh(o.input);
  std::cout << "read " << o.input << ": " << num_vertices(mesh) << " vertices, " << num_faces(mesh)
            << " faces (" << clock.lap() << " ms)\n";
  std::vector<Vector> field(num_vertices(mesh));
  auto field_map = CGAL::make_property_map(field);
  if(o.boundary != "free" && std::none_of(halfedges(mesh).begin(), halfedges(mesh).end(),
                                          [&mesh](auto h) { return is_border(h, mesh); }))
    std::cout << "note: --boundary " << o.boundary << " has no effect: the mesh has no boundary\n";
  if(o.method == "smoothest")
  {
    // the creases (none without --sharp-angle)
    auto sharp = mesh.add_property_map<Mesh::Edge_index, bool>("e:sharp", false).first;
    if(o.sharp_angle > 0.)
      std::cout << "creases: " << program::detect_creases(mesh, o.sharp_angle, sharp)
                << " edges whose faces' normals differ by more than " << o.sharp_angle << " degrees\n";
    const auto info = SD::smoothest_direction_field(
      mesh, field_map,
      SD::parameters::symmetry_order(
        o.n, SD::parameters::curvature_alignment_weight(
               o.curvature_weight,
               SD::parameters::field_boundary_condition(
                 boundary_condition(o.boundary),
                 CGAL::parameters::edge_is_constrained_map(sharp).sparse_linear_solver(solver)))));
    if(o.sharp_angle > 0.)
      std::cout << "the field follows them at " << info.feature_vertices << " vertices\n";
    std::cout << "smoothest field (n = " << o.n << "): " << clock.lap() << " ms";
    if(info.iterations > 0)
    {
      std::cout << ", " << info.iterations << " Lanczos steps" << (info.converged ? "" : " (not converged)")
                << ", eigenvalue";
      for(double l : info.eigenvalues)
        std::cout << ' ' << l;
    }
    std::cout << '\n';
  }
  else
  {
    SD::Trivial_connection tc(
      mesh, SD::parameters::symmetry_order(o.n, SD::parameters::field_boundary_condition(
                                                  boundary_condition(o.boundary), SD::parameters::sparse_linear_solver(solver))));
    std::cout << "trivial connection set-up and factorization: " << clock.lap() << " ms\n";
    for(const auto& [f, k] : o.singularities)
      tc.set_index(f, k);
    tc.solve();
    tc.field(field_map);
    std::cout << "solve: " << clock.lap() << " ms (adjustment norm^2 " << tc.adjustment_norm2() << ", largest "
              << tc.largest_adjustment() << " rad)\n";
  }

  // indices in units of 1/n
  std::vector<int> index(num_faces(mesh), 0);
  const std::size_t count = SD::direction_field_singularities(
    mesh, field_map, CGAL::make_property_map(index), SD::parameters::symmetry_order(o.n));
  long sum = 0;
  auto text = [&o](long k) { return o.n == 1 ? std::to_string(k) : std::to_string(k) + "/" + std::to_string(o.n); };
  std::cout << "singularities (" << count << "):";
  for(std::size_t f = 0; f < index.size(); ++f)
    if(index[f] != 0)
    {
      sum += index[f];
      std::cout << ' ' << f << ':' << text(index[f]);
    }
  std::cout << "\nindex sum " << text(sum) << " (Euler characteristic "
            << long(num_vertices(mesh)) - long(num_edges(mesh)) + long(num_faces(mesh)) << ")\n";

  program::Ply_property fx{"field_x", "double", {}}, fy{"field_y", "double", {}}, fz{"field_z", "double", {}};
  for(const Vector& x : field)
  {
    fx.values.push_back(x.x());
    fy.values.push_back(x.y());
    fz.values.push_back(x.z());
  }
  program::Ply_property numerator{"field_index_numerator", "int", {}}, value{"field_index", "double", {}};
  for(int k : index)
  {
    numerator.values.push_back(k);
    value.values.push_back(double(k) / o.n);
  }
  program::Output_files outputs;
  program::write_ply(outputs.stage(o.output), mesh, {fx, fy, fz}, {value, numerator});
  if(!o.picture.empty())
    write_picture(mesh, field, index, o.n, o, outputs);
  outputs.commit();
  std::cout << "total " << total.lap() << " ms\n";
  return 0;
}

} // namespace

int main(int argc, char** argv)
{
  return program::run_main("direction_field", usage, argc, [&] {
    const Options o = parse(argc, argv);
    return program::with_solver(o.solver, [&o](auto traits) { return run(o, traits); });
  });
}
