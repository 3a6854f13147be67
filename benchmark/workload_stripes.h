// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Workloads `stripes` and `stripes_face_space`: the field-aligned parameterization (stripe
// patterns with prescribed singularities, Noma & Kawahara) computed by the library's vertex-space
// `Field_aligned_parameterizer`, and by the paper's face-space formulation (sec. 5.2,
// `internal::Face_space_stripe_solver`) on exactly the same inputs, with phases of the same names
// so that the harness puts them side by side (`stripes` names `stripes_face_space` as reference).

#ifndef CGAL_SURFACE_DESIGN_BENCHMARK_WORKLOAD_STRIPES_H
#define CGAL_SURFACE_DESIGN_BENCHMARK_WORKLOAD_STRIPES_H

#include "harness.h"

#include <CGAL/Surface_design/Branched_stripe_parameterizer.h>
#include <CGAL/Surface_design/Field_aligned_parameterizer.h>
#include <CGAL/Surface_design/direction_fields.h>
#include "Face_space_stripe_solver.h"
#include <CGAL/Surface_design/internal/Core/Mesh_indices.h>
#include <CGAL/Surface_design/internal/Core/dec.h>
#include <CGAL/Surface_design/internal/Core/geometry.h>

#include <CGAL/property_map.h>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace benchmark {

namespace stripes_detail {

namespace SD = CGAL::Surface_design;
namespace SDI = CGAL::Surface_design::internal;

using Vertex_point_map = boost::property_map<Mesh, CGAL::vertex_point_t>::const_type;
template <class SolverTraits>
using Parameterizer = SD::Field_aligned_parameterizer<Mesh, Vertex_point_map, SolverTraits>;
using Field_map = CGAL::Constant_property_map<Mesh::Vertex_index, Kernel::Vector_3>;

/// The target field: one constant direction, projected to the tangent planes by set_field().
inline Field_map direction_field() { return Field_map(Kernel::Vector_3(1., 0.4, 0.2)); }

/// Stripes per longest edge: at most 0.15 of a period (0.94 rad) along any edge, so the pattern
/// is resolved on every mesh, and the problem has the same shape at every size.
constexpr double stripes_per_longest_edge = 0.15;

/// The optimality condition d0^T W (y - omega) = 0 (one row per vertex) holds up to the rounding
/// of the back-substitution: relative to the size of the terms it sums, max |w| (|y| + |omega|).
constexpr double kkt_bound = 1e-8;
/// d1 y = 2 pi k holds by construction of the particular solution (d1 d0 = 0 exactly); only the
/// rounding of y = y* + d0 f remains.
constexpr double curl_bound = 1e-8;
/// Both formulations minimize the same strictly convex energy under the same constraints.
constexpr double agreement_bound = 1e-6;

/// The inputs of a run, chosen deterministically from the mesh (outside the timed phases).
struct Stripe_setup
{
  double stripes_per_unit_length = 0.;
  std::vector<std::pair<std::size_t, int>> singularities; ///< (face index, index)
  std::size_t moved_from = SDI::npos, moved_to = SDI::npos; ///< the move of `resolve`, if any
};

/// Two +1/-1 pairs, at faces (n/7, n/3) and (4n/5, n/2) of the n faces, or the next faces in index
/// order with no edge on the boundary (those cannot hold a singularity); a pair whose faces lie on
/// different connected components (or coincide with another chosen face) is left out, so that
/// each closed component keeps a zero index sum. The move of `resolve` takes the first +1 to an
/// edge-adjacent face without singularity and without boundary edge.
template <class Fap>
Stripe_setup make_setup(const Fap& fap)
{
  const auto& idx = fap.indices();
  const Mesh& mesh = idx.mesh();
  const auto vpm = get(CGAL::vertex_point, mesh);
  Stripe_setup s;

  double longest = 0.;
  for(std::size_t e = 0; e < idx.number_of_edges(); ++e)
  {
    const auto ij = idx.edge_vertices(e);
    longest = (std::max)(longest, std::sqrt(CGAL::squared_distance(get(vpm, idx.vertex(ij.first)),
                                                                   get(vpm, idx.vertex(ij.second)))));
  }
  // longest > 0: the parameterizer's validation rejects degenerate faces
  s.stripes_per_unit_length = stripes_per_longest_edge / longest;

  const std::size_t n = idx.number_of_faces();
  const std::vector<std::size_t>& component = fap.topology().components.face_component;
  auto is_chosen = [&s](std::size_t f) {
    return std::any_of(s.singularities.begin(), s.singularities.end(),
                       [f](const std::pair<std::size_t, int>& x) { return x.first == f; });
  };
  auto interior = [&](std::size_t f) { // the first face from f on with no edge on the boundary
    for(std::size_t i = 0; i < n; ++i, f = (f + 1) % n)
      if(!fap.has_boundary_edge(idx.face(f)))
        return f;
    return f;
  };
  const std::pair<std::size_t, std::size_t> pairs[] = {{interior(n / 7), interior(n / 3)},
                                                       {interior(4 * n / 5), interior(n / 2)}};
  for(const auto& p : pairs)
    if(p.first != p.second && !is_chosen(p.first) && !is_chosen(p.second) &&
       component[p.first] == component[p.second] && !fap.has_boundary_edge(idx.face(p.first)) &&
       !fap.has_boundary_edge(idx.face(p.second)))
    {
      s.singularities.emplace_back(p.first, +1);
      s.singularities.emplace_back(p.second, -1);
    }

  if(!s.singularities.empty())
  {
    const std::size_t from = s.singularities.front().first;
    for(auto h : halfedges_around_face(halfedge(idx.face(from), mesh), mesh))
    {
      const auto o = opposite(h, mesh);
      if(is_border(o, mesh))
        continue;
      const std::size_t to = idx.index(face(o, mesh));
      if(!is_chosen(to) && !fap.has_boundary_edge(face(o, mesh)))
      {
        s.moved_from = from;
        s.moved_to = to;
        break;
      }
    }
  }
  return s;
}

template <class Fap>
void set_singularities(Fap& fap, const Stripe_setup& s)
{
  for(const auto& fk : s.singularities)
    fap.set_index(fk.first, fk.second);
}

template <class Fap>
void move_singularity(Fap& fap, const Stripe_setup& s)
{
  if(s.moved_from != SDI::npos)
    fap.move_singularity(fap.indices().face(s.moved_from), fap.indices().face(s.moved_to));
}

template <class Fap>
std::vector<int> windings(const Fap& fap)
{
  std::vector<int> w(fap.number_of_loops());
  for(std::size_t l = 0; l < w.size(); ++l)
    w[l] = fap.loop_winding(l);
  return w;
}

/// The two conditions that define the solution (paper, eq. 15-16): stationarity of the energy
/// over exact forms, d0^T W (y - omega) = 0, and the face constraints d1 y = 2 pi k.
template <class Fap>
void check_solution(const Fap& fap, const std::string& when, Run& run)
{
  const auto& idx = fap.indices();
  const std::vector<double>& y = fap.one_form();
  const std::vector<double>& omega = fap.target_one_form();
  const std::vector<double>& w = fap.edge_weights();
  const Eigen::Index ne = Eigen::Index(y.size());
  Eigen::VectorXd weighted(ne), y_vector(ne);
  double scale = 0.;
  for(Eigen::Index e = 0; e < ne; ++e)
  {
    const std::size_t i = std::size_t(e);
    weighted[e] = w[i] * (y[i] - omega[i]);
    y_vector[e] = y[i];
    scale = (std::max)(scale, std::abs(w[i]) * (std::abs(y[i]) + std::abs(omega[i])));
  }
  const Eigen::VectorXd gradient = SDI::d0(idx).transpose() * weighted;
  const double kkt = gradient.cwiseAbs().maxCoeff();
  run.check(when + ": max|d0^T W (y-omega)| / max|w|(|y|+|omega|)", scale > 0. ? kkt / scale : kkt,
            kkt_bound);

  const double two_pi = 2. * std::acos(-1.);
  const std::vector<int>& k = fap.indices_per_face();
  const Eigen::VectorXd curl = SDI::d1(idx) * y_vector;
  double curl_error = 0.;
  for(Eigen::Index f = 0; f < curl.size(); ++f)
    curl_error = (std::max)(curl_error, std::abs(curl[f] - two_pi * k[std::size_t(f)]));
  run.check(when + ": max|d1 y - 2 pi k|", curl_error, curl_bound);
}

/// max |a - b| / max |b|.
inline double relative_difference(const std::vector<double>& a, const std::vector<double>& b)
{
  double difference = 0., size = 0.;
  for(std::size_t i = 0; i < b.size(); ++i)
  {
    difference = (std::max)(difference, std::abs(a[i] - b[i]));
    size = (std::max)(size, std::abs(b[i]));
  }
  return size > 0. ? difference / size : difference;
}

template <class SolverTraits>
void run_stripes(const Mesh& mesh, Run& run)
{
  std::optional<Parameterizer<SolverTraits>> fap;
  run.phase("factor", [&] { fap.emplace(mesh); });
  const Stripe_setup setup = make_setup(*fap);
  const Field_map field = direction_field();
  run.phase("field", [&] { fap->set_field(field, setup.stripes_per_unit_length); });
  set_singularities(*fap, setup);
  run.phase("solve", [&] { fap->solve(); });
  if(run.checks_enabled())
    check_solution(*fap, "solve", run);
  run.phase("resolve", [&] {
    move_singularity(*fap, setup);
    fap->solve();
  });
  if(run.checks_enabled())
    check_solution(*fap, "resolve", run);
  run.sum_phase("full", {"factor", "field", "solve"});
}

/// The traits of two systems on one mesh: with the library's default traits, sharing one
/// `Symbolic_analysis_cache` when `shared` (each new cache, else); other traits as they are.
template <class SolverTraits>
std::pair<SolverTraits, SolverTraits> traits_pair(bool shared)
{
  SolverTraits a, b;
  if constexpr(std::is_same<SolverTraits, SD::Default_solver_traits>::value ||
               std::is_same<SolverTraits, SD::Supernodal_solver_traits>::value)
  {
    auto cache = std::make_shared<SD::Symbolic_analysis_cache>();
    a.solver().set_analysis_cache(cache);
    b.solver().set_analysis_cache(shared ? cache : std::make_shared<SD::Symbolic_analysis_cache>());
  }
  return {a, b};
}

/// The smoothest vector field, then the stripes along it (no singularity prescribed; the windings
/// automatic), the two systems sharing their analysis when `shared` (see `traits_pair`).
/// Returns the number of analyses reused.
template <class SolverTraits>
std::size_t field_then_stripes(const Mesh& mesh, bool shared, std::vector<Kernel::Vector_3>& field,
                               std::optional<Parameterizer<SolverTraits>>& fap, Run* run)
{
  auto traits = traits_pair<SolverTraits>(shared); // not a structured binding: the lambdas capture them
  auto& field_traits = traits.first;
  auto& stripe_traits = traits.second;
  auto timed = [run](const char* name, auto&& f) {
    if(run)
      run->phase(name, f);
    else
      f();
  };
  SD::Smoothest_direction_field_result info;
  timed("field", [&] {
    info = SD::smoothest_direction_field(mesh, CGAL::make_property_map(field),
                                         SD::parameters::sparse_linear_solver(field_traits));
  });
  timed("stripes", [&] {
    fap.emplace(mesh, SD::parameters::sparse_linear_solver(stripe_traits));
    fap->set_field(CGAL::make_property_map(field), make_setup(*fap).stripes_per_unit_length);
    fap->solve();
  });
  if(run)
    run->check("field: Lanczos not converged", info.converged ? 0. : 1., 0.5);
  if constexpr(std::is_same<SolverTraits, SD::Default_solver_traits>::value ||
               std::is_same<SolverTraits, SD::Supernodal_solver_traits>::value)
    return stripe_traits.solver().analysis_cache()->hits();
  return 0;
}

template <class SolverTraits>
void run_field_stripes(const Mesh& mesh, Run& run)
{
  std::vector<Kernel::Vector_3> field(num_vertices(mesh));
  std::optional<Parameterizer<SolverTraits>> fap, own;
  const std::size_t hits = field_then_stripes<SolverTraits>(mesh, true, field, fap, &run);
  run.sum_phase("full", {"field", "stripes"});
  run.phase("full, analyses not shared", [&] { field_then_stripes<SolverTraits>(mesh, false, field, own, nullptr); });
  run.check("analyses shared between the field and the stripes", double(hits), 1e300);
  if(run.checks_enabled())
    check_solution(*fap, "stripes", run);
}

/// Stripes on the smoothest n-direction field (n = 2: line field, 4: cross field), the pipeline
/// of geometry-central's stripe patterns on line fields. Phases: `field` (the smoothest n-field),
/// `stripes` (Branched_stripe_parameterizer: cover, weights, factorization, then one solve with
/// no stripe singularity; the first solve includes the harmonic parts of the free windings),
/// `full` = field + stripes; `automatic` (the relaxation and its pruning, then the solve);
/// `edit` (a +1/-1 pair added, re-solved: back-substitutions only). The frequency: 40 stripes
/// across the bounding box diagonal. Checks: the Lanczos runs converged, and every regular face's
/// stripe index read from the solution equals the prescribed one.
template <class SolverTraits>
void run_branched_stripes(const Mesh& mesh, int n, Run& run)
{
  using Branched = SD::Branched_stripe_parameterizer<Mesh, Vertex_point_map, SolverTraits>;
  auto traits = traits_pair<SolverTraits>(true); // not a structured binding: the lambdas capture them
  auto& field_traits = traits.first;
  auto& stripe_traits = traits.second;
  std::vector<Kernel::Vector_3> field(num_vertices(mesh));
  SD::Smoothest_direction_field_result info;
  run.phase("field", [&] {
    info = SD::smoothest_direction_field(mesh, CGAL::make_property_map(field),
                                         SD::parameters::symmetry_order(n).sparse_linear_solver(field_traits));
  });
  CGAL::Bbox_3 box;
  for(auto v : vertices(mesh))
    box += mesh.point(v).bbox();
  const double diagonal = std::sqrt(CGAL::square(box.xmax() - box.xmin()) + CGAL::square(box.ymax() - box.ymin()) +
                                    CGAL::square(box.zmax() - box.zmin()));
  std::optional<Branched> stripes;
  run.phase("stripes", [&] {
    stripes.emplace(mesh, SD::parameters::symmetry_order(n).sparse_linear_solver(stripe_traits));
    stripes->set_field(CGAL::make_property_map(field), 40. / diagonal);
    stripes->solve();
  });
  run.sum_phase("full", {"field", "stripes"});
  std::size_t count = 0;
  run.phase("automatic", [&] {
    count = stripes->place_automatic_singularities();
    stripes->solve();
  });
  // an edit: a +1/-1 pair in two regular faces without boundary edge, a tenth of the faces apart
  const auto& idx = stripes->indices();
  std::vector<std::size_t> chosen;
  for(std::size_t i = 0; i < idx.number_of_faces() && chosen.size() < 2; i += idx.number_of_faces() / 10 + 1)
  {
    const auto f = idx.face(i);
    bool border = false;
    for(auto h : halfedges_around_face(halfedge(f, mesh), mesh))
      border = border || is_border(opposite(h, mesh), mesh);
    if(!border && !stripes->is_branch_face(f) && stripes->index(f) == 0)
      chosen.push_back(i);
  }
  run.phase("edit", [&] {
    if(chosen.size() == 2)
    {
      stripes->set_index(chosen[0], 1);
      stripes->set_index(chosen[1], -1);
    }
    stripes->solve();
  });
  if(run.checks_enabled())
  {
    run.check("field: Lanczos not converged", info.converged ? 0. : 1., 0.5);
    std::size_t wrong = 0;
    for(auto f : faces(mesh))
      for(int a = 0; a < stripes->number_of_families(); ++a)
        wrong += stripes->stripe_index(f, a) == stripes->index(f, a) ? 0 : 1;
    run.check("faces whose stripe index differs from the prescribed one", double(wrong), 0.5);
    run.check("automatic singularities (reported, not bounded)", double(count), 1e300);
    run.check("branch faces (reported, not bounded)", double(stripes->branch_faces().size()), 1e300);
  }
}

/// The face-space formulation needs W^-1: every cotangent weight positive (the condition the
/// solver's constructor enforces). Checked on its own first, so that an inapplicable mesh costs
/// no factorization.
inline void require_positive_weights(const Mesh& mesh)
{
  const SDI::Mesh_indices<Mesh> idx(mesh);
  const std::vector<double> w = SDI::cotangent_weights(idx, get(CGAL::vertex_point, mesh));
  const auto bad = std::count_if(w.begin(), w.end(), [](double x) { return !(x > 0.); });
  if(bad > 0)
    throw Not_applicable("non-positive cotangent weights (" + std::to_string(bad) + " of " +
                         std::to_string(w.size()) + " edges)");
}

template <class SolverTraits>
void run_stripes_face_space(const Mesh& mesh, Run& run)
{
  require_positive_weights(mesh);

  // untimed: the vertex-space solver provides the inputs (index maps, topology, weights, loops,
  // omega) and the windings it chooses, which the face-space solver takes as given
  Parameterizer<SolverTraits> fap(mesh);
  const Stripe_setup setup = make_setup(fap);
  set_singularities(fap, setup);
  const std::vector<std::vector<std::size_t>> loops = fap.loops_as_indices();

  std::optional<SDI::Face_space_stripe_solver<SolverTraits>> face_space;
  run.phase("factor", [&] {
    face_space.emplace(fap.indices(), fap.topology(), fap.edge_weights(), loops);
  });
  // the same computation of omega as in `stripes`, so that `full` sums the same steps
  const Field_map field = direction_field();
  run.phase("field", [&] { fap.set_field(field, setup.stripes_per_unit_length); });

  fap.solve();
  const std::vector<int> k = fap.indices_per_face(), h = windings(fap);
  const std::vector<double> y_vertex_space = fap.one_form();
  std::vector<double> y;
  run.phase("solve", [&] { y = face_space->solve(fap.target_one_form(), k, h); });
  run.check("solve: max|y - y_vertex_space| / max|y_vertex_space|",
            relative_difference(y, y_vertex_space), agreement_bound);

  move_singularity(fap, setup);
  fap.solve();
  const std::vector<int> k_moved = fap.indices_per_face(), h_moved = windings(fap);
  run.phase("resolve", [&] { y = face_space->solve(fap.target_one_form(), k_moved, h_moved); });
  run.check("resolve: max|y - y_vertex_space| / max|y_vertex_space|",
            relative_difference(y, fap.one_form()), agreement_bound);
  run.sum_phase("full", {"factor", "field", "solve"});
}

} // namespace stripes_detail

/// Phases: `factor` (constructing `Field_aligned_parameterizer`: validation, index maps, topology,
/// cotangent weights, factorization of the pinned Laplacian), `field` (`set_field` with a constant
/// direction), `solve` (first solve with two +1/-1 singularity pairs, automatic windings),
/// `resolve` (one +1 moved to a neighbouring face, solved again), and `full` = factor + field +
/// solve (the paper's "with factorization"). Checks: stationarity and face constraints.
inline void stripes_workload(const Mesh& mesh, const std::string& solver, Run& run)
{
  with_solver_traits(solver, [&](auto tag) {
    stripes_detail::run_stripes<typename decltype(tag)::type>(mesh, run);
  });
}

/// The smoothest vector field (n = 1, free boundary) and the stripes along it, the pipeline that
/// geometry-central's examples run (smoothest line field + stripe pattern). Phases: `field`,
/// `stripes` (constructing `Field_aligned_parameterizer` with its factorization, `set_field`,
/// `solve`), `full` = field + stripes, with the two systems sharing one ordering and analysis
/// through a `Symbolic_analysis_cache` (the default and the supernodal traits; the others have
/// none), and `full, analyses not shared` (the same with a cache each). Checks: the Lanczos
/// iteration converged, the stripes' optimality conditions, the number of analyses shared.
inline void field_stripes_workload(const Mesh& mesh, const std::string& solver, Run& run)
{
  with_solver_traits(solver, [&](auto tag) {
    stripes_detail::run_field_stripes<typename decltype(tag)::type>(mesh, run);
  });
}

/// Stripes on the smoothest line field (see `run_branched_stripes`).
inline void line_field_stripes_workload(const Mesh& mesh, const std::string& solver, Run& run)
{
  with_solver_traits(solver, [&](auto tag) {
    stripes_detail::run_branched_stripes<typename decltype(tag)::type>(mesh, 2, run);
  });
}

/// Stripes on the smoothest cross field: two families (see `run_branched_stripes`).
inline void cross_field_stripes_workload(const Mesh& mesh, const std::string& solver, Run& run)
{
  with_solver_traits(solver, [&](auto tag) {
    stripes_detail::run_branched_stripes<typename decltype(tag)::type>(mesh, 4, run);
  });
}

/// The same problem solved by `internal::Face_space_stripe_solver`, with the windings the
/// vertex-space solver chose. Phases: `factor` (its constructor: assembly of A W^-1 A^T and
/// factorization; the topology and weights it takes are computed untimed), `field`, `solve`,
/// `resolve` (after the same move), `full` = factor + field + solve. Not applicable (reported as
/// such) on meshes with a non-positive cotangent weight. Check: y equals the vertex-space y.
inline void stripes_face_space_workload(const Mesh& mesh, const std::string& solver, Run& run)
{
  with_solver_traits(solver, [&](auto tag) {
    stripes_detail::run_stripes_face_space<typename decltype(tag)::type>(mesh, run);
  });
}

} // namespace benchmark

#endif // CGAL_SURFACE_DESIGN_BENCHMARK_WORKLOAD_STRIPES_H
