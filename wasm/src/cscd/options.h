#pragma once

#include <cstdint>

namespace cscd {

// How the target cut-locus point is chosen (paper Sec. 4.1.3): nearest in space or along the surface.
enum class TargetMode { Euclidean, Geodesic };

// Every option of the CSCD pipeline with its default. Mirrored by `Options` in lib/core/types.ts; the
// same names are used by the bindings, worker messages, UI labels and CLI flags (kebab-case there).
struct Options {
  TargetMode target = TargetMode::Euclidean; // "euclid" | "geodesic"
  bool sphere = true;                        // keep the shortened loop inside a sphere around the source
  uint32_t seed = 1;                         // fixes every random choice
  double angleThreshold = 1.75;              // cut locus: min turn of the distance gradient, radians
  double laplacianThreshold = 0.2;           // cut locus: min -(mean edge length) x Laplacian of the distance
  int pruneDepth = 3;                        // cut locus: leaf branches shorter than this (edges) are pruned
  int n = 0;                                 // sources to sample; 0 = auto (until coverage stops growing)
  double pruneLengthFactor = 3;              // loops shorter than this many mean edge lengths are pruned
};

} // namespace cscd
