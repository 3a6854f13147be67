// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// barycentric_embed: barycentric ("nice") embedding of any polygon mesh. The boundary loops (or
// the vertices listed in a file) stay fixed; every other vertex moves to the weighted barycentre
// of its neighbours. Run without arguments for the usage.

#include "embedding_support.h"

#include <CGAL/Surface_design/Barycentric_embedder.h>
#include <CGAL/Surface_design/barycentric_embedding.h>

#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>

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
  "  --solver ldlt|cholmod   sparse solver of the symmetric systems (default ldlt)\n"
  "  --output OUT.off    the embedded mesh (.off, .ply, .obj...)\n"
  "  --picture OUT.png   picture coloured by how far each vertex moved, rendered with f3d\n"
  "  --up +Y|+Z|...      up direction of the picture (default +Y)\n";

std::vector<Mesh::Vertex_index> read_fixed(const std::string& path, const Mesh& mesh)
{
  std::ifstream in(path);
  if(!in)
    throw std::runtime_error("cannot read " + path);
  std::vector<Mesh::Vertex_index> fixed;
  std::string line;
  for(std::size_t number = 1; std::getline(in, line); ++number)
  {
    std::istringstream words(line.substr(0, line.find('#')));
    std::string word;
    while(words >> word)
    {
      const bool digits = word.size() < 10 && word.find_first_not_of("0123456789") == std::string::npos;
      const std::size_t i = digits ? std::size_t(std::stoul(word)) : std::size_t(-1);
      if(i >= num_vertices(mesh))
        throw example::Usage_error(path + ":" + std::to_string(number) + ": \"" + word +
                                    "\" is not a vertex index (the mesh has " +
                                    std::to_string(num_vertices(mesh)) + " vertices)");
      fixed.push_back(Mesh::Vertex_index(Mesh::size_type(i)));
    }
  }
  return fixed;
}

template <class Solver>
std::size_t embed(Mesh& mesh, const std::vector<Mesh::Vertex_index>& fixed, SD::Edge_weighting w)
{
  SD::Barycentric_embedder<Mesh, boost::property_map<Mesh, CGAL::vertex_point_t>::type, Solver> embedder(
    mesh, fixed, P::weighting(w));
  embedder.update();
  return embedder.number_of_free_vertices();
}

} // namespace

int main(int argc, char** argv)
{
  try
  {
    if(argc < 2)
    {
      std::cerr << usage;
      return 1;
    }
    std::string input = argv[1], fixed_file, output, png, up = "+Y", solver = "ldlt";
    SD::Edge_weighting weighting = SD::Edge_weighting::uniform;
    for(int i = 2; i < argc; ++i)
    {
      const std::string a = argv[i];
      auto value = [&] { return example::option_value(argc, argv, i); };
      if(a == "--fixed")
        fixed_file = value();
      else if(a == "--output")
        output = value();
      else if(a == "--picture")
        png = value();
      else if(a == "--up")
        up = value();
      else if(a == "--solver")
        solver = value();
      else if(a == "--weights")
      {
        const std::string w = value();
        if(w == "uniform")
          weighting = SD::Edge_weighting::uniform;
        else if(w == "cotangent")
          weighting = SD::Edge_weighting::cotangent;
        else if(w == "mean-value")
          weighting = SD::Edge_weighting::mean_value;
        else
          throw example::Usage_error("--weights is uniform, cotangent or mean-value, not " + w);
      }
      else
        throw example::Usage_error("unknown option " + a + "\n" + usage);
    }

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
      solver, [&](auto traits) { return embed<decltype(traits)>(mesh, fixed, weighting); });
    std::cout << input << ": " << num_vertices(mesh) << " vertices, " << num_faces(mesh) << " faces; "
              << moved << " free vertices moved to the barycentre of their neighbours ("
              << SD::to_string(weighting) << " weights) in " << clock.lap() << " ms; area "
              << example::surface_area(original) << " -> " << example::surface_area(mesh) << "\n";

    if(!output.empty())
    {
      if(!CGAL::IO::write_polygon_mesh(output, mesh, CGAL::parameters::stream_precision(17)))
        throw std::runtime_error("cannot write " + output);
      std::cout << "wrote " << output << "\n";
    }
    if(!png.empty())
    {
      std::vector<double> moved_by;
      double largest = 0.;
      for(auto v : vertices(mesh))
      {
        moved_by.push_back(std::sqrt(CGAL::squared_distance(mesh.point(v), original.point(v))));
        largest = (std::max)(largest, moved_by.back());
      }
      const std::string vtk = png.substr(0, png.rfind('.')) + ".vtk";
      if(example::picture(mesh, moved_by, "displacement", 0., largest > 0. ? largest : 1., vtk, png, up))
        std::cout << "wrote " << png << "\n";
    }
    return 0;
  }
  catch(const std::exception& e)
  {
    std::cerr << "barycentric_embed: " << e.what() << "\n";
    return 1;
  }
}
