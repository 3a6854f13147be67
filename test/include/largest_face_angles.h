// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Tests' own reading of the triangles' largest angles, from the points (an oracle independent of
// the library's corner angles).

#ifndef CGAL_SURFACE_DESIGN_TEST_LARGEST_FACE_ANGLES_H
#define CGAL_SURFACE_DESIGN_TEST_LARGEST_FACE_ANGLES_H

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/properties.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace test {

/// The largest angle (radians) of every triangle, in the order of `idx` (the library's index maps).
template <class Mesh, class Indices>
std::vector<double> largest_face_angles(const Mesh& mesh, const Indices& idx)
{
  std::vector<double> largest(idx.number_of_faces(), 0.);
  for(std::size_t f = 0; f < largest.size(); ++f)
  {
    std::vector<Eigen::Vector3d> x;
    for(auto v : vertices_around_face(halfedge(idx.face(f), mesh), mesh))
    {
      const auto p = get(CGAL::vertex_point, mesh, v);
      x.emplace_back(p.x(), p.y(), p.z());
    }
    for(std::size_t k = 0; k < 3; ++k)
    {
      const Eigen::Vector3d a = x[(k + 1) % 3] - x[k], b = x[(k + 2) % 3] - x[k];
      largest[f] = (std::max)(largest[f], std::atan2(a.cross(b).norm(), a.dot(b)));
    }
  }
  return largest;
}

} // namespace test

#endif // CGAL_SURFACE_DESIGN_TEST_LARGEST_FACE_ANGLES_H
