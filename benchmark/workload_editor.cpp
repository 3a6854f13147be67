// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The `editor` workload (see workload_editor.h).

#include "workload_editor.h"

#include "../examples/Programs/Editor/editor_session.h"

#include <CGAL/Polygon_mesh_processing/measure.h>

#include <cmath>
#include <set>
#include <string>
#include <vector>

namespace benchmark {

namespace editor_detail {

// A walk across edges from face `start`: each step to an adjacent face not visited yet and with
// no edge on the boundary (those cannot hold a singularity). Stops early when stuck.
inline std::vector<std::size_t> walk(const Mesh& mesh, std::size_t start, std::size_t steps)
{
  auto interior = [&](Mesh::Face_index f) {
    for(auto h : halfedges_around_face(halfedge(f, mesh), mesh))
      if(is_border(opposite(h, mesh), mesh))
        return false;
    return true;
  };
  std::vector<std::size_t> path{start};
  std::set<std::size_t> visited{start};
  Mesh::Face_index f(static_cast<std::uint32_t>(start));
  Mesh::Halfedge_index h = halfedge(f, mesh);
  for(std::size_t i = 0; i < steps; ++i)
  {
    bool moved = false;
    for(int k = 0; k < 3 && !moved; ++k, h = next(h, mesh))
    {
      const auto g = face(opposite(h, mesh), mesh);
      if(g != Mesh::null_face() && !visited.count(std::size_t(g)) && interior(g))
      {
        path.push_back(std::size_t(g));
        visited.insert(std::size_t(g));
        h = next(opposite(h, mesh), mesh); // keep heading away: leave g by another edge
        moved = true;
      }
    }
    if(!moved)
      break;
  }
  return path;
}

inline std::size_t first_interior_face(const Mesh& mesh, std::size_t from)
{
  for(std::size_t i = 0; i < num_faces(mesh); ++i)
  {
    const Mesh::Face_index f(static_cast<std::uint32_t>((from + i) % num_faces(mesh)));
    bool interior = true;
    for(auto h : halfedges_around_face(halfedge(f, mesh), mesh))
      interior = interior && !is_border(opposite(h, mesh), mesh);
    if(interior)
      return std::size_t(f);
  }
  throw Not_applicable("every face has an edge on the boundary");
}

} // namespace editor_detail

void editor_workload(const Mesh& mesh, const std::string&, Run& run)
{
  using editor::Json;
  std::unique_ptr<editor::Session> session;
  run.phase("open", [&] { session = std::make_unique<editor::Session>(mesh, "benchmark"); });
  const std::vector<std::size_t> path =
    editor_detail::walk(mesh, editor_detail::first_interior_face(mesh, num_faces(mesh) / 3), 40);
  if(path.size() < 41)
    throw Not_applicable("no walk of 40 interior faces from face " + std::to_string(path.front()));
  // what the server does with a request body: parse, edit, serialize
  auto request = [&](const std::string& body) { return session->edit(Json::parse(body)); };
  std::string bytes;
  run.phase("add pair", [&] {
    bytes = request(R"({"op":"add_pair","plus":)" + std::to_string(path[0]) + R"(,"minus":)" +
                    std::to_string(path[20]) + "}");
  });
  double moves_ms = 0.;
  const std::size_t moves = 20;
  for(std::size_t i = 20; i < 20 + moves; ++i)
  {
    const auto start = Clock::now();
    bytes = request(R"({"op":"move","from":)" + std::to_string(path[i]) + R"(,"to":)" + std::to_string(path[i + 1]) + "}");
    moves_ms += std::chrono::duration<double, std::milli>(Clock::now() - start).count();
  }
  run.record("drag step", moves_ms / double(moves));
  run.phase("frequency", [&] { bytes = request(R"({"op":"frequency","stripes":3.5})"); });
  run.phase("state", [&] { bytes = session->state(); });
  if(run.checks_enabled())
  {
    const std::uint32_t length = std::uint32_t((unsigned char)bytes[0]) | std::uint32_t((unsigned char)bytes[1]) << 8 |
                                 std::uint32_t((unsigned char)bytes[2]) << 16 | std::uint32_t((unsigned char)bytes[3]) << 24;
    const Json state = Json::parse(bytes.substr(4, length));
    run.check("size of the state - (4 + header + 12 bytes per face)",
              std::abs(double(bytes.size()) - double(4 + length + 12 * num_faces(mesh))), 0.5);
    run.check("|singularities after the drag - 2|", std::abs(double(state["singularities"].size()) - 2.), 0.5);
  }
  // the quad preview of a cross field: the trivial connection's cones (on a mesh with a boundary,
  // the smoothest field's along it, and the connection along it too), about 2000 quads, then a
  // cone dragged across 10 faces, each step a new field, a factorization, the stripes, the
  // extraction (and its stiffening rounds where the map folds)
  const bool closed = CGAL::is_closed(mesh);
  auto state_of = [](const std::string& b) {
    const std::uint32_t length = std::uint32_t((unsigned char)b[0]) | std::uint32_t((unsigned char)b[1]) << 8 |
                                 std::uint32_t((unsigned char)b[2]) << 16 | std::uint32_t((unsigned char)b[3]) << 24;
    return Json::parse(b.substr(4, length));
  };
  bytes = request(R"({"op":"clear"})");
  try
  {
    const auto start = Clock::now();
    bytes = request(closed ? R"({"op":"field","kind":"trivial","order":4})"
                           : R"({"op":"field","kind":"trivial","order":4,"cones":"smoothest","boundary":"tangent"})");
    run.record("cross field", std::chrono::duration<double, std::milli>(Clock::now() - start).count());
  }
  catch(const editor::Request_error&)
  {
    // the trivial connection's default cones admit no field on some meshes (a tip of high
    // curvature without a cone): then this part does not apply
    return;
  }
  Json state = state_of(bytes);
  if(state["field_singularities"].empty())
    return;
  const double diagonal = session->mesh_json()["diagonal"].get<double>(); // the session's own
  const double stripes = (std::min)(double(state["max_stripes"]),
                                    diagonal * std::sqrt(2000. / CGAL::Polygon_mesh_processing::area(mesh)));
  // (a number, not its decimal text: std::to_string may round the largest count up, past the limit)
  bytes = session->edit(Json{{"op", "frequency"}, {"stripes", stripes}});
  run.phase("quads on", [&] { bytes = request(R"({"op":"quads","on":true})"); });
  state = state_of(bytes); // (a range-for over a temporary's member would dangle)
  std::set<std::size_t> cones;
  for(const auto& c : state["field_singularities"])
    cones.insert(c[0].get<std::size_t>());
  const std::size_t cone = *cones.begin();
  std::vector<std::size_t> cone_path = editor_detail::walk(mesh, cone, 10);
  double quad_ms = 0.;
  std::size_t steps = 0, valid = 0;
  for(std::size_t i = 0; i + 1 < cone_path.size() && !cones.count(cone_path[i + 1]); ++i)
  {
    const auto start = Clock::now();
    try
    {
      bytes = request(R"({"op":"move_field_singularity","from":)" + std::to_string(cone_path[i]) + R"(,"to":)" +
                      std::to_string(cone_path[i + 1]) + "}");
    }
    catch(const editor::Request_error&)
    {
      break; // no field with the cone there (refused, the state unchanged): the drag stops
    }
    quad_ms += std::chrono::duration<double, std::milli>(Clock::now() - start).count();
    ++steps;
    valid += state_of(bytes)["quads"].value("valid", false) ? 1 : 0;
  }
  if(steps == 0)
    return;
  run.record("quad drag step", quad_ms / double(steps));
  if(run.checks_enabled())
    // where the stiffening rounds do not unfold the map the preview reports what the check found
    // instead (a result, not an error); a drag none of whose steps gives quads is one
    run.check("fraction of the drag steps whose preview was not the field's quad mesh",
              double(steps - valid) / double(steps), 1.);
}

} // namespace benchmark
