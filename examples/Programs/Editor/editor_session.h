// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The state of the stripe editor, apart from HTTP: one mesh, the field the stripes follow (a
// vector field, or a line or cross field: symmetry order 1, 2 or 4), the stripes' solver for that
// order (Field_aligned_parameterizer for vector fields, factored once per mesh;
// Branched_stripe_parameterizer for line and cross fields, factored once per field), the
// prescribed singularities, and the per-corner stripe angles of the last solve. Every edit is a
// JSON request; it either succeeds and re-solves (one back-substitution for the singularities and
// the frequency, plus the field's own solve, and for line and cross fields a factorization, when
// the field changes), or throws Request_error and leaves the state as it was. For a cross field,
// the quad preview ("quads" on) puts the cones on the lattice and extracts, after every solve, the
// quad mesh of the two families' level-0 lines (extract_field_aligned_quads()). The server
// (surface_design_editor.cpp), the benchmark (benchmark/workload_editor.cpp) and the fuzzer
// (test/fuzz/fuzz_editor_edit.cpp) drive this class.

#ifndef CGAL_SURFACE_DESIGN_EDITOR_SESSION_H
#define CGAL_SURFACE_DESIGN_EDITOR_SESSION_H

#include "../common/program_support.h"
#include "../common/stripe_fields.h"

#include <CGAL/Surface_design/Branched_stripe_parameterizer.h>
#include <CGAL/Surface_design/direction_fields.h>
#include <CGAL/Surface_design/exceptions.h>
#include <CGAL/Surface_design/Field_aligned_parameterizer.h>
#include <CGAL/Surface_design/field_aligned_quad_remeshing.h>
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
  using Branched = SD::Branched_stripe_parameterizer<Mesh>;
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
    m_field_spec = {{"kind", "axis"}, {"order", 1}, {"axis", {0., 1., 0.}}};
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
      const int a = family_arg(request);
      singularities_edit([&] { set_stripe_index(f, a, stripe_index(f, a) + k); },
                         "adding index " + std::to_string(k) + " at face " + std::to_string(f));
    }
    else if(op == "add_pair")
    {
      const std::size_t plus = face_arg(request, "plus"), minus = face_arg(request, "minus");
      const int a = family_arg(request);
      if(plus == minus)
        throw Request_error("add_pair: the +1 and the -1 must be in different faces (both are " + std::to_string(plus) + ")");
      singularities_edit([&] {
        set_stripe_index(plus, a, stripe_index(plus, a) + 1);
        set_stripe_index(minus, a, stripe_index(minus, a) - 1);
      }, "adding a +1/-1 pair at faces " + std::to_string(plus) + " and " + std::to_string(minus));
    }
    else if(op == "move")
    {
      const std::size_t from = face_arg(request, "from"), to = face_arg(request, "to");
      if(!has_stripe_singularity(from))
        throw Request_error("move: face " + std::to_string(from) + " holds no singularity");
      if(from == to)
        return state(received); // nothing moved: no solve
      singularities_edit([&] {
        if(m_order == 1)
          m_fap->move_singularity(descriptor(from), descriptor(to));
        else
          m_bsp->move_singularity(descriptor(from), descriptor(to));
      }, "moving the singularity of face " + std::to_string(from) + " to face " + std::to_string(to));
    }
    else if(op == "annihilate")
    {
      const std::size_t a = face_arg(request, "a"), b = face_arg(request, "b");
      singularities_edit([&] {
        if(m_order == 1)
          return m_fap->annihilate(descriptor(a), descriptor(b));
        bool opposite = a != b && has_stripe_singularity(a);
        for(int family = 0; family < families(); ++family)
          opposite = opposite && stripe_index(a, family) + stripe_index(b, family) == 0;
        if(!opposite)
          throw SD::Invalid_constraints("faces " + std::to_string(a) + " and " + std::to_string(b) +
                                        " do not hold opposite singularities");
        for(int family = 0; family < families(); ++family)
          set_stripe_index(a, family, 0), set_stripe_index(b, family, 0);
      }, "annihilating faces " + std::to_string(a) + " and " + std::to_string(b));
    }
    else if(op == "remove")
    {
      const std::size_t f = face_arg(request, "face");
      if(!has_stripe_singularity(f))
        throw Request_error("remove: face " + std::to_string(f) + " holds no singularity");
      singularities_edit([&] {
        for(int family = 0; family < families(); ++family)
          set_stripe_index(f, family, 0);
      }, "removing the singularity of face " + std::to_string(f));
    }
    else if(op == "clear")
      singularities_edit([&] { m_order == 1 ? m_fap->clear_indices() : m_bsp->clear_indices(); },
                         "removing every singularity");
    else if(op == "automatic")
    {
      if(m_order == 1)
        throw Request_error("automatic: the singularities of stripes on a vector field are only the ones you place "
                            "(choose a line or cross field)");
      singularities_edit([&] {
        const auto start = Clock::now();
        m_bsp->place_automatic_singularities();
        m_timing["automatic_ms"] = ms_since(start);
      }, "placing the singularities automatically");
    }
    else if(op == "frequency")
      set_stripes(number_arg(request, "stripes"));
    else if(op == "field")
      set_field(request);
    else if(op == "move_field_singularity")
    {
      const std::size_t from = face_arg(request, "from"), to = face_arg(request, "to");
      connection("move_field_singularity");
      if(!m_field_singularities.count(from))
        throw Request_error("move_field_singularity: face " + std::to_string(from) + " holds no field singularity");
      if(from == to)
        return state(received); // nothing moved: no solve
      move_field_singularity(from, to);
    }
    else if(op == "add_field_pair")
      add_field_pair(face_arg(request, "plus"), face_arg(request, "minus"));
    else if(op == "annihilate_field")
      annihilate_field(face_arg(request, "a"), face_arg(request, "b"));
    else if(op == "quads")
      set_quads(request);
    else
      throw Request_error("unknown op '" + op + "' (add, add_pair, move, annihilate, remove, clear, automatic, "
                          "frequency, field, move_field_singularity, add_field_pair, annihilate_field, quads, load, "
                          "state)");
    ++m_version;
    return state(received);
  }

  /// The current state: a 4-byte little-endian length L, L bytes of JSON (padded with spaces to
  /// a multiple of 4 bytes in all), then float32 data: the stripe angle u at the three corners of
  /// every face (cos u is the stripe pattern; u / 2 pi counts stripes), for a cross field the
  /// second family's angle v the same way, and for line and cross fields the three triangles
  /// around the branch point of every branch face ("overlay" of them in the JSON), 15 floats per
  /// triangle: x y z u v at each of its corners (the page draws these instead of the face), and
  /// with the quad preview on the quad mesh's edges ("quad_edges" of them), 6 floats per edge:
  /// x y z at its two ends.
  std::string state(Clock::time_point received = Clock::now()) const
  {
    const auto start = Clock::now();
    std::string data((m_u.size() + m_v.size() + m_overlay.size() + m_quad_edges.size()) * sizeof(float), '\0');
    float* out = reinterpret_cast<float*>(data.data());
    for(const std::vector<float>* part : {&m_u, &m_v, &m_overlay, &m_quad_edges})
      out = std::copy(part->begin(), part->end(), out);
    Json singular = Json::array(), field_singular = Json::array(), branch = Json::array();
    for(auto f : faces(*m_mesh))
      for(int a = 0; a < families(); ++a)
        if(stripe_index(std::size_t(f), a) != 0)
          singular.push_back({std::size_t(f), stripe_index(std::size_t(f), a), a});
    for(const auto& [f, k] : m_field_singularities)
      field_singular.push_back({f, k});
    if(m_order > 1)
      for(std::size_t f : m_bsp->branch_faces())
        branch.push_back({f, m_bsp->field_index_numerator(descriptor(f))});
    Json timing = m_timing;
    timing["serialize_ms"] = ms_since(start);
    timing["server_ms"] = ms_since(received);
    const Json state{{"version", m_version},
                     {"mesh", m_name},
                     {"mesh_version", m_mesh_version},
                     {"faces", num_faces(*m_mesh)},
                     {"order", m_order},
                     {"families", families()},
                     {"singularities", singular},
                     {"field", m_field_spec},
                     {"field_singularities", field_singular},
                     {"branch_faces", branch},
                     {"overlay", m_overlay.size() / 15},
                     {"quads", m_quad_info},
                     {"quad_edges", m_quad_edges.size() / 6},
                     {"stripes", m_stripes},
                     {"max_stripes", max_stripes()},
                     {"energy", m_order == 1 ? m_fap->energy() : m_bsp->energy()},
                     {"timing", timing}};
    std::string header = state.dump();
    while((4 + header.size()) % 4 != 0)
      header += ' ';
    std::string bytes(4, '\0');
    const std::uint32_t length = std::uint32_t(header.size());
    for(int i = 0; i < 4; ++i)
      bytes[std::size_t(i)] = char((length >> (8 * i)) & 0xFF);
    return bytes + header + data;
  }

  /// The stripes as an ASCII PLY. Vector field: alpha per vertex, the prescribed index per face.
  /// Line and cross field: per face the stripe angles at its corners (corner_alpha, and
  /// corner_beta for a cross field's second family, in the order of the face's vertices; linear
  /// inside a regular face), the prescribed indices (stripe_index, stripe_index_beta) and the
  /// field's index numerator (field_index: k for an index k / order).
  std::string export_ply() const
  {
    std::vector<program::Ply_property> vertex_props, face_props;
    if(m_order == 1)
    {
      program::Ply_property alpha{"alpha", "double", {}}, index{"index", "int", {}};
      for(auto v : vertices(*m_mesh))
        alpha.values.push_back(m_fap->alpha(v));
      for(auto f : faces(*m_mesh))
        index.values.push_back(m_fap->index(f));
      vertex_props = {alpha};
      face_props = {index};
    }
    else
    {
      program::Ply_property corner_alpha{"corner_alpha", "float", {}, 3}, corner_beta{"corner_beta", "float", {}, 3},
        index{"stripe_index", "int", {}}, index_beta{"stripe_index_beta", "int", {}}, field{"field_index", "int", {}};
      for(auto f : faces(*m_mesh))
      {
        for(int a = 0; a < families(); ++a)
        {
          const auto c = m_bsp->corner_values(f, a); // source(h), target(h), target(next(h)): the file starts at target(h)
          (a == 0 ? corner_alpha : corner_beta).values.insert((a == 0 ? corner_alpha : corner_beta).values.end(),
                                                             {c[1], c[2], c[0]});
          (a == 0 ? index : index_beta).values.push_back(m_bsp->index(f, a));
        }
        field.values.push_back(m_bsp->field_index_numerator(f));
      }
      face_props = {corner_alpha, index, field};
      if(families() == 2)
        face_props.insert(face_props.end(), {corner_beta, index_beta});
    }
    const auto file = std::filesystem::temp_directory_path() /
                      ("surface_design_editor_" + std::to_string(::getpid()) + "_" + std::to_string(m_version) + ".ply");
    program::write_ply(file.string(), *m_mesh, vertex_props, face_props);
    std::ifstream in(file, std::ios::binary);
    std::ostringstream content;
    content << in.rdbuf();
    std::error_code ec;
    std::filesystem::remove(file, ec);
    return content.str();
  }

  /// The quad preview's mesh as an OFF or OBJ file (`format` "off" or "obj"); Request_error when
  /// the preview is off or its last extraction failed.
  std::string export_quads(const std::string& format) const
  {
    if(format != "off" && format != "obj")
      throw Request_error("quads export: the format is \"off\" or \"obj\", not '" + format + "'");
    if(!m_quads)
      throw Request_error("quads export: the quad preview is off (a cross field, then {\"op\": \"quads\", \"on\": true})");
    if(num_faces(m_quad_mesh) == 0)
      throw Request_error("quads export: the lines of the last solve are not a quad mesh: " +
                          m_quad_info.value("problem", std::string("no quads")));
    std::ostringstream out;
    out.precision(17);
    if(format == "off")
      out << "OFF\n" << num_vertices(m_quad_mesh) << ' ' << num_faces(m_quad_mesh) << " 0\n";
    else
      out << "# field-aligned quads of " << m_name << " (CGAL Surface Design editor)\n";
    for(auto v : vertices(m_quad_mesh))
      out << (format == "obj" ? "v " : "") << m_quad_mesh.point(v) << '\n';
    for(auto f : faces(m_quad_mesh))
    {
      out << (format == "obj" ? "f" : "4");
      for(auto v : vertices_around_face(halfedge(f, m_quad_mesh), m_quad_mesh))
        out << ' ' << (format == "obj" ? std::size_t(v) + 1 : std::size_t(v));
      out << '\n';
    }
    return out.str();
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
  // the stripe family of an edit: 0, or 1 for a cross field's second family (default 0)
  int family_arg(const Json& request) const
  {
    if(!request.contains("family"))
      return 0;
    const int a = int(integer_arg(request, "family", 0, 1));
    if(a >= families())
      throw Request_error("\"family\" = 1: the stripes of a " + std::string(m_order == 1 ? "vector" : "line") +
                          " field have one family (0); a cross field has two");
    return a;
  }
  static Mesh::Face_index descriptor(std::size_t f) { return Mesh::Face_index(static_cast<std::uint32_t>(f)); }

  // ---- the stripe singularities, of either solver
  int families() const { return m_order == 4 ? 2 : 1; }
  int stripe_index(std::size_t f, int a) const
  {
    return m_order == 1 ? m_fap->index(descriptor(f)) : m_bsp->index(descriptor(f), a);
  }
  void set_stripe_index(std::size_t f, int a, int k)
  {
    if(m_order == 1)
      m_fap->set_index(descriptor(f), k);
    else
      m_bsp->set_index(descriptor(f), k, a);
  }
  bool has_stripe_singularity(std::size_t f) const
  {
    for(int a = 0; a < families(); ++a)
      if(stripe_index(f, a) != 0)
        return true;
    return false;
  }
  // the non-zero indices: (face, family, index)
  std::vector<std::array<int, 3>> stripe_indices() const
  {
    std::vector<std::array<int, 3>> out;
    for(auto f : faces(*m_mesh))
      for(int a = 0; a < families(); ++a)
        if(const int k = stripe_index(std::size_t(f), a); k != 0)
          out.push_back({int(f), a, k});
    return out;
  }
  void restore_stripe_indices(const std::vector<std::array<int, 3>>& indices)
  {
    m_order == 1 ? m_fap->clear_indices() : m_bsp->clear_indices();
    for(const auto& [f, a, k] : indices)
      set_stripe_index(std::size_t(f), a, k);
  }

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
    const auto before = stripe_indices();
    auto restore = [&] { restore_stripe_indices(before); };
    try
    {
      change();
      solve();
    }
    catch(const SD::Invalid_constraints& e)
    {
      restore();
      solve();
      throw Request_error(what + ": " + e.what() + closed_hint());
    }
    catch(const SD::Invalid_parameter& e)
    {
      restore();
      solve();
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
      if(m_order == 1)
        m_fap->set_field(CGAL::make_property_map(m_field), m_stripes / m_diagonal);
      else
        m_bsp->set_frequency(m_stripes / m_diagonal);
      solve();
    }
    catch(const std::invalid_argument& e)
    {
      m_stripes = before;
      m_order == 1 ? m_fap->set_field(CGAL::make_property_map(m_field), m_stripes / m_diagonal)
                   : m_bsp->set_frequency(m_stripes / m_diagonal);
      solve();
      throw Request_error(std::string("frequency: ") + e.what());
    }
  }

  // the symmetry order of a field request: "order" 1, 2 or 4 (default 1; principal: 2)
  int order_arg(const Json& request, const std::string& kind) const
  {
    const int order = request.contains("order") ? int(integer_arg(request, "order", 1, 4)) : (kind == "principal" ? 2 : 1);
    if(order == 3)
      throw Request_error("\"order\" = 3: choose 1 (vector field), 2 (line field) or 4 (cross field)");
    if(kind == "heat" && order != 1)
      throw Request_error("the heat field is a vector field (order 1)");
    if(kind == "principal" && order != 2)
      throw Request_error("the principal curvature field is a line field (order 2)");
    return order;
  }

  void set_field(const Json& request)
  {
    const std::string kind = text_arg(request, "kind");
    if(kind != "axis" && kind != "smoothest" && kind != "heat" && kind != "trivial" && kind != "principal")
      throw Request_error("unknown field kind '" + kind + "' (axis, smoothest, principal, heat, trivial)");
    const int order = order_arg(request, kind);
    // "boundary": "tangent": the field follows the boundary (one of its directions along every
    // boundary edge), as the quad preview of a mesh with a boundary needs; "free" (default) not
    const std::string boundary = request.contains("boundary") ? text_arg(request, "boundary") : "free";
    if(boundary != "free" && boundary != "tangent")
      throw Request_error("\"boundary\" = '" + boundary + "': choose \"free\" or \"tangent\"");
    const bool tangent = boundary == "tangent";
    if(tangent && kind != "smoothest" && kind != "trivial")
      throw Request_error("\"boundary\": \"tangent\" takes the smoothest field or a trivial connection, not " + kind);
    if(tangent && kind == "trivial" && (!request.contains("cones") || text_arg(request, "cones") != "smoothest"))
      throw Request_error("\"boundary\": \"tangent\" with a trivial connection takes \"cones\": \"smoothest\" (the "
                          "smoothest field's along the boundary: their sum is the one such a field needs)");
    if(m_quads && order == 4 && !tangent && m_closed_euler.size() != m_components) // (another order: quads off)
      throw Request_error("field: the quad preview of " + m_name + " (it has a boundary) needs a field along it "
                          "(\"boundary\": \"tangent\"): switch the quad preview off first");
    const auto start = Clock::now();
    std::vector<Vector> field;
    Json spec{{"kind", kind}, {"order", order}};
    if(tangent)
      spec["boundary"] = boundary;
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
    else if(kind == "smoothest" || kind == "principal")
      field = smoothest_field(kind, order, tangent);
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
    else // trivial
    {
      // its singularities: spread by farthest-point sampling (default), or the smoothest field's
      // (for a cross field moved at least the quads' size h apart); a cross field's out of wide
      // faces, as quad_remesh does
      const std::string cones = request.contains("cones") ? text_arg(request, "cones") : "spread";
      if(cones != "spread" && cones != "smoothest")
        throw Request_error("\"cones\" = '" + cones + "': choose \"spread\" or \"smoothest\"");
      connection = std::make_unique<Connection>(
        *m_mesh, SD::parameters::symmetry_order(
                   order, SD::parameters::field_boundary_condition(
                            tangent ? SD::Direction_field_boundary::tangent : SD::Direction_field_boundary::free,
                            CGAL::parameters::sparse_linear_solver(m_field_solver))));
      if(cones == "spread")
        field_singularities = default_field_singularities(order);
      else
      {
        const std::vector<Vector> smoothest = smoothest_field("smoothest", order, tangent);
        std::vector<int> index(num_faces(*m_mesh), 0);
        wrap_library([&] {
          SD::direction_field_singularities(*m_mesh, CGAL::make_property_map(smoothest), CGAL::make_property_map(index),
                                            SD::parameters::symmetry_order(order));
        }, "the smoothest field's singularities");
        for(std::size_t f = 0; f < index.size(); ++f)
          if(index[f] != 0)
            field_singularities[f] = index[f];
        spec["cones"] = cones;
      }
      for(const auto& [f, k] : field_singularities)
        connection->set_index(f, k);
      field.resize(num_vertices(*m_mesh));
      wrap_library([&] {
        if(order == 4)
        {
          if(cones == "smoothest")
            connection->separate_singularities(m_diagonal / m_stripes);
          connection->move_singularities_from_wide_faces(); // a -1/4 cone there folds the quads' map
          field_singularities.clear();
          for(auto f : faces(*m_mesh))
            if(const int k = connection->index(f); k != 0)
              field_singularities[std::size_t(f)] = k;
        }
        connection->solve();
        connection->field(CGAL::make_property_map(field));
      }, "trivial connection");
    }
    const double field_ms = ms_since(start);
    // all or nothing: the stripes solve with the new field, or everything stays
    install_field(std::move(field), order, "field " + kind);
    m_field_spec = spec;
    m_connection = std::move(connection);
    m_field_singularities = std::move(field_singularities);
    m_timing["field_ms"] = field_ms;
  }

  // Makes `field` (of symmetry order `order`) the stripes' field and solves, or throws
  // Request_error with everything as it was. The stripe singularities are kept when the order
  // stays (refused if one lies in a branch face of the new field), dropped when it changes.
  void install_field(std::vector<Vector> field, int order, const std::string& what)
  {
    const auto start = Clock::now();
    // the stripes' field, for the current order's solver
    auto apply = [this](const std::vector<Vector>& f) {
      if(m_order == 1)
        m_fap->set_field(CGAL::make_property_map(f), m_stripes / m_diagonal);
      else
        m_bsp->set_field(CGAL::make_property_map(f), m_stripes / m_diagonal);
    };
    if(order == m_order)
    {
      // the same order: the singularities are kept (a line or cross field refuses one that
      // would lie in a new branch face, and then nothing has changed; the vector stripes'
      // field is set again)
      wrap_library([&] { apply(field); }, what, [&] {
        if(m_order == 1)
        {
          apply(m_field);
          solve();
        }
      });
      std::swap(field, m_field);
      wrap_library([&] { solve(); }, what, [&] {
        std::swap(field, m_field);
        apply(m_field);
        solve();
      });
    }
    else if(order == 1)
    {
      // back to a vector field, without singularities (the vector stripes are unused until
      // then: a failure leaves the line or cross field's state as it was)
      try
      {
        m_fap->clear_indices();
        m_fap->set_field(CGAL::make_property_map(field), m_stripes / m_diagonal);
        m_fap->solve();
      }
      catch(const std::invalid_argument& e)
      {
        throw Request_error(what + ": " + e.what());
      }
      m_field = std::move(field);
      m_order = 1;
      m_bsp.reset();
      m_quads = false;
      clear_quads();
      solve();
    }
    else
    {
      // the stripes of every field on this mesh (and their stiffened systems) have one pattern:
      // ordered and analysed once (measured: 45 analyses in one run of the benchmark's editor workload on bunny_8k)
      auto bsp = std::make_unique<Branched>(
        *m_mesh, SD::parameters::symmetry_order(order).sparse_linear_solver(program::solver_sharing_analysis(m_stripe_solver)));
      try
      {
        bsp->set_field(CGAL::make_property_map(field), m_stripes / m_diagonal);
        bsp->solve();
      }
      catch(const std::invalid_argument& e)
      {
        throw Request_error(what + ": " + e.what());
      }
      m_bsp = std::move(bsp);
      m_field = std::move(field);
      m_order = order;
      m_quads = false;
      clear_quads();
      solve();
    }
    m_timing["factor_and_solve_ms"] = ms_since(start);
  }

  // The quad preview on or off ({"on": bool, "rounds": stiffening rounds in [0, 64], default 4}):
  // a cross field's branch points on the lattice, and after every solve the quads of its lines.
  void set_quads(const Json& request)
  {
    const Json& on_arg = member(request, "on");
    if(!on_arg.is_boolean())
      throw Request_error("quads: \"on\" must be true or false");
    const bool on = on_arg.get<bool>();
    const int rounds = request.contains("rounds") ? int(integer_arg(request, "rounds", 0, 64)) : m_quad_rounds;
    if(on && m_order != 4)
      throw Request_error("quads: the quad preview needs a cross field (order 4: \"cross field: trivial\" places "
                          "the cones, \"cross field: smoothest\" chooses them)");
    const bool open = m_closed_euler.size() != m_components;
    if(on && open && m_field_spec.value("boundary", "free") != "tangent")
      throw Request_error("quads: " + m_name + " has a boundary, and the quads follow it: the cross field must follow "
                          "it too (\"boundary\": \"tangent\"; in the page, \"cross field: trivial, the smoothest "
                          "field's cones, along the boundary\")");
    if(on && !stripe_indices().empty())
      throw Request_error("quads: remove the stripe singularities first (a dislocation is a T-junction, not a quad)");
    const bool was = m_quads;
    const int was_rounds = m_quad_rounds;
    // the stripes' system without the stiffening of earlier extractions, its branch points on
    // the lattice or not
    auto apply = [this, open](bool quads, int r) {
      m_quads = quads;
      m_quad_rounds = r;
      clear_quads();
      if(m_order != 4)
        return;
      m_bsp->set_boundary_on_level_lines(quads && open); // every boundary loop a line of the quads
      m_bsp->set_field(CGAL::make_property_map(m_field), m_stripes / m_diagonal);
      m_bsp->set_lattice_branch_points(quads);
      solve();
    };
    try
    {
      apply(on, rounds);
    }
    catch(const std::invalid_argument& e)
    {
      apply(was, was_rounds);
      throw Request_error(std::string("quads: ") + e.what());
    }
  }

  void clear_quads()
  {
    m_quad_edges.clear();
    m_quad_mesh.clear();
    m_quad_info = Json{{"on", m_quads}};
  }

  // The quads of the cross field's lines (after a solve; stiffened and solved again where the map
  // folds): their edges for the page, the mesh for the export, or what is wrong with them.
  void extract_quads()
  {
    const auto start = Clock::now();
    clear_quads();
    try
    {
      // (the lines' crossings, not snapped onto the input's features: the drag's time goes to the
      // stripes, and the preview shows the map the cones make)
      const auto r = SD::extract_field_aligned_quads(
        *m_bsp, m_quad_mesh, SD::parameters::stiffening_rounds(m_quad_rounds, SD::parameters::feature_snapping(false)));
      m_quad_info = Json{{"on", true},
                         {"valid", true},
                         {"faces", r.faces},
                         {"vertices", r.vertices},
                         {"irregular_vertices", r.irregular_vertices},
                         {"cones", r.cones},
                         {"edge_length", r.edge_length},
                         {"stiffening_rounds", r.stiffening_rounds},
                         {"boundary_loops", r.boundary_loops},
                         {"rounds", m_quad_rounds}};
      for(auto e : edges(m_quad_mesh))
        for(auto v : {source(halfedge(e, m_quad_mesh), m_quad_mesh), target(halfedge(e, m_quad_mesh), m_quad_mesh)})
          for(int i = 0; i < 3; ++i)
            m_quad_edges.push_back(float(m_quad_mesh.point(v)[i]));
    }
    catch(const SD::Remeshing_failure& e)
    {
      m_quad_mesh.clear();
      m_quad_info = Json{{"on", true}, {"valid", false}, {"problem", e.what()}, {"rounds", m_quad_rounds}};
    }
    m_timing["quads_ms"] = ms_since(start);
  }

  // the smoothest field of `order` (kind "smoothest"), or the principal curvature line field
  // (kind "principal"), computed once per mesh
  const std::vector<Vector>& smoothest_field(const std::string& kind, int order, bool along_boundary = false)
  {
    // the cache: 0 holds the principal field, -order the smoothest field along the boundary
    const int key = kind == "principal" ? 0 : along_boundary ? -order : order;
    auto it = m_fields.find(key);
    if(it == m_fields.end())
    {
      std::vector<Vector> computed(num_vertices(*m_mesh));
      wrap_library([&] {
        if(kind == "principal")
          SD::smoothest_direction_field(*m_mesh, CGAL::make_property_map(computed),
                                        SD::parameters::symmetry_order(
                                          2, SD::parameters::curvature_alignment_weight(
                                               0.1, SD::parameters::sparse_linear_solver(m_field_solver))));
        else if(along_boundary) // its cones kept apart by the flow, as quad_remesh does
          SD::smoothest_direction_field(
            *m_mesh, CGAL::make_property_map(computed),
            SD::parameters::symmetry_order(
              order, SD::parameters::field_boundary_condition(
                       SD::Direction_field_boundary::tangent,
                       SD::parameters::unit_length_iterations(30, CGAL::parameters::sparse_linear_solver(m_field_solver)))));
        else
          SD::smoothest_direction_field(*m_mesh, CGAL::make_property_map(computed),
                                        SD::parameters::symmetry_order(order).sparse_linear_solver(m_field_solver));
      }, kind + " field");
      it = m_fields.emplace(key, std::move(computed)).first;
    }
    return it->second;
  }

  // the field singularity edits below need a trivial connection
  Connection& connection(const char* op) const
  {
    if(!m_connection)
      throw Request_error(std::string(op) + ": the field is not a trivial connection (choose \"trivial\" first)");
    return *m_connection;
  }

  // Sets the trivial connection's indices (numerators) in `changes`, solves it and the stripes;
  // on failure puts everything back.
  void edit_field_singularities(const std::map<std::size_t, int>& changes, const std::string& what)
  {
    Connection& tc = connection(what.c_str());
    if(tc.boundary_condition() != SD::Direction_field_boundary::free)
      for(const auto& [f, k] : changes)
        if(k != 0 && m_fap->has_boundary_edge(descriptor(f)))
          throw Request_error(what + ": face " + std::to_string(f) + " has an edge on the boundary, which the field "
                              "follows (its direction is fixed there): choose a face inside");
    std::map<std::size_t, int> before;
    for(const auto& [f, k] : changes)
      before[f] = tc.index(descriptor(f));
    const auto start = Clock::now();
    std::vector<Vector> field(num_vertices(*m_mesh));
    auto restore = [&] {
      for(const auto& [f, k] : before)
        tc.set_index(descriptor(f), k);
      tc.solve();
    };
    wrap_library([&] {
      for(const auto& [f, k] : changes)
        tc.set_index(descriptor(f), k);
      tc.solve();
      tc.field(CGAL::make_property_map(field));
    }, what, restore);
    m_timing["field_ms"] = ms_since(start);
    // a cone moved, added or removed: the new map mostly folds where the last one did, so the
    // quad preview starts from the stiffening of its last quads (dropped after a failure, where
    // it would only pile up), for this edit only
    struct Kept_for_this_edit
    {
      Branched* bsp;
      ~Kept_for_this_edit() { if(bsp) bsp->keep_stiffening(false); }
    } kept{m_order > 1 ? m_bsp.get() : nullptr};
    if(kept.bsp)
      kept.bsp->keep_stiffening(m_quads && m_quad_info.value("valid", false));
    try
    {
      install_field(std::move(field), m_order, what);
    }
    catch(...)
    {
      restore();
      throw;
    }
    for(const auto& [f, k] : changes)
      k == 0 ? void(m_field_singularities.erase(f)) : void(m_field_singularities[f] = k);
  }

  void move_field_singularity(std::size_t from, std::size_t to)
  {
    connection("move_field_singularity");
    const auto it = m_field_singularities.find(from);
    if(it == m_field_singularities.end())
      throw Request_error("move_field_singularity: face " + std::to_string(from) + " holds no field singularity");
    if(m_field_singularities.count(to))
      throw Request_error("move_field_singularity: face " + std::to_string(to) +
                          " already holds a field singularity (the field turns at most once around a face)");
    edit_field_singularities({{from, 0}, {to, it->second}},
                             "move_field_singularity from face " + std::to_string(from) + " to face " + std::to_string(to));
  }

  // a +1/order and a -1/order field singularity (a vector field: +1 and -1)
  void add_field_pair(std::size_t plus, std::size_t minus)
  {
    connection("add_field_pair");
    if(plus == minus)
      throw Request_error("add_field_pair: the two singularities must be in different faces (both are " +
                          std::to_string(plus) + ")");
    for(std::size_t f : {plus, minus})
      if(m_field_singularities.count(f))
        throw Request_error("add_field_pair: face " + std::to_string(f) + " already holds a field singularity");
    edit_field_singularities({{plus, 1}, {minus, -1}}, "add_field_pair at faces " + std::to_string(plus) + " and " +
                                                         std::to_string(minus));
  }

  void annihilate_field(std::size_t a, std::size_t b)
  {
    connection("annihilate_field");
    const auto i = m_field_singularities.find(a), j = m_field_singularities.find(b);
    if(a == b || i == m_field_singularities.end() || j == m_field_singularities.end() || i->second + j->second != 0)
      throw Request_error("annihilate_field: faces " + std::to_string(a) + " and " + std::to_string(b) +
                          " do not hold opposite field singularities");
    edit_field_singularities({{a, 0}, {b, 0}}, "annihilate_field at faces " + std::to_string(a) + " and " +
                                                 std::to_string(b));
  }

  // order |chi| singularities of index sign(chi) / order on every closed component with chi != 0,
  // spread out by farthest-point sampling of the face centroids, starting from the highest face (+Y)
  std::map<std::size_t, int> default_field_singularities(int order) const
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
      for(long n = 0; n < order * std::abs(chi) && n < long(candidates.size()); ++n)
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

  // Runs f; if it throws, runs `undo`, and reports a refusal (std::invalid_argument) as a
  // Request_error saying `what`, any other exception as it is.
  template <class F, class Undo = void (*)()>
  static void wrap_library(F&& f, const std::string& what, Undo&& undo = [] {})
  {
    try
    {
      f();
    }
    catch(const std::invalid_argument& e)
    {
      undo();
      throw Request_error(what + ": " + e.what());
    }
    catch(...)
    {
      undo();
      throw;
    }
  }

  // Solves the stripes and reads the per-corner angles in the page's corner order (the targets
  // of halfedge(f), next, next-next), and the triangles around the branch points.
  void solve()
  {
    const auto start = Clock::now();
    const Mesh& mesh = *m_mesh;
    const std::size_t nf = num_faces(mesh);
    m_u.resize(3 * nf);
    m_v.clear();
    m_overlay.clear();
    if(m_order == 1)
    {
      m_fap->solve();
      m_fap->corner_coordinates(m_corner);
      for(auto f : faces(mesh))
      {
        std::size_t k = 0;
        for(auto h : corners(f))
          m_u[3 * std::size_t(f) + k++] = float(m_corner[h]);
      }
      m_timing["solve_ms"] = ms_since(start);
      return;
    }
    m_bsp->solve();
    if(m_quads)
      extract_quads(); // may stiffen and solve again: the corner values are read after it
    if(families() == 2)
      m_v.resize(3 * nf);
    for(auto f : faces(mesh))
      for(int a = 0; a < families(); ++a)
      {
        const auto c = m_bsp->corner_values(f, a); // source(h), target(h), target(next(h))
        float* out = (a == 0 ? m_u : m_v).data() + 3 * std::size_t(f);
        out[0] = float(c[1]), out[1] = float(c[2]), out[2] = float(c[0]);
      }
    // a branch face as three triangles (corner i, corner i + 1, branch point), on each of which
    // the angle is linear: values taken just inside each triangle's corners
    for(std::size_t f : m_bsp->branch_faces())
    {
      const auto h = halfedge(descriptor(f), mesh);
      const std::array<Eigen::Vector3d, 3> p{program::eigen(mesh.point(source(h, mesh))),
                                             program::eigen(mesh.point(target(h, mesh))),
                                             program::eigen(mesh.point(target(next(h, mesh), mesh)))};
      const std::array<double, 3> o = m_bsp->branch_point(descriptor(f)); // barycentric, as p
      const Eigen::Vector3d centre = o[0] * p[0] + o[1] * p[1] + o[2] * p[2];
      for(int i = 0; i < 3; ++i)
      {
        const int j = (i + 1) % 3;
        std::array<double, 3> middle{o[0] / 3., o[1] / 3., o[2] / 3.}; // the small triangle's centroid
        middle[std::size_t(i)] += 1. / 3., middle[std::size_t(j)] += 1. / 3.;
        for(int corner = 0; corner < 3; ++corner)
        {
          std::array<double, 3> b = o;
          Eigen::Vector3d x = centre;
          if(corner < 2)
          {
            b = {0., 0., 0.};
            b[std::size_t(corner == 0 ? i : j)] = 1.;
            x = p[std::size_t(corner == 0 ? i : j)];
          }
          const double inward = 1e-7;
          for(int l = 0; l < 3; ++l)
            b[std::size_t(l)] = (1. - inward) * b[std::size_t(l)] + inward * middle[std::size_t(l)];
          m_overlay.insert(m_overlay.end(), {float(x.x()), float(x.y()), float(x.z())});
          for(int a = 0; a < 2; ++a)
            m_overlay.push_back(a < families() ? float(m_bsp->value(descriptor(f), b, a)) : 0.f);
        }
      }
    }
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
  std::map<int, std::vector<Vector>> m_fields; // computed smoothest fields by order (0: principal)
  int m_order = 1;                             // the field's symmetry order
  std::unique_ptr<Branched> m_bsp;             // the stripes of a line or cross field
  std::vector<float> m_u, m_v, m_overlay;      // the state's float data (see state())
  std::unique_ptr<Connection> m_connection;
  std::map<std::size_t, int> m_field_singularities;
  bool m_quads = false;                   // the quad preview (a cross field only)
  int m_quad_rounds = 4;                  // its stiffening rounds at most (a preview: fewer than quad_remesh)
  Mesh m_quad_mesh;                       // its last quads (empty: off, or not a quad mesh)
  std::vector<float> m_quad_edges;        // their edges for the state (see state())
  Json m_quad_info = Json{{"on", false}}; // what they are, or what is wrong
  Json m_timing = Json::object();
  long m_version = 0;
};

} // namespace editor

#endif // CGAL_SURFACE_DESIGN_EDITOR_SESSION_H
