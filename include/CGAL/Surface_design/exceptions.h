// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Exceptions thrown by every algorithm of the library.

#ifndef CGAL_SURFACE_DESIGN_EXCEPTIONS_H
#define CGAL_SURFACE_DESIGN_EXCEPTIONS_H

#include <cstddef>
#include <limits>
#include <stdexcept>
#include <string>

namespace CGAL {
namespace Surface_design {

/// \ingroup PkgSurfaceDesignRef
/// What is wrong with a mesh rejected by the input validation.
enum class Mesh_defect
{
  empty,                  ///< the mesh has no face
  invalid_index_map,      ///< an index map is not a bijection onto `[0, n)` (e.g. a `Surface_mesh` with removed elements: call `collect_garbage()`)
  non_finite_coordinates, ///< a vertex has a NaN or infinite coordinate, or one beyond 1e150 in magnitude (squares overflow)
  isolated_vertex,        ///< a vertex has no incident face
  not_triangle,           ///< a face is not a triangle
  non_manifold_vertex,    ///< the faces around a vertex form more than one fan
  degenerate_face,        ///< a face has (numerically) zero area
  not_a_disk,             ///< a connected component is not a topological disk (flattening needs one boundary loop and Euler characteristic 1)
  not_closed              ///< the mesh has a boundary where the algorithm needs closed surfaces
};

/// \ingroup PkgSurfaceDesignRef
/// Human-readable name of a `Mesh_defect`.
inline const char* to_string(Mesh_defect d)
{
  switch(d)
  {
    case Mesh_defect::empty: return "empty mesh";
    case Mesh_defect::invalid_index_map: return "invalid index map";
    case Mesh_defect::non_finite_coordinates: return "non-finite coordinates";
    case Mesh_defect::isolated_vertex: return "isolated vertex";
    case Mesh_defect::not_triangle: return "not a triangle mesh";
    case Mesh_defect::non_manifold_vertex: return "non-manifold vertex";
    case Mesh_defect::degenerate_face: return "degenerate face";
    case Mesh_defect::not_a_disk: return "not a topological disk";
    case Mesh_defect::not_closed: return "not a closed surface";
  }
  return "unknown defect";
}

/// \ingroup PkgSurfaceDesignRef
/// Thrown when an input mesh does not satisfy an algorithm's preconditions.
/// The mesh's geometry and connectivity and every output property map are left unchanged. (As
/// everywhere in CGAL, `get_initialized_*_index_map()` may renumber the ids of a `Polyhedron_3`
/// with `Polyhedron_items_with_id_3` whose ids are not a valid numbering.)
/// `defect()` says what is wrong and `element()` which element (the index of the vertex or face
/// in the index maps used by the algorithm, i.e. the input order for meshes read from a file), or
/// `no_element` when the defect concerns the whole mesh.
class Invalid_mesh : public std::invalid_argument
{
public:
  static constexpr std::size_t no_element = (std::numeric_limits<std::size_t>::max)();

  Invalid_mesh(Mesh_defect defect, std::size_t element, const std::string& what)
    : std::invalid_argument(std::string("CGAL::Surface_design: invalid mesh (") + to_string(defect) +
                            "): " + what),
      m_defect(defect), m_element(element)
  {}

  Mesh_defect defect() const { return m_defect; }
  std::size_t element() const { return m_element; }

private:
  Mesh_defect m_defect;
  std::size_t m_element;
};

/// \ingroup PkgSurfaceDesignRef
/// Thrown when user constraints are inconsistent or refer to elements that do not exist: e.g.
/// singularity indices whose sum violates Stokes' theorem on a component, a face or loop index out
/// of range. The message gives the numbers involved. Nothing is modified.
class Invalid_constraints : public std::invalid_argument
{
public:
  explicit Invalid_constraints(const std::string& what)
    : std::invalid_argument("CGAL::Surface_design: invalid constraints: " + what)
  {}
};

/// \ingroup PkgSurfaceDesignRef
/// Thrown when a parameter of an algorithm (a named parameter, a constructor or function
/// argument) has a value outside its documented range: NaN or infinite numbers, negative
/// scales, a symmetry order below 1, an enumerator an algorithm does not support... `name()` is
/// the parameter's name; the message gives the value and the valid range. Nothing is modified.
class Invalid_parameter : public std::invalid_argument
{
public:
  Invalid_parameter(const std::string& name, const std::string& what)
    : std::invalid_argument("CGAL::Surface_design: invalid parameter `" + name + "`: " + what), m_name(name)
  {}

  const std::string& name() const { return m_name; }

private:
  std::string m_name;
};

/// \ingroup PkgSurfaceDesignRef
/// Thrown when a sparse factorization or solve fails (e.g. a matrix that should be positive
/// definite is not). The message names the system and the solver's diagnosis.
class Linear_solver_failure : public std::runtime_error
{
public:
  explicit Linear_solver_failure(const std::string& what)
    : std::runtime_error("CGAL::Surface_design: linear solver failure: " + what)
  {}
};

/// \ingroup PkgSurfaceDesignRef
/// Thrown when an algorithm cannot produce a result that keeps its promise, for example a
/// remesher that cannot make a mesh with the input's topology. The message says what was tried
/// and why each attempt failed. The output mesh is left unchanged.
class Remeshing_failure : public std::runtime_error
{
public:
  explicit Remeshing_failure(const std::string& what)
    : std::runtime_error("CGAL::Surface_design: remeshing failure: " + what)
  {}
};

/// \ingroup PkgSurfaceDesignRef
/// Thrown when the library finds one of its own invariants broken (a bug, not a bad input): the
/// message says what was found and asks for the input to be reported. Nothing is returned that
/// breaks the function's promise.
class Internal_error : public std::logic_error
{
public:
  explicit Internal_error(const std::string& what)
    : std::logic_error("CGAL::Surface_design: internal error: " + what + " (please report this with the input)")
  {}
};

} // namespace Surface_design
} // namespace CGAL

#endif // CGAL_SURFACE_DESIGN_EXCEPTIONS_H
