// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Components, boundary loops, tree-cotree homology generators, spanning-tree integration.

#include <test_support.h>

#include <CGAL/Surface_design/internal/Core/dec.h>
#include <CGAL/Surface_design/internal/Core/Mesh_indices.h>
#include <CGAL/Surface_design/internal/Core/topology.h>
#include <CGAL/Surface_design/mesh_generators.h>

#include <CGAL/Curves_on_surface_topology.h>
#include <CGAL/Path_on_surface.h>

#include <functional>
#include <random>

namespace SD = CGAL::Surface_design;
namespace SDI = CGAL::Surface_design::internal;

namespace {

struct Expected
{
  std::size_t components;
  long genus_sum;          // sum of the genera of all components
  std::size_t boundary_loops;
};

template <class Mesh>
Mesh make_case(const std::string& name)
{
  Mesh mesh;
  if(name == "generated sphere")
    SD::make_sphere(mesh, 6);
  else if(name == "generated torus")
    SD::make_torus(mesh, 16, 8);
  else if(name == "generated disk")
    SD::make_grid(mesh, 10, 10);
  else if(name == "generated disk with 3 holes")
    SD::make_grid(mesh, 12, 12, 0.1, [](std::size_t i, std::size_t j) {
      return (j == 3 && (i == 3 || i == 7)) || (i == 8 && j == 9);
    });
  else
    mesh = test::load_mesh<Mesh>(name);
  return mesh;
}

const std::vector<std::pair<std::string, Expected>> cases = {
  {"generated sphere", {1, 0, 0}},
  {"generated torus", {1, 1, 0}},
  {"generated disk", {1, 0, 1}},
  {"generated disk with 3 holes", {1, 0, 4}},
  {"bunny_1k.off", {1, 0, 0}},
  {"torus.off", {1, 1, 0}},
  {"eight.off", {1, 2, 0}},
  {"double-torus.off", {1, 2, 0}},
  {"hemisphere.off", {1, 0, 1}},
  {"mech-holes-shark.off", {1, 0, 4}},
  {"elephant-with-holes.off", {1, 3, 106}},
  {"bones.off", {26, 0, 0}},
  {"blobby_3cc.off", {3, 0, 4}},
};

// True iff the mod-2 edge chain `chain` bounds a set of faces and virtual faces of the capped
// surface: colour the dual nodes, flipping the colour across chain edges; the colouring is
// consistent iff the chain is a boundary. Independent of the tree-cotree code under test.
template <class Indices>
bool is_mod2_boundary(const Indices& idx, const SDI::Boundary_loops& loops,
                      const std::vector<char>& chain)
{
  const auto& tm = idx.mesh();
  const std::size_t nf = idx.number_of_faces();
  auto node_of = [&](std::size_t h) {
    const auto hd = idx.halfedge(h);
    return idx.is_border(hd) ? nf + loops.loop_of_halfedge[h] : idx.index(face(hd, tm));
  };
  // halfedges of every dual node
  std::vector<std::vector<std::size_t>> node_halfedges(nf + loops.size());
  for(std::size_t h = 0; h < idx.number_of_halfedges(); ++h)
    node_halfedges[node_of(h)].push_back(h);
  std::vector<int> colour(node_halfedges.size(), -1);
  for(std::size_t start = 0; start < colour.size(); ++start)
  {
    if(colour[start] != -1)
      continue;
    colour[start] = 0;
    std::vector<std::size_t> stack{start};
    while(!stack.empty())
    {
      const std::size_t n = stack.back();
      stack.pop_back();
      for(std::size_t h : node_halfedges[n])
      {
        const std::size_t other = node_of(idx.index(opposite(idx.halfedge(h), tm)));
        const int c = colour[n] ^ int(chain[idx.edge_index(idx.halfedge(h))]);
        if(colour[other] == -1)
        {
          colour[other] = c;
          stack.push_back(other);
        }
        else if(colour[other] != c)
          return false;
      }
    }
  }
  return true;
}

} // namespace

TEMPLATE_TEST_CASE("Components, Euler characteristic, genus and boundary loops", "[topology]",
                   SD_MESH_TYPES_WITH_IDS)
{
  for(const auto& [name, expected] : cases)
  {
    INFO(name);
    const TestType mesh = make_case<TestType>(name);
    SDI::Mesh_indices<TestType> idx(mesh);
    const SDI::Topology topo = SDI::compute_topology(idx);

    REQUIRE(topo.components.size() == expected.components);
    REQUIRE(topo.boundary.size() == expected.boundary_loops);
    long genus = 0;
    std::size_t v = 0, e = 0, f = 0, b = 0;
    for(const auto& c : topo.components.info)
    {
      REQUIRE((2 - long(c.boundary_loops) - c.euler_characteristic()) % 2 == 0);
      REQUIRE(c.genus() >= 0);
      genus += c.genus();
      v += c.vertices;
      e += c.edges;
      f += c.faces;
      b += c.boundary_loops;
      REQUIRE(topo.components.vertex_component[c.root_vertex] ==
              std::size_t(&c - topo.components.info.data()));
    }
    REQUIRE(genus == expected.genus_sum);
    REQUIRE(v == idx.number_of_vertices());
    REQUIRE(e == idx.number_of_edges());
    REQUIRE(f == idx.number_of_faces());
    REQUIRE(b == topo.boundary.size());

    // boundary loops: closed next() cycles of border halfedges covering each exactly once
    std::vector<int> seen(idx.number_of_halfedges(), 0);
    for(std::size_t l = 0; l < topo.boundary.size(); ++l)
    {
      const auto& loop = topo.boundary.loops[l];
      for(std::size_t k = 0; k < loop.size(); ++k)
      {
        const auto h = idx.halfedge(loop[k]);
        REQUIRE(idx.is_border(h));
        REQUIRE(topo.boundary.loop_of_halfedge[loop[k]] == l);
        REQUIRE(idx.index(next(h, mesh)) == loop[(k + 1) % loop.size()]);
        ++seen[loop[k]];
      }
    }
    for(std::size_t h = 0; h < idx.number_of_halfedges(); ++h)
      REQUIRE(seen[h] == (idx.is_border(idx.halfedge(h)) ? 1 : 0));

    // every face belongs to the component of its vertices
    for(std::size_t fi = 0; fi < idx.number_of_faces(); ++fi)
      for(auto vd : vertices_around_face(halfedge(idx.face(fi), mesh), mesh))
        REQUIRE(topo.components.vertex_component[idx.index(vd)] == topo.components.face_component[fi]);
  }
}

TEMPLATE_TEST_CASE("Tree-cotree: trees span, generators are closed, independent and non-contractible",
                   "[topology]", SD_MESH_TYPES_WITH_IDS)
{
  // the default breadth-first tree, and the one that walks the boundary loops first
  for(const bool boundary_first : {false, true})
  for(const auto& [name, expected] : cases)
  {
    INFO(name << (boundary_first ? ", boundary first" : ""));
    const TestType mesh = make_case<TestType>(name);
    SDI::Mesh_indices<TestType> idx(mesh);
    const SDI::Topology topo = SDI::compute_topology(idx, boundary_first);
    const SDI::Tree_cotree& t = topo.tree;
    const std::size_t C = topo.components.size();
    // boundary first: every boundary loop has exactly one edge outside T (its virtual face is a
    // leaf of the dual graph); the default tree leaves several outside on these meshes
    std::size_t loops_with_one_gap = 0;
    for(const auto& loop : topo.boundary.loops)
    {
      std::size_t outside = 0;
      for(std::size_t h : loop)
        outside += t.edge_in_tree[idx.edge_index(idx.halfedge(h))] ? 0 : 1;
      if(boundary_first)
        REQUIRE(outside == 1);
      loops_with_one_gap += outside == 1 ? 1 : 0;
    }
    if(!boundary_first && expected.boundary_loops > 0)
      REQUIRE(loops_with_one_gap < topo.boundary.size()); // the oracle sees a difference

    // sizes: |T| = V - C, |T*| = F + b - C, and 2g generators per component
    const auto tree_edges = std::count(t.edge_in_tree.begin(), t.edge_in_tree.end(), true);
    const auto cotree_edges = std::count(t.edge_in_cotree.begin(), t.edge_in_cotree.end(), true);
    REQUIRE(std::size_t(tree_edges) == idx.number_of_vertices() - C);
    REQUIRE(std::size_t(cotree_edges) == idx.number_of_faces() + topo.boundary.size() - C);
    REQUIRE(t.generator_loops.size() == std::size_t(2 * expected.genus_sum));
    for(std::size_t e = 0; e < idx.number_of_edges(); ++e)
      REQUIRE(!(t.edge_in_tree[e] && t.edge_in_cotree[e]));
    std::vector<long> per_component(C, 0);
    for(std::size_t g : t.generator_component)
      ++per_component[g];
    for(std::size_t c = 0; c < C; ++c)
      REQUIRE(per_component[c] == 2 * topo.components.info[c].genus());

    // the primal tree reaches every vertex, parents come first in the order
    std::vector<bool> placed(idx.number_of_vertices(), false);
    for(std::size_t v : t.vertex_order)
    {
      if(t.parent_halfedge[v] != SDI::npos)
      {
        const auto h = idx.halfedge(t.parent_halfedge[v]);
        REQUIRE(idx.target_index(h) == v);
        REQUIRE(placed[idx.source_index(h)]);
        REQUIRE(t.edge_in_tree[idx.edge_index(h)]);
      }
      placed[v] = true;
    }
    REQUIRE(t.vertex_order.size() == idx.number_of_vertices());
    REQUIRE(t.dual_order.size() == idx.number_of_faces() + topo.boundary.size());

    // each generator loop is a closed cycle: d0^T (loop chain) = 0 and consecutive halfedges meet
    const SDI::Sparse_matrix d0t = SDI::Sparse_matrix(SDI::d0(idx).transpose());
    for(const auto& loop : t.generator_loops)
    {
      Eigen::VectorXd chain = Eigen::VectorXd::Zero(Eigen::Index(idx.number_of_edges()));
      for(std::size_t k = 0; k < loop.size(); ++k)
      {
        const auto h = idx.halfedge(loop[k]);
        REQUIRE(target(h, mesh) == source(idx.halfedge(loop[(k + 1) % loop.size()]), mesh));
        chain[Eigen::Index(idx.edge_index(h))] += idx.orientation_sign(h);
      }
      REQUIRE((d0t * chain).cwiseAbs().maxCoeff() == 0.);
    }

    // independence in H1(capped surface; Z/2): no non-empty combination of generators bounds.
    // Checked for all 2^(2g) - 1 combinations (2g <= 6 here). This also proves that each loop
    // is non-contractible.
    const std::size_t n = t.generator_loops.size();
    REQUIRE(n <= 8);
    for(std::size_t mask = 1; mask < (std::size_t(1) << n); ++mask)
    {
      std::vector<char> chain(idx.number_of_edges(), 0);
      for(std::size_t g = 0; g < n; ++g)
        if(mask & (std::size_t(1) << g))
          for(std::size_t h : t.generator_loops[g])
            chain[idx.edge_index(idx.halfedge(h))] ^= 1;
      REQUIRE_FALSE(is_mod2_boundary(idx, topo.boundary, chain));
    }
    // sanity of the checker itself: the boundary of one face, and of a whole component's faces
    // plus its virtual faces (the empty chain), are boundaries
    std::vector<char> face_chain(idx.number_of_edges(), 0);
    for(auto h : halfedges_around_face(halfedge(idx.face(0), mesh), mesh))
      face_chain[idx.edge_index(h)] ^= 1;
    REQUIRE(is_mod2_boundary(idx, topo.boundary, face_chain));
  }
}

TEMPLATE_TEST_CASE("Generators are non-contractible for CGAL::Surface_mesh_topology", "[topology]",
                   test::Surface_mesh, test::Polyhedron_with_id)
{
  // an independent check with CGAL's own homotopy test, on closed and bordered surfaces
  for(const std::string name : {"eight.off", "generated torus", "elephant-with-holes.off"})
  {
    INFO(name);
    const TestType mesh = make_case<TestType>(name);
    SDI::Mesh_indices<TestType> idx(mesh);
    const SDI::Topology topo = SDI::compute_topology(idx);
    REQUIRE(!topo.tree.generator_loops.empty());
    CGAL::Surface_mesh_topology::Curves_on_surface_topology<TestType> cst(mesh);
    for(const auto& loop : topo.tree.generator_loops)
    {
      CGAL::Surface_mesh_topology::Path_on_surface<TestType> path(mesh);
      for(std::size_t h : loop)
        path.push_back(idx.halfedge(h));
      REQUIRE(path.is_closed());
      REQUIRE_FALSE(cst.is_contractible(path));
    }
    // and a contractible loop (around one vertex) is recognised as such
    CGAL::Surface_mesh_topology::Path_on_surface<TestType> around(mesh);
    const auto h0 = halfedge(idx.face(0), mesh);
    for(auto h : halfedges_around_face(h0, mesh))
      around.push_back(h);
    REQUIRE(cst.is_contractible(around));
  }
}

TEMPLATE_TEST_CASE("Spanning-tree integration recovers a function from its differential",
                   "[topology]", SD_MESH_TYPES_WITH_IDS)
{
  for(const std::string name : {"bones.off", "eight.off", "mech-holes-shark.off"})
  {
    INFO(name);
    const TestType mesh = test::load_mesh<TestType>(name);
    SDI::Mesh_indices<TestType> idx(mesh);
    const SDI::Topology topo = SDI::compute_topology(idx);
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> uniform(-5., 5.);
    Eigen::VectorXd g(Eigen::Index(idx.number_of_vertices()));
    for(Eigen::Index i = 0; i < g.size(); ++i)
      g[i] = uniform(rng);
    const Eigen::VectorXd dg = SDI::d0(idx) * g;
    const std::vector<double> y(dg.data(), dg.data() + dg.size());
    const std::vector<double> u = SDI::integrate_along_tree(idx, topo.tree, y, 1.5);
    for(std::size_t v = 0; v < idx.number_of_vertices(); ++v)
    {
      const std::size_t root = topo.components.info[topo.components.vertex_component[v]].root_vertex;
      REQUIRE(u[v] - 1.5 == Approx(g[Eigen::Index(v)] - g[Eigen::Index(root)]).margin(1e-10));
    }
    // an exact form integrates to zero around every generator and boundary loop
    for(const auto& loop : topo.tree.generator_loops)
      REQUIRE(SDI::integrate_along_loop(idx, loop, y) == Approx(0.).margin(1e-10));
    for(const auto& loop : topo.boundary.loops)
      REQUIRE(SDI::integrate_along_loop(idx, loop, y) == Approx(0.).margin(1e-10));
  }
}
