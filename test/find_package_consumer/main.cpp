// Uses the installed headers: topology of a generated torus, solved with the default solver.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_design/internal/Core/dec.h>
#include <CGAL/Surface_design/internal/Core/Factored_system.h>
#include <CGAL/Surface_design/internal/Core/geometry.h>
#include <CGAL/Surface_design/internal/Core/topology.h>
#include <CGAL/Surface_design/mesh_generators.h>

#include <iostream>

int main()
{
  using Mesh = CGAL::Surface_mesh<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3>;
  namespace SDI = CGAL::Surface_design::internal;
  Mesh mesh;
  CGAL::Surface_design::make_torus(mesh, 12, 6);
  SDI::Mesh_indices<Mesh> idx(mesh);
  const SDI::Topology topo = SDI::compute_topology(idx);
  SDI::Sparse_matrix L = SDI::weighted_laplacian(idx, SDI::cotangent_weights(idx, mesh.points()));
  L.coeffRef(0, 0) += 1.;
  SDI::Factored_system<> system;
  system.factor(std::move(L));
  const Eigen::VectorXd x = system.solve(Eigen::VectorXd::Ones(Eigen::Index(idx.number_of_vertices())));
  std::cout << "genus " << topo.components.info[0].genus() << " generators "
            << topo.tree.generator_loops.size() << " solution norm " << x.norm() << std::endl;
#if defined(CGAL_SURFACE_DESIGN_HAS_CHOLMOD)
  std::cout << "CHOLMOD available" << std::endl;
#endif
  return topo.tree.generator_loops.size() == 2 ? 0 : 1;
}
