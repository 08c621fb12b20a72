#pragma once

#include "cscd/options.h"
#include "cscd/ridge_tree.h"

#include "geometrycentral/utilities/vector3.h"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

namespace cscd {

// Targets must be reached by a detour: geodesic >= 1.2 x Euclidean distance (see rankTargets).
constexpr double kMinDetour = 1.2;

// When a target's loop fails (it encloses nothing: a spurious ridge), the next target tried is at least
// this much farther away (its targetKey)...
constexpr double kFallbackGrowth = 1.5;
// ...up to this many targets in all.
constexpr int kMaxTargets = 6;

// What the targets are ranked by: Euclidean or geodesic distance from the source. `positions`: a mesh's
// vertex positions or a cloud's point positions, anything that gives a vertex's Vector3 by its index.
template <class Positions>
double targetKey(const Positions& positions,
                 const std::vector<double>& distance, size_t source, size_t target, TargetMode mode) {
  return mode == TargetMode::Euclidean ? norm(positions[target] - positions[source]) : distance[target];
}

// Cut-locus vertices ordered from nearest to farthest from the source, by Euclidean distance in space
// (the paper's default: a protrusion's cut locus is close in space but far along the surface) or by
// geodesic distance.
// Only detours qualify: cut-locus vertices whose geodesic distance is at least `minDetour` times their
// Euclidean distance from the source. Around any feature the surface bends between the source and its
// cut locus (pi/2 across a round limb, on a sphere, around a torus tube), while spurious ridge points
// next to the source or on flat stretches are about as far along the surface as in space.
// The first one is the paper's target; the others are fall-backs when its loop turns out degenerate.
template <class Positions>
std::vector<size_t> rankTargets(const CutLocus& cutLocus, const std::vector<double>& distance, const Positions& positions,
                                size_t source, TargetMode mode, double minDetour) {
  std::vector<std::pair<double, size_t>> ranked;
  for (size_t v : cutLocus.vertices) {
    const double euclidean = norm(positions[v] - positions[source]);
    if (!std::isfinite(distance[v]) || !(distance[v] >= minDetour * euclidean) || euclidean == 0) continue;
    ranked.emplace_back(targetKey(positions, distance, source, v, mode), v);
  }
  std::sort(ranked.begin(), ranked.end());
  std::vector<size_t> targets;
  for (const auto& [key, v] : ranked) targets.push_back(v);
  return targets;
}

} // namespace cscd
