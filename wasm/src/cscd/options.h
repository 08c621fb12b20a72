#pragma once

#include <cmath>
#include <cstdint>

namespace cscd {

// How the target cut-locus point is chosen (paper Sec. 4.1.3): nearest in space or along the surface.
enum class TargetMode { Euclidean, Geodesic };

// Every option of the CSCD pipeline with its default. The specification all front ends derive from is
// lib/core/options.ts (names, kinds, defaults, ranges, CLI flags, help); the core declares the same
// defaults here and ranges below, and tests/unit/options.test.ts holds the two to each other through
// the bindings (`optionLimits`).
struct Options {
  TargetMode target = TargetMode::Euclidean; // "euclid" | "geodesic"
  bool sphere = true;                        // keep the shortened loop inside a sphere around the source
  uint32_t seed = 1;                         // fixes every random choice
  double angleThreshold = 1.75;              // cut locus: min turn of the distance gradient, radians
  double laplacianThreshold = 0.2;           // cut locus: min -(mean edge length) x Laplacian of the distance
  int pruneDepth = 3;                        // cut locus: leaf branches shorter than this (edges) are pruned
  int n = 0;                                 // sources to sample; 0 = auto (until coverage stops growing)
  // Sources drawn ahead of their separators (each draw knows the separators of all but the
  // drawAhead - 1 sources before it): up to this many are computed side by side, by a pool of workers.
  // 4 keeps cycles and tips as one at a time does (8 did not), and two workers never wait
  // (docs/parallel.md, "Choosing drawAhead"). 1: one at a time.
  int drawAhead = 4;
  double pruneLengthFactor = 3;              // loops shorter than this many mean edge lengths are pruned
  // Point clouds only: neighbours of each point its local triangulation is built from (k of the kNN
  // search). 30 is geometry-central's default, which the paper's PotPourri3D point-cloud solver uses;
  // at least 3, as fewer cannot surround a point with triangles.
  int neighbours = 30;
  // Meshes only: above this many vertices stage 1 runs on a simplified copy (0: never). The front ends
  // make the copy (lib/mesh/simplify.ts, quadric edge collapse in TypeScript) and give the pipeline both
  // surfaces; declared here so that the core checks its range as it checks every option's.
  int stage1Vertices = 20000;
};

// Accepted ranges of the numeric options (inclusive); toOptions in the bindings refuses anything else.
struct OptionRange {
  const char* name;
  double low, high;
};
constexpr OptionRange kOptionRanges[] = {
    {"seed", 0, 4294967295.0},   {"angleThreshold", 0, M_PI}, {"laplacianThreshold", 0, 1e6},
    {"pruneDepth", 0, 1000},     {"n", 1, 100000},            {"pruneLengthFactor", 0, 1000},
    {"drawAhead", 1, 256},       {"neighbours", 3, 256},      {"stage1Vertices", 0, 100000000},
};

} // namespace cscd
