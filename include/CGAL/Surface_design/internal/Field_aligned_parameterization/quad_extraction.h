// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A quad mesh from the level-0 lines of the two stripe families of a cross field: the crossings
// of the lines are its vertices, the pieces of lines between crossings its edges, and its faces
// are traced from the order of the pieces around each vertex on the surface.

#ifndef CGAL_SURFACE_DESIGN_INTERNAL_FIELD_ALIGNED_PARAMETERIZATION_QUAD_EXTRACTION_H
#define CGAL_SURFACE_DESIGN_INTERNAL_FIELD_ALIGNED_PARAMETERIZATION_QUAD_EXTRACTION_H

#include <CGAL/Surface_design/internal/Core/geometry.h>
#include <CGAL/Surface_design/internal/Core/topology.h>
#include <CGAL/Surface_design/internal/Field_aligned_parameterization/stripe_isolines.h>

#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_design {
namespace internal {

/// What the extraction found: the polygons traced on the surface (quads where the map is an
/// integer-grid map), their vertices (on the input's faces) and why it is not a quad mesh
/// otherwise.
struct Quad_extraction
{
  std::vector<Eigen::Vector3d> points;
  std::vector<std::size_t> point_face;                 ///< the input face each point lies in
  std::vector<std::vector<std::size_t>> faces;         ///< every traced polygon, counterclockwise
  std::vector<std::size_t> cone_vertex;                ///< per cone (input order), its vertex
  std::vector<bool> on_boundary;                       ///< per point: whether it lies on a boundary loop
  std::vector<std::pair<std::size_t, int>> corner_vertex; ///< boundary corners: (vertex, the quads due there)
  std::size_t non_quads = 0;                           ///< faces with other than four sides
  std::size_t open_ends = 0;                           ///< lines ending elsewhere than at a cone or a boundary
  std::size_t closed_lines_without_crossing = 0;       ///< closed lines (boundary loops too) that meet no other line
  std::size_t holes = 0;                               ///< polygons traced outside a boundary loop (not in faces)
  std::size_t broken_holes = 0;                        ///< polygons running partly outside a boundary loop
};

/// The boundary loops of the input as closed polylines, the surface on their left (along the
/// face's halfedges): points at the boundary vertices, faces[i] the face of the edge from points[i].
template <class Indices, class VertexPointMap>
std::vector<Stripe_isoline_polyline> boundary_polylines(const Indices& idx, const VertexPointMap& vpm)
{
  const auto& tm = idx.mesh();
  std::vector<Stripe_isoline_polyline> result;
  for(const auto& loop : boundary_loops(idx).loops)
  {
    Stripe_isoline_polyline line;
    line.closed = true;
    // the border halfedges run with the surface on their right: backwards, along their opposites
    for(std::size_t i = loop.size(); i-- > 0;)
    {
      const auto h = idx.halfedge(loop[i]);
      line.points.push_back(position(vpm, target(h, tm)));
      line.faces.push_back(idx.index(face(opposite(h, tm), tm)));
    }
    result.push_back(std::move(line));
  }
  return result;
}

/// A corner of the boundary (a boundary vertex where the family normal to it switches): the
/// point of the mesh vertex and the quads due there (1 at a convex corner, 3 at a concave one).
struct Quad_extraction_corner
{
  Eigen::Vector3d point;
  int quads;
};

/// One cone of the field: its branch face and the branch point (where its lines end).
struct Quad_extraction_cone
{
  std::size_t face;
  Eigen::Vector3d point;
};

/// The quad layout of the lines of level `level` (0 or pi, both families; the other lines are
/// ignored): level 0 where the cones are on the lattice; without cones either level works, and pi
/// avoids the mesh vertex where the stripe angle is pinned to 0. `normal` gives each input face's
/// unit normal (the orientation of the surface), `cones` the branch points where lines end
/// (within `tolerance` of the point). `boundary`: the input's boundary loops
/// (`boundary_polylines()`) where they lie on level lines: the lines that end on them make
/// vertices there, and the polygons traced outside them are the holes; `corners` are vertices
/// too, lines ending there or not.
///
/// Vertices: every crossing of two pieces of line inside one input face (pieces are half-open at
/// their ends, so that a crossing on an input edge is counted once), and every cone. Edges: the
/// pieces of line between consecutive vertices along a line. Around each vertex the edges leaving
/// it are sorted counterclockwise in its face's tangent plane; the face to the left of an edge
/// a -> b continues with the edge leaving b just before b -> a in that order.
inline Quad_extraction extract_quads(const std::vector<Stripe_isoline_polyline>& all_lines,
                                     const std::vector<Eigen::Vector3d>& normal,
                                     const std::vector<Quad_extraction_cone>& cones, double tolerance,
                                     double level = 0.,
                                     const std::vector<Stripe_isoline_polyline>& boundary = {},
                                     const std::vector<Quad_extraction_corner>& corners = {})
{
  std::vector<const Stripe_isoline_polyline*> lines;
  for(const auto& line : all_lines)
    if(std::abs(line.level - level) < 1e-9 && line.points.size() >= 2)
      lines.push_back(&line);
  const std::size_t first_boundary_line = lines.size();
  for(const auto& line : boundary)
    lines.push_back(&line);
  auto is_boundary = [&](std::size_t l) { return l >= first_boundary_line; };
  Quad_extraction out;

  // the pieces: piece s of line l from points[s] to points[s + 1] (closed lines wrap) in faces[s]
  auto piece_count = [&](std::size_t l) {
    const auto& line = *lines[l];
    return line.closed ? line.points.size() : line.points.size() - 1;
  };
  auto piece_end = [&](std::size_t l, std::size_t s) -> const Eigen::Vector3d& {
    const auto& line = *lines[l];
    return line.points[(s + 1) % line.points.size()];
  };
  std::size_t nf = normal.size();
  std::vector<std::vector<std::pair<std::size_t, std::size_t>>> in_face(nf);
  for(std::size_t l = 0; l < lines.size(); ++l)
    for(std::size_t s = 0; s < piece_count(l); ++s)
      in_face[lines[l]->faces[s]].emplace_back(l, s);

  // vertices along each line: (position along the line, vertex)
  std::vector<std::vector<std::pair<double, std::size_t>>> on_line(lines.size());
  // the direction in which each vertex leaves along each line it lies on is read from the
  // piece it is on; vertex -> its face
  auto add_point = [&](const Eigen::Vector3d& x, std::size_t f) {
    out.points.push_back(x);
    out.point_face.push_back(f);
    out.on_boundary.push_back(false);
    return out.points.size() - 1;
  };
  // the branch point of each branch face: the lines that end there meet only there, at the cone
  std::vector<const Eigen::Vector3d*> cone_in_face(nf, nullptr);
  for(const auto& cone : cones)
    cone_in_face[cone.face] = &cone.point;
  for(std::size_t f = 0; f < nf; ++f)
  {
    const auto& here = in_face[f];
    if(here.size() < 2)
      continue;
    // a basis of the face's plane
    const Eigen::Vector3d n = normal[f];
    Eigen::Vector3d e1 = n.unitOrthogonal(), e2 = n.cross(e1);
    auto flat = [&](const Eigen::Vector3d& x) { return Eigen::Vector2d(x.dot(e1), x.dot(e2)); };
    for(std::size_t i = 0; i < here.size(); ++i)
      for(std::size_t j = i + 1; j < here.size(); ++j)
      {
        const auto [l1, s1] = here[i];
        const auto [l2, s2] = here[j];
        if(is_boundary(l1) || is_boundary(l2))
          continue; // lines meet the boundary at their ends (below)
        const Eigen::Vector3d& p0 = lines[l1]->points[s1];
        const Eigen::Vector3d& q0 = lines[l2]->points[s2];
        const Eigen::Vector3d &p1 = piece_end(l1, s1), &q1 = piece_end(l2, s2);
        if(p0 == q0 || p0 == q1 || p1 == q0 || p1 == q1)
          continue; // pieces with a point in common cross there or end there (below)
        const Eigen::Vector2d p = flat(p0), r = flat(p1) - p;
        const Eigen::Vector2d q = flat(q0), t = flat(q1) - q;
        const double den = r.x() * t.y() - r.y() * t.x();
        if(den == 0.)
          continue; // parallel pieces do not cross (overlapping ones are not lines of a map)
        const Eigen::Vector2d w = q - p;
        const double a = (w.x() * t.y() - w.y() * t.x()) / den, b = (w.x() * r.y() - w.y() * r.x()) / den;
        if(!(a >= 0. && a < 1. && b >= 0. && b < 1.))
          continue;
        const Eigen::Vector3d x = p0 + a * (p1 - p0);
        if(cone_in_face[f] && (x - *cone_in_face[f]).norm() < tolerance)
          continue;
        const std::size_t v = add_point(x, f);
        on_line[l1].emplace_back(double(s1) + a, v);
        on_line[l2].emplace_back(double(s2) + b, v);
      }
  }
  // the lines that cross exactly at a mesh vertex or on an input edge share that point (the
  // isolines run through it, see Stripe_isoline_builder): a vertex where two lines pass through
  // one point, which the pieces, half-open, would miss or meet in either face
  {
    std::map<std::array<double, 3>, std::vector<std::pair<std::size_t, std::size_t>>> through;
    for(std::size_t l = 0; l < first_boundary_line; ++l)
      for(std::size_t i : lines[l]->crossings)
      {
        const Eigen::Vector3d& x = lines[l]->points[i];
        through[{x.x(), x.y(), x.z()}].emplace_back(l, i);
      }
    for(const auto& [x, at] : through)
    {
      if(at.size() < 2)
        continue;
      const auto [l, i] = at.front();
      const std::size_t v = add_point(lines[l]->points[i], lines[l]->faces[i]);
      for(const auto& [m, j] : at)
        on_line[m].emplace_back(double(j), v);
    }
  }
  // vertex v at point x on every line (not the boundary's) that ends there or runs through it
  std::vector<bool> end_used(2 * lines.size(), false);
  auto on_lines_at = [&](const Eigen::Vector3d& x, std::size_t v) {
    for(std::size_t l = 0; l < first_boundary_line; ++l)
    {
      const auto& line = *lines[l];
      for(std::size_t i = 0; i < line.points.size(); ++i)
        if((line.points[i] - x).norm() < tolerance)
        {
          on_line[l].emplace_back(double(i), v);
          if(!line.closed && i == 0)
            end_used[2 * l] = true;
          if(!line.closed && i + 1 == line.points.size())
            end_used[2 * l + 1] = true;
        }
    }
  };
  // cones: the points of lines at their branch points (line ends, or points a line runs through)
  for(const auto& cone : cones)
  {
    const std::size_t v = add_point(cone.point, cone.face);
    out.cone_vertex.push_back(v);
    on_lines_at(cone.point, v);
  }
  // the ends on the boundary: a point of a boundary piece in the end's face (on the boundary
  // edge), or a boundary vertex; lines ending at the same point share its vertex
  if(!boundary.empty())
  {
    std::map<std::array<double, 3>, std::pair<std::size_t, std::size_t>> boundary_vertex; // point -> (line, i)
    for(std::size_t l = first_boundary_line; l < lines.size(); ++l)
      for(std::size_t i = 0; i < lines[l]->points.size(); ++i)
      {
        const Eigen::Vector3d& x = lines[l]->points[i];
        boundary_vertex.emplace(std::array<double, 3>{x.x(), x.y(), x.z()}, std::make_pair(l, i));
      }
    std::map<std::pair<std::size_t, std::size_t>, std::vector<std::pair<double, std::size_t>>> on_piece;
    for(const auto& corner : corners)
    {
      const auto it = boundary_vertex.find({corner.point.x(), corner.point.y(), corner.point.z()});
      if(it == boundary_vertex.end())
        continue; // not a boundary vertex: the check finds its quads missing
      const auto [b, i] = it->second;
      const std::size_t v = add_point(corner.point, lines[b]->faces[i]);
      out.on_boundary[v] = true;
      out.corner_vertex.emplace_back(v, corner.quads);
      on_piece[{b, i}].emplace_back(double(i), v);
      on_line[b].emplace_back(double(i), v);
      // the lines through the corner (at a concave one the two continuations of the boundary's
      // lines into the surface, chained into one line there) or ending there
      on_lines_at(corner.point, v);
    }
    auto boundary_point = [&](const Eigen::Vector3d& x, std::size_t f) -> std::pair<std::size_t, double> {
      for(const auto& [l, s] : in_face[f])
      {
        if(!is_boundary(l))
          continue;
        const Eigen::Vector3d& a = lines[l]->points[s];
        const Eigen::Vector3d d = piece_end(l, s) - a;
        const double t = std::clamp((x - a).dot(d) / d.squaredNorm(), 0., 1.);
        if((a + t * d - x).norm() < tolerance)
          return {l, (x - piece_end(l, s)).norm() < tolerance ? double(s + 1) : double(s) + t};
      }
      const auto it = boundary_vertex.find({x.x(), x.y(), x.z()});
      if(it != boundary_vertex.end())
        return {it->second.first, double(it->second.second)};
      return {lines.size(), 0.};
    };
    for(std::size_t l = 0; l < first_boundary_line; ++l)
      for(int end = 0; end < 2; ++end)
      {
        const auto& line = *lines[l];
        if(line.closed || end_used[2 * l + std::size_t(end)])
          continue;
        const Eigen::Vector3d& x = end == 0 ? line.points.front() : line.points.back();
        const std::size_t f = end == 0 ? line.faces.front() : line.faces.back();
        auto [b, position] = boundary_point(x, f);
        if(b == lines.size())
          continue;
        const std::size_t count = lines[b]->points.size();
        if(position >= double(count))
          position -= double(count);
        const std::size_t piece = std::size_t(position);
        auto& here = on_piece[{b, piece}];
        std::size_t v = out.points.size();
        for(const auto& [p, w] : here)
          if(std::abs(p - position) * (piece_end(b, piece) - lines[b]->points[piece]).norm() < tolerance)
            v = w;
        if(v == out.points.size())
        {
          add_point(x, f);
          out.on_boundary[v] = true;
          here.emplace_back(position, v);
          on_line[b].emplace_back(position, v);
        }
        on_line[l].emplace_back(end == 0 ? 0. : double(line.points.size() - 1), v);
        end_used[2 * l + std::size_t(end)] = true;
      }
  }
  for(std::size_t l = 0; l < first_boundary_line; ++l)
    if(!lines[l]->closed)
      out.open_ends += (end_used[2 * l] ? 0 : 1) + (end_used[2 * l + 1] ? 0 : 1);

  // half-edges: from vertex a along line l to the next vertex b; the direction at a (into the
  // line's piece) and the direction at b (back along the piece it arrives on)
  struct Half
  {
    std::size_t from, to;
    Eigen::Vector3d direction; // leaving `from`
    bool outside = false;      // along a boundary loop, the surface on its right
  };
  std::vector<Half> half;
  auto piece_direction = [&](std::size_t l, double position, bool forward) {
    const std::size_t count = piece_count(l);
    // the piece holding the position; a position at a piece's start belongs to it going forward,
    // and to the piece before going backward
    double s = std::floor(position);
    if(!forward && position == s)
      s -= 1.;
    std::size_t k = std::size_t(std::max(0., s));
    if(lines[l]->closed)
      k = std::size_t(std::fmod(std::fmod(s, double(count)) + double(count), double(count)));
    k = std::min(k, count - 1);
    const Eigen::Vector3d d = piece_end(l, k) - lines[l]->points[k];
    return Eigen::Vector3d(forward ? d : Eigen::Vector3d(-d));
  };
  for(std::size_t l = 0; l < lines.size(); ++l)
  {
    auto& list = on_line[l];
    std::sort(list.begin(), list.end());
    if(list.empty())
    {
      if(lines[l]->closed)
        ++out.closed_lines_without_crossing;
      continue;
    }
    const std::size_t count = list.size();
    const std::size_t edges = lines[l]->closed ? count : count - 1;
    for(std::size_t i = 0; i < edges; ++i)
    {
      const auto& [pa, a] = list[i];
      const auto& [pb, b] = list[(i + 1) % count];
      half.push_back({a, b, piece_direction(l, pa, true), false});
      half.push_back({b, a, piece_direction(l, pb, false), is_boundary(l)});
    }
  }
  // the rotation around each vertex: counterclockwise in its face's plane
  const std::size_t nv = out.points.size();
  std::vector<std::vector<std::size_t>> around(nv);
  for(std::size_t h = 0; h < half.size(); ++h)
    around[half[h].from].push_back(h);
  std::vector<std::size_t> position_in_rotation(half.size(), 0);
  for(std::size_t v = 0; v < nv; ++v)
  {
    const Eigen::Vector3d n = normal[out.point_face[v]];
    const Eigen::Vector3d e1 = n.unitOrthogonal(), e2 = n.cross(e1);
    auto& list = around[v];
    std::vector<std::pair<double, std::size_t>> by_angle;
    for(std::size_t h : list)
      by_angle.emplace_back(std::atan2(half[h].direction.dot(e2), half[h].direction.dot(e1)), h);
    std::sort(by_angle.begin(), by_angle.end());
    for(std::size_t i = 0; i < by_angle.size(); ++i)
    {
      list[i] = by_angle[i].second;
      position_in_rotation[list[i]] = i;
    }
  }
  // twins: half-edges come in pairs (2k, 2k + 1)
  auto twin = [](std::size_t h) { return h ^ std::size_t(1); };
  auto next = [&](std::size_t h) {
    const std::size_t t = twin(h);
    const auto& list = around[half[h].to];
    const std::size_t i = position_in_rotation[t];
    return list[(i + list.size() - 1) % list.size()];
  };
  std::vector<bool> done(half.size(), false);
  for(std::size_t h0 = 0; h0 < half.size(); ++h0)
  {
    if(done[h0])
      continue;
    std::vector<std::size_t> polygon;
    std::size_t h = h0, outside = 0;
    while(!done[h])
    {
      done[h] = true;
      polygon.push_back(half[h].from);
      outside += half[h].outside ? 1 : 0;
      h = next(h);
    }
    if(h != h0)
      polygon.clear(); // not a cycle through h0: cannot happen with a rotation at every vertex
    if(outside != 0)
    {
      // outside a boundary loop: a hole when it runs along the loop alone
      ++(outside == polygon.size() ? out.holes : out.broken_holes);
      continue;
    }
    if(polygon.size() != 4)
      ++out.non_quads;
    out.faces.push_back(std::move(polygon));
  }
  return out;
}

/// The input as the extraction reads it: its area and every face's unit normal.
struct Quad_extraction_input
{
  double area = 0.;
  std::vector<Eigen::Vector3d> normal;
};

template <class Indices, class VertexPointMap>
Quad_extraction_input quad_extraction_input(const Indices& idx, const VertexPointMap& vpm)
{
  const auto& tm = idx.mesh();
  Quad_extraction_input in;
  in.normal.resize(idx.number_of_faces());
  for(std::size_t f = 0; f < idx.number_of_faces(); ++f)
  {
    const auto h = halfedge(idx.face(f), tm);
    const Eigen::Vector3d a = position(vpm, source(h, tm)), b = position(vpm, target(h, tm)),
                          c = position(vpm, target(next(h, tm), tm));
    const Eigen::Vector3d n = (b - a).cross(c - a);
    in.area += 0.5 * n.norm();
    in.normal[f] = n.normalized();
  }
  return in;
}

/// The point of barycentric coordinates o in face f (corners source(h), target(h),
/// target(next(h)), h = halfedge(f)).
template <class Indices, class VertexPointMap>
Eigen::Vector3d point_in_face(const Indices& idx, const VertexPointMap& vpm, std::size_t f, const std::array<double, 3>& o)
{
  const auto& tm = idx.mesh();
  const auto h = halfedge(idx.face(f), tm);
  return o[0] * position(vpm, source(h, tm)) + o[1] * position(vpm, target(h, tm)) +
         o[2] * position(vpm, target(next(h, tm), tm));
}

/// Checks that the extraction is a pure quad mesh with Euler characteristic `chi` and
/// `boundary_loops` holes (every line ending at a cone or on a boundary loop, every edge in two
/// quads, or in one along a boundary) whose vertex at cone i has valence 4 - cone_index[i], every
/// boundary vertex valence 3 (in two quads) but the corners (in the quads due there) and every
/// other vertex valence 4, and whose quads face the way of the input (the normal of a quad, the cross product
/// of its diagonals, against the unit normals `normal` of the input faces its corners lie in).
/// Returns what is wrong, or an empty string.
inline std::string quad_extraction_problem(const Quad_extraction& q, const std::vector<int>& cone_index, long chi,
                                           const std::vector<Eigen::Vector3d>& normal,
                                           std::size_t boundary_loops = 0)
{
  if(q.open_ends != 0)
    return std::to_string(q.open_ends) + " line ends are not at a cone" + (boundary_loops != 0 ? " or a boundary" : "");
  if(q.closed_lines_without_crossing != 0)
    return std::to_string(q.closed_lines_without_crossing) + " closed lines (or boundary loops) meet no other line";
  if(q.broken_holes != 0)
    return std::to_string(q.broken_holes) + " polygons run partly outside the boundary";
  if(q.holes != boundary_loops)
    return "the quads have " + std::to_string(q.holes) + " holes, the input " + std::to_string(boundary_loops) +
           " boundary loops";
  if(q.non_quads != 0)
    return std::to_string(q.non_quads) + " of " + std::to_string(q.faces.size()) + " faces are not quads";
  std::map<std::pair<std::size_t, std::size_t>, int> edge_faces;
  std::vector<int> valence(q.points.size(), 0);
  for(const auto& face : q.faces)
    for(std::size_t i = 0; i < face.size(); ++i)
    {
      const std::size_t a = face[i], b = face[(i + 1) % face.size()];
      ++edge_faces[{(std::min)(a, b), (std::max)(a, b)}];
      ++valence[a];
    }
  for(const auto& [edge, count] : edge_faces)
    if(count != 2 && !(count == 1 && q.on_boundary[edge.first] && q.on_boundary[edge.second]))
      return "the edge between vertices " + std::to_string(edge.first) + " and " + std::to_string(edge.second) +
             " has " + std::to_string(count) + " quads";
  if(!CGAL::Polygon_mesh_processing::is_polygon_soup_a_polygon_mesh(q.faces))
    return "the quads do not form a manifold, consistently oriented mesh";
  const long euler = long(q.points.size()) - long(edge_faces.size()) + long(q.faces.size());
  if(euler != chi)
    return "Euler characteristic " + std::to_string(euler) + ", the input's " + std::to_string(chi);
  // (valence: the quads around a vertex, as many as its edges inside, one fewer on a boundary)
  std::vector<int> expected(q.points.size(), 4);
  for(std::size_t i = 0; i < cone_index.size(); ++i)
    expected[q.cone_vertex[i]] = 4 - cone_index[i];
  for(std::size_t v = 0; v < q.points.size(); ++v)
    if(q.on_boundary[v])
      expected[v] = 2;
  for(const auto& [v, quads] : q.corner_vertex)
    expected[v] = quads;
  for(std::size_t v = 0; v < q.points.size(); ++v)
    if(valence[v] != expected[v])
      return "vertex " + std::to_string(v) + (q.on_boundary[v] ? " on the boundary is in " : " is in ") +
             std::to_string(valence[v]) + " quads where " + std::to_string(expected[v]) + " are due";
  std::size_t flipped = 0;
  for(const auto& face : q.faces)
  {
    const Eigen::Vector3d n = (q.points[face[2]] - q.points[face[0]]).cross(q.points[face[3]] - q.points[face[1]]);
    double agreement = 0.;
    for(std::size_t v : face)
      agreement += n.dot(normal[q.point_face[v]]);
    flipped += agreement < 0. ? 1 : 0;
  }
  if(flipped != 0)
    return std::to_string(flipped) + " quads face against the surface";
  return "";
}

} // namespace internal
} // namespace Surface_design
} // namespace CGAL

#endif // CGAL_SURFACE_DESIGN_INTERNAL_FIELD_ALIGNED_PARAMETERIZATION_QUAD_EXTRACTION_H
