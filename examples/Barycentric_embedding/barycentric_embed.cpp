// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// barycentric_embed: barycentric ("nice") embedding of any polygon mesh. The boundary loops (or
// the vertices listed in a file) stay fixed; every other vertex moves to the weighted barycentre
// of its neighbours. Run without arguments for the usage.

#include "embedding_support.h"

#include <CGAL/Surface_design/Barycentric_embedder.h>
#include <CGAL/Surface_design/barycentric_embedding.h>

#include <cctype>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace SD = CGAL::Surface_design;
namespace P = CGAL::Surface_design::parameters;
using example::Mesh;

namespace {

const char* usage =
  "usage: barycentric_embed INPUT [options]\n"
  "  Fixes the boundary loops (default) or the vertices listed in a file, and moves every other\n"
  "  vertex to the weighted barycentre of its neighbours (one sparse solve).\n"
  "options:\n"
  "  --fixed FILE        fixed vertices: indices in the input file's order, separated by\n"
  "                      white space; '#' starts a comment\n"
  "  --weights uniform|cotangent|mean-value   (default uniform, the paper's; the others are\n"
  "                      computed on the input geometry)\n"
  "  --solver S          sparse solver of the symmetric systems: default (simplicial LDLT below 20k\n"
  "                      unknowns, supernodal Cholesky above), ldlt, supernodal, cholmod\n"
  "  --output OUT.off    the embedded mesh (.off, .ply, .obj...)\n"
  "  --picture OUT.png   picture coloured by how far each vertex moved, rendered with f3d\n"
  "  --up +Y|+Z|...      up direction of the picture (default +Y)\n";

std::vector<Mesh::Vertex_index> read_fixed(const std::string& path, const Mesh& mesh)
{
  std::error_code ec;
  std::ifstream in(path);
  if(!in || std::filesystem::is_directory(path, ec))
    throw example::Usage_error("--fixed: cannot read " + path);
  std::vector<Mesh::Vertex_index> fixed;
  std::string line;
  for(std::size_t number = 1; std::getline(in, line); ++number)
  {
    std::istringstream words(line.substr(0, line.find('#')));
    std::string word;
    while(words >> word)
    {
      const bool digits = word.find_first_not_of("0123456789") == std::string::npos;
      const std::size_t first = digits ? (std::min)(word.find_first_not_of('0'), word.size() - 1) : 0; // leading zeros
      const std::size_t i = digits && word.size() - first < 10 ? std::size_t(std::stoul(word.substr(first))) : std::size_t(-1);
      if(i >= num_vertices(mesh))
      {
        std::string shown; // printable characters only
        for(char c : word.substr(0, 40))
          shown += std::isprint(static_cast<unsigned char>(c)) ? c : '?';
        throw example::Usage_error(path + ":" + std::to_string(number) + ": \"" + shown +
                                   "\" is not a vertex index (the mesh has " + std::to_string(num_vertices(mesh)) +
                                   " vertices)");
      }
      fixed.push_back(Mesh::Vertex_index(Mesh::size_type(i)));
    }
  }
  return fixed;
}

template <class Solver>
std::size_t embed(Mesh& mesh, const std::vector<Mesh::Vertex_index>& fixed, SD::Edge_weighting w,
                  const Solver& solver)
{
  SD::Barycentric_embedder<Mesh, boost::property_map<Mesh, CGAL::vertex_point_t>::type, Solver> embedder(
    mesh, fixed, P::weighting(w, P::sparse_linear_solver(solver)));
  embedder.update();
  return embedder.number_of_free_vertices();
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
    std::string input, fixed_file, output, png, up = "+Y", solver = "default";
    SD::Edge_weighting weighting = SD::Edge_weighting::uniform;
    example::Once once;
    for(int i = 1; i < argc; ++i)
    {
      const std::string a = argv[i];
      auto value = [&] { return example::option_value(argc, argv, i); };
      if(!a.empty() && a[0] == '-')
        once.check(a);
      if(a == "--fixed")
      {
        fixed_file = value();
        if(fixed_file.empty())
          throw example::Usage_error("--fixed needs a file name");
      }
      else if(a == "--output")
        example::check_output_path(output = value(), a, {".off", ".obj", ".ply", ".stl"});
      else if(a == "--picture")
        example::check_output_path(png = value(), a, {".png"});
      else if(a == "--up")
        up = example::parse_choice(value(), a, {"+X", "-X", "+Y", "-Y", "+Z", "-Z"});
      else if(a == "--solver")
        solver = example::parse_choice(value(), a, example::solver_names());
      else if(a == "--weights")
      {
        const std::string w = example::parse_choice(value(), a, {"uniform", "cotangent", "mean-value"});
        weighting = w == "uniform" ? SD::Edge_weighting::uniform
                    : w == "cotangent" ? SD::Edge_weighting::cotangent
                                       : SD::Edge_weighting::mean_value;
      }
      else if(!a.empty() && a[0] == '-')
        throw example::Usage_error("unknown option " + a);
      else if(input.empty())
        input = a;
      else
        throw example::Usage_error("more than one input file: " + input + " and " + a);
    }
    if(input.empty())
      throw example::Usage_error("no input mesh");
    example::check_paths_and_picture({{"INPUT", input}, {"--fixed", fixed_file}, {"--output", output}}, png, once.contains("--up"));

    Mesh mesh = example::read_mesh(input);
    const Mesh original = mesh;
    std::vector<Mesh::Vertex_index> fixed;
    if(!fixed_file.empty())
      fixed = read_fixed(fixed_file, mesh);
    else
    {
      for(auto h : halfedges(mesh))
        if(is_border(h, mesh))
          fixed.push_back(target(h, mesh));
      if(fixed.empty())
        throw example::Usage_error(input + " has no boundary: give the fixed vertices with --fixed");
    }

    example::Stopwatch clock;
    const std::size_t moved = example::with_solver(
      solver, [&](auto traits) { return embed(mesh, fixed, weighting, traits); });
    const double area_before = example::surface_area(original), area_after = example::surface_area(mesh);
    if(!std::isfinite(area_before) || !std::isfinite(area_after))
      throw std::runtime_error("the surface area overflows (coordinates too large for double precision)");
    std::cout << input << ": " << num_vertices(mesh) << " vertices, " << num_faces(mesh) << " faces; " << moved
              << " free vertices moved to the barycentre of their neighbours (" << SD::to_string(weighting)
              << " weights) in " << clock.lap() << " ms; area " << area_before << " -> " << area_after << "\n";

    example::Output_files outputs;
    if(!output.empty())
      example::write_mesh(output, mesh, outputs);
    if(!png.empty())
    {
      std::vector<double> moved_by;
      double largest = 0.;
      for(auto v : vertices(mesh))
      {
        moved_by.push_back(std::sqrt(CGAL::squared_distance(mesh.point(v), original.point(v))));
        largest = (std::max)(largest, moved_by.back());
      }
      example::picture(mesh, moved_by, "displacement", 0., largest > 0. ? largest : 1., png, outputs, up);
    }
    outputs.commit();
    return 0;
  }
  catch(const example::Usage_error& e)
  {
    std::cerr << "barycentric_embed: " << e.what() << "\n(run without arguments for the usage)\n";
    return 1;
  }
  catch(const std::exception& e)
  {
    std::cerr << "barycentric_embed: " << e.what() << "\n";
    return 1;
  }
}
