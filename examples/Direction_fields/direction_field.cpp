// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// direction_field: smoothest or prescribed-singularity n-direction fields on any triangle mesh.
// Run without arguments for the usage.

#include "../common/example_support.h"

#include <CGAL/Surface_design/direction_fields.h>
#include <CGAL/Surface_design/internal/geometry.h>
#include <CGAL/Surface_design/Trivial_connection.h>

#include <cmath>
#include <iostream>
#include <map>
#include <string>
#include <vector>

namespace SD = CGAL::Surface_design;
namespace SDI = CGAL::Surface_design::internal;
using example::Mesh;
using example::Point;
using example::Vector;

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
  "  --boundary free|tangent|normal   smoothest: boundary condition (default free)\n"
  "  --solver ldlt|cholmod     sparse solver (default ldlt)\n"
  "  --output OUT.ply          mesh with vertex field_x, field_y, field_z and face field_index\n"
  "  --picture OUT.png         arrows (n = 1), segments (n = 2) or crosses (n = 4) on the surface,\n"
  "                            singular faces red (positive) and blue (negative), rendered with f3d\n"
  "  --up +Y|+Z|...            up direction of the picture (default +Y)\n";

struct Options
{
  std::string input, method, output, picture, up = "+Y", solver = "ldlt";
  std::string boundary = "free";
  int n = 1;
  double curvature_weight = 0.;
  std::map<std::size_t, int> singularities;
};

Options parse(int argc, char** argv)
{
  Options o;
  for(int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    auto next = [&]() -> std::string {
      if(i + 1 >= argc)
        throw std::invalid_argument(a + " needs a value");
      return argv[++i];
    };
    if(a == "--method")
      o.method = next();
    else if(a == "--n")
      o.n = std::stoi(next());
    else if(a == "--singularity")
    {
      const auto [f, k] = example::parse_pair(next(), "FACE:INDEX");
      if(f < 0)
        throw std::invalid_argument("face numbers start at 0");
      o.singularities[std::size_t(f)] += int(k);
    }
    else if(a == "--curvature-weight")
      o.curvature_weight = std::stod(next());
    else if(a == "--boundary")
      o.boundary = next();
    else if(a == "--solver")
      o.solver = next();
    else if(a == "--output")
      o.output = next();
    else if(a == "--picture")
      o.picture = next();
    else if(a == "--up")
      o.up = next();
    else if(!a.empty() && a[0] == '-')
      throw std::invalid_argument("unknown option " + a);
    else if(o.input.empty())
      o.input = a;
    else
      throw std::invalid_argument("more than one input file");
  }
  if(o.input.empty())
    throw std::invalid_argument("no input mesh");
  if(o.method != "smoothest" && o.method != "trivial")
    throw std::invalid_argument("--method must be smoothest or trivial");
  if(o.output.empty())
    throw std::invalid_argument("--output OUT.ply is required");
  if(o.method == "smoothest" && !o.singularities.empty())
    throw std::invalid_argument("--singularity needs --method trivial (smoothest fields place their own)");
  if(o.method == "trivial" && (o.curvature_weight != 0. || o.boundary != "free"))
    throw std::invalid_argument("--curvature-weight and --boundary apply to --method smoothest");
  return o;
}

SD::Direction_field_boundary boundary_condition(const std::string& b)
{
  if(b == "free")
    return SD::Direction_field_boundary::free;
  if(b == "tangent")
    return SD::Direction_field_boundary::tangent;
  if(b == "normal")
    return SD::Direction_field_boundary::normal;
  throw std::invalid_argument("--boundary must be free, tangent or normal");
}

// Glyphs of an n-direction field, one per face (every stride-th face on big meshes), over the
// surface; scalar 0 surface, 1 glyphs, 2 / 3 faces of positive / negative index.
void write_picture(const Mesh& mesh, const std::vector<Vector>& field, const std::vector<double>& index, int n,
                   const Options& o)
{
  const SDI::Mesh_indices<Mesh> idx(mesh);
  const auto normal = SDI::vertex_normals(idx, mesh.points());
  const auto face_normal = SDI::face_normals(idx, mesh.points());
  const auto area = SDI::face_areas(idx, mesh.points());
  example::Vtk_surface vtk;
  vtk.scalar_name = "field";
  auto add_point = [&](const Eigen::Vector3d& p, const Eigen::Vector3d& nn, double s) {
    vtk.points.push_back({p.x(), p.y(), p.z()});
    vtk.normals.push_back({nn.x(), nn.y(), nn.z()});
    vtk.scalars.push_back(s);
    return vtk.points.size() - 1;
  };
  double mean_area = 0.;
  for(double a : area)
    mean_area += a / double(area.size());
  const std::size_t stride = (std::max<std::size_t>)(1, num_faces(mesh) / 12000);
  const double pi = std::acos(-1.);
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
      const Eigen::Vector3d p = SDI::position(mesh.points(), v);
      centre += p / 3.;
      t[std::size_t(k++)] = add_point(p, normal[std::size_t(v)], s);
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
        const double a = 2. * pi * r / n;
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
      const std::size_t i2 = add_point(tip, nf, 1.);
      if(n == 1)
        vtk.triangles.push_back({add_point(tail - side, nf, 1.), add_point(tail + side, nf, 1.), i2});
      else
      {
        const std::size_t i0 = add_point(tail, nf, 1.);
        vtk.triangles.push_back({i0, add_point(c + side, nf, 1.), i2});
        vtk.triangles.push_back({i0, i2, add_point(c - side, nf, 1.)});
      }
    }
  }
  const std::string vtk_path = o.picture + ".vtk";
  vtk.write(vtk_path);
  // colours: light surface, dark glyphs, red / blue singular faces
  const std::string colormap = "0,0.93,0.9,0.84,0.333,0.12,0.16,0.3,0.667,0.85,0.15,0.1,1,0.15,0.35,0.85";
  if(example::render_png(vtk_path, o.picture, "field", 0., 3., o.up, colormap))
    std::cout << "wrote " << o.picture << " (surface in " << vtk_path << ")\n";
}

template <class Solver>
int run(const Options& o)
{
  example::Stopwatch clock, total;
  Mesh mesh = example::read_mesh(o.input);
  std::cout << "read " << o.input << ": " << num_vertices(mesh) << " vertices, " << num_faces(mesh)
            << " faces (" << clock.lap() << " ms)\n";
  std::vector<Vector> field(num_vertices(mesh));
  auto field_map = CGAL::make_property_map(field);
  if(o.method == "smoothest")
  {
    const auto info = SD::smoothest_direction_field(
      mesh, field_map,
      SD::parameters::symmetry_order(
        o.n, SD::parameters::curvature_alignment_weight(
               o.curvature_weight, SD::parameters::field_boundary_condition(
                                     boundary_condition(o.boundary), SD::parameters::sparse_linear_solver(Solver())))));
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
    SD::Trivial_connection<Mesh, Mesh::Property_map<Mesh::Vertex_index, Point>, Solver> tc(mesh, mesh.points(), o.n);
    std::cout << "trivial connection set-up and factorization: " << clock.lap() << " ms\n";
    for(const auto& [f, k] : o.singularities)
      tc.set_index(f, k);
    tc.solve();
    tc.field(field_map);
    std::cout << "solve: " << clock.lap() << " ms (adjustment norm^2 " << tc.adjustment_norm2() << ", largest "
              << tc.largest_adjustment() << " rad)\n";
  }

  std::vector<double> index(num_faces(mesh), 0.);
  const std::size_t count = SD::direction_field_singularities(
    mesh, field_map, CGAL::make_property_map(index), SD::parameters::symmetry_order(o.n));
  double sum = 0.;
  std::cout << "singularities (" << count << "):";
  for(std::size_t f = 0; f < index.size(); ++f)
    if(index[f] != 0.)
    {
      sum += index[f];
      std::cout << ' ' << f << ':' << index[f];
    }
  std::cout << "\nindex sum " << sum << " (Euler characteristic "
            << long(num_vertices(mesh)) - long(num_edges(mesh)) + long(num_faces(mesh)) << ")\n";

  example::Ply_property fx{"field_x", "double", {}}, fy{"field_y", "double", {}}, fz{"field_z", "double", {}};
  for(const Vector& x : field)
  {
    fx.values.push_back(x.x());
    fy.values.push_back(x.y());
    fz.values.push_back(x.z());
  }
  example::write_ply(o.output, mesh, {fx, fy, fz}, {{"field_index", "double", index}});
  std::cout << "wrote " << o.output << '\n';
  if(!o.picture.empty())
    write_picture(mesh, field, index, o.n, o);
  std::cout << "total " << total.lap() << " ms\n";
  return 0;
}

} // namespace

int main(int argc, char** argv)
{
  if(argc < 2)
  {
    std::cerr << usage;
    return 1;
  }
  try
  {
    const Options o = parse(argc, argv);
    return example::with_solver(o.solver, [&o](auto traits) { return run<decltype(traits)>(o); });
  }
  catch(const std::exception& e)
  {
    std::cerr << "error: " << e.what() << "\n\n" << usage;
    return 1;
  }
}
