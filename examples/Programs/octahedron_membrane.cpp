// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// octahedron_membrane: the example surface of Imafuji & Ochiai (Fig. 2, Table 1). An octahedron
// whose six vertices are circular holes (loops L1..L6 in the planes z, x, y = +-3) and whose faces
// are hexagons triangulated with m segments per side; the loops are fixed, every other vertex goes
// to the barycentre of its neighbours in one sparse solve.

#include "common/embedding_support.h"
#include "common/option_parser.h"

#include <CGAL/Surface_design/barycentric_embedding.h>
#include <CGAL/Surface_design/mesh_generators.h>
#include <CGAL/Surface_design/octahedron_membrane.h>

#include <cstdio>
#include <iostream>
#include <string>
#include <vector>

namespace SD = CGAL::Surface_design;
using program::Mesh;

namespace {

const char* usage =
  "usage: octahedron_membrane --m M --radius R [options]\n"
  "  M: segments per hexagon side, 1..100; R: radius of the loops, in [3e-6, 3)\n"
  "  The octahedron surface of Imafuji & Ochiai: 6 circular loops of radius R in the planes\n"
  "  z = 3, z = -3, x = 3, y = 3, x = -3, y = -3 (centred on the axes), 8 hexagons with M\n"
  "  segments per side; the loops are fixed, the other vertices at the barycentre of their\n"
  "  neighbours. Prints: vertices V triangles T area A\n"
  "options:\n"
  "  --placement equal|radial  loop vertices at equal angles (default) or the truncated\n"
  "                            octahedron's lattice points projected radially on the circle\n"
  "  --iterative               also run the paper's iterative method 2 (until the area changes\n"
  "                            by < 1e-6) from the flat starting positions; prints its steps\n"
  "  --output OUT.off          write the surface (.off, .obj, .ply, .stl)\n"
  "  --picture OUT.png         picture of the surface, rendered with f3d\n";

} // namespace

int main(int argc, char** argv)
{
  if(argc < 2)
  {
    std::cerr << usage;
    return 1;
  }
  try
  {
    std::size_t m = 0;
    double radius = 0.;
    bool iterative = false;
    std::string output, png;
    SD::Octahedron_loop_placement placement = SD::Octahedron_loop_placement::equal_angles;
    program::Option_parser p;
    p.value("--m", [&](const std::string& v) { m = program::parse_count(v, "--m", 100); })
      .value("--radius", [&](const std::string& v) { radius = program::parse_double(v, "--radius"); })
      .output("--output", output, {".off", ".obj", ".ply", ".stl"})
      .output("--picture", png, {".png"})
      .flag("--iterative", [&] { iterative = true; })
      .value("--placement",
             [&](const std::string& v) {
               placement = program::parse_choice(v, "--placement", {"equal", "radial"}) == "equal"
                             ? SD::Octahedron_loop_placement::equal_angles
                             : SD::Octahedron_loop_placement::radial_projection;
             })
      .parse(argc, argv);
    if(m == 0)
      throw program::Usage_error("--m M (segments per hexagon side, 1..100) is required");
    if(!p.given("--radius"))
      throw program::Usage_error("--radius R is required");
    // the loops lie in the planes at distance 3: two of them meet when R >= 3 (a loop leaves its
    // face of the cube [-3, 3]^3 and cuts its neighbours), and below 1e-6 the triangles at the
    // loops are numerically degenerate
    if(!(radius >= 3e-6 && radius < 3.))
      throw program::Usage_error("--radius must lie in [3e-6, 3): the loops lie in the planes at distance 3 and "
                                 "would meet at R >= 3; got " + program::text(radius));
    if(iterative && m > 30)
      throw program::Usage_error("--iterative needs m <= 30 (its steps grow like m^4); got " + std::to_string(m));
    program::check_paths_and_picture({{"--output", output}}, png, false);

    Mesh mesh;
    const auto loops = SD::make_octahedron_membrane(mesh, m, radius, 3., placement);
    std::vector<Mesh::Vertex_index> fixed;
    for(const auto& loop : loops)
      fixed.insert(fixed.end(), loop.begin(), loop.end());
    Mesh flat = mesh; // the starting positions of the iterative method

    program::Stopwatch clock;
    SD::barycentric_embedding(mesh, fixed);
    const double direct_ms = clock.lap();
    std::printf("vertices %zu triangles %zu area %.6f\n", std::size_t(num_vertices(mesh)),
                std::size_t(num_faces(mesh)), program::surface_area(mesh));
    std::fprintf(stderr, "direct solve: %.3f ms\n", direct_ms);

    if(iterative)
    {
      clock.lap();
      const SD::Iterative_embedding_result r = SD::barycentric_embedding_iterative(flat, fixed);
      const double ms = clock.lap();
      double gap = 0.;
      for(auto v : vertices(mesh))
        gap = (std::max)(gap, std::sqrt(CGAL::squared_distance(mesh.point(v), flat.point(v))));
      // the paper's criterion (the area changes by < 1e-6 in one step) can stop the Jacobi
      // iteration far from its limit on fine meshes: say so
      std::printf("iterative iterations %zu area %.6f max-distance-to-direct %.3g%s\n", r.iterations, r.area, gap,
                  !r.converged ? " (not converged)"
                               : gap > 1e-3 * radius ? " (stopped by the area criterion far from the limit)" : "");
      std::fprintf(stderr, "iterative: %.3f ms (%.1f x the direct solve)\n", ms, ms / direct_ms);
    }
    program::Output_files outputs;
    if(!output.empty())
      program::write_mesh(output, mesh, outputs);
    if(!png.empty())
    {
      std::vector<double> height;
      for(auto v : vertices(mesh))
        height.push_back(mesh.point(v).z());
      program::picture(mesh, height, "z", -3., 3., png, outputs);
    }
    outputs.commit();
    return 0;
  }
  catch(const program::Usage_error& e)
  {
    std::cerr << "octahedron_membrane: " << e.what() << "\n(run without arguments for the usage)\n";
    return 1;
  }
  catch(const std::exception& e)
  {
    std::cerr << "octahedron_membrane: " << e.what() << "\n";
    return 1;
  }
}
