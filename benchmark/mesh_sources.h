// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Where the benchmark meshes come from: files bundled with the project (`bundled:NAME`), the larger
// shared set (`shared:NAME`, optional, `.off.gz` read through `gzip -dc`), and generated spheres
// and tori of a requested size (`sphere:F`, `torus:F`, `storus:F`); plus named lists of sources
// (presets).

#ifndef CGAL_SURFACE_DESIGN_BENCHMARK_MESH_SOURCES_H
#define CGAL_SURFACE_DESIGN_BENCHMARK_MESH_SOURCES_H

#include "harness.h"

#include <CGAL/Surface_design/exceptions.h>
#include <CGAL/Surface_design/internal/Core/Mesh_indices.h>
#include <CGAL/Surface_design/internal/Core/validation.h>
#include <CGAL/Surface_design/mesh_generators.h>
#include <CGAL/Surface_design/octahedron_membrane.h>

#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/boost/graph/IO/OFF.h>
#include <CGAL/boost/graph/helpers.h>

#include <sys/wait.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <string>
#include <system_error>
#include <vector>

#include "../examples/Programs/common/configured_paths.h"

namespace benchmark {

enum class Mesh_origin { bundled, shared, sphere, torus, staggered_torus, octahedron };

/// A parsed `--mesh` argument. Its text (`spec`) names the mesh in every report.
struct Mesh_source
{
  std::string spec;
  Mesh_origin origin = Mesh_origin::bundled;
  std::string file;      ///< bundled, shared: file name relative to the folder
  std::size_t faces = 0; ///< sphere, torus, storus: requested number of faces
};

/// A named list of mesh sources (`--preset NAME`), and the workloads it is meant for.
struct Preset
{
  const char* name;
  const char* description;
  std::vector<const char*> sources;
  std::vector<const char*> workloads = {}; ///< run when no --workload is given; empty: all
};

inline const std::vector<Preset>& presets()
{
  static const std::vector<Preset> table{
    {"quick", "the default: a scanned and a generated mesh of moderate size",
     {"bundled:bunny_8k.off", "sphere:63000"}},
    {"smoke", "every workload once on two small meshes (CTest's benchmark_smoke_run)",
     {"bundled:bunny_1k.off", "storus:1000"}},
    {"sizes", "scaling on well-shaped spheres, ~1k to ~1M faces",
     {"sphere:1000", "sphere:8000", "sphere:63000", "sphere:250000", "sphere:1000000"}},
    {"bunny", "scaling on the shared bunny meshes, 1k to 955k faces (skipped when absent)",
     {"shared:bunny_1k.off", "shared:bunny_8k.off", "shared:bunny_60k.off",
      "shared:bunny_loop1_239k.off", "shared:bunny_loop2_955k.off.gz"}},
    {"tori", "scaling on genus-1 tori, ~8k to ~250k faces",
     {"torus:8000", "torus:63000", "torus:250000"}},
    // the bunnies of the paper's timing table; they all have a few obtuse corners (non-positive
    // cotangent weights), where the face-space reference does not apply: the staggered tori
    // (every weight positive) give the side-by-side comparison at ~1k, 8k and 63k faces
    {"paper", "the paper's stripe timings: bunnies 1k to 955k faces, and all-acute tori for the "
              "face-space comparison",
     {"bundled:bunny_1k.off", "bundled:bunny_8k.off", "shared:bunny_60k.off",
      "shared:bunny_loop1_239k.off", "shared:bunny_loop2_955k.off.gz", "storus:1000",
      "storus:8000", "storus:63000"},
     {"stripes", "stripes_face_space"}},
    {"storus", "scaling on all-acute staggered tori (every cotangent weight positive), ~1k to "
               "~250k faces",
     {"storus:1000", "storus:8000", "storus:63000", "storus:250000"}},
    {"fields", "direction fields on the bunnies, 1k to 955k faces (the larger ones from ../shared)",
     {"bundled:bunny_1k.off", "bundled:bunny_8k.off", "shared:bunny_60k.off",
      "shared:bunny_loop1_239k.off", "shared:bunny_loop2_955k.off.gz"},
     {"smoothest_field", "trivial_connection"}},
    {"field_stripes", "the smoothest field and the stripes along it, end to end, on the sizes of the peer "
                      "figures: bunnies and the kitten, 8k to 955k faces",
     {"bundled:bunny_8k.off", "bundled:kitten.off", "shared:bunny_60k.off", "shared:bunny_loop1_239k.off",
      "shared:bunny_loop2_955k.off.gz"},
     {"field_stripes"}},
    {"line_field_stripes", "stripes on line and cross fields end to end, on the sizes of geometry-central's "
                           "figures: bunny_8k, the kitten, bunny_60k, bunny_loop1_239k",
     {"bundled:bunny_8k.off", "bundled:kitten.off", "shared:bunny_60k.off", "shared:bunny_loop1_239k.off"},
     {"line_field_stripes", "cross_field_stripes"}},
    {"editor", "the stripe editor's per-edit latency at 1k, 8k, 60k and 239k faces",
     {"bundled:bunny_1k.off", "bundled:bunny_8k.off", "shared:bunny_60k.off", "shared:bunny_loop1_239k.off"},
     {"editor"}},
    // barycentric embedding (Imafuji & Ochiai): the octahedron of the paper's Table 1 and 2
    {"table1", "the paper's Table 1: octahedron m = 4, 8, 12, direct vs iterative",
     {"octahedron:4", "octahedron:8", "octahedron:12"},
     {"embedding", "embedding_iterative"}},
    {"table2", "the paper's Table 2: 10 deformation steps on the octahedron m = 4, 8, 12, against "
               "the iteration and PMP::fair",
     {"octahedron:4", "octahedron:8", "octahedron:12"},
     {"deformation", "deformation_iterative", "deformation_vs_fair", "deformation_fair"}},
    // developability (Stein et al.): coarse inputs of about 1k faces, as the paper and the
    // reference code's sphere (642 vertices) and bunny; the flow subdivides them twice
    {"developability", "the developability flow on ~1k-2k-face inputs (egg, twisted pebble, bunny, sphere, spot), 2 subdivisions",
     {"bundled:egg_1k.off", "bundled:pebble_1k.off", "bundled:bunny_1k.off", "sphere:1200", "bundled:spot_2k.off"},
     {"developable_flow_intrinsic", "developable_flow_covariance", "developable_flow_intrinsic_width",
      "developable_flow_covariance_max", "developable_flow_combinatorial"}},
    {"developability_evaluation", "energy + gradient evaluations on ~8k to ~250k faces",
     {"bundled:bunny_8k.off", "sphere:63000", "sphere:250000"},
     {"developability_evaluation"}},
    {"factorization", "the first solve in phases (ordering, symbolic, numeric, solve) for each ordering and "
     "kernel, with fill and flops: bunnies and the kitten, 8k to 955k faces",
     {"bundled:bunny_8k.off", "bundled:kitten.off", "shared:bunny_60k.off", "shared:bunny_loop1_239k.off",
      "shared:bunny_loop2_955k.off.gz"},
     {"factorization"}},
    {"flattening", "cutting and BFF: the octahedron membrane (6 boundary loops joined into one disk), ~1k to "
     "~1M faces, and a developable design",
     {"octahedron:8", "octahedron:50", "octahedron:100", "octahedron:144", "bundled:pebble_design.off"},
     {"flatten", "flatten_split", "flatten_arap"}},
    {"harmonic_quad", "harmonic quad remeshing: the seed's eight and kitten (Table 2), genus 0 to 4 with and without "
     "boundary (a serrated one: mech-holes-shark), and input sizes up to 240k faces",
     {"bundled:eight.off", "bundled:kitten.off", "bundled:fertility.off", "bundled:hemisphere.off",
      "bundled:camelhead.off", "bundled:blobby_3cc.off", "bundled:mech-holes-shark.off", "shared:bunny_60k.off",
      "shared:bunny_loop1_239k.off"},
     {"quad_remesh", "quad_remesh_net", "quad_remesh_no_spectacles", "quad_remesh_delaunay", "quad_remesh_curvature"}},
    {"embedding_sizes", "barycentric embedding scaling: octahedra of ~62k, 241k and 1M vertices",
     {"octahedron:50", "octahedron:100", "octahedron:204"},
     {"embedding", "deformation"}},
  };
  return table;
}

inline const Preset* find_preset(const std::string& name)
{
  for(const Preset& p : presets())
    if(name == p.name)
      return &p;
  return nullptr;
}

/// Parses a face count: digits with an optional suffix `k` (x 1000) or `M` (x 10^6).
inline bool parse_face_count(const std::string& text, std::size_t& count)
{
  std::size_t digits = 0;
  while(digits < text.size() && text[digits] >= '0' && text[digits] <= '9')
    ++digits;
  const std::string suffix = text.substr(digits);
  if(digits == 0 || digits > 9 || !(suffix.empty() || suffix == "k" || suffix == "M"))
    return false;
  count = std::size_t(std::stoul(text.substr(0, digits))) *
          (suffix == "k" ? 1000u : suffix == "M" ? 1000000u : 1u);
  return count > 0;
}

/// Parses `bundled:NAME`, `shared:NAME`, `sphere:F`, `torus:F` or `storus:F`; on failure returns
/// false and explains why in `error`.
inline bool parse_mesh_source(const std::string& spec, Mesh_source& source, std::string& error)
{
  const std::size_t colon = spec.find(':');
  const std::string kind = spec.substr(0, colon);
  const std::string argument = colon == std::string::npos ? std::string() : spec.substr(colon + 1);
  source = Mesh_source();
  source.spec = spec;
  if(kind == "bundled" || kind == "shared")
  {
    source.origin = kind == "bundled" ? Mesh_origin::bundled : Mesh_origin::shared;
    source.file = argument;
    if(argument.empty())
    {
      error = "mesh source \"" + spec + "\" names no file";
      return false;
    }
    return true;
  }
  if(kind == "sphere" || kind == "torus" || kind == "storus")
  {
    source.origin = kind == "sphere"  ? Mesh_origin::sphere
                    : kind == "torus" ? Mesh_origin::torus
                                      : Mesh_origin::staggered_torus;
    if(!parse_face_count(argument, source.faces))
    {
      error = "mesh source \"" + spec + "\": the face count must be a positive integer "
              "(optionally with suffix k or M)";
      return false;
    }
    return true;
  }
  if(kind == "octahedron")
  {
    source.origin = Mesh_origin::octahedron;
    if(!parse_face_count(argument, source.faces)) // here: segments per hexagon side
    {
      error = "mesh source \"" + spec + "\": the number of segments must be a positive integer";
      return false;
    }
    return true;
  }
  error = "mesh source \"" + spec +
          "\" is not bundled:NAME, shared:NAME, sphere:F, torus:F or storus:F";
  return false;
}

/// Folder of the shared meshes: the environment variable CGAL_SURFACE_DESIGN_SHARED_MESH_DIR if
/// set, else the folder configured in CMake.
inline std::string shared_mesh_dir()
{
  return program::configured_path("CGAL_SURFACE_DESIGN_SHARED_MESH_DIR");
}

namespace mesh_sources_detail {

inline bool ends_with(const std::string& s, const std::string& tail)
{
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

/// Quotes `s` for /bin/sh: inside single quotes everything is literal except the quote itself.
inline std::string shell_quoted(const std::string& s)
{
  std::string q = "'";
  for(char c : s)
    q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

/// Reads a gzip-compressed OFF file through a `gzip -dc` pipe.
inline bool read_gzipped_off(const std::string& path, Mesh& mesh, std::string& error)
{
  const std::string command = "gzip -dc -- " + shell_quoted(path);
  FILE* pipe = popen(command.c_str(), "r");
  if(!pipe)
  {
    error = "cannot start \"" + command + "\"";
    return false;
  }
  std::string text;
  char buffer[1 << 16];
  std::size_t n;
  while((n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0)
    text.append(buffer, n);
  const int status = pclose(pipe);
  if(status == -1 || !WIFEXITED(status) || WEXITSTATUS(status) != 0)
  {
    error = "\"" + command + "\" failed (is gzip installed, is the file intact?)";
    return false;
  }
  std::istringstream in(text);
  if(!CGAL::IO::read_OFF(in, mesh))
  {
    error = "cannot parse the decompressed OFF data of " + path;
    return false;
  }
  return true;
}

} // namespace mesh_sources_detail

enum class Load_status
{
  loaded,
  skipped, ///< an optional file or folder is absent: not an error
  failed   ///< unreadable or invalid mesh
};

/// Loads or generates the mesh of `source` and checks it with the library's own validation.
/// On `skipped` or `failed`, `message` says why.
inline Load_status load_mesh(const Mesh_source& source, Mesh& mesh, std::string& message)
{
  namespace fs = std::filesystem;
  using namespace mesh_sources_detail;
  CGAL::clear(mesh);
  if(source.origin == Mesh_origin::sphere)
  {
    // make_sphere gives 12 n^2 faces
    const double n = std::round(std::sqrt(double(source.faces) / 12.));
    CGAL::Surface_design::make_sphere(mesh, std::max<std::size_t>(1, std::size_t(n)));
  }
  else if(source.origin == Mesh_origin::torus)
  {
    // make_torus gives 2 * major * minor faces; major = 2.5 minor, as R / r = 1 / 0.4: square cells
    const std::size_t minor_segments = std::max<std::size_t>(
      3, std::size_t(std::round(std::sqrt(double(source.faces) / 5.))));
    const std::size_t major_segments = std::size_t(std::round(2.5 * double(minor_segments)));
    CGAL::Surface_design::make_torus(mesh, major_segments, minor_segments);
  }
  else if(source.origin == Mesh_origin::octahedron)
    CGAL::Surface_design::make_octahedron_membrane(mesh, source.faces); // radius 1, loops at 3
  else if(source.origin == Mesh_origin::staggered_torus)
  {
    // 2 * major * minor faces; staggered rings with R = 1, r = 0.3, an even minor count and
    // major = 3.3 minor make nearly isosceles triangles whose angles are all acute: every
    // cotangent weight is positive (about 0.35), at every size
    const std::size_t minor_segments = std::max<std::size_t>(
      4, 2 * std::size_t(std::round(std::sqrt(double(source.faces) / 6.6) / 2.)));
    const std::size_t major_segments = std::size_t(std::round(3.3 * double(minor_segments)));
    CGAL::Surface_design::make_torus(mesh, major_segments, minor_segments, 1., 0.3, true);
  }
  else
  {
    const bool shared = source.origin == Mesh_origin::shared;
    const std::string dir = shared ? shared_mesh_dir() : program::configured_path("CGAL_SURFACE_DESIGN_DATA_DIR");
    const std::string path = dir + "/" + source.file;
    // messages show the paths without "..", which the OS resolves (through symlinks) when opening
    auto shown = [](const std::string& p) { return fs::path(p).lexically_normal().string(); };
    // an absent shared mesh is expected (the folder is optional); an absent bundled one is not
    const std::string prefix = shared ? "skipped: " : "";
    std::error_code ec;
    if(!fs::is_directory(dir, ec))
    {
      message = prefix + source.spec + ": mesh folder " + shown(dir) + " not found";
      if(shared)
        message += " (set CGAL_SURFACE_DESIGN_SHARED_MESH_DIR to the shared mesh folder)";
      return shared ? Load_status::skipped : Load_status::failed;
    }
    if(!fs::is_regular_file(path, ec))
    {
      message = prefix + source.spec + ": file " + shown(path) + " not found";
      return shared ? Load_status::skipped : Load_status::failed;
    }
    std::string error;
    bool ok;
    if(ends_with(path, ".off.gz"))
      ok = read_gzipped_off(path, mesh, error);
    else if(ends_with(path, ".gz"))
    {
      ok = false;
      error = "only gzip-compressed OFF files (.off.gz) are supported";
    }
    else
    {
      ok = CGAL::IO::read_polygon_mesh(path, mesh);
      error = "cannot read " + path + " as a polygon mesh";
    }
    if(!ok || CGAL::is_empty(mesh))
    {
      message = source.spec + ": " + (ok ? "the mesh " + path + " is empty" : error);
      return Load_status::failed;
    }
  }

  try
  {
    const CGAL::Surface_design::internal::Mesh_indices<Mesh> indices(mesh);
    CGAL::Surface_design::internal::validate_mesh(indices, get(CGAL::vertex_point, mesh));
  }
  catch(const CGAL::Surface_design::Invalid_mesh& e)
  {
    message = source.spec + ": invalid mesh: " + e.what();
    return Load_status::failed;
  }
  return Load_status::loaded;
}

} // namespace benchmark

#endif // CGAL_SURFACE_DESIGN_BENCHMARK_MESH_SOURCES_H
