// One ordering and symbolic analysis for the systems of one mesh: the smoothest vector field (a
// complex Hermitian system) and the stripes along it (a real one) have the same pattern, so with a
// shared Symbolic_analysis_cache the second factorization skips the ordering and the analysis.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_design/direction_fields.h>
#include <CGAL/Surface_design/Field_aligned_parameterizer.h>
#include <CGAL/Surface_design/mesh_generators.h>
#include <CGAL/Surface_design/solver_traits.h>

#include <iostream>
#include <memory>
#include <vector>

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;
namespace SD = CGAL::Surface_design;
namespace P = CGAL::Surface_design::parameters;

int main()
{
  Mesh sphere;
  SD::make_sphere(sphere, 60); // 43200 triangles, 21602 vertices: the default solver goes supernodal

  // one solver per system (copies of a traits object share its factorization), one cache for both
  auto cache = std::make_shared<SD::Symbolic_analysis_cache>();
  SD::Default_solver_traits field_solver, stripe_solver;
  field_solver.solver().set_analysis_cache(cache);
  stripe_solver.solver().set_analysis_cache(cache);

  std::vector<Kernel::Vector_3> field(num_vertices(sphere));
  SD::smoothest_direction_field(sphere, CGAL::make_property_map(field), P::sparse_linear_solver(field_solver));
  SD::Field_aligned_parameterizer stripes(sphere, P::sparse_linear_solver(stripe_solver));
  stripes.set_field(CGAL::make_property_map(field), 4.);
  stripes.solve();

  std::cout << "systems factored: 2, orderings and analyses: " << cache->size() << " (" << cache->hits()
            << " reused)\n";
  return cache->size() == 1 && cache->hits() == 1 ? 0 : 1;
}
