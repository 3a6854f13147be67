// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The pipeline of `Harmonic_quad_remesher::remesh()`: nets tried in turn (with spectacles, without,
// on the function of the intrinsic Delaunay Laplacian, with finer spacings) until one is a valid
// polygon mesh with the input's topology; each net is made of the function (re-solved on the
// mesh refined along the spectacles), its curves and cells, and with all quads its odd faces
// paired.

#ifndef CGAL_SURFACE_DESIGN_INTERNAL_HARMONIC_QUAD_REMESHING_PIPELINE_H
#define CGAL_SURFACE_DESIGN_INTERNAL_HARMONIC_QUAD_REMESHING_PIPELINE_H

#include <CGAL/Surface_design/exceptions.h>
#include <CGAL/Surface_design/internal/Core/intrinsic_delaunay.h>
#include <CGAL/Surface_design/internal/Core/Mesh_indices.h>
#include <CGAL/Surface_design/internal/Core/validation.h>
#include <CGAL/Surface_design/internal/Harmonic_quad_remeshing/harmonic_function.h>
#include <CGAL/Surface_design/internal/Harmonic_quad_remeshing/net_cells.h>
#include <CGAL/Surface_design/internal/Harmonic_quad_remeshing/odd_faces.h>
#include <CGAL/Surface_design/internal/Harmonic_quad_remeshing/quad_net.h>
#include <CGAL/Surface_design/internal/Harmonic_quad_remeshing/spectacles.h>
#include <CGAL/Surface_design/internal/Harmonic_quad_remeshing/trace_mesh.h>
#include <CGAL/Surface_design/internal/Solvers/solver_traits.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_design {
namespace internal {
namespace harmonic_quad {

/// What the nets of a remesh are made from.
template <class SolverTraits>
struct Pipeline_input
{
  const Trace_mesh& mesh;                                         ///< the input
  const std::vector<double>& u;                                   ///< the harmonic function on it
  const std::vector<std::pair<std::size_t, double>>& constraints; ///< (vertex, value)
  const Soup_topology& topology;                                  ///< of the input
  bool intrinsic_delaunay;      ///< the Laplacian's weights are the intrinsic Delaunay ones (also on refined meshes)
  std::size_t negative_weights; ///< of the cotangent Laplacian: the intrinsic fall-back is tried when some are
  SolverTraits& traits;         ///< a model for the solvers of the refined meshes
  std::function<const std::vector<double>&()> intrinsic_u; ///< the intrinsic Delaunay function, solved on demand
};

/// The options of a remesh that the nets follow.
struct Pipeline_options
{
  double h = 1.;          ///< target spacing
  double adaptation = 0.; ///< curvature adaptation of the spacing
  bool spectacles = true, quad_poles = true, all_quads = true;
};

using Pipeline_clock = std::chrono::steady_clock;

inline double seconds_since(Pipeline_clock::time_point t)
{
  return std::chrono::duration<double>(Pipeline_clock::now() - t).count();
}

struct Net_attempt
{
  bool spectacles;
  double spacing;  // times h
  bool intrinsic;  // the function of the intrinsic Delaunay Laplacian
  bool near_saddles; // half the spacing within 2 h of the saddles
  const char* what;
};

struct Net_settings
{
  double h = 1., adaptation = 0.;
  bool quad_poles = true, all_quads = true;
  std::vector<double> near_saddles; // spacing scale per face: 1/2 within 2 h of a saddle
};

// Nagano & Imai: the spectacles of the saddles (planned on the function and the levels of
// the net), inserted into a copy of the mesh; the function re-solved there with every
// spectacles vertex held at its value; `placed`: their saddles. False (every saddle reported as
// skipped) when no spectacles remain.
template <class SolverTraits, class Result>
bool insert_spectacles(const Pipeline_input<SolverTraits>& in, const std::vector<Critical_point>& critical,
                       Net_options& options, Trace_mesh& refined, std::vector<double>& refined_u,
                       std::vector<std::size_t>& placed, Result& report)
{
  namespace hq = harmonic_quad;
  hq::Spectacles_planner planner(in.mesh, in.u, options.levels, options.edge_length);
  planner.plan(critical);
  for(const auto& s : planner.skipped())
    report.skipped_saddles.emplace_back(s.vertex, s.reason);
  std::vector<hq::Spectacles_plan> plans = planner.plans();
  auto skip_all = [&](const std::string& why) {
    for(const auto& p : plans)
      report.skipped_saddles.emplace_back(p.saddle, why);
    return false;
  };
  hq::Refined_mesh r;
  std::vector<hq::Net_spectacles> net;
  std::vector<char> critical_vertex(in.mesh.number_of_vertices(), 0); // (the input's vertices come first in r)
  for(const Critical_point& c : critical)
    critical_vertex[c.vertex] = c.kind != Critical_kind::regular;
  for(;;)
  {
    if(plans.empty())
      return false;
    hq::Polyline_inserter inserter(in.mesh);
    std::vector<std::array<std::size_t, 2>> junction;
    for(const auto& p : plans)
    {
      inserter.add(p.frame[0], true);
      inserter.add(p.frame[1], true);
      inserter.add(p.bridge, false);
      junction.push_back({inserter.add({p.frame[0][p.junction[0]]}, false).front(),
                          inserter.add({p.frame[1][p.junction[1]]}, false).front()});
    }
    std::string error;
    if(!inserter.build(r, error))
      return skip_all(error);
    // every curve must stay apart from the others after snapping, but at the junctions
    net.clear();
    std::vector<std::size_t> owner(r.points.size(), npos);
    for(const auto& [v, value] : in.constraints)
      owner[v] = plans.size();
    std::size_t bad = npos;
    std::string why = "its curves touch other curves or a constrained vertex once inserted into the mesh";
    for(std::size_t k = 0; k < plans.size() && bad == npos; ++k)
    {
      hq::Net_spectacles sp;
      sp.value = plans[k].value;
      sp.sigma = plans[k].sigma;
      sp.frame = {{r.chains[5 * k], r.chains[5 * k + 1]}};
      sp.bridge = r.chains[5 * k + 2];
      sp.junction = junction[k];
      bool ok = sp.frame[0].size() >= 3 && sp.frame[1].size() >= 3 && sp.bridge.size() >= 2 &&
                sp.bridge.front() == sp.junction[0] && sp.bridge.back() == sp.junction[1] &&
                sp.junction[0] != sp.junction[1];
      std::vector<std::size_t> all(sp.frame[0]);
      all.insert(all.end(), sp.frame[1].begin(), sp.frame[1].end());
      all.insert(all.end(), sp.bridge.begin() + 1, sp.bridge.end() - 1);
      std::vector<std::size_t> sorted(all);
      std::sort(sorted.begin(), sorted.end());
      ok = ok && std::adjacent_find(sorted.begin(), sorted.end()) == sorted.end();
      for(int j = 0; j < 2; ++j)
        ok = ok && std::find(sp.frame[std::size_t(j)].begin(), sp.frame[std::size_t(j)].end(),
                             sp.junction[std::size_t(j)]) != sp.frame[std::size_t(j)].end();
      for(std::size_t v : all)
      {
        ok = ok && owner[v] == npos;
        owner[v] = k;
      }
      // Curves through another critical point would hold it at their value: the level there
      // has another loop, which meets a frame at that vertex (found on the genus-100 slabs,
      // where a frame ran down the vertical edge of the next hole's corner, at its saddle).
      for(std::size_t v : all)
        if(ok && v < critical_vertex.size() && critical_vertex[v] && v != plans[k].saddle)
        {
          ok = false;
          why = "its curves pass through another critical point (vertex " + std::to_string(v) +
                ") once inserted into the mesh";
        }
      if(!ok)
        bad = k;
      else
        net.push_back(std::move(sp));
    }
    if(bad == npos)
      break;
    report.skipped_saddles.emplace_back(plans[bad].saddle, why);
    plans.erase(plans.begin() + std::ptrdiff_t(bad));
  }
  // the refined mesh, its Laplacian and the function held at the spectacles
  using Point = CGAL::Exact_predicates_inexact_constructions_kernel::Point_3;
  using Mesh = CGAL::Surface_mesh<Point>;
  Mesh sm;
  for(const auto& p : r.points)
    sm.add_vertex(Point(p.x(), p.y(), p.z()));
  for(const auto& t : r.triangles)
    if(sm.add_face(typename Mesh::Vertex_index(std::uint32_t(t[0])), typename Mesh::Vertex_index(std::uint32_t(t[1])),
                   typename Mesh::Vertex_index(std::uint32_t(t[2]))) == Mesh::null_face())
      return skip_all("inserting the spectacles into the mesh made it non-manifold");
  Mesh_indices<Mesh> idx(sm);
  const auto vpm = get(CGAL::vertex_point, sm);
  try
  {
    validate_mesh(idx, vpm);
  }
  catch(const Invalid_mesh& e)
  {
    return skip_all(std::string("inserting the spectacles into the mesh made it invalid: ") + e.what());
  }
  refined = hq::make_trace_mesh(idx, vpm);
  Intrinsic_triangulation intrinsic(idx, vpm);
  if(in.intrinsic_delaunay)
    intrinsic.make_delaunay();
  Harmonic_solver<SolverTraits> solver(refined.number_of_vertices(), intrinsic.cotangent_weights(),
                                       new_solver_like(in.traits));
  std::vector<char> constrained(refined.number_of_vertices(), 0);
  refined_u.assign(refined.number_of_vertices(), 0.);
  for(const auto& [v, value] : in.constraints)
  {
    constrained[v] = 1;
    refined_u[v] = value;
  }
  for(const auto& sp : net)
    for(const auto* chain : {&sp.frame[0], &sp.frame[1], &sp.bridge})
      for(std::size_t v : *chain)
      {
        constrained[v] = 1;
        refined_u[v] = sp.value;
      }
  try
  {
    solver.factor(constrained);
    solver.solve(refined_u);
  }
  catch(const Linear_solver_failure& e)
  {
    return skip_all(std::string("the function could not be solved again with the spectacles: ") + e.what());
  }
  options.spectacles = std::move(net);
  report.spectacles = options.spectacles.size();
  placed.clear();
  for(const auto& p : plans)
    placed.push_back(p.saddle);
  return true;
}

// One net: the function, spectacles, curves, cells; true when it is a valid polygon mesh
// with the input's topology (else `why` says what went wrong). With all quads, the odd faces
// are paired (the pairing is kept only when it keeps the mesh valid and its topology).
template <class SolverTraits, class Result>
bool make_net(const Pipeline_input<SolverTraits>& in, const Net_attempt& attempt,
              const std::vector<Critical_point>& critical, const Net_settings& settings, Polygon_soup& soup,
              Result& report, std::string& why)
{
  namespace hq = harmonic_quad;
  using CGAL::Polygon_mesh_processing::is_polygon_soup_a_polygon_mesh;
  hq::Net_options options;
  options.edge_length = settings.h * attempt.spacing;
  options.quad_poles = settings.quad_poles;
  report.spacing = options.edge_length;
  const std::vector<double>* u = &in.u;
  if(attempt.intrinsic)
  {
    const auto start = Pipeline_clock::now();
    u = &in.intrinsic_u();
    report.harmonic_seconds += seconds_since(start);
  }
  // with spectacles: the net of the re-solved function on the mesh refined along them
  hq::Trace_mesh refined;
  std::vector<double> refined_u;
  const hq::Trace_mesh* mesh = &in.mesh;
  std::vector<std::size_t> spectacles_saddles; // the saddles given spectacles
  report.spectacles = 0;
  if(attempt.spectacles)
  {
    const auto start = Pipeline_clock::now();
    options.levels = hq::Quad_net_builder(in.mesh, in.u, options).regular_levels();
    if(insert_spectacles(in, critical, options, refined, refined_u, spectacles_saddles, report))
    {
      mesh = &refined;
      u = &refined_u;
    }
    else
      options.levels.clear();
    report.spectacles_seconds += seconds_since(start);
  }

  auto start = Pipeline_clock::now();
  if(settings.adaptation > 0.)
    options.spacing_scale = hq::curvature_spacing_scale(*mesh, options.edge_length, settings.adaptation);
  if(attempt.near_saddles) // (no spectacles: `mesh` is the input)
  {
    const std::vector<double>& near = settings.near_saddles;
    if(options.spacing_scale.empty())
      options.spacing_scale = near;
    else
      for(std::size_t f = 0; f < near.size(); ++f)
        options.spacing_scale[f] = (std::max)(0.25, options.spacing_scale[f] * near[f]);
  }
  hq::Quad_net_builder builder(*mesh, *u, options);
  soup = builder.build();
  const auto& s = builder.statistics();
  report.levels = s.levels;
  report.isolines = s.isolines;
  report.gradient_lines = s.gradient_lines;
  report.stopped_lines = s.stopped_lines;
  report.started_lines = s.started_lines;
  report.merged_lines = s.merged_lines;
  report.saddle_levels = s.saddle_levels;
  report.spectacles_lines = s.spectacles_lines;
  report.boundary_detail_vertices = s.boundary_detail_nodes;
  report.curves_seconds += seconds_since(start);

  start = Pipeline_clock::now();
  report.repaired_cells = hq::split_pinched_cells(soup);
  auto failed = [&](const std::string& reason) {
    why = reason;
    for(std::size_t sp : spectacles_saddles)
      report.skipped_saddles.emplace_back(sp, "the net around its spectacles is not a valid polygon mesh "
                                              "with the input's topology");
    report.meshing_seconds += seconds_since(start);
    return false;
  };
  if(soup.faces.empty())
  {
    char spacing[32];
    std::snprintf(spacing, sizeof spacing, "%.4g", options.edge_length);
    return failed(std::string("the net is empty (every isoline was shorter than the spacing ") + spacing + ")");
  }
  if(!is_polygon_soup_a_polygon_mesh(soup.faces))
    return failed("the net is not a valid polygon mesh (a cell of the net could not be made a disk)");
  const hq::Soup_topology net = hq::soup_topology(soup.faces, soup.points.size());
  if(net != in.topology)
    return failed("the net has " + net.text() + " (a cell of the net is not a disk: the curves "
                  "missed a handle or a hole)");
  report.odd_faces = 0;
  bool only_quads = true;
  for(const auto& face : soup.faces)
  {
    report.odd_faces += face.size() % 2;
    only_quads = only_quads && face.size() == 4;
  }
  if(settings.all_quads && !only_quads)
  {
    const auto quads_start = Pipeline_clock::now();
    hq::Polygon_soup quads = soup;
    const hq::Odd_face_statistics pairing = hq::Odd_face_pairing(quads).run();
    // (kept only when valid: the pairing never breaks a valid mesh, this is a safety net)
    if(is_polygon_soup_a_polygon_mesh(quads.faces) && hq::soup_topology(quads.faces, quads.points.size()) == in.topology)
    {
      soup = std::move(quads);
      report.odd_face_paths = pairing.paths + pairing.boundary_paths;
      report.split_edges = pairing.split_edges;
    }
    report.all_quads_seconds += seconds_since(quads_start);
  }
  report.meshing_seconds += seconds_since(start);
  return true;
}


/// The net with the input's topology: the attempts in turn (as asked; without spectacles; the
/// intrinsic Delaunay function when the cotangent Laplacian has negative weights; finer spacings,
/// the one adding the fewest faces first). `report` (a `Harmonic_quad_remeshing_result`) receives
/// the counts of the net made, the fall-backs taken and the times, which add up over the attempts.
/// \throws Remeshing_failure when no attempt gives a net with the input's topology
template <class SolverTraits, class Result>
Polygon_soup make_quad_net(const Pipeline_input<SolverTraits>& in, const Pipeline_options& options, Result& report)
{
  const double h = options.h;
  double area = 0.;
  for(double a : in.mesh.area)
    area += a;
  namespace hq = harmonic_quad;
  const auto critical = hq::critical_points(in.mesh, in.u).first;
  std::vector<std::size_t> saddles;
  for(const auto& c : critical)
    if(c.kind == hq::Critical_kind::saddle)
      saddles.push_back(c.vertex);
  report.saddles = saddles.size();
  // what the package has, tried in turn until the net has the input's topology
  const bool spectacles = options.spectacles && report.saddles > 0;
  std::vector<Net_attempt> attempts{{spectacles, 1., false, false, "as asked"}};
  if(spectacles)
    attempts.push_back({false, 1., false, false, "without spectacles"});
  if(in.negative_weights > 0)
    attempts.push_back({false, 1., true, false, "the intrinsic Delaunay Laplacian"});
  // finer spacings, the one that adds the fewest faces first: h / 2 near the saddles (a share
  // a of the area: about 1 + 3 a times the faces), h / sqrt 2 (twice), h / 2 (four times)
  Net_settings settings;
  std::vector<std::pair<double, Net_attempt>> finer;
  if(!saddles.empty())
  {
    settings.near_saddles = hq::saddle_spacing_scale(in.mesh, saddles, 2. * h, 0.5);
    double near = 0.;
    for(std::size_t f = 0; f < in.mesh.number_of_faces(); ++f)
      near += settings.near_saddles[f] < 1. ? in.mesh.area[f] : 0.;
    if(area * (1. + 3. * near / area) / (h * h) <= 1e7)
      finer.push_back({1. + 3. * near / area, {false, 1., false, true, "spacing h / 2 within 2 h of the saddles"}});
  }
  for(const auto& [scale, name] : {std::make_pair(std::sqrt(0.5), "spacing h / sqrt 2"), std::make_pair(0.5, "spacing h / 2")})
    if(area / (h * h * scale * scale) <= 1e7)
      finer.push_back({1. / (scale * scale), {false, scale, false, false, name}});
  std::stable_sort(finer.begin(), finer.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  for(const auto& f : finer)
    attempts.push_back(f.second);
  settings.h = h;
  settings.adaptation = options.adaptation;
  settings.quad_poles = options.quad_poles;
  settings.all_quads = options.all_quads;
  hq::Polygon_soup soup;
  bool made = false;
  for(std::size_t k = 0; k < attempts.size() && !made; ++k)
  {
    const Net_attempt& attempt = attempts[k];
    Result r = report;
    std::string why;
    made = make_net(in, attempt, critical, settings, soup, r, why);
    // the times add up over the attempts
    report.harmonic_seconds = r.harmonic_seconds;
    report.spectacles_seconds = r.spectacles_seconds;
    report.curves_seconds = r.curves_seconds;
    report.meshing_seconds = r.meshing_seconds;
    report.all_quads_seconds = r.all_quads_seconds;
    if(made)
    {
      r.fallbacks = report.fallbacks;
      if(k > 0)
        r.fallbacks.push_back(std::string("used: ") + attempt.what);
      report = std::move(r);
    }
    else
    {
      report.fallbacks.push_back(std::string(attempt.what) + ": " + why);
      report.skipped_saddles = r.skipped_saddles;
    }
    // a later attempt without spectacles would repeat this one when no spectacles were placed
    if(!made && attempt.spectacles && r.spectacles == 0 && k + 1 < attempts.size() && !attempts[k + 1].spectacles &&
       attempts[k + 1].spacing == 1. && !attempts[k + 1].intrinsic && !attempts[k + 1].near_saddles)
      ++k;
  }
  if(!made)
  {
    std::string what = "no net of isolines and gradient lines with the input's topology (" + in.topology.text() +
                       "); tried";
    for(const auto& f : report.fallbacks)
      what += "\n  " + f;
    throw Remeshing_failure(what);
  }
  return soup;
}

} // namespace harmonic_quad
} // namespace internal
} // namespace Surface_design
} // namespace CGAL

#endif // CGAL_SURFACE_DESIGN_INTERNAL_HARMONIC_QUAD_REMESHING_PIPELINE_H
