// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Splitting flattened pieces whose image in the plane overlaps itself.

#ifndef CGAL_SURFACE_DESIGN_OVERLAP_SPLITTING_CUT_H
#define CGAL_SURFACE_DESIGN_OVERLAP_SPLITTING_CUT_H

#include <CGAL/Surface_design/internal/Core/Mesh_indices.h>
#include <CGAL/Surface_design/internal/Core/named_parameters.h>
#include <CGAL/Surface_design/internal/Core/validation.h>
#include <CGAL/Surface_design/internal/Developability/overlap_split.h>

#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Named_function_parameters.h>

#include <cstddef>
#include <vector>

namespace CGAL {
namespace Surface_design {

/// \ingroup PkgFlatteningRef
/// What `compute_overlap_splitting_cut()` found.
struct Overlap_splitting_result
{
  std::size_t overlapping_pieces = 0; ///< pieces whose boundary crosses itself in the plane
  std::size_t split_pieces = 0;       ///< of these, the pieces the cut splits into disks
  std::size_t cut_edges = 0;          ///< edges of the cut
};

/// \ingroup PkgFlatteningRef
///
/// Computes a cut that splits every flattened piece whose image in the plane overlaps itself
/// (its boundary crosses itself), so that the piece can be cut out of a sheet once its parts are
/// flattened again. A long piece may curl round in the plane until one end lies on the other
/// (Stein et al. cut such pieces by hand, paper Fig. 24).
///
/// **Where it cuts.** Of the pairs of boundary edges that cross in the plane, the two farthest
/// apart along the boundary (in space, the shorter way round), i and k, overlap most globally.
/// The piece is cut between them: a face goes with k when its vertices are closer to k than to
/// i (shortest paths along the edges, summed over its three vertices), so the cut runs across
/// the piece halfway between the two. Each side is made connected (an island of one side inside
/// the other joins the other), and both must be topological disks, otherwise the piece is left
/// whole (counted in `overlapping_pieces`, not in `split_pieces`).
///
/// One call splits each overlapping piece once. Cut the mesh along the edges
/// (`cut_mesh_along_edges()`), flatten it again, and repeat until no piece overlaps itself (the
/// CLI `flatten` does so, for at most 64 rounds).
///
/// \param tm a triangle mesh whose components are disks (validated), normally the output of
///        `cut_mesh_along_edges()`
/// \param uv a readable vertex -> `Point_2` map: the flattening of `tm`
/// \param cut_edges output iterator receiving the `edge_descriptor`s of the cut (edges of `tm`)
/// \param np an optional sequence of named parameters among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{a property map associating points to the vertices of `tm`}
///     \cgalParamType{a class model of `ReadablePropertyMap` with
///                    `boost::graph_traits<TriangleMesh>::%vertex_descriptor` as key type and `%Point_3` as
///                    value type}
///     \cgalParamDefault{`boost::get(CGAL::vertex_point, tm)`}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_index_map}
///     \cgalParamDescription{a property map associating to each vertex of `tm` a unique index in
///                           `[0, num_vertices(tm))`: the numbering of the elements in error messages}
///     \cgalParamType{a class model of `ReadablePropertyMap` with
///                    `boost::graph_traits<TriangleMesh>::%vertex_descriptor` as key type and an integer as
///                    value type}
///     \cgalParamDefault{the mesh's own (`CGAL::get_initialized_vertex_index_map(tm)`)}
///     \cgalParamExtra{throws `Invalid_mesh` (`Mesh_defect::invalid_index_map`) if it is not a bijection onto
///                     `[0, num_vertices(tm))`}
///   \cgalParamNEnd
///   \cgalParamNBegin{halfedge_index_map}
///     \cgalParamDescription{a property map associating to each halfedge of `tm` a unique index in
///                           `[0, num_halfedges(tm))`: the numbering of the elements in error messages}
///     \cgalParamType{a class model of `ReadablePropertyMap` with
///                    `boost::graph_traits<TriangleMesh>::%halfedge_descriptor` as key type and an integer as
///                    value type}
///     \cgalParamDefault{the mesh's own (`CGAL::get_initialized_halfedge_index_map(tm)`)}
///     \cgalParamExtra{throws `Invalid_mesh` (`Mesh_defect::invalid_index_map`) if it is not a bijection onto
///                     `[0, num_halfedges(tm))`}
///   \cgalParamNEnd
///   \cgalParamNBegin{edge_index_map}
///     \cgalParamDescription{a property map associating to each edge of `tm` a unique index in
///                           `[0, num_edges(tm))`: the numbering of the elements in error messages}
///     \cgalParamType{a class model of `ReadablePropertyMap` with
///                    `boost::graph_traits<TriangleMesh>::%edge_descriptor` as key type and an integer as
///                    value type}
///     \cgalParamDefault{the order of `edges(tm)`}
///     \cgalParamExtra{throws `Invalid_mesh` (`Mesh_defect::invalid_index_map`) if it is not a bijection onto
///                     `[0, num_edges(tm))`}
///   \cgalParamNEnd
///   \cgalParamNBegin{face_index_map}
///     \cgalParamDescription{a property map associating to each face of `tm` a unique index in
///                           `[0, num_faces(tm))`: the numbering of the elements in error messages}
///     \cgalParamType{a class model of `ReadablePropertyMap` with
///                    `boost::graph_traits<TriangleMesh>::%face_descriptor` as key type and an integer as
///                    value type}
///     \cgalParamDefault{the mesh's own (`CGAL::get_initialized_face_index_map(tm)`)}
///     \cgalParamExtra{throws `Invalid_mesh` (`Mesh_defect::invalid_index_map`) if it is not a bijection onto
///                     `[0, num_faces(tm))`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \returns what was found and cut
/// \throws Invalid_mesh the mesh is invalid, Invalid_parameter a coordinate of `uv` is not
///         finite (nothing is written then)
/// Complexity: O(|E| log |V|) per overlapping piece (two Dijkstra searches), plus about linear
/// time in the boundary's size to find crossings.
template <class TriangleMesh, class UVMap, class EdgeOutputIterator,
          class NamedParameters = CGAL::parameters::Default_named_parameters>
Overlap_splitting_result compute_overlap_splitting_cut(const TriangleMesh& tm, const UVMap& uv,
                                                       EdgeOutputIterator cut_edges,
                                                       const NamedParameters& np = CGAL::parameters::default_values())
{
  const auto vpm = internal::const_vertex_point_map(tm, np);
  const internal::Mesh_indices<TriangleMesh> idx(tm, np);
  internal::validate_mesh(idx, vpm);
  const internal::Overlap_split split = internal::overlap_splitting_cut(idx, vpm, internal::plane_coordinates(idx, uv));
  Overlap_splitting_result r;
  r.overlapping_pieces = split.overlapping;
  r.split_pieces = split.split;
  for(std::size_t e = 0; e < idx.number_of_edges(); ++e)
    if(split.edge_is_cut[e])
    {
      ++r.cut_edges;
      *cut_edges++ = idx.edge(e);
    }
  return r;
}

} // namespace Surface_design
} // namespace CGAL

#endif // CGAL_SURFACE_DESIGN_OVERLAP_SPLITTING_CUT_H
