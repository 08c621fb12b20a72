#include "evaluate/tube_radii.h"

#include "evaluate/closest_point.h"

#include <cmath>

namespace cscd {

std::vector<bool> referencedVertices(const TriangleMesh& mesh) {
  std::vector<bool> used(mesh.vertices.size(), false);
  for (const auto& t : mesh.triangles)
    for (uint32_t v : t) used[v] = true;
  return used;
}

std::vector<double> tubeRadii(const TriangleMesh& mesh, const SkeletonCurves& skeleton) {
  // Every node is a segment of its own too (a, a), so isolated nodes are found.
  std::vector<std::array<uint32_t, 2>> segments = skeleton.edges;
  for (uint32_t i = 0; i < skeleton.nodes.size(); i++) segments.push_back({i, i});
  SegmentTree tree(skeleton.nodes, segments);

  std::vector<double> weightedSum(skeleton.nodes.size(), 0), weight(skeleton.nodes.size(), 0);
  std::vector<bool> used = referencedVertices(mesh);
  for (size_t v = 0; v < mesh.vertices.size(); v++) {
    if (!used[v]) continue;
    SegmentTree::Hit hit = tree.closest(mesh.vertices[v]);
    auto [a, b] = segments[hit.primitive];
    double t = closestParameterOnSegment(mesh.vertices[v], skeleton.nodes[a], skeleton.nodes[b]);
    double distance = std::sqrt(hit.distance2);
    weightedSum[a] += (1 - t) * distance;
    weight[a] += 1 - t;
    weightedSum[b] += t * distance;
    weight[b] += t;
  }

  std::vector<double> radii(skeleton.nodes.size());
  TriangleTree surface(mesh.vertices, mesh.triangles);
  for (size_t i = 0; i < radii.size(); i++)
    radii[i] = weight[i] > 1e-9 ? weightedSum[i] / weight[i] : std::sqrt(surface.closest(skeleton.nodes[i]).distance2);
  return radii;
}

} // namespace cscd
