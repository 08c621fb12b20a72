#pragma once

#include "evaluate/convolution_surface.h"

#include <vector>

namespace cscd {

// Vertices used by at least one triangle.
std::vector<bool> referencedVertices(const TriangleMesh& mesh);

// The radius of the tube that best fits the surface around each skeleton node: every mesh vertex finds
// its closest point on the skeleton's segments, at distance d, and lends d to the segment's two nodes,
// weighted linearly by where that point lies (all to a node when it is the point); a node's radius is
// the weighted mean. A node no vertex chose (one hidden inside a junction) gets its distance to the
// surface. Used for CSCD's own node radii and for skeletons of other tools that carry none.
std::vector<double> tubeRadii(const TriangleMesh& mesh, const SkeletonCurves& skeleton);

// The same around a point cloud's points (a node no point chose gets its distance to the nearest point).
std::vector<double> tubeRadii(const std::vector<Vector3>& points, const SkeletonCurves& skeleton);

} // namespace cscd
