#pragma once

#include "cscd/options.h"
#include "pointcloud/cut_locus.h"
#include "pointcloud/neighbourhood.h"

#include <array>
#include <vector>

namespace cscd {

// The paper's condition for clouds, that the two incoming gradients at a target be opposite, read two
// ways. On a noisy cloud: at least kMinOpposedAngle apart, as most ridges of the noise are not. On a
// clean cloud: the two fronts head towards each other, each gradient at least kMinHeading into the
// other neighbour's side (its component along the step from its own neighbour to the other one). Fronts
// that meet at a shallow angle, as behind a leg far from the source, where the two halves of the front
// run along the leg and close in slowly, collide all the same; fronts that run side by side (a stretch of
// the tree that bridges ridges) do not (docs/pointcloud.md, "Fronts that meet at a shallow angle").
constexpr double kMinOpposedAngle = M_PI / 2;
constexpr double kMinHeading = M_PI / 9;

// A target and the two neighbours the descents start from.
struct CloudTarget {
  size_t point;
  std::array<size_t, 2> starts;
};

// The targets of a cloud, the nearest first: its cut-locus points ranked as on a mesh (cscd/target.h,
// rankTargets: detours only, by Euclidean or geodesic distance from the source), each with its two
// incoming neighbours on either side of the cut locus (cscd/descent.h, incomingNeighbours, on the
// target's ring in the neighbourhood graph), with the condition the paper adds for clouds: their
// gradients are opposite (above). A point without two such neighbours is no target.
std::vector<CloudTarget> rankCloudTargets(const CloudNeighbourhood& neighbourhood, const CloudCutLocusSolver& solver,
                                          const CloudCutLocus& cutLocus, const std::vector<double>& distance,
                                          size_t source, TargetMode mode);

} // namespace cscd
