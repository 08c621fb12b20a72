#pragma once

#include "cscd/graph.h"
#include "cscd/measures.h"
#include "cscd/pipeline.h"

namespace cscd {

// Region and branch nodes placed (the realization's centre step, the same for every representation).
// A separator's node keeps its region centroid's position along the separator's normal (so end regions
// reach towards their tips) but takes the loop centroid's position across it: on a bent tube the outer
// side has more area and drags the region centroid outwards (by r^2 / 2R on a torus), while the
// centroid of a loop around the tube stays on its axis. A node that still falls outside the shape moves
// to the loop centroid, which is inside (loops with an outside centroid were pruned); a branch node
// outside moves to its heaviest neighbour's position.
// A path across a sheet (open separator) has no inside: its node keeps the region centroid along the
// path's normal and the path centroid across it, and so do junctions next to such paths.
// normalOf(candidate): the loop's normal, or a path's direction across the sheet; inside(point).
template <class C, class NormalOf, class Inside>
void centreNodes(SkeletonGraph& graph, const Selection<C>& packed, NormalOf normalOf, Inside inside) {
  for (size_t node = 0; node < packed.size(); node++) {
    const C& c = *packed[node];
    geometrycentral::Vector3 centroid = loopCentroid(c.loop, c.closed), n = normalOf(c);
    graph.nodes[node] = centroid + dot(graph.nodes[node] - centroid, n) * n;
    if (c.closed && !inside(graph.nodes[node])) graph.nodes[node] = centroid;
  }
  for (size_t node = packed.size(); node < graph.nodes.size(); node++) {
    if (graph.weights[node] != 0) continue;
    size_t heaviest = SIZE_MAX;
    bool nextToPath = false;
    for (const auto& e : graph.edges) {
      size_t other = e[0] == node ? e[1] : e[1] == node ? e[0] : SIZE_MAX;
      if (other == SIZE_MAX) continue;
      nextToPath = nextToPath || (other < packed.size() && !packed[other]->closed);
      if (heaviest == SIZE_MAX || graph.weights[other] > graph.weights[heaviest]) heaviest = other;
    }
    if (heaviest != SIZE_MAX && !nextToPath && !inside(graph.nodes[node])) graph.nodes[node] = graph.nodes[heaviest];
  }
}

} // namespace cscd
