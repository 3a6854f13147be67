// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What every entry point reads the same way: the vertex point map, the sparse solver traits, and
// range checks of numeric parameters.

#ifndef CGAL_SURFACE_DESIGN_INTERNAL_CORE_NAMED_PARAMETERS_H
#define CGAL_SURFACE_DESIGN_INTERNAL_CORE_NAMED_PARAMETERS_H

#include <CGAL/Surface_design/exceptions.h>
#include <CGAL/Surface_design/internal/Solvers/solver_traits.h>

#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Named_function_parameters.h>

#include <cmath>
#include <sstream>
#include <string>
#include <type_traits>

namespace CGAL {
namespace Surface_design {
namespace internal {

/// `x` as text with up to 17 significant digits ("nan", "inf" as such).
inline std::string to_text(double x)
{
  std::ostringstream s;
  s.precision(17);
  s << x;
  return s.str();
}

// The types that the named parameters choose, derived here only (every public header uses these):

/// The (read-only) vertex point map of `vertex_point_map`, else the mesh's own.
template <class Mesh, class NamedParameters>
using Const_vertex_point_map_t = typename CGAL::GetVertexPointMap<Mesh, NamedParameters>::const_type;

/// The (writable) vertex point map of `vertex_point_map`, else the mesh's own, for the algorithms
/// that move vertices.
template <class Mesh, class NamedParameters>
using Vertex_point_map_t = typename CGAL::GetVertexPointMap<Mesh, NamedParameters>::type;

/// The type of `sparse_linear_solver`, else `Default_solver_traits`.
template <class NamedParameters>
using Solver_traits_t = typename CGAL::internal_np::Lookup_named_param_def<
  CGAL::internal_np::sparse_linear_solver_t, NamedParameters, Default_solver_traits>::type;

template <class Mesh, class NamedParameters>
Const_vertex_point_map_t<Mesh, NamedParameters> const_vertex_point_map(const Mesh& tm, const NamedParameters& np)
{
  return CGAL::parameters::choose_parameter(CGAL::parameters::get_parameter(np, CGAL::internal_np::vertex_point),
                                            get_const_property_map(CGAL::vertex_point, tm));
}

template <class NamedParameters>
Solver_traits_t<NamedParameters> solver_traits(const NamedParameters& np)
{
  return CGAL::parameters::choose_parameter<Solver_traits_t<NamedParameters>>(
    CGAL::parameters::get_parameter(np, CGAL::internal_np::sparse_linear_solver));
}

/// The vertex point map of a class whose template parameter is `VertexPointMap`: the one of
/// `vertex_point_map`, else the mesh's own (`writable`: through `get_property_map`, for classes
/// that write positions).
template <class VertexPointMap, bool writable = false, class Mesh, class NamedParameters>
VertexPointMap class_vertex_point_map(Mesh& tm, const NamedParameters& np)
{
  const auto given = CGAL::parameters::get_parameter(np, CGAL::internal_np::vertex_point);
  if constexpr(std::is_same<std::decay_t<decltype(given)>, CGAL::internal_np::Param_not_found>::value)
  {
    if constexpr(writable)
      return get_property_map(CGAL::vertex_point, tm);
    else
      return get_const_property_map(CGAL::vertex_point, tm);
  }
  else
  {
    static_assert(std::is_convertible<std::decay_t<decltype(given)>, VertexPointMap>::value,
                  "the named parameter vertex_point_map has another type than the class's VertexPointMap "
                  "template parameter: name that type, or let class template argument deduction find it");
    return given;
  }
}

/// The solver traits of a class whose template parameter is `SolverTraits`: the object of
/// `sparse_linear_solver`, else `SolverTraits()`.
template <class SolverTraits, class NamedParameters>
SolverTraits class_solver_traits(const NamedParameters& np)
{
  const auto given = CGAL::parameters::get_parameter(np, CGAL::internal_np::sparse_linear_solver);
  if constexpr(std::is_same<std::decay_t<decltype(given)>, CGAL::internal_np::Param_not_found>::value)
    return SolverTraits();
  else
  {
    static_assert(std::is_convertible<std::decay_t<decltype(given)>, SolverTraits>::value,
                  "the named parameter sparse_linear_solver has another type than the class's SolverTraits "
                  "template parameter: name that type, or let class template argument deduction find it");
    return given;
  }
}

/// \name Range checks of numeric parameters: each throws `Invalid_parameter` naming the
/// parameter, its value and the valid range, and returns the value.
/// @{
inline double require_finite(const char* name, double x)
{
  if(!std::isfinite(x))
    throw Invalid_parameter(name, "must be a finite number, got " + to_text(x));
  return x;
}
inline double require_nonnegative(const char* name, double x)
{
  if(!(x >= 0.) || !std::isfinite(x))
    throw Invalid_parameter(name, "must be a finite number >= 0, got " + to_text(x));
  return x;
}
inline double require_positive(const char* name, double x)
{
  if(!(x > 0.) || !std::isfinite(x))
    throw Invalid_parameter(name, "must be a finite number > 0, got " + to_text(x));
  return x;
}
/// lo <= x <= hi (or lo < x when `open_below`, x < hi when `open_above`)
inline double require_in_range(const char* name, double x, double lo, double hi, bool open_below = false,
                               bool open_above = false)
{
  const bool above = open_below ? x > lo : x >= lo, below = open_above ? x < hi : x <= hi;
  if(!(above && below))
    throw Invalid_parameter(name, "must lie in " + std::string(open_below ? "(" : "[") + to_text(lo) + ", " +
                                    to_text(hi) + (open_above ? ")" : "]") + ", got " + to_text(x));
  return x;
}
template <class Integer>
Integer require_at_least(const char* name, Integer x, Integer lo)
{
  if(!(x >= lo))
    throw Invalid_parameter(name, "must be at least " + std::to_string(lo) + ", got " + std::to_string(x));
  return x;
}
/// @}

/// Calls `fn(value)` if the named parameter `tag` was given.
template <class NamedParameters, class Tag, class Fn>
void if_given(const NamedParameters& np, Tag tag, Fn&& fn)
{
  const auto p = CGAL::parameters::get_parameter(np, tag);
  if constexpr(!std::is_same<std::decay_t<decltype(p)>, CGAL::internal_np::Param_not_found>::value)
    fn(p);
  (void)p;
}

} // namespace internal
} // namespace Surface_design
} // namespace CGAL

#endif // CGAL_SURFACE_DESIGN_INTERNAL_CORE_NAMED_PARAMETERS_H
