#pragma once

#include "cscd/graph.h"

#include <functional>

namespace cscd {

// A cycle of the skeleton is a handle of the shape only if no disk it bounds lies inside the shape: a
// cycle whose disk does (three cross-sections of one tube whose regions touched past each other) can be
// shrunk to a point within the shape, and closes no hole. Each edge, longest first, with the shortest
// other path between its ends (edge lengths in space), makes a cycle; its disk is sampled as the cone
// from the cycle's centroid to its nodes and edge midpoints, and the edge is dropped when every sample
// is `inside`. A handle's cycle goes round its hole, where its centroid lies, so it keeps its edges.
// (docs/skeleton.md, "Filled cycles")
void openFilledCycles(SkeletonGraph& graph, const std::function<bool(const geometrycentral::Vector3&)>& inside);

} // namespace cscd
