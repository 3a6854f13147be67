// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A quad mesh from the level-0 lines of the two stripe families of a cross field: the crossings
// of the lines are its vertices, the pieces of lines between crossings its edges, and its faces
// are traced from the order of the pieces around each vertex on the surface.

#ifndef CGAL_SURFACE_DESIGN_INTERNAL_FIELD_ALIGNED_PARAMETERIZATION_QUAD_EXTRACTION_H
#define CGAL_SURFACE_DESIGN_INTERNAL_FIELD_ALIGNED_PARAMETERIZATION_QUAD_EXTRACTION_H

#include <CGAL/Surface_design/internal/Core/geometry.h>
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
  std::size_t non_quads = 0;                           ///< faces with other than four sides
  std::size_t open_ends = 0;                           ///< lines ending elsewhere than at a cone
  std::size_t closed_lines_without_crossing = 0;       ///< closed lines that cross no other line
};

/// One cone of the field: its branch face and the branch point (where its lines end).
struct Quad_extraction_cone
{
  std::size_t face;
  Eigen::Vector3d point;
};

/// The quad layout of the lines of level `level` (0 or pi, both families; the other lines are
/// ignored): level 0 where the cones are on the lattice; without cones either level works, and pi
/// avoids the mesh vertex where the stripe angle is pinned to 0. `normal` gives each input face's unit normal (the orientation of the surface),
/// `cones` the branch points where lines end (within `tolerance` of the point).
///
/// Vertices: every crossing of two pieces of line inside one input face (pieces are half-open at
/// their ends, so that a crossing on an input edge is counted once), and every cone. Edges: the
/// pieces of line between consecutive vertices along a line. Around each vertex the edges leaving
/// it are sorted counterclockwise in its face's tangent plane; the face to the left of an edge
/// a -> b continues with the edge leaving b just before b -> a in that order.
inline Quad_extraction extract_quads(const std::vector<Stripe_isoline_polyline>& all_lines,
                                     const std::vector<Eigen::Vector3d>& normal,
                                     const std::vector<Quad_extraction_cone>& cones, double tolerance,
                                     double level = 0.)
{
  std::vector<const Stripe_isoline_polyline*> lines;
  for(const auto& line : all_lines)
    if(std::abs(line.level - level) < 1e-9 && line.points.size() >= 2)
      lines.push_back(&line);
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
        const Eigen::Vector3d& p0 = lines[l1]->points[s1];
        const Eigen::Vector3d& q0 = lines[l2]->points[s2];
        const Eigen::Vector2d p = flat(p0), r = flat(piece_end(l1, s1)) - p;
        const Eigen::Vector2d q = flat(q0), t = flat(piece_end(l2, s2)) - q;
        const double den = r.x() * t.y() - r.y() * t.x();
        if(den == 0.)
          continue; // parallel pieces do not cross (overlapping ones are not lines of a map)
        const Eigen::Vector2d w = q - p;
        const double a = (w.x() * t.y() - w.y() * t.x()) / den, b = (w.x() * r.y() - w.y() * r.x()) / den;
        if(!(a >= 0. && a < 1. && b >= 0. && b < 1.))
          continue;
        const Eigen::Vector3d x = p0 + a * (piece_end(l1, s1) - p0);
        if(cone_in_face[f] && (x - *cone_in_face[f]).norm() < tolerance)
          continue;
        const std::size_t v = add_point(x, f);
        on_line[l1].emplace_back(double(s1) + a, v);
        on_line[l2].emplace_back(double(s2) + b, v);
      }
  }
  // cones: the points of lines at their branch points (line ends, or points a line runs through)
  std::vector<bool> end_used(2 * lines.size(), false);
  for(const auto& cone : cones)
  {
    const std::size_t v = add_point(cone.point, cone.face);
    out.cone_vertex.push_back(v);
    for(std::size_t l = 0; l < lines.size(); ++l)
    {
      const auto& line = *lines[l];
      for(std::size_t i = 0; i < line.points.size(); ++i)
        if((line.points[i] - cone.point).norm() < tolerance)
        {
          on_line[l].emplace_back(double(i), v);
          if(!line.closed && i == 0)
            end_used[2 * l] = true;
          if(!line.closed && i + 1 == line.points.size())
            end_used[2 * l + 1] = true;
        }
    }
  }
  for(std::size_t l = 0; l < lines.size(); ++l)
    if(!lines[l]->closed)
      out.open_ends += (end_used[2 * l] ? 0 : 1) + (end_used[2 * l + 1] ? 0 : 1);

  // half-edges: from vertex a along line l to the next vertex b; the direction at a (into the
  // line's piece) and the direction at b (back along the piece it arrives on)
  struct Half
  {
    std::size_t from, to;
    Eigen::Vector3d direction; // leaving `from`
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
      half.push_back({a, b, piece_direction(l, pa, true)});
      half.push_back({b, a, piece_direction(l, pb, false)});
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
    std::size_t h = h0;
    while(!done[h])
    {
      done[h] = true;
      polygon.push_back(half[h].from);
      h = next(h);
    }
    if(h != h0)
      polygon.clear(); // not a cycle through h0: cannot happen with a rotation at every vertex
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

/// Checks that the extraction is a closed pure quad mesh with Euler characteristic `chi` whose
/// vertex at cone i has valence 4 - cone_index[i] and every other vertex valence 4, and whose
/// quads face the way of the input (the normal of a quad, the cross product of its diagonals,
/// against the unit normals `normal` of the input faces its corners lie in). Returns what is wrong,
/// or an empty string.
inline std::string quad_extraction_problem(const Quad_extraction& q, const std::vector<int>& cone_index, long chi,
                                           const std::vector<Eigen::Vector3d>& normal)
{
  if(q.open_ends != 0)
    return std::to_string(q.open_ends) + " line ends are not at a cone";
  if(q.closed_lines_without_crossing != 0)
    return std::to_string(q.closed_lines_without_crossing) + " closed lines cross no other line";
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
    if(count != 2)
      return "the edge between vertices " + std::to_string(edge.first) + " and " + std::to_string(edge.second) +
             " has " + std::to_string(count) + " quads";
  if(!CGAL::Polygon_mesh_processing::is_polygon_soup_a_polygon_mesh(q.faces))
    return "the quads do not form a manifold, consistently oriented mesh";
  const long euler = long(q.points.size()) - long(edge_faces.size()) + long(q.faces.size());
  if(euler != chi)
    return "Euler characteristic " + std::to_string(euler) + ", the input's " + std::to_string(chi);
  std::vector<int> expected(q.points.size(), 4);
  for(std::size_t i = 0; i < cone_index.size(); ++i)
    expected[q.cone_vertex[i]] = 4 - cone_index[i];
  for(std::size_t v = 0; v < q.points.size(); ++v)
    if(valence[v] != expected[v])
      return "vertex " + std::to_string(v) + " has valence " + std::to_string(valence[v]) + " where " +
             std::to_string(expected[v]) + " is due";
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
