#include "pointcloud/target.h"

#include "cscd/descent.h"
#include "cscd/target.h"

#include <cmath>

namespace cscd {
namespace {

// Each front heads at least kMinHeading into the other's side, all seen in the target's tangent plane.
bool frontsMeet(const CloudNeighbourhood& neighbourhood, const std::vector<geometrycentral::Vector3>& gradient,
                size_t target, size_t a, size_t b) {
  const geometrycentral::Vector2 across =
      neighbourhood.inTangentPlane(target, neighbourhood.position(b) - neighbourhood.position(a));
  const geometrycentral::Vector2 fromA = neighbourhood.inTangentPlane(target, gradient[a]);
  const geometrycentral::Vector2 fromB = neighbourhood.inTangentPlane(target, gradient[b]);
  const double scale = norm(across), lengthA = norm(fromA), lengthB = norm(fromB);
  if (!(scale > 0 && lengthA > 0 && lengthB > 0)) return false;
  const double minHeading = std::sin(kMinHeading);
  return dot(fromA, across) >= minHeading * scale * lengthA && -dot(fromB, across) >= minHeading * scale * lengthB;
}

} // namespace

std::vector<CloudTarget> rankCloudTargets(const CloudNeighbourhood& neighbourhood, const CloudCutLocusSolver& solver,
                                          const CloudCutLocus& cutLocus, const std::vector<double>& distance,
                                          size_t source, TargetMode mode) {
  const NeighbourGraph& graph = neighbourhood.graph();
  std::vector<CloudTarget> targets;
  const CutLocusNeighbours alongCutLocus = cutLocusNeighbours(cutLocus.graph);
  for (size_t target : rankTargets(cutLocus.graph, distance, neighbourhood.positions(), source, mode, kMinDetour)) {
    const std::vector<size_t> ring(graph.neighbour.begin() + long(graph.rowStart[target]),
                                   graph.neighbour.begin() + long(graph.rowStart[target + 1]));
    const std::vector<size_t> starts = incomingNeighbours(ring, distance, alongCutLocus, target);
    if (starts.size() != 2) continue;
    const bool opposite = neighbourhood.noisyCloud()
                              ? solver.angleBetween(cutLocus.gradient, target, starts[0], starts[1]) >= kMinOpposedAngle
                              : frontsMeet(neighbourhood, cutLocus.gradient, target, starts[0], starts[1]);
    if (opposite) targets.push_back({target, {starts[0], starts[1]}});
  }
  return targets;
}

} // namespace cscd
