#pragma once

#include "geometrycentral/utilities/vector3.h"

#include <deque>
#include <random>
#include <vector>

namespace cscd {

// Coverage radius of the auto mode, as a share of the bounding-box diagonal: what lies this near a
// source or a separator is covered.
constexpr double kCoverageRadius = 0.03;

// Adaptive sampling of sources (paper Sec. 4.1.7). The first source is drawn uniformly over the
// surface; then vertex i is drawn with probability proportional to A_i (exp(d_i / s) - 1), where d_i
// is the geodesic distance from i to the sources and separators found so far, A_i the vertex area
// (so that the draw does not depend on how densely a region is meshed) and s = diagonal / 10 the
// scale that makes d scale-free: a vertex a tenth of the diagonal away weighs e - 1 = 1.7, one half
// a diagonal away e^5 - 1 = 147, so far, unexplored features are visited first. Components not yet
// reached weigh the most. Deterministic for a seed (std::mt19937 is fully specified).
//
// The shape is given as its elements (mesh vertices, cloud points) with their positions and areas; the
// realization measures what a source and its separator cover (its own geodesic distance), so the
// sampler is the same for every representation.
//
// Sources are drawn ahead of their separators (Pipeline: a window of drawAhead sources), which are
// computed side by side: a draw also keeps away from the sources drawn before it whose separators are
// not covered yet (d_i is then the distance to the covered set or the straight distance to those
// sources, whichever is nearer: no solve, so a draw costs next to nothing), while coverage counts only
// what is covered.
class SourceSampler {
public:
  // areas: per element, the surface area it stands for (only ratios matter); diagonal: of the bounding box.
  SourceSampler(std::vector<geometrycentral::Vector3> positions, std::vector<double> areas, double diagonal, uint32_t seed);

  // The next source, away from what is covered and from the sources drawn and not covered yet.
  size_t next();

  // Marks as covered what `reach` measures (per element, its geodesic distance from a source and its
  // separator: a function of the shape alone, so a pool worker computes it with the separator), for the
  // oldest source drawn and not covered yet: sources are covered in the order they were drawn.
  void cover(const std::vector<double>& reach);

  // Share of the surface area within `radius` of what is covered.
  double coverage(double radius) const;

private:
  // Element v's straight distance to the uncovered sources, lowered to that of the one numbered `serial`.
  void offerUncovered(size_t v, size_t serial);

  std::vector<geometrycentral::Vector3> position;
  std::vector<double> area;
  std::mt19937 rng;
  std::vector<double> distance; // to the covered set; +infinity before the first source
  // The sources drawn and not covered yet, oldest first, with the serial number of the first; per
  // element the straight distance to the nearest of them and that one's serial number (so covering a
  // source revisits only the elements it was nearest to).
  std::deque<size_t> uncovered;
  size_t firstUncovered = 0;
  std::vector<double> nearUncovered;
  std::vector<double> nearUncoveredSquared; // its square, as computed (a square root of it gives nearUncovered)
  std::vector<size_t> nearestUncovered;
  // Per element, its draw weight and the distance it was computed for (NaN: not yet), and the running
  // sum of the weights a draw searches.
  std::vector<double> weight;
  std::vector<double> weightedAway;
  std::vector<double> cumulative;
  double scale;
  double totalArea = 0;
};

} // namespace cscd
