// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The stripe singularities the energy wants: the relaxation of Knöppel et al. 2015 on the cover
// of an n-direction field, read off as integer indices per face.

#ifndef CGAL_SURFACE_DESIGN_INTERNAL_FIELD_ALIGNED_PARAMETERIZATION_STRIPE_RELAXATION_H
#define CGAL_SURFACE_DESIGN_INTERNAL_FIELD_ALIGNED_PARAMETERIZATION_STRIPE_RELAXATION_H

#include <CGAL/Surface_design/internal/Core/angles.h>
#include <CGAL/Surface_design/internal/Core/Mesh_indices.h>
#include <CGAL/Surface_design/internal/Solvers/Factored_system.h>
#include <CGAL/Surface_design/internal/Solvers/shift_invert_lanczos.h>
#include <CGAL/Surface_design/internal/Solvers/sparse_types.h>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <random>
#include <vector>

namespace CGAL {
namespace Surface_design {
namespace internal {

/// The stripe indices of the smallest eigenvector psi (one complex value per vertex and sheet)
/// of sum_e w_e sum_a |psi^_{j,a} - exp(i omega_{e,a}) psi_{i,a}|^2 = lambda sum_v m_v |psi_v|^2,
/// where psi^_{j,a} is the value of the target's sheet a + r_e (its conjugate when that sheet is
/// the opposite of an unknown one): the relaxed stripe problem, whose zeros are where the energy
/// wants singularities. With theta = arg psi, the phase difference closest to omega along every
/// edge, y_{e,a} = omega + wrap(arg psi^_{j,a} - theta_{i,a} - omega), is d_P theta modulo 2 pi;
/// its twisted curl in a regular face is 2 pi times an integer: the face's index.
/// Negative cotangent weights are clamped to 0 here (a positive semi-definite matrix; only the
/// positions of the zeros are used); `vertex_mass` the lumped mass (barycentric areas). Shift-invert Lanczos on A + sigma M, one factorization.
template <class Indices, class Solver, class SolverTraits>
std::vector<Eigen::Vector2i> relaxed_stripe_indices(const Indices& idx, const Solver& solver,
                                                    const std::vector<Eigen::Vector2d>& omega,
                                                    const std::vector<double>& vertex_mass, const SolverTraits& traits)
{
  const int d = solver.values_per_vertex();
  const std::size_t nv = idx.number_of_vertices(), ne = idx.number_of_edges(), nf = idx.number_of_faces();
  const std::size_t unknowns = 2 * std::size_t(d) * nv;
  auto row = [d](std::size_t v, int a, int part) {
    return Eigen::Index(2 * (v * std::size_t(d) + std::size_t(a)) + std::size_t(part));
  };
  // the sheet a of the target reads unknown `c` of j, conjugated when `sign` < 0
  auto target_sheet = [&](std::size_t e, int a, int& c, double& sign) {
    const Eigen::Matrix2d& P = solver.transition(e);
    for(c = 0; c < d; ++c)
      if(P(a, c) != 0.)
        break;
    sign = P(a, c);
  };

  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(ne * std::size_t(d) * 16 + unknowns);
  Eigen::VectorXd diagonal = Eigen::VectorXd::Zero(Eigen::Index(unknowns));
  for(std::size_t e = 0; e < ne; ++e)
  {
    const double w = (std::max)(solver.weights()[e], 0.);
    if(w == 0.)
      continue;
    const auto [i, j] = idx.edge_vertices(e);
    for(int a = 0; a < d; ++a)
    {
      int c;
      double sign;
      target_sheet(e, a, c, sign);
      // w |C z - R x|^2: the cross block -w R^T C between x (i, a) and z (j, c)
      const double co = std::cos(omega[e][a]), si = std::sin(omega[e][a]);
      Eigen::Matrix2d RtC;
      RtC << co, si * sign, -si, co * sign;
      for(int p = 0; p < 2; ++p)
      {
        diagonal[row(i, a, p)] += w;
        diagonal[row(j, c, p)] += w;
        for(int q = 0; q < 2; ++q)
        {
          entries.emplace_back(row(i, a, p), row(j, c, q), -w * RtC(p, q));
          entries.emplace_back(row(j, c, q), row(i, a, p), -w * RtC(p, q));
        }
      }
    }
  }
  Eigen::VectorXd mass = Eigen::VectorXd::Zero(Eigen::Index(unknowns));
  for(std::size_t v = 0; v < nv; ++v)
    for(int a = 0; a < d; ++a)
      for(int p = 0; p < 2; ++p)
        mass[row(v, a, p)] = vertex_mass[v];
  const double scale = diagonal.sum() / (std::max)(mass.sum(), 1e-300);
  const double sigma = 1e-6 * scale;
  for(Eigen::Index r = 0; r < Eigen::Index(unknowns); ++r)
  {
    if(!(mass[r] > 0.))
      mass[r] = 1e-300;
    entries.emplace_back(r, r, diagonal[r] + sigma * mass[r]);
  }
  Sparse_matrix S(static_cast<Eigen::Index>(unknowns), static_cast<Eigen::Index>(unknowns));
  S.setFromTriplets(entries.begin(), entries.end());
  S.makeCompressed();
  Factored_system<SolverTraits> system(traits, "relaxed stripe matrix");
  system.factor(std::move(S));

  std::vector<std::size_t> group(unknowns, 0);
  std::mt19937 random(20150801u);
  Eigen::VectorXd start = Eigen::VectorXd::Zero(Eigen::Index(unknowns));
  for(Eigen::Index r = 0; r < start.size(); ++r)
    start[r] = 2. * (double(random()) / 4294967296.) - 1.;
  const Lanczos_result eig = largest_eigenvectors_by_group(
    [&system](const Eigen::VectorXd& b, Eigen::VectorXd& y) { system.solve(b, y); }, mass, group,
    std::vector<bool>{true}, start, 1e-8, 300);

  std::vector<double> theta(std::size_t(d) * nv);
  for(std::size_t v = 0; v < nv; ++v)
    for(int a = 0; a < d; ++a)
      theta[v * std::size_t(d) + std::size_t(a)] = std::atan2(eig.x[row(v, a, 1)], eig.x[row(v, a, 0)]);
  std::vector<Eigen::Vector2d> y(ne, Eigen::Vector2d::Zero());
  for(std::size_t e = 0; e < ne; ++e)
  {
    const auto [i, j] = idx.edge_vertices(e);
    for(int a = 0; a < d; ++a)
    {
      int c;
      double sign;
      target_sheet(e, a, c, sign);
      const double target = sign * theta[j * std::size_t(d) + std::size_t(c)];
      y[e][a] = omega[e][a] + wrap_angle(target - theta[i * std::size_t(d) + std::size_t(a)] - omega[e][a]);
    }
  }
  std::vector<Eigen::Vector2i> k(nf, Eigen::Vector2i::Zero());
  for(std::size_t f = 0; f < nf; ++f)
    if(solver.cover().regular[f])
    {
      const Eigen::Vector2d c = solver.curl(y, f);
      for(int a = 0; a < d; ++a)
        k[f][a] = int(std::lround(c[a] / two_pi));
    }
  return k;
}

} // namespace internal
} // namespace Surface_design
} // namespace CGAL

#endif // CGAL_SURFACE_DESIGN_INTERNAL_FIELD_ALIGNED_PARAMETERIZATION_STRIPE_RELAXATION_H
