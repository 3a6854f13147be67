// Harmonic quad remeshing: one call with the default constraints, then the class with chosen
// extrema, its critical points, two edge lengths from one factorization, and the quality.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Surface_design/Harmonic_quad_remesher.h>
#include <CGAL/Surface_design/harmonic_quad_remeshing.h>
#include <CGAL/Surface_design/quad_mesh_quality.h>

#include <cstdio>
#include <string>
#include <utility>
#include <vector>

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;
namespace SD = CGAL::Surface_design;
namespace P = CGAL::Surface_design::parameters;

int main(int argc, char** argv)
{
  const std::string data = argc > 1 ? argv[1] : "data";
  Mesh kitten;
  if(!CGAL::IO::read_polygon_mesh(data + "/kitten.off", kitten))
    return 1;

  // one call: default constraints, about 3000 faces
  Mesh quads;
  const SD::Harmonic_quad_remeshing_result r = SD::harmonic_quad_remeshing(kitten, quads);
  const SD::Quad_mesh_quality q = SD::quad_mesh_quality(quads, kitten);
  std::printf("%zu faces, %.1f%% quads, Hausdorff %.2f%% of the diagonal, in %.3f s\n", q.faces,
              100. * q.quad_fraction, 100. * q.relative_hausdorff_distance,
              r.harmonic_seconds + r.spectacles_seconds + r.curves_seconds + r.meshing_seconds);

  // the class: a minimum and a maximum of our choice, on the intrinsic Delaunay Laplacian
  std::vector<std::pair<Mesh::Vertex_index, double>> extrema = {{Mesh::Vertex_index(0), 0.},
                                                               {Mesh::Vertex_index(5000), 1.}};
  SD::Harmonic_quad_remesher remesher(
    kitten, P::harmonic_constraints(extrema, P::harmonic_weights(SD::Harmonic_weights::intrinsic_delaunay)));
  const SD::Harmonic_critical_points cp = remesher.critical_points();
  std::printf("%zu minima + %zu maxima - %d (saddles) = %ld\n", cp.minima.size(), cp.maxima.size(),
              cp.saddle_multiplicity(), cp.euler_characteristic);
  Mesh coarse, fine; // one factorization serves both
  remesher.remesh(coarse, P::target_edge_length(0.05));
  remesher.remesh(fine, P::target_edge_length(0.02));
  std::printf("h = 0.05: %zu faces, h = 0.02: %zu faces\n", std::size_t(num_faces(coarse)),
              std::size_t(num_faces(fine)));
  return q.valid && q.same_topology && q.quad_fraction > 0.85 && num_faces(fine) > num_faces(coarse) ? 0 : 1;
}
