// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Fabrication patterns: flattened pieces laid out without overlap on sheets, written as SVG or PDF
// with cut lines, fold lines, matching seam labels, glue tabs and a scale bar.

#ifndef CGAL_SURFACE_DESIGN_FABRICATION_PATTERN_H
#define CGAL_SURFACE_DESIGN_FABRICATION_PATTERN_H

#include <CGAL/Surface_design/exceptions.h>
#include <CGAL/Surface_design/internal/Core/Mesh_indices.h>
#include <CGAL/Surface_design/internal/Core/named_parameters.h>
#include <CGAL/Surface_design/internal/Core/topology.h>
#include <CGAL/Surface_design/internal/Developability/distortion.h>
#include <CGAL/Surface_design/internal/Developability/pattern_layout.h>
#include <CGAL/Surface_design/parameters.h>

#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Named_function_parameters.h>

#include <Eigen/Core>

#include <cstddef>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_design {

/// \ingroup PkgFlatteningRef
/// Where `lay_out_flattened_pieces()` put every piece. Lengths on the sheet are in millimetres.
struct Fabrication_layout
{
  double sheet_width = 210., sheet_height = 297.; ///< mm
  double margin = 10., spacing = 5.;              ///< mm
  double scale = 1.;     ///< mm on the sheet per unit of the model
  double sheet_gap = 20.; ///< mm between two sheets placed side by side in the plane of `uv`
  double glue_tab_width = 0.; ///< mm of room left around every piece for the glue tabs of the drawing
  std::size_t sheets = 0;
  struct Piece
  {
    std::size_t sheet = 0;
    double x = 0., y = 0., width = 0., height = 0.; ///< bounding box on its sheet, mm from the sheet's lower left corner
    double rotation = 0.; ///< radians the piece was turned by
    std::size_t faces = 0;
  };
  std::vector<Piece> pieces; ///< per connected component, in the order of their smallest vertex index
};

/// \ingroup PkgFlatteningRef
/// What `write_fabrication_pattern_svg()` drew besides the pieces.
struct Fabrication_pattern_report
{
  std::size_t seams = 0;              ///< seam curves, each numbered on both sides (0 without `seam_vertex_index_map`)
  std::size_t glue_tabs = 0;          ///< glue tabs drawn: one per seam at most
  std::size_t narrowed_glue_tabs = 0; ///< of those, drawn at half or a quarter of the width, to fit
  std::size_t omitted_glue_tabs = 0;  ///< seams without a tab: it would overlap a piece or a tab at any width
};

/// \ingroup PkgFlatteningRef
///
/// Moves every flattened piece (connected component) of `tm` rigidly in the plane so that the
/// pieces lie without overlap on sheets of a given size: each piece turned to its smallest
/// bounding rectangle (then by 90 degrees if only that fits), then packed in shelves, tallest
/// first, on as many sheets as needed. Rigid motions change no distortion. Sheet k occupies
/// [k (W + G), k (W + G) + W] x [0, H] / scale in the coordinates of `uv` (model units, y up).
///
/// \param tm a triangle mesh (its faces' connectivity defines the pieces)
/// \param uv a readable and writable vertex -> `Point_2` map (the flattening; overwritten)
/// \param np an optional sequence of named parameters among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{sheet_size}
///     \cgalParamDescription{the width and the height of a sheet, in mm}
///     \cgalParamType{`std::pair<double, double>`}
///     \cgalParamDefault{(210, 297): A4}
///     \cgalParamExtra{throws `Invalid_parameter` if the width or the height is not in [1, 1e6]}
///   \cgalParamNEnd
///   \cgalParamNBegin{pattern_scale}
///     \cgalParamDescription{mm on the sheet per unit of the model; 0: the largest "round" scale (1, 1.2,
///                           1.5, 2, 2.5, 3, 4, 5, 6, 8 times a power of ten) at which every piece fits}
///     \cgalParamType{`double`}
///     \cgalParamDefault{`0`}
///     \cgalParamExtra{throws `Invalid_parameter` if it is negative or not finite, or if a piece does not fit
///                     inside the margins of a sheet at it}
///   \cgalParamNEnd
///   \cgalParamNBegin{sheet_margin}
///     \cgalParamDescription{the margin along the sides of a sheet, in mm}
///     \cgalParamType{`double`}
///     \cgalParamDefault{`10`}
///     \cgalParamExtra{throws `Invalid_parameter` if it is negative or not finite, or if twice the margin is
///                     not less than the smaller side of a sheet}
///   \cgalParamNEnd
///   \cgalParamNBegin{piece_spacing}
///     \cgalParamDescription{the spacing between the pieces on a sheet, in mm}
///     \cgalParamType{`double`}
///     \cgalParamDefault{`5`}
///     \cgalParamExtra{throws `Invalid_parameter` if it is negative or not finite}
///   \cgalParamNEnd
///   \cgalParamNBegin{glue_tab_width}
///     \cgalParamDescription{the width of the glue tabs that `write_fabrication_pattern_svg()` draws along
///                           one side of every seam, in mm: every piece is packed with this much room on
///                           every side (in addition to `piece_spacing`); 0: no tabs}
///     \cgalParamType{`double`}
///     \cgalParamDefault{`0`}
///     \cgalParamExtra{throws `Invalid_parameter` if it is negative or not finite, or leaves no room inside the
///                     margins}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_index_map}
///     \cgalParamDescription{a property map associating to each vertex of `tm` a unique index in
///                           `[0, num_vertices(tm))`: the numbering of the elements, in error messages and
///                           for the pieces (numbered in the order of their smallest vertex index)}
///     \cgalParamType{a class model of `ReadablePropertyMap` with
///                    `boost::graph_traits<TriangleMesh>::%vertex_descriptor` as key type and an integer as
///                    value type}
///     \cgalParamDefault{the mesh's own (`CGAL::get_initialized_vertex_index_map(tm)`)}
///     \cgalParamExtra{throws `Invalid_mesh` (`Mesh_defect::invalid_index_map`) if it is not a bijection onto
///                     `[0, num_vertices(tm))`}
///   \cgalParamNEnd
///   \cgalParamNBegin{halfedge_index_map}
///     \cgalParamDescription{a property map associating to each halfedge of `tm` a unique index in
///                           `[0, num_halfedges(tm))`: the numbering of the elements, in error messages and
///                           for the pieces (numbered in the order of their smallest vertex index)}
///     \cgalParamType{a class model of `ReadablePropertyMap` with
///                    `boost::graph_traits<TriangleMesh>::%halfedge_descriptor` as key type and an integer as
///                    value type}
///     \cgalParamDefault{the mesh's own (`CGAL::get_initialized_halfedge_index_map(tm)`)}
///     \cgalParamExtra{throws `Invalid_mesh` (`Mesh_defect::invalid_index_map`) if it is not a bijection onto
///                     `[0, num_halfedges(tm))`}
///   \cgalParamNEnd
///   \cgalParamNBegin{edge_index_map}
///     \cgalParamDescription{a property map associating to each edge of `tm` a unique index in
///                           `[0, num_edges(tm))`: the numbering of the elements, in error messages and for
///                           the pieces (numbered in the order of their smallest vertex index)}
///     \cgalParamType{a class model of `ReadablePropertyMap` with
///                    `boost::graph_traits<TriangleMesh>::%edge_descriptor` as key type and an integer as
///                    value type}
///     \cgalParamDefault{the order of `edges(tm)`}
///     \cgalParamExtra{throws `Invalid_mesh` (`Mesh_defect::invalid_index_map`) if it is not a bijection onto
///                     `[0, num_edges(tm))`}
///   \cgalParamNEnd
///   \cgalParamNBegin{face_index_map}
///     \cgalParamDescription{a property map associating to each face of `tm` a unique index in
///                           `[0, num_faces(tm))`: the numbering of the elements, in error messages and for
///                           the pieces (numbered in the order of their smallest vertex index)}
///     \cgalParamType{a class model of `ReadablePropertyMap` with
///                    `boost::graph_traits<TriangleMesh>::%face_descriptor` as key type and an integer as
///                    value type}
///     \cgalParamDefault{the mesh's own (`CGAL::get_initialized_face_index_map(tm)`)}
///     \cgalParamExtra{throws `Invalid_mesh` (`Mesh_defect::invalid_index_map`) if it is not a bijection onto
///                     `[0, num_faces(tm))`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \throws Invalid_parameter a size is not finite or out of range, or a piece does not fit on a
///         sheet at the given scale; `uv` is not written then
template <class TriangleMesh, class UVMap, class NamedParameters = CGAL::parameters::Default_named_parameters>
Fabrication_layout lay_out_flattened_pieces(const TriangleMesh& tm, UVMap uv,
                                            const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  Fabrication_layout layout;
  const std::pair<double, double> size =
    choose_parameter(get_parameter(np, internal_np::sheet_size), std::pair<double, double>(210., 297.));
  layout.sheet_width = internal::require_in_range("sheet_size", size.first, 1., 1e6);
  layout.sheet_height = internal::require_in_range("sheet_size", size.second, 1., 1e6);
  layout.margin = internal::require_nonnegative("sheet_margin",
                                                choose_parameter(get_parameter(np, internal_np::sheet_margin), 10.));
  layout.spacing = internal::require_nonnegative("piece_spacing",
                                                 choose_parameter(get_parameter(np, internal_np::piece_spacing), 5.));
  const double scale = internal::require_nonnegative("pattern_scale",
                                                     choose_parameter(get_parameter(np, internal_np::pattern_scale), 0.));
  if(!(2. * layout.margin < (std::min)(layout.sheet_width, layout.sheet_height)))
    throw Invalid_parameter("sheet_margin", "margins of " + internal::to_text(layout.margin) +
                                              " mm leave no room on a sheet of " + internal::to_text(layout.sheet_width) +
                                              " x " + internal::to_text(layout.sheet_height) + " mm");
  layout.sheet_gap = 20.;
  layout.glue_tab_width = internal::require_nonnegative(
    "glue_tab_width", choose_parameter(get_parameter(np, internal_np::glue_tab_width), 0.));

  const internal::Mesh_indices<TriangleMesh> idx(tm, np);
  const internal::Boundary_loops loops = internal::boundary_loops(idx);
  const internal::Components comps = internal::connected_components(idx, loops);
  const std::vector<Eigen::Vector2d> p = internal::plane_coordinates(idx, uv);
  internal::Pattern_packing packing;
  packing.sheet_width = layout.sheet_width;
  packing.sheet_height = layout.sheet_height;
  packing.margin = layout.margin;
  packing.spacing = layout.spacing;
  packing.sheet_gap = layout.sheet_gap;
  packing.tab = layout.glue_tab_width;
  const std::vector<Eigen::Vector2d> moved = internal::pack_pieces(p, comps.vertex_component, comps.size(), scale, packing);
  layout.scale = packing.scale;
  layout.sheets = packing.sheets;
  for(const internal::Packed_piece& piece : packing.pieces)
  {
    Fabrication_layout::Piece out;
    out.sheet = piece.sheet;
    out.x = piece.x;
    out.y = piece.y;
    out.width = piece.width;
    out.height = piece.height;
    out.rotation = piece.rotation;
    layout.pieces.push_back(out);
  }
  for(std::size_t f = 0; f < idx.number_of_faces(); ++f)
    ++layout.pieces[comps.face_component[f]].faces;
  using Point_2 = typename boost::property_traits<UVMap>::value_type;
  for(std::size_t v = 0; v < p.size(); ++v)
    put(uv, idx.vertex(v), Point_2(moved[v].x(), moved[v].y()));
  return layout;
}

namespace internal {

// The drawing of write_fabrication_pattern_svg() and write_fabrication_pattern_pdf(), validated
// before anything is written.
template <class TriangleMesh, class UVMap, class NamedParameters>
Fabrication_pattern_report draw_fabrication_pattern(const TriangleMesh& tm, const UVMap& uv,
                                                    const Fabrication_layout& layout, const NamedParameters& np,
                                                    Pattern_scene& scene)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  const double fold_angle = require_in_range(
    "fold_angle", choose_parameter(get_parameter(np, internal_np::fold_angle), 5. * pi / 180.), 0., pi);
  const auto vpm = const_vertex_point_map(tm, np);
  const Mesh_indices<TriangleMesh> idx(tm, np);
  Pattern_drawing drawing;
  drawing.layout.sheet_width = layout.sheet_width;
  drawing.layout.sheet_height = layout.sheet_height;
  drawing.layout.margin = layout.margin;
  drawing.layout.sheet_gap = require_nonnegative("Fabrication_layout::sheet_gap", layout.sheet_gap);
  drawing.layout.scale = layout.scale;
  drawing.layout.sheets = layout.sheets;
  drawing.layout.tab = require_nonnegative("Fabrication_layout::glue_tab_width", layout.glue_tab_width);
  drawing.fold_angle = fold_angle;
  const std::size_t nv = idx.number_of_vertices();
  drawing.uv = plane_coordinates(idx, uv);
  drawing.position.resize(nv);
  for(std::size_t v = 0; v < nv; ++v)
    drawing.position[v] = position(vpm, idx.vertex(v));
  const auto seam_map = get_parameter(np, internal_np::seam_vertex_index_map);
  if constexpr(!std::is_same<std::decay_t<decltype(seam_map)>, CGAL::internal_np::Param_not_found>::value)
  {
    drawing.original.resize(nv);
    for(std::size_t v = 0; v < nv; ++v)
      drawing.original[v] = std::size_t(get(seam_map, idx.vertex(v)));
  }
  const auto& mesh = idx.mesh();
  drawing.faces.resize(idx.number_of_faces());
  for(std::size_t f = 0; f < drawing.faces.size(); ++f)
  {
    auto h = halfedge(idx.face(f), mesh);
    for(std::size_t k = 0; k < 3; ++k, h = next(h, mesh))
      drawing.faces[f][k] = idx.target_index(h);
  }
  const Pattern_report r = draw_pattern(drawing, scene);
  Fabrication_pattern_report report;
  report.seams = r.seams;
  report.glue_tabs = r.tabs;
  report.narrowed_glue_tabs = r.narrowed_tabs;
  report.omitted_glue_tabs = r.omitted_tabs;
  return report;
}

} // namespace internal

/// \ingroup PkgFlatteningRef
///
/// Writes the cutting pattern of laid-out pieces (`lay_out_flattened_pieces()`) as SVG, in
/// millimetres (one drawing, the sheets side by side, each outlined in grey): every piece's
/// boundary as a solid black cut line, its number at its centre; interior edges whose dihedral
/// angle in space exceeds `fold_angle` as fold lines (blue dashes: mountain folds, red dash-dots:
/// valley folds, seen from the side the faces' orientation points to); the two sides of every
/// seam curve labelled with the same number; with a `glue_tab_width` in the layout, a glue tab
/// along one side of every seam (outside its piece, tapered at 45 degrees, numbered like the seam,
/// narrowed to a half or a quarter where the full width would overlap a piece or another tab, and
/// left out where even that does: see the returned report); and a scale bar on every sheet.
///
/// \param os the stream
/// \param tm the flattened mesh (its pieces are the sides of the seams)
/// \param uv a readable vertex -> `Point_2` map, laid out
/// \param layout the layout that placed them
/// \param np an optional sequence of named parameters among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{a property map associating points to the vertices of `tm`: the positions in
///                           space, which give the dihedral angles of the fold lines}
///     \cgalParamType{a class model of `ReadablePropertyMap` with
///                    `boost::graph_traits<TriangleMesh>::%vertex_descriptor` as key type and `%Point_3` as
///                    value type}
///     \cgalParamDefault{`boost::get(CGAL::vertex_point, tm)`}
///   \cgalParamNEnd
///   \cgalParamNBegin{seam_vertex_index_map}
///     \cgalParamDescription{the vertex of the uncut mesh that a vertex copies (e.g. from
///                           `cut_mesh_along_edges()`'s `vertex_to_vertex_output_iterator`); two boundary
///                           edges joining copies of the same two vertices are the two sides of a seam}
///     \cgalParamType{a class model of `ReadablePropertyMap` with
///                    `boost::graph_traits<TriangleMesh>::%vertex_descriptor` as key type and an integer as
///                    value type}
///     \cgalParamDefault{none: no seam is labelled}
///   \cgalParamNEnd
///   \cgalParamNBegin{fold_angle}
///     \cgalParamDescription{the dihedral angle in space, in radians, that an interior edge must exceed to be
///                           drawn as a fold line; pi draws no fold line}
///     \cgalParamType{`double`}
///     \cgalParamDefault{5 degrees (`5 * pi / 180`)}
///     \cgalParamExtra{throws `Invalid_parameter` if it is not in [0, pi]}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_index_map}
///     \cgalParamDescription{a property map associating to each vertex of `tm` a unique index in
///                           `[0, num_vertices(tm))`: the numbering of the elements in the drawing and in
///                           error messages}
///     \cgalParamType{a class model of `ReadablePropertyMap` with
///                    `boost::graph_traits<TriangleMesh>::%vertex_descriptor` as key type and an integer as
///                    value type}
///     \cgalParamDefault{the mesh's own (`CGAL::get_initialized_vertex_index_map(tm)`)}
///     \cgalParamExtra{throws `Invalid_mesh` (`Mesh_defect::invalid_index_map`) if it is not a bijection onto
///                     `[0, num_vertices(tm))`}
///   \cgalParamNEnd
///   \cgalParamNBegin{halfedge_index_map}
///     \cgalParamDescription{a property map associating to each halfedge of `tm` a unique index in
///                           `[0, num_halfedges(tm))`: the numbering of the elements in the drawing and in
///                           error messages}
///     \cgalParamType{a class model of `ReadablePropertyMap` with
///                    `boost::graph_traits<TriangleMesh>::%halfedge_descriptor` as key type and an integer as
///                    value type}
///     \cgalParamDefault{the mesh's own (`CGAL::get_initialized_halfedge_index_map(tm)`)}
///     \cgalParamExtra{throws `Invalid_mesh` (`Mesh_defect::invalid_index_map`) if it is not a bijection onto
///                     `[0, num_halfedges(tm))`}
///   \cgalParamNEnd
///   \cgalParamNBegin{edge_index_map}
///     \cgalParamDescription{a property map associating to each edge of `tm` a unique index in
///                           `[0, num_edges(tm))`: the numbering of the elements in the drawing and in error
///                           messages}
///     \cgalParamType{a class model of `ReadablePropertyMap` with
///                    `boost::graph_traits<TriangleMesh>::%edge_descriptor` as key type and an integer as
///                    value type}
///     \cgalParamDefault{the order of `edges(tm)`}
///     \cgalParamExtra{throws `Invalid_mesh` (`Mesh_defect::invalid_index_map`) if it is not a bijection onto
///                     `[0, num_edges(tm))`}
///   \cgalParamNEnd
///   \cgalParamNBegin{face_index_map}
///     \cgalParamDescription{a property map associating to each face of `tm` a unique index in
///                           `[0, num_faces(tm))`: the numbering of the elements in the drawing and in error
///                           messages}
///     \cgalParamType{a class model of `ReadablePropertyMap` with
///                    `boost::graph_traits<TriangleMesh>::%face_descriptor` as key type and an integer as
///                    value type}
///     \cgalParamDefault{the mesh's own (`CGAL::get_initialized_face_index_map(tm)`)}
///     \cgalParamExtra{throws `Invalid_mesh` (`Mesh_defect::invalid_index_map`) if it is not a bijection onto
///                     `[0, num_faces(tm))`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \returns the seams, and the glue tabs drawn, narrowed and omitted
/// \throws Invalid_parameter (`fold_angle`, or a coordinate of `uv` that is not finite; nothing
///         is written then); std::ios_base::failure is not thrown, check `os`
template <class TriangleMesh, class UVMap, class NamedParameters = CGAL::parameters::Default_named_parameters>
Fabrication_pattern_report write_fabrication_pattern_svg(std::ostream& os, const TriangleMesh& tm, const UVMap& uv,
                                   const Fabrication_layout& layout,
                                   const NamedParameters& np = CGAL::parameters::default_values())
{
  internal::Pattern_scene scene;
  const Fabrication_pattern_report report = internal::draw_fabrication_pattern(tm, uv, layout, np, scene);
  internal::write_scene_svg(os, scene);
  return report;
}

/// \ingroup PkgFlatteningRef
///
/// Writes the cutting pattern of `write_fabrication_pattern_svg()` as a PDF document, one page
/// per sheet at the sheet's size, ready to print at 100%: the same cut lines, fold lines, piece
/// and seam numbers, glue tabs and scale bars, in the same colours (PDF 1.4 written directly,
/// vector paths and the standard Helvetica fonts; no library needed). `os` must be a binary
/// stream (`std::ios::binary`: the cross-reference table holds byte offsets). The parameters,
/// named parameters, report and exceptions are those of `write_fabrication_pattern_svg()`.
template <class TriangleMesh, class UVMap, class NamedParameters = CGAL::parameters::Default_named_parameters>
Fabrication_pattern_report write_fabrication_pattern_pdf(std::ostream& os, const TriangleMesh& tm, const UVMap& uv,
                                                         const Fabrication_layout& layout,
                                                         const NamedParameters& np = CGAL::parameters::default_values())
{
  internal::Pattern_scene scene;
  const Fabrication_pattern_report report = internal::draw_fabrication_pattern(tm, uv, layout, np, scene);
  internal::write_scene_pdf(os, scene);
  return report;
}

} // namespace Surface_design
} // namespace CGAL

#endif // CGAL_SURFACE_DESIGN_FABRICATION_PATTERN_H
