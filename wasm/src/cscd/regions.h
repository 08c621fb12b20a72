#pragma once

#include "geometrycentral/utilities/vector3.h"

#include <array>
#include <cstdint>
#include <set>
#include <vector>

namespace cscd {

// The shape divided among the packed separators (paper Sec. 4.2.4): every element (vertex, point)
// belongs to its geodesically nearest separator; parts of the shape no separator reaches become one
// region each.
struct Regions {
  std::vector<uint32_t> label;    // per element: regions 0..separators-1 are the separators', then the rest
  std::vector<double> distance;   // per element: to the nearest separator (+infinity where none reaches)
  size_t count = 0;
  std::vector<geometrycentral::Vector3> centroid; // area-weighted
  std::vector<double> area;
  std::set<std::array<size_t, 2>> adjacent;  // regions that touch (sorted pairs)
  std::set<std::array<size_t, 3>> junctions; // regions that meet in one place (sorted triples)
};

} // namespace cscd
