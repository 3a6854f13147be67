// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Workloads of the barycentric embedding (Imafuji & Ochiai): the direct solve against the paper's
// iteration (Table 1), and the deformation of Table 2 (factor once + updates) against the
// iteration and against PMP::fair, which refactors at every call.

#ifndef CGAL_SURFACE_DESIGN_BENCHMARK_WORKLOAD_EMBEDDING_H
#define CGAL_SURFACE_DESIGN_BENCHMARK_WORKLOAD_EMBEDDING_H

#include "harness.h"

#include <CGAL/Surface_design/Barycentric_embedder.h>
#include <CGAL/Surface_design/barycentric_embedding.h>

#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Polygon_mesh_processing/fair.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace benchmark {

namespace embedding_detail {

namespace SD = CGAL::Surface_design;
using Vertex = Mesh::Vertex_index;
using Point = Kernel::Point_3;

/// Deformation steps of Table 2.
constexpr int deformation_steps = 10;
/// The iterative reference and PMP::fair run only up to this size (Jacobi needs ~diameter^2
/// steps: hours at 1M vertices).
constexpr std::size_t reference_size_limit = 60000;

/// The fixed vertices: the boundary (the octahedron's six loops), or on a closed mesh every
/// 100th vertex.
inline std::vector<Vertex> fixed_vertices(const Mesh& mesh)
{
  std::vector<Vertex> fixed;
  std::vector<bool> seen(num_vertices(mesh), false);
  for(auto h : halfedges(mesh))
    if(is_border(h, mesh) && !seen[std::size_t(target(h, mesh))])
    {
      seen[std::size_t(target(h, mesh))] = true;
      fixed.push_back(target(h, mesh));
    }
  if(fixed.empty())
    for(auto v : vertices(mesh))
      if(std::size_t(v) % 100 == 0)
        fixed.push_back(v);
  return fixed;
}

/// Table 2's motion, for any mesh: the fixed vertices of the top tenth of the height move down,
/// those of the bottom tenth up, by a twentieth of the height per step (on the octahedron: L1
/// and L2, by 0.3).
struct Motion
{
  std::vector<Vertex> moving;
  std::vector<double> direction;
  double step = 0.;

  Motion(const Mesh& mesh, const std::vector<Vertex>& fixed)
  {
    double lo = 1e300, hi = -1e300;
    for(auto v : vertices(mesh))
    {
      lo = (std::min)(lo, mesh.point(v).z());
      hi = (std::max)(hi, mesh.point(v).z());
    }
    step = 0.05 * (hi - lo);
    for(auto v : fixed)
    {
      const double z = mesh.point(v).z();
      if(z > hi - 0.1 * (hi - lo) || z < lo + 0.1 * (hi - lo))
      {
        moving.push_back(v);
        direction.push_back(z > 0.5 * (lo + hi) ? -1. : 1.);
      }
    }
  }

  void apply(Mesh& mesh) const
  {
    for(std::size_t k = 0; k < moving.size(); ++k)
    {
      const Point p = mesh.point(moving[k]);
      mesh.point(moving[k]) = Point(p.x(), p.y(), p.z() + direction[k] * step);
    }
  }
};

inline void check_not_too_large(const Mesh& mesh, const char* what)
{
  if(num_vertices(mesh) > reference_size_limit)
    throw Not_applicable(std::string(what) + " is run up to " + std::to_string(reference_size_limit) +
                         " vertices only");
}

/// max |x_i - barycentre of its neighbours| over the free vertices, relative to the bounding box.
inline double relative_residual(const Mesh& mesh, const std::vector<Vertex>& fixed)
{
  std::vector<bool> is_fixed(num_vertices(mesh), false);
  for(auto v : fixed)
    is_fixed[std::size_t(v)] = true;
  const CGAL::Bbox_3 box = CGAL::Polygon_mesh_processing::bbox(mesh);
  const double size = std::sqrt(CGAL::square(box.xmax() - box.xmin()) + CGAL::square(box.ymax() - box.ymin()) +
                                CGAL::square(box.zmax() - box.zmin()));
  double worst = 0.;
  for(auto v : vertices(mesh))
  {
    if(is_fixed[std::size_t(v)])
      continue;
    Kernel::Vector_3 sum(0., 0., 0.);
    double n = 0.;
    for(auto w : vertices_around_target(halfedge(v, mesh), mesh))
    {
      sum = sum + (mesh.point(w) - CGAL::ORIGIN);
      n += 1.;
    }
    worst = (std::max)(worst, std::sqrt(CGAL::squared_distance(mesh.point(v), CGAL::ORIGIN + sum / n)));
  }
  return worst / size;
}

/// PMP::fair's weights for the uniform graph barycentre (w_ij = 1; w_i plays no role at
/// continuity 0).
struct Uniform_fair_weights
{
  double w_i(Vertex) const { return 1.; }
  double w_ij(Mesh::Halfedge_index) const { return 1.; }
};

} // namespace embedding_detail

/// `embedding`: phases `factor` (Barycentric_embedder: validation, uniform stencil, factorization)
/// and `update` (three back-substitutions, writing the positions); `full` = factor + update.
inline void embedding_workload(const Mesh& input, const std::string& solver, Run& run)
{
  using namespace embedding_detail;
  with_solver_traits(solver, [&](auto tag) {
    using Traits = typename decltype(tag)::type;
    Mesh mesh = input;
    const std::vector<Vertex> fixed = fixed_vertices(mesh);
    std::unique_ptr<SD::Barycentric_embedder<Mesh, Mesh::Property_map<Vertex, Point>, Traits>> e;
    run.phase("factor", [&] { e = std::make_unique<SD::Barycentric_embedder<Mesh, Mesh::Property_map<Vertex, Point>, Traits>>(mesh, fixed); });
    run.phase("update", [&] { e->update(); });
    run.sum_phase("full", {"factor", "update"});
    if(run.checks_enabled())
      run.check("max |x - barycentre| / bbox (uniform weights)", relative_residual(mesh, fixed), 1e-10);
  });
}

/// `embedding_iterative`: the paper's method 2 from the input positions, until the area changes
/// by < 1e-6 (phase `full`).
inline void embedding_iterative_workload(const Mesh& input, const std::string&, Run& run)
{
  using namespace embedding_detail;
  check_not_too_large(input, "the iterative method");
  Mesh mesh = input;
  const std::vector<Vertex> fixed = fixed_vertices(mesh);
  SD::Iterative_embedding_result r;
  run.phase("full", [&] { r = SD::barycentric_embedding_iterative(mesh, fixed); });
  if(run.checks_enabled())
  {
    run.check("iterations of the paper's method 2", double(r.iterations), 1e7);
    run.check("iterative: max |x - barycentre| / bbox", relative_residual(mesh, fixed), 1e-4);
  }
}

/// `deformation`: Table 2. Phases `factor` (once) and `updates` (10 steps: move the fixed
/// vertices, update()); `full` = factor + updates.
inline void deformation_workload(const Mesh& input, const std::string& solver, Run& run)
{
  using namespace embedding_detail;
  with_solver_traits(solver, [&](auto tag) {
    using Traits = typename decltype(tag)::type;
    Mesh mesh = input;
    const std::vector<Vertex> fixed = fixed_vertices(mesh);
    const Motion motion(mesh, fixed);
    std::unique_ptr<SD::Barycentric_embedder<Mesh, Mesh::Property_map<Vertex, Point>, Traits>> e;
    run.phase("factor", [&] { e = std::make_unique<SD::Barycentric_embedder<Mesh, Mesh::Property_map<Vertex, Point>, Traits>>(mesh, fixed); });
    run.phase("updates", [&] {
      for(int k = 0; k < deformation_steps; ++k)
      {
        motion.apply(mesh);
        e->update();
      }
    });
    run.sum_phase("full", {"factor", "updates"});
    if(run.checks_enabled())
      run.check("after the deformation: max |x - barycentre| / bbox", relative_residual(mesh, fixed), 1e-10);
  });
}

/// `deformation_iterative`: the same 10 steps, each solved by the paper's method 2 starting from
/// the previous frame (phase `full`).
inline void deformation_iterative_workload(const Mesh& input, const std::string&, Run& run)
{
  using namespace embedding_detail;
  check_not_too_large(input, "the iterative method");
  Mesh mesh = input;
  const std::vector<Vertex> fixed = fixed_vertices(mesh);
  const Motion motion(mesh, fixed);
  std::size_t iterations = 0;
  run.phase("full", [&] {
    for(int k = 0; k < deformation_steps; ++k)
    {
      motion.apply(mesh);
      iterations += SD::barycentric_embedding_iterative(mesh, fixed).iterations;
    }
  });
  if(run.checks_enabled())
    run.check("iterations over the 10 steps", double(iterations), 1e8);
}

/// `deformation_fair`: the same 10 steps, each by CGAL::Polygon_mesh_processing::fair at
/// continuity 0 with uniform weights and its default solver (SparseLU): it builds and factors the
/// system at every call (phase `full`).
inline void deformation_fair_workload(const Mesh& input, const std::string&, Run& run)
{
  using namespace embedding_detail;
  check_not_too_large(input, "PMP::fair");
  Mesh mesh = input;
  const std::vector<Vertex> fixed = fixed_vertices(mesh);
  std::vector<bool> is_fixed(num_vertices(mesh), false);
  for(auto v : fixed)
    is_fixed[std::size_t(v)] = true;
  std::vector<Vertex> free_vertices;
  for(auto v : vertices(mesh))
    if(!is_fixed[std::size_t(v)])
      free_vertices.push_back(v);
  const Motion motion(mesh, fixed);
  bool ok = true;
  run.phase("full", [&] {
    for(int k = 0; k < deformation_steps; ++k)
    {
      motion.apply(mesh);
      ok = CGAL::Polygon_mesh_processing::fair(
             mesh, free_vertices,
             CGAL::parameters::fairing_continuity(0).weight_calculator(Uniform_fair_weights())) && ok;
    }
  });
  if(!ok)
    throw std::runtime_error("PMP::fair failed");
  if(run.checks_enabled())
    run.check("fair, after the deformation: max |x - barycentre| / bbox", relative_residual(mesh, fixed), 1e-8);
}

} // namespace benchmark

#endif // CGAL_SURFACE_DESIGN_BENCHMARK_WORKLOAD_EMBEDDING_H
