// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Workloads of the developability package (Stein, Grinspun & Crane 2018):
// `developability_evaluation` (one energy + gradient evaluation per energy, sequential and with
// TBB: evaluations per second and the parallel speed-up) and `developable_flow_<energy>` (the
// whole flow with two 4-1 subdivisions, as the CLI runs it by default: time, iterations, the
// time to reach 90% hinges, and the metrics of the result).

#ifndef CGAL_SURFACE_DESIGN_BENCHMARK_WORKLOAD_DEVELOPABILITY_H
#define CGAL_SURFACE_DESIGN_BENCHMARK_WORKLOAD_DEVELOPABILITY_H

#include "harness.h"

#include <CGAL/Surface_design/developability.h>

#include <array>
#include <chrono>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#if defined(CGAL_LINKED_WITH_TBB)
#include <tbb/global_control.h>
#endif

namespace benchmark {

namespace developability_detail {

namespace SD = CGAL::Surface_design;
namespace SDI = CGAL::Surface_design::internal;

/// The energies the flow workloads and the evaluation workload cover.
inline const std::vector<SD::Developability_energy>& energies()
{
  static const std::vector<SD::Developability_energy> e{
    SD::Developability_energy::intrinsic,     SD::Developability_energy::covariance,
    SD::Developability_energy::intrinsic_width, SD::Developability_energy::covariance_max,
    SD::Developability_energy::combinatorial, SD::Developability_energy::squared_angle_defect};
  return e;
}

/// Share of the interior vertices of valence >= 4 whose covariance lambda is below 2 pi 1e-4.
inline double hinge_share(const Mesh& mesh)
{
  return SD::developability_metrics(mesh, SD::parameters::developability_energy(SD::Developability_energy::covariance))
    .hinge_share_1e4;
}

/// Bounding-box diagonal of a mesh.
inline double diagonal(const Mesh& mesh)
{
  CGAL::Bbox_3 box;
  for(auto v : vertices(mesh))
    box += mesh.point(v).bbox();
  return std::sqrt(CGAL::square(box.xmax() - box.xmin()) + CGAL::square(box.ymax() - box.ymin()) +
                   CGAL::square(box.zmax() - box.zmin()));
}

} // namespace developability_detail

/// One evaluation of every energy and its gradient on the mesh (all interior stars of valence
/// >= 4), sequential (phase `<energy>`) and with TBB on 2 threads (phase `<energy>_tbb`, when TBB
/// is linked). 1000 / ms is the number of evaluations per second.
inline void developability_evaluation_workload(const Mesh& mesh, const std::string&, Run& run)
{
  using namespace developability_detail;
  const SDI::Mesh_indices<Mesh> idx(mesh);
  SDI::validate_mesh(idx, mesh.points());
  const SDI::Vertex_stars stars = SDI::vertex_stars(idx, false, 4);
  std::vector<Eigen::Vector3d> x(idx.number_of_vertices()), gradient;
  for(std::size_t v = 0; v < x.size(); ++v)
    x[v] = SDI::position(mesh.points(), idx.vertex(v));
  // untimed: sizes the gradient and warms the caches, so that the first timed phase is not the
  // only one to pay for them
  SDI::developability_energy(stars, x, energies().front(), &gradient, nullptr, false);
  for(SD::Developability_energy e : energies())
  {
    double sequential = 0., parallel = 0.;
    run.phase(SD::to_string(e), [&] { sequential = SDI::developability_energy(stars, x, e, &gradient, nullptr, false); });
#if defined(CGAL_LINKED_WITH_TBB)
    {
      tbb::global_control threads(tbb::global_control::max_allowed_parallelism, 2);
      run.phase(std::string(SD::to_string(e)) + "_tbb",
                [&] { parallel = SDI::developability_energy(stars, x, e, &gradient, nullptr, true); });
    }
    run.check(std::string(SD::to_string(e)) + ": |parallel - sequential| (bitwise identical)",
              std::abs(parallel - sequential), 1e-300);
#else
    (void)parallel;
#endif
  }
}

/// The flow of the CLI's default run (two 4-1 subdivisions, each level until it has converged,
/// at most 10000 iterations) with one energy. Phases: `flow`, `metrics`. Checks: hinge share of
/// the result (as 1 - share < 0.2: at least 80% hinges), Hausdorff distance to the input / bbox
/// diagonal, iterations, evaluations, whether the last level converged, and the flow time and
/// iterations (all levels) at which 90%, 95% and 99% of the measured vertices first were hinges
/// in the last level (looked at every 50 iterations when checks are on; the time spent looking
/// is subtracted; infinite if never).
template <CGAL::Surface_design::Developability_energy energy>
void developable_flow_workload(const Mesh& input, const std::string&, Run& run)
{
  using namespace developability_detail;
  Mesh mesh = input;
  SD::Developability_flow_result result;
  const std::array<double, 3> shares{0.9, 0.95, 0.99};
  std::array<double, 3> reached_ms, reached_iterations;
  reached_ms.fill(std::numeric_limits<double>::infinity());
  reached_iterations.fill(std::numeric_limits<double>::infinity());
  double looking = 0.;
  const auto start = Clock::now();
  run.phase("flow", [&] {
    result = SD::make_piecewise_developable(
      mesh, SD::parameters::developability_energy(energy, SD::parameters::number_of_subdivisions(std::size_t(2)))
              .visitor([&](const SD::Developability_iteration& it) {
                if(run.checks_enabled() && it.level == 2 && it.level_iteration % 50 == 0 &&
                   reached_ms.back() == std::numeric_limits<double>::infinity())
                {
                  const auto look = Clock::now();
                  const double share = hinge_share(mesh);
                  for(std::size_t k = 0; k < shares.size(); ++k)
                    if(share >= shares[k] && reached_ms[k] == std::numeric_limits<double>::infinity())
                    {
                      reached_ms[k] = std::chrono::duration<double, std::milli>(look - start).count() - looking;
                      reached_iterations[k] = double(it.iteration);
                    }
                  looking += std::chrono::duration<double, std::milli>(Clock::now() - look).count();
                }
                return true;
              }));
  });
  SD::Developability_metrics m;
  run.phase("metrics", [&] { m = SD::developability_metrics(mesh, input); });
  run.check("1 - hinge share (lambda < 2 pi 1e-4)", 1. - m.hinge_share_1e4, 0.2);
  // converged flows move the shape farther than the 1000-iteration levels before (0.06)
  run.check("Hausdorff distance / bbox diagonal", m.hausdorff_distance, 0.12);
  run.check("iterations", double(result.iterations), 30001.);
  run.check("evaluations", double(result.evaluations), 1e9);
  run.check("1 - converged (last level)", result.converged ? 0. : 1., 0.5);
  for(std::size_t k = 0; k < shares.size(); ++k)
    if(std::isfinite(reached_ms[k])) // shares never reached are left out of the table
    {
      const std::string share = std::to_string(int(100. * shares[k] + 0.5)) + "%";
      run.check("ms of flow to " + share + " hinges (last level; informative)", reached_ms[k], 1e300);
      run.check("iterations to " + share + " hinges (all levels; informative)", reached_iterations[k], 1e300);
    }
  run.check("seam curvature share (informative)", m.seam_curvature_share, 2.);
  // the other figures of developability_metrics(), informative (bounds that always hold)
  run.check("lambda max (informative)", m.lambda_max, 3.);
  run.check("lambda mean (informative)", m.lambda_mean, 3.);
  run.check("lambda p95 (informative)", m.lambda_p95, 3.);
  run.check("angle defect max (informative)", m.angle_defect_max, 7.);
  run.check("angle defect mean (informative)", m.angle_defect_mean, 7.);
  run.check("seam curves (informative)", double(m.seam_curves), 1e9);
  run.check("seam length / bbox diagonal of the input (informative)", m.seam_length / diagonal(input), 1e9);
  run.check("smallest angle, degrees (informative)", m.minimum_angle * 180. / SDI::pi, 61.);
  run.check("flips (informative)", double(result.flips), 1e9);
  run.check("collapses (informative)", double(result.collapses), 1e9);
  run.check("seconds: evaluation (informative)", result.evaluation_seconds, 1e9);
  run.check("seconds: small angles (informative)", result.remeshing_seconds, 1e9);
  run.check("seconds: subdivision (informative)", result.subdivision_seconds, 1e9);
}

} // namespace benchmark

#endif // CGAL_SURFACE_DESIGN_BENCHMARK_WORKLOAD_DEVELOPABILITY_H
