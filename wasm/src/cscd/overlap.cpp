#include "cscd/overlap.h"

#include <algorithm>
#include <cmath>
#include <tuple>
#include <cstdint>
#include <unordered_map>
#include <unordered_set>

using geometrycentral::Vector3;

namespace cscd {
namespace {

// Squared distance between segments pq and rs (Ericson, Real-Time Collision Detection, 5.1.9).
double segmentDistance2(Vector3 p, Vector3 q, Vector3 r, Vector3 s) {
  Vector3 d1 = q - p, d2 = s - r, w = p - r;
  double a = dot(d1, d1), e = dot(d2, d2), f = dot(d2, w);
  double t1 = 0, t2 = 0;
  if (a <= 1e-30 && e <= 1e-30) return norm2(w);
  if (a <= 1e-30) {
    t2 = std::clamp(f / e, 0.0, 1.0);
  } else {
    double c = dot(d1, w);
    if (e <= 1e-30) {
      t1 = std::clamp(-c / a, 0.0, 1.0);
    } else {
      double b = dot(d1, d2), denom = a * e - b * b;
      t1 = denom > 0 ? std::clamp((b * f - c * e) / denom, 0.0, 1.0) : 0;
      t2 = (b * t1 + f) / e;
      if (t2 < 0) {
        t2 = 0;
        t1 = std::clamp(-c / a, 0.0, 1.0);
      } else if (t2 > 1) {
        t2 = 1;
        t1 = std::clamp((b - c) / a, 0.0, 1.0);
      }
    }
  }
  return norm2((p + t1 * d1) - (r + t2 * d2));
}

struct CellHash {
  size_t operator()(const std::tuple<long, long, long>& c) const {
    auto [x, y, z] = c;
    return size_t(x) * 73856093u ^ size_t(y) * 19349663u ^ size_t(z) * 83492791u;
  }
};

} // namespace

std::vector<std::vector<size_t>> overlappingLoops(const std::vector<std::vector<Vector3>>& loops,
                                                  const std::vector<char>& closed, double tolerance) {
  // Cells as large as the longest segment (and the tolerance): a segment then spans few cells.
  double cell = tolerance;
  for (size_t l = 0; l < loops.size(); l++)
    for (size_t i = 0; i + (closed[l] ? 0 : 1) < loops[l].size(); i++)
      cell = std::max(cell, norm(loops[l][(i + 1) % loops[l].size()] - loops[l][i]));
  struct Segment {
    size_t loop, index;
  };
  std::unordered_map<std::tuple<long, long, long>, std::vector<Segment>, CellHash> grid;
  auto cellOf = [&](double x) { return long(std::floor(x / cell)); };
  for (size_t l = 0; l < loops.size(); l++)
    for (size_t i = 0; i + (closed[l] ? 0 : 1) < loops[l].size(); i++) {
      Vector3 a = loops[l][i], b = loops[l][(i + 1) % loops[l].size()];
      for (long x = cellOf(std::min(a.x, b.x) - tolerance); x <= cellOf(std::max(a.x, b.x) + tolerance); x++)
        for (long y = cellOf(std::min(a.y, b.y) - tolerance); y <= cellOf(std::max(a.y, b.y) + tolerance); y++)
          for (long z = cellOf(std::min(a.z, b.z) - tolerance); z <= cellOf(std::max(a.z, b.z) + tolerance); z++)
            grid[{x, y, z}].push_back({l, i});
    }

  // Many loops crowd the same cells (every source on a tube finds about the same loop): a cell's
  // segments come in runs of one loop (filed loop by loop), and each pair of runs is looked up once in
  // the set of pairs found, then tested segment by segment until one pair is close.
  const uint64_t n = loops.size();
  std::unordered_set<uint64_t> found;
  const double tolerance2 = tolerance * tolerance;
  auto close = [&](const Segment& s, const Segment& t) {
    const auto &ls = loops[s.loop], &lt = loops[t.loop];
    return segmentDistance2(ls[s.index], ls[(s.index + 1) % ls.size()], lt[t.index], lt[(t.index + 1) % lt.size()]) <= tolerance2;
  };
  std::vector<size_t> runStart;
  for (const auto& [key, segments] : grid) {
    runStart.clear();
    for (size_t i = 0; i < segments.size(); i++)
      if (i == 0 || segments[i].loop != segments[i - 1].loop) runStart.push_back(i);
    runStart.push_back(segments.size());
    for (size_t a = 0; a + 1 < runStart.size(); a++)
      for (size_t b = a + 1; b + 1 < runStart.size(); b++) {
        const uint64_t pair = segments[runStart[a]].loop * n + segments[runStart[b]].loop;
        if (found.count(pair)) continue;
        bool hit = false;
        for (size_t i = runStart[a]; i < runStart[a + 1] && !hit; i++)
          for (size_t j = runStart[b]; j < runStart[b + 1] && !hit; j++) hit = close(segments[i], segments[j]);
        if (hit) found.insert(pair);
      }
  }
  std::vector<std::vector<size_t>> overlaps(n);
  for (uint64_t key : found) {
    overlaps[key / n].push_back(key % n);
    overlaps[key % n].push_back(key / n);
  }
  for (auto& list : overlaps) std::sort(list.begin(), list.end());
  return overlaps;
}

} // namespace cscd
