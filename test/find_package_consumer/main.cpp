// Uses the installed public headers only: stripes on a generated torus, solved with the default
// solver, and (when the installed package was built with them) CHOLMOD and TBB.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_design/developability.h>
#include <CGAL/Surface_design/Field_aligned_parameterizer.h>
#include <CGAL/Surface_design/mesh_generators.h>

#include <iostream>

int main()
{
  using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
  using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;
  namespace SD = CGAL::Surface_design;
  Mesh mesh;
  SD::make_torus(mesh, 24, 12);
  auto field = mesh.add_property_map<Mesh::Vertex_index, Kernel::Vector_3>("v:field", Kernel::Vector_3(1, 0, 0)).first;
  SD::Field_aligned_parameterizer fap(mesh);
  fap.set_field(field, 1.);
  fap.solve();
  const double energy = SD::developability_energy(mesh);
  std::cout << "genus " << fap.genus(0) << " generators " << fap.number_of_generator_loops() << " stripe energy "
            << fap.energy() << " developability " << energy << std::endl;
#if defined(CGAL_SURFACE_DESIGN_HAS_CHOLMOD)
  std::cout << "CHOLMOD available" << std::endl;
#endif
#if defined(CGAL_LINKED_WITH_TBB)
  std::cout << "TBB available" << std::endl;
#endif
  return fap.number_of_generator_loops() == 2 && energy > 0. ? 0 : 1;
}
