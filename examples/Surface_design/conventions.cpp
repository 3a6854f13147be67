// The conventions every package shares, on the least convenient mesh type (Polyhedron_3 without
// ids): classes take the mesh and named parameters, indices are integers in units of 1/n,
// element numbers follow the index maps, and bad input throws a documented exception.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/boost/graph/graph_traits_Polyhedron_3.h>
#include <CGAL/Surface_design/direction_fields.h>
#include <CGAL/Surface_design/exceptions.h>
#include <CGAL/Surface_design/Field_aligned_parameterizer.h>
#include <CGAL/Surface_design/mesh_generators.h>
#include <CGAL/Surface_design/Trivial_connection.h>

#include <iostream>
#include <map>

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Polyhedron_3<Kernel>; // no ids: the library builds dynamic index maps
using V = boost::graph_traits<Mesh>::vertex_descriptor;
using F = boost::graph_traits<Mesh>::face_descriptor;
namespace SD = CGAL::Surface_design;
namespace P = CGAL::Surface_design::parameters;

int main()
{
  Mesh torus;
  SD::make_torus(torus, 40, 12, 1., 0.3, /*staggered=*/true); // genus 1, all angles acute

  // 1. A class takes the mesh and named parameters; the types follow from them.
  std::map<V, Kernel::Vector_3> field;
  SD::Trivial_connection tc(torus, P::symmetry_order(4, P::sparse_linear_solver(SD::Default_solver_traits())));
  std::map<F, int> index; // 2. an index is an int k: k / n turns (here +1/4 and -1/4)
  const F a = *faces(torus).begin(), b = *std::next(faces(torus).begin(), 500);
  index[a] = 1;
  index[b] = -1;
  tc.set_indices(boost::make_assoc_property_map(index));
  tc.solve();
  tc.field(boost::make_assoc_property_map(field));
  std::map<F, int> found;
  SD::direction_field_singularities(torus, boost::make_assoc_property_map(field), boost::make_assoc_property_map(found),
                                    P::symmetry_order(4));
  std::cout << "cross field: index " << found[a] << "/4 at a, " << found[b] << "/4 at b\n";

  // 3. Stripes along that field: one factorization, then any number of solves.
  SD::Field_aligned_parameterizer fap(torus, P::weighting(SD::Edge_weighting::cotangent));
  fap.set_field(boost::make_assoc_property_map(field), 3.);
  fap.solve();
  std::cout << fap.number_of_generator_loops() << " generator loops, windings " << fap.loop_winding(0) << " and "
            << fap.loop_winding(1) << '\n';

  // 4. Errors: a documented exception naming what is wrong; nothing is modified.
  try
  {
    fap.set_field(boost::make_assoc_property_map(field), -1.);
  }
  catch(const SD::Invalid_parameter& e)
  {
    std::cout << "refused: " << e.what() << '\n';
  }
  try
  {
    fap.set_index(std::size_t(1), 1); // a single +1 on a closed surface violates Stokes' theorem
    fap.solve();
  }
  catch(const SD::Invalid_constraints& e)
  {
    std::cout << "refused: " << e.what() << '\n';
  }
  return found[a] == 1 && found[b] == -1 ? 0 : 1;
}
