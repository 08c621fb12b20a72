#pragma once

#include "cscd/graph.h"

#include <functional>
#include <vector>

namespace cscd {

// Cycles of the skeleton that the shape does not have, opened at the end of stage 2. Both rules take
// each edge, longest first, that still lies on a cycle (the shortest other path between its ends, edge
// lengths in space, closes it) and drop it when the rule says so; an edge on no cycle is never dropped,
// so the skeleton keeps its pieces.

// A cycle is a handle of the shape only if no disk it bounds lies inside the shape: a cycle whose disk
// does (three cross-sections of one tube whose regions touched past each other) can be shrunk to a point
// within the shape, and closes no hole. The disk is sampled as the cone from the cycle's centroid to its
// nodes and edge midpoints, and the edge is dropped when every sample is `inside`. A handle's cycle goes
// round its hole, where its centroid lies, so it keeps its edges. (docs/skeleton.md, "Filled cycles")
void openFilledCycles(SkeletonGraph& graph, const std::function<bool(const geometrycentral::Vector3&)>& inside);

// An edge that leaves the shape joins parts that touch nowhere along it (two branches of a scanned tree
// crown, regions that met where the scan's branches pass close): a point of it farther than
// kAirInRadii times the larger radius of its two nodes from every element of the shape (`surface`) lies
// in the air, and the edge is dropped. A point within a tube lies about a radius from its surface.
// Needs the graph's radii; returns whether an edge was dropped. (docs/skeleton.md, "Cycles through the air")
bool openCyclesThroughAir(SkeletonGraph& graph, const std::vector<geometrycentral::Vector3>& surface);

} // namespace cscd
