#pragma once

#include "cscd/ridge_tree.h"

#include <string>
#include <unordered_map>
#include <vector>

namespace cscd {

// The approximate loop of paper Sec. 4.1.4 / Alg. 3, on any graph of vertices: from the target, two
// steepest-descent paths of the distance towards the source, started on the two sides of the cut locus
// and cut where they meet. CSCD-M traces it on the intrinsic triangulation (mesh/trace.h), CSCD-PC on
// the cloud's neighbourhood graph (pointcloud/trace.h). On a surface with boundary it can be an open
// path instead: the two descents start at two boundary extremities (mesh/boundary.h).
struct TracedLoop {
  std::vector<size_t> firstPath;  // target (or first boundary end) ... meeting vertex (vertex indices)
  std::vector<size_t> secondPath; // target (or second boundary end) ... meeting vertex
  // Closed: target, first path, meeting vertex, second path back (target not repeated).
  // Open: first end, first path, meeting vertex, second path back to the second end.
  std::vector<size_t> loop;
  bool closed = true;
  std::string failure; // why no loop could be traced; empty on success
};

// Every cut-locus vertex's neighbours along the cut locus (vertex indices), by vertex index: listed once
// per cut locus, as a cloud looks at every cut-locus point as a target (scanning the edges for each cost
// a noisy cloud's source 20-45 ms).
using CutLocusNeighbours = std::unordered_map<size_t, std::vector<size_t>>;
CutLocusNeighbours cutLocusNeighbours(const CutLocus& cutLocus);

// The two neighbours of the target from which the wavefront arrived, on either side of the cut locus:
// `ring` (the target's neighbours in their cyclic order around it) is split into arcs by the target's
// cut-locus neighbours and the lowest vertex of the two lowest arcs is taken. At a branch end (one
// cut-locus neighbour or none) the ring is halved opposite it. Empty when there are no two.
std::vector<size_t> incomingNeighbours(const std::vector<size_t>& ring, const std::vector<double>& distance,
                                       const CutLocusNeighbours& alongCutLocus, size_t target);

// Greedy descent (Alg. 3) from path.back(): always to the neighbour with the smallest distance (the
// first one of equals, in the order forEachNeighbour(v, visit) visits them), until the source. False
// at a local minimum of the distance away from the source.
template <class ForEachNeighbour>
bool descend(ForEachNeighbour&& forEachNeighbour, const std::vector<double>& distance, size_t source,
             std::vector<size_t>& path) {
  while (path.back() != source) {
    const size_t current = path.back();
    size_t next = current;
    forEachNeighbour(current, [&](size_t w) {
      if (distance[w] < distance[next]) next = w;
    });
    if (next == current) return false;
    path.push_back(next);
  }
  return true;
}

// Both descents end at the source; each is cut at the first vertex they share after their start, and
// the loop (or path, when !traced.closed) is made of them.
void joinDescents(TracedLoop& traced);

} // namespace cscd
