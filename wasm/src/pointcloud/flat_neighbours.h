#pragma once

#include "geometrycentral/pointcloud/point_cloud.h"
#include "geometrycentral/utilities/vector3.h"

#include <vector>

namespace cscd {

// Each point's k nearest neighbours (nearest first) cut to the largest count m, at least
// kMinFlatNeighbours, at which they lie flat: the point and its m nearest have a covariance whose least
// eigenvalue is at most kMaxFlatness of its trace. Across a part thinner than the neighbourhood
// (a leg a few spacings round, a plate whose two sheets are closer than the k-th neighbour) the k
// nearest are not a disc of the surface, and a point's local triangulation projected to its tangent
// plane folds them over one another; a flat part, a sparse region or a rim keeps all k (one count for
// the whole cloud cannot be narrow at the first and wide at the others: docs/pointcloud.md, "A
// neighbour count per point"). Returns how many neighbours were left out in all.
size_t trimToFlat(geometrycentral::pointcloud::PointData<std::vector<geometrycentral::pointcloud::Point>>& neighbours,
                  const geometrycentral::pointcloud::PointData<geometrycentral::Vector3>& positions);

} // namespace cscd
