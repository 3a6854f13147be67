// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Layout of flattened pieces on sheets (smallest bounding rectangles, shelf packing) and the SVG
// drawing of a pattern, on plain arrays.

#ifndef CGAL_SURFACE_DESIGN_INTERNAL_DEVELOPABILITY_PATTERN_LAYOUT_H
#define CGAL_SURFACE_DESIGN_INTERNAL_DEVELOPABILITY_PATTERN_LAYOUT_H

#include <CGAL/Surface_design/exceptions.h>
#include <CGAL/Surface_design/internal/Core/Mesh_indices.h>
#include <CGAL/Surface_design/internal/Core/angles.h>
#include <CGAL/Surface_design/internal/Core/named_parameters.h>
#include <CGAL/Surface_design/internal/Developability/glue_tabs.h>
#include <CGAL/Surface_design/internal/Developability/pattern_canvas.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <iomanip>
#include <numeric>
#include <ostream>
#include <sstream>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_design {
namespace internal {

/// Convex hull (counter-clockwise, no collinear points) by Andrew's monotone chain.
inline std::vector<Eigen::Vector2d> convex_hull(std::vector<Eigen::Vector2d> points)
{
  std::sort(points.begin(), points.end(), [](const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y());
  });
  if(points.size() < 3)
    return points;
  auto cross = [](const Eigen::Vector2d& o, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    return (a - o).x() * (b - o).y() - (a - o).y() * (b - o).x();
  };
  std::vector<Eigen::Vector2d> hull(2 * points.size());
  std::size_t k = 0;
  for(std::size_t i = 0; i < points.size(); ++i)
  {
    while(k >= 2 && cross(hull[k - 2], hull[k - 1], points[i]) <= 0.)
      --k;
    hull[k++] = points[i];
  }
  for(std::size_t i = points.size() - 1, t = k + 1; i-- > 0;)
  {
    while(k >= t && cross(hull[k - 2], hull[k - 1], points[i]) <= 0.)
      --k;
    hull[k++] = points[i];
  }
  hull.resize(k - 1);
  return hull;
}

/// The rotation angle that gives the points their smallest-area axis-aligned bounding box (a
/// side of the smallest rectangle lies on a hull edge), the box made wider than tall.
inline double smallest_box_rotation(const std::vector<Eigen::Vector2d>& points)
{
  const std::vector<Eigen::Vector2d> hull = convex_hull(points);
  double best_angle = 0., best_area = std::numeric_limits<double>::infinity();
  auto extent = [&](double angle) {
    const Eigen::Rotation2Dd r(angle);
    Eigen::Vector2d lo = Eigen::Vector2d::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
    for(const Eigen::Vector2d& q : hull)
    {
      const Eigen::Vector2d t = r * q;
      lo = lo.cwiseMin(t);
      hi = hi.cwiseMax(t);
    }
    return Eigen::Vector2d(hi - lo);
  };
  for(std::size_t i = 0; i < hull.size(); ++i)
  {
    const Eigen::Vector2d e = hull[(i + 1) % hull.size()] - hull[i];
    const double angle = -std::atan2(e.y(), e.x());
    const Eigen::Vector2d size = extent(angle);
    if(size.x() * size.y() < best_area * (1. - 1e-12))
    {
      best_area = size.x() * size.y();
      best_angle = angle;
    }
  }
  const Eigen::Vector2d size = extent(best_angle);
  if(size.y() > size.x())
    best_angle += 0.5 * pi;
  return best_angle;
}

/// The largest "round" number (1, 1.2, 1.5, 2, 2.5, 3, 4, 5, 6, 8 times a power of ten) <= x.
inline double round_down(double x)
{
  const double decade = std::pow(10., std::floor(std::log10(x)));
  double best = decade;
  for(double m : {1., 1.2, 1.5, 2., 2.5, 3., 4., 5., 6., 8., 10.})
    if(m * decade <= x * (1. + 1e-12))
      best = m * decade;
  return best;
}

struct Packed_piece
{
  std::size_t sheet = 0;
  double x = 0., y = 0., width = 0., height = 0., rotation = 0.;
};

struct Pattern_packing
{
  double sheet_width = 210., sheet_height = 297., margin = 10., spacing = 5., sheet_gap = 20.;
  double tab = 0.;        ///< width of the glue tabs, mm: room left around every piece
  double scale = 0.;      ///< output: mm per model unit
  std::size_t sheets = 0; ///< output
  std::vector<Packed_piece> pieces;
};

/// Turns, scales (for the test of fit only) and packs the pieces; returns the new positions in
/// model units, sheet k starting at x = k (W + G) / scale.
inline std::vector<Eigen::Vector2d> pack_pieces(const std::vector<Eigen::Vector2d>& p,
                                                const std::vector<std::size_t>& piece_of_vertex, std::size_t n_pieces,
                                                double given_scale, Pattern_packing& packing)
{
  std::vector<std::vector<std::size_t>> members(n_pieces);
  for(std::size_t v = 0; v < p.size(); ++v)
    members[piece_of_vertex[v]].push_back(v);
  std::vector<Eigen::Vector2d> q(p.size());
  std::vector<Eigen::Vector2d> size(n_pieces), corner(n_pieces);
  packing.pieces.assign(n_pieces, Packed_piece());
  for(std::size_t k = 0; k < n_pieces; ++k)
  {
    std::vector<Eigen::Vector2d> points;
    for(std::size_t v : members[k])
      points.push_back(p[v]);
    const double angle = smallest_box_rotation(points);
    const Eigen::Rotation2Dd r(angle);
    Eigen::Vector2d lo = Eigen::Vector2d::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
    for(std::size_t v : members[k])
    {
      q[v] = r * p[v];
      lo = lo.cwiseMin(q[v]);
      hi = hi.cwiseMax(q[v]);
    }
    for(std::size_t v : members[k])
      q[v] -= lo;
    size[k] = hi - lo;
    packing.pieces[k].rotation = angle;
  }
  // a piece and its tabs fit in its box grown by the tab width on every side: W, H inside the
  // margins; the box of a piece must fit in them, and so must the box grown by T
  const double T = 2. * packing.tab;
  const double W0 = packing.sheet_width - 2. * packing.margin, H0 = packing.sheet_height - 2. * packing.margin;
  const double W = W0 - T, H = H0 - T;
  if(!(W > 0. && H > 0.))
    throw Invalid_parameter("glue_tab_width", "tabs of " + to_text(packing.tab) + " mm leave no room inside the margins");
  // the scale at which piece k fits (turned by 90 degrees if that fits better)
  auto fit = [&](std::size_t k) {
    const double w = (std::max)(size[k].x(), 1e-300), h = (std::max)(size[k].y(), 1e-300);
    return (std::max)((std::min)(W / w, H / h), (std::min)(W / h, H / w));
  };
  double scale = given_scale;
  if(scale == 0.)
  {
    scale = std::numeric_limits<double>::infinity();
    for(std::size_t k = 0; k < n_pieces; ++k)
      scale = (std::min)(scale, fit(k));
    scale = round_down(scale);
  }
  else
    for(std::size_t k = 0; k < n_pieces; ++k)
      if(fit(k) < scale * (1. - 1e-12))
      {
        std::ostringstream s;
        s << "at " << scale << " mm per unit, piece " << k << " measures " << size[k].x() * scale << " x "
          << size[k].y() * scale << " mm, more than the " << W << " x " << H
          << " mm inside the margins of a sheet (the largest scale at which it fits is " << fit(k) << ")";
        throw Invalid_parameter("pattern_scale", s.str());
      }
  packing.scale = scale;
  // turn the pieces that only fit upright
  for(std::size_t k = 0; k < n_pieces; ++k)
    if(size[k].x() * scale > W * (1. + 1e-12))
    {
      for(std::size_t v : members[k])
        q[v] = Eigen::Vector2d(size[k].y() - q[v].y(), q[v].x());
      size[k] = Eigen::Vector2d(size[k].y(), size[k].x());
      packing.pieces[k].rotation += 0.5 * pi;
    }
  // shelves, tallest pieces first; first fit over the open shelves of all sheets
  std::vector<std::size_t> order(n_pieces);
  std::iota(order.begin(), order.end(), std::size_t(0));
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return size[a].y() > size[b].y(); });
  struct Shelf
  {
    std::size_t sheet;
    double y, height, used;
  };
  std::vector<Shelf> shelves;
  std::vector<double> sheet_used; // height used per sheet
  const double gap = packing.spacing;
  for(std::size_t k : order)
  {
    const double w = size[k].x() * scale + T, h = size[k].y() * scale + T;
    Shelf* target = nullptr;
    for(Shelf& s : shelves)
      if(h <= s.height * (1. + 1e-12) && s.used + w <= W0 * (1. + 1e-12))
      {
        target = &s;
        break;
      }
    if(!target)
    {
      std::size_t sheet = 0;
      while(sheet < sheet_used.size() && sheet_used[sheet] + h > H0 * (1. + 1e-12))
        ++sheet;
      if(sheet == sheet_used.size())
        sheet_used.push_back(0.);
      shelves.push_back(Shelf{sheet, sheet_used[sheet], h, 0.});
      sheet_used[sheet] += h + gap;
      target = &shelves.back();
    }
    Packed_piece& piece = packing.pieces[k];
    piece.sheet = target->sheet;
    piece.x = packing.margin + target->used + packing.tab;
    // shelves fill the sheet from the top down (y up: the first shelf is highest)
    piece.y = packing.sheet_height - packing.margin - target->y - h + packing.tab;
    piece.width = w - T;
    piece.height = h - T;
    target->used += w + gap;
  }
  packing.sheets = sheet_used.size();
  for(std::size_t k = 0; k < n_pieces; ++k)
  {
    const Packed_piece& piece = packing.pieces[k];
    const Eigen::Vector2d offset(
      (double(piece.sheet) * (packing.sheet_width + packing.sheet_gap) + piece.x) / scale, piece.y / scale);
    for(std::size_t v : members[k])
      q[v] += offset;
  }
  return q;
}

/// Everything the drawing of the pattern needs, by index.
struct Pattern_drawing
{
  Pattern_packing layout;
  std::vector<Eigen::Vector2d> uv;             ///< laid out, model units
  std::vector<Eigen::Vector3d> position;       ///< in space (for fold angles)
  std::vector<std::size_t> original;           ///< per vertex: the uncut vertex (empty: no seam labels)
  std::vector<std::array<std::size_t, 3>> faces;
  double fold_angle = 0.;
};

struct Pattern_report;

/// One glue tab per seam curve, along the side met first: its boundary edges in the order of its
/// piece's boundary, outside the piece; width d.layout.tab mm, else half, else a quarter, else
/// none, whichever first stays inside its sheet's margins and overlaps no piece and no tab drawn
/// before (glue_tab_fits()). Drawn as filled polygons whose outer edges are cut lines, numbered
/// like their seam.
template <class Sides>
void draw_glue_tabs(Pattern_scene& scene, const Pattern_drawing& d, const std::vector<std::size_t>& boundary_next,
                    const std::vector<std::vector<unsigned long long>>& chains, Sides& sides, Pattern_report& report);

/// What the drawing holds besides the pieces.
struct Pattern_report
{
  std::size_t seams = 0;          ///< seam curves, each labelled on both sides
  std::size_t tabs = 0;           ///< glue tabs drawn (one per seam, with a tab width)
  std::size_t narrowed_tabs = 0;  ///< of those, drawn at half or a quarter of the width to fit
  std::size_t omitted_tabs = 0;   ///< seams whose tab would overlap a piece or a tab at any width
};

/// The cutting pattern of the laid-out pieces, in mm on the sheets side by side (y down): the
/// sheets, the pieces' outlines (cut lines), the fold lines (mountain and valley), the piece
/// numbers, the glue tabs, the seam numbers on both sides of every seam, a scale bar per sheet.
inline Pattern_report draw_pattern(const Pattern_drawing& d, Pattern_scene& scene)
{
  Pattern_report report;
  const double s = d.layout.scale, H = d.layout.sheet_height;
  const std::size_t nv = d.uv.size(), nf = d.faces.size();
  auto at = [&](std::size_t v) { return Eigen::Vector2d(d.uv[v].x() * s, H - d.uv[v].y() * s); };
  // directed edges -> (face, corner)
  std::unordered_map<unsigned long long, std::pair<std::size_t, std::size_t>> directed;
  directed.reserve(3 * nf);
  auto key = [nv](std::size_t a, std::size_t b) { return (unsigned long long)a * nv + b; };
  for(std::size_t f = 0; f < nf; ++f)
    for(std::size_t k = 0; k < 3; ++k)
      directed[key(d.faces[f][k], d.faces[f][(k + 1) % 3])] = {f, k};
  // pieces: union of faces through interior edges
  std::vector<std::size_t> parent(nf);
  std::iota(parent.begin(), parent.end(), std::size_t(0));
  auto find = [&parent](std::size_t x) {
    while(parent[x] != x)
      x = parent[x] = parent[parent[x]];
    return x;
  };
  std::vector<std::size_t> boundary_next(nv, npos); // boundary edge a -> b, faces on the left
  for(std::size_t f = 0; f < nf; ++f)
    for(std::size_t k = 0; k < 3; ++k)
    {
      const std::size_t a = d.faces[f][k], b = d.faces[f][(k + 1) % 3];
      const auto it = directed.find(key(b, a));
      if(it == directed.end())
        boundary_next[a] = b;
      else
      {
        const std::size_t x = find(f), y = find(it->second.first);
        if(x != y)
          parent[(std::max)(x, y)] = (std::min)(x, y);
      }
    }

  scene.sheet_width = d.layout.sheet_width;
  scene.sheet_height = H;
  scene.sheet_gap = d.layout.sheet_gap;
  scene.sheets = d.layout.sheets;
  {
    std::ostringstream title;
    title << std::fixed << std::setprecision(3) << "Cutting pattern: " << d.layout.sheets << " sheet(s) of "
          << d.layout.sheet_width << " x " << H << " mm, scale " << std::setprecision(6) << s << " mm per model unit";
    scene.title = title.str();
  }
  auto layer = [&scene](const std::string& id, const std::string& fill, const std::string& stroke, double width) {
    scene.layers.emplace_back();
    Pattern_layer& l = scene.layers.back();
    l.id = id;
    l.style.fill = fill;
    l.style.stroke = stroke;
    l.style.width = width;
    return scene.layers.size() - 1;
  };
  // sheets
  {
    Pattern_layer& sheets = scene.layers[layer("sheets", "none", "#bbbbbb", 0.2)];
    sheets.rectangles = true;
    for(std::size_t k = 0; k < d.layout.sheets; ++k)
    {
      const double x = double(k) * (d.layout.sheet_width + d.layout.sheet_gap), w = d.layout.sheet_width;
      sheets.paths.push_back({{{Eigen::Vector2d(x, 0.), Eigen::Vector2d(x + w, 0.), Eigen::Vector2d(x + w, H),
                                Eigen::Vector2d(x, H)}},
                              true, false, {}});
    }
  }
  // pieces: filled outlines = cut lines
  {
    Pattern_layer& cuts = scene.layers[layer("cuts", "#f4efe6", "#000000", 0.25)];
    cuts.round_joins = true;
    std::vector<bool> done(nv, false);
    for(std::size_t v = 0; v < nv; ++v)
    {
      if(boundary_next[v] == npos || done[v])
        continue;
      Pattern_path outline;
      outline.closed = true;
      outline.parts.emplace_back();
      for(std::size_t x = v; x != npos && !done[x]; x = boundary_next[x])
      {
        done[x] = true;
        outline.parts.back().push_back(at(x));
      }
      cuts.paths.push_back(std::move(outline));
    }
  }

  // fold lines
  {
    Pattern_path mountain, valley;
    mountain.own_style = valley.own_style = true;
    mountain.style = {"none", "#1f4fbf", 0.2, "2,1"};
    valley.style = {"none", "#c0392b", 0.2, "2,1,0.5,1"};
    for(std::size_t f = 0; f < nf; ++f)
      for(std::size_t k = 0; k < 3; ++k)
      {
        const std::size_t a = d.faces[f][k], b = d.faces[f][(k + 1) % 3], c = d.faces[f][(k + 2) % 3];
        const auto it = directed.find(key(b, a));
        if(it == directed.end() || a > b)
          continue;
        const std::size_t g = it->second.first;
        const std::size_t c2 = d.faces[g][(it->second.second + 2) % 3];
        const Eigen::Vector3d n1 = (d.position[b] - d.position[a]).cross(d.position[c] - d.position[a]).normalized();
        const Eigen::Vector3d n2 = (d.position[a] - d.position[b]).cross(d.position[c2] - d.position[b]).normalized();
        const double dihedral = std::atan2(n1.cross(n2).norm(), n1.dot(n2));
        if(!(dihedral > d.fold_angle))
          continue;
        Pattern_path& out = (d.position[c2] - d.position[a]).dot(n1) < 0. ? mountain : valley;
        out.parts.push_back({at(a), at(b)});
      }
    if(!mountain.parts.empty() || !valley.parts.empty())
    {
      Pattern_layer& folds = scene.layers[layer("folds", "none", "none", 0.2)];
      for(Pattern_path* p : {&mountain, &valley})
        if(!p->parts.empty())
          folds.paths.push_back(std::move(*p));
    }
  }

  // piece numbers at their area centroids
  {
    std::vector<std::size_t> piece_of_root(nf, npos);
    std::vector<Eigen::Vector3d> centroid; // x, y, area
    for(std::size_t f = 0; f < nf; ++f)
    {
      const std::size_t r = find(f);
      if(piece_of_root[r] == npos)
      {
        piece_of_root[r] = centroid.size();
        centroid.emplace_back(Eigen::Vector3d::Zero());
      }
      const Eigen::Vector2d a = d.uv[d.faces[f][0]], b = d.uv[d.faces[f][1]], c = d.uv[d.faces[f][2]];
      const double area = std::abs(0.5 * ((b - a).x() * (c - a).y() - (b - a).y() * (c - a).x()));
      const Eigen::Vector2d m = (a + b + c) / 3.;
      centroid[piece_of_root[r]] += Eigen::Vector3d(m.x() * area, m.y() * area, area);
    }
    Pattern_layer& pieces = scene.layers[layer("pieces", "#777777", "none", 0.)];
    pieces.font_size = 5.;
    pieces.bold = true;
    for(std::size_t k = 0; k < centroid.size(); ++k)
      if(centroid[k].z() > 0.)
        pieces.texts.push_back({Eigen::Vector2d(centroid[k].x() / centroid[k].z() * s, H - centroid[k].y() / centroid[k].z() * s),
                                "P" + std::to_string(k + 1)});
  }

  // seam labels: boundary edges joining copies of the same two uncut vertices
  if(!d.original.empty())
  {
    std::unordered_map<unsigned long long, std::vector<std::pair<std::size_t, std::size_t>>> sides; // -> (a, b) edges
    std::size_t n_original = 0;
    for(std::size_t o : d.original)
      n_original = (std::max)(n_original, o + 1);
    auto seam_key = [n_original](std::size_t a, std::size_t b) {
      return (unsigned long long)(std::min)(a, b) * n_original + (std::max)(a, b);
    };
    for(std::size_t a = 0; a < nv; ++a)
      if(boundary_next[a] != npos)
        sides[seam_key(d.original[a], d.original[boundary_next[a]])].emplace_back(a, boundary_next[a]);
    // the seam graph on uncut vertices, walked into chains between vertices of degree != 2
    std::unordered_map<std::size_t, std::vector<unsigned long long>> incident;
    for(const auto& [k, list] : sides)
      if(list.size() == 2)
      {
        incident[k / n_original].push_back(k);
        incident[k % n_original].push_back(k);
      }
    std::unordered_map<unsigned long long, bool> visited;
    std::vector<std::vector<unsigned long long>> chains;
    auto walk = [&](std::size_t start, unsigned long long first) {
      std::vector<unsigned long long> chain;
      std::size_t x = start;
      unsigned long long e = first;
      while(!visited[e])
      {
        visited[e] = true;
        chain.push_back(e);
        x = (e / n_original == x) ? std::size_t(e % n_original) : std::size_t(e / n_original);
        const auto& next = incident[x];
        if(next.size() != 2)
          break;
        e = next[0] == e ? next[1] : next[0];
      }
      chains.push_back(std::move(chain));
    };
    std::vector<std::size_t> ends;
    for(const auto& [v, list] : incident)
      if(list.size() != 2)
        ends.push_back(v);
    std::sort(ends.begin(), ends.end());
    for(std::size_t v : ends)
      for(unsigned long long e : incident[v])
        if(!visited[e])
          walk(v, e);
    std::vector<unsigned long long> rest;
    for(const auto& [k, list] : sides)
      if(list.size() == 2 && !visited[k])
        rest.push_back(k);
    std::sort(rest.begin(), rest.end());
    for(unsigned long long e : rest)
      if(!visited[e])
        walk(std::size_t(e / n_original), e);
    report.seams = chains.size();
    if(d.layout.tab > 0.)
      draw_glue_tabs(scene, d, boundary_next, chains, sides, report);
    Pattern_layer& seams = scene.layers[layer("seams", "#1f4fbf", "none", 0.)];
    seams.font_size = 2.5;
    for(std::size_t c = 0; c < chains.size(); ++c)
    {
      const unsigned long long middle = chains[c][chains[c].size() / 2];
      for(const auto& [a, b] : sides[middle])
      {
        // inwards: the faces lie left of a -> b
        const Eigen::Vector2d pa = at(a), pb = at(b);
        Eigen::Vector2d t = pb - pa;
        const double length = t.norm();
        if(length > 0.)
          t /= length;
        const Eigen::Vector2d inward(t.y(), -t.x()); // left of a -> b with y pointing down
        seams.texts.push_back({0.5 * (pa + pb) + 2. * inward, std::to_string(c + 1)});
      }
    }
  }

  // scale bars
  {
    const double bar_units = round_down(40. / s);
    Pattern_layer& scale = scene.layers[layer("scale", "#000000", "none", 0.)];
    scale.font_size = 3.;
    scale.centered = false;
    for(std::size_t k = 0; k < d.layout.sheets; ++k)
    {
      const double x0 = double(k) * (d.layout.sheet_width + d.layout.sheet_gap) + (std::max)(d.layout.margin, 2.);
      const double y0 = H - 0.5 * (std::max)(d.layout.margin, 4.);
      Pattern_path bar;
      bar.own_style = true;
      bar.style = {"none", "#000000", 0.4, ""};
      bar.parts.push_back({Eigen::Vector2d(x0, y0 - 1.), Eigen::Vector2d(x0, y0), Eigen::Vector2d(x0 + bar_units * s, y0),
                           Eigen::Vector2d(x0 + bar_units * s, y0 - 1.)});
      scale.paths.push_back(std::move(bar));
      std::ostringstream text;
      text << std::setprecision(6) << bar_units << " model units = " << bar_units * s << " mm; sheet " << k + 1 << " of "
           << d.layout.sheets;
      scale.texts.push_back({Eigen::Vector2d(x0 + bar_units * s + 2., y0), text.str()});
    }
  }
  return report;
}

template <class Sides>
void draw_glue_tabs(Pattern_scene& scene, const Pattern_drawing& d, const std::vector<std::size_t>& boundary_next,
                    const std::vector<std::vector<unsigned long long>>& chains, Sides& sides, Pattern_report& report)
{
  const double s = d.layout.scale, H = d.layout.sheet_height;
  const std::size_t nv = d.uv.size();
  auto mm = [&](std::size_t v) { return Eigen::Vector2d(d.uv[v] * s); }; // on the sheet, y up
  auto down = [H](const Eigen::Vector2d& x) { return Eigen::Vector2d(x.x(), H - x.y()); };
  // the piece outlines
  std::vector<std::vector<Eigen::Vector2d>> pieces;
  std::vector<bool> done(nv, false);
  for(std::size_t v = 0; v < nv; ++v)
  {
    if(boundary_next[v] == npos || done[v])
      continue;
    pieces.emplace_back();
    for(std::size_t x = v; x != npos && !done[x]; x = boundary_next[x])
    {
      done[x] = true;
      pieces.back().push_back(mm(x));
    }
  }
  std::vector<std::vector<Eigen::Vector2d>> placed;
  Pattern_layer shapes, cuts, folds, labels;
  shapes.id = "tabs";
  shapes.style = {"#dde7f3", "none", 0., ""};
  cuts.id = "tab-cuts";
  cuts.style = {"none", "#000000", 0.25, ""};
  cuts.round_joins = true;
  cuts.paths.emplace_back();
  folds.id = "tab-folds";
  folds.style = {"none", "#1f4fbf", 0.2, "1,1"};
  folds.paths.emplace_back();
  labels.id = "tab-labels";
  labels.style.fill = "#1f4fbf";
  labels.font_size = 2.;
  for(std::size_t c = 0; c < chains.size(); ++c)
  {
    // the side: the boundary edges of the first side, walked in boundary order
    std::vector<std::size_t> walk;
    for(unsigned long long k : chains[c])
    {
      bool joined = false;
      for(const auto& [a, b] : sides[k])
      {
        if(walk.empty())
          walk = {a, b};
        else if(walk.back() == a)
          walk.push_back(b);
        else if(walk.front() == b)
          walk.insert(walk.begin(), a);
        else
          continue;
        joined = true;
        break;
      }
      if(!joined)
        break; // the side does not go on (a seam along which the pieces branch): the tab stops
    }
    std::vector<Eigen::Vector2d> p;
    for(std::size_t v : walk)
      p.push_back(mm(v));
    // the inside of the margins of the tab's sheet (sheet k spans [k (W + G), k (W + G) + W])
    const double period = d.layout.sheet_width + d.layout.sheet_gap;
    const double x0 = std::floor(p.front().x() / period) * period + d.layout.margin;
    const double x1 = x0 + d.layout.sheet_width - 2. * d.layout.margin;
    const double y0 = d.layout.margin, y1 = H - d.layout.margin;
    auto on_sheet = [&](const std::vector<Eigen::Vector2d>& q) {
      for(const Eigen::Vector2d& x : q)
        if(!(x.x() >= x0 && x.x() <= x1 && x.y() >= y0 && x.y() <= y1))
          return false;
      return true;
    };
    bool drawn = false;
    for(int halving = 0; halving < 3 && !drawn; ++halving)
    {
      const double width = d.layout.tab / double(1 << halving);
      const std::vector<Eigen::Vector2d> q = glue_tab_outer(p, width);
      if(!on_sheet(q) || !glue_tab_fits(p, q, pieces, placed))
        continue;
      drawn = true;
      ++report.tabs;
      report.narrowed_tabs += halving > 0;
      std::vector<Eigen::Vector2d> polygon(p);
      polygon.insert(polygon.end(), q.rbegin(), q.rend());
      placed.push_back(polygon);
      // the polygon (filled), its outer edges (cut) and its base (folded)
      Pattern_path shape;
      shape.closed = true;
      shape.parts.emplace_back();
      for(const Eigen::Vector2d& x : polygon)
        shape.parts.back().push_back(down(x));
      shapes.paths.push_back(std::move(shape));
      std::vector<Eigen::Vector2d> outer{down(p.front())};
      for(const Eigen::Vector2d& x : q)
        outer.push_back(down(x));
      outer.push_back(down(p.back()));
      cuts.paths.front().parts.push_back(std::move(outer));
      std::vector<Eigen::Vector2d> base;
      for(const Eigen::Vector2d& x : p)
        base.push_back(down(x));
      folds.paths.front().parts.push_back(std::move(base));
      const std::size_t i = p.size() / 2;
      labels.texts.push_back({down(0.5 * (p[i] + q[i])), std::to_string(c + 1)});
    }
    report.omitted_tabs += !drawn;
  }
  scene.layers.push_back(std::move(shapes));
  if(report.tabs > 0)
  {
    scene.layers.push_back(std::move(cuts));
    scene.layers.push_back(std::move(folds));
  }
  scene.layers.push_back(std::move(labels));
}

} // namespace internal
} // namespace Surface_design
} // namespace CGAL

#endif // CGAL_SURFACE_DESIGN_INTERNAL_DEVELOPABILITY_PATTERN_LAYOUT_H
