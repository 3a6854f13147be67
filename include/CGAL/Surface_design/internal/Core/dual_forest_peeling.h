// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The peeling of a dual spanning forest (Branched_one_form_solver): the faces off the forest's
// roots, leaves first, each with the edge to its parent and the two others of its triangle, so
// that a one-form given off the forest gets every such face's twisted curl by setting the parent
// edges one after the other.

#ifndef CGAL_SURFACE_DESIGN_INTERNAL_CORE_DUAL_FOREST_PEELING_H
#define CGAL_SURFACE_DESIGN_INTERNAL_CORE_DUAL_FOREST_PEELING_H

#include <CGAL/Surface_design/internal/Core/angles.h>
#include <CGAL/Surface_design/internal/Core/Mesh_indices.h>

#include <Eigen/Core>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace Surface_design {
namespace internal {

class Dual_forest_peeling
{
public:
  using Value = Eigen::Vector2d;
  using Face_index = Eigen::Vector2i;

  Dual_forest_peeling() = default;

  /// `order`: the forest's nodes (faces, then possibly other nodes that are roots), each after
  /// its parent; `parent_edge_of`: per node, the edge to its parent (npos at a root). The curl of
  /// face f is sum_h M_h y_h around it (y_e along the edge, -P_e^T y_e against it), M_h the
  /// product of the transitions `transition_along(h)` before h (h a halfedge index).
  template <class TriangleMesh, class Transition>
  Dual_forest_peeling(const Mesh_indices<TriangleMesh>& idx, const std::vector<Eigen::Matrix2d>& P,
                      const std::vector<std::size_t>& order, const std::vector<std::size_t>& parent_edge_of,
                      const Transition& transition_along)
  {
    const auto& tm = idx.mesh();
    m_steps.reserve(order.size());      // one per node but the roots,
    m_others.reserve(2 * order.size()); // with the two other edges of its triangle
    for(auto it = order.rbegin(); it != order.rend(); ++it)
    {
      const std::size_t f = *it;
      if(parent_edge_of[f] == npos)
        continue; // a root
      Step step{std::uint32_t(f), 0, std::uint32_t(m_others.size()), 0, Sign_matrix::Zero()};
      Eigen::Matrix2d M = Eigen::Matrix2d::Identity();
      for(auto h : halfedges_around_face(halfedge(idx.face(f), tm), tm))
      {
        const std::size_t hi = idx.index(h), e = idx.edge_index(h);
        // the contribution of y_e to the curl: M y_e along the edge, -M P_e^T y_e against it
        const Eigen::Matrix2d C = idx.orientation_sign(h) > 0 ? M : Eigen::Matrix2d(-M * P[e].transpose());
        if(e == parent_edge_of[f])
        {
          step.parent = std::uint32_t(e);
          step.parent_inverse = C.transpose().cast<std::int8_t>(); // C is a signed permutation
        }
        else
          m_others.push_back({std::uint32_t(e), C.cast<std::int8_t>()});
        M = M * transition_along(hi);
      }
      step.others_end = std::uint32_t(m_others.size());
      m_steps.push_back(step);
    }
  }

  /// y with its forest edges set so that every peeled face f gets the curl 2 pi k_f (0 when `k`
  /// is null); the second values stay 0 when `d` is 1.
  std::vector<Value> peel(std::vector<Value> y, const std::vector<Face_index>* k, int d) const
  {
    for(const Step& step : m_steps)
    {
      Value target = Value::Zero();
      if(k)
        target = two_pi * (*k)[step.face].template cast<double>();
      for(std::size_t i = step.others_begin; i < step.others_end; ++i)
        target -= m_others[i].coefficient.template cast<double>() * y[m_others[i].edge];
      y[step.parent] = step.parent_inverse.template cast<double>() * target;
      if(d == 1)
        y[step.parent][1] = 0.;
    }
    return y;
  }

private:
  using Sign_matrix = Eigen::Matrix<std::int8_t, 2, 2>; // signed permutations, 32-bit indices
  struct Other
  {
    std::uint32_t edge;
    Sign_matrix coefficient;
  };
  struct Step
  {
    std::uint32_t face, parent, others_begin, others_end;
    Sign_matrix parent_inverse;
  };
  std::vector<Step> m_steps;
  std::vector<Other> m_others;
};

} // namespace internal
} // namespace Surface_design
} // namespace CGAL

#endif // CGAL_SURFACE_DESIGN_INTERNAL_CORE_DUAL_FOREST_PEELING_H
