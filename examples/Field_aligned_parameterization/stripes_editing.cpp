// Factor once, edit singularities and windings many times: each solve() is one back-substitution.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Surface_design/Field_aligned_parameterizer.h>

#include <iostream>
#include <string>

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;
namespace SD = CGAL::Surface_design;

int main(int argc, char** argv)
{
  const std::string data = argc > 1 ? argv[1] : "data";
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(data + "/bunny_8k.off", mesh))
    return 1;
  auto field = mesh.add_property_map<Mesh::Vertex_index, Kernel::Vector_3>("v:field", Kernel::Vector_3(0, 1, 0)).first;
  auto alpha = mesh.add_property_map<Mesh::Vertex_index, double>("v:alpha").first;

  SD::Field_aligned_parameterizer fap(mesh); // validate, topology, factor: once
  fap.set_field(field, 6.);                  // 6 stripes per unit length
  const Mesh::Face_index a(1598), b(1184), c(355);
  fap.set_index(a, +1);
  fap.set_index(b, -1);
  fap.solve();                               // Figure 2, left
  fap.move_singularity(b, c);
  fap.solve();                               // Figure 2, right
  fap.annihilate(a, c);                      // the pair cancels: plain stripes
  fap.solve();
  fap.alpha(alpha);                          // or dalpha(), corner_coordinates(), energy()

  // windings: on a torus (genus 1) both generator loops are automatic unless prescribed
  Mesh torus;
  if(!CGAL::IO::read_polygon_mesh(data + "/torus.off", torus))
    return 1;
  auto along = torus.add_property_map<Mesh::Vertex_index, Kernel::Vector_3>("v:field", Kernel::Vector_3(1, 0, 0)).first;
  SD::Field_aligned_parameterizer on_torus(torus);
  on_torus.set_field(along, 2.);
  on_torus.solve();                          // automatic windings (Figure 3, left)
  on_torus.set_loop_winding(0, 8);           // alpha turns 8 times along loop 0
  on_torus.solve();                          // loop 1 stays automatic (Figure 3, right)
  for(std::size_t l = 0; l < on_torus.number_of_loops(); ++l)
    std::cout << "loop " << l << ": " << on_torus.loop(l).size() << " halfedges, winding "
              << on_torus.loop_winding(l) << '\n';
  return on_torus.loop_winding(0) == 8 ? 0 : 1;
}
