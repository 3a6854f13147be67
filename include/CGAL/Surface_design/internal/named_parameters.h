// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The named parameters every entry point reads the same way: the vertex point map and the sparse
// solver traits.

#ifndef CGAL_SURFACE_DESIGN_INTERNAL_NAMED_PARAMETERS_H
#define CGAL_SURFACE_DESIGN_INTERNAL_NAMED_PARAMETERS_H

#include <CGAL/Surface_design/solver_traits.h>

#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Named_function_parameters.h>

#include <type_traits>

namespace CGAL {
namespace Surface_design {
namespace internal {

/// The (read-only) vertex point map of `vertex_point_map`, else the mesh's own.
template <class Mesh, class NamedParameters>
using Const_vertex_point_map_t = typename CGAL::GetVertexPointMap<Mesh, NamedParameters>::const_type;

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

#endif // CGAL_SURFACE_DESIGN_INTERNAL_NAMED_PARAMETERS_H
