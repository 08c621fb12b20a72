#pragma once

#include "mesh/surface.h"

#include <random>
#include <vector>

namespace cscd {

// Adaptive sampling of sources (paper Sec. 4.1.7). The first source is drawn uniformly over the
// surface; then vertex i is drawn with probability proportional to A_i (exp(d_i / s) - 1), where d_i
// is the geodesic distance from i to the sources and separators found so far, A_i the vertex area
// (so that the draw does not depend on how densely a region is meshed) and s = diagonal / 10 the
// scale that makes d scale-free: a vertex a tenth of the diagonal away weighs e - 1 = 1.7, one half
// a diagonal away e^5 - 1 = 147, so far, unexplored features are visited first. Components not yet
// reached weigh the most. Deterministic for a seed (std::mt19937 is fully specified).
class SourceSampler {
public:
  SourceSampler(Surface& surface, uint32_t seed);

  size_t next();

  // Marks a source and its separator's loop (empty if it had none) as covered.
  void cover(size_t source, const std::vector<geometrycentral::surface::SurfacePoint>& loop);

  // Share of the surface area within `radius` of what is covered.
  double coverage(double radius) const;

private:
  Surface& surface;
  std::mt19937 rng;
  std::vector<double> area;
  std::vector<double> distance; // to the covered set; +infinity before the first source
  double scale;
  double totalArea = 0;
};

} // namespace cscd
