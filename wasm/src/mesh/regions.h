#pragma once

#include "cscd/regions.h"
#include "mesh/surface.h"

#include <vector>

namespace cscd {

// One heat solve from all loops at once gives the distance to the nearest separator; labels then flow
// from each loop's own vertices outwards in order of increasing distance (a watershed), each vertex
// taking the label of its nearest already-labelled neighbour. Every region is thus connected, and no
// solve per separator is needed.
Regions assignRegions(Surface& surface, const std::vector<std::vector<geometrycentral::surface::SurfacePoint>>& loops);

} // namespace cscd
