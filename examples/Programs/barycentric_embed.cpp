// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// barycentric_embed: barycentric ("nice") embedding of any polygon mesh. The boundary loops (or
// the vertices listed in a file) stay fixed; every other vertex moves to the weighted barycentre
// of its neighbours. Run without arguments for the usage.

#include "common/embedding_support.h"
#include "common/option_parser.h"

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
using program::Mesh;

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
    throw program::Usage_error("--fixed: cannot read " + path);
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
        throw program::Usage_error(path + ":" + std::to_string(number) + ": \"" + shown +
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
    program::Option_parser p;
    p.input(input)
      .value("--fixed",
             [&](const std::string& v) {
               if((fixed_file = v).empty())
                 throw program::Usage_error("--fixed needs a file name");
             })
      .output("--output", output, {".off", ".obj", ".ply", ".stl"})
      .picture(png, up)
      .solver(solver)
      .value("--weights",
             [&](const std::string& v) {
               const std::string w = program::parse_choice(v, "--weights", {"uniform", "cotangent", "mean-value"});
               weighting = w == "uniform" ? SD::Edge_weighting::uniform
                           : w == "cotangent" ? SD::Edge_weighting::cotangent
                                              : SD::Edge_weighting::mean_value;
             })
      .parse(argc, argv);
    program::check_paths_and_picture({{"INPUT", input}, {"--fixed", fixed_file}, {"--output", output}}, png, p.given("--up"));

    Mesh mesh = program::read_mesh(input);
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
        throw program::Usage_error(input + " has no boundary: give the fixed vertices with --fixed");
    }

    program::Stopwatch clock;
    const std::size_t moved = program::with_solver(
      solver, [&](auto traits) { return embed(mesh, fixed, weighting, traits); });
    const double area_before = program::surface_area(original), area_after = program::surface_area(mesh);
    if(!std::isfinite(area_before) || !std::isfinite(area_after))
      throw std::runtime_error("the surface area overflows (coordinates too large for double precision)");
    std::cout << input << ": " << num_vertices(mesh) << " vertices, " << num_faces(mesh) << " faces; " << moved
              << " free vertices moved to the barycentre of their neighbours (" << SD::to_string(weighting)
              << " weights) in " << clock.lap() << " ms; area " << area_before << " -> " << area_after << "\n";

    program::Output_files outputs;
    if(!output.empty())
      program::write_mesh(output, mesh, outputs);
    if(!png.empty())
    {
      std::vector<double> moved_by;
      double largest = 0.;
      for(auto v : vertices(mesh))
      {
        moved_by.push_back(std::sqrt(CGAL::squared_distance(mesh.point(v), original.point(v))));
        largest = (std::max)(largest, moved_by.back());
      }
      program::picture(mesh, moved_by, "displacement", 0., largest > 0. ? largest : 1., png, outputs, up);
    }
    outputs.commit();
    return 0;
  }
  catch(const program::Usage_error& e)
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
