// A Polyhedron_3 with boundary, several outputs at once, CHOLMOD when available; the named
// parameters of the library nest through their second argument.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Polyhedron_items_with_id_3.h>
#include <CGAL/boost/graph/graph_traits_Polyhedron_3.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/property_map.h>
#include <CGAL/Surface_design/field_aligned_parameterization.h>

#include <iostream>
#include <map>
#include <string>

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Polyhedron_3<Kernel, CGAL::Polyhedron_items_with_id_3>;
using V = boost::graph_traits<Mesh>::vertex_descriptor;
using E = boost::graph_traits<Mesh>::edge_descriptor;
using H = boost::graph_traits<Mesh>::halfedge_descriptor;
using F = boost::graph_traits<Mesh>::face_descriptor;
namespace SD = CGAL::Surface_design;
namespace P = CGAL::Surface_design::parameters;

#if defined(CGAL_SURFACE_DESIGN_HAS_CHOLMOD)
using Solver = SD::Cholmod_solver_traits;
#else
using Solver = SD::Default_solver_traits;
#endif

int main(int argc, char** argv)
{
  const std::string data = argc > 1 ? argv[1] : "data";
  Mesh shark; // four boundary loops
  if(!CGAL::IO::read_polygon_mesh(data + "/mech-holes-shark.off", shark))
    return 1;
  CGAL::Constant_property_map<V, Kernel::Vector_3> field(Kernel::Vector_3(1, 0, 0));
  F singular = *faces(shark).begin(); // a face with no edge on the boundary
  for(F f : faces(shark))
  {
    bool boundary_edge = false;
    for(H h : halfedges_around_face(halfedge(f, shark), shark))
      boundary_edge = boundary_edge || is_border(opposite(h, shark), shark);
    if(!boundary_edge)
    {
      singular = f;
      break;
    }
  }
  std::map<F, int> k;
  k[singular] = 1; // a sum of 1 is allowed: the boundary windings absorb it
  std::map<V, double> alpha;
  std::map<E, double> dalpha;
  std::map<H, double> u;
  const double energy = SD::field_aligned_parameterization(
    shark, field, boost::make_assoc_property_map(k), boost::make_assoc_property_map(alpha),
    P::stripes_per_unit_length(4.,
      P::loop_windings(std::map<std::size_t, int>{{0, 1}},          // boundary loop 0: winding 1
        P::edge_dalpha_map(boost::make_assoc_property_map(dalpha),
          P::corner_coordinate_map(boost::make_assoc_property_map(u),
            P::sparse_linear_solver(Solver()))))));
  std::map<F, int> curl; // == k, exactly: the curl of dalpha
  SD::one_form_singularities(shark, boost::make_assoc_property_map(dalpha), boost::make_assoc_property_map(curl));
  std::cout << "energy " << energy << ", curl in the singular face " << curl[singular] << '\n';
  return curl[singular] == 1 ? 0 : 1;
}
