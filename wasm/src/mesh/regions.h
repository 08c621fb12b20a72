#pragma once

#include "cscd/bands.h"
#include "cscd/regions.h"
#include "mesh/surface.h"

#include <vector>

namespace cscd {

// One heat solve from all loops at once gives the distance to the nearest separator; each loop's seeds
// are the corners of the faces it runs through (a corner two loops pass goes to the nearer in space);
// the regions grow from them (growRegions in cscd/regions.h), so no solve per separator is needed.
Regions assignRegions(Surface& surface, const Samples& samples,
                      const std::vector<std::vector<geometrycentral::surface::SurfacePoint>>& loops);

} // namespace cscd
