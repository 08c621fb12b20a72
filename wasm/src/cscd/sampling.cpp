#include "cscd/sampling.h"

#include <algorithm>
#include <cmath>

using namespace geometrycentral;

namespace cscd {

SourceSampler::SourceSampler(std::vector<Vector3> positions, std::vector<double> areas, double diagonal, uint32_t seed)
    : position(std::move(positions)), area(std::move(areas)), rng(seed), distance(area.size(), INFINITY),
      scale(diagonal / 10) {
  for (double a : area) totalArea += a;
}

size_t SourceSampler::next(const std::vector<size_t>& round) {
  if (round.empty()) {
    roundSeen = 0;
  } else {
    if (roundSeen == 0) nearRound = distance;
    for (; roundSeen < round.size(); roundSeen++) {
      const Vector3 p = position[round[roundSeen]];
      for (size_t v = 0; v < area.size(); v++) nearRound[v] = std::min(nearRound[v], norm(position[v] - p));
    }
  }
  const std::vector<double>& away = round.empty() ? distance : nearRound;
  // Unreached vertices (nothing sampled yet in their component) get the largest finite weight.
  constexpr double kMaxExponent = 50;
  std::vector<double> cumulative(area.size());
  double sum = 0;
  bool anyCovered = std::any_of(away.begin(), away.end(), [](double d) { return std::isfinite(d); });
  for (size_t v = 0; v < area.size(); v++) {
    double weight = area[v];
    if (anyCovered) weight *= std::expm1(std::isfinite(away[v]) ? std::min(away[v] / scale, kMaxExponent) : kMaxExponent);
    cumulative[v] = sum += weight;
  }
  // 53 random bits make a uniform double in [0, 1) the same way on every platform.
  double u = double((uint64_t(rng()) << 21) ^ uint64_t(rng() >> 11)) / 9007199254740992.0;
  size_t v = size_t(std::upper_bound(cumulative.begin(), cumulative.end(), u * sum) - cumulative.begin());
  return std::min(v, area.size() - 1);
}

void SourceSampler::cover(const std::vector<double>& reach) {
  for (size_t v = 0; v < reach.size(); v++) distance[v] = std::min(distance[v], reach[v]);
}

double SourceSampler::coverage(double radius) const {
  double covered = 0;
  for (size_t v = 0; v < area.size(); v++)
    if (distance[v] <= radius) covered += area[v];
  return totalArea > 0 ? covered / totalArea : 1;
}

} // namespace cscd
