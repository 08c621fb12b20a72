#include "evaluate/reconstruction_error.h"

#include "cscd/stage_clock.h"
#include "cscd/union_find.h"
#include "evaluate/closest_point.h"
#include "mesh/mesh_check.h"

#include <algorithm>
#include <cmath>
#include <set>

namespace cscd {
namespace {

std::vector<Vector3> meshVertices(const MeshArrays& mesh) {
  std::vector<Vector3> vertices(mesh.vertexCount());
  for (size_t i = 0; i < vertices.size(); i++)
    vertices[i] = {mesh.positions[3 * i], mesh.positions[3 * i + 1], mesh.positions[3 * i + 2]};
  return vertices;
}

std::vector<std::array<uint32_t, 3>> meshTriangles(const MeshArrays& mesh) {
  std::vector<std::array<uint32_t, 3>> triangles(mesh.faceCount());
  for (size_t f = 0; f < triangles.size(); f++)
    triangles[f] = {mesh.triangles[3 * f], mesh.triangles[3 * f + 1], mesh.triangles[3 * f + 2]};
  return triangles;
}

std::vector<bool> referencedVertices(const MeshArrays& mesh) {
  std::vector<bool> used(mesh.vertexCount(), false);
  for (uint32_t v : mesh.triangles) used[v] = true;
  return used;
}

void checkSkeleton(const SkeletonCurves& skeleton) {
  if (skeleton.nodes.empty()) throw InputError("the skeleton has no nodes");
  for (size_t i = 0; i < skeleton.nodes.size(); i++)
    if (!std::isfinite(skeleton.nodes[i].x) || !std::isfinite(skeleton.nodes[i].y) || !std::isfinite(skeleton.nodes[i].z))
      throw InputError("skeleton node " + std::to_string(i) + " has a coordinate that is not a finite number");
  for (size_t e = 0; e < skeleton.edges.size(); e++)
    for (uint32_t v : skeleton.edges[e])
      if (v >= skeleton.nodes.size())
        throw InputError("skeleton edge " + std::to_string(e) + " names node " + std::to_string(v) + ", but the skeleton has only " +
                         std::to_string(skeleton.nodes.size()) + " nodes");
  if (skeleton.radii.empty()) return;
  if (skeleton.radii.size() != skeleton.nodes.size())
    throw InputError("the skeleton has " + std::to_string(skeleton.nodes.size()) + " nodes but " + std::to_string(skeleton.radii.size()) +
                     " radii");
  for (size_t i = 0; i < skeleton.radii.size(); i++)
    if (!(skeleton.radii[i] >= 0) || !std::isfinite(skeleton.radii[i]))
      throw InputError("skeleton node " + std::to_string(i) + " has a radius that is not a finite number >= 0");
}

// Self-loops and repeated edges close no cycle of a curve skeleton.
size_t cycleCount(const SkeletonCurves& skeleton) {
  std::set<std::array<uint32_t, 2>> edges;
  for (auto [a, b] : skeleton.edges)
    if (a != b) edges.insert({std::min(a, b), std::max(a, b)});
  UnionFind sets(skeleton.nodes.size());
  for (auto [a, b] : edges) sets.unite(a, b);
  size_t components = 0;
  for (size_t i = 0; i < skeleton.nodes.size(); i++)
    if (sets.find(uint32_t(i)) == i) components++;
  return edges.size() + components - skeleton.nodes.size();
}

double quantile(std::vector<double> values, double q) {
  size_t k = size_t(std::round(q * double(values.size() - 1)));
  std::nth_element(values.begin(), values.begin() + k, values.end());
  return values[k];
}

} // namespace

std::vector<double> deriveRadii(const MeshArrays& mesh, const SkeletonCurves& skeleton) {
  std::vector<Vector3> vertices = meshVertices(mesh);
  // Every node is a segment of its own too (a, a), so isolated nodes are found.
  std::vector<std::array<uint32_t, 2>> segments = skeleton.edges;
  for (uint32_t i = 0; i < skeleton.nodes.size(); i++) segments.push_back({i, i});
  SegmentTree tree(skeleton.nodes, segments);

  std::vector<double> weightedSum(skeleton.nodes.size(), 0), weight(skeleton.nodes.size(), 0);
  std::vector<bool> used = referencedVertices(mesh);
  for (size_t v = 0; v < vertices.size(); v++) {
    if (!used[v]) continue;
    SegmentTree::Hit hit = tree.closest(vertices[v]);
    auto [a, b] = segments[hit.primitive];
    double t = closestParameterOnSegment(vertices[v], skeleton.nodes[a], skeleton.nodes[b]);
    double distance = std::sqrt(hit.distance2);
    weightedSum[a] += (1 - t) * distance;
    weight[a] += 1 - t;
    weightedSum[b] += t * distance;
    weight[b] += t;
  }

  std::vector<double> radii(skeleton.nodes.size());
  TriangleTree surface(vertices, meshTriangles(mesh));
  for (size_t i = 0; i < radii.size(); i++)
    radii[i] = weight[i] > 1e-9 ? weightedSum[i] / weight[i] : std::sqrt(surface.closest(skeleton.nodes[i]).distance2);
  return radii;
}

Evaluation evaluateSkeleton(const MeshArrays& mesh, SkeletonCurves skeleton) {
  MeshFacts facts = checkMesh(mesh).facts;
  checkSkeleton(skeleton);
  if (!(facts.bboxDiagonal > 0)) throw InputError("the mesh has no extent: its bounding box is a point");

  Evaluation result;
  StageClock clock(result.timings);
  result.nodes = skeleton.nodes.size();
  result.cycles = cycleCount(skeleton);
  result.radiiDerived = skeleton.radii.empty();
  if (result.radiiDerived) skeleton.radii = deriveRadii(mesh, skeleton);
  result.radii = skeleton.radii;
  clock.lap("radii");

  Vector3 lower{facts.bboxMin[0], facts.bboxMin[1], facts.bboxMin[2]};
  Vector3 upper{facts.bboxMax[0], facts.bboxMax[1], facts.bboxMax[2]};
  result.grid = reconstructionGrid(skeleton, lower, upper);
  result.surface = convolutionSurface(skeleton, result.grid);
  clock.lap("surface");
  if (result.surface.triangles.empty())
    throw InputError("the skeleton's reconstructed surface is empty: its radii are too small for the mesh");

  TriangleTree tree(result.surface.vertices, result.surface.triangles);
  std::vector<Vector3> vertices = meshVertices(mesh);
  std::vector<bool> used = referencedVertices(mesh);
  const double scale = 1e3 / (facts.bboxDiagonal * facts.bboxDiagonal);
  result.vertexError.assign(vertices.size(), 0);
  std::vector<double> errors;
  errors.reserve(vertices.size());
  for (size_t v = 0; v < vertices.size(); v++) {
    if (!used[v]) continue;
    result.vertexError[v] = tree.closest(vertices[v]).distance2 * scale;
    errors.push_back(result.vertexError[v]);
  }
  double sum = 0;
  for (double e : errors) sum += e;
  result.reconError = sum / double(errors.size());
  result.median = quantile(errors, 0.5);
  result.p95 = quantile(errors, 0.95);
  clock.lap("distances");
  return result;
}

} // namespace cscd
