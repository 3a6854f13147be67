// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The peer of the `line_field_stripes` workload: geometry-central's smoothest line field
// (computeSmoothestVertexDirectionField, n = 2) and stripe pattern (computeStripePattern, Knöppel
// et al. 2015) on one mesh, 40 stripes across the bounding-box diagonal as in the workload.
// Built outside the project against a geometry-central checkout by stripe_peer_comparison.py;
// nothing in the library uses it.
//
// usage: geometry_central_stripes MESH RUNS
// Prints one JSON object: the sizes, the singular faces of the last pattern, and the median, min
// and max over RUNS runs (after one warm-up) of "field", "stripes" and "full", in milliseconds.
// Every run starts from the positions alone (the geometry's cached quantities purged), as the
// workload does.

#include "geometrycentral/surface/direction_fields.h"
#include "geometrycentral/surface/meshio.h"
#include "geometrycentral/surface/stripe_patterns.h"
#include "geometrycentral/surface/vertex_position_geometry.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <string>
#include <vector>

using namespace geometrycentral;
using namespace geometrycentral::surface;

namespace {

double now_ms()
{
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

void print_phase(const char* name, std::vector<double> t, bool last)
{
  std::sort(t.begin(), t.end());
  std::printf("\"%s\": {\"median_ms\": %.4f, \"min_ms\": %.4f, \"max_ms\": %.4f}%s", name, t[t.size() / 2], t.front(),
              t.back(), last ? "" : ", ");
}

} // namespace

int main(int argc, char** argv)
{
  if(argc != 3 || std::atoi(argv[2]) < 1)
  {
    std::fprintf(stderr, "usage: geometry_central_stripes MESH RUNS (RUNS >= 1)\n");
    return 1;
  }
  const int runs = std::atoi(argv[2]);
  std::unique_ptr<ManifoldSurfaceMesh> mesh;
  std::unique_ptr<VertexPositionGeometry> geometry;
  std::tie(mesh, geometry) = readManifoldSurfaceMesh(argv[1]);
  Vector3 lo = geometry->vertexPositions[mesh->vertex(0)], hi = lo;
  for(Vertex v : mesh->vertices())
  {
    lo = componentwiseMin(lo, geometry->vertexPositions[v]);
    hi = componentwiseMax(hi, geometry->vertexPositions[v]);
  }
  const double diagonal = norm(hi - lo);
  std::vector<double> field_ms, stripes_ms, full_ms;
  std::size_t singular = 0, branch = 0;
  for(int r = 0; r <= runs; ++r) // run 0: the warm-up
  {
    geometry->purgeQuantities();
    const double t0 = now_ms();
    const VertexData<Vector2> field = computeSmoothestVertexDirectionField(*geometry, 2);
    const double t1 = now_ms();
    const VertexData<double> frequency(*mesh, 40. / diagonal);
    const auto pattern = computeStripePattern(*geometry, frequency, field);
    const double t2 = now_ms();
    if(r == 0)
      continue;
    field_ms.push_back(t1 - t0);
    stripes_ms.push_back(t2 - t1);
    full_ms.push_back(t2 - t0);
    singular = branch = 0;
    for(Face f : mesh->faces())
    {
      singular += std::get<1>(pattern)[f] != 0 ? 1 : 0;
      branch += std::get<2>(pattern)[f] != 0 ? 1 : 0;
    }
  }
  std::printf("{\"vertices\": %zu, \"faces\": %zu, \"stripe_singular_faces\": %zu, \"branch_faces\": %zu, \"runs\": %d, ",
              mesh->nVertices(), mesh->nFaces(), singular, branch, runs);
  print_phase("field", field_ms, false);
  print_phase("stripes", stripes_ms, false);
  print_phase("full", full_ms, true);
  std::printf("}\n");
  return 0;
}
