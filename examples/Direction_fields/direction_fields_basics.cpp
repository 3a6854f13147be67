// A smoothest cross field aligned with the principal curvature directions, its singularities,
// and a vector field with exactly the singularities we ask for (trivial connection).
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Surface_design/direction_fields.h>
#include <CGAL/Surface_design/Trivial_connection.h>

#include <iostream>
#include <string>

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;
namespace SD = CGAL::Surface_design;
namespace P = CGAL::Surface_design::parameters;

int main(int argc, char** argv)
{
  const std::string data = argc > 1 ? argv[1] : "data";
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(data + "/bunny_8k.off", mesh))
    return 1;

  // smoothest cross field (n = 4), aligned to the principal curvature directions
  auto field = mesh.add_property_map<Mesh::Vertex_index, Kernel::Vector_3>("v:field").first;
  const SD::Smoothest_direction_field_result info =
    SD::smoothest_direction_field(mesh, field, P::symmetry_order(4, P::curvature_alignment_weight(0.1)));

  // its singularities: integers k, the index being k / 4
  auto index = mesh.add_property_map<Mesh::Face_index, int>("f:index").first;
  const std::size_t singular = SD::direction_field_singularities(mesh, field, index, P::symmetry_order(4));

  // a vector field with exactly two +1 singularities (their sum is the Euler characteristic, 2)
  SD::Trivial_connection tc(mesh); // factors once
  tc.set_index(std::size_t(10), 1);
  tc.set_index(std::size_t(3000), 1);
  tc.solve(); // O(|E|) plus one back-substitution
  tc.field(field);
  tc.move_singularity(Mesh::Face_index(3000), Mesh::Face_index(3001));
  tc.solve(); // again linear time: interactive editing
  tc.field(field);
  const std::size_t prescribed = SD::direction_field_singularities(mesh, field, index);

  std::cout << "cross field: " << singular << " singular faces (" << info.iterations << " Lanczos steps); "
            << "trivial connection: " << prescribed << " singular faces, index at 3001: " << index[Mesh::Face_index(3001)]
            << '\n';
  return prescribed == 2 && index[Mesh::Face_index(3001)] == 1 ? 0 : 1;
}
