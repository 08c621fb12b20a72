#pragma once

#include "geometrycentral/utilities/vector3.h"

#include <vector>

namespace cscd {

// Separators closer than this many units of the shape's resolution (mean edge length, mean spacing)
// overlap: a slab between them too thin to hold an element would let the regions on either side
// touch and form spurious junctions.
constexpr double kOverlapTolerance = 1.0;

// Which loops (closed polylines) and paths (open ones, closed[i] == 0) overlap: they cross or touch, i.e. two of their segments come within `tolerance`
// of each other in space. (The paper tests crossings inside input faces; our loops run along the
// intrinsic triangulation, so the test is made in space on the loops' polylines, which lie on the
// surface, as the paper does for point clouds.) Segments are hashed into a uniform grid, so the cost
// grows with the total loop length, not with the number of pairs. Returns, per loop, the sorted
// indices of the loops it overlaps.
std::vector<std::vector<size_t>> overlappingLoops(const std::vector<std::vector<geometrycentral::Vector3>>& loops,
                                                  const std::vector<char>& closed, double tolerance);

} // namespace cscd
