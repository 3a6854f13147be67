// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Developability energies (Stein, Grinspun & Crane 2018) per vertex star and summed over meshes:
// gradients against finite differences (random, open and near-developable stars), zero energy on
// hinges and flat stars, positive energy on cones, closed forms on regular cones, brute-force
// minima (splittings, unit directions), scale and rigid-motion invariance, degenerate stars, the
// vertex stars of Surface_mesh and Polyhedron_3, mesh totals against independently built stars and
// finite differences, valence-3 omission, parallel and sequential results bitwise identical.

#include <test_support.h>

#include <CGAL/Surface_design/developability_energy.h>
#include <CGAL/Surface_design/internal/Core/geometry.h>
#include <CGAL/Surface_design/internal/Core/Mesh_indices.h>
#include <CGAL/Surface_design/internal/Core/validation.h>
#include <CGAL/Surface_design/internal/Developability/star_energies.h>
#include <CGAL/Surface_design/internal/Developability/vertex_stars.h>
#include <CGAL/Surface_design/mesh_generators.h>

#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>

#include <Eigen/Dense>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/global_control.h>
#include <tbb/task_arena.h>
#endif

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstring>
#include <iomanip>
#include <iostream>
#include <map>
#include <random>
#include <set>
#include <vector>

namespace SD = CGAL::Surface_design;
namespace SDI = CGAL::Surface_design::internal;

namespace {

using SD::Developability_energy;
using SDI::pi;
using Vec = Eigen::Vector3d;
using Vecs = std::vector<Vec>;

const std::array<Developability_energy, 8> all_energies = {
  Developability_energy::combinatorial,  Developability_energy::combinatorial_max,
  Developability_energy::covariance,     Developability_energy::covariance_max,
  Developability_energy::intrinsic,      Developability_energy::intrinsic_width,
  Developability_energy::squared_angle_defect, Developability_energy::absolute_angle_defect};

// Where finite differences may straddle a kink: the min/max energies where the minimizing
// splitting or candidate or the maximizing face changes, the eigenvalue energies where their
// smallest eigenvalue is repeated (frequent near flat stars, whose two smallest eigenvalues are
// both of the order of the squared noise). Only the angle defect is smooth everywhere.
bool smooth_everywhere(Developability_energy e) { return e == Developability_energy::squared_angle_defect; }

// Finite differences: fourth-order central differences with step h (truncation ~ h^4, rounding
// ~ 1e-16 |E| / h), and the same with h / 2. Where both agree the function is smooth across the
// stencil; if the analytic gradient then differs, the formula is wrong. Where they disagree, a
// kink (a change of the minimizing splitting or candidate, of the maximizing face, or a crossing
// of eigenvalues) lies within the stencil: a star is then perturbed away from it and checked
// again; a mesh coordinate or direction is skipped.
constexpr double fd_relative_step = 1e-5;
constexpr double fd_tolerance = 1e-6;         // relative error of a gradient where smooth
constexpr double fd_smoothness_ratio = 0.1;   // the two steps agree to fd_tolerance * this
constexpr int max_perturbations = 8;
constexpr double fd_gradient_floor = 1e-4;
constexpr double zero_energy_tolerance = 1e-14;
// a gradient this small is rounding: the energy is constant (the absolute angle defect summed
// over a closed surface whose defects all have one sign is 2 pi chi)
constexpr double constant_gradient_norm = 1e-12;

template <class F>
double central_difference(const F& f, double h)
{
  return (8. * (f(h) - f(-h)) - (f(2. * h) - f(-2. * h))) / (12. * h);
}

double norm(const Vecs& v)
{
  double s = 0.;
  for(const Vec& x : v)
    s += x.squaredNorm();
  return std::sqrt(s);
}

double distance(const Vecs& a, const Vecs& b)
{
  double s = 0.;
  for(std::size_t i = 0; i < a.size(); ++i)
    s += (a[i] - b[i]).squaredNorm();
  return std::sqrt(s);
}

// ------------------------------------------------------------------------------------------------
// Stars
// ------------------------------------------------------------------------------------------------

struct Star
{
  Vec center = Vec::Zero();
  Vecs ring;
  bool closed = true;

  std::size_t number_of_points() const { return ring.size() + 1; }
  Vec& point(std::size_t i) { return i == 0 ? center : ring[i - 1]; }
  const Vec& point(std::size_t i) const { return i == 0 ? center : ring[i - 1]; }
  std::size_t number_of_faces() const { return closed ? ring.size() : ring.size() - 1; }
  // independent of the library: unit normal and corner angle at the centre of face k
  Vec normal(std::size_t k) const
  {
    return (ring[k] - center).cross(ring[(k + 1) % ring.size()] - center).normalized();
  }
  double angle(std::size_t k) const
  {
    const Vec a = ring[k] - center, b = ring[(k + 1) % ring.size()] - center;
    return std::atan2(a.cross(b).norm(), a.dot(b));
  }
  double size() const
  {
    double r = 0.;
    for(const Vec& p : ring)
      r = (std::max)(r, (p - center).norm());
    return r;
  }
};

double energy_of(Developability_energy e, const Star& s, Vecs* gradient = nullptr)
{
  if(gradient)
    gradient->assign(s.number_of_points(), Vec::Constant(std::nan("")));
  return SDI::star_energy(e, s.center, s.ring.data(), s.ring.size(), s.closed, gradient ? gradient->data() : nullptr);
}

Vecs fd_gradient(Developability_energy e, Star s, double h)
{
  Vecs g(s.number_of_points());
  for(std::size_t i = 0; i < s.number_of_points(); ++i)
    for(int c = 0; c < 3; ++c)
    {
      const double x = s.point(i)[c];
      g[i][c] = central_difference(
        [&](double t) {
          s.point(i)[c] = x + t;
          const double value = energy_of(e, s);
          s.point(i)[c] = x;
          return value;
        },
        h);
    }
  return g;
}

struct Gradient_check
{
  double error = 0.;      // relative error of the analytic gradient against finite differences
  int perturbations = 0;  // how many times the star was moved away from a kink
  bool smooth = true;     // false: still at a kink after max_perturbations
};

Gradient_check check_star_gradient(Developability_energy e, Star s, std::mt19937& rng,
                                   double relative_step = fd_relative_step)
{
  Gradient_check r;
  for(;; ++r.perturbations)
  {
    Vecs g;
    energy_of(e, s, &g);
    const double h = relative_step * s.size();
    const Vecs fd = fd_gradient(e, s, h);
    // Rounding limits the finite differences to about 1e-16 * (sum of the angles) / h = 1e-10
    // absolute: gradients smaller than fd_gradient_floor are compared absolutely.
    const double denominator = (std::max)(norm(fd), fd_gradient_floor / s.size());
    r.error = distance(g, fd) / denominator;
    r.smooth = true;
    if(r.error <= fd_tolerance)
      return r;
    r.smooth = distance(fd, fd_gradient(e, s, h / 2.)) <= fd_smoothness_ratio * fd_tolerance * denominator;
    if(r.smooth || r.perturbations == max_perturbations)
      return r;
    // a kink within 2h: move every point by up to 10 h
    std::uniform_real_distribution<double> u(-10. * h, 10. * h);
    for(std::size_t i = 0; i < s.number_of_points(); ++i)
      s.point(i) += Vec(u(rng), u(rng), u(rng));
  }
}

Eigen::Matrix3d random_rotation(std::mt19937& rng)
{
  std::normal_distribution<double> n(0., 1.);
  Eigen::Quaterniond q(n(rng), n(rng), n(rng), n(rng));
  return q.normalized().toRotationMatrix();
}

Star transformed(const Star& s, const Eigen::Matrix3d& R, const Vec& t, double scale = 1.)
{
  Star r = s;
  for(std::size_t i = 0; i < r.number_of_points(); ++i)
    r.point(i) = scale * (R * s.point(i)) + t;
  return r;
}

Star randomly_placed(const Star& s, std::mt19937& rng)
{
  std::uniform_real_distribution<double> u(-2., 2.);
  return transformed(s, random_rotation(rng), Vec(u(rng), u(rng), u(rng)));
}

// Ring angles: `degree` increasing angles covering 2 pi (closed) or [0, span] (open, first and
// last exactly at the ends), each jittered by up to `jitter` times the spacing.
std::vector<double> ring_angles(std::size_t degree, bool closed, double span, double jitter, std::mt19937& rng)
{
  std::uniform_real_distribution<double> u(-jitter, jitter);
  std::vector<double> a(degree);
  const double step = closed ? 2. * pi / double(degree) : span / double(degree - 1);
  for(std::size_t k = 0; k < degree; ++k)
  {
    a[k] = step * double(k);
    if(closed || (k > 0 && k + 1 < degree))
      a[k] += step * u(rng);
  }
  return a;
}

// A random, generally curved star: ring at random radii and heights (|z| <= height).
Star random_star(std::size_t degree, bool closed, double height, std::mt19937& rng)
{
  std::uniform_real_distribution<double> radius(0.6, 1.4), z(-height, height), span(0.7 * pi, 1.5 * pi);
  Star s;
  s.closed = closed;
  for(double a : ring_angles(degree, closed, span(rng), 0.3, rng))
  {
    const double r = radius(rng);
    s.ring.emplace_back(r * std::cos(a), r * std::sin(a), z(rng));
  }
  return randomly_placed(s, rng);
}

// A flat star (closed, or an open fan spanning exactly pi: a straight boundary, zero angle
// defect), folded by `fold` radians about the spoke of ring vertex `hinge` (the antiparallel
// spoke is ring vertex hinge + degree / 2 on a closed star): the ring vertices after the hinge
// spoke, and up to the antiparallel one, rotate. A hinge in the sense of Definition 3.1.
Star hinge_star(std::size_t degree, bool closed, std::size_t hinge, double fold, std::mt19937& rng)
{
  std::uniform_real_distribution<double> radius(0.6, 1.4);
  Star s;
  s.closed = closed;
  std::vector<double> a = ring_angles(degree, closed, pi, 0.15, rng);
  std::size_t last = degree; // ring vertices hinge + 1, ..., last - 1 rotate
  if(closed)
  {
    // make spoke `hinge + degree / 2` exactly opposite spoke `hinge`
    last = hinge + degree / 2;
    a[last] = a[hinge] + pi;
  }
  for(double angle : a)
  {
    const double r = radius(rng);
    s.ring.emplace_back(r * std::cos(angle), r * std::sin(angle), 0.);
  }
  const Vec axis = s.ring[hinge].normalized();
  const Eigen::AngleAxisd rotation(fold, axis);
  for(std::size_t k = hinge + 1; k < last; ++k)
    s.ring[k] = rotation * s.ring[k];
  return randomly_placed(s, rng);
}

Star with_noise(Star s, double amplitude, std::mt19937& rng)
{
  std::uniform_real_distribution<double> u(-amplitude, amplitude);
  for(Vec& p : s.ring)
    p += Vec(u(rng), u(rng), u(rng));
  s.center += Vec(u(rng), u(rng), u(rng));
  return s;
}

// Apex of the cone z = -height * r over the unit circle, ring at the regular angles 2 pi k / d.
Star regular_cone(std::size_t degree, double height)
{
  Star s;
  for(std::size_t k = 0; k < degree; ++k)
  {
    const double a = 2. * pi * double(k) / double(degree);
    s.ring.emplace_back(std::cos(a), std::sin(a), -height);
  }
  return s;
}

// ------------------------------------------------------------------------------------------------
// Independent reference values
// ------------------------------------------------------------------------------------------------

// Contiguous splittings by brute force over subsets; cost of eq. 1 by its pair form
// (1/n^2) sum over unordered pairs, or the largest pair difference of eq. 5.
double brute_force_combinatorial(const Star& s, bool use_max)
{
  const std::size_t m = s.number_of_faces();
  double best = std::numeric_limits<double>::infinity();
  for(unsigned mask = 1; mask + 1 < (1u << m); ++mask)
  {
    // both regions contiguous: 2 changes around the cycle (closed) or 1 along the path (open)
    std::size_t changes = 0;
    for(std::size_t k = 0; k + 1 < m; ++k)
      changes += ((mask >> k) & 1u) != ((mask >> (k + 1)) & 1u);
    if(s.closed)
      changes += ((mask >> (m - 1)) & 1u) != (mask & 1u);
    if(changes != (s.closed ? 2u : 1u))
      continue;
    double cost[2] = {0., 0.};
    for(unsigned side = 0; side < 2; ++side)
    {
      std::vector<std::size_t> region;
      for(std::size_t k = 0; k < m; ++k)
        if(((mask >> k) & 1u) == side)
          region.push_back(k);
      double pair_sum = 0., pair_max = 0.;
      for(std::size_t i = 0; i < region.size(); ++i)
        for(std::size_t j = i + 1; j < region.size(); ++j)
        {
          const double d = (s.normal(region[i]) - s.normal(region[j])).squaredNorm();
          pair_sum += d;
          pair_max = (std::max)(pair_max, d);
        }
      cost[side] = use_max ? pair_max : pair_sum / double(region.size() * region.size());
    }
    best = (std::min)(best, use_max ? (std::max)(cost[0], cost[1]) : cost[0] + cost[1]);
  }
  return best;
}

// The log-mapped normals of App. B.5 with an explicit tangent basis (t1, t2): 2D points.
std::vector<Eigen::Vector2d> log_mapped_normals(const Star& s, Vec* vertex_normal = nullptr)
{
  Vec n = Vec::Zero();
  for(std::size_t k = 0; k < s.number_of_faces(); ++k)
    n += (s.ring[k] - s.center).cross(s.ring[(k + 1) % s.ring.size()] - s.center);
  const Vec N = n.normalized();
  const Vec t1 = (std::abs(N.x()) < 0.9 ? Vec::UnitX() : Vec::UnitY()).cross(N).normalized();
  const Vec t2 = N.cross(t1);
  std::vector<Eigen::Vector2d> p;
  for(std::size_t k = 0; k < s.number_of_faces(); ++k)
  {
    const Vec Nf = s.normal(k);
    const double angle = std::atan2(N.cross(Nf).norm(), N.dot(Nf));
    const Vec direction = (Nf - N.dot(Nf) * N).normalized();
    p.emplace_back(angle * direction.dot(t1), angle * direction.dot(t2));
  }
  if(vertex_normal)
    *vertex_normal = N;
  return p;
}

double reference_intrinsic(const Star& s)
{
  const std::vector<Eigen::Vector2d> p = log_mapped_normals(s);
  double a = 0., b = 0., c = 0.;
  for(std::size_t k = 0; k < p.size(); ++k)
  {
    a += s.angle(k) * p[k].x() * p[k].x();
    b += s.angle(k) * p[k].x() * p[k].y();
    c += s.angle(k) * p[k].y() * p[k].y();
  }
  // smallest root of the characteristic polynomial, in the cancellation-free form det / lambda_max
  const double lambda_max = 0.5 * (a + c) + std::hypot(0.5 * (a - c), b);
  return lambda_max > 0. ? (a * c - b * b) / lambda_max : 0.;
}

// min over a dense set of unit directions u (in 3D: `dimension` 3; in the tangent plane of the
// log map: 2) of max_f <u, v_f>^2, refined twice around the best sample.
double sampled_min_max(const Vecs& v, int dimension)
{
  auto phi = [&v](const Vec& u) {
    double m = 0.;
    for(const Vec& x : v)
      m = (std::max)(m, u.dot(x) * u.dot(x));
    return m;
  };
  double best = std::numeric_limits<double>::infinity();
  if(dimension == 2)
  {
    double best_angle = 0., radius = pi / 2.;
    for(int level = 0; level < 3; ++level)
    {
      const int n = 20000;
      const double centre = best_angle;
      for(int i = -n; i <= n; ++i)
      {
        const double a = centre + radius * double(i) / n;
        const double value = phi(Vec(std::cos(a), std::sin(a), 0.));
        if(value < best)
        {
          best = value;
          best_angle = a;
        }
      }
      radius *= 4. / n;
    }
    return best;
  }
  // Fibonacci sphere (spacing about 0.018), then grid refinements around the 40 best samples
  const int n = 40000;
  std::vector<std::pair<double, Vec>> samples;
  for(int i = 0; i < n; ++i)
  {
    const double z = 1. - (2. * i + 1.) / n, r = std::sqrt(1. - z * z), a = i * pi * (3. - std::sqrt(5.));
    const Vec u(r * std::cos(a), r * std::sin(a), z);
    samples.emplace_back(phi(u), u);
  }
  std::partial_sort(samples.begin(), samples.begin() + 40, samples.end(),
                    [](const auto& a, const auto& b) { return a.first < b.first; });
  for(int start = 0; start < 40; ++start)
  {
    Vec centre = samples[std::size_t(start)].second;
    double value = samples[std::size_t(start)].first;
    for(double radius = 0.03; radius > 1e-9; radius /= 8.)
    {
      const Vec t1 = centre.unitOrthogonal(), t2 = centre.cross(t1);
      const Vec previous = centre;
      for(int i = -20; i <= 20; ++i)
        for(int j = -20; j <= 20; ++j)
        {
          const Vec u = (previous + radius * (i / 20. * t1 + j / 20. * t2)).normalized();
          const double candidate = phi(u);
          if(candidate < value)
          {
            value = candidate;
            centre = u;
          }
        }
    }
    best = (std::min)(best, value);
  }
  return best;
}

// ------------------------------------------------------------------------------------------------
// Meshes (soups converted to each mesh type)
// ------------------------------------------------------------------------------------------------

struct Soup
{
  std::vector<std::array<double, 3>> points;
  std::vector<std::array<std::size_t, 3>> triangles;
};

template <class Mesh>
Mesh to_mesh(const Soup& soup)
{
  std::vector<test::Point> points;
  for(const auto& p : soup.points)
    points.emplace_back(p[0], p[1], p[2]);
  Mesh mesh;
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, soup.triangles, mesh);
  return mesh;
}

// Moves every point by up to `amplitude` along each axis (deterministic).
void add_noise(Soup& soup, double amplitude, unsigned seed)
{
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-amplitude, amplitude);
  for(auto& p : soup.points)
    for(double& c : p)
      c += u(rng);
}

// Subdivided icosahedron on the unit sphere: 12, 42, 162, ... vertices.
Soup icosphere(int levels)
{
  const double t = (1. + std::sqrt(5.)) / 2.;
  Soup s;
  for(const auto& p : std::vector<std::array<double, 3>>{{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0},
                                                       {0, -1, t}, {0, 1, t}, {0, -1, -t}, {0, 1, -t},
                                                       {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}})
    s.points.push_back(p);
  s.triangles = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
                 {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
                 {3, 8, 9},  {4, 9, 5},  {2, 4, 11},  {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
  auto project = [&s]() {
    for(auto& p : s.points)
    {
      const double r = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
      p = {p[0] / r, p[1] / r, p[2] / r};
    }
  };
  project();
  for(int l = 0; l < levels; ++l)
  {
    std::map<std::pair<std::size_t, std::size_t>, std::size_t> midpoint;
    auto mid = [&](std::size_t a, std::size_t b) {
      const auto key = std::minmax(a, b);
      auto it = midpoint.find(key);
      if(it != midpoint.end())
        return it->second;
      const auto& p = s.points[a];
      const auto& q = s.points[b];
      s.points.push_back({(p[0] + q[0]) / 2, (p[1] + q[1]) / 2, (p[2] + q[2]) / 2});
      return midpoint[key] = s.points.size() - 1;
    };
    std::vector<std::array<std::size_t, 3>> finer;
    for(const auto& f : s.triangles)
    {
      const std::size_t a = mid(f[0], f[1]), b = mid(f[1], f[2]), c = mid(f[2], f[0]);
      finer.push_back({f[0], a, c});
      finer.push_back({f[1], b, a});
      finer.push_back({f[2], c, b});
      finer.push_back({a, b, c});
    }
    s.triangles = finer;
    project();
  }
  return s;
}

// Open cylinder (two boundary loops) of radius 1, `rows` rows of `around` quads split into
// triangles. Not staggered: every quad is planar, the mesh is developable (every interior star a
// hinge). Staggered: every other ring is rotated by half a step (curved stars).
Soup cylinder(std::size_t around, std::size_t rows, bool staggered)
{
  Soup s;
  for(std::size_t j = 0; j <= rows; ++j)
    for(std::size_t i = 0; i < around; ++i)
    {
      const double a = 2. * pi * (double(i) + (staggered ? 0.5 * double(j % 2) : 0.)) / double(around);
      s.points.push_back({std::cos(a), std::sin(a), 0.4 * double(j)});
    }
  auto id = [around](std::size_t i, std::size_t j) { return j * around + i % around; };
  for(std::size_t j = 0; j < rows; ++j)
    for(std::size_t i = 0; i < around; ++i)
      if(!staggered || j % 2 == 0)
      {
        s.triangles.push_back({id(i, j), id(i + 1, j), id(i, j + 1)});
        s.triangles.push_back({id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
      }
      else
      {
        s.triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
        s.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
      }
  return s;
}

// A saddle-shaped disk: n x n grid over [-1, 1]^2 with alternating diagonals.
Soup saddle_patch(std::size_t n)
{
  Soup s;
  for(std::size_t j = 0; j <= n; ++j)
    for(std::size_t i = 0; i <= n; ++i)
    {
      const double x = 2. * double(i) / double(n) - 1., y = 2. * double(j) / double(n) - 1.;
      s.points.push_back({x, y, 0.3 * (x * x - 0.6 * y * y) + 0.1 * x * y});
    }
  auto id = [n](std::size_t i, std::size_t j) { return j * (n + 1) + i; };
  for(std::size_t j = 0; j < n; ++j)
    for(std::size_t i = 0; i < n; ++i)
      if((i + j) % 2 == 0)
      {
        s.triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
        s.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
      }
      else
      {
        s.triangles.push_back({id(i, j), id(i + 1, j), id(i, j + 1)});
        s.triangles.push_back({id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
      }
  return s;
}

// The surface of the cube [-1, 1]^3, each side an n x n grid (n even) whose diagonals run
// perpendicular to the direction of the side's centre: every cube corner has valence 3.
Soup cube_like(std::size_t n)
{
  Soup s;
  std::map<std::array<long, 3>, std::size_t> id; // lattice point (in units of 2 / n) -> index
  auto vertex = [&](const std::array<long, 3>& p) {
    auto it = id.find(p);
    if(it != id.end())
      return it->second;
    const double h = 2. / double(n);
    s.points.push_back({-1. + h * p[0], -1. + h * p[1], -1. + h * p[2]});
    return id[p] = s.points.size() - 1;
  };
  const long N = long(n);
  for(int axis = 0; axis < 3; ++axis)
    for(long side : {0L, N})
    {
      const int u = (axis + 1) % 3, v = (axis + 2) % 3;
      for(long i = 0; i < N; ++i)
        for(long j = 0; j < N; ++j)
        {
          auto P = [&](long a, long b) {
            std::array<long, 3> p{};
            p[axis] = side;
            p[u] = a;
            p[v] = b;
            return p;
          };
          // diagonal perpendicular to the direction of the side's centre: in the lower-left
          // and upper-right quadrants it joins (i + 1, j) and (i, j + 1)
          const bool anti = (2 * i + 1 < N) == (2 * j + 1 < N);
          std::array<std::array<long, 3>, 3> t1, t2;
          if(anti)
          {
            t1 = {P(i, j), P(i + 1, j), P(i, j + 1)};
            t2 = {P(i + 1, j), P(i + 1, j + 1), P(i, j + 1)};
          }
          else
          {
            t1 = {P(i, j), P(i + 1, j), P(i + 1, j + 1)};
            t2 = {P(i, j), P(i + 1, j + 1), P(i, j + 1)};
          }
          for(auto t : {t1, t2})
          {
            if(side == 0) // (u, v, axis) is right-handed: flip the lower side to face outwards
              std::swap(t[1], t[2]);
            s.triangles.push_back({vertex(t[0]), vertex(t[1]), vertex(t[2])});
          }
        }
    }
  return s;
}

template <class Mesh>
Vecs positions(const SDI::Mesh_indices<Mesh>& idx)
{
  Vecs x(idx.number_of_vertices());
  for(std::size_t v = 0; v < x.size(); ++v)
    x[v] = SDI::position(get(CGAL::vertex_point, idx.mesh()), idx.vertex(v));
  return x;
}

// Stars built without halfedge navigation: from the faces, "after ring vertex b comes c" around
// each corner; an open chain starts at the vertex that follows nothing.
struct Reference_star
{
  std::vector<std::size_t> ring;
  bool closed = true;
};

template <class Mesh>
std::vector<Reference_star> reference_stars(const SDI::Mesh_indices<Mesh>& idx)
{
  const Mesh& tm = idx.mesh();
  std::vector<std::map<std::size_t, std::size_t>> after(idx.number_of_vertices());
  for(std::size_t f = 0; f < idx.number_of_faces(); ++f)
  {
    std::vector<std::size_t> c;
    for(auto v : vertices_around_face(halfedge(idx.face(f), tm), tm))
      c.push_back(idx.index(v));
    for(int i = 0; i < 3; ++i)
      after[c[i]][c[(i + 1) % 3]] = c[(i + 2) % 3];
  }
  std::vector<Reference_star> stars(idx.number_of_vertices());
  for(std::size_t v = 0; v < stars.size(); ++v)
  {
    std::set<std::size_t> followers;
    for(const auto& [b, c] : after[v])
      followers.insert(c);
    std::size_t start = after[v].begin()->first;
    for(const auto& [b, c] : after[v])
      if(!followers.count(b))
      {
        start = b;
        stars[v].closed = false;
      }
    std::size_t r = start;
    do
    {
      stars[v].ring.push_back(r);
      auto it = after[v].find(r);
      r = it == after[v].end() ? std::size_t(-1) : it->second;
    } while(r != std::size_t(-1) && r != start);
  }
  return stars;
}

Star star_at(const Reference_star& r, const Vecs& x, std::size_t v)
{
  Star s;
  s.center = x[v];
  s.closed = r.closed;
  for(std::size_t k : r.ring)
    s.ring.push_back(x[k]);
  return s;
}

bool bitwise_equal(const Vecs& a, const Vecs& b)
{
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(Vec)) == 0);
}
bool bitwise_equal(const std::vector<double>& a, const std::vector<double>& b)
{
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0);
}

struct Named_soup
{
  const char* name;
  Soup soup;
};

std::vector<Named_soup> small_meshes()
{
  Soup sphere = icosphere(1);
  add_noise(sphere, 0.03, 1);
  Soup tube = cylinder(10, 4, true);
  add_noise(tube, 0.03, 2);
  Soup saddle = saddle_patch(6);
  add_noise(saddle, 0.02, 3);
  Soup cube = cube_like(2);
  add_noise(cube, 0.02, 4);
  return {{"noisy icosphere", sphere}, {"noisy cylinder", tube}, {"noisy saddle disk", saddle}, {"noisy cube", cube}};
}

} // namespace

// ================================================================================================
// Single stars
// ================================================================================================

TEST_CASE("Star gradients match finite differences", "[developability][gradient]")
{
  std::mt19937 rng(20180705);
  struct Case
  {
    const char* name;
    bool closed;
    double noise; // < 0: a random curved star; else a hinge (or flat star) with this noise
    bool flat;    // fold 0: the log map factors take their series branch (angles < 1e-2)
    // finite difference step: features (kinks, near-repeated eigenvalues) are about
    // noise * noise apart in energy and noise apart in positions; steps well below that
    double step() const { return noise < 0. || noise >= 1e-2 ? fd_relative_step : 1e-3 * noise; }
  };
  for(const Case& c : {Case{"random closed", true, -1., false}, Case{"random open", false, -1., false},
                       Case{"hinge + 1e-2 noise, closed", true, 1e-2, false},
                       Case{"hinge + 1e-2 noise, open", false, 1e-2, false},
                       Case{"hinge + 1e-3 noise, closed", true, 1e-3, false},
                       Case{"hinge + 1e-3 noise, open", false, 1e-3, false},
                       Case{"flat + 1e-3 noise, closed", true, 1e-3, true},
                       Case{"flat + 1e-3 noise, open", false, 1e-3, true}})
    for(Developability_energy e : all_energies)
    {
      // the absolute angle defect draws from a copy of the generator: the other energies see the
      // stars they saw before it was added
      std::mt19937 copy = rng;
      std::mt19937& rng_e = e == Developability_energy::absolute_angle_defect ? copy : rng;
      std::size_t perturbed = 0;
      double worst = 0.;
      for(std::size_t degree = 4; degree <= 8; ++degree)
        for(int trial = 0; trial < 12; ++trial)
        {
          Star s;
          if(c.noise < 0.)
            s = random_star(degree, c.closed, 0.35, rng_e);
          else
          {
            std::uniform_real_distribution<double> fold(0.3, 1.2);
            const std::size_t hinge = c.closed ? std::size_t(trial) % (degree / 2) : 1 + std::size_t(trial) % (degree - 2);
            s = with_noise(hinge_star(degree, c.closed, hinge, c.flat ? 0. : fold(rng_e), rng_e), c.noise, rng_e);
          }
          const Gradient_check r = check_star_gradient(e, s, rng_e, c.step());
          INFO(c.name << ", " << SD::to_string(e) << ", valence " << degree << ", trial " << trial
                      << ": relative error " << r.error << " after " << r.perturbations << " perturbations");
          CHECK(r.smooth);
          CHECK(r.error <= fd_tolerance);
          perturbed += r.perturbations > 0;
          worst = (std::max)(worst, r.error);
        }
      INFO(c.name << ", " << SD::to_string(e) << ": " << perturbed << " of 60 stars moved away from a kink");
      if(smooth_everywhere(e))
        CHECK(perturbed == 0);
      CHECK(perturbed <= 6); // kinks are rare: at most 10% of the stars start near one
      if(std::getenv("SD_REPORT"))
        std::cout << std::setw(30) << c.name << std::setw(22) << SD::to_string(e) << "  max relative error "
                  << std::scientific << std::setprecision(1) << worst << ", " << perturbed << " perturbed\n"
                  << std::defaultfloat;
    }
}

TEST_CASE("Hinge and flat stars have zero energy", "[developability]")
{
  std::mt19937 rng(3);
  for(std::size_t degree = 4; degree <= 9; ++degree)
    for(bool closed : {true, false})
    {
      const std::size_t hinges = closed ? degree / 2 : degree - 2;
      for(std::size_t hinge = closed ? 0 : 1; hinge < (closed ? hinges : hinges + 1); ++hinge)
        for(double fold : {0., 0.4, 1.3, 2.5})
        {
          const Star s = hinge_star(degree, closed, hinge, fold, rng);
          for(Developability_energy e : all_energies)
          {
            INFO(SD::to_string(e) << (closed ? ", closed" : ", open") << ", valence " << degree << ", hinge spoke "
                                  << hinge << ", fold " << fold);
            Vecs g;
            CHECK(std::abs(energy_of(e, s, &g)) <= zero_energy_tolerance);
            // a minimum: the gradient vanishes too (to rounding)
            CHECK(norm(g) <= 1e-7);
          }
        }
    }
  // An open fan folded at its first interior spoke: one region is a single face (the reason
  // single-face regions are allowed in E^P).
  Star s = hinge_star(5, false, 1, 0.9, rng);
  CHECK(energy_of(Developability_energy::combinatorial, s) <= zero_energy_tolerance);
  CHECK(energy_of(Developability_energy::combinatorial_max, s) <= zero_energy_tolerance);
}

TEST_CASE("Curved stars have positive energy", "[developability]")
{
  std::mt19937 rng(11);
  for(std::size_t degree = 3; degree <= 8; ++degree)
  {
    // a cone apex, and a vertex of a sphere with an irregular ring
    Star sphere;
    sphere.center = Vec(0., 0., 1.);
    for(double a : ring_angles(degree, true, 0., 0.3, rng))
      sphere.ring.emplace_back(std::sin(0.4) * std::cos(a), std::sin(0.4) * std::sin(a), std::cos(0.4));
    for(const Star& s : {randomly_placed(regular_cone(degree, 0.5), rng), randomly_placed(sphere, rng)})
      for(Developability_energy e : all_energies)
      {
        INFO(SD::to_string(e) << ", valence " << degree);
        CHECK(energy_of(e, s) > 1e-3);
      }
  }
}

TEST_CASE("Regular cones: closed forms", "[developability]")
{
  for(std::size_t degree = 3; degree <= 9; ++degree)
    for(double height : {0.2, 0.7, 2.})
    {
      const Star s = regular_cone(degree, height);
      const double d = double(degree);
      const double theta = s.angle(0);
      const double gamma = std::acos(s.normal(0).z()); // polar angle of every face normal
      INFO("valence " << degree << ", height " << height);
      // eq. 4: A = theta d (sin^2(gamma)/2 (I - z z^T) + cos^2(gamma) z z^T)
      const double covariance =
        theta * d * (std::min)(0.5 * std::sin(gamma) * std::sin(gamma), std::cos(gamma) * std::cos(gamma));
      CHECK(energy_of(Developability_energy::covariance, s) == Approx(covariance).epsilon(1e-12));
      // B.5: N_v = z, images gamma (cos b_k, sin b_k): A~ = theta d gamma^2 / 2 I
      CHECK(energy_of(Developability_energy::intrinsic, s) == Approx(theta * d * gamma * gamma / 2.).epsilon(1e-12));
      // B.5.1: +-images form a regular d-gon (d even) or 2d-gon (d odd) of circumradius gamma
      const double half_width = gamma * std::cos(pi / (degree % 2 == 0 ? d : 2. * d));
      CHECK(energy_of(Developability_energy::intrinsic_width, s) == Approx(half_width * half_width).epsilon(1e-12));
      const double defect = 2. * pi - d * theta;
      CHECK(energy_of(Developability_energy::squared_angle_defect, s) == Approx(defect * defect).epsilon(1e-12));
      CHECK(energy_of(Developability_energy::absolute_angle_defect, s) == Approx(std::abs(defect)).epsilon(1e-12));
    }
}

TEST_CASE("Energies equal independent brute-force minima", "[developability]")
{
  std::mt19937 rng(5);
  for(std::size_t degree = 3; degree <= 8; ++degree)
    for(bool closed : {true, false})
      for(int trial = 0; trial < 4; ++trial)
      {
        const Star s = trial % 2 == 0 ? random_star(degree, closed, 0.4, rng)
                                      : with_noise(hinge_star(std::max<std::size_t>(degree, 4), closed, 1, 0.8, rng), 0.05, rng);
        INFO((closed ? "closed" : "open") << ", valence " << s.ring.size() << ", trial " << trial);
        const std::size_t m = s.number_of_faces();
        Vecs normals;
        for(std::size_t k = 0; k < m; ++k)
          normals.push_back(s.normal(k));

        CHECK(energy_of(Developability_energy::combinatorial, s) ==
              Approx(brute_force_combinatorial(s, false)).epsilon(1e-12).margin(1e-15));
        CHECK(energy_of(Developability_energy::combinatorial_max, s) ==
              Approx(brute_force_combinatorial(s, true)).epsilon(1e-12).margin(1e-15));

        // eq. 3 as a minimum over unit vectors: no sampled direction beats lambda_min
        const double covariance = energy_of(Developability_energy::covariance, s);
        Eigen::Matrix3d A = Eigen::Matrix3d::Zero();
        for(std::size_t k = 0; k < m; ++k)
          A += s.angle(k) * normals[k] * normals[k].transpose();
        CHECK(covariance == Approx(A.eigenvalues().real().minCoeff()).epsilon(1e-10).margin(1e-14));

        // eq. 6: E is phi at a candidate, so E >= min phi; no sample may beat it, and the refined
        // sampling comes within its resolution
        const double cov_max = energy_of(Developability_energy::covariance_max, s);
        const double sampled = sampled_min_max(normals, 3);
        CHECK(cov_max <= sampled + 1e-15);
        CHECK(cov_max >= sampled - 1e-6);

        // B.5 with an explicit basis and a closed-form 2x2 eigenvalue
        CHECK(energy_of(Developability_energy::intrinsic, s) ==
              Approx(reference_intrinsic(s)).epsilon(1e-10).margin(1e-15));

        // B.5.1 by sampling tangent directions
        Vecs images;
        for(const Eigen::Vector2d& p : log_mapped_normals(s))
          images.emplace_back(p.x(), p.y(), 0.);
        const double width = energy_of(Developability_energy::intrinsic_width, s);
        const double sampled_width = sampled_min_max(images, 2);
        CHECK(width <= sampled_width + 1e-14);
        CHECK(width >= sampled_width - 1e-8);
      }
}

TEST_CASE("Energies are scale and rigid-motion invariant", "[developability]")
{
  std::mt19937 rng(7);
  for(Developability_energy e : all_energies)
    for(std::size_t degree = 4; degree <= 8; ++degree)
      for(bool closed : {true, false})
      {
        INFO(SD::to_string(e) << ", valence " << degree << (closed ? ", closed" : ", open"));
        const Star s = random_star(degree, closed, 0.4, rng);
        Vecs g;
        const double value = energy_of(e, s, &g);
        REQUIRE(value > 0.);

        // scaled by 7.3 about the origin: same energy, gradient / 7.3
        const double scale = 7.3;
        Vecs g_scaled;
        const double scaled = energy_of(e, transformed(s, Eigen::Matrix3d::Identity(), Vec::Zero(), scale), &g_scaled);
        CHECK(scaled == Approx(value).epsilon(1e-12));
        for(Vec& x : g_scaled)
          x *= scale;
        CHECK(distance(g_scaled, g) <= 1e-10 * norm(g));

        // rotated and translated: same energy, rotated gradient
        const Eigen::Matrix3d R = random_rotation(rng);
        Vecs g_moved;
        const double moved = energy_of(e, transformed(s, R, Vec(3., -1., 2.)), &g_moved);
        CHECK(moved == Approx(value).epsilon(1e-11));
        for(Vec& x : g)
          x = R * x;
        CHECK(distance(g_moved, g) <= 1e-9 * norm(g));

        // translation invariance of the gradient itself: the gradient sums to zero
        Vec sum = Vec::Zero();
        for(const Vec& x : g)
          sum += x;
        CHECK(sum.norm() <= 1e-12 * norm(g));
      }
}

TEST_CASE("Degenerate stars give finite energies and zero gradients", "[developability]")
{
  std::mt19937 rng(13);
  for(Developability_energy e : all_energies)
  {
    INFO(SD::to_string(e));
    Star s = random_star(6, true, 0.3, rng);
    // collapse ring vertex 2 onto ring vertex 3: face 2 has zero area
    s.ring[2] = s.ring[3];
    Vecs g;
    CHECK(std::isfinite(energy_of(e, s, &g)));
    CHECK(norm(g) == 0.);
    // a ring vertex on the centre
    s = random_star(5, false, 0.3, rng);
    s.ring[1] = s.center;
    CHECK(std::isfinite(energy_of(e, s, &g)));
    CHECK(norm(g) == 0.);
    // all points coincide
    s.ring.assign(5, s.center);
    CHECK(std::isfinite(energy_of(e, s, &g)));
    CHECK(norm(g) == 0.);
    // a star folded onto itself: the ring goes half-way around and back, the area vector
    // vanishes and half the normals are antipodal to the others (no vertex normal, and faces on
    // the cut locus of any log map)
    Star folded;
    folded.ring = {Vec(1, 0, 0), Vec(0, 1, 0), Vec(-1, 0, 0), Vec(0, 1, 0)};
    CHECK(std::isfinite(energy_of(e, folded, &g)));
    for(const Vec& x : g)
      CHECK(x.allFinite());
    if(e == Developability_energy::intrinsic || e == Developability_energy::intrinsic_width)
      CHECK(norm(g) == 0.);
    // no face
    Star single;
    single.closed = false;
    single.ring = {Vec(1, 0, 0)};
    CHECK(energy_of(e, single, &g) == 0.);
  }
}

// ================================================================================================
// Meshes
// ================================================================================================

TEMPLATE_TEST_CASE("Vertex stars: rings, activity and gather lists", "[developability][stars]", SD_MESH_TYPES)
{
  for(const auto& [name, soup] : small_meshes())
  {
    INFO(name);
    const TestType mesh = to_mesh<TestType>(soup);
    const SDI::Mesh_indices<TestType> idx(mesh);
    SDI::validate_mesh(idx, get(CGAL::vertex_point, mesh));
    const std::vector<Reference_star> reference = reference_stars(idx);
    for(bool boundary : {false, true})
    {
      const SDI::Vertex_stars stars = SDI::vertex_stars(idx, boundary, 4);
      REQUIRE(stars.number_of_vertices() == idx.number_of_vertices());
      std::vector<std::size_t> slot_vertex(stars.number_of_slots(), std::size_t(-1));
      for(std::size_t v = 0; v < stars.number_of_vertices(); ++v)
      {
        INFO("vertex " << v);
        const Reference_star& r = reference[v];
        CHECK(stars.closed[v] == r.closed);
        REQUIRE(stars.degree(v) == r.ring.size());
        std::vector<std::size_t> ring(stars.ring_of(v), stars.ring_of(v) + stars.degree(v));
        if(r.closed)
        {
          // the same cycle, starting at the smallest index
          CHECK(ring.front() == *std::min_element(r.ring.begin(), r.ring.end()));
          std::vector<std::size_t> rotated = r.ring;
          std::rotate(rotated.begin(), std::find(rotated.begin(), rotated.end(), ring.front()), rotated.end());
          CHECK(ring == rotated);
        }
        else
          CHECK(ring == r.ring); // the same fan, from the same boundary edge
        CHECK(stars.active[v] == ((r.closed || boundary) && r.ring.size() >= 4));
        if(stars.active[v])
        {
          slot_vertex[stars.block_begin(v)] = v;
          for(std::size_t k = 0; k < stars.degree(v); ++k)
            slot_vertex[stars.block_begin(v) + 1 + k] = ring[k];
        }
      }
      // every slot of an active star is gathered exactly once, by its vertex, in increasing order
      std::vector<int> gathered(stars.number_of_slots(), 0);
      for(std::size_t p = 0; p < stars.number_of_vertices(); ++p)
        for(std::size_t j = stars.gather_begin[p]; j < stars.gather_begin[p + 1]; ++j)
        {
          CHECK(slot_vertex[stars.gather_slot[j]] == p);
          ++gathered[stars.gather_slot[j]];
          if(j > stars.gather_begin[p])
            CHECK(stars.gather_slot[j - 1] < stars.gather_slot[j]);
        }
      for(std::size_t slot = 0; slot < gathered.size(); ++slot)
        CHECK(gathered[slot] == (slot_vertex[slot] == std::size_t(-1) ? 0 : 1));
    }
  }
}

TEMPLATE_TEST_CASE("Mesh totals: sum of the stars, gradient by finite differences, parallel = sequential",
                   "[developability][mesh]", SD_MESH_TYPES)
{
  std::mt19937 rng(17);
  for(const auto& [name, soup] : small_meshes())
  {
    const TestType mesh = to_mesh<TestType>(soup);
    const SDI::Mesh_indices<TestType> idx(mesh);
    SDI::validate_mesh(idx, get(CGAL::vertex_point, mesh));
    const Vecs x = positions(idx);
    const std::size_t nv = x.size();
    const std::vector<Reference_star> reference = reference_stars(idx);
    for(bool boundary : {false, true})
    {
      const SDI::Vertex_stars stars = SDI::vertex_stars(idx, boundary, 4);
      for(Developability_energy e : all_energies)
      {
        INFO(name << ", " << SD::to_string(e) << (boundary ? ", with boundary vertices" : ""));
        Vecs gradient, gradient_parallel;
        std::vector<double> per_vertex, per_vertex_parallel;
        const double total = SDI::developability_energy(stars, x, e, &gradient, &per_vertex, false);
        const double total_parallel =
          SDI::developability_energy(stars, x, e, &gradient_parallel, &per_vertex_parallel, true);
        CHECK(std::memcmp(&total, &total_parallel, sizeof(double)) == 0);
        CHECK(bitwise_equal(gradient, gradient_parallel));
        CHECK(bitwise_equal(per_vertex, per_vertex_parallel));
        CHECK(SDI::developability_energy(stars, x, e, nullptr, nullptr, true) == total);

        // the stars, built independently, one by one
        double sum = 0.;
        Vecs accumulated(nv, Vec::Zero());
        for(std::size_t v = 0; v < nv; ++v)
        {
          if(!stars.active[v])
          {
            CHECK(per_vertex[v] == 0.);
            continue;
          }
          const Star s = star_at(reference[v], x, v);
          Vecs g;
          const double value = energy_of(e, s, &g);
          CHECK(per_vertex[v] == Approx(value).epsilon(1e-12).margin(1e-15));
          sum += value;
          accumulated[v] += g[0];
          for(std::size_t k = 0; k < s.ring.size(); ++k)
            accumulated[reference[v].ring[k]] += g[1 + k];
        }
        CHECK(total == Approx(sum).epsilon(1e-12));
        CHECK(distance(gradient, accumulated) <= 1e-10 * norm(gradient));

        // finite differences of the total along random directions
        auto total_at = [&](const Vecs& y) { return SDI::developability_energy(stars, y, e, nullptr, nullptr, false); };
        std::normal_distribution<double> normal(0., 1.);
        int checked = 0;
        for(int trial = 0; trial < 6; ++trial)
        {
          Vecs direction(nv);
          for(Vec& d : direction)
            d = Vec(normal(rng), normal(rng), normal(rng));
          const double length = norm(direction);
          for(Vec& d : direction)
            d /= length;
          auto along = [&](double t) {
            Vecs y = x;
            for(std::size_t i = 0; i < nv; ++i)
              y[i] += t * direction[i];
            return total_at(y);
          };
          const double h = fd_relative_step; // meshes of unit size
          const double fd = central_difference(along, h), fd_fine = central_difference(along, h / 2.);
          double analytic = 0.;
          for(std::size_t i = 0; i < nv; ++i)
            analytic += gradient[i].dot(direction[i]);
          const double scale = norm(gradient);
          INFO("direction " << trial << ": analytic " << analytic << ", finite differences " << fd << ", " << fd_fine);
          if(scale <= constant_gradient_norm)
          {
            // a constant: sum |Omega| of a closed surface whose defects have one sign is 4 pi
            // (Gauss-Bonnet); the differences are rounding
            CHECK(e == Developability_energy::absolute_angle_defect);
            CHECK(std::abs(fd) <= 1e-7);
            ++checked;
            continue;
          }
          if(std::abs(fd - fd_fine) > fd_smoothness_ratio * fd_tolerance * scale)
          {
            CHECK(!smooth_everywhere(e));
            continue;
          }
          ++checked;
          CHECK(std::abs(analytic - fd) <= fd_tolerance * scale);
        }
        CHECK(checked >= 4);
      }
    }
  }
}

TEMPLATE_TEST_CASE("Mesh totals: every gradient entry by finite differences", "[developability][mesh]", SD_MESH_TYPES)
{
  for(const auto& [name, soup] : small_meshes())
  {
    const TestType mesh = to_mesh<TestType>(soup);
    const SDI::Mesh_indices<TestType> idx(mesh);
    const Vecs x = positions(idx);
    const SDI::Vertex_stars stars = SDI::vertex_stars(idx, true, 4);
    for(Developability_energy e : all_energies)
    {
      INFO(name << ", " << SD::to_string(e));
      Vecs gradient;
      SDI::developability_energy(stars, x, e, &gradient, nullptr, false);
      double error2 = 0., reference2 = 0.;
      std::size_t skipped = 0;
      Vecs y = x;
      for(std::size_t i = 0; i < x.size(); ++i)
        for(int c = 0; c < 3; ++c)
        {
          auto f = [&](double t) {
            y[i][c] = x[i][c] + t;
            const double value = SDI::developability_energy(stars, y, e, nullptr, nullptr, false);
            y[i][c] = x[i][c];
            return value;
          };
          const double fd = central_difference(f, fd_relative_step), fd_fine = central_difference(f, fd_relative_step / 2.);
          if(norm(gradient) <= constant_gradient_norm) // a constant (Gauss-Bonnet): see the test above
          {
            CHECK(e == Developability_energy::absolute_angle_defect);
            CHECK(std::abs(fd) <= 1e-7);
            continue;
          }
          if(std::abs(fd - fd_fine) > fd_smoothness_ratio * fd_tolerance * norm(gradient))
          {
            ++skipped;
            continue;
          }
          error2 += (fd - gradient[i][c]) * (fd - gradient[i][c]);
          reference2 += fd * fd;
        }
      CHECK(std::sqrt(error2) <= fd_tolerance * std::sqrt(reference2));
      if(std::getenv("SD_REPORT"))
        std::cout << std::setw(20) << name << std::setw(22) << SD::to_string(e) << "  relative error "
                  << std::scientific << std::setprecision(1) << std::sqrt(error2 / reference2) << ", " << skipped
                  << " of " << 3 * x.size() << " coordinates at a kink\n"
                  << std::defaultfloat;
      if(smooth_everywhere(e))
        CHECK(skipped == 0);
      CHECK(skipped * 20 <= 3 * x.size());
    }
  }
}

TEMPLATE_TEST_CASE("Valence-3 vertices carry no energy when the minimum valence is 4", "[developability][mesh]",
                   SD_MESH_TYPES)
{
  Soup soup = cube_like(4);
  add_noise(soup, 0.01, 9);
  const TestType mesh = to_mesh<TestType>(soup);
  const SDI::Mesh_indices<TestType> idx(mesh);
  const Vecs x = positions(idx);
  std::vector<std::size_t> corners;
  for(std::size_t v = 0; v < x.size(); ++v)
    if(std::abs(std::abs(x[v].x()) - 1.) < 0.05 && std::abs(std::abs(x[v].y()) - 1.) < 0.05 &&
       std::abs(std::abs(x[v].z()) - 1.) < 0.05)
      corners.push_back(v);
  REQUIRE(corners.size() == 8);

  const SDI::Vertex_stars omitted = SDI::vertex_stars(idx, false, 4);
  const SDI::Vertex_stars kept = SDI::vertex_stars(idx, false, 3);
  for(std::size_t v : corners)
  {
    CHECK(omitted.degree(v) == 3);
    CHECK(!omitted.active[v]);
    CHECK(kept.active[v]);
  }
  for(Developability_energy e : all_energies)
  {
    INFO(SD::to_string(e));
    std::vector<double> without, with;
    Vecs gradient;
    const double total_without = SDI::developability_energy(omitted, x, e, &gradient, &without, false);
    const double total_with = SDI::developability_energy(kept, x, e, nullptr, &with, false);
    double corner_energy = 0.;
    for(std::size_t v : corners)
    {
      CHECK(without[v] == 0.);
      CHECK(with[v] > 1e-3); // a cube corner is no hinge (Prop. A.3)
      corner_energy += with[v];
    }
    CHECK(total_with == Approx(total_without + corner_energy).epsilon(1e-12));
    // every other vertex of the cube has valence >= 4 and is active in both
    for(std::size_t v = 0; v < x.size(); ++v)
      if(std::find(corners.begin(), corners.end(), v) == corners.end())
        CHECK(with[v] == without[v]);
  }
}

TEMPLATE_TEST_CASE("Ruling directions and intrinsic lambda per vertex", "[developability][mesh]", SD_MESH_TYPES)
{
  // a noisy cylinder: rulings along the axis, small intrinsic lambda away from the boundary
  Soup soup = cylinder(16, 6, false);
  add_noise(soup, 1e-4, 21);
  const TestType mesh = to_mesh<TestType>(soup);
  const SDI::Mesh_indices<TestType> idx(mesh);
  const Vecs x = positions(idx);
  const SDI::Vertex_stars stars = SDI::vertex_stars(idx, false, 4);
  const SDI::Vertex_star_descriptors d = SDI::vertex_star_descriptors(stars, x, true);
  const SDI::Vertex_star_descriptors sequential = SDI::vertex_star_descriptors(stars, x, false);
  CHECK(bitwise_equal(d.ruling_direction, sequential.ruling_direction));
  CHECK(bitwise_equal(d.intrinsic_lambda, sequential.intrinsic_lambda));
  std::vector<double> intrinsic;
  SDI::developability_energy(stars, x, Developability_energy::intrinsic, nullptr, &intrinsic, false);
  for(std::size_t v = 0; v < x.size(); ++v)
  {
    INFO("vertex " << v);
    CHECK(d.ruling_direction[v].norm() == Approx(1.).epsilon(1e-12));
    if(stars.closed[v])
    {
      CHECK(std::abs(d.ruling_direction[v].z()) > 0.99);
      CHECK(d.intrinsic_lambda[v] == intrinsic[v]);
      CHECK(d.intrinsic_lambda[v] < 1e-5);
    }
  }
}

// Timing of one energy + gradient evaluation on a ~6k-vertex mesh (hidden: run with
// "[.timing]"). Sequential, then with TBB limited to 2 threads.
TEST_CASE("Timing of the energies on a 6k-vertex noisy sphere", "[.timing]")
{
  test::Surface_mesh mesh;
  SD::make_sphere(mesh, 32); // 6146 vertices
  std::mt19937 rng(99);
  std::uniform_real_distribution<double> u(-0.005, 0.005);
  for(auto v : vertices(mesh))
  {
    const test::Point& p = mesh.point(v);
    mesh.point(v) = test::Point(p.x() + u(rng), p.y() + u(rng), p.z() + u(rng));
  }
  const SDI::Mesh_indices<test::Surface_mesh> idx(mesh);
  const Vecs x = positions(idx);
  const SDI::Vertex_stars stars = SDI::vertex_stars(idx, true, 4);
  std::cout << "timing on " << x.size() << " vertices, " << stars.active_vertices.size() << " active stars\n";
#ifdef CGAL_LINKED_WITH_TBB
  tbb::global_control two_threads(tbb::global_control::max_allowed_parallelism, 2);
  REQUIRE(tbb::this_task_arena::max_concurrency() == 2);
#endif
  for(Developability_energy e : all_energies)
  {
    Vecs gradient;
    auto time = [&](bool parallel) {
      const int repetitions = 10;
      double best = std::numeric_limits<double>::infinity();
      SDI::developability_energy(stars, x, e, &gradient, nullptr, parallel); // warm-up
      for(int r = 0; r < repetitions; ++r)
      {
        const auto start = std::chrono::steady_clock::now();
        SDI::developability_energy(stars, x, e, &gradient, nullptr, parallel);
        best = (std::min)(best, std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
      }
      return best;
    };
    const double sequential = time(false);
#ifdef CGAL_LINKED_WITH_TBB
    const double parallel = time(true);
#else
    const double parallel = std::nan("");
#endif
    std::cout << std::setw(22) << SD::to_string(e) << ": sequential " << std::fixed << std::setprecision(2)
              << sequential << " ms, TBB (2 threads) " << parallel << " ms\n";
  }
}
