// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Helpers shared by the command-line programs: strict parsing of option values (the options
// themselves: option_parser.h), reading a mesh in input order,
// writing PLY with extra properties and legacy VTK, rendering to PNG with f3d (no shell), and
// all-or-nothing outputs (written under temporary names, renamed when everything succeeded).

#ifndef CGAL_SURFACE_DESIGN_PROGRAMS_PROGRAM_SUPPORT_H
#define CGAL_SURFACE_DESIGN_PROGRAMS_PROGRAM_SUPPORT_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Polygon_mesh_processing/detect_features.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_design/solver_traits.h>

#include <Eigen/Core>

#include <fcntl.h>
#include <spawn.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <limits>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <iterator>
#include <memory>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace program {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Vector = Kernel::Vector_3;
using Mesh = CGAL::Surface_mesh<Point>;

/// A command-line error: the program prints the message and exits with status 1, writing nothing.
struct Usage_error : std::invalid_argument
{
  using std::invalid_argument::invalid_argument;
};

/// The `main` of a command-line program: the usage when there are no arguments, else `body()`'s
/// exit status; a Usage_error or any other exception ends the program with status 1 and
/// "NAME: message" on stderr.
template <class Body>
int run_main(const char* name, const char* usage, int argc, Body&& body)
{
  if(argc < 2)
  {
    std::cerr << usage;
    return 1;
  }
  try
  {
    return body();
  }
  catch(const Usage_error& e)
  {
    std::cerr << name << ": " << e.what() << "\n(run without arguments for the usage)\n";
  }
  catch(const std::exception& e)
  {
    std::cerr << name << ": " << e.what() << '\n';
  }
  return 1;
}


/// The digits of `text` from `i` on; advances `i` past them.
inline std::size_t skip_digits(const std::string& text, std::size_t& i)
{
  const std::size_t start = i;
  while(i < text.size() && text[i] >= '0' && text[i] <= '9')
    ++i;
  return i - start;
}

/// `text` for a message: at most 40 characters of it.
inline std::string shown(const std::string& text)
{
  return text.size() <= 40 ? text : text.substr(0, 40) + "... (" + std::to_string(text.size()) + " characters)";
}

/// Whether the whole of `text` is -?(D+.?D*|.D+)([eE][-+]?D+)? with D a decimal digit. Scanned
/// by hand: std::regex matches recursively and overflows the stack on long arguments (found by
/// fuzzing: a 20 000-digit --scale crashed every program).
inline bool is_decimal(const std::string& text)
{
  std::size_t i = 0;
  if(i < text.size() && text[i] == '-')
    ++i;
  std::size_t digits = skip_digits(text, i);
  if(i < text.size() && text[i] == '.')
    digits += skip_digits(text, ++i);
  if(digits == 0)
    return false;
  if(i < text.size() && (text[i] == 'e' || text[i] == 'E'))
  {
    ++i;
    if(i < text.size() && (text[i] == '+' || text[i] == '-'))
      ++i;
    if(skip_digits(text, i) == 0)
      return false;
  }
  return i == text.size();
}

/// Whether the whole of `text` is -?D+.
inline bool is_integer(const std::string& text)
{
  std::size_t i = text.size() > 0 && text[0] == '-' ? 1 : 0;
  return skip_digits(text, i) > 0 && i == text.size();
}

/// Refuses a PLY header that CGAL 5.5's PLY reader mishandles (both found by fuzzing the
/// programs' reader): a "property" line before any "element" line (the reader takes the last
/// element of an empty list: undefined behaviour, a crash), and an element with more items than the
/// file has bytes, or items without properties (the reader loops over every announced item, for
/// hours on a count like 888888888888880); vertex coordinates that are not float or double (an
/// assertion, a null dereference without assertions).
inline void check_ply_header(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  std::error_code ec;
  const std::uintmax_t bytes = std::filesystem::file_size(path, ec);
  std::string line;
  std::string element; // the current element, its item count and its property count
  std::size_t count = 0, properties = 0, number = 0;
  auto check_element = [&]() {
    if(!element.empty() && count > 0 && (properties == 0 || ec || count > bytes))
      throw std::runtime_error("cannot read " + path + ": its PLY header announces " + std::to_string(count) + " '" +
                               element + "' items" + (properties == 0 ? " without any property" : ", more than the file holds"));
  };
  while(std::getline(in, line))
  {
    std::istringstream words(line);
    std::string keyword, type;
    std::size_t items = 0;
    if(++number <= 2 || !(words >> keyword)) // the signature and the format line, or an empty line
      continue;
    if(keyword == "end_header")
      break;
    if(keyword == "element" && words >> type >> items)
    {
      check_element();
      element = type;
      count = items;
      properties = 0;
    }
    else if(keyword == "property")
    {
      if(element.empty())
        throw std::runtime_error("cannot read " + path + ": its PLY header declares a property before any element (line " +
                                 std::to_string(number) + ")");
      ++properties;
      std::string name, size_type, index_type;
      words >> type >> name;
      if(type == "list")
        words >> index_type >> name;
      const bool coordinate = (element == "vertex" || element == "vertices") && (name == "x" || name == "y" || name == "z");
      if(coordinate && type != "float" && type != "float32" && type != "double" && type != "float64")
        throw std::runtime_error("cannot read " + path + ": its PLY header declares the vertex coordinate " + name +
                                 " as '" + type + "' (line " + std::to_string(number) + "); coordinates are float or double");
    }
  }
  check_element();
}

/// Reads an ASCII OFF file (OFF, COFF, NOFF, STOFF and their combinations: one vertex per line,
/// its first three numbers the position, anything after them (colour, normal, texture) ignored;
/// one face per line, its size then its vertex indices, anything after them ignored) into a
/// soup, strictly: every number whole and finite, every count and index in range, every face of
/// at least 3 vertices. Returns false for a binary OFF file (left to CGAL's reader). Written for
/// the programs because CGAL 5.5's OFF scanner trusts the file: it allocates whatever a count
/// announces (gigabytes for "OFF 301111111 3") and converts numbers through a double into
/// unsigned integers, undefined behaviour out of range (a colour of 765, an index of 27 digits);
/// all found by fuzzing the programs' reader.
inline bool read_ascii_off(const std::string& path, std::vector<Point>& points,
                           std::vector<std::vector<std::size_t>>& polygons)
{
  std::ifstream in(path, std::ios::binary);
  if(!in)
    throw std::runtime_error("cannot read " + path + ": the file cannot be opened");
  std::size_t number = 0;
  std::vector<std::string> words;
  // the words of the next line that has any (comments after '#' removed); false at the end
  auto next_line = [&]() {
    std::string line;
    while(std::getline(in, line))
    {
      ++number;
      std::istringstream stream(line.substr(0, line.find('#')));
      words.assign(std::istream_iterator<std::string>(stream), std::istream_iterator<std::string>());
      if(!words.empty())
        return true;
    }
    return false;
  };
  auto fail = [&](const std::string& what) {
    throw std::runtime_error("cannot read " + path + ": line " + std::to_string(number) + ": " + what);
  };
  auto count = [&](const std::string& word, std::size_t bound, const char* what) {
    std::size_t i = 0;
    if(skip_digits(word, i) == 0 || i != word.size() || i > 18 || std::stoull(word) > bound)
      fail(std::string(what) + " \"" + shown(word) + "\" is not an integer from 0 to " + std::to_string(bound));
    return std::size_t(std::stoull(word));
  };
  if(!next_line())
    fail("the file is empty");
  const std::string keyword = words[0];
  const std::size_t off = keyword.rfind("OFF");
  if(off == std::string::npos || off + 3 != keyword.size() ||
     keyword.substr(0, off).find_first_not_of("STCN") != std::string::npos)
    fail("\"" + shown(keyword) + "\" is not an OFF keyword (OFF, COFF, NOFF, STOFF, ...; 4OFF and nOFF are not read)");
  if(words.size() > 1 && words[1] == "BINARY")
    return false;
  words.erase(words.begin());
  if(words.empty() && !next_line())
    fail("no vertex and face counts");
  std::error_code ec;
  const std::size_t bytes = std::size_t(std::filesystem::file_size(path, ec));
  // every vertex and face takes a line of at least 2 bytes: counts above that are not in the file
  const std::size_t nv = count(words[0], bytes / 2, "the vertex count");
  const std::size_t nf = count(words.size() > 1 ? words[1] : "", bytes / 2, "the face count");
  points.clear();
  polygons.clear();
  points.reserve(nv);
  polygons.reserve(nf);
  for(std::size_t v = 0; v < nv; ++v)
  {
    if(!next_line() || words.size() < 3)
      fail("vertex " + std::to_string(v) + " needs three coordinates");
    double x[3];
    for(int k = 0; k < 3; ++k)
    {
      if(!is_decimal(words[std::size_t(k)]))
        fail("coordinate \"" + shown(words[std::size_t(k)]) + "\" of vertex " + std::to_string(v) + " is not a number");
      x[k] = std::strtod(words[std::size_t(k)].c_str(), nullptr);
      if(!std::isfinite(x[k]))
        fail("coordinate \"" + shown(words[std::size_t(k)]) + "\" of vertex " + std::to_string(v) + " is not finite");
    }
    points.emplace_back(x[0], x[1], x[2]);
  }
  for(std::size_t f = 0; f < nf; ++f)
  {
    if(!next_line())
      fail("face " + std::to_string(f) + " is missing (" + std::to_string(nf) + " announced)");
    const std::size_t size = count(words[0], nv, "the size of a face");
    if(size < 3 || words.size() < 1 + size)
      fail("face " + std::to_string(f) + " needs at least 3 vertex indices, and as many as its size says");
    std::vector<std::size_t> polygon;
    for(std::size_t k = 1; k <= size; ++k)
    {
      polygon.push_back(count(words[k], nv, "a vertex index"));
      if(polygon.back() == nv)
        fail("face " + std::to_string(f) + " refers to vertex " + words[k] + ", but the file has " + std::to_string(nv) +
             " vertices");
    }
    polygons.push_back(std::move(polygon));
  }
  return true;
}

/// Reads OFF, OBJ, PLY, STL... into a Surface_mesh whose vertices and faces keep the file's order
/// (vertex i and face i of the file are Mesh::Vertex_index(i) and Mesh::Face_index(i)).
/// Refuses, with a clear message, inputs that are not already a valid polygon mesh rather than
/// repairing them silently (repairs would renumber the faces).
inline Mesh read_mesh(const std::string& path)
{
  std::string extension = std::filesystem::path(path).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  if(extension == ".ply")
    check_ply_header(path);
  std::vector<Point> points;
  std::vector<std::vector<std::size_t>> polygons;
  bool read = extension == ".off" && read_ascii_off(path, points, polygons);
  try
  {
    read = read || CGAL::IO::read_polygon_soup(path, points, polygons);
  }
  catch(const std::exception& e) // CGAL's readers throw what their containers throw (a list size of -5, say)
  {
    throw std::runtime_error("cannot read " + path + ": not a readable mesh file (" + e.what() + ")");
  }
  if(!read)
    throw std::runtime_error("cannot read " + path + ": not a readable mesh file (missing or unreadable file, unknown "
                             "extension, non-numeric or non-finite coordinates, or a face with an invalid vertex "
                             "index)");
  // CGAL 5.5's OBJ reader keeps faces that refer to vertices the file does not have (found by
  // fuzzing: the conversion below then reads past the points)
  for(std::size_t f = 0; f < polygons.size(); ++f)
    for(std::size_t v : polygons[f])
      if(v >= points.size())
        throw std::runtime_error("cannot read " + path + ": face " + std::to_string(f) + " refers to vertex " +
                                 std::to_string(v) + ", but the file has " + std::to_string(points.size()) + " vertices");
  if(!CGAL::Polygon_mesh_processing::is_polygon_soup_a_polygon_mesh(polygons))
    throw std::runtime_error(path + " is not a manifold, consistently oriented polygon mesh; "
                                    "repair it first (e.g. CGAL::Polygon_mesh_processing::repair_polygon_soup "
                                    "and orient_polygon_soup)");
  Mesh mesh;
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, polygons, mesh);
  if(num_vertices(mesh) != points.size())
    throw std::runtime_error(path + " has vertices used by no face; remove them first");
  return mesh;
}

/// Milliseconds since construction or the last lap.
class Stopwatch
{
public:
  double lap()
  {
    const auto now = std::chrono::steady_clock::now();
    const double ms = std::chrono::duration<double, std::milli>(now - m_start).count();
    m_start = now;
    return ms;
  }

private:
  std::chrono::steady_clock::time_point m_start = std::chrono::steady_clock::now();
};

// The creases of `mesh` (--sharp-angle DEG): `sharp` set on the edges whose faces' normals
// differ by more than `degrees`; returns how many of them are interior edges.
template <class EdgeMap>
std::size_t detect_creases(Mesh& mesh, double degrees, EdgeMap sharp)
{
  CGAL::Polygon_mesh_processing::detect_sharp_edges(mesh, degrees, sharp);
  std::size_t count = 0;
  for(auto e : edges(mesh))
    count += get(sharp, e) && !is_border(e, mesh) ? 1 : 0;
  return count;
}

/// The solvers of the programs' `--solver` option: "default" (the library's `Default_solver_traits`:
/// simplicial LDLT with AMD below 20k unknowns, supernodal Cholesky with nested dissection above),
/// "ldlt" and "supernodal" (the same traits with one of the two forced by the size threshold, as
/// `Simplicial_ldlt_solver_traits` and `Supernodal_solver_traits` would) and, when the library was
/// built with CHOLMOD, "cholmod" (`Cholmod_solver_traits`).
inline const std::vector<std::string>& solver_names()
{
  static const std::vector<std::string> names{"default", "ldlt", "supernodal"
#if defined(CGAL_SURFACE_DESIGN_HAS_CHOLMOD)
                                              ,
                                              "cholmod"
#endif
  };
  return names;
}

/// Calls `f(traits)` with a solver traits object of the solver named `name` (one of
/// `solver_names()`) and returns what it returns. One traits type serves the first three names, so
/// that every program compiles each algorithm for two solver types only.
template <class F>
decltype(auto) with_solver(const std::string& name, F&& f)
{
  using Traits = CGAL::Surface_design::Default_solver_traits;
  if(name == "default" || name == "ldlt" || name == "supernodal")
  {
    Traits traits;
    if(name == "ldlt")
      traits.solver().set_size_threshold(std::numeric_limits<Eigen::Index>::max());
    else if(name == "supernodal")
      traits.solver().set_size_threshold(0);
    return f(traits);
  }
#if defined(CGAL_SURFACE_DESIGN_HAS_CHOLMOD)
  if(name == "cholmod")
    return f(CGAL::Surface_design::Cholmod_solver_traits());
#endif
  throw Usage_error("unknown or unavailable solver \"" + name +
                    "\" (default, ldlt, supernodal, or cholmod when built with CHOLMOD)");
}

/// Gives `traits` an analysis cache (`CGAL::Surface_design::Symbolic_analysis_cache`) if it has
/// none and returns a new traits object with the same settings (size threshold, cache), for another
/// system on the same mesh: with the library's default traits, systems with one pattern are then
/// ordered and analysed once. Other traits: a new default-constructed object.
template <class Traits>
Traits solver_sharing_analysis(Traits& traits)
{
  Traits fresh;
  if constexpr(std::is_same<Traits, CGAL::Surface_design::Default_solver_traits>::value)
  {
    if(!traits.solver().analysis_cache())
      traits.solver().set_analysis_cache(std::make_shared<CGAL::Surface_design::Symbolic_analysis_cache>());
    fresh.solver().use_settings_of(traits.solver());
  }
  return fresh;
}

/// A new traits object with the settings of `traits` (size threshold) and no state shared with
/// it (no factorization, no analysis cache): for a system solved on another thread.
template <class Traits>
Traits independent_solver(Traits& traits)
{
  Traits fresh;
  if constexpr(std::is_same<Traits, CGAL::Surface_design::Default_solver_traits>::value)
    fresh.solver().set_size_threshold(traits.solver().size_threshold());
  return fresh;
}

/// `x` with 4 significant digits (for messages).
inline std::string text(double x)
{
  std::ostringstream s;
  s.precision(4);
  s << x;
  return s.str();
}

/// The value of option argv[i] (argv[i + 1]), advancing i; throws if it is missing.
inline std::string option_value(int argc, char** argv, int& i)
{
  if(i + 1 >= argc)
    throw Usage_error(std::string(argv[i]) + " needs a value");
  return argv[++i];
}

/// Parses the whole of `text` as a finite decimal number in [lo, hi], or throws naming the option.
/// Strict: no leading spaces or '+', no hexadecimal, no trailing characters.
inline double parse_double(const std::string& text, const std::string& option,
                           double lo = -std::numeric_limits<double>::max(),
                           double hi = std::numeric_limits<double>::max())
{
  if(!is_decimal(text))
    throw Usage_error(option + " expects a decimal number, not \"" + shown(text) + "\"");
  errno = 0;
  const double value = std::strtod(text.c_str(), nullptr);
  if(errno == ERANGE || !std::isfinite(value) || (value != 0. && std::abs(value) < std::numeric_limits<double>::min()))
    throw Usage_error(option + " " + text + " is out of the range of double-precision numbers");
  if(value < lo || value > hi)
  {
    std::ostringstream s;
    s << option << " must lie in [" << lo << ", " << hi << "], not " << text;
    throw Usage_error(s.str());
  }
  return value;
}

/// Parses the whole of `text` as a number > 0 (finite).
inline double parse_positive(const std::string& text, const std::string& option)
{
  const double value = parse_double(text, option);
  if(!(value > 0.))
    throw Usage_error(option + " must be positive, not " + text);
  return value;
}

/// Parses the whole of `text` as a decimal integer in [lo, hi], or throws naming the option.
inline long parse_integer(const std::string& text, const std::string& option, long lo, long hi)
{
  if(!is_integer(text))
    throw Usage_error(option + " expects an integer, not \"" + shown(text) + "\"");
  errno = 0;
  const long value = std::strtol(text.c_str(), nullptr, 10);
  if(errno == ERANGE || value < lo || value > hi)
    throw Usage_error(option + " must lie in [" + std::to_string(lo) + ", " + std::to_string(hi) + "], not " + text);
  return value;
}

/// Parses "A:B" into two integers; throws naming `what` otherwise.
inline std::pair<long, long> parse_pair(const std::string& s, const char* what)
{
  const auto colon = s.find(':');
  if(colon == std::string::npos)
    throw Usage_error(std::string("expected ") + what + ", got '" + s + "'");
  const long lim = std::numeric_limits<int>::max();
  return {parse_integer(s.substr(0, colon), what, -lim, lim), parse_integer(s.substr(colon + 1), what, -lim, lim)};
}

/// Parses one of `words`, or throws listing them.
inline std::string parse_choice(const std::string& text, const std::string& option,
                                const std::vector<std::string>& words)
{
  for(const std::string& w : words)
    if(w == text)
      return text;
  std::string list;
  for(const std::string& w : words)
    list += (list.empty() ? "" : ", ") + w;
  throw Usage_error(option + " is one of " + list + ", not \"" + text + "\"");
}

/// Throws unless `path` can be created: a non-empty file name whose folder exists and is
/// writable, with one of `extensions` (if given). Checked before any computation, so that a run
/// never computes for minutes and then fails to write.
inline void check_output_path(const std::string& path, const std::string& option,
                              const std::vector<std::string>& extensions = {})
{
  namespace fs = std::filesystem;
  const fs::path p(path);
  if(path.empty() || !p.has_filename() || p.filename() == "." || p.filename() == "..")
    throw Usage_error(option + " needs a file name, not \"" + path + "\"");
  const fs::path folder = p.has_parent_path() ? p.parent_path() : fs::path(".");
  std::error_code ec;
  if(!fs::is_directory(folder, ec) || access(folder.c_str(), W_OK) != 0)
    throw Usage_error(option + ": the folder \"" + folder.string() + "\" of " + path + " does not exist or is not writable");
  if(fs::is_directory(p, ec))
    throw Usage_error(option + ": " + path + " is a folder");
  if(!extensions.empty())
  {
    const std::string ext = p.extension().string();
    bool known = false;
    for(const std::string& e : extensions)
      known = known || e == ext;
    if(!known)
    {
      std::string list;
      for(const std::string& e : extensions)
        list += (list.empty() ? "" : ", ") + e;
      throw Usage_error(option + " expects a file ending in " + list + ", not " + path);
    }
  }
}

/// Throws if two of the named paths (option -> path; empty paths ignored) are the same file, e.g.
/// an output that would overwrite the input.
inline void check_distinct_paths(const std::vector<std::pair<std::string, std::string>>& named)
{
  namespace fs = std::filesystem;
  for(std::size_t i = 0; i < named.size(); ++i)
    for(std::size_t j = i + 1; j < named.size(); ++j)
    {
      if(named[i].second.empty() || named[j].second.empty())
        continue;
      std::error_code ec;
      const bool same = fs::weakly_canonical(named[i].second, ec) == fs::weakly_canonical(named[j].second, ec);
      if(same)
        throw Usage_error(named[i].first + " and " + named[j].first + " name the same file, " + named[j].second);
    }
}

/// The outputs of one run, all or nothing: every file is written under a temporary name in its
/// final folder (keeping the extension, which selects the format) and renamed by `commit()`
/// once everything succeeded; without a commit (an exception) the temporary files are removed.
class Output_files
{
public:
  Output_files() = default;
  Output_files(const Output_files&) = delete;
  Output_files& operator=(const Output_files&) = delete;
  ~Output_files()
  {
    if(!m_committed)
      for(const auto& [final_path, temporary] : m_files)
        std::remove(temporary.c_str());
  }

  /// The temporary name to write `final_path` to.
  std::string stage(const std::string& final_path)
  {
    namespace fs = std::filesystem;
    const fs::path p(final_path);
    const fs::path temporary =
      p.parent_path() / (".partial-" + std::to_string(getpid()) + "-" + p.filename().string());
    m_files.emplace_back(final_path, temporary.string());
    return temporary.string();
  }

  /// Renames every staged file to its final name; prints "wrote ...".
  void commit()
  {
    for(const auto& [final_path, temporary] : m_files)
    {
      if(std::rename(temporary.c_str(), final_path.c_str()) != 0)
        throw std::runtime_error("cannot move " + temporary + " to " + final_path);
      std::cout << "wrote " << final_path << '\n';
    }
    m_committed = true;
  }

private:
  std::vector<std::pair<std::string, std::string>> m_files;
  bool m_committed = false;
};

/// A named per-element column of a PLY element.
struct Ply_property
{
  std::string name;
  std::string type; // "double" (float64), "float" (float32) or "int"
  std::vector<double> values;
  std::size_t list_size = 0; // > 0: a list of that many values per element, `values` flattened
};

/// Writes an ASCII PLY: vertices (x y z + extra properties), faces (vertex_indices + extras) and,
/// if `edges` is not empty, an `edge` element with vertex1, vertex2 and extras.
inline void write_ply(const std::string& path, const Mesh& mesh, const std::vector<Ply_property>& vertex_props,
                      const std::vector<Ply_property>& face_props,
                      const std::vector<std::array<std::size_t, 2>>& edges = {},
                      const std::vector<Ply_property>& edge_props = {})
{
  std::ofstream out(path);
  if(!out)
    throw std::runtime_error("cannot write " + path);
  out << "ply\nformat ascii 1.0\ncomment written by CGAL Surface Design\n";
  out << "element vertex " << num_vertices(mesh) << "\nproperty double x\nproperty double y\nproperty double z\n";
  auto declare = [&out](const Ply_property& p) {
    out << "property " << (p.list_size > 0 ? "list uchar " : "") << p.type << ' ' << p.name << '\n';
  };
  for(const auto& p : vertex_props)
    declare(p);
  out << "element face " << num_faces(mesh) << "\nproperty list uchar int vertex_indices\n";
  for(const auto& p : face_props)
    declare(p);
  if(!edges.empty())
  {
    out << "element edge " << edges.size() << "\nproperty int vertex1\nproperty int vertex2\n";
    for(const auto& p : edge_props)
      declare(p);
  }
  out << "end_header\n" << std::setprecision(17);
  auto scalar = [&out](const Ply_property& p, double x) {
    out << ' ';
    if(p.type == "int")
      out << static_cast<long>(x);
    else if(p.type == "float")
      out << std::setprecision(9) << static_cast<float>(x) << std::setprecision(17);
    else
      out << x;
  };
  auto value = [&out, &scalar](const Ply_property& p, std::size_t i) {
    if(p.list_size == 0)
      return scalar(p, p.values[i]);
    out << ' ' << p.list_size;
    for(std::size_t k = 0; k < p.list_size; ++k)
      scalar(p, p.values[i * p.list_size + k]);
  };
  for(auto v : vertices(mesh))
  {
    const Point& p = mesh.point(v);
    out << p.x() << ' ' << p.y() << ' ' << p.z();
    for(const auto& prop : vertex_props)
      value(prop, std::size_t(v));
    out << '\n';
  }
  for(auto f : faces(mesh))
  {
    out << mesh.degree(f);
    for(auto v : vertices_around_face(halfedge(f, mesh), mesh))
      out << ' ' << std::size_t(v);
    for(const auto& prop : face_props)
      value(prop, std::size_t(f));
    out << '\n';
  }
  for(std::size_t e = 0; e < edges.size(); ++e)
  {
    out << edges[e][0] << ' ' << edges[e][1];
    for(const auto& prop : edge_props)
      value(prop, e);
    out << '\n';
  }
  out.flush();
  if(!out)
    throw std::runtime_error("writing " + path + " failed (disk full?)");
}

/// A triangle soup with per-point scalars and normals, written as legacy VTK (POLYDATA).
struct Vtk_surface
{
  std::vector<std::array<double, 3>> points, normals;
  std::vector<std::array<std::size_t, 3>> triangles;
  std::string scalar_name = "value";
  std::vector<double> scalars;

  /// Adds a point with its normal and scalar; returns its index.
  std::size_t add(const Eigen::Vector3d& p, const Eigen::Vector3d& n, double s)
  {
    points.push_back({p.x(), p.y(), p.z()});
    normals.push_back({n.x(), n.y(), n.z()});
    scalars.push_back(s);
    return points.size() - 1;
  }

  void write(const std::string& path) const
  {
    std::ofstream out(path);
    if(!out)
      throw std::runtime_error("cannot write " + path);
    out << "# vtk DataFile Version 3.0\nCGAL Surface Design\nASCII\nDATASET POLYDATA\n";
    out << "POINTS " << points.size() << " float\n" << std::setprecision(7);
    for(const auto& p : points)
      out << p[0] << ' ' << p[1] << ' ' << p[2] << '\n';
    out << "POLYGONS " << triangles.size() << ' ' << 4 * triangles.size() << '\n';
    for(const auto& t : triangles)
      out << "3 " << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
    out << "POINT_DATA " << points.size() << '\n';
    if(!scalars.empty())
    {
      out << "SCALARS " << scalar_name << " float 1\nLOOKUP_TABLE default\n";
      for(double s : scalars)
        out << s << '\n';
    }
    if(!normals.empty())
    {
      out << "NORMALS normals float\n";
      for(const auto& n : normals)
        out << n[0] << ' ' << n[1] << ' ' << n[2] << '\n';
    }
    out.flush();
    if(!out)
      throw std::runtime_error("writing " + path + " failed (disk full?)");
  }
};

/// Whether `program` is an executable file in one of the folders of PATH.
inline bool on_path(const std::string& program)
{
  const char* path = std::getenv("PATH");
  std::stringstream folders(path ? path : "");
  for(std::string folder; std::getline(folders, folder, ':');)
    if(!folder.empty() && access((folder + "/" + program).c_str(), X_OK) == 0)
      return true;
  return false;
}

/// Throws unless the programs a picture needs are installed: f3d, and xvfb-run when there is no
/// display. Called while the options are parsed, before anything is computed.
inline void require_picture_tools()
{
  const bool has_display = std::getenv("DISPLAY") != nullptr;
  if(!on_path("f3d") || (!has_display && !on_path("xvfb-run")))
    throw Usage_error("--picture needs f3d" + std::string(has_display ? "" : " and xvfb-run") +
                      " (Debian: apt-get install f3d xvfb xauth)");
}

/// The checks of a program with `--picture PNG [--up AXIS]`, once its options are read: `--up`
/// (`up_given`) needs `--picture`; no two of the `named` paths, the picture and its surface file
/// PNG.vtk are the same file; the programs a picture needs are installed.
inline void check_paths_and_picture(std::vector<std::pair<std::string, std::string>> named,
                                    const std::string& picture, bool up_given)
{
  if(picture.empty() && up_given)
    throw Usage_error("--up applies to --picture");
  named.emplace_back("--picture", picture);
  named.emplace_back("the picture's surface file", picture.empty() ? "" : picture + ".vtk");
  check_distinct_paths(named);
  if(!picture.empty())
    require_picture_tools();
}

/// Runs a program with arguments (no shell: nothing in the arguments is interpreted), its
/// output discarded; returns its exit status (-1 if it could not be started).
inline int run_program(const std::vector<std::string>& arguments)
{
  std::vector<char*> argv;
  for(const std::string& a : arguments)
    argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&actions, 2, "/dev/null", O_WRONLY, 0);
  pid_t pid = 0;
  const int spawned = posix_spawnp(&pid, argv[0], &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if(spawned != 0)
    return -1;
  int status = 0;
  if(waitpid(pid, &status, 0) != pid)
    return -1;
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

/// Renders a VTK file to PNG headlessly with f3d (Debian package `f3d`, run under `xvfb-run`
/// when there is no display; f3d 1.3 has no offscreen mode of its own). Colours by the point
/// scalar `scalar` in [lo, hi] with `colormap` when `scalar` is not empty; `--dry-run` ignores
/// any user configuration of f3d. The programs are started without a shell. f3d's exit code does
/// not tell whether it rendered, so success is judged by the PNG file. f3d frames the bounding box
/// for a 30-degree view; a 27-degree view fills the picture without cropping tall shapes (20
/// cut off the top and bottom of the eight).
/// \throws std::runtime_error if f3d cannot render (call `require_picture_tools()` first)
inline void render_png(const std::string& vtk, const std::string& png, const std::string& scalar = "",
                       double lo = -1., double hi = 1., const std::string& up = "+Y",
                       const std::string& colormap =
                         "0,0.1,0.18,0.42,0.4,0.1,0.18,0.42,0.6,0.96,0.9,0.78,1,0.96,0.9,0.78")
{
  std::vector<std::string> command;
  if(std::getenv("DISPLAY") == nullptr)
    command = {"xvfb-run", "-a"};
  std::ostringstream range;
  range << lo << ',' << hi;
  for(const std::string& a : {std::string("f3d"), vtk, "--output=" + png, std::string("--dry-run"), std::string("--quiet"),
                              std::string("--resolution=1200,900"), std::string("--bg-color=1,1,1"),
                              std::string("--camera-view-angle=27"), std::string("--roughness=0.8"), "--up=" + up,
                              std::string("-a")})
    command.push_back(a);
  if(!scalar.empty())
    for(const std::string& a : {"--scalars=" + scalar, "--range=" + range.str(), "--colormap=" + colormap})
      command.push_back(a);
  std::remove(png.c_str());
  // xvfb-run can lose a race for a display number: try once more before giving up
  for(int attempt = 0; attempt < 2 && !std::ifstream(png).good(); ++attempt)
    (void)run_program(command);
  if(!std::ifstream(png).good())
    throw std::runtime_error("f3d could not render " + png);
}

} // namespace program

#endif // CGAL_SURFACE_DESIGN_PROGRAMS_PROGRAM_SUPPORT_H
