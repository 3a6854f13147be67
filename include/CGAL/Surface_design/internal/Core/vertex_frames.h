// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Angle-rescaled vertex tangent frames (Knöppel et al. 2013, sec. 5; Noma & Kawahara, sec. 4.1):
// around every vertex the corner angles are scaled so that the star becomes flat, and a tangent
// direction is an angle measured counter-clockwise from a reference outgoing edge.

#ifndef CGAL_SURFACE_DESIGN_INTERNAL_CORE_VERTEX_FRAMES_H
#define CGAL_SURFACE_DESIGN_INTERNAL_CORE_VERTEX_FRAMES_H

#include <CGAL/Surface_design/exceptions.h>
#include <CGAL/Surface_design/internal/Core/geometry.h>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

namespace CGAL {
namespace Surface_design {
namespace internal {

/// The frames of all vertices. Interior vertex v: s_v = 2 pi / (angle sum at v); boundary vertex:
/// s_v = 1 (a boundary star keeps its angles, so that a planar mesh keeps its flat geometry and
/// the turning of the boundary stays where it is). Outgoing
/// halfedges of v are visited counter-clockwise from a reference one (for a boundary vertex: the
/// outgoing halfedge along the boundary, whose opposite is a border halfedge); the rescaled angle
/// of each is s_v times the sum of the corner angles swept from the reference. At a boundary vertex
/// the exterior gap takes what remains of 2 pi.
///
/// A 3D vector is converted to an angle by projecting it onto the tangent plane (angle-weighted
/// vertex normal), measuring its polar angle psi from the projected reference edge and
/// interpolating linearly between the polar angles of the two projected edges around it; the
/// conversion back is the inverse of that piecewise-linear map. Both are exact inverses because
/// the breakpoints psi strictly increase around every star: where the projected star folds (a
/// corner projects with reversed orientation, common next to skinny or obtuse triangles on scanned
/// meshes), vertex_frames() replaces its polar angles by monotone ones (make_star_monotone()).
struct Vertex_frames
{
  std::vector<double> scale;           ///< s_v
  std::vector<double> angle;           ///< per halfedge h: rescaled angle of h at source(h), in [0, 2 pi)
  std::vector<Eigen::Vector3d> normal; ///< angle-weighted unit vertex normals
  std::vector<Eigen::Vector3d> e0, e1; ///< tangent basis: e0 = projected reference edge, e1 = n x e0
  std::vector<bool> border;            ///< boundary vertex
  // the stars in compressed rows: polar angles psi and rescaled angles phi of the outgoing
  // halfedges, counter-clockwise, followed by the sentinel (2 pi, 2 pi)
  std::vector<std::size_t> star_begin;
  std::vector<double> star_psi, star_phi;

  /// Rescaled angle in [0, 2 pi) of the tangent direction of `x` at vertex `v` (x != 0 after
  /// projection; returns 0 otherwise).
  double to_angle(std::size_t v, const Eigen::Vector3d& x) const
  {
    const double px = x.dot(e0[v]), py = x.dot(e1[v]);
    if(px == 0. && py == 0.)
      return 0.;
    double psi = std::atan2(py, px);
    if(psi < 0.)
      psi += two_pi;
    const std::size_t b = star_begin[v], e = star_begin[v + 1] - 1; // e: the sentinel
    for(std::size_t k = b; k < e; ++k)
      if(star_psi[k + 1] > star_psi[k] && psi >= star_psi[k] && psi <= star_psi[k + 1])
        return wrap_angle(star_phi[k] + (psi - star_psi[k]) / (star_psi[k + 1] - star_psi[k]) *
                                    (star_phi[k + 1] - star_phi[k]), 0.);
    // not reached (the breakpoints increase from 0 to the sentinel 2 pi); kept as a safe fallback:
    // the nearest edge
    double best = two_pi, theta = 0.;
    for(std::size_t k = b; k < e; ++k)
    {
      double d = std::abs(psi - star_psi[k]);
      d = (std::min)(d, two_pi - d);
      if(d < best)
      {
        best = d;
        theta = star_phi[k];
      }
    }
    return theta;
  }

  /// Unit tangent vector at vertex `v` of rescaled angle `a` (any real; taken modulo 2 pi).
  Eigen::Vector3d to_vector(std::size_t v, double a) const
  {
    a = wrap_angle(a, 0.);
    const std::size_t b = star_begin[v], e = star_begin[v + 1] - 1;
    std::size_t k = b;
    while(k + 1 < e && star_phi[k + 1] <= a)
      ++k;
    const double span = star_phi[k + 1] - star_phi[k];
    const double t = span > 0. ? (a - star_phi[k]) / span : 0.;
    const double psi = star_psi[k] + t * (star_psi[k + 1] - star_psi[k]);
    return std::cos(psi) * e0[v] + std::sin(psi) * e1[v];
  }

};

/// Stars whose polar-angle sectors are all at least this fraction of their rescaled sectors keep
/// their geometric polar angles; the others (folded, or compressed so much that the conversion
/// would amplify rounding more than 1000-fold) get monotone ones. Unfolded stars of the shared
/// test meshes are all above 0.01 (the smallest: 0.0127, triceratops), so only folded ones change.
constexpr double min_star_sector_ratio = 1e-3;

/// Makes the polar angles psi[0..m) of one star strictly increasing (psi[0] = 0 is the reference
/// edge, psi[m - 1] = 2 pi the sentinel; phi the rescaled angles, strictly increasing, same layout),
/// so that the psi <-> phi map of the star is a bijection: to_vector() must not send two
/// rescaled angles to one 3D direction, or to_angle() reads back another angle than was written
/// and a field written as vectors gets different singularities (pairs of opposite index in the
/// faces around the vertex). Stars with every sector psi[k+1] - psi[k] >= min_ratio (phi[k+1] - phi[k])
/// are left untouched (bit for bit). Otherwise psi becomes the blend (1 - t) u + t phi, where u are
/// the polar angles unwrapped along the star (each step the signed projected angle between
/// consecutive edges, wrap(psi[k+1] - psi[k]); the last one closes on 2 pi), and t in (0, 1] is
/// the smallest value that gives every sector at least min_ratio times its rescaled sector: each
/// sector is linear in t and equals the rescaled one (> 0) at t = 1. The result stays as close to
/// the projected geometry as the fold allows, only at that vertex.
inline void make_star_monotone(double* psi, const double* phi, std::size_t m, double min_ratio)
{
  bool monotone = true;
  for(std::size_t k = 0; k + 1 < m; ++k)
    monotone = monotone && psi[k + 1] - psi[k] >= min_ratio * (phi[k + 1] - phi[k]);
  if(monotone)
    return;
  std::vector<double> u(m);
  u[0] = 0.;
  for(std::size_t k = 1; k + 1 < m; ++k)
    u[k] = u[k - 1] + wrap_angle(psi[k] - psi[k - 1]);
  u[m - 1] = two_pi;
  double t = 0.;
  for(std::size_t k = 0; k + 1 < m; ++k)
  {
    const double du = u[k + 1] - u[k], dphi = phi[k + 1] - phi[k];
    if(dphi > 0. && du < min_ratio * dphi) // (dphi <= 0: the gap of a boundary star whose angle sum is 2 pi or more)
      t = (std::max)(t, (min_ratio * dphi - du) / (dphi - du)); // in (0, 1]: dphi > 0, min_ratio < 1
  }
  for(std::size_t k = 1; k + 1 < m; ++k)
    psi[k] = (1. - t) * u[k] + t * phi[k];
}

/// Computes the frames (see Vertex_frames). `corner` are the corner angles (corner_angles()).
/// The stars are independent: with TBB they are computed by concurrent tasks, each star by the same
/// sequence of operations as alone (the same bits with any number of threads).
template <class Indices, class VertexPointMap>
Vertex_frames vertex_frames(const Indices& idx, const VertexPointMap& vpm,
                            const std::vector<double>& corner)
{
  const auto& tm = idx.mesh();
  const std::size_t nv = idx.number_of_vertices();
  const std::vector<Eigen::Vector3d> x = vertex_positions(idx, vpm);
  Vertex_frames fr;
  fr.scale.assign(nv, 1.);
  fr.angle.assign(idx.number_of_halfedges(), 0.);
  fr.normal = vertex_normals(idx, vpm, corner);
  fr.e0.assign(nv, Eigen::Vector3d::Zero());
  fr.e1.assign(nv, Eigen::Vector3d::Zero());
  std::vector<char> border_of(nv, 0); // (std::vector<bool> packs bits: not safe to write concurrently)
  // star v: its outgoing halfedges, then the sentinel 2 pi
  fr.star_begin.assign(nv + 1, 0);
  for(std::size_t h = 0; h < idx.number_of_halfedges(); ++h)
    ++fr.star_begin[idx.source_index(idx.halfedge(h)) + 1];
  for(std::size_t v = 0; v < nv; ++v)
    fr.star_begin[v + 1] += fr.star_begin[v] + 1;
  fr.star_psi.assign(fr.star_begin[nv], 0.);
  fr.star_phi.assign(fr.star_begin[nv], 0.);

  constexpr std::size_t block = 256;
  for_each_index((nv + block - 1) / block, worth_parallel(nv), [&](std::size_t b) {
    std::vector<std::size_t> out;
    std::vector<double> wedge; // corner angle between out[k] and out[k+1]; -1 for the boundary gap
    for(std::size_t v = b * block; v < (std::min)(nv, (b + 1) * block); ++v)
    {
      const auto vd = idx.vertex(v);
      auto start = opposite(halfedge(vd, tm), tm); // an outgoing halfedge
      for(auto h : halfedges_around_source(vd, tm))
        if(idx.is_border(opposite(h, tm)))
          start = h;
      out.clear();
      wedge.clear();
      auto h = start;
      do
      {
        out.push_back(idx.index(h));
        wedge.push_back(idx.is_border(h) ? -1. : corner[idx.index(prev(h, tm))]);
        h = opposite(prev(h, tm), tm);
      } while(h != start);

      const bool border = wedge.back() < 0.;
      double angle_sum = 0.;
      for(double w : wedge)
        angle_sum += (std::max)(w, 0.);
      const double s = border ? 1. : two_pi / angle_sum;
      fr.scale[v] = s;
      border_of[v] = border;

      const Eigen::Vector3d n = fr.normal[v];
      const Eigen::Vector3d& p = x[v];
      auto planar = [&](const Eigen::Vector3d& d) { return Eigen::Vector3d(d - d.dot(n) * n); };
      auto head = [&](std::size_t k) { return x[idx.target_index(idx.halfedge(out[k]))]; };
      const Eigen::Vector3d e0 = planar(head(0) - p).normalized();
      const Eigen::Vector3d e1 = n.cross(e0);
      fr.e0[v] = e0;
      fr.e1[v] = e1;
      double phi = 0.;
      const std::size_t first = fr.star_begin[v];
      for(std::size_t k = 0; k < out.size(); ++k)
      {
        const Eigen::Vector3d d = planar(head(k) - p);
        double psi = k == 0 ? 0. : std::atan2(d.dot(e1), d.dot(e0));
        if(psi < 0.)
          psi += two_pi;
        fr.angle[out[k]] = phi;
        fr.star_psi[first + k] = psi;
        fr.star_phi[first + k] = phi;
        phi += s * (std::max)(wedge[k], 0.);
      }
      fr.star_psi[first + out.size()] = two_pi;
      fr.star_phi[first + out.size()] = two_pi;
      make_star_monotone(fr.star_psi.data() + first, fr.star_phi.data() + first, out.size() + 1,
                         min_star_sector_ratio);
    }
  });
  fr.border.assign(border_of.begin(), border_of.end());
  return fr;
}

/// The rescaled angle, per vertex, of the tangential part of `field`'s vector there.
/// \throws Invalid_parameter (`field`) if a vector is not finite or has no tangential component
template <class Indices, class VertexVectorMap>
std::vector<double> field_angles(const Indices& idx, const Vertex_frames& frames, const VertexVectorMap& field)
{
  std::vector<double> angle(idx.number_of_vertices());
  for(std::size_t v = 0; v < angle.size(); ++v)
  {
    const auto& x = get(field, idx.vertex(v));
    const Eigen::Vector3d xv(CGAL::to_double(x.x()), CGAL::to_double(x.y()), CGAL::to_double(x.z()));
    const Eigen::Vector3d t = xv - xv.dot(frames.normal[v]) * frames.normal[v];
    if(!(t.norm() > 1e-12 * xv.norm()) || !t.allFinite())
      throw Invalid_parameter("field", "the field vector at vertex " + std::to_string(v) +
                                (t.allFinite() ? " has no tangential component" : " is not finite") +
                                ": the direction, and the index of the faces around it, are undefined");
    angle[v] = frames.to_angle(v, t);
  }
  return angle;
}

} // namespace internal
} // namespace Surface_design
} // namespace CGAL

#endif // CGAL_SURFACE_DESIGN_INTERNAL_CORE_VERTEX_FRAMES_H
