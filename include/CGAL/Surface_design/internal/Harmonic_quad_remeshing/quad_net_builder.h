// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The net of isolines and gradient lines of a harmonic function, and its faces: its options and
// statistics, the kinds of its points and edges, and `Quad_net_builder`, whose longer methods are
// defined by phase in quad_net_levels.h (the levels of the isolines), quad_net_crossings.h (where
// gradient lines cross the isolines, and their spacing), quad_net_tracing.h (tracing the lines)
// and quad_net_assembly.h (the faces). Include quad_net.h, which includes them all.

#ifndef CGAL_SURFACE_DESIGN_INTERNAL_HARMONIC_QUAD_REMESHING_QUAD_NET_BUILDER_H
#define CGAL_SURFACE_DESIGN_INTERNAL_HARMONIC_QUAD_REMESHING_QUAD_NET_BUILDER_H

#include <CGAL/Surface_design/internal/Harmonic_quad_remeshing/curves.h>
#include <CGAL/Surface_design/internal/Harmonic_quad_remeshing/harmonic_function.h>
#include <CGAL/Surface_design/internal/Harmonic_quad_remeshing/trace_mesh.h>

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <map>
#include <numeric>
#include <optional>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_design {
namespace internal {
namespace harmonic_quad {

/// Spectacles inserted into the mesh, for the net: frames and bridge run along mesh edges, their
/// vertices hold `value`.
struct Net_spectacles
{
  double value = 0.;
  int sigma = 1;                                 ///< +1: frames around lower regions, the bridge a valley
  std::array<std::vector<std::size_t>, 2> frame; ///< vertex loops, higher values on their right
  std::array<std::size_t, 2> junction{{npos, npos}}; ///< where the bridge meets each frame
  std::vector<std::size_t> bridge;               ///< vertex path from junction[0] to junction[1]
};

struct Net_options
{
  double edge_length = 1.;       ///< target spacing h of both families of curves
  double min_spacing = 0.7071;   ///< a gradient line stops where its neighbour is closer than this * h
  double max_spacing = 1.4142;   ///< a gradient line starts in gaps wider than this * h
  bool quad_poles = true;        ///< every other line ends at an extremum: a fan of quads (else triangles)
  std::vector<double> levels;    ///< the levels (else chosen by `regular_levels()`); spectacles values among them
  /// per face of the mesh: the local spacing is edge_length times this (empty: uniform; see
  /// `curvature_spacing_scale()`)
  std::vector<double> spacing_scale;
  std::vector<Net_spectacles> spectacles;
};

struct Net_statistics
{
  std::size_t levels = 0, isolines = 0, gradient_lines = 0, stopped_lines = 0, started_lines = 0;
  std::size_t lost_lines = 0, removed_dangling_edges = 0, extra_boundary_levels = 0, saddle_levels = 0;
  std::size_t reordered_lines = 0, merged_lines = 0, refined_levels = 0, attached_loops = 0;
  std::size_t spectacles_lines = 0; ///< lines from bridges and junctions
  std::size_t boundary_detail_nodes = 0; ///< nodes at the input's boundary vertices where it leaves the chords
};

/// A spacing scale per face for curvature-adapted spacing: h(f) = h / (1 + adaptation h kappa(f)),
/// at least h / 4, with kappa the normal curvature across the face's edges (dihedral angle over
/// the distance between the two face centroids, the largest of the three), smoothed by three
/// area-weighted averages with the neighbours so that a noisy scan does not scatter it.
inline std::vector<double> curvature_spacing_scale(const Trace_mesh& m, double h, double adaptation)
{
  const std::size_t nf = m.number_of_faces();
  std::vector<Eigen::Vector3d> centroid(nf);
  for(std::size_t f = 0; f < nf; ++f)
    centroid[f] = (m.point[m.tri[f][0]] + m.point[m.tri[f][1]] + m.point[m.tri[f][2]]) / 3.;
  std::vector<double> kappa(nf, 0.);
  for(std::size_t f = 0; f < nf; ++f)
    for(std::size_t i = 0; i < 3; ++i)
    {
      const std::size_t g = m.neighbour[f][i];
      if(g == npos)
        continue;
      const double angle = std::atan2(m.normal[f].cross(m.normal[g]).norm(), m.normal[f].dot(m.normal[g]));
      const double d = (centroid[f] - centroid[g]).norm();
      if(d > 0.)
        kappa[f] = (std::max)(kappa[f], angle / d);
    }
  for(int pass = 0; pass < 3; ++pass)
  {
    std::vector<double> next(nf);
    for(std::size_t f = 0; f < nf; ++f)
    {
      double sum = m.area[f] * kappa[f], weight = m.area[f];
      for(std::size_t g : m.neighbour[f])
        if(g != npos)
        {
          sum += m.area[g] * kappa[g];
          weight += m.area[g];
        }
      next[f] = weight > 0. ? sum / weight : kappa[f];
    }
    kappa.swap(next);
  }
  std::vector<double> scale(nf);
  for(std::size_t f = 0; f < nf; ++f)
    scale[f] = (std::max)(0.25, 1. / (1. + adaptation * h * kappa[f]));
  return scale;
}

/// What a point of the net is: a crossing of an isoline and a gradient line, an extremum where
/// lines end (a pole), a point on the boundary, or a node on the bridge of spectacles.
enum class Net_point_kind { crossing, pole, boundary, bridge };

/// What an edge of the net is: a piece of a gradient line, of an isoline, of the boundary, or of
/// the bridge of spectacles.
enum class Net_edge_kind { line, isoline, boundary, bridge };

/// The output polygon mesh as a soup: vertex positions and counter-clockwise faces.
struct Polygon_soup
{
  std::vector<Eigen::Vector3d> points;
  std::vector<std::vector<std::size_t>> faces;
  std::vector<Net_point_kind> kind; ///< per point
};

/// Builds the net of Dong et al.: isolines at levels spaced by h (adaptively: the next level is
/// h times the median gradient norm further), gradient lines traced upwards from isoline to
/// isoline with spacing kept in [min_spacing, max_spacing] * h along every isoline (a line stops
/// or starts there otherwise), lines ending at extrema (poles) and at the boundary; then the faces
/// of the embedded graph by its rotation system.
class Quad_net_builder
{
public:
  Quad_net_builder(const Trace_mesh& m, const std::vector<double>& u, const Net_options& options)
    : m_m(m), m_u(u), m_opt(options), m_levels_in_face(m.number_of_faces())
  {}

  const Net_statistics& statistics() const { return m_stats; }
  const std::vector<Isoline>& isolines() const { return m_iso; }

  Polygon_soup build()
  {
    choose_levels();
    trace_lines();
    return assemble();
  }

private:
  // ---- levels -------------------------------------------------------------------------------
  // The q-quantile of the values of (value, weight) pairs by weight; 0 for no pair.
  static double weighted_quantile(std::vector<std::pair<double, double>>& g, double q);

  double median_gradient_at(double c) const;

  bool is_boundary_edge(std::size_t e) const
  {
    const auto [f, i] = m_m.edge_side[e];
    return m_m.neighbour[f][i] == npos;
  }

  std::size_t loop_of_edge(std::size_t e) const
  {
    const auto [f, i] = m_m.edge_side[e];
    return m_m.boundary_position[m_m.tri[f][i]].first;
  }

  // A loop shorter than h would carry fewer than three crossings, and a path shorter than 2 h from
  // a boundary loop back to it would cut off a sliver next to a small hole: such isolines are
  // left out.
  bool worth_keeping(const Isoline& iso) const
  {
    if(iso.closed)
      return iso.length() >= m_opt.edge_length;
    return iso.length() >= 2. * m_opt.edge_length ||
           loop_of_edge(iso.point_edge.front()) != loop_of_edge(iso.point_edge.back());
  }

  void include(Isoline&& iso)
  {
    const std::size_t id = m_iso.size();
    for(std::size_t k = 0; k < iso.segments(); ++k)
      m_levels_in_face[iso.faces[k]].push_back({iso.value, id, k});
    m_iso.push_back(std::move(iso));
  }

  void add_level(double c)
  {
    for(Isoline& iso : extract_isolines(m_m, m_u, c))
      if(worth_keeping(iso))
        include(std::move(iso));
    ++m_stats.levels;
  }

public:
  /// The levels h apart: from the minimum value up, the next level is h times the median of
  /// |grad u| around the middle of the step further.
  std::vector<double> regular_levels();

private:
  void compute_gradient_norms()
  {
    m_grad_norm.resize(m_m.number_of_faces());
    for(std::size_t f = 0; f < m_m.number_of_faces(); ++f)
      m_grad_norm[f] = m_m.gradient(f, m_u).norm();
  }

  // Frames and bridge as curves of the net at their value, registered in every face around
  // their vertices (a line may reach them at a vertex); frames first, so that a line reaching a
  // junction lands on its frame.
  void include_spectacles(std::size_t k);

  void choose_levels();

  // The connected regions of the faces in `candidates` whose values meet (a, b) (a band between two
  // levels): where a region is wider than 1.6 h across the levels (measured with the 10% quantile
  // of its gradient norm), isolines at intermediate values are added inside that region only,
  // recursively.
  void refine_band(double a, double b, const std::vector<std::size_t>& candidates, const std::vector<double>& sorted,
                   double gap, int depth);

  // Two saddles between the same two levels leave a band that the gradient lines may fail to cut
  // into disks (the cell next to a hole's wall holds its handle): every saddle gets an isoline
  // between it and the next higher saddle value, in the slab of values between them around it,
  // unless an isoline between them crosses that slab already.
  void separate_saddles(const std::vector<double>& sorted, double gap);

  // ---- gradient lines ------------------------------------------------------------------------
  struct Crossing
  {
    double s;                 // arc-length position on its isoline
    Eigen::Vector3d point;
    std::size_t down = npos;    // the node below, when a line arrived from there
    bool up = false;            // a line continues upwards from here
    std::size_t node = npos;    // net node id
    std::vector<std::size_t> pending; // pending codes of the lines that landed here
    bool fixed = false;         // part of spectacles: never stopped, moved or merged away
    bool no_trace = false;      // its upward edge exists already (spectacles)
    bool keep = false;          // reached by a spectacles line: not reordered
  };

  struct Spectacles_curves
  {
    std::array<std::size_t, 2> frame;
    std::size_t bridge;
  };

  // an edge of the net with the directions of its ends in the rotation system, where the
  // generic rule (up, along, down, back) does not apply
  struct Keyed_edge
  {
    std::size_t a, b; // codes (pending allowed)
    Net_edge_kind kind; // a line (a below b) or a bridge
    double key_a, key_b; // NaN: the generic rule
  };

  // a net node: crossing (isoline, index), pole (mesh vertex) or boundary point
  struct Node
  {
    Eigen::Vector3d point;
    Net_point_kind kind;
    std::size_t curve = npos, vertex = npos, loop = npos;
    double loop_position = 0.;
    double s = 0.; // arc-length position on `curve`
  };

  std::size_t node_for_end(const Trace_end& e, std::size_t from_node);

  // crossings get their node ids when their isoline is finalized; until then a line that lands
  // on one refers to it by a pending code
  static constexpr std::size_t pending_bit = std::size_t(1) << (sizeof(std::size_t) * 8 - 1);
  std::size_t resolve(std::size_t id) const
  {
    if(id == npos || !(id & pending_bit))
      return id;
    return m_pending_node[id & ~pending_bit];
  }

  // Fences along an isoline: the continuing crossings (and the boundary ends of a path), with
  // the gaps between consecutive ones.
  struct Fences
  {
    std::vector<double> pos;
    std::vector<std::size_t> who; // crossing index, npos for a boundary end
    double length;
    bool closed;
    std::size_t size() const { return pos.size(); }
    std::size_t gaps() const { return closed ? pos.size() : (pos.empty() ? 0 : pos.size() - 1); }
    double gap(std::size_t k) const
    {
      return k + 1 < pos.size() ? pos[k + 1] - pos[k] : pos[0] + length - pos[k];
    }
  };

  Fences fences(const Isoline& iso, const std::vector<Crossing>& cr) const;

  void add_crossing(std::size_t c, double s);

  void space_crossings(std::size_t c);

  // A line arriving from below next to a spectacles line that landed here from above (a bridge
  // or junction line of spectacles above, which has no line below it) joins it: one line through.
  void merge_into_spectacles_lines(std::size_t c);

  void finalize_crossings(std::size_t c);

  static double wrapped(double d, double length, bool closed)
  {
    if(!closed)
      return d;
    d = std::fmod(d, length);
    if(d > 0.5 * length)
      d -= length;
    else if(d <= -0.5 * length)
      d += length;
    return d;
  }

  // Discrete gradient lines may cross or merge (through vertices, along sink edges), which would
  // make the net non-planar. The lines from one isoline keep their order on the next one: their
  // landing points are given back to them in the order of their sources (the cyclic shift that
  // moves them least); of two lines landing on the same point, one stops.
  void untangle_arrivals(std::size_t c);

  void trace_lines();

  // Where a line traced downwards from spectacles ends: on an isoline below (processed later), a
  // crossing whose upward edge is that line; else a pole or boundary node.
  std::size_t landing_from_above(const Trace_end& e);

  // A line of spectacles from node `from` (a code), started in face f at p, towards the side
  // of sigma, with rotation key `key` at `from`.
  void spectacles_line(std::size_t from, double key, std::size_t f, const Eigen::Vector3d& p, double value, int sigma,
                       const Gradient_walker& walker);

  // The nodes and lines of spectacles k, before any isoline is processed: a junction on each
  // frame (a crossing that is never stopped), bridge nodes about h apart with one line on each
  // side (up from a valley, down from a ridge), and from each junction one line into each of
  // the two sectors between its frame and the bridge (the corner of the level set there is a
  // right angle, which the (u, psi) net opens to a straight one: the line along its bisector
  // keeps the cells there quadrilateral).
  void spectacles_lines(std::size_t k, const Gradient_walker& walker);

  // Where the line into a sector of junction v starts: (face, point) near the sector's bisector,
  // in the face that holds it or else the nearest face of the sector on the side of sigma with a
  // corner off the level (not flat), close to v (before the first level beyond `value`, `step`
  // away); none when no face of the sector is on that side.
  std::optional<std::pair<std::size_t, Eigen::Vector3d>> sector_start(std::size_t v, const Vertex_sector& sector,
                                                                       double value, int sigma, double step) const;

  // the spacing at arc length s of an isoline (on segment j for the second form)
  double local_h_at(const Isoline& iso, double s) const
  {
    return m_opt.spacing_scale.empty() ? m_opt.edge_length : local_h_on_segment(iso, iso.at(s).second);
  }

  double local_h_on_segment(const Isoline& iso, std::size_t j) const
  {
    if(m_opt.spacing_scale.empty() || j >= iso.faces.size() || iso.faces[j] >= m_opt.spacing_scale.size())
      return m_opt.edge_length;
    return m_opt.edge_length * m_opt.spacing_scale[iso.faces[j]];
  }

  static Eigen::Vector3d tangent_of(const Eigen::Vector3d& d, const Eigen::Vector3d& n)
  {
    const Eigen::Vector3d t = d - d.dot(n) * n;
    return t.norm() > 0. ? Eigen::Vector3d(t.normalized()) : t;
  }

  // The node where a traced line ends, or npos if it got lost. On an isoline not processed yet
  // (ascending lines) a pending code, resolved when that isoline is; on one already processed
  // (descending lines) a new crossing there with its node at once.
  std::size_t end_node(const Trace_end& e, std::size_t from);

  // ---- assembly ------------------------------------------------------------------------------
  // A boundary loop that no line reaches and no isoline with lines on it touches (a small hole
  // inside one cell) would leave the cell an annulus: it gets a gradient line upwards from its
  // highest vertex and one downwards from its lowest, which end on the net.
  void attach_floating_loops();

  Polygon_soup assemble();

  // the point at `position` (vertex index + fraction of the next edge) along boundary loop `l`
  Eigen::Vector3d loop_point(std::size_t l, double position) const
  {
    const auto& loop = m_m.boundary_loop[l];
    const std::size_t n = loop.size();
    const double w = std::fmod(position, double(n));
    const std::size_t i = (std::min)(std::size_t(w), n - 1);
    const double f = w - double(i);
    return (1. - f) * m_m.point[loop[i]] + f * m_m.point[loop[(i + 1) % n]];
  }

  // Douglas-Peucker on boundary loop `l` between loop positions `begin` < `end` (`end` may
  // exceed the loop's size: it wraps): the positions (increasing, between them) of the loop's
  // vertices to keep so that the boundary between consecutive kept points stays within h / 4 of
  // their chord; vertices closer than h / 8 to a kept point are not taken. An even number, so
  // that the face along it keeps the parity of its sides: an odd count gets the next farthest
  // vertex, or the middle of the longest piece when no vertex is left.
  std::vector<double> boundary_detail(std::size_t l, double begin, double end) const;

  std::size_t boundary_node(std::size_t mesh_edge, const Eigen::Vector3d& p);

  Eigen::Vector3d vertex_normal(std::size_t v) const
  {
    Eigen::Vector3d n = Eigen::Vector3d::Zero();
    for(const auto& [f, i] : m_m.star[v])
      n += m_m.area[f] * m_m.normal[f];
    return n.norm() > 0. ? n.normalized() : m_m.normal[m_m.star[v].front().first];
  }

  template <class Edges>
  void sort_around(std::size_t p, std::vector<std::size_t>& in, const Edges& edges) const;

  template <class Edges>
  Polygon_soup faces_of(Edges edges);

  Eigen::Vector3d boundary_normal(const Node& n) const
  {
    const auto& loop = m_m.boundary_loop[n.loop];
    const std::size_t a = loop[std::size_t(n.loop_position) % loop.size()];
    return vertex_normal(a);
  }

  Eigen::Vector3d boundary_tangent(const Node& n) const;

  const Trace_mesh& m_m;
  const std::vector<double>& m_u;
  Net_options m_opt;
  std::vector<double> m_grad_norm;
  std::vector<std::vector<Face_level>> m_levels_in_face;
  std::vector<Isoline> m_iso;
  std::vector<std::vector<Crossing>> m_crossings;
  std::vector<std::size_t> m_pending_node; // node of every pending code
  std::vector<std::size_t> m_trace_down;
  std::vector<char> m_processed;
  std::vector<Node> m_nodes;
  std::map<std::size_t, std::size_t> m_pole_node;
  std::vector<Spectacles_curves> m_spectacles_curves;
  std::vector<char> m_on_spectacles;
  std::vector<Keyed_edge> m_keyed_edges;
  std::vector<std::pair<std::size_t, std::size_t>> m_line_edges; // (lower node, upper node), pending codes allowed
  Net_statistics m_stats;
};

} // namespace harmonic_quad
} // namespace internal
} // namespace Surface_design
} // namespace CGAL

#endif // CGAL_SURFACE_DESIGN_INTERNAL_HARMONIC_QUAD_REMESHING_QUAD_NET_BUILDER_H
