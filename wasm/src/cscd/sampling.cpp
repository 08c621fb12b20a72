#include "cscd/sampling.h"

#include <algorithm>
#include <cmath>

using namespace geometrycentral;

namespace cscd {

SourceSampler::SourceSampler(std::vector<Vector3> positions, std::vector<double> areas, double diagonal, uint32_t seed)
    : position(std::move(positions)), area(std::move(areas)), rng(seed), distance(area.size(), INFINITY),
      nearUncovered(area.size(), INFINITY), nearUncoveredSquared(area.size(), INFINITY), nearestUncovered(area.size()),
      weight(area.size()), weightedAway(area.size(), NAN), cumulative(area.size()), scale(diagonal / 10) {
  for (double a : area) totalArea += a;
}

size_t SourceSampler::next() {
  // Unreached vertices (nothing sampled yet in their component) get the largest finite weight.
  constexpr double kMaxExponent = 50;
  double sum = 0;
  bool anyCovered = !uncovered.empty() || std::any_of(distance.begin(), distance.end(), [](double d) { return std::isfinite(d); });
  for (size_t v = 0; v < area.size(); v++) {
    const double away = std::min(distance[v], nearUncovered[v]);
    // Most elements are as far as at the last draw: their weight is kept (no expm1 for them).
    if (!(away == weightedAway[v])) {
      weightedAway[v] = away;
      weight[v] = area[v] * std::expm1(std::isfinite(away) ? std::min(away / scale, kMaxExponent) : kMaxExponent);
    }
    cumulative[v] = sum += anyCovered ? weight[v] : area[v];
  }
  // 53 random bits make a uniform double in [0, 1) the same way on every platform.
  double u = double((uint64_t(rng()) << 21) ^ uint64_t(rng() >> 11)) / 9007199254740992.0;
  size_t source = size_t(std::upper_bound(cumulative.begin(), cumulative.end(), u * sum) - cumulative.begin());
  source = std::min(source, area.size() - 1);

  const size_t serial = firstUncovered + uncovered.size();
  uncovered.push_back(source);
  for (size_t v = 0; v < area.size(); v++) offerUncovered(v, serial);
  return source;
}

void SourceSampler::cover(const std::vector<double>& reach) {
  for (size_t v = 0; v < reach.size(); v++) distance[v] = std::min(distance[v], reach[v]);
  if (uncovered.empty()) return;
  const size_t gone = firstUncovered++;
  uncovered.pop_front();
  for (size_t v = 0; v < area.size(); v++) {
    if (!std::isfinite(nearUncovered[v]) || nearestUncovered[v] != gone) continue;
    nearUncovered[v] = nearUncoveredSquared[v] = INFINITY;
    for (size_t k = 0; k < uncovered.size(); k++) offerUncovered(v, firstUncovered + k);
  }
}

void SourceSampler::offerUncovered(size_t v, size_t serial) {
  // Most elements are nearer to another uncovered source: compared squared, they need no square root.
  const double squared = norm2(position[v] - position[uncovered[serial - firstUncovered]]);
  if (!(squared < nearUncoveredSquared[v])) return;
  const double d = std::sqrt(squared);
  if (d < nearUncovered[v]) {
    nearUncovered[v] = d;
    nearUncoveredSquared[v] = squared;
    nearestUncovered[v] = serial;
  }
}

double SourceSampler::coverage(double radius) const {
  double covered = 0;
  for (size_t v = 0; v < area.size(); v++)
    if (distance[v] <= radius) covered += area[v];
  return totalArea > 0 ? covered / totalArea : 1;
}

} // namespace cscd
