// One call: stripes along a constant direction on the bunny, with a +1/-1 pair of singularities.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Surface_design/field_aligned_parameterization.h>

#include <iostream>
#include <string>

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;
namespace SD = CGAL::Surface_design;

int main(int argc, char** argv)
{
  const std::string data = argc > 1 ? argv[1] : "data";
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(data + "/bunny_8k.off", mesh)) // faces keep the file's order
    return 1;
  auto field = mesh.add_property_map<Mesh::Vertex_index, Kernel::Vector_3>("v:field", Kernel::Vector_3(0, 1, 0)).first;
  auto k = mesh.add_property_map<Mesh::Face_index, int>("f:index", 0).first;
  auto alpha = mesh.add_property_map<Mesh::Vertex_index, double>("v:alpha").first;
  k[Mesh::Face_index(1598)] = +1; // on a closed surface the indices sum to 0
  k[Mesh::Face_index(1184)] = -1;
  const double energy =
    SD::field_aligned_parameterization(mesh, field, k, alpha, SD::parameters::stripes_per_unit_length(2.));

  auto found = mesh.add_property_map<Mesh::Face_index, int>("f:found", 0).first;
  std::cout << "energy " << energy << ", singular faces of alpha: " << SD::stripe_singularities(mesh, alpha, found)
            << " (+1 at 1598: " << found[Mesh::Face_index(1598)] << ")\n";
  return found[Mesh::Face_index(1598)] == 1 && found[Mesh::Face_index(1184)] == -1 ? 0 : 1;
}
