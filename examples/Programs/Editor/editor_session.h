// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The state of the stripe editor, apart from HTTP: one mesh, its Field_aligned_parameterizer
// (factored once per mesh), the field the stripes follow, the prescribed singularities, and the
// per-corner stripe coordinate of the last solve. Every edit is a JSON request; it either succeeds
// and re-solves (one back-substitution for the singularities, O(|E|) for a new frequency, plus
// the field's own solve when the field changes), or throws Request_error and leaves the state as
// it was. The server (surface_design_editor.cpp) and the benchmark (benchmark/editor_latency.cpp)
// drive this class.

#ifndef CGAL_SURFACE_DESIGN_EDITOR_SESSION_H
#define CGAL_SURFACE_DESIGN_EDITOR_SESSION_H

#include "../common/program_support.h"
#include "../common/stripe_fields.h"

#include <CGAL/Surface_design/direction_fields.h>
#include <CGAL/Surface_design/exceptions.h>
#include <CGAL/Surface_design/Field_aligned_parameterizer.h>
#include <CGAL/Surface_design/Trivial_connection.h>

#include <CGAL/Polygon_mesh_processing/connected_components.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace editor {

namespace SD = CGAL::Surface_design;
using program::Mesh;
using program::Point;
using program::Vector;
using Json = nlohmann::json;
using Clock = std::chrono::steady_clock;

/// A request that cannot be carried out (malformed, out of range, or inconsistent with the mesh):
/// the message says what and where; the session is unchanged.
struct Request_error : std::invalid_argument
{
  using std::invalid_argument::invalid_argument;
};

inline double ms_since(Clock::time_point start)
{
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

/// The meshes the editor can load, by name: the `.off`, `.obj` and `.ply` files of a folder, plus
/// the mesh given on the command line.
class Mesh_catalog
{
public:
  void add_folder(const std::string& folder)
  {
    std::error_code ec;
    for(const auto& entry : std::filesystem::directory_iterator(folder, ec))
    {
      const std::string ext = entry.path().extension().string();
      if(entry.is_regular_file() && (ext == ".off" || ext == ".obj" || ext == ".ply"))
        m_paths.emplace(entry.path().filename().string(), entry.path().string());
    }
  }
  /// Adds `path` under its file name (replacing a bundled mesh of that name) and returns the name.
  std::string add_file(const std::string& path)
  {
    const std::string name = std::filesystem::path(path).filename().string();
    m_paths[name] = path;
    return name;
  }
  const std::string& path(const std::string& name) const
  {
    const auto it = m_paths.find(name);
    if(it == m_paths.end())
      throw Request_error("unknown mesh '" + name + "' (GET /api/meshes lists the meshes)");
    return it->second;
  }
  Json names() const
  {
    Json list = Json::array();
    for(const auto& [name, path] : m_paths)
      list.push_back(name);
    return list;
  }

private:
  std::map<std::string, std::string> m_paths;
};

/// One mesh being edited.
class Session
{
  using Solver = SD::Default_solver_traits;
  using Parameterizer = SD::Field_aligned_parameterizer<Mesh>;
  using Connection = SD::Trivial_connection<Mesh>;

public:
  /// Reads and validates `path`, factors the stripes' Laplacian and solves for the default field
  /// (the +Y axis, 10 stripes across the bounding box or fewer on coarse meshes), no singularity.
  /// `mesh_version` tells the page that the mesh changed. Throws std::runtime_error (unreadable
  /// file) or the library's exceptions (invalid mesh).
  Session(const std::string& path, const std::string& name, long mesh_version = 0)
    : Session(program::read_mesh(path), name, mesh_version)
  {}

  /// The same for a mesh in memory.
  Session(Mesh mesh_in, const std::string& name, long mesh_version = 0)
    : m_name(name), m_mesh(std::make_unique<Mesh>(std::move(mesh_in))), m_mesh_version(mesh_version)
  {
    const Mesh& mesh = *m_mesh;
    if(num_faces(mesh) == 0)
      throw std::runtime_error(name + " has no face");
    m_field_solver = program::solver_sharing_analysis(m_stripe_solver);
    m_fap = std::make_unique<Parameterizer>(mesh, SD::parameters::sparse_linear_solver(m_stripe_solver));
    m_corner = m_mesh->add_property_map<Mesh::Halfedge_index, double>("h:editor_corner", 0.).first;
    geometry();
    m_stripes = (std::min)(10., 0.1 * m_diagonal / m_mean_edge);
    m_field = std::vector<Vector>(num_vertices(mesh), Vector(0., 1., 0.));
    m_field_spec = {{"kind", "axis"}, {"axis", {0., 1., 0.}}};
    m_fap->set_field(CGAL::make_property_map(m_field), m_stripes / m_diagonal);
    solve();
  }

  const std::string& name() const { return m_name; }
  const Mesh& mesh() const { return *m_mesh; }
  std::size_t number_of_faces() const { return num_faces(*m_mesh); }

  /// The mesh as JSON: positions (x y z per vertex), triangles (three vertex indices per face,
  /// in the order of the per-corner data), faces with an edge on the boundary (they cannot hold
  /// a singularity), the bounding-box diagonal and the largest stripe count the mesh resolves.
  Json mesh_json() const
  {
    const Mesh& mesh = *m_mesh;
    std::vector<float> positions;
    positions.reserve(3 * num_vertices(mesh));
    for(auto v : vertices(mesh))
      for(int i = 0; i < 3; ++i)
        positions.push_back(float(mesh.point(v)[i]));
    std::vector<std::uint32_t> triangles;
    triangles.reserve(3 * num_faces(mesh));
    Json boundary = Json::array();
    for(auto f : faces(mesh))
    {
      for(auto h : corners(f))
        triangles.push_back(std::uint32_t(target(h, mesh)));
      if(m_fap->has_boundary_edge(f))
        boundary.push_back(std::size_t(f));
    }
    return Json{{"name", m_name},
                {"vertices", num_vertices(mesh)},
                {"faces", num_faces(mesh)},
                {"positions", positions},
                {"triangles", triangles},
                {"boundary_faces", boundary},
                {"diagonal", m_diagonal},
                {"max_stripes", max_stripes()},
                {"closed_components_euler", closed_euler_characteristics()},
                {"mesh_version", m_mesh_version}};
  }

  /// Carries out one edit (see the manual for the requests) and returns the new state, or throws
  /// Request_error with the state unchanged. `received`: when the request arrived (for the
  /// server time reported in the state).
  std::string edit(const Json& request, Clock::time_point received = Clock::now())
  {
    if(!request.is_object())
      throw Request_error("the request must be a JSON object with an \"op\" member");
    const std::string op = text_arg(request, "op");
    m_timing = {};
    if(op == "state")
      return state(received);
    if(op == "add")
    {
      const std::size_t f = face_arg(request, "face");
      const int k = index_arg(request, "index");
      singularities_edit([&] { m_fap->set_index(descriptor(f), m_fap->index(descriptor(f)) + k); },
                         "adding index " + std::to_string(k) + " at face " + std::to_string(f));
    }
    else if(op == "add_pair")
    {
      const std::size_t a = face_arg(request, "plus"), b = face_arg(request, "minus");
      if(a == b)
        throw Request_error("add_pair: the +1 and the -1 must be in different faces (both are " + std::to_string(a) + ")");
      singularities_edit([&] {
        m_fap->set_index(descriptor(a), m_fap->index(descriptor(a)) + 1);
        m_fap->set_index(descriptor(b), m_fap->index(descriptor(b)) - 1);
      }, "adding a +1/-1 pair at faces " + std::to_string(a) + " and " + std::to_string(b));
    }
    else if(op == "move")
    {
      const std::size_t from = face_arg(request, "from"), to = face_arg(request, "to");
      if(m_fap->index(descriptor(from)) == 0)
        throw Request_error("move: face " + std::to_string(from) + " holds no singularity");
      if(from == to)
        return state(received); // nothing moved: no solve
      singularities_edit([&] { m_fap->move_singularity(descriptor(from), descriptor(to)); },
                         "moving the singularity of face " + std::to_string(from) + " to face " + std::to_string(to));
    }
    else if(op == "annihilate")
    {
      const std::size_t a = face_arg(request, "a"), b = face_arg(request, "b");
      singularities_edit([&] { m_fap->annihilate(descriptor(a), descriptor(b)); },
                         "annihilating faces " + std::to_string(a) + " and " + std::to_string(b));
    }
    else if(op == "remove")
    {
      const std::size_t f = face_arg(request, "face");
      if(m_fap->index(descriptor(f)) == 0)
        throw Request_error("remove: face " + std::to_string(f) + " holds no singularity");
      singularities_edit([&] { m_fap->set_index(descriptor(f), 0); }, "removing the singularity of face " + std::to_string(f));
    }
    else if(op == "clear")
      singularities_edit([&] { m_fap->clear_indices(); }, "removing every singularity");
    else if(op == "frequency")
      set_stripes(number_arg(request, "stripes"));
    else if(op == "field")
      set_field(request);
    else if(op == "move_field_singularity")
      move_field_singularity(face_arg(request, "from"), face_arg(request, "to"));
    else
      throw Request_error("unknown op '" + op + "' (add, add_pair, move, annihilate, remove, clear, frequency, field, "
                          "move_field_singularity, load, state)");
    ++m_version;
    return state(received);
  }

  /// The current state: a 4-byte little-endian length L, L bytes of JSON (padded with spaces to
  /// a multiple of 4 bytes in all), then 3 float32 per face: the stripe coordinate u at the
  /// corners of every face (cos u is the stripe pattern; u / 2 pi counts stripes).
  std::string state(Clock::time_point received = Clock::now()) const
  {
    const auto start = Clock::now();
    const std::size_t nf = num_faces(*m_mesh);
    std::string corners_bytes(3 * nf * sizeof(float), '\0');
    float* out = reinterpret_cast<float*>(corners_bytes.data());
    for(auto f : faces(*m_mesh))
    {
      std::size_t k = 0;
      for(auto h : corners(f))
        out[3 * std::size_t(f) + k++] = float(m_corner[h]);
    }
    Json singular = Json::array(), field_singular = Json::array();
    for(auto f : faces(*m_mesh))
      if(m_fap->index(f) != 0)
        singular.push_back({std::size_t(f), m_fap->index(f)});
    for(const auto& [f, k] : m_field_singularities)
      field_singular.push_back({f, k});
    Json timing = m_timing;
    timing["serialize_ms"] = ms_since(start);
    timing["server_ms"] = ms_since(received);
    const Json state{{"version", m_version},
                     {"mesh", m_name},
                     {"mesh_version", m_mesh_version},
                     {"faces", nf},
                     {"singularities", singular},
                     {"field", m_field_spec},
                     {"field_singularities", field_singular},
                     {"stripes", m_stripes},
                     {"max_stripes", max_stripes()},
                     {"energy", m_fap->energy()},
                     {"timing", timing}};
    std::string header = state.dump();
    while((4 + header.size()) % 4 != 0)
      header += ' ';
    std::string bytes(4, '\0');
    const std::uint32_t length = std::uint32_t(header.size());
    for(int i = 0; i < 4; ++i)
      bytes[std::size_t(i)] = char((length >> (8 * i)) & 0xFF);
    return bytes + header + corners_bytes;
  }

  /// The stripes as an ASCII PLY: alpha per vertex, the prescribed index per face.
  std::string export_ply() const
  {
    program::Ply_property alpha{"alpha", "double", {}}, index{"index", "int", {}};
    for(auto v : vertices(*m_mesh))
      alpha.values.push_back(m_fap->alpha(v));
    for(auto f : faces(*m_mesh))
      index.values.push_back(m_fap->index(f));
    const auto file = std::filesystem::temp_directory_path() /
                      ("surface_design_editor_" + std::to_string(::getpid()) + "_" + std::to_string(m_version) + ".ply");
    program::write_ply(file.string(), *m_mesh, {alpha}, {index});
    std::ifstream in(file, std::ios::binary);
    std::ostringstream content;
    content << in.rdbuf();
    std::error_code ec;
    std::filesystem::remove(file, ec);
    return content.str();
  }

private:
  // ---- request fields
  static const Json& member(const Json& request, const char* key)
  {
    const auto it = request.find(key);
    if(it == request.end())
      throw Request_error(std::string("missing \"") + key + "\" in the request");
    return *it;
  }
  static std::string text_arg(const Json& request, const char* key)
  {
    const Json& j = member(request, key);
    if(!j.is_string())
      throw Request_error(std::string("\"") + key + "\" must be a string");
    return j.get<std::string>();
  }
  static double number_arg(const Json& request, const char* key)
  {
    const Json& j = member(request, key);
    if(!j.is_number() || !std::isfinite(j.get<double>()))
      throw Request_error(std::string("\"") + key + "\" must be a finite number");
    return j.get<double>();
  }
  static long integer_arg(const Json& request, const char* key, long lo, long hi)
  {
    const Json& j = member(request, key);
    if(!j.is_number_integer())
      throw Request_error(std::string("\"") + key + "\" must be an integer");
    const long long value = j.get<long long>();
    if(value < lo || value > hi)
      throw Request_error(std::string("\"") + key + "\" = " + std::to_string(value) + " is out of range [" +
                          std::to_string(lo) + ", " + std::to_string(hi) + "]");
    return long(value);
  }
  std::size_t face_arg(const Json& request, const char* key) const
  {
    const Json& j = member(request, key);
    if(!j.is_number_integer() || j.get<long long>() < 0 || j.get<long long>() >= (long long)(num_faces(*m_mesh)))
      throw Request_error(std::string("\"") + key + "\" = " + j.dump() + " is not a face of " + m_name + " (0 to " +
                          std::to_string(num_faces(*m_mesh) - 1) + ")");
    return std::size_t(j.get<long long>());
  }
  static int index_arg(const Json& request, const char* key)
  {
    const int k = int(integer_arg(request, key, -4, 4));
    if(k == 0)
      throw Request_error("index 0 adds nothing (use \"remove\")");
    return k;
  }
  static Mesh::Face_index descriptor(std::size_t f) { return Mesh::Face_index(static_cast<std::uint32_t>(f)); }

  // the three halfedges of face f, whose targets are its corners, in the order of mesh_json()
  std::array<Mesh::Halfedge_index, 3> corners(Mesh::Face_index f) const
  {
    const auto h = halfedge(f, *m_mesh);
    return {h, next(h, *m_mesh), next(next(h, *m_mesh), *m_mesh)};
  }

  // ---- edits
  // Applies `change` to the singularities and solves; on failure restores them and reports why.
  template <class Change>
  void singularities_edit(Change&& change, const std::string& what)
  {
    const std::vector<int> before = m_fap->indices_per_face();
    auto restore = [&] {
      for(auto f : faces(*m_mesh))
        m_fap->set_index(f, before[std::size_t(f)]);
    };
    try
    {
      change();
      solve();
    }
    catch(const SD::Invalid_constraints& e)
    {
      restore();
      throw Request_error(what + ": " + e.what() + closed_hint());
    }
    catch(const SD::Invalid_parameter& e)
    {
      restore();
      throw Request_error(what + ": " + e.what());
    }
  }

  std::string closed_hint() const
  {
    return closed_euler_characteristics().empty()
             ? std::string()
             : " (on a closed surface the stripe indices sum to 0: add them in +1/-1 pairs, or move and "
               "annihilate existing ones)";
  }

  void set_stripes(double stripes)
  {
    if(!(stripes > 0.) || stripes > max_stripes())
      throw Request_error("\"stripes\" = " + program::text(stripes) + ": choose a count in (0, " +
                          program::text(max_stripes()) + "] (the mesh's average edge must carry less than half a stripe)");
    const double before = m_stripes;
    m_stripes = stripes;
    try
    {
      set_field_and_solve();
    }
    catch(const std::invalid_argument& e)
    {
      m_stripes = before;
      set_field_and_solve();
      throw Request_error(std::string("frequency: ") + e.what());
    }
  }

  void set_field(const Json& request)
  {
    const std::string kind = text_arg(request, "kind");
    const auto start = Clock::now();
    std::vector<Vector> field;
    Json spec{{"kind", kind}};
    std::map<std::size_t, int> field_singularities;
    std::unique_ptr<Connection> connection;
    if(kind == "axis")
    {
      const Json& axis = member(request, "axis");
      if(!axis.is_array() || axis.size() != 3 || !std::all_of(axis.begin(), axis.end(), [](const Json& x) {
           return x.is_number() && std::isfinite(x.get<double>());
         }))
        throw Request_error("\"axis\" must be an array of three finite numbers");
      const double x = axis[0].get<double>(), y = axis[1].get<double>(), z = axis[2].get<double>();
      const double largest = (std::max)({std::abs(x), std::abs(y), std::abs(z)});
      if(largest == 0.)
        throw Request_error("\"axis\" [0, 0, 0] has no direction");
      field.assign(num_vertices(*m_mesh), Vector(x / largest, y / largest, z / largest));
      spec["axis"] = {x, y, z};
    }
    else if(kind == "smoothest")
    {
      if(!m_smoothest)
      {
        std::vector<Vector> smoothest(num_vertices(*m_mesh));
        wrap_library([&] {
          SD::smoothest_direction_field(*m_mesh, CGAL::make_property_map(smoothest),
                                        SD::parameters::sparse_linear_solver(m_field_solver));
        }, "smoothest field");
        m_smoothest = std::move(smoothest);
      }
      field = *m_smoothest;
    }
    else if(kind == "heat")
    {
      const std::size_t v = std::size_t(integer_arg(request, "vertex", 0, long(num_vertices(*m_mesh)) - 1));
      const double degrees = request.contains("degrees") ? number_arg(request, "degrees") : 0.;
      if(std::abs(degrees) > 360.)
        throw Request_error("\"degrees\" must lie in [-360, 360]");
      if(m_components > 1)
        throw Request_error("the heat field covers only the connected component of its source, and " + m_name +
                            " has " + std::to_string(m_components) + " components: use axis, smoothest or trivial");
      field = program::heat_field(*m_mesh, Mesh::Vertex_index(static_cast<std::uint32_t>(v)), degrees);
      spec["vertex"] = v;
      spec["degrees"] = degrees;
    }
    else if(kind == "trivial")
    {
      connection = std::make_unique<Connection>(*m_mesh, SD::parameters::sparse_linear_solver(m_field_solver));
      field_singularities = default_field_singularities();
      for(const auto& [f, k] : field_singularities)
        connection->set_index(f, k);
      field.resize(num_vertices(*m_mesh));
      wrap_library([&] {
        connection->solve();
        connection->field(CGAL::make_property_map(field));
      }, "trivial connection");
    }
    else
      throw Request_error("unknown field kind '" + kind + "' (axis, smoothest, heat, trivial)");
    const double field_ms = ms_since(start);
    // all or nothing: the stripes solve with the new field, or everything stays
    std::swap(field, m_field);
    try
    {
      set_field_and_solve();
    }
    catch(const std::invalid_argument& e)
    {
      std::swap(field, m_field);
      set_field_and_solve();
      throw Request_error(std::string("field ") + kind + ": " + e.what());
    }
    m_field_spec = spec;
    m_connection = std::move(connection);
    m_field_singularities = std::move(field_singularities);
    m_timing["field_ms"] = field_ms;
  }

  void move_field_singularity(std::size_t from, std::size_t to)
  {
    if(!m_connection)
      throw Request_error("move_field_singularity: the field is not a trivial connection (choose \"trivial\" first)");
    const auto it = m_field_singularities.find(from);
    if(it == m_field_singularities.end())
      throw Request_error("move_field_singularity: face " + std::to_string(from) + " holds no field singularity");
    if(m_field_singularities.count(to))
      throw Request_error("move_field_singularity: face " + std::to_string(to) +
                          " already holds a field singularity (a vector field turns at most once around a face)");
    const int k = it->second;
    const auto start = Clock::now();
    std::vector<Vector> field(num_vertices(*m_mesh));
    try
    {
      m_connection->set_index(from, 0);
      m_connection->set_index(to, k);
      m_connection->solve();
      m_connection->field(CGAL::make_property_map(field));
    }
    catch(const std::invalid_argument& e)
    {
      m_connection->set_index(to, 0);
      m_connection->set_index(from, k);
      m_connection->solve();
      throw Request_error("move_field_singularity from face " + std::to_string(from) + " to face " +
                          std::to_string(to) + ": " + e.what());
    }
    m_timing["field_ms"] = ms_since(start);
    std::swap(field, m_field);
    set_field_and_solve();
    m_field_singularities.erase(it);
    m_field_singularities[to] = k;
  }

  // |chi| singularities of the sign of chi on every closed component with chi != 0, spread out by
  // farthest-point sampling of the face centroids, starting from the highest face (+Y)
  std::map<std::size_t, int> default_field_singularities() const
  {
    std::map<std::size_t, int> result;
    const Mesh& mesh = *m_mesh;
    for(const auto& [component, chi] : m_closed_euler)
    {
      std::vector<std::size_t> candidates;
      for(auto f : faces(mesh))
        if(m_face_component[std::size_t(f)] == component)
          candidates.push_back(std::size_t(f));
      std::vector<double> distance(candidates.size(), std::numeric_limits<double>::infinity());
      std::size_t pick = 0;
      for(std::size_t i = 1; i < candidates.size(); ++i)
        if(m_centroid[candidates[i]].y() > m_centroid[candidates[pick]].y())
          pick = i;
      for(long n = 0; n < std::abs(chi) && n < long(candidates.size()); ++n)
      {
        result[candidates[pick]] = chi > 0 ? 1 : -1;
        const Eigen::Vector3d c = m_centroid[candidates[pick]];
        std::size_t farthest = 0;
        for(std::size_t i = 0; i < candidates.size(); ++i)
        {
          distance[i] = (std::min)(distance[i], (m_centroid[candidates[i]] - c).norm());
          if(distance[i] > distance[farthest])
            farthest = i;
        }
        pick = farthest;
      }
    }
    return result;
  }

  template <class F>
  static void wrap_library(F&& f, const std::string& what)
  {
    try
    {
      f();
    }
    catch(const std::invalid_argument& e)
    {
      throw Request_error(what + ": " + e.what());
    }
  }

  void set_field_and_solve()
  {
    m_fap->set_field(CGAL::make_property_map(m_field), m_stripes / m_diagonal);
    solve();
  }

  void solve()
  {
    const auto start = Clock::now();
    m_fap->solve();
    m_fap->corner_coordinates(m_corner);
    m_timing["solve_ms"] = ms_since(start);
  }

  double max_stripes() const { return 0.5 * m_diagonal / m_mean_edge; }

  Json closed_euler_characteristics() const
  {
    Json list = Json::array();
    for(const auto& [component, chi] : m_closed_euler)
      list.push_back(chi);
    return list;
  }

  // bounding box, mean edge length, face centroids, components and the Euler characteristic of
  // the closed ones
  void geometry()
  {
    const Mesh& mesh = *m_mesh;
    CGAL::Bbox_3 box;
    for(const Point& p : mesh.points())
      box += p.bbox();
    m_diagonal = std::sqrt(CGAL::square(box.xmax() - box.xmin()) + CGAL::square(box.ymax() - box.ymin()) +
                           CGAL::square(box.zmax() - box.zmin()));
    m_mean_edge = 0.;
    for(auto e : edges(mesh))
      m_mean_edge += std::sqrt(CGAL::squared_distance(mesh.point(source(halfedge(e, mesh), mesh)),
                                                      mesh.point(target(halfedge(e, mesh), mesh))));
    m_mean_edge /= double(num_edges(mesh));
    for(auto f : faces(mesh))
    {
      Eigen::Vector3d c = Eigen::Vector3d::Zero();
      for(auto v : vertices_around_face(halfedge(f, mesh), mesh))
        c += program::eigen(mesh.point(v)) / 3.;
      m_centroid.push_back(c);
    }
    m_face_component.assign(num_faces(mesh), 0);
    m_components = CGAL::Polygon_mesh_processing::connected_components(
      mesh, CGAL::make_property_map(m_face_component),
      CGAL::parameters::face_index_map(get(CGAL::face_index, mesh)));
    std::vector<long> chi(m_components, 0);
    std::vector<bool> closed(m_components, true);
    for(auto f : faces(mesh))
      ++chi[m_face_component[std::size_t(f)]];
    for(auto e : edges(mesh))
    {
      const auto h = halfedge(e, mesh);
      const auto f = is_border(h, mesh) ? face(opposite(h, mesh), mesh) : face(h, mesh);
      --chi[m_face_component[std::size_t(f)]];
      if(is_border_edge(h, mesh))
        closed[m_face_component[std::size_t(f)]] = false;
    }
    for(auto v : vertices(mesh))
    {
      const auto h = halfedge(v, mesh);
      const auto f = is_border(h, mesh) ? face(opposite(h, mesh), mesh) : face(h, mesh);
      ++chi[m_face_component[std::size_t(f)]];
    }
    for(std::size_t c = 0; c < m_components; ++c)
      if(closed[c])
        m_closed_euler.emplace_back(c, chi[c]);
  }

  std::string m_name;
  std::unique_ptr<Mesh> m_mesh; // on the heap: the parameterizer keeps a reference
  long m_mesh_version = 0;
  Solver m_stripe_solver, m_field_solver;
  std::unique_ptr<Parameterizer> m_fap;
  Mesh::Property_map<Mesh::Halfedge_index, double> m_corner;
  double m_diagonal = 1., m_mean_edge = 1., m_stripes = 10.;
  std::vector<Eigen::Vector3d> m_centroid;
  std::vector<std::size_t> m_face_component;
  std::size_t m_components = 1;
  std::vector<std::pair<std::size_t, long>> m_closed_euler; // the closed components and their chi
  std::vector<Vector> m_field;
  Json m_field_spec;
  std::optional<std::vector<Vector>> m_smoothest;
  std::unique_ptr<Connection> m_connection;
  std::map<std::size_t, int> m_field_singularities;
  Json m_timing = Json::object();
  long m_version = 0;
};

} // namespace editor

#endif // CGAL_SURFACE_DESIGN_EDITOR_SESSION_H
