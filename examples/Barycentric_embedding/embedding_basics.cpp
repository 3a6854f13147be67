// Barycentric embedding: one call with the boundary fixed, weights of a reference geometry, and
// a factor-once deformation of the paper's octahedron (Table 2).
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Surface_design/Barycentric_embedder.h>
#include <CGAL/Surface_design/barycentric_embedding.h>
#include <CGAL/Surface_design/octahedron_membrane.h>

#include <iostream>
#include <string>
#include <vector>

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;
namespace SD = CGAL::Surface_design;
namespace P = CGAL::Surface_design::parameters;

int main(int argc, char** argv)
{
  const std::string data = argc > 1 ? argv[1] : "data";
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(data + "/hemisphere.off", mesh))
    return 1;

  // one call: fix the boundary, move every other vertex to the barycentre of its neighbours
  std::vector<Mesh::Vertex_index> fixed; // or a vertex -> bool property map
  for(auto h : halfedges(mesh))
    if(is_border(h, mesh))
      fixed.push_back(target(h, mesh));
  const Mesh original = mesh;
  SD::barycentric_embedding(mesh, fixed); // uniform weights, the paper's

  // mean-value weights of the original geometry, another solver
  mesh = original;
  SD::barycentric_embedding(mesh, fixed,
                            P::weighting(SD::Edge_weighting::mean_value,
                                         P::reference_point_map(original.points(),
                                                                P::sparse_linear_solver(SD::Default_solver_traits()))));

  // factor once, deform many times (the paper's Table 2)
  Mesh octahedron;
  const auto loops = SD::make_octahedron_membrane(octahedron, 6); // L1..L6
  std::vector<Mesh::Vertex_index> all_loops;
  for(const auto& loop : loops)
    all_loops.insert(all_loops.end(), loop.begin(), loop.end());
  SD::Barycentric_embedder embedder(octahedron, all_loops); // factors
  embedder.update();                                        // solves, writes
  for(int step = 0; step < 10; ++step)
  {
    for(auto v : loops[0])
      octahedron.point(v) = octahedron.point(v) + Kernel::Vector_3(0, 0, -0.3);
    for(auto v : loops[1])
      octahedron.point(v) = octahedron.point(v) + Kernel::Vector_3(0, 0, +0.3);
    embedder.update();                                      // 3 back-substitutions
  }
  std::cout << embedder.number_of_free_vertices() << " free vertices, barycentre residual "
            << embedder.barycentre_residual() << '\n';
  return embedder.barycentre_residual() < 1e-9 ? 0 : 1;
}
