// Developability: the energy of a mesh and of each vertex star, the flow to a piecewise
// developable design with a visitor, and the metrics of the result.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Surface_design/developability.h>

#include <cstdio>
#include <string>

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;
namespace SD = CGAL::Surface_design;
namespace P = CGAL::Surface_design::parameters;

int main(int argc, char** argv)
{
  const std::string file = argc > 1 ? argv[1] : "data/pebble_1k.off";
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(file, mesh))
    return 1;
  const Mesh input = mesh;

  // the energy (default: covariance E^lambda), and each star's share of it
  auto star_energy = mesh.add_property_map<Mesh::Vertex_index, double>("v:energy", 0.).first;
  const double before = SD::developability_energy(mesh, P::vertex_energy_map(star_energy));

  // the flow: intrinsic width energy, two 4-1 subdivisions, a progress line per 500 iterations
  const SD::Developability_flow_result result = SD::make_piecewise_developable(
    mesh, P::developability_energy(SD::Developability_energy::intrinsic_width,
                                   P::number_of_subdivisions(std::size_t(2)))
            .visitor([](const SD::Developability_iteration& it) {
              if(it.level_iteration % 500 == 0)
                std::printf("level %zu, iteration %zu: energy %g\n", it.level, it.level_iteration, it.energy);
              return true; // false stops the flow
            }));

  // what came out: hinges, seams, distance to the input
  const SD::Developability_metrics m = SD::developability_metrics(mesh, input);
  std::printf("%zu iterations in %.1f s; hinges %.1f%%, %zu seam curves, Hausdorff %.3f\n", result.iterations,
              result.total_seconds, 100. * m.hinge_share_1e4, m.seam_curves, m.hausdorff_distance);
  return before > 0. && m.hinge_share_1e4 > 0.8 && m.hausdorff_distance < 0.06 ? 0 : 1;
}
