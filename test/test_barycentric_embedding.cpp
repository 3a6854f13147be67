// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Barycentric ("nice") embedding with fixed vertices (Imafuji & Ochiai): the barycentre
// conditions (uniform, cotangent, mean-value), Tutte's planar embedding, re-solves after moving
// the fixed vertices, the iterative reference, agreement with PMP::fair, the octahedron
// generator, bad input.

#include <test_support.h>

#include <CGAL/Surface_design/barycentric_embedding.h>
#include <CGAL/Surface_design/Barycentric_embedder.h>
#include <CGAL/Surface_design/internal/Core/topology.h>
#include <CGAL/Surface_design/mesh_generators.h>
#include <CGAL/Surface_design/octahedron_membrane.h>

#include <CGAL/boost/graph/generators.h>
#include <CGAL/Polygon_mesh_processing/fair.h>
#include <CGAL/Weights/cotangent_weights.h>
#include <CGAL/Weights/mean_value_weights.h>

#include <boost/property_map/function_property_map.hpp>

#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <typeinfo>
#include <set>
#include <vector>

namespace SD = CGAL::Surface_design;
namespace SDI = CGAL::Surface_design::internal;
namespace P = CGAL::Surface_design::parameters;

namespace {

template <class T>
struct Tag
{
  using type = T;
};

// Runs f(Tag<Traits>()) with every symmetric solver of the build.
template <class F>
void for_each_solver(F&& f)
{
  f(Tag<SD::Default_solver_traits>());
#if defined(CGAL_SURFACE_DESIGN_HAS_CHOLMOD)
  f(Tag<SD::Cholmod_solver_traits>());
#endif
}

template <class Mesh>
using Vertex = typename boost::graph_traits<Mesh>::vertex_descriptor;

template <class Mesh>
Eigen::Vector3d point(const Mesh& mesh, Vertex<Mesh> v)
{
  const auto& p = get(CGAL::vertex_point, mesh, v);
  return Eigen::Vector3d(p.x(), p.y(), p.z());
}

template <class Mesh>
std::vector<Eigen::Vector3d> positions(const Mesh& mesh)
{
  std::vector<Eigen::Vector3d> x;
  for(auto v : vertices(mesh))
    x.push_back(point(mesh, v));
  return x;
}

template <class Mesh>
double bbox_size(const Mesh& mesh)
{
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::max()), hi = -lo;
  for(auto v : vertices(mesh))
  {
    lo = lo.cwiseMin(point(mesh, v));
    hi = hi.cwiseMax(point(mesh, v));
  }
  return (hi - lo).norm();
}

double max_distance(const std::vector<Eigen::Vector3d>& a, const std::vector<Eigen::Vector3d>& b)
{
  REQUIRE(a.size() == b.size());
  double d = 0.;
  for(std::size_t i = 0; i < a.size(); ++i)
    d = (std::max)(d, (a[i] - b[i]).norm());
  return d;
}

template <class Mesh>
std::set<Vertex<Mesh>> border_vertices(const Mesh& mesh)
{
  std::set<Vertex<Mesh>> s;
  for(auto h : halfedges(mesh))
    if(is_border(h, mesh))
      s.insert(target(h, mesh));
  return s;
}

template <class Mesh>
auto set_map(const std::set<Vertex<Mesh>>& s)
{
  return boost::make_function_property_map<Vertex<Mesh>>([&s](Vertex<Mesh> v) { return s.count(v) > 0; });
}

// max over free vertices of |sum_j w_ij (x_j - x_i)| / sum_j |w_ij|: the weighted barycentre
// condition, with the weight of halfedge h (pointing from a neighbour to the free vertex) given
// by `weight(h)`, computed here independently of the library.
template <class Mesh, class Weight>
double barycentre_residual(const Mesh& mesh, const std::set<Vertex<Mesh>>& fixed, Weight&& weight)
{
  double worst = 0.;
  for(auto v : vertices(mesh))
  {
    if(fixed.count(v))
      continue;
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    double total = 0.;
    for(auto h : halfedges_around_target(v, mesh))
    {
      const double w = weight(h);
      sum += w * (point(mesh, source(h, mesh)) - point(mesh, v));
      total += std::abs(w);
    }
    worst = (std::max)(worst, sum.norm() / total);
  }
  return worst;
}

template <class Mesh>
double uniform_residual(const Mesh& mesh, const std::set<Vertex<Mesh>>& fixed)
{
  return barycentre_residual(mesh, fixed, [](auto) { return 1.; });
}

// The octahedron of the paper with its six loops fixed.
template <class Mesh>
std::set<Vertex<Mesh>> octahedron(Mesh& mesh, std::size_t m, double radius = 1.)
{
  const auto loops = SD::make_octahedron_membrane(mesh, m, radius);
  std::set<Vertex<Mesh>> fixed;
  for(const auto& loop : loops)
    fixed.insert(loop.begin(), loop.end());
  return fixed;
}

// A quad mesh (CGAL::make_grid, not triangulated) bent out of the plane, boundary fixed.
template <class Mesh>
std::set<Vertex<Mesh>> bent_quad_grid(Mesh& mesh, std::size_t n)
{
  using Point = typename boost::property_traits<
    typename boost::property_map<Mesh, CGAL::vertex_point_t>::type>::value_type;
  CGAL::make_grid(n, n, mesh, [n](std::size_t i, std::size_t j) {
    const double x = double(i) / double(n), y = double(j) / double(n);
    return Point(x, y, 0.3 * std::sin(3. * x) * std::cos(2. * y) + 0.1 * x * y);
  }, false);
  return border_vertices(mesh);
}

// A planar jittered grid (negative cotangent weights) whose boundary is lifted to a wavy
// non-planar curve: reference geometry = the planar grid.
template <class Mesh>
std::set<Vertex<Mesh>> lifted_grid(Mesh& mesh, Mesh& reference)
{
  SD::make_grid(reference, 12, 12, 0.3);
  mesh = reference;
  const std::set<Vertex<Mesh>> fixed = border_vertices(mesh);
  auto vpm = get(CGAL::vertex_point, mesh);
  for(auto v : fixed)
  {
    const auto p = get(vpm, v);
    put(vpm, v, test::Point(p.x(), p.y(), 0.2 * std::sin(6. * p.x()) + 0.3 * p.y() * p.y()));
  }
  return fixed;
}

// Maps vertices of `mesh` to those of its copy (same iteration order).
template <class Mesh>
std::map<Vertex<Mesh>, Vertex<Mesh>> vertex_correspondence(const Mesh& a, const Mesh& b)
{
  std::map<Vertex<Mesh>, Vertex<Mesh>> c;
  auto vb = vertices(b).begin();
  for(auto v : vertices(a))
    c.emplace(v, *vb++);
  return c;
}

} // namespace

TEMPLATE_TEST_CASE("uniform weights: every free vertex is the barycentre of its neighbours",
                   "[barycentric]", SD_MESH_TYPES)
{
  using Mesh = TestType;
  for_each_solver([](auto tag) {
    using Solver = typename decltype(tag)::type;
    INFO("solver " << typeid(Solver).name());
    {
      Mesh mesh;
      const auto fixed = octahedron(mesh, 4);
      const std::size_t moved = SD::barycentric_embedding(mesh, set_map<Mesh>(fixed),
                                                          P::sparse_linear_solver(Solver()));
      CHECK(moved == num_vertices(mesh) - fixed.size());
      CHECK(uniform_residual(mesh, fixed) <= 1e-10 * bbox_size(mesh));
    }
    {
      // any polygon mesh: quads
      Mesh mesh;
      const auto fixed = bent_quad_grid(mesh, 10);
      SD::barycentric_embedding(mesh, fixed, P::sparse_linear_solver(Solver())); // a range
      CHECK(uniform_residual(mesh, fixed) <= 1e-10 * bbox_size(mesh));
    }
    {
      // a scanned mesh with four holes: its boundary loops fixed
      Mesh mesh = test::load_mesh<Mesh>("mech-holes-shark.off");
      const auto fixed = border_vertices(mesh);
      SD::Barycentric_embedder<Mesh, typename boost::property_map<Mesh, CGAL::vertex_point_t>::type, Solver>
        embedder(mesh, fixed);
      embedder.update();
      CHECK(embedder.number_of_fixed_vertices() == fixed.size());
      CHECK(uniform_residual(mesh, fixed) <= 1e-10 * bbox_size(mesh));
      CHECK(embedder.barycentre_residual() <= 1e-10 * bbox_size(mesh));
    }
  });
}

TEMPLATE_TEST_CASE("cotangent and mean-value weights: the weighted barycentre conditions",
                   "[barycentric]", SD_MESH_TYPES)
{
  using Mesh = TestType;
  const test::Kernel kernel;
  for_each_solver([&](auto tag) {
    using Solver = typename decltype(tag)::type;
    Mesh reference, mesh;
    lifted_grid(mesh, reference);
    // the planar reference geometry, as a point map of a copy of `mesh`
    auto reference_of = [&reference](const Mesh& copy) {
      auto to_reference = std::make_shared<std::map<Vertex<Mesh>, Vertex<Mesh>>>(
        vertex_correspondence(copy, reference));
      return boost::make_function_property_map<Vertex<Mesh>>(
        [to_reference, &reference](Vertex<Mesh> v) { return get(CGAL::vertex_point, reference, to_reference->at(v)); });
    };

    // cotangent: w_ij = (cot a + cot b) / 2 of the planar reference (some negative)
    Mesh cot_mesh = mesh;
    const auto cot_fixed = border_vertices(cot_mesh);
    const auto cot_ref = reference_of(cot_mesh);
    SD::barycentric_embedding(cot_mesh, set_map<Mesh>(cot_fixed),
                              P::weighting(SD::Edge_weighting::cotangent,
                                           P::reference_point_map(cot_ref, P::sparse_linear_solver(Solver()))));
    std::size_t negative = 0;
    auto cotangent = [&](auto h) {
      double w = 0.;
      for(auto k : {h, opposite(h, cot_mesh)})
        if(!is_border(k, cot_mesh))
          w += 0.5 * CGAL::Weights::cotangent(get(cot_ref, source(k, cot_mesh)),
                                              get(cot_ref, target(next(k, cot_mesh), cot_mesh)),
                                              get(cot_ref, target(k, cot_mesh)), kernel);
      negative += (w < 0.);
      return w;
    };
    CHECK(barycentre_residual(cot_mesh, cot_fixed, cotangent) <= 1e-10 * bbox_size(cot_mesh));
    CHECK(negative > 0); // the jittered grid really has negative weights
    CHECK(uniform_residual(cot_mesh, cot_fixed) > 1e-4); // and they are not the uniform ones

    // mean value: w_ij = (tan(a/2) + tan(b/2)) / |x_j - x_i| of the planar reference, by CGAL's
    // four-point formula; the system is not symmetric (LU) whatever the solver
    Mesh mv_mesh = mesh;
    const auto mv_fixed = border_vertices(mv_mesh);
    const auto mv_ref = reference_of(mv_mesh);
    SD::barycentric_embedding(mv_mesh, set_map<Mesh>(mv_fixed),
                              P::weighting(SD::Edge_weighting::mean_value,
                                           P::reference_point_map(mv_ref, P::sparse_linear_solver(Solver()))));
    auto mean_value = [&](auto h) {
      // h: neighbour r -> free vertex q; t and p the neighbours before and after r around q
      const auto q = target(h, mv_mesh), r = source(h, mv_mesh);
      const auto t = source(prev(h, mv_mesh), mv_mesh);
      const auto p = target(next(opposite(h, mv_mesh), mv_mesh), mv_mesh);
      auto flat = [&](Vertex<Mesh> v) {
        const test::Point x = get(mv_ref, v);
        return test::Kernel::Point_2(x.x(), x.y());
      };
      return CGAL::Weights::mean_value_weight(flat(t), flat(r), flat(p), flat(q));
    };
    CHECK(barycentre_residual(mv_mesh, mv_fixed, mean_value) <= 1e-10 * bbox_size(mv_mesh));
    CHECK(uniform_residual(mv_mesh, mv_fixed) > 1e-4);
  });
}

TEMPLATE_TEST_CASE("a planar convex boundary gives Tutte's embedding without flipped triangles",
                   "[barycentric]", SD_MESH_TYPES)
{
  using Mesh = TestType;
  Mesh original = test::load_mesh<Mesh>("hemisphere.off");
  // the boundary loop, by arc length, onto the unit circle
  SDI::Mesh_indices<Mesh> idx(original);
  const SDI::Boundary_loops loops = SDI::boundary_loops(idx);
  REQUIRE(loops.size() == 1);
  std::vector<double> arc{0.};
  for(std::size_t h : loops.loops[0])
  {
    const auto hd = idx.halfedge(h);
    arc.push_back(arc.back() + (point(original, target(hd, original)) - point(original, source(hd, original))).norm());
  }
  auto vpm = get(CGAL::vertex_point, original);
  std::set<Vertex<Mesh>> fixed;
  for(std::size_t k = 0; k < loops.loops[0].size(); ++k)
  {
    const double angle = 2. * CGAL_PI * arc[k] / arc.back();
    const auto v = source(idx.halfedge(loops.loops[0][k]), original);
    put(vpm, v, test::Point(std::cos(angle), std::sin(angle), 0.));
    fixed.insert(v);
  }
  for(auto weighting : {SD::Edge_weighting::uniform, SD::Edge_weighting::mean_value})
  {
    INFO("weights " << SD::to_string(weighting));
    Mesh mesh = original;
    const auto to_mesh = vertex_correspondence(original, mesh);
    std::set<Vertex<Mesh>> f;
    for(auto v : fixed)
      f.insert(to_mesh.at(v));
    // mean-value weights of the original (curved) hemisphere: positive, so Floater's theorem
    // applies as Tutte's does to uniform weights
    Mesh reference = test::load_mesh<Mesh>("hemisphere.off");
    const auto to_reference = vertex_correspondence(mesh, reference);
    SD::barycentric_embedding(mesh, set_map<Mesh>(f),
                              P::weighting(weighting, P::reference_point_map(boost::make_function_property_map<Vertex<Mesh>>(
                                [&](Vertex<Mesh> v) { return get(CGAL::vertex_point, reference, to_reference.at(v)); }))));
    double max_z = 0.;
    std::size_t positive = 0, negative = 0;
    double smallest = std::numeric_limits<double>::max();
    for(auto v : vertices(mesh))
      max_z = (std::max)(max_z, std::abs(point(mesh, v).z()));
    for(auto fd : faces(mesh))
    {
      const auto h = halfedge(fd, mesh);
      const Eigen::Vector3d a = point(mesh, source(h, mesh)), b = point(mesh, target(h, mesh)),
                            c = point(mesh, target(next(h, mesh), mesh));
      const double signed_area = 0.5 * (b - a).cross(c - a).z();
      positive += signed_area > 0.;
      negative += signed_area < 0.;
      smallest = (std::min)(smallest, std::abs(signed_area));
    }
    CHECK(max_z == 0.);
    CHECK((positive == num_faces(mesh) || negative == num_faces(mesh)));
    CHECK(smallest > 1e-8);
  }
}

TEMPLATE_TEST_CASE("update() after moving the fixed vertices equals a fresh solve", "[barycentric]",
                   SD_MESH_TYPES)
{
  using Mesh = TestType;
  using Vpm = typename boost::property_map<Mesh, CGAL::vertex_point_t>::type;
  for_each_solver([](auto tag) {
    using Solver = typename decltype(tag)::type;
    Mesh mesh;
    const auto loops = SD::make_octahedron_membrane(mesh, 4);
    std::vector<Vertex<Mesh>> fixed;
    for(const auto& loop : loops)
      fixed.insert(fixed.end(), loop.begin(), loop.end());
    SD::Barycentric_embedder<Mesh, Vpm, Solver> embedder(mesh, fixed);
    embedder.update();

    // the paper's deformation: L1 down, L2 up, by 0.3 per step; through the overload taking the
    // new fixed positions
    for(int step = 1; step <= 3; ++step)
    {
      std::map<Vertex<Mesh>, test::Point> moved;
      for(int l = 0; l < 2; ++l)
        for(auto v : loops[std::size_t(l)])
        {
          const auto p = get(CGAL::vertex_point, mesh, v);
          moved.emplace(v, test::Point(p.x(), p.y(), p.z() + (l == 0 ? -0.3 : 0.3)));
        }
      embedder.update(boost::make_function_property_map<Vertex<Mesh>>([&](Vertex<Mesh> v) {
        const auto it = moved.find(v);
        return it != moved.end() ? it->second : get(CGAL::vertex_point, mesh, v);
      }));
      CHECK(std::abs(point(mesh, loops[0][0]).z() - (3. - 0.3 * step)) < 1e-12);

      Mesh fresh = mesh; // same fixed positions, free ones to be recomputed from scratch
      auto fresh_vpm = get(CGAL::vertex_point, fresh);
      for(auto v : vertices(fresh))
        put(fresh_vpm, v, test::Point(0., 0., 0.));
      const auto to_fresh = vertex_correspondence(mesh, fresh);
      for(auto v : fixed)
        put(fresh_vpm, to_fresh.at(v), get(CGAL::vertex_point, mesh, v));
      std::vector<Vertex<Mesh>> fresh_fixed;
      for(auto v : fixed)
        fresh_fixed.push_back(to_fresh.at(v));
      SD::barycentric_embedding(fresh, fresh_fixed, P::sparse_linear_solver(Solver()));
      CHECK(max_distance(positions(mesh), positions(fresh)) <= 1e-12 * bbox_size(mesh));
    }

    // moving a fixed vertex through the vertex point map, then update()
    auto vpm = get(CGAL::vertex_point, mesh);
    for(auto v : loops[2])
    {
      const auto p = get(vpm, v);
      put(vpm, v, test::Point(p.x() + 0.5, p.y(), p.z()));
    }
    embedder.update();
    std::set<Vertex<Mesh>> fixed_set(fixed.begin(), fixed.end());
    CHECK(uniform_residual(mesh, fixed_set) <= 1e-10 * bbox_size(mesh));
  });
}

TEMPLATE_TEST_CASE("the direct solution is the limit of the paper's iteration", "[barycentric]",
                   SD_MESH_TYPES)
{
  using Mesh = TestType;
  {
    Mesh direct;
    const auto fixed = octahedron(direct, 3);
    Mesh iterated = direct, coarse = direct;
    SD::barycentric_embedding(direct, set_map<Mesh>(fixed));
    const auto to_iterated = vertex_correspondence(direct, iterated);
    std::vector<Vertex<Mesh>> it_fixed;
    for(auto v : fixed)
      it_fixed.push_back(to_iterated.at(v));
    const SD::Iterative_embedding_result r =
      SD::barycentric_embedding_iterative(iterated, it_fixed, P::area_tolerance(1e-14));
    CHECK(r.converged);
    CHECK(r.iterations > 50); // Jacobi needs many steps (~diameter^2)
    CHECK(max_distance(positions(direct), positions(iterated)) <= 1e-7 * bbox_size(direct));

    // the paper's tolerance (1e-6 on the area) stops earlier, but close to the limit area
    const SD::Iterative_embedding_result paper = SD::barycentric_embedding_iterative(
      coarse, set_map<Mesh>(border_vertices(coarse)), P::number_of_iterations(std::size_t(100000)));
    CHECK(paper.converged);
    CHECK(std::abs(paper.area - r.area) < 1e-4);

    Mesh capped = test::load_mesh<Mesh>("hemisphere.off");
    const auto capped_result = SD::barycentric_embedding_iterative(
      capped, border_vertices(capped), P::number_of_iterations(std::size_t(3)));
    CHECK(capped_result.iterations == 3);
    CHECK(!capped_result.converged);
  }
  {
    // mean-value weights on quads
    Mesh direct;
    const auto fixed = bent_quad_grid(direct, 6);
    Mesh iterated = direct;
    SD::barycentric_embedding(direct, set_map<Mesh>(fixed), P::weighting(SD::Edge_weighting::mean_value));
    const auto r = SD::barycentric_embedding_iterative(
      iterated, set_map<Mesh>(border_vertices(iterated)),
      P::weighting(SD::Edge_weighting::mean_value, P::area_tolerance(1e-15)));
    CHECK(r.converged);
    CHECK(max_distance(positions(direct), positions(iterated)) <= 1e-7 * bbox_size(direct));
  }
}

namespace {

// PMP::fair's weight calculator for uniform graph weights (w_ij = 1; w_i plays no role at
// continuity 0).
template <class Mesh>
struct Uniform_fair_weights
{
  double w_i(Vertex<Mesh>) const { return 1.; }
  double w_ij(typename boost::graph_traits<Mesh>::halfedge_descriptor) const { return 1.; }
};

} // namespace

TEMPLATE_TEST_CASE("agrees with PMP::fair at membrane continuity with the same weights",
                   "[barycentric]", SD_MESH_TYPES)
{
  using Mesh = TestType;
  // uniform weights on the octahedron; cotangent weights on the hemisphere (well-shaped: fair's
  // clamping of near-degenerate angles does not act), both with the same reference geometry
  for(auto weighting : {SD::Edge_weighting::uniform, SD::Edge_weighting::cotangent})
  {
    INFO("weights " << SD::to_string(weighting));
    Mesh ours;
    std::set<Vertex<Mesh>> fixed;
    if(weighting == SD::Edge_weighting::uniform)
      fixed = octahedron(ours, 4);
    else
    {
      ours = test::load_mesh<Mesh>("hemisphere.off");
      fixed = border_vertices(ours);
      // a non-trivial boundary: lift it
      auto vpm = get(CGAL::vertex_point, ours);
      for(auto v : fixed)
      {
        const auto p = get(vpm, v);
        put(vpm, v, test::Point(p.x(), p.y(), p.z() + 0.3 * p.x() * p.y()));
      }
    }
    Mesh theirs = ours;
    SD::barycentric_embedding(ours, set_map<Mesh>(fixed), P::weighting(weighting));
    std::vector<Vertex<Mesh>> free_vertices;
    const auto to_theirs = vertex_correspondence(ours, theirs);
    for(auto v : vertices(ours))
      if(!fixed.count(v))
        free_vertices.push_back(to_theirs.at(v));
    bool ok;
    if(weighting == SD::Edge_weighting::uniform)
      ok = CGAL::Polygon_mesh_processing::fair(theirs, free_vertices,
                                               CGAL::parameters::fairing_continuity(0).weight_calculator(
                                                 Uniform_fair_weights<Mesh>()));
    else
      ok = CGAL::Polygon_mesh_processing::fair(theirs, free_vertices, CGAL::parameters::fairing_continuity(0));
    REQUIRE(ok);
    CHECK(max_distance(positions(ours), positions(theirs)) <= 1e-9 * bbox_size(ours));
  }
}

TEMPLATE_TEST_CASE("the octahedron of the paper: counts of Table 1, loops, topology", "[barycentric]",
                   SD_MESH_TYPES)
{
  using Mesh = TestType;
  for(std::size_t m : {1u, 2u, 4u, 8u, 12u})
  {
    INFO("m = " << m);
    Mesh mesh;
    const double radius = 1.25;
    const auto loops = SD::make_octahedron_membrane(mesh, m, radius);
    CHECK(num_vertices(mesh) == 24 * m * m + 12 * m - 4); // 428, 1628, 3596 for m = 4, 8, 12
    CHECK(num_faces(mesh) == 48 * m * m);                 // 768, 3072, 6912
    CHECK(CGAL::is_valid_polygon_mesh(mesh));
    SDI::Mesh_indices<Mesh> idx(mesh);
    const SDI::Topology topo = SDI::compute_topology(idx);
    REQUIRE(topo.components.size() == 1);
    CHECK(topo.components.info[0].boundary_loops == 6);
    CHECK(topo.components.info[0].genus() == 0);
    // the loops are exactly the border vertices, 4m each, on circles of the given radius in the
    // planes z = 3, z = -3, x = 3, y = 3, x = -3, y = -3
    const auto border = border_vertices(mesh);
    std::size_t on_loops = 0;
    const int axis[6] = {2, 2, 0, 1, 0, 1};
    const double side[6] = {3., -3., 3., 3., -3., -3.};
    for(std::size_t l = 0; l < 6; ++l)
    {
      CHECK(loops[l].size() == 4 * m);
      for(auto v : loops[l])
      {
        on_loops += border.count(v);
        Eigen::Vector3d p = point(mesh, v);
        CHECK(p[axis[l]] == side[l]);
        p[axis[l]] = 0.;
        CHECK(std::abs(p.norm() - radius) < 1e-12);
      }
    }
    CHECK(on_loops == 24 * m);
    CHECK(border.size() == 24 * m);
    // the paper's numbering: loops first
    auto v = vertices(mesh).begin();
    for(std::size_t l = 0; l < 6; ++l)
      for(std::size_t k = 0; k < 4 * m; ++k)
        CHECK(*v++ == loops[l][k]);
  }
  // outward orientation: the embedded surface encloses a positive volume
  Mesh mesh;
  const auto fixed = octahedron(mesh, 4);
  SD::barycentric_embedding(mesh, set_map<Mesh>(fixed));
  double volume = 0.;
  for(auto f : faces(mesh))
  {
    const auto h = halfedge(f, mesh);
    volume += point(mesh, source(h, mesh)).dot(point(mesh, target(h, mesh)).cross(point(mesh, target(next(h, mesh), mesh)))) / 6.;
  }
  CHECK(volume > 0.);
  CHECK_THROWS_AS(SD::make_octahedron_membrane(mesh, 0), SD::Invalid_parameter);
}

TEMPLATE_TEST_CASE("bad input throws and leaves the mesh untouched, and an all-fixed mesh is a no-op",
                   "[barycentric]", SD_MESH_TYPES)
{
  using Mesh = TestType;
  using Vpm = typename boost::property_map<Mesh, CGAL::vertex_point_t>::type;
  {
    // three components, fixed vertices in the first only
    Mesh mesh = test::load_mesh<Mesh>("blobby_3cc.off");
    const test::Mesh_snapshot before(mesh);
    SDI::Mesh_indices<Mesh> idx(mesh);
    const SDI::Components comps = SDI::connected_components(idx, SDI::boundary_loops(idx));
    REQUIRE(comps.size() == 3);
    std::set<Vertex<Mesh>> fixed;
    for(auto v : border_vertices(mesh))
      if(comps.vertex_component[idx.index(v)] == 0)
        fixed.insert(v);
    REQUIRE(!fixed.empty());
    CHECK_THROWS_AS(SD::barycentric_embedding(mesh, set_map<Mesh>(fixed)), SD::Invalid_constraints);
    CHECK_THROWS_WITH(SD::barycentric_embedding(mesh, set_map<Mesh>(fixed)),
                      Catch::Contains("has no fixed vertex") && Catch::Contains("component 1"));
    CHECK_THROWS_AS(SD::barycentric_embedding_iterative(mesh, set_map<Mesh>(fixed)), SD::Invalid_constraints);
    CHECK(test::Mesh_snapshot(mesh) == before);
  }
  {
    // a non-finite position
    Mesh mesh;
    const auto fixed = octahedron(mesh, 2);
    auto vpm = get(CGAL::vertex_point, mesh);
    put(vpm, *fixed.begin(), test::Point(std::numeric_limits<double>::quiet_NaN(), 0., 0.));
    const test::Mesh_snapshot before(mesh);
    CHECK_THROWS_AS(SD::barycentric_embedding(mesh, set_map<Mesh>(fixed)), SD::Invalid_mesh);
    CHECK_THROWS_AS(SD::barycentric_embedding_iterative(mesh, set_map<Mesh>(fixed)), SD::Invalid_mesh);
    CHECK(test::Mesh_snapshot(mesh) == before);
  }
  {
    // non-finite positions after factorization: update() and update(map) refuse them
    Mesh mesh;
    const auto fixed = octahedron(mesh, 2);
    SD::Barycentric_embedder<Mesh, Vpm> embedder(mesh, fixed);
    embedder.update();
    const test::Mesh_snapshot solved(mesh);
    const auto bad = *fixed.begin();
    CHECK_THROWS_AS(embedder.update(boost::make_function_property_map<Vertex<Mesh>>([&](Vertex<Mesh> v) {
                      return v == bad ? test::Point(0., std::numeric_limits<double>::infinity(), 0.)
                                      : get(CGAL::vertex_point, mesh, v);
                    })),
                    SD::Invalid_constraints);
    CHECK(test::Mesh_snapshot(mesh) == solved);
    put(get(CGAL::vertex_point, mesh), bad, test::Point(0., 0., std::numeric_limits<double>::quiet_NaN()));
    const test::Mesh_snapshot broken(mesh);
    CHECK_THROWS_AS(embedder.update(), SD::Invalid_mesh);
    CHECK(test::Mesh_snapshot(mesh) == broken);
  }
  {
    // cotangent weights need triangles
    Mesh mesh;
    const auto fixed = bent_quad_grid(mesh, 4);
    const test::Mesh_snapshot before(mesh);
    CHECK_THROWS_AS(SD::barycentric_embedding(mesh, fixed, P::weighting(SD::Edge_weighting::cotangent)),
                    SD::Invalid_mesh);
    CHECK(test::Mesh_snapshot(mesh) == before);
  }
  {
    // every vertex fixed: nothing to solve, nothing written
    Mesh mesh = test::load_mesh<Mesh>("hemisphere.off");
    const test::Mesh_snapshot before(mesh);
    std::vector<Vertex<Mesh>> all(vertices(mesh).begin(), vertices(mesh).end());
    CHECK(SD::barycentric_embedding(mesh, all) == 0);
    const auto r = SD::barycentric_embedding_iterative(mesh, all);
    CHECK((r.iterations == 0 && r.converged));
    CHECK(test::Mesh_snapshot(mesh) == before);
  }
}
