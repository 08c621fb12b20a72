#pragma once

#include "geometrycentral/utilities/vector3.h"

#include <array>
#include <vector>

namespace cscd {

// Length-weighted centroid of a polyline; a closed one has its last point joined to the first.
geometrycentral::Vector3 loopCentroid(const std::vector<geometrycentral::Vector3>& loop, bool closed);

// Length of a closed loop (its last point joined to the first).
double loopLength(const std::vector<geometrycentral::Vector3>& loop);

// Unit normal of the loop's vector area (the direction it winds around); zero for a degenerate loop.
geometrycentral::Vector3 loopNormal(const std::vector<geometrycentral::Vector3>& loop);

// The direction an open path across a sheet separates, the analogue of a loop's normal: across the
// chord between its ends, in the tangent plane of the surface (`surfaceNormal`, e.g. the mean normal
// of the faces it crosses). Zero when the path is degenerate.
geometrycentral::Vector3 pathNormal(const std::vector<geometrycentral::Vector3>& path,
                                    geometrycentral::Vector3 surfaceNormal);

// The separator score of paper Sec. 4.2.1: s = A1 / (A2 * length), A1 <= A2 the areas of the two sides.
double separatorScore(const std::array<double, 2>& areas, double length);

} // namespace cscd
