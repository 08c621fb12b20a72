#pragma once

#include "geometrycentral/utilities/vector3.h"

#include <array>
#include <functional>
#include <map>
#include <set>
#include <vector>

namespace cscd {

// A skeleton graph: nodes with positions and radii, undirected edges.
struct SkeletonGraph {
  std::vector<geometrycentral::Vector3> nodes;
  std::vector<double> radii;
  std::vector<double> weights; // e.g. the surface area a node stands for, for weighted means
  std::vector<std::array<size_t, 2>> edges;

  size_t components() const;
  size_t cycleRank() const { return edges.size() + components() - nodes.size(); }
};

// A packed separator as the clique-to-star step sees it: its loop's centroid, unit normal and radius;
// a zero normal where it has none (an open path).
struct SeparatorFrame {
  geometrycentral::Vector3 centre{0, 0, 0};
  geometrycentral::Vector3 normal{0, 0, 0};
  double radius = 0;
};

// Clique to star (paper Sec. 4.2.5, after LS): 3-cliques that are junctions are grouped when they share
// an edge, and each group becomes a star around a new node at the weighted mean of its members. Only
// triangles listed in `junctions` (sorted node triples, with the place where the three meet) count: three
// regions that meet at one place of the surface. A ring of three regions that touch pairwise in three
// different places is a cycle of the shape (e.g. a torus cut by three separators), not a junction, and is
// kept. A junction of three consecutive slices of one tube (`separators[i]`: node i's separator, for the
// first nodes) is no branching: its edge between the outer two is dropped instead. A group whose
// junctions are spread over many separator radii, around no deep middle, is a tiling of the surface
// (`surface`: the shape's elements), not one branching, and so, where the separators may go round the
// noise (`noisy`), is a group of many members spread over many of their radii at any depth (the tiles
// of a whole blob), and a group whose triangles go round a hole of the shape (a cycle of the group that
// its triangles do not fill, whose middle is not `inside`): their members are joined by the shortest
// tree of their edges, plus an edge closing each such hole.
void cliquesToStars(SkeletonGraph& graph, const std::map<std::array<size_t, 3>, geometrycentral::Vector3>& junctions,
                    const std::vector<SeparatorFrame>& separators, const std::vector<geometrycentral::Vector3>& surface,
                    const std::function<bool(const geometrycentral::Vector3&)>& inside, bool noisy);

} // namespace cscd
