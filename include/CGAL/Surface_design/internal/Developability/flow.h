// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The developability flow (Stein, Grinspun & Crane 2018, sec. 4.2-4.3): descent of a vertex-star
// energy by L-BFGS with the Lewis-Overton line search, small-angle removal after every step, and
// a schedule of 4-1 subdivisions.

#ifndef CGAL_SURFACE_DESIGN_INTERNAL_DEVELOPABILITY_FLOW_H
#define CGAL_SURFACE_DESIGN_INTERNAL_DEVELOPABILITY_FLOW_H

#include <CGAL/Surface_design/developability_energy.h>
#include <CGAL/Surface_design/internal/Core/geometry.h>
#include <CGAL/Surface_design/internal/Solvers/Lbfgs_minimizer.h>
#include <CGAL/Surface_design/internal/Core/Mesh_indices.h>
#include <CGAL/Surface_design/internal/Developability/remeshing.h>
#include <CGAL/Surface_design/internal/Developability/star_energies.h>
#include <CGAL/Surface_design/internal/Developability/vertex_stars.h>

#include <Eigen/Core>

#include <chrono>
#include <cmath>
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_design {
namespace internal {

/// Everything the flow reads (checked by the public entry point).
struct Developability_flow_options
{
  Developability_energy energy = Developability_energy::covariance;
  std::size_t subdivisions = 0;            ///< 4-1 subdivisions, each after a level of descent
  std::size_t iterations_per_level = 10000; ///< at most this many descent iterations per level
  double gradient_tolerance = 1e-6;        ///< stop a level when |g| (RMS, times the mean edge length) is below
  /// Convergence: a level has converged when, over the last `convergence_window` iterations, the
  /// energy fell by at most this (relative) and the number of measured vertices with lambda_i
  /// above `target` fell by at most max(1, `count_tolerance` times the measured vertices).
  double energy_tolerance = 1e-2;
  double count_tolerance = 5e-3;
  std::size_t convergence_window = 300;
  std::size_t check_interval = 50;         ///< iterations between two counts of the vertices above the target
  double target = two_pi * 1e-4;            ///< lambda_i at most this: a hinge (the metrics' threshold)
  bool stop_at_target = false;              ///< end a level when every measured vertex is at most `target`
  double minimum_angle = 0.01;             ///< radians; 0 disables the small-angle handling
  bool omit_valence_three = true;
  bool include_boundary = false;
  bool parallel = true;
  Descent_method method = Descent_method::lbfgs;
};

/// Why a level of descent ended.
enum class Developability_level_end
{
  iteration_limit,  ///< `iterations_per_level` iterations were made
  gradient_small,   ///< the scaled gradient norm fell below `gradient_tolerance`
  converged,        ///< neither the energy nor the vertices above the target decreased over the window
  target_reached,   ///< every measured vertex has lambda_i at most the target
  line_search_failed, ///< the line search failed twice in a row (a kink the descent cannot pass)
  visitor           ///< the visitor asked to stop
};

inline const char* to_string(Developability_level_end e)
{
  switch(e)
  {
    case Developability_level_end::iteration_limit: return "iteration limit";
    case Developability_level_end::gradient_small: return "gradient below tolerance";
    case Developability_level_end::converged: return "converged";
    case Developability_level_end::target_reached: return "target reached";
    case Developability_level_end::line_search_failed: return "line search failed";
    case Developability_level_end::visitor: return "stopped by the visitor";
  }
  return "unknown";
}

/// Seconds of wall-clock time since construction.
class Phase_clock
{
public:
  double seconds() const
  {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - m_start).count();
  }

private:
  std::chrono::steady_clock::time_point m_start = std::chrono::steady_clock::now();
};

/// The flow's working state on one connectivity: indices, stars, positions.
template <class Mesh, class VertexPointMap>
class Developability_state
{
public:
  Developability_state(Mesh& tm, const VertexPointMap& vpm, const Developability_flow_options& o)
    : m_tm(tm), m_vpm(vpm), m_options(o), m_idx(tm)
  {
    rebuild();
  }

  /// After the connectivity changed: new indices, stars and positions.
  void rebuild()
  {
    m_idx = Mesh_indices<Mesh>(m_tm);
    m_stars = vertex_stars(m_idx, m_options.include_boundary, m_options.omit_valence_three ? 4 : 0);
    m_measured = vertex_stars(m_idx, false, 4);
    const std::size_t nv = m_idx.number_of_vertices();
    m_x.resize(Eigen::Index(3 * nv));
    for(std::size_t v = 0; v < nv; ++v)
      m_x.template segment<3>(Eigen::Index(3 * v)) = position(m_vpm, m_idx.vertex(v));
    double length = 0.;
    for(std::size_t e = 0; e < m_idx.number_of_edges(); ++e)
    {
      const auto ij = m_idx.edge_vertices(e);
      length += (m_x.template segment<3>(Eigen::Index(3 * ij.first)) - m_x.template segment<3>(Eigen::Index(3 * ij.second))).norm();
    }
    m_mean_edge_length = m_idx.number_of_edges() > 0 ? length / double(m_idx.number_of_edges()) : 1.;
    m_positions.resize(nv);
    m_gradient.resize(nv);
  }

  /// The energy and its gradient at the flat coordinates X (3 per vertex).
  double operator()(const Eigen::VectorXd& X, Eigen::VectorXd& G)
  {
    const std::size_t nv = m_positions.size();
    for(std::size_t v = 0; v < nv; ++v)
      m_positions[v] = X.template segment<3>(Eigen::Index(3 * v));
    const double E = developability_energy(m_stars, m_positions, m_options.energy, &m_gradient, nullptr, m_options.parallel);
    for(std::size_t v = 0; v < nv; ++v)
      G.template segment<3>(Eigen::Index(3 * v)) = m_gradient[v];
    ++m_evaluations;
    return E;
  }

  /// The number of measured vertices (interior, valence >= 4) and, among them, the number whose
  /// covariance lambda_i (eq. 3, the measure of the metrics) at the current coordinates exceeds
  /// `target`.
  std::pair<std::size_t, std::size_t> count_above(double target)
  {
    const std::size_t nv = m_positions.size();
    for(std::size_t v = 0; v < nv; ++v)
      m_positions[v] = m_x.template segment<3>(Eigen::Index(3 * v));
    developability_energy(m_measured, m_positions, Developability_energy::covariance, nullptr, &m_lambda, m_options.parallel);
    std::size_t above = 0;
    for(std::size_t v : m_measured.active_vertices)
      above += m_lambda[v] > target;
    return {m_measured.active_vertices.size(), above};
  }

  /// Writes the current coordinates to the mesh.
  void write_positions() const
  {
    using Point = typename boost::property_traits<VertexPointMap>::value_type;
    for(std::size_t v = 0; v < m_idx.number_of_vertices(); ++v)
    {
      const auto p = m_x.template segment<3>(Eigen::Index(3 * v));
      put(m_vpm, m_idx.vertex(v), Point(p[0], p[1], p[2]));
    }
  }

  Eigen::VectorXd& coordinates() { return m_x; }
  double mean_edge_length() const { return m_mean_edge_length; }
  std::size_t evaluations() const { return m_evaluations; }
  const Mesh_indices<Mesh>& indices() const { return m_idx; }

private:
  Mesh& m_tm;
  VertexPointMap m_vpm;
  Developability_flow_options m_options;
  Mesh_indices<Mesh> m_idx;
  Vertex_stars m_stars, m_measured;
  std::vector<double> m_lambda;
  Eigen::VectorXd m_x;
  std::vector<Eigen::Vector3d> m_positions, m_gradient;
  double m_mean_edge_length = 1.;
  std::size_t m_evaluations = 0;
};

} // namespace internal
} // namespace Surface_design
} // namespace CGAL

#endif // CGAL_SURFACE_DESIGN_INTERNAL_DEVELOPABILITY_FLOW_H
