// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Stripes on line and cross fields: exact prescribed singularities read back independently,
// continuity across every edge, the cover (Riemann-Hurwitz), branch-point values, analytic cases,
// the vector case unchanged, automatic singularities, factor once, bad input.

#include <test_support.h>

#include <CGAL/Surface_design/Branched_stripe_parameterizer.h>
#include <CGAL/Surface_design/direction_fields.h>
#include <CGAL/Surface_design/Field_aligned_parameterizer.h>
#include <CGAL/Surface_design/mesh_generators.h>
#include <CGAL/Surface_design/Trivial_connection.h>
#include <CGAL/Surface_design/internal/Solvers/integer_quadratic.h>

#include <CGAL/Bbox_3.h>
#include <CGAL/Random.h>
#include <CGAL/boost/graph/helpers.h>

#include <boost/property_map/function_property_map.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <map>
#include <numeric>
#include <set>
#include <sstream>
#include <utility>

namespace SD = CGAL::Surface_design;
namespace SDI = CGAL::Surface_design::internal;

namespace {

using SDI::pi;
using SDI::two_pi;
using test::Vpm;
template <class Mesh, class Solver = SD::Default_solver_traits>
using Bsp = SD::Branched_stripe_parameterizer<Mesh, Vpm<Mesh>, Solver>;
template <class Mesh>
using Vector_of = typename CGAL::Kernel_traits<typename boost::property_traits<Vpm<Mesh>>::value_type>::Kernel::Vector_3;

template <class Mesh>
using Face = typename boost::graph_traits<Mesh>::face_descriptor;
template <class Mesh>
using Vertex = typename boost::graph_traits<Mesh>::vertex_descriptor;

// A tube or an annulus as a polar grid: ring i (of nr + 1) at parameter i / nr, nt segments
// around, the quads split along alternating diagonals. `place(s, theta)` gives the point.
template <class Mesh>
Mesh polar_grid(std::size_t nr, std::size_t nt, const std::function<std::array<double, 3>(double, double)>& place)
{
  test::Soup_points points;
  test::Soup_triangles triangles;
  for(std::size_t i = 0; i <= nr; ++i)
    for(std::size_t j = 0; j < nt; ++j)
      points.push_back(place(double(i) / double(nr), two_pi * double(j) / double(nt)));
  auto id = [nt](std::size_t i, std::size_t j) { return i * nt + j % nt; };
  for(std::size_t i = 0; i < nr; ++i)
    for(std::size_t j = 0; j < nt; ++j)
      if((i + j) % 2 == 0)
      {
        triangles.push_back({id(i, j), id(i, j + 1), id(i + 1, j + 1)});
        triangles.push_back({id(i, j), id(i + 1, j + 1), id(i + 1, j)});
      }
      else
      {
        triangles.push_back({id(i, j), id(i, j + 1), id(i + 1, j)});
        triangles.push_back({id(i, j + 1), id(i + 1, j + 1), id(i + 1, j)});
      }
  return test::from_soup<Mesh>(points, triangles);
}

template <class Mesh>
Mesh make_case(const std::string& name)
{
  Mesh mesh;
  if(name == "torus")
    SD::make_torus(mesh, 36, 12, 1., 0.35, true);
  else if(name == "sphere")
    SD::make_sphere(mesh, 8);
  else if(name == "band") // 800 faces of a sphere between two circles: two boundary loops
    mesh = polar_grid<Mesh>(10, 40, [](double s, double t) {
      const double r = 0.05 + 0.95 * s, z = std::sqrt(1. - 0.9 * r * r);
      return std::array<double, 3>{r * std::cos(t), r * std::sin(t), z};
    });
  else
    mesh = test::load_mesh<Mesh>(name);
  return mesh;
}

template <class Mesh>
double diagonal(const Mesh& mesh)
{
  CGAL::Bbox_3 box;
  for(auto v : vertices(mesh))
    box += get(CGAL::vertex_point, mesh, v).bbox();
  return std::sqrt(CGAL::square(box.xmax() - box.xmin()) + CGAL::square(box.ymax() - box.ymin()) +
                   CGAL::square(box.zmax() - box.zmin()));
}

template <class Mesh>
std::vector<Vector_of<Mesh>> smoothest(const Mesh& mesh, int n)
{
  const SDI::Mesh_indices<Mesh> idx(mesh);
  std::vector<Vector_of<Mesh>> by_index(num_vertices(mesh));
  std::map<Vertex<Mesh>, Vector_of<Mesh>> map;
  SD::smoothest_direction_field(mesh, boost::make_assoc_property_map(map), SD::parameters::symmetry_order(n));
  for(std::size_t v = 0; v < idx.number_of_vertices(); ++v)
    by_index[v] = map.at(idx.vertex(v));
  return by_index;
}

// The field as a vertex -> vector map over the mesh's own vertex descriptors.
template <class Mesh>
auto field_map(const Mesh& mesh, const std::vector<Vector_of<Mesh>>& by_index)
{
  auto idx = std::make_shared<SDI::Mesh_indices<Mesh>>(mesh);
  return boost::make_function_property_map<Vertex<Mesh>>(
    [idx, &by_index](Vertex<Mesh> v) { return by_index[idx->index(v)]; });
}

// The stripe energy at y + d_P delta and y - d_P delta (delta per vertex): equal to first order
// exactly when y is optimal over the values that delta moves.
template <class Solver, class Indices>
std::pair<double, double> energies_along(const Solver& solver, const Indices& idx, const std::vector<Eigen::Vector2d>& y,
                                         const std::vector<Eigen::Vector2d>& omega,
                                         const std::vector<Eigen::Vector2d>& delta)
{
  std::vector<Eigen::Vector2d> plus = y, minus = y;
  for(std::size_t e = 0; e < y.size(); ++e)
  {
    const auto ij = idx.edge_vertices(e);
    const Eigen::Vector2d z = solver.transition(e) * delta[ij.second] - delta[ij.first];
    plus[e] += z;
    minus[e] -= z;
  }
  return {solver.energy(plus, omega), solver.energy(minus, omega)};
}

// --- the independent readings of a pattern, from `value(f, b, family)` alone

using Value_function = std::function<double(std::size_t face, const std::array<double, 3>& b, int family)>;

// The barycentric coordinates, in the corner order source(h), target(h), target(next(h)) of
// h = halfedge(f), of the point at parameter t from vertex a to vertex b of f.
template <class Mesh>
std::array<double, 3> on_edge(const Mesh& mesh, Face<Mesh> f, Vertex<Mesh> a, Vertex<Mesh> b, double t)
{
  const auto h = halfedge(f, mesh);
  const Vertex<Mesh> corner[3] = {source(h, mesh), target(h, mesh), target(next(h, mesh), mesh)};
  std::array<double, 3> out{0., 0., 0.};
  for(int i = 0; i < 3; ++i)
  {
    if(corner[i] == a)
      out[std::size_t(i)] += 1. - t;
    if(corner[i] == b)
      out[std::size_t(i)] += t;
  }
  return out;
}

// The winding of the pattern around face f: the sum of the wrapped steps of its value along a
// dense walk around the face's boundary, over 2 pi. Returns the winding and the distance of the
// sum to the nearest multiple of 2 pi.
inline std::pair<int, double> winding_around(const Value_function& value, std::size_t f, int family)
{
  const int samples = 24;
  double sum = 0., previous = value(f, {1., 0., 0.}, family);
  for(int edge = 0; edge < 3; ++edge)
    for(int s = 1; s <= samples; ++s)
    {
      std::array<double, 3> b{0., 0., 0.};
      const double t = double(s) / samples;
      b[std::size_t(edge)] = 1. - t;
      b[std::size_t((edge + 1) % 3)] = t;
      const double current = value(f, b, family);
      sum += SDI::wrap_angle(current - previous);
      previous = current;
    }
  const double k = std::round(sum / two_pi);
  return {int(k), std::abs(sum - two_pi * k)};
}

// The largest jump of the pattern across an interior edge: values sampled inside the edge from
// both faces, compared up to the symmetry of the field (sign for a line field, a quarter turn of
// the two families for a cross field) and 2 pi.
template <class Mesh>
double largest_jump(const Mesh& mesh, const SDI::Mesh_indices<Mesh>& idx, const Value_function& value, int families)
{
  double worst = 0.;
  for(auto e : edges(mesh))
  {
    const auto h = halfedge(e, mesh);
    if(is_border_edge(h, mesh))
      continue;
    const Face<Mesh> f = face(h, mesh), g = face(opposite(h, mesh), mesh);
    const std::size_t fi = idx.index(f), gi = idx.index(g);
    const Vertex<Mesh> a = source(h, mesh), b = target(h, mesh);
    std::vector<std::array<double, 2>> from_f, from_g;
    for(int s = 0; s < 5; ++s)
    {
      const double t = 0.1 + 0.2 * s;
      std::array<double, 2> x{0., 0.}, y{0., 0.};
      for(int c = 0; c < families; ++c)
      {
        x[std::size_t(c)] = value(fi, on_edge(mesh, f, a, b, t), c);
        y[std::size_t(c)] = value(gi, on_edge(mesh, g, a, b, t), c);
      }
      from_f.push_back(x);
      from_g.push_back(y);
    }
    // the symmetries: (u, v) -> (u, v), (v, -u), (-u, -v), (-v, u); for one family: u -> +-u
    double best = 1e300;
    for(int r = 0; r < 4; ++r)
    {
      if(families == 1 && r % 2 == 1)
        continue;
      double dev = 0.;
      std::array<double, 2> offset{0., 0.};
      for(std::size_t s = 0; s < from_f.size(); ++s)
      {
        const std::array<double, 2> y = from_g[s];
        std::array<double, 2> q = r == 0 ? y : r == 1 ? std::array<double, 2>{y[1], -y[0]}
                                             : r == 2 ? std::array<double, 2>{-y[0], -y[1]}
                                                      : std::array<double, 2>{-y[1], y[0]};
        for(int c = 0; c < families; ++c)
        {
          const double d = from_f[s][std::size_t(c)] - q[std::size_t(c)];
          if(s == 0)
            offset[std::size_t(c)] = two_pi * std::round(d / two_pi);
          dev = (std::max)(dev, std::abs(d - offset[std::size_t(c)]));
        }
      }
      best = (std::min)(best, dev);
    }
    worst = (std::max)(worst, best);
  }
  return worst;
}

template <class Parameterizer>
Value_function value_of(const Parameterizer& p)
{
  return [&p](std::size_t f, const std::array<double, 3>& b, int family) {
    return p.value(p.indices().face(f), b, family);
  };
}

// Regular faces with no vertex on the boundary, spread over the mesh, at least `gap` faces apart
// in index order, not next to a branch face.
template <class Parameterizer>
std::vector<std::size_t> free_faces(const Parameterizer& p, std::size_t count)
{
  const auto& idx = p.indices();
  const auto& tm = idx.mesh();
  std::vector<bool> near_branch(idx.number_of_faces(), false);
  for(std::size_t f : p.branch_faces())
    for(auto h : halfedges_around_face(halfedge(idx.face(f), tm), tm))
      for(auto g : faces_around_target(h, tm))
        if(g != boost::graph_traits<typename std::decay_t<decltype(tm)>>::null_face())
          near_branch[idx.index(g)] = true;
  std::vector<std::size_t> out;
  const std::size_t nf = idx.number_of_faces();
  for(std::size_t i = 0; i < nf && out.size() < count; ++i)
  {
    const std::size_t f = (i * 7919 + nf / 3) % nf;
    bool boundary = false;
    for(auto h : halfedges_around_face(halfedge(idx.face(f), tm), tm))
      boundary = boundary || is_border(opposite(h, tm), tm) || is_border(h, tm) ||
                 bool(CGAL::is_border(target(h, tm), tm));
    if(boundary || near_branch[f])
      continue;
    bool spread = true;
    for(std::size_t g : out)
      spread = spread && (g > f ? g - f : f - g) > nf / (2 * count + 2);
    if(spread)
      out.push_back(f);
  }
  return out;
}

// Everything the pattern promises, read independently: the winding around every regular face
// is the prescribed index (0 almost everywhere), the values do not jump across any edge, and the
// branch points sit at the symmetric values.
template <class Parameterizer>
void check_pattern(const Parameterizer& p)
{
  const auto& idx = p.indices();
  const auto& tm = idx.mesh();
  const Value_function value = value_of(p);
  const int families = p.number_of_families();
  std::size_t singular = 0;
  for(std::size_t f = 0; f < idx.number_of_faces(); ++f)
  {
    const auto fd = idx.face(f);
    if(p.is_branch_face(fd))
    {
      const auto c = p.branch_point_value(fd);
      const int quarter = ((p.field_index_numerator(fd) % 4) + 4) % 2; // odd numerator of a cross field
      for(int a = 0; a < families; ++a)
      {
        INFO("branch face " << f << " family " << a << " value " << c[std::size_t(a)]);
        REQUIRE(std::abs(SDI::wrap_angle(2. * c[std::size_t(a)])) < 1e-9); // 0 or pi
      }
      if(families == 2 && quarter == 1) // a quarter turn: (0, 0) or (pi, pi)
        REQUIRE(std::abs(SDI::wrap_angle(c[0] - c[1])) < 1e-9);
      // the segment from the first corner to the branch point is a cut: on its two sides the
      // pattern is on two sheets, so the values there must be one sheet map apart (only the
      // fixed point of the exchange at the branch point makes that hold all along the segment)
      for(double t : {0.25, 0.6})
      {
        const double e = 1e-10; // the values move by about e times the corner values (tens of radians)
        const auto o = p.branch_point(fd);
        const std::array<double, 3> on{1. - t + t * o[0], t * o[1], t * o[2]};
        std::array<double, 2> x{0., 0.}, y{0., 0.};
        for(int a = 0; a < families; ++a)
        {
          x[std::size_t(a)] = value(f, {on[0], on[1] + e, on[2] - e}, a); // the side of corner 1
          y[std::size_t(a)] = value(f, {on[0], on[1] - e, on[2] + e}, a); // the side of corner 2
        }
        double best = 1e300;
        for(int r = 0; r < 4; ++r)
        {
          if(families == 1 && r % 2 == 1)
            continue;
          const std::array<double, 2> q = r == 0 ? y : r == 1 ? std::array<double, 2>{y[1], -y[0]}
                                                     : r == 2 ? std::array<double, 2>{-y[0], -y[1]}
                                                              : std::array<double, 2>{-y[1], y[0]};
          double dev = 0.;
          for(int a = 0; a < families; ++a)
            dev = (std::max)(dev, std::abs(SDI::wrap_angle(x[std::size_t(a)] - q[std::size_t(a)])));
          best = (std::min)(best, dev);
        }
        INFO("branch face " << f << " across its cut at " << t);
        REQUIRE(best < 1e-6);
      }
      continue;
    }
    for(int a = 0; a < families; ++a)
    {
      const auto [k, residual] = winding_around(value, f, a);
      INFO("face " << f << " family " << a);
      REQUIRE(residual < 1e-8);
      REQUIRE(k == p.index(fd, a));
      REQUIRE(k == p.stripe_index(fd, a));
      singular += k != 0 ? 1 : 0;
    }
  }
  std::size_t prescribed = 0;
  for(std::size_t f : p.singular_faces())
    for(int a = 0; a < families; ++a)
      prescribed += p.index(idx.face(f), a) != 0 ? 1 : 0;
  REQUIRE(singular == prescribed);
  REQUIRE(largest_jump(tm, idx, value, families) < 1e-9);
  const auto& solver = p.solver();
  const auto& y = p.one_form();
  const auto& omega = p.target_one_form();
  if(solver.has_spokes())
  {
    // the energy also holds the spokes of the branch faces (W couples their edges): optimality
    // over the continuous part read off the energy alone, which is quadratic: along y +- d_P delta
    // (delta random, 0 where pinned) it changes by 4 <gradient, d_P delta>, which must vanish
    std::uint32_t state = 7;
    for(int trial = 0; trial < 3; ++trial)
    {
      std::vector<Eigen::Vector2d> delta(idx.number_of_vertices(), Eigen::Vector2d::Zero());
      for(std::size_t v = 0; v < delta.size(); ++v)
        for(int a = 0; a < families; ++a)
        {
          state = state * 1664525u + 1013904223u;
          delta[v][a] = solver.is_pinned(v) ? 0. : double(state >> 8) / double(1u << 24) - 0.5;
        }
      const auto [ep, em] = energies_along(solver, idx, y, omega, delta);
      INFO("energy along +- d_P delta: " << ep << " " << em);
      REQUIRE(std::abs(ep - em) <= 1e-9 * (ep + em));
    }
    return;
  }
  // optimality over the continuous part: d_P^T W (y - omega) = 0 at every vertex not pinned,
  // relative to the size of the terms it sums
  std::vector<Eigen::Vector2d> gradient(idx.number_of_vertices(), Eigen::Vector2d::Zero());
  double scale = 0.;
  for(std::size_t e = 0; e < y.size(); ++e)
  {
    const auto ij = idx.edge_vertices(e);
    const Eigen::Vector2d r = solver.weights()[e] * (y[e] - omega[e]);
    gradient[ij.first] -= r;
    gradient[ij.second] += solver.transition(e).transpose() * r;
    scale = (std::max)(scale, std::abs(solver.weights()[e]) * (y[e].norm() + omega[e].norm()));
  }
  double worst = 0.;
  for(std::size_t v = 0; v < gradient.size(); ++v)
    if(!solver.is_pinned(v))
      worst = (std::max)(worst, gradient[v].head(families).cwiseAbs().maxCoeff());
  REQUIRE(worst <= 1e-9 * scale);
}

// The isolines, read independently of how they were built:
// - every piece lies in its face, and in a face where the angle is linear (regular without
//   singularity, or a branch face) its midpoint is at the line's level modulo 2 pi;
// - on every edge the lines cross exactly as often as the angle along the edge (from the one-form
//   and the vertex values, not from the faces) passes a multiple of pi;
// - lines end only on the boundary, at mesh vertices, or in branch and singular faces.
// Returns what is wrong ("" if nothing) and counts the open lines.
template <class Parameterizer, class Lines>
std::string isoline_problem(const Parameterizer& p, const Lines& lines, std::size_t& open)
{
  const auto& idx = p.indices();
  const auto& tm = idx.mesh();
  using Mesh = std::decay_t<decltype(tm)>;
  using P3 = Eigen::Vector3d;
  const auto point = [&](Vertex<Mesh> v) {
    const auto q = get(CGAL::vertex_point, tm, v);
    return P3(q.x(), q.y(), q.z());
  };
  const double scale = diagonal(tm);
  std::vector<std::vector<double>> on_edge_t(idx.number_of_edges());
  const auto singular = [&](Face<Mesh> f) {
    for(int a = 0; a < p.number_of_families(); ++a)
      if(p.stripe_index(f, a) != 0)
        return true;
    return false;
  };
  // barycentric coordinates of x in f (corner order of value()), and the distance to its plane
  const auto barycentric = [&](Face<Mesh> f, const P3& x) {
    const auto h = halfedge(f, tm);
    const P3 a = point(source(h, tm)), b = point(target(h, tm)), c = point(target(next(h, tm), tm));
    Eigen::Matrix<double, 3, 2> A;
    A << b - a, c - a;
    const Eigen::Vector2d l = (A.transpose() * A).ldlt().solve(A.transpose() * (x - a));
    return std::make_pair(std::array<double, 3>{1. - l[0] - l[1], l[0], l[1]}, (A * l + a - x).norm());
  };
  open = 0;
  std::ostringstream problem;
  for(const auto& line : lines)
  {
    const std::size_t np = line.points.size();
    if(np < 2 || line.faces.size() != (line.closed ? np : np - 1) || !(line.level == 0. || line.level == pi))
      return "a line with " + std::to_string(np) + " points, " + std::to_string(line.faces.size()) + " faces";
    for(std::size_t i = 0; i < line.faces.size(); ++i)
    {
      const Face<Mesh> f = line.faces[i];
      const P3 x = P3(line.points[i].x(), line.points[i].y(), line.points[i].z());
      const auto& q = line.points[(i + 1) % np];
      const P3 y(q.x(), q.y(), q.z());
      const auto [b, off] = barycentric(f, 0.5 * (x + y));
      if(off > 1e-9 * scale || *std::min_element(b.begin(), b.end()) < -1e-9)
        problem << "a piece outside its face " << idx.index(f) << "; ";
      if(!singular(f))
      {
        // a line of a cross field changes family where the field's two families are exchanged
        double off_level = 1e300;
        for(int family = 0; family < p.number_of_families(); ++family)
          off_level = (std::min)(off_level, std::abs(SDI::wrap_angle(p.value(f, b, family) - line.level)));
        if(off_level > 1e-7)
          problem << "a piece in face " << idx.index(f) << " off its level by " << off_level << "; ";
      }
      // the ends of the piece on the edges of its face
      for(const P3& z : {x, y})
        for(auto g : halfedges_around_face(halfedge(f, tm), tm))
        {
          const std::size_t e = idx.edge_index(g);
          const auto ends = idx.edge_vertices(e);
          const P3 a = point(idx.vertex(ends.first)), c = point(idx.vertex(ends.second));
          const double t = (z - a).dot(c - a) / (c - a).squaredNorm();
          if(t > 1e-9 && t < 1. - 1e-9 && (a + t * (c - a) - z).norm() < 1e-10 * scale)
            on_edge_t[e].push_back(t);
        }
    }
    if(line.closed)
      continue;
    ++open;
    for(const bool last : {false, true})
    {
      const Face<Mesh> f = last ? line.faces.back() : line.faces.front();
      const auto& q = last ? line.points.back() : line.points.front();
      const P3 z(q.x(), q.y(), q.z());
      bool allowed = p.is_branch_face(f) || singular(f);
      for(auto g : halfedges_around_face(halfedge(f, tm), tm))
      {
        allowed = allowed || (point(target(g, tm)) - z).norm() < 1e-12 * scale;
        if(is_border_edge(g, tm))
        {
          const P3 a = point(source(g, tm)), c = point(target(g, tm));
          const double t = (z - a).dot(c - a) / (c - a).squaredNorm();
          allowed = allowed || (a + t * (c - a) - z).norm() < 1e-10 * scale;
        }
      }
      if(!allowed)
        problem << "an open line ends in the regular face " << idx.index(f) << "; ";
    }
  }
  // the crossings of every edge: the multiples of pi strictly between the angle at its first end
  // and that angle plus the one-form along it, family by family
  for(std::size_t e = 0; e < idx.number_of_edges(); ++e)
  {
    auto& t = on_edge_t[e];
    std::sort(t.begin(), t.end());
    t.erase(std::unique(t.begin(), t.end(), [](double u, double v) { return v - u < 1e-8; }), t.end());
    long expected = 0;
    for(int a = 0; a < p.number_of_families(); ++a)
    {
      // (ends closer than 1e-9 to a multiple of pi are on it: the lines pass through the vertex)
      const double a0 = p.vertex_values()[idx.edge_vertices(e).first][a] / pi;
      const double a1 = a0 + p.one_form()[e][a] / pi;
      const double lo = (std::min)(a0, a1) + 1e-9 / pi, hi = (std::max)(a0, a1) - 1e-9 / pi;
      expected += (std::max)(0L, long(std::ceil(hi) - std::floor(lo)) - 1);
    }
    if(long(t.size()) != expected)
      problem << "edge " << e << " crossed " << t.size() << " times, not " << expected << "; ";
  }
  return problem.str();
}

template <class Parameterizer>
std::size_t check_isolines(const Parameterizer& p)
{
  std::size_t open = 0;
  REQUIRE(isoline_problem(p, p.isolines(), open) == "");
  return open;
}

} // namespace

TEMPLATE_TEST_CASE("Line and cross field stripes: exactly the prescribed singularities, continuous elsewhere",
                   "[branched_stripes]", SD_MESH_TYPES)
{
  // genus 0, 1, 2, a disk, an obtuse scan (under the sanitizers a band of 800 faces with two
  // boundary loops instead of the 4000-face disk: the readings sample every face and edge)
  const char* disk = CGAL_SURFACE_DESIGN_TESTS_UNDER_SANITIZERS ? "band" : "hemisphere.off";
  for(const std::string name : {"sphere", "torus", "eight.off", disk, "bunny_1k.off"})
    for(int n : {2, 4})
    {
      INFO(name << ", n = " << n);
      const TestType mesh = make_case<TestType>(name);
      const test::Mesh_snapshot before(mesh);
      const auto field = smoothest(mesh, n);
      Bsp<TestType> p(mesh, SD::parameters::symmetry_order(n));
      REQUIRE(p.number_of_families() == (n == 4 ? 2 : 1));
      p.set_field(field_map(mesh, field), 12. / diagonal(mesh));
      p.solve();
      check_pattern(p); // no singularity prescribed: none anywhere
      check_isolines(p);
      // pairs of opposite indices (a closed component without twist needs the sum 0)
      const std::vector<std::size_t> faces_ = free_faces(p, 4);
      REQUIRE(faces_.size() == 4);
      p.set_index(faces_[0], 1);
      p.set_index(faces_[1], -1);
      p.set_index(faces_[2], 2, n == 4 ? 1 : 0);
      p.set_index(faces_[3], -2, n == 4 ? 1 : 0);
      p.solve();
      check_pattern(p);
      check_isolines(p);
      REQUIRE(test::Mesh_snapshot(mesh) == before);
    }
}

TEMPLATE_TEST_CASE("The cover is a closed surface and obeys Riemann-Hurwitz", "[branched_stripes]",
                   SD_MESH_TYPES)
{
  const char* disk = CGAL_SURFACE_DESIGN_TESTS_UNDER_SANITIZERS ? "band" : "hemisphere.off";
  for(const std::string name : {"torus", "eight.off", disk})
    for(int n : {2, 4})
    {
      INFO(name << ", n = " << n);
      const TestType mesh = make_case<TestType>(name);
      const auto field = smoothest(mesh, n);
      Bsp<TestType> p(mesh, SD::parameters::symmetry_order(n));
      p.set_field(field_map(mesh, field), 5. / diagonal(mesh));
      const auto& idx = p.indices();
      const auto& cover = p.cover();
      // the field's indices, from the direction-field package (an independent reading)
      std::map<Face<TestType>, int> numerator;
      SD::direction_field_singularities(mesh, field_map(mesh, field), boost::make_assoc_property_map(numerator),
                                        SD::parameters::symmetry_order(n));
      long index_sum = 0;
      std::size_t branch = 0;
      for(std::size_t f = 0; f < idx.number_of_faces(); ++f)
      {
        const int k = numerator.at(idx.face(f));
        index_sum += k;
        REQUIRE(cover.index_numerator[f] == k);
        // regular exactly when the transitions around the face compose to the identity
        Eigen::Matrix2d M = Eigen::Matrix2d::Identity();
        for(auto h : halfedges_around_face(halfedge(idx.face(f), mesh), mesh))
          M = M * p.solver().transition_along(idx.index(h));
        REQUIRE(M.isIdentity(0.) == (((k % n) + n) % n == 0));
        REQUIRE(cover.regular[f] == M.isIdentity(0.));
        branch += cover.regular[f] ? 0 : 1;
      }
      const long chi = long(num_vertices(mesh)) - long(num_edges(mesh)) + long(num_faces(mesh));
      if(name != "hemisphere.off" && name != "band")
        REQUIRE(index_sum == n * chi); // Poincare-Hopf
      // the explicit cover: n sheets per vertex, regular faces lifted n times, branch faces split
      // at the centroid, whose preimages are the orbits of the face's total matching R
      const std::size_t nv = idx.number_of_vertices();
      std::vector<std::array<std::size_t, 3>> triangles;
      std::size_t next_vertex = nv * std::size_t(n);
      long ramification = 0;
      auto matching_along = [&](std::size_t h) {
        const auto hd = idx.halfedge(h);
        const int r = cover.matching[idx.edge_index(hd)];
        return idx.orientation_sign(hd) > 0 ? r : (n - r) % n;
      };
      for(std::size_t f = 0; f < idx.number_of_faces(); ++f)
      {
        std::array<std::size_t, 3> v, r;
        std::size_t t = 0;
        for(auto h : halfedges_around_face(halfedge(idx.face(f), mesh), mesh))
        {
          v[t] = idx.source_index(h);
          r[t++] = std::size_t(matching_along(idx.index(h)));
        }
        const std::size_t R = (r[0] + r[1] + r[2]) % std::size_t(n);
        std::vector<std::size_t> centre(static_cast<std::size_t>(n), 0);
        if(R != 0)
        {
          const std::size_t preimages = std::size_t(std::gcd(int(R), n));
          ramification += n - long(preimages);
          for(std::size_t s = 0; s < std::size_t(n); ++s)
            centre[s] = next_vertex + s % preimages; // s and s + R share the point
          next_vertex += preimages;
        }
        for(std::size_t s = 0; s < std::size_t(n); ++s)
        {
          const std::size_t s1 = (s + r[0]) % std::size_t(n), s2 = (s1 + r[1]) % std::size_t(n),
                            s3 = (s2 + r[2]) % std::size_t(n);
          const std::size_t a = v[0] * std::size_t(n) + s, b = v[1] * std::size_t(n) + s1,
                            c = v[2] * std::size_t(n) + s2, a3 = v[0] * std::size_t(n) + s3;
          if(R == 0)
            triangles.push_back({a, b, c});
          else
          {
            triangles.push_back({a, b, centre[s]});
            triangles.push_back({b, c, centre[s]});
            triangles.push_back({c, a3, centre[s]});
          }
        }
      }
      // every lifted interior edge bounds two lifted triangles, once each way
      std::map<std::pair<std::size_t, std::size_t>, int> uses;
      for(const auto& t : triangles)
        for(int i = 0; i < 3; ++i)
          ++uses[{t[std::size_t(i)], t[std::size_t((i + 1) % 3)]}];
      std::size_t border_uses = 0;
      for(const auto& [edge, count] : uses)
      {
        REQUIRE(count == 1);
        if(!uses.count({edge.second, edge.first}))
          ++border_uses;
      }
      std::size_t border_edges = 0;
      for(auto h : halfedges(mesh))
        border_edges += is_border(h, mesh) ? 1 : 0;
      REQUIRE(border_uses == border_edges * std::size_t(n));
      const long cover_chi = long(next_vertex) - long((uses.size() + border_uses) / 2) + long(triangles.size());
      REQUIRE(cover_chi == n * chi - ramification); // Riemann-Hurwitz
      REQUIRE(branch == p.branch_faces().size());
      if(n == 2 && name != "hemisphere.off" && name != "band")
        REQUIRE(branch % 2 == 0); // the cover's genus 2g - 1 + B/2 is an integer
    }
}

// A cross-check of two methods (the forest and the tree-cotree solvers), not of genericity: on
// Surface_mesh only (the other tests run on every mesh type), which keeps the build time down.
TEST_CASE("n = 1 gives the vector field stripes of Field_aligned_parameterizer", "[branched_stripes]")
{
  using TestType = test::Surface_mesh;
  const char* disk = CGAL_SURFACE_DESIGN_TESTS_UNDER_SANITIZERS ? "band" : "hemisphere.off";
  for(const std::string name : {"torus", "eight.off", disk})
  {
    INFO(name);
    const TestType mesh = make_case<TestType>(name);
    const auto field = smoothest(mesh, 1);
    const double frequency = 15. / diagonal(mesh);
    Bsp<TestType> p(mesh, SD::parameters::symmetry_order(1));
    p.set_field(field_map(mesh, field), frequency);
    const std::size_t count = p.place_automatic_singularities();
    INFO(count << " automatic singularities");
    SD::Field_aligned_parameterizer<TestType, Vpm<TestType>> fap(mesh);
    fap.set_field(field_map(mesh, field), frequency);
    for(std::size_t f : p.singular_faces())
      fap.set_index(f, p.index(p.indices().face(f)));
    p.solve();
    fap.solve();
    check_pattern(p);
    REQUIRE(std::abs(p.energy() - fap.energy()) <= 1e-9 * (1. + fap.energy()));
    for(std::size_t e = 0; e < fap.one_form().size(); ++e)
      REQUIRE(std::abs(p.one_form()[e][0] - fap.one_form()[e]) <= 1e-9 * (1. + std::abs(fap.one_form()[e])));
    // the isolines, read from the branched solution, and the vector stripes' own: the same lines
    check_isolines(p);
    const auto mine = fap.isolines(), theirs = p.isolines();
    const auto summary = [](const auto& lines) {
      std::array<double, 3> out{0., 0., 0.}; // open lines, closed lines, length
      for(const auto& line : lines)
      {
        out[line.closed ? 1 : 0] += 1.;
        for(std::size_t i = 0; i + 1 < line.points.size() + (line.closed ? 1 : 0); ++i)
          out[2] += std::sqrt(CGAL::squared_distance(line.points[i], line.points[(i + 1) % line.points.size()]));
      }
      return out;
    };
    const auto a = summary(mine), b = summary(theirs);
    REQUIRE(a[0] == b[0]);
    REQUIRE(a[1] == b[1]);
    REQUIRE(std::abs(a[2] - b[2]) <= 1e-6 * b[2]);
    REQUIRE(b[2] > 0.);
  }
}

TEST_CASE("Analytic: a cylinder's rings and a flat annulus around a +1/2 line-field singularity",
          "[branched_stripes]")
{
  using Mesh = test::Surface_mesh;
  const double R = 1.;
  const Mesh tube = polar_grid<Mesh>(12, 48, [R](double s, double t) {
    return std::array<double, 3>{R * std::cos(t), R * std::sin(t), 2. * s};
  });
  // rings: a line field along the axis, integrable: the stripes are alpha = 2 pi nu z exactly
  {
    const std::vector<Vector_of<Mesh>> axis(num_vertices(tube), Vector_of<Mesh>(0., 0., 1.));
    Bsp<Mesh> p(tube, SD::parameters::symmetry_order(2));
    p.set_field(field_map(tube, axis), 1.3);
    p.solve();
    REQUIRE(p.branch_faces().empty());
    REQUIRE(p.energy() < 1e-20);
    check_pattern(p);
    // the isolines are the rings z = const where 2 pi 1.3 z + alpha_0 is a multiple of pi
    REQUIRE(check_isolines(p) == 0);
    const auto lines = p.isolines();
    const double a0 = p.value(*faces(tube).begin(), {1., 0., 0.}) - two_pi * 1.3 * tube.point(source(halfedge(*faces(tube).begin(), tube), tube)).z();
    std::set<long> heights;
    for(const auto& line : lines)
    {
      const double z = line.points.front().z();
      double length = 0.;
      for(std::size_t i = 0; i < line.points.size(); ++i)
      {
        REQUIRE(std::abs(line.points[i].z() - z) < 1e-9);
        length += std::sqrt(CGAL::squared_distance(line.points[i], line.points[(i + 1) % line.points.size()]));
      }
      REQUIRE(length <= two_pi * R);
      REQUIRE(length >= two_pi * R * std::cos(pi / 48.));
      const double m = (two_pi * 1.3 * z + a0) / pi;
      REQUIRE(std::abs(m - std::round(m)) < 1e-9);
      heights.insert(std::lround(m));
    }
    REQUIRE(heights.size() == lines.size());
    // every multiple of pi the angle reaches on the tube (z in [0, 2]) has its ring
    REQUIRE(long(lines.size()) == long(std::floor((two_pi * 2.6 + a0) / pi + 1e-9) - std::ceil(a0 / pi - 1e-9)) + 1);
  }
  // around: a circumferential line field at 2.3 stripes per unit length wants 2.3 * 2 pi R
  // = 14.45 stripes around; the pattern takes 14 (integer), alpha = 14 theta
  {
    std::vector<Vector_of<Mesh>> around;
    for(auto v : vertices(tube))
    {
      const auto q = tube.point(v);
      around.emplace_back(-q.y(), q.x(), 0.);
    }
    for(int n : {2, 4})
    {
      Bsp<Mesh> p(tube, SD::parameters::symmetry_order(n));
      p.set_field(field_map(tube, around), 2.3);
      p.solve();
      check_pattern(p);
      // the turn of the stripe angle along a ring
      const auto& idx = p.indices();
      double turn = 0.;
      for(std::size_t j = 0; j < 48; ++j)
      {
        const auto a = Vertex<Mesh>(std::uint32_t(j)), b = Vertex<Mesh>(std::uint32_t((j + 1) % 48));
        const auto h = halfedge(a, b, tube).first;
        const std::size_t e = idx.edge_index(h);
        turn += idx.orientation_sign(h) * p.one_form()[e][0];
      }
      REQUIRE(std::abs(std::abs(turn) - 14. * two_pi) < 1e-9);
      // the lines of the family along the axis: 28 segments from rim to rim (14 at 0, 14 at pi)
      check_isolines(p);
      std::size_t axial = 0;
      // (a cross field's rings at z = 0 may lie on the rim, where the axial lines cut them)
      for(const auto& line : p.isolines())
        if(!line.closed && std::abs(line.points.back().z() - line.points.front().z()) > 1e-9)
        {
          ++axial;
          const double z0 = line.points.front().z(), z1 = line.points.back().z();
          REQUIRE((std::abs(z0) < 1e-12 || std::abs(z0 - 2.) < 1e-12));
          REQUIRE(std::abs(std::abs(z1 - z0) - 2.) < 1e-12);
        }
      REQUIRE(axial == 28);
    }
  }
  // the annulus 0.3 <= r <= 1 around a +1/2 line field: the sheets exchange around the hole
  const Mesh annulus = polar_grid<Mesh>(14, 64, [](double s, double t) {
    const double r = 0.3 + 0.7 * s;
    return std::array<double, 3>{r * std::cos(t), r * std::sin(t), 0.};
  });
  std::vector<Vector_of<Mesh>> half;
  for(auto v : vertices(annulus))
  {
    const auto q = annulus.point(v);
    const double theta = std::atan2(q.y(), q.x());
    half.emplace_back(std::cos(theta / 2.), std::sin(theta / 2.), 0.);
  }
  Bsp<Mesh> p(annulus, SD::parameters::symmetry_order(2));
  p.set_field(field_map(annulus, half), 4.);
  REQUIRE(p.branch_faces().empty());
  REQUIRE(p.solver().is_twisted(0));
  p.solve();
  check_pattern(p);
  // isolines perpendicular to the field: the gradient of alpha along it (the convention)
  const auto& idx = p.indices();
  double aligned = 0., area = 0.;
  for(auto f : faces(annulus))
  {
    const auto c = p.corner_values(f);
    const auto h = halfedge(f, annulus);
    const auto p0 = annulus.point(source(h, annulus)), p1 = annulus.point(target(h, annulus)),
               p2 = annulus.point(target(next(h, annulus), annulus));
    // the gradient of the linear function with values c at p0, p1, p2 (in the plane z = 0)
    const double x1 = p1.x() - p0.x(), y1 = p1.y() - p0.y(), x2 = p2.x() - p0.x(), y2 = p2.y() - p0.y();
    const double det = x1 * y2 - x2 * y1;
    const double gx = ((c[1] - c[0]) * y2 - (c[2] - c[0]) * y1) / det;
    const double gy = (x1 * (c[2] - c[0]) - x2 * (c[1] - c[0])) / det;
    const auto d = p.field_direction(f);
    const double cosine = std::abs(gx * d.x() + gy * d.y()) / std::hypot(gx, gy);
    aligned += std::abs(det) * cosine;
    area += std::abs(det);
  }
  (void)idx;
  REQUIRE(aligned / area > 0.97);
}

TEMPLATE_TEST_CASE("Automatic singularities: where the energy wants them, then exact", "[branched_stripes]",
                   SD_MESH_TYPES)
{
  const TestType mesh = make_case<TestType>("bunny_1k.off");
  for(int n : {2, 4})
  {
    INFO("n = " << n);
    const auto field = smoothest(mesh, n);
    Bsp<TestType> p(mesh, SD::parameters::symmetry_order(n));
    p.set_field(field_map(mesh, field), 20. / diagonal(mesh));
    p.solve();
    const double without = p.energy();
    const std::size_t count = p.place_automatic_singularities();
    REQUIRE(count > 0);
    REQUIRE(count == p.singular_faces().size());
    p.solve();
    check_pattern(p);
    INFO(count << " singularities: energy " << p.energy() << " against " << without << " without");
    // the pruned candidates never raise the energy; on a line field they lower it a lot
    REQUIRE(p.energy() <= without);
    if(n == 2)
      REQUIRE(p.energy() < 0.5 * without);
    for(std::size_t f : p.singular_faces())
      REQUIRE_FALSE(p.is_branch_face(p.indices().face(f)));
  }
}

TEST_CASE("Edits are back-substitutions and equal a fresh solve, and both solvers agree", "[branched_stripes]")
{
  using Mesh = test::Surface_mesh;
  const Mesh mesh = make_case<Mesh>("eight.off");
  const auto field = smoothest(mesh, 4);
  const double frequency = 10. / diagonal(mesh);
  Bsp<Mesh> editor(mesh, SD::parameters::symmetry_order(4));
  editor.set_field(field_map(mesh, field), frequency);
  REQUIRE(editor.number_of_factorizations() == 1);
  editor.solve();
  const auto faces_ = free_faces(editor, 4);
  editor.set_index(faces_[0], 1);
  editor.set_index(faces_[1], -1, 1);
  editor.solve();
  editor.move_singularity(editor.indices().face(faces_[0]), editor.indices().face(faces_[2]));
  editor.set_frequency(1.2 * frequency);
  editor.solve();
  REQUIRE(editor.number_of_factorizations() == 1); // the edits were back-substitutions
  Bsp<Mesh> fresh(mesh, SD::parameters::symmetry_order(4));
  fresh.set_field(field_map(mesh, field), 1.2 * frequency);
  fresh.set_index(faces_[2], 1);
  fresh.set_index(faces_[1], -1, 1);
  fresh.solve();
  REQUIRE(std::abs(editor.energy() - fresh.energy()) <= 1e-9 * fresh.energy());
  for(std::size_t e = 0; e < fresh.one_form().size(); ++e)
    REQUIRE((editor.one_form()[e] - fresh.one_form()[e]).norm() <= 1e-9 * (1. + fresh.one_form()[e].norm()));
#if defined(CGAL_SURFACE_DESIGN_HAS_CHOLMOD)
  Bsp<Mesh, SD::Cholmod_solver_traits> other(mesh, SD::parameters::symmetry_order(4));
  other.set_field(field_map(mesh, field), 1.2 * frequency);
  other.set_index(faces_[2], 1);
  other.set_index(faces_[1], -1, 1);
  other.solve();
  for(std::size_t e = 0; e < fresh.one_form().size(); ++e)
    REQUIRE((other.one_form()[e] - fresh.one_form()[e]).norm() <= 1e-8 * (1. + fresh.one_form()[e].norm()));
#else
  SD_CHOLMOD_UNAVAILABLE("the comparison of the branched stripes of both solvers");
#endif
}

TEST_CASE("The isoline reading catches missing, cut and displaced lines", "[branched_stripes][oracle]")
{
  using Mesh = test::Surface_mesh;
  const Mesh mesh = make_case<Mesh>("torus");
  Bsp<Mesh> p(mesh, SD::parameters::symmetry_order(2));
  p.set_field(field_map(mesh, smoothest(mesh, 2)), 8. / diagonal(mesh));
  p.solve();
  const auto lines = p.isolines();
  std::size_t open = 0;
  REQUIRE(isoline_problem(p, lines, open) == "");
  REQUIRE(open == 0); // a torus without singularities: closed lines only
  REQUIRE(lines.size() >= 4);
  auto missing = lines;
  missing.pop_back();
  REQUIRE_THAT(isoline_problem(p, missing, open), Catch::Matchers::Contains("crossed"));
  auto cut = lines;
  cut[0].closed = false;
  cut[0].faces.pop_back();
  REQUIRE_THAT(isoline_problem(p, cut, open), Catch::Matchers::Contains("ends in the regular face"));
  auto moved = lines;
  // a point pulled towards the centroid of its first piece's face: inside the face, off the line
  const auto h = halfedge(moved[1].faces[0], mesh);
  const auto centroid = CGAL::centroid(mesh.point(source(h, mesh)), mesh.point(target(h, mesh)),
                                       mesh.point(target(next(h, mesh), mesh)));
  moved[1].points[0] = CGAL::barycenter(moved[1].points[0], 0.7, centroid, 0.3);
  REQUIRE_THAT(isoline_problem(p, moved, open), Catch::Matchers::Contains("off its level"));
}

TEST_CASE("The readings catch a broken pattern", "[branched_stripes][oracle]")
{
  using Mesh = test::Surface_mesh;
  const Mesh mesh = make_case<Mesh>("torus");
  const auto field = smoothest(mesh, 2);
  Bsp<Mesh> p(mesh, SD::parameters::symmetry_order(2));
  p.set_field(field_map(mesh, field), 8. / diagonal(mesh));
  p.solve();
  const Value_function good = value_of(p);
  REQUIRE(largest_jump(mesh, p.indices(), good, 1) < 1e-9);
  // a bump of 0.3 in one face: the jump reading sees it
  const Value_function bumped = [&](std::size_t f, const std::array<double, 3>& b, int family) {
    return good(f, b, family) + (f == 17 ? 0.3 * b[0] * b[1] * b[2] * 27. + 0.3 * b[0] : 0.);
  };
  REQUIRE(largest_jump(mesh, p.indices(), bumped, 1) > 0.05);
  // a vortex painted into one face: the winding reading sees it
  const Value_function vortex = [&](std::size_t f, const std::array<double, 3>& b, int family) {
    return good(f, b, family) + (f == 17 ? SDI::barycentric_argument(b) : 0.);
  };
  REQUIRE(winding_around(vortex, 17, 0).first == 1);
  REQUIRE(winding_around(good, 17, 0).first == 0);
}

TEMPLATE_TEST_CASE("Bad input is refused clearly and changes nothing", "[branched_stripes]", SD_MESH_TYPES)
{
  const TestType mesh = make_case<TestType>("hemisphere.off");
  const test::Mesh_snapshot before(mesh);
  REQUIRE_THROWS_AS(Bsp<TestType>(mesh, SD::parameters::symmetry_order(3)), SD::Invalid_parameter);
  REQUIRE_THROWS_AS(Bsp<TestType>(mesh, SD::parameters::weighting(SD::Edge_weighting::mean_value)),
                    SD::Invalid_parameter);
  const auto field = smoothest(mesh, 2);
  Bsp<TestType> p(mesh);
  REQUIRE(p.symmetry_order() == 2);
  REQUIRE_THROWS_AS(p.solve(), SD::Invalid_constraints);
  for(double bad : {0., -1., std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()})
    REQUIRE_THROWS_AS(p.set_field(field_map(mesh, field), bad), SD::Invalid_parameter);
  std::vector<Vector_of<TestType>> broken = field;
  broken[5] = Vector_of<TestType>(std::numeric_limits<double>::quiet_NaN(), 0., 0.);
  REQUIRE_THROWS_AS(p.set_field(field_map(mesh, broken), 1.), SD::Invalid_parameter);
  REQUIRE_FALSE(p.has_field());
  p.set_field(field_map(mesh, field), 6. / diagonal(mesh));
  const auto& idx = p.indices();
  // a face with an edge on the boundary, a branch face, a family that does not exist
  std::size_t boundary_face = SDI::npos;
  for(std::size_t f = 0; f < idx.number_of_faces() && boundary_face == SDI::npos; ++f)
    for(auto h : halfedges_around_face(halfedge(idx.face(f), mesh), mesh))
      if(is_border(opposite(h, mesh), mesh))
        boundary_face = f;
  REQUIRE_THROWS_AS(p.set_index(boundary_face, 1), SD::Invalid_constraints);
  REQUIRE_THROWS_AS(p.set_index(idx.number_of_faces(), 1), SD::Invalid_constraints);
  REQUIRE_THROWS_AS(p.set_index(std::size_t(0), 1, 1), SD::Invalid_constraints);
  REQUIRE_THROWS_AS(p.set_frequency(-2.), SD::Invalid_parameter);
  if(!p.branch_faces().empty())
    REQUIRE_THROWS_AS(p.set_index(p.branch_faces().front(), 1), SD::Invalid_constraints);
  REQUIRE(p.singular_faces().empty());
  // Stokes on a closed surface without twist: a vector field's stripes with one +1
  const TestType closed = make_case<TestType>("torus");
  const auto smooth = smoothest(closed, 1);
  Bsp<TestType> q(closed, SD::parameters::symmetry_order(1));
  q.set_field(field_map(closed, smooth), 1.);
  q.set_index(std::size_t(40), 1);
  REQUIRE_THROWS_AS(q.solve(), SD::Invalid_constraints);
  REQUIRE_FALSE(q.is_solved());
  REQUIRE(test::Mesh_snapshot(mesh) == before);
}

TEST_CASE("The closest lattice point: LLL and enumeration against brute force", "[branched_stripes][lattice]")
{
  // skewed bases: plain rounding of the relaxed optimum misses, the reduced search does not
  for(int trial = 0; trial < 40; ++trial)
  {
    const int m = 2 + trial % 3;
    Eigen::MatrixXd B(m, m); // a skewed basis: near-parallel columns
    for(int i = 0; i < m; ++i)
      for(int j = 0; j < m; ++j)
        B(i, j) = (i == j ? 1. : 0.) + 0.93 * std::sin(1.7 * (trial + 1) * (i + 1) + 0.3 * j) * (j > 0 ? 1. : 0.) +
                  (i == 0 ? 3. * j : 0.);
    const Eigen::MatrixXd Q = B.transpose() * B;
    Eigen::VectorXd g(m);
    for(int i = 0; i < m; ++i)
      g[i] = 7.3 * std::cos(2.1 * trial + i);
    auto cost = [&](const Eigen::VectorXi& c) {
      const Eigen::VectorXd x = c.cast<double>();
      return 2. * g.dot(x) + x.dot(Q * x);
    };
    const SDI::Reduced_integer_quadratic reduced = SDI::reduce_integer_quadratic(Q);
    // U is unimodular: integer entries and determinant +-1
    REQUIRE((reduced.U.array() - reduced.U.array().round()).abs().maxCoeff() == 0.);
    REQUIRE(std::abs(std::abs(reduced.U.determinant()) - 1.) < 1e-9);
    const Eigen::VectorXi found = SDI::closest_integer_point(reduced, g);
    // brute force around the relaxed optimum
    const Eigen::VectorXd center = -Q.ldlt().solve(g);
    double best = std::numeric_limits<double>::infinity();
    const int R = 12;
    Eigen::VectorXi c(m);
    std::function<void(int)> search = [&](int i) {
      if(i == m)
      {
        best = (std::min)(best, cost(c));
        return;
      }
      for(int k = -R; k <= R; ++k)
      {
        c[i] = int(std::round(center[i])) + k;
        search(i + 1);
      }
    };
    if(m <= 3)
      search(0);
    INFO("trial " << trial << ", m = " << m);
    REQUIRE(cost(found) <= best + 1e-9 * (1. + std::abs(best)));
  }
}

TEST_CASE("Twisted fields without singularity and singularities in new branch faces are refused", "[branched_stripes]")
{
  using Mesh = test::Surface_mesh;
  Mesh torus;
  SD::make_torus(torus, 36, 12, 1., 0.35, true);
  // a line field that turns by a half turn along the torus's major circle: no singularity, but
  // its two directions exchange around that loop
  std::vector<Vector_of<Mesh>> twisted;
  for(auto v : vertices(torus))
  {
    const auto q = torus.point(v);
    const double phi = std::atan2(q.y(), q.x()), rho = std::hypot(q.x(), q.y());
    const double theta = std::atan2(q.z(), rho - 1.);
    const Eigen::Vector3d along(-std::sin(phi), std::cos(phi), 0.);
    const Eigen::Vector3d around(-std::sin(theta) * std::cos(phi), -std::sin(theta) * std::sin(phi), std::cos(theta));
    const Eigen::Vector3d x = std::cos(phi / 2.) * along + std::sin(phi / 2.) * around;
    twisted.emplace_back(x.x(), x.y(), x.z());
  }
  Bsp<Mesh> p(torus, SD::parameters::symmetry_order(2));
  REQUIRE_THROWS_AS(p.set_field(field_map(torus, twisted), 2.), SD::Invalid_constraints);
  REQUIRE_FALSE(p.has_field());

  // a sphere's line field, then one with +1/2 singularities at four chosen faces: a stripe
  // singularity prescribed in one of them refuses the new field and keeps the old one
  Mesh sphere;
  SD::make_sphere(sphere, 8);
  const auto smooth = smoothest(sphere, 2);
  Bsp<Mesh> q(sphere, SD::parameters::symmetry_order(2));
  q.set_field(field_map(sphere, smooth), 3.);
  const auto faces_ = free_faces(q, 4);
  q.set_index(faces_[0], 1);
  q.set_index(faces_[1], -1);
  const std::vector<std::size_t> branch_before = q.branch_faces();
  SD::Trivial_connection tc(sphere, SD::parameters::symmetry_order(2));
  for(std::size_t f : {faces_[0], faces_[2], faces_[3], (faces_[1] + 1) % num_faces(sphere)})
    tc.set_index(f, 1); // four +1/2: 2 chi
  tc.solve();
  std::vector<Vector_of<Mesh>> prescribed(num_vertices(sphere));
  tc.field(CGAL::make_property_map(prescribed));
  REQUIRE_THROWS_AS(q.set_field(field_map(sphere, prescribed), 3.), SD::Invalid_constraints);
  REQUIRE(q.branch_faces() == branch_before);
  REQUIRE(q.index(q.indices().face(faces_[0])) == 1);
  q.solve();
  check_pattern(q);
  // without the singularity there, the new field is accepted and its branch faces are the four
  q.set_index(faces_[0], 0);
  q.set_index(faces_[1], 0);
  q.set_field(field_map(sphere, prescribed), 3.);
  REQUIRE(q.branch_faces().size() == 4);
  q.solve();
  check_pattern(q);
}

TEST_CASE("Integer points of given parities: the coset against brute force", "[branched_stripes][lattice]")
{
  // random systems A (x, s) = b (mod 2) with n unknowns and n_aux auxiliary binary ones
  std::uint32_t state = 12345;
  auto bit = [&state]() {
    state = state * 1664525u + 1013904223u;
    return std::uint8_t((state >> 16) & 1u);
  };
  std::size_t feasible_seen = 0, infeasible_seen = 0;
  for(int trial = 0; trial < 300; ++trial)
  {
    const std::size_t n = 1 + std::size_t(trial % 5), n_aux = std::size_t(trial / 5 % 3), rows = 1 + std::size_t(trial % 7);
    std::vector<std::vector<std::uint8_t>> A(rows, std::vector<std::uint8_t>(n + n_aux));
    std::vector<std::uint8_t> b(rows);
    for(auto& row : A)
      for(auto& a : row)
        a = bit();
    for(auto& x : b)
      x = bit();
    // brute force: the parities x in {0,1}^n for which some s solves the system
    auto solves = [&](std::size_t xbits, std::size_t sbits) {
      for(std::size_t r = 0; r < rows; ++r)
      {
        std::uint8_t sum = 0;
        for(std::size_t j = 0; j < n; ++j)
          sum ^= std::uint8_t(A[r][j] & ((xbits >> j) & 1u));
        for(std::size_t j = 0; j < n_aux; ++j)
          sum ^= std::uint8_t(A[r][n + j] & ((sbits >> j) & 1u));
        if(sum != b[r])
          return false;
      }
      return true;
    };
    std::set<std::size_t> allowed;
    for(std::size_t x = 0; x < (std::size_t(1) << n); ++x)
      for(std::size_t s = 0; s < (std::size_t(1) << n_aux); ++s)
        if(solves(x, s))
          allowed.insert(x);
    const SDI::Parity_coset coset = SDI::parity_coset(A, b, n, n_aux);
    INFO("trial " << trial);
    REQUIRE(coset.feasible == !allowed.empty());
    if(!coset.feasible)
    {
      ++infeasible_seen;
      continue;
    }
    ++feasible_seen;
    auto parity_bits = [n](const Eigen::VectorXi& x) {
      std::size_t bits = 0;
      for(std::size_t j = 0; j < n; ++j)
        bits |= std::size_t(((x[Eigen::Index(j)] % 2) + 2) % 2) << j;
      return bits;
    };
    // every point offset + B z for small z is allowed, and the lattice has the index the
    // allowed parities give: 2^n / |allowed| (then B generates all of it, as it lies inside)
    REQUIRE(allowed.count(parity_bits(coset.offset)) == 1);
    for(int k = 0; k < 50; ++k)
    {
      Eigen::VectorXi z = Eigen::VectorXi::Zero(Eigen::Index(n));
      for(std::size_t j = 0; j < n; ++j)
        z[Eigen::Index(j)] = int(bit()) + 2 * int(bit()) - int(bit());
      REQUIRE(allowed.count(parity_bits(coset.offset + coset.basis * z)) == 1);
    }
    const double det = std::abs(coset.basis.cast<double>().determinant());
    REQUIRE(std::abs(det * double(allowed.size()) - double(std::size_t(1) << n)) < 1e-9);
  }
  REQUIRE(feasible_seen > 50);
  REQUIRE(infeasible_seen > 20);
}

// The isolines that end at the branch point of branch face f, by level (0 or pi).
template <class Parameterizer>
std::array<std::size_t, 2> ends_at_branch_point(const Parameterizer& p,
                                                const std::vector<typename Parameterizer::Isoline>& lines,
                                                std::size_t f, double tolerance)
{
  const auto& idx = p.indices();
  const auto& tm = idx.mesh();
  const auto o = p.branch_point(idx.face(f));
  // the corners in the order of corner_values(): source(h), target(h), target(next(h))
  // (vertices_around_face() starts at target(h))
  const auto h = halfedge(idx.face(f), tm);
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
  std::size_t k = 0;
  for(auto v : {source(h, tm), target(h, tm), target(next(h, tm), tm)})
  {
    const auto q = get(CGAL::vertex_point, tm, v);
    point += o[k++] * Eigen::Vector3d(q.x(), q.y(), q.z());
  }
  std::array<std::size_t, 2> count{0, 0};
  for(const auto& line : lines)
  {
    if(line.closed || line.points.empty())
      continue;
    for(const auto& q : {line.points.front(), line.points.back()})
      if((Eigen::Vector3d(q.x(), q.y(), q.z()) - point).norm() < tolerance)
        ++count[std::abs(line.level) < 1e-9 ? 0 : 1];
  }
  return count;
}

TEST_CASE("The branch point: the face's Fermat point, kept away from its edges", "[branched_stripes][lattice]")
{
  using V = Eigen::Vector3d;
  auto point = [](const std::array<V, 3>& x, const std::array<double, 3>& b) { return V(b[0] * x[0] + b[1] * x[1] + b[2] * x[2]); };
  auto angle = [](const V& p, const V& q) { return std::atan2(p.cross(q).norm(), p.dot(q)); };
  // an equilateral triangle: its centroid
  const std::array<V, 3> equilateral{V(0, 0, 0), V(1, 0, 0), V(0.5, std::sqrt(3.) / 2., 0)};
  for(double b : SDI::branch_point_barycentric(equilateral))
    REQUIRE(std::abs(b - 1. / 3.) < 1e-12);
  // triangles with every angle below 120 degrees (in 3D): each edge seen under 120 degrees
  CGAL::Random rng(7);
  std::size_t acute = 0;
  for(int trial = 0; trial < 300; ++trial)
  {
    std::array<V, 3> x;
    for(V& p : x)
      p = V(rng.get_double(-1, 1), rng.get_double(-1, 1), rng.get_double(-1, 1));
    double largest = 0.;
    for(int i = 0; i < 3; ++i)
      largest = (std::max)(largest, angle(x[(i + 1) % 3] - x[i], x[(i + 2) % 3] - x[i]));
    const auto b = SDI::branch_point_barycentric(x);
    REQUIRE(std::abs(b[0] + b[1] + b[2] - 1.) < 1e-12);
    for(double c : b)
      REQUIRE(c >= 0.1 - 1e-12); // inside, away from the edges
    const V o = point(x, b);
    // an angle well below 120 degrees, and no coordinate at the floor: the Fermat point itself
    if(largest < 2. * SDI::pi / 3. - 0.2 && *std::min_element(b.begin(), b.end()) > 0.1 + 1e-9)
    {
      ++acute;
      for(int i = 0; i < 3; ++i)
        REQUIRE(std::abs(angle(x[i] - o, x[(i + 1) % 3] - o) - 2. * SDI::pi / 3.) < 1e-9);
    }
    // the sub-triangle of any point: it is rebuilt from its coordinates there, all of them >= 0
    for(int k = 0; k < 5; ++k)
    {
      std::array<double, 3> q{rng.get_double(), rng.get_double(), rng.get_double()};
      const double sum = q[0] + q[1] + q[2];
      for(double& c : q)
        c /= sum;
      const auto [opposite, l] = SDI::branch_sub_triangle(b, q);
      const std::size_t i = std::size_t((opposite + 1) % 3), j = std::size_t((opposite + 2) % 3);
      std::array<double, 3> rebuilt{l[2] * b[0], l[2] * b[1], l[2] * b[2]};
      rebuilt[i] += l[0];
      rebuilt[j] += l[1];
      for(int c = 0; c < 3; ++c)
        REQUIRE(std::abs(rebuilt[std::size_t(c)] - q[std::size_t(c)]) < 1e-12);
      for(double c : l)
        REQUIRE(c >= -1e-12);
    }
  }
  REQUIRE(acute > 30);
}

TEMPLATE_TEST_CASE("Branch points on the lattice: the lines end at every cone, 4 - k of them where the map is injective",
                   "[branched_stripes][lattice]", SD_MESH_TYPES)
{
  const char* disk = CGAL_SURFACE_DESIGN_TESTS_UNDER_SANITIZERS ? "band" : "hemisphere.off";
  std::size_t off_lattice_before = 0, cones = 0, injective_cross_cones = 0;
  for(const std::string name : {"sphere", "eight.off", disk, "bunny_1k.off"})
    for(int n : {2, 4})
    {
      INFO(name << ", n = " << n);
      const TestType mesh = make_case<TestType>(name);
      const double h = diagonal(mesh);
      Bsp<TestType> p(mesh, SD::parameters::symmetry_order(n));
      p.set_field(field_map(mesh, smoothest(mesh, n)), 10. / h);
      p.solve();
      const std::vector<std::size_t> branch = p.branch_faces();
      const auto before = p.isolines();
      for(std::size_t f : branch)
        off_lattice_before += ends_at_branch_point(p, before, f, 1e-9 * h)[0] == 0 ? 1 : 0;

      // the branch faces' spokes enter the system: one more factorization
      p.set_lattice_branch_points(true);
      REQUIRE_FALSE(p.is_solved());
      REQUIRE(p.number_of_factorizations() == 2);
      p.solve();
      check_pattern(p); // continuity, indices, branch values, optimality (with the spokes)
      const auto lines = p.isolines();
      for(std::size_t f : branch)
      {
        ++cones;
        const auto fd = p.indices().face(f);
        const auto c = p.branch_point_value(fd);
        for(int a = 0; a < p.number_of_families(); ++a)
          REQUIRE(std::abs(SDI::wrap_angle(c[std::size_t(a)])) < 1e-9);
        // the values around the branch point: corners 0, 1, 2 and corner 0 again after the walk
        // (read on the side of the third edge), relative to the branch point
        std::array<Eigen::Vector2d, 4> around;
        for(int a = 0; a < p.number_of_families(); ++a)
        {
          const auto cv = p.corner_values(fd, a);
          for(int k = 0; k < 3; ++k)
            around[std::size_t(k)][a] = cv[std::size_t(k)] - c[std::size_t(a)];
          around[3][a] = p.value(fd, {1. - 1e-12, 0., 1e-12}, a) - c[std::size_t(a)];
        }
        const auto ends = ends_at_branch_point(p, lines, f, 1e-9 * h);
        INFO("branch face " << f << ", index " << p.field_index_numerator(fd) << "/" << n);
        REQUIRE(ends[1] == 0); // no line of level pi there
        if(n == 2)
        {
          // as many lines end there as the angle changes sign around it: at least one
          std::size_t changes = 0;
          for(int k = 0; k < 3; ++k)
            changes += (around[std::size_t(k)][0] < 0.) != (around[std::size_t(k + 1)][0] < 0.) ? 1 : 0;
          REQUIRE(ends[0] == changes);
          REQUIRE(changes >= 1);
          continue;
        }
        // a cross field where the three triangles around the branch point keep their orientation
        // in the (alpha, beta) plane: a crossing of 4 - k lines (a +1/4 cone: valence 3, -1/4: 5)
        bool injective = true;
        for(int k = 0; k < 3; ++k)
        {
          const Eigen::Vector2d& x = around[std::size_t(k)];
          const Eigen::Vector2d& y = around[std::size_t(k + 1)];
          injective = injective && x.x() * y.y() - x.y() * y.x() > 0.;
        }
        std::ostringstream values;
        for(const auto& x : around)
          values << "(" << x[0] << ", " << x[1] << ") ";
        INFO("around the branch point: " << values.str() << "ends " << ends[0]);
        if(injective)
        {
          ++injective_cross_cones;
          REQUIRE(int(ends[0]) == 4 - p.field_index_numerator(fd));
        }
      }
    }
  REQUIRE(cones > 20);
  REQUIRE(injective_cross_cones > 5);
  // without the condition some branch points are off the lattice: the test can see the difference
  REQUIRE(off_lattice_before > 0);
}

TEST_CASE("Branch points on the lattice: a torus with two +1/4 and two -1/4 cones", "[branched_stripes][lattice]")
{
  using Mesh = test::Surface_mesh;
  Mesh torus;
  SD::make_torus(torus, 36, 12, 1., 0.35, true);
  SD::Trivial_connection tc(torus, SD::parameters::symmetry_order(4));
  for(const auto& [f, k] : std::vector<std::pair<std::size_t, int>>{{10, 1}, {200, 1}, {500, -1}, {700, -1}})
    tc.set_index(f, k);
  tc.solve();
  std::vector<Vector_of<Mesh>> x(num_vertices(torus));
  tc.field(CGAL::make_property_map(x));
  // switched on before the field: no extra factorization
  Bsp<Mesh> p(torus, SD::parameters::symmetry_order(4));
  p.set_lattice_branch_points(true);
  p.set_field(field_map(torus, x), 3.);
  REQUIRE(p.number_of_factorizations() == 1);
  REQUIRE(p.branch_faces().size() == 4);
  p.solve();
  check_pattern(p);
  for(std::size_t f : p.branch_faces())
  {
    const auto c = p.branch_point_value(p.indices().face(f));
    REQUIRE(std::abs(SDI::wrap_angle(c[0])) < 1e-9);
    REQUIRE(std::abs(SDI::wrap_angle(c[1])) < 1e-9);
  }
#if defined(CGAL_SURFACE_DESIGN_HAS_CHOLMOD)
  // the other solver: the same pattern
  Bsp<Mesh, SD::Cholmod_solver_traits> q(torus, SD::parameters::symmetry_order(4));
  q.set_lattice_branch_points(true);
  q.set_field(field_map(torus, x), 3.);
  q.solve();
  REQUIRE(std::abs(q.energy() - p.energy()) <= 1e-8 * p.energy());
  for(std::size_t v = 0; v < p.vertex_values().size(); ++v)
    REQUIRE((q.vertex_values()[v] - p.vertex_values()[v]).norm() < 1e-7);
#else
  SD_CHOLMOD_UNAVAILABLE("the lattice branch points with CHOLMOD");
#endif
}

namespace {

// The smoothest n-direction field normal to the boundary.
template <class Mesh>
std::vector<Vector_of<Mesh>> smoothest_normal_to_boundary(const Mesh& mesh, int n)
{
  const SDI::Mesh_indices<Mesh> idx(mesh);
  std::vector<Vector_of<Mesh>> by_index(num_vertices(mesh));
  std::map<Vertex<Mesh>, Vector_of<Mesh>> map;
  SD::smoothest_direction_field(
    mesh, boost::make_assoc_property_map(map),
    SD::parameters::symmetry_order(n, SD::parameters::field_boundary_condition(SD::Direction_field_boundary::normal)));
  for(std::size_t v = 0; v < idx.number_of_vertices(); ++v)
    by_index[v] = map.at(idx.vertex(v));
  return by_index;
}

// The largest distance to 2 pi Z of the stripe angle at a boundary vertex, and of the change of
// the angle along a boundary edge from 0 (both read from the corner values of the faces).
template <class Mesh, class Parameterizer>
std::pair<double, double> boundary_level_gaps(const Mesh& mesh, const Parameterizer& p)
{
  double off_level = 0., along = 0.;
  for(auto f : faces(mesh))
  {
    if(p.is_branch_face(f))
      continue;
    // the family normal to the boundary: the closest to the level of the two (a cross field's)
    std::array<std::array<double, 3>, 2> values{p.corner_values(f, 0), p.corner_values(f, 0)};
    if(p.symmetry_order() == 4)
      values[1] = p.corner_values(f, 1);
    std::array<bool, 3> on_boundary{};
    std::array<bool, 3> edge_on_boundary{}; // edge k from corner k to corner k + 1
    int k = 0;
    for(auto h : halfedges_around_face(halfedge(f, mesh), mesh))
    {
      on_boundary[std::size_t(k)] = is_border(source(h, mesh), mesh).has_value();
      edge_on_boundary[std::size_t(k)] = is_border(opposite(h, mesh), mesh);
      ++k;
    }
    for(std::size_t c = 0; c < 3; ++c)
    {
      if(on_boundary[c])
        off_level = (std::max)(off_level, (std::min)(std::abs(std::remainder(values[0][c], two_pi)),
                                                      std::abs(std::remainder(values[1][c], two_pi))));
      if(edge_on_boundary[c])
        along = (std::max)(along, (std::min)(std::abs(values[0][(c + 1) % 3] - values[0][c]),
                                             std::abs(values[1][(c + 1) % 3] - values[1][c])));
    }
  }
  return {off_level, along};
}

} // namespace

TEMPLATE_TEST_CASE("Boundary loops on level lines: the angle is 0 on the boundary, no stripe crosses it",
                   "[branched_stripes]", SD_MESH_TYPES)
{
  for(const std::string name : {"band", "hemisphere.off"})
    for(int n : {1, 2, 4})
    {
      // (the band's cross field has no cone: its two loops' windings are coupled by Stokes)
      INFO(name << ", n = " << n);
      const TestType mesh = make_case<TestType>(name);
      const auto field = smoothest_normal_to_boundary(mesh, n);
      Bsp<TestType> p(mesh, SD::parameters::symmetry_order(n));
      p.set_field(field_map(mesh, field), 7.3 / diagonal(mesh));
      p.solve();
      const double free_energy = p.energy();
      const auto [free_off, free_along] = boundary_level_gaps(mesh, p);
      CHECK(free_off > 0.1); // the oracle sees the difference: the free boundary is off the level
      p.set_boundary_on_level_lines(true);
      p.solve();
      const auto [off, along] = boundary_level_gaps(mesh, p);
      CHECK(off < 1e-8);
      CHECK(along < 1e-8);
      CHECK(p.energy() >= free_energy * (1. - 1e-12)); // a constraint cannot lower the optimum
      CHECK(p.energy() <= 4. * free_energy + 1.);      // and the boundary's stripes stay close to the field's
      (void)free_along;
#if defined(CGAL_SURFACE_DESIGN_HAS_CHOLMOD)
      // the other solver: the same optimum
      Bsp<TestType, SD::Cholmod_solver_traits> q(mesh, SD::parameters::symmetry_order(n));
      q.set_boundary_on_level_lines(true);
      q.set_field(field_map(mesh, field), 7.3 / diagonal(mesh));
      q.solve();
      CHECK(std::abs(q.energy() - p.energy()) <= 1e-8 * p.energy());
      CHECK(boundary_level_gaps(mesh, q).first < 1e-8);
#else
      SD_CHOLMOD_UNAVAILABLE("the boundary's level lines with both solvers");
#endif
      // optimal over the values left free: the energy, quadratic, changes by the same amount along
      // y +- d_P delta (delta random, 0 on the fixed values); along a delta on the boundary's
      // values alone it does not (the constraint holds the optimum there)
      const auto& solver = p.solver();
      const auto& y = p.one_form();
      const auto& omega = p.target_one_form();
      const auto& idx = p.indices();
      std::uint32_t state = 11;
      for(const bool on_level : {false, true})
      {
        std::vector<Eigen::Vector2d> delta(idx.number_of_vertices(), Eigen::Vector2d::Zero());
        std::size_t moved = 0;
        for(std::size_t v = 0; v < delta.size(); ++v)
        {
          state = state * 1664525u + 1013904223u;
          const bool boundary = is_border(idx.vertex(v), mesh).has_value();
          for(int a = 0; a < (n == 4 ? 2 : 1); ++a)
            if(solver.is_fixed(v, a) == on_level && (!on_level || boundary))
            {
              delta[v][a] = double(state >> 8) / double(1u << 24) - 0.5;
              ++moved;
            }
        }
        REQUIRE(moved > 0);
        const auto [ep, em] = energies_along(solver, idx, y, omega, delta);
        INFO("moving " << (on_level ? "the boundary's" : "the free") << " values: energy " << ep << " " << em);
        if(on_level)
          CHECK(std::abs(ep - em) > 1e-6 * (ep + em));
        else
          CHECK(std::abs(ep - em) <= 1e-9 * (ep + em));
      }
    }
}

TEMPLATE_TEST_CASE("Boundary loops on level lines: refused where the field runs along the boundary, and a cross field "
                   "without cones and two loops",
                   "[branched_stripes]", SD_MESH_TYPES)
{
  const TestType band = make_case<TestType>("band");
  // the smoothest line field tangent to the boundary: no level line can follow it
  std::vector<Vector_of<TestType>> tangent(num_vertices(band));
  {
    const SDI::Mesh_indices<TestType> idx(band);
    std::map<Vertex<TestType>, Vector_of<TestType>> map;
    SD::smoothest_direction_field(band, boost::make_assoc_property_map(map),
                                  SD::parameters::symmetry_order(2, SD::parameters::field_boundary_condition(
                                                                      SD::Direction_field_boundary::tangent)));
    for(std::size_t v = 0; v < idx.number_of_vertices(); ++v)
      tangent[v] = map.at(idx.vertex(v));
  }
  Bsp<TestType> p(band, SD::parameters::symmetry_order(2));
  p.set_field(field_map(band, tangent), 7.3 / diagonal(band));
  p.solve();
  const double energy = p.energy();
  REQUIRE_THROWS_WITH(p.set_boundary_on_level_lines(true),
                      Catch::Matchers::Contains("the field runs along the boundary"));
  REQUIRE_FALSE(p.boundary_on_level_lines()); // nothing changed
  p.solve();
  REQUIRE(p.energy() == energy);
  // a cross field normal to both circles of the band has no cone: the root face closes by Stokes,
  // so the windings of the two loops on the family along them must cancel: one free direction
  // for the pair (and none for a loop alone, see the disks of the quad tests)
  Bsp<TestType> c(band, SD::parameters::symmetry_order(4));
  c.set_boundary_on_level_lines(true);
  c.set_field(field_map(band, smoothest_normal_to_boundary(band, 4)), 7.3 / diagonal(band));
  REQUIRE(c.branch_faces().empty());
  c.solve();
  // every face closes, the root's included: the stripe indices are all 0, on both families
  for(auto f : faces(band))
    for(int a = 0; a < 2; ++a)
      REQUIRE(c.stripe_index(f, a) == 0);
  const auto [off, along] = boundary_level_gaps(band, c);
  CHECK(off < 1e-8);
  CHECK(along < 1e-8);
}
