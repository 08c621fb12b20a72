#include "evaluate/tube_radii.h"

#include "evaluate/closest_point.h"

#include <algorithm>
#include <cmath>
#include <memory>

namespace cscd {

std::vector<bool> referencedVertices(const TriangleMesh& mesh) {
  std::vector<bool> used(mesh.vertices.size(), false);
  for (const auto& t : mesh.triangles)
    for (uint32_t v : t) used[v] = true;
  return used;
}

namespace {

// The weighted mean distance that the points `used` lend each node; a node no point chose gets
// `fallback(node)`.
template <class Fallback>
std::vector<double> lentRadii(const std::vector<Vector3>& points, const std::vector<bool>& used,
                              const SkeletonCurves& skeleton, Fallback fallback) {
  // Every node is a segment of its own too (a, a), so isolated nodes are found.
  std::vector<std::array<uint32_t, 2>> segments = skeleton.edges;
  for (uint32_t i = 0; i < skeleton.nodes.size(); i++) segments.push_back({i, i});
  SegmentTree tree(skeleton.nodes, segments);

  std::vector<double> weightedSum(skeleton.nodes.size(), 0), weight(skeleton.nodes.size(), 0);
  for (size_t v = 0; v < points.size(); v++) {
    if (!used[v]) continue;
    SegmentTree::Hit hit = tree.closest(points[v]);
    auto [a, b] = segments[hit.primitive];
    double t = closestParameterOnSegment(points[v], skeleton.nodes[a], skeleton.nodes[b]);
    double distance = std::sqrt(hit.distance2);
    weightedSum[a] += (1 - t) * distance;
    weight[a] += 1 - t;
    weightedSum[b] += t * distance;
    weight[b] += t;
  }

  std::vector<double> radii(skeleton.nodes.size());
  for (size_t i = 0; i < radii.size(); i++) radii[i] = weight[i] > 1e-9 ? weightedSum[i] / weight[i] : fallback(i);
  return radii;
}

} // namespace

std::vector<double> tubeRadii(const TriangleMesh& mesh, const SkeletonCurves& skeleton) {
  std::unique_ptr<TriangleTree> surface; // built only if a node needs it
  return lentRadii(mesh.vertices, referencedVertices(mesh), skeleton, [&](size_t i) {
    if (!surface) surface = std::make_unique<TriangleTree>(mesh.vertices, mesh.triangles);
    return std::sqrt(surface->closest(skeleton.nodes[i]).distance2);
  });
}

std::vector<double> tubeRadii(const std::vector<Vector3>& points, const SkeletonCurves& skeleton) {
  return lentRadii(points, std::vector<bool>(points.size(), true), skeleton, [&](size_t i) {
    double nearest2 = INFINITY;
    for (const Vector3& p : points) nearest2 = std::min(nearest2, norm2(p - skeleton.nodes[i]));
    return std::sqrt(nearest2);
  });
}

} // namespace cscd
