#include "mesh/target.h"

#include <algorithm>
#include <cmath>
#include <utility>

using namespace geometrycentral;
using namespace geometrycentral::surface;

namespace cscd {

std::vector<size_t> rankTargets(const CutLocus& cutLocus, const std::vector<double>& distance,
                                VertexPositionGeometry& geometry, size_t source, TargetMode mode, double minDetour) {
  const Vector3 sourcePosition = geometry.vertexPositions[source];
  std::vector<std::pair<double, size_t>> ranked;
  for (size_t v : cutLocus.vertices) {
    const double euclidean = norm(geometry.vertexPositions[v] - sourcePosition);
    if (!std::isfinite(distance[v]) || !(distance[v] >= minDetour * euclidean) || euclidean == 0) continue;
    const double key = targetKey(geometry, distance, source, v, mode);
    ranked.emplace_back(key, v);
  }
  std::sort(ranked.begin(), ranked.end());
  std::vector<size_t> targets;
  for (const auto& [key, v] : ranked) targets.push_back(v);
  return targets;
}

double targetKey(VertexPositionGeometry& geometry, const std::vector<double>& distance, size_t source, size_t target,
                 TargetMode mode) {
  return mode == TargetMode::Euclidean ? norm(geometry.vertexPositions[target] - geometry.vertexPositions[source])
                                       : distance[target];
}

} // namespace cscd
