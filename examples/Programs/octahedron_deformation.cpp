// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// octahedron_deformation: the deformation of Imafuji & Ochiai (Fig. 6, Table 2). Loops L1 (z = 3)
// and L2 (z = -3) move towards each other by 0.3 per step for 10 steps, until they meet. The
// system is factored once; every step is one update() (three back-substitutions). Writes every
// frame and a picture of frames 0, 5 and 10, and compares with the paper's iterative method.

#include "common/embedding_support.h"
#include "common/option_parser.h"

#include <CGAL/Surface_design/Barycentric_embedder.h>
#include <CGAL/Surface_design/barycentric_embedding.h>
#include <CGAL/Surface_design/mesh_generators.h>
#include <CGAL/Surface_design/octahedron_membrane.h>

#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>

#include <cstdio>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

namespace SD = CGAL::Surface_design;
using program::Mesh;
using program::Point;

namespace {

const char* usage =
  "usage: octahedron_deformation --out-dir DIR [--m M] [--radius R] [--steps N] [--step D]\n"
  "                              [--no-iterative]\n"
  "  Table 2 / Fig. 6 of Imafuji & Ochiai: L1 and L2 move towards each other by D per step\n"
  "  (defaults: m 6 as in Fig. 2 (1..100), R 1 (at most 1.5), 10 steps of 0.3; steps times step\n"
  "  at most 3: the loops meet at z = 0). Writes DIR/frame_XX.off and DIR/deformation_{0,5,10}.png\n"
  "  (pictures with f3d).\n";

} // namespace

int main(int argc, char** argv)
{
  try
  {
    std::size_t m = 6, steps = 10;
    double radius = 1., step = 0.3;
    std::string dir;
    bool iterative = true;
    program::Option_parser()
      .value("--m", [&](const std::string& v) { m = program::parse_count(v, "--m", 100); })
      .value("--radius", [&](const std::string& v) { radius = program::parse_double(v, "--radius"); })
      .value("--steps", [&](const std::string& v) { steps = program::parse_count(v, "--steps", 1000); })
      .value("--step", [&](const std::string& v) { step = program::parse_positive(v, "--step"); })
      .value("--out-dir", [&](const std::string& v) { dir = v; })
      .flag("--no-iterative", [&] { iterative = false; })
      .parse(argc, argv);
    if(dir.empty())
      throw program::Usage_error("--out-dir DIR (an existing, writable folder for the frames) is required");
    namespace fs = std::filesystem;
    std::error_code ec;
    if(!fs::is_directory(dir, ec) || access(dir.c_str(), W_OK) != 0)
      throw program::Usage_error("--out-dir: \"" + dir + "\" is not an existing, writable folder");
    // Larger loops fold the surface over a moving loop in the middle frames (first seen at
    // R = 1.6 for m = 8, 12); the loops start at z = +-3 and meet at z = 0.
    if(!(radius >= 3e-6 && radius <= 1.5))
      throw program::Usage_error("--radius must lie in [3e-6, 1.5] (larger loops fold the surface while they move); got " +
                                 program::text(radius));
    if(double(steps) * step > 3. + 1e-12)
      throw program::Usage_error("--steps times --step must be at most 3: L1 and L2 start at z = 3 and -3 and meet at "
                                 "z = 0; got " + program::text(double(steps) * step));
    if(iterative && m > 30)
      throw program::Usage_error("the iterative comparison needs m <= 30 (its steps grow like m^4): give --no-iterative");

    Mesh mesh;
    const auto loops = SD::make_octahedron_membrane(mesh, m, radius);
    std::vector<Mesh::Vertex_index> fixed;
    for(const auto& loop : loops)
      fixed.insert(fixed.end(), loop.begin(), loop.end());
    Mesh reference = mesh; // for the iterative method, which restarts from the previous frame

    program::Stopwatch clock;
    SD::Barycentric_embedder<Mesh> embedder(mesh, fixed); // Table 2, process 1 (factorization)
    const double factor_ms = clock.lap();
    embedder.update();
    double update_ms = clock.lap(), iterative_ms = 0.;
    std::size_t iterations = 0;
    if(iterative)
    {
      const auto r = SD::barycentric_embedding_iterative(reference, fixed);
      iterative_ms += clock.lap();
      iterations += r.iterations;
    }
    std::printf("vertices %zu triangles %zu; factor %.3f ms\n", std::size_t(num_vertices(mesh)),
                std::size_t(num_faces(mesh)), factor_ms);
    std::printf("frame  0: area %.6f\n", program::surface_area(mesh));

    program::Output_files outputs;
    const bool pictures = program::on_path("f3d") && (std::getenv("DISPLAY") != nullptr || program::on_path("xvfb-run"));
    if(!pictures)
      std::cout << "note: no pictures (they need f3d and xvfb: apt-get install f3d xvfb xauth)\n";
    auto write_frame = [&](std::size_t k) {
      char name[64];
      std::snprintf(name, sizeof name, "/frame_%02zu.off", k);
      program::write_mesh(dir + name, mesh, outputs);
      if(pictures && (k == 0 || 2 * k == steps || k == steps))
      {
        std::vector<double> height;
        for(auto v : vertices(mesh))
          height.push_back(mesh.point(v).z());
        program::picture(mesh, height, "z", -3., 3., dir + "/deformation_" + std::to_string(k) + ".png", outputs);
      }
    };
    write_frame(0);
    double worst_gap = 0.;
    for(std::size_t k = 1; k <= steps; ++k)
    {
      // Table 2, process 2: new fixed positions, then the solve
      auto vpm = get(CGAL::vertex_point, mesh);
      for(int l = 0; l < 2; ++l)
        for(auto v : loops[std::size_t(l)])
        {
          const Point p = get(vpm, v);
          put(vpm, v, Point(p.x(), p.y(), p.z() + (l == 0 ? -step : step)));
          put(get(CGAL::vertex_point, reference), v, Point(p.x(), p.y(), p.z() + (l == 0 ? -step : step)));
        }
      clock.lap();
      embedder.update();
      update_ms += clock.lap();
      if(iterative)
      {
        const auto r = SD::barycentric_embedding_iterative(reference, fixed);
        iterative_ms += clock.lap();
        iterations += r.iterations;
        for(auto v : vertices(mesh))
          worst_gap = (std::max)(worst_gap, std::sqrt(CGAL::squared_distance(mesh.point(v), reference.point(v))));
      }
      std::printf("frame %2zu: L1 at z = %+.1f, L2 at z = %+.1f, area %.6f\n", k,
                  mesh.point(loops[0][0]).z(), mesh.point(loops[1][0]).z(), program::surface_area(mesh));
      write_frame(k);
    }
    std::printf("direct: factor %.3f ms + %zu updates %.3f ms = %.3f ms\n", factor_ms, steps + 1,
                update_ms, factor_ms + update_ms);
    if(iterative)
      std::printf("iterative: %zu steps in all, %.3f ms (%.1f x the direct total); max distance "
                  "to the direct frames %.3g\n",
                  iterations, iterative_ms, iterative_ms / (factor_ms + update_ms), worst_gap);
    outputs.commit();
    return 0;
  }
  catch(const program::Usage_error& e)
  {
    std::cerr << "octahedron_deformation: " << e.what() << "\n\n" << usage;
    return 1;
  }
  catch(const std::exception& e)
  {
    std::cerr << "octahedron_deformation: " << e.what() << "\n";
    return 1;
  }
}
