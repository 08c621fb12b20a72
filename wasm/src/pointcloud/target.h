#pragma once

#include "cscd/options.h"
#include "pointcloud/cut_locus.h"
#include "pointcloud/neighbourhood.h"

#include <array>
#include <vector>

namespace cscd {

// Below this angle the gradients at the two incoming neighbours of a target are not opposite: they
// arrive side by side (the target lies on a stretch of the tree that bridges ridges, not where fronts
// collide).
constexpr double kMinOpposedAngle = M_PI / 2;

// A target and the two neighbours the descents start from.
struct CloudTarget {
  size_t point;
  std::array<size_t, 2> starts;
};

// The targets of a cloud, the nearest first: its cut-locus points ranked as on a mesh (cscd/target.h,
// rankTargets: detours only, by Euclidean or geodesic distance from the source), each with its two
// incoming neighbours on either side of the cut locus (cscd/descent.h, incomingNeighbours, on the
// target's ring in the neighbourhood graph), with the condition the paper adds for clouds: their
// gradients are opposite (at least kMinOpposedAngle apart in the target's tangent plane). A point
// without two such neighbours is no target.
std::vector<CloudTarget> rankCloudTargets(const CloudNeighbourhood& neighbourhood, const CloudCutLocusSolver& solver,
                                          const CloudCutLocus& cutLocus, const std::vector<double>& distance,
                                          size_t source, TargetMode mode);

} // namespace cscd
