#include "evaluate/reconstruction_error.h"

#include "cscd/stage_clock.h"
#include "cscd/union_find.h"
#include "evaluate/closest_point.h"
#include "mesh/mesh_check.h"
#include "evaluate/tube_radii.h"

#include <algorithm>
#include <cmath>
#include <set>
#include <string>

namespace cscd {
namespace {

TriangleMesh toTriangleMesh(const MeshArrays& mesh) {
  TriangleMesh out;
  out.vertices.resize(mesh.vertexCount());
  for (size_t i = 0; i < out.vertices.size(); i++)
    out.vertices[i] = {mesh.positions[3 * i], mesh.positions[3 * i + 1], mesh.positions[3 * i + 2]};
  out.triangles.resize(mesh.faceCount());
  for (size_t f = 0; f < out.triangles.size(); f++)
    out.triangles[f] = {mesh.triangles[3 * f], mesh.triangles[3 * f + 1], mesh.triangles[3 * f + 2]};
  return out;
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

namespace {

// The error of the reconstructed surface at `points` (those `used`), with the bounding box they span.
// `deriveRadii` fits radii around the shape (a "mesh", a "point cloud") when the skeleton has none.
template <class DeriveRadii>
Evaluation evaluateAt(const std::vector<Vector3>& points, const std::vector<bool>& used, Vector3 lower, Vector3 upper,
                      SkeletonCurves skeleton, const std::string& shape, DeriveRadii deriveRadii) {
  checkSkeleton(skeleton);
  const double diagonal = norm(upper - lower);
  if (!(diagonal > 0)) throw InputError("the " + shape + " has no extent: its bounding box is a point");

  Evaluation result;
  StageClock clock(result.timings);
  result.nodes = skeleton.nodes.size();
  result.cycles = cycleCount(skeleton);
  result.radiiDerived = skeleton.radii.empty();
  if (result.radiiDerived) skeleton.radii = deriveRadii(skeleton);
  result.radii = skeleton.radii;
  clock.lap("radii");

  result.grid = reconstructionGrid(skeleton, lower, upper);
  result.surface = convolutionSurface(skeleton, result.grid);
  clock.lap("surface");
  if (result.surface.triangles.empty())
    throw InputError("the skeleton's reconstructed surface is empty: its radii are too small for the " + shape);

  TriangleTree tree(result.surface.vertices, result.surface.triangles);
  const double scale = 1e3 / (diagonal * diagonal);
  result.vertexError.assign(points.size(), 0);
  std::vector<double> errors;
  errors.reserve(points.size());
  for (size_t v = 0; v < points.size(); v++) {
    if (!used[v]) continue;
    result.vertexError[v] = tree.closest(points[v]).distance2 * scale;
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

} // namespace

Evaluation evaluateSkeleton(const MeshArrays& mesh, SkeletonCurves skeleton) {
  MeshFacts facts = checkMesh(mesh).facts;
  TriangleMesh input = toTriangleMesh(mesh);
  return evaluateAt(input.vertices, referencedVertices(input), {facts.bboxMin[0], facts.bboxMin[1], facts.bboxMin[2]},
                    {facts.bboxMax[0], facts.bboxMax[1], facts.bboxMax[2]}, std::move(skeleton), "mesh",
                    [&](const SkeletonCurves& s) { return tubeRadii(input, s); });
}

Evaluation evaluateSkeleton(const std::vector<Vector3>& points, SkeletonCurves skeleton) {
  if (points.empty()) throw InputError("the point cloud has no points");
  Vector3 lower = points.front(), upper = points.front();
  for (const Vector3& p : points) {
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) throw InputError("a point has a coordinate that is not a finite number");
    lower = componentwiseMin(lower, p);
    upper = componentwiseMax(upper, p);
  }
  return evaluateAt(points, std::vector<bool>(points.size(), true), lower, upper, std::move(skeleton), "point cloud",
                    [&](const SkeletonCurves& s) { return tubeRadii(points, s); });
}

} // namespace cscd
