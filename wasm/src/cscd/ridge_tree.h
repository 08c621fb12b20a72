#pragma once

#include "cscd/options.h"

#include <array>
#include <cstddef>
#include <limits>
#include <vector>

namespace cscd {

// The representation-independent half of the practical cut locus (Mancinelli, Livesu, Puppo 2021):
// once every vertex (mesh vertex or cloud point) has its scale-free Laplacian of the distance and the
// angle its ring's gradients turn by, the ridge tree, its restriction and its pruning only see a graph.
// CSCD-M runs it on the intrinsic triangulation's edges (mesh/cut_locus.h), CSCD-PC on the cloud's
// neighbourhood graph (pointcloud/cut_locus.h).

// How the ridge tree is cut down to the vertices that pass the thresholds.
enum class CutLocusRestriction {
  Growing, // breadth-first from the root through passing vertices: passing parts not reached are lost
  Pruning, // every passing vertex with its tree path to the root: weak stretches of ridge are bridged
};

// Thresholds of the practical cut locus, all scale-free.
struct CutLocusOptions {
  // theta, radians in [0, pi]: a vertex can be on the cut locus only if the gradient of the distance
  // turns by at least this much towards one of its neighbours (gradients collide across a ridge).
  double angleThreshold = 1.75;
  // lambda >= 0: a vertex can be on the cut locus only if h * (Laplacian of the distance) <= -lambda,
  // h the mean edge length. The distance has a ridge (a concave kink) on the cut locus.
  double laplacianThreshold = 0.2;
  CutLocusRestriction restriction = CutLocusRestriction::Pruning;
  // Leaf branches with fewer edges than this are removed (0 keeps everything).
  int pruneDepth = 3;
  // Every vertex's angle deviation, for teaching views. Without it, only vertices that pass the other
  // tests and whose gradients turn by nearly the threshold or more get theirs (NaN elsewhere): the only
  // ones the thresholds look at.
  bool everyAngle = true;
};

// The cut-locus thresholds of the run's options (the teaching-only everyAngle left to the caller).
inline CutLocusOptions cutLocusOptionsOf(const Options& options) {
  CutLocusOptions cutLocus;
  cutLocus.angleThreshold = options.angleThreshold;
  cutLocus.laplacianThreshold = options.laplacianThreshold;
  cutLocus.pruneDepth = options.pruneDepth;
  return cutLocus;
}

// The cut locus of one source as a graph on the shape's vertices (mesh vertices or cloud points).
struct CutLocus {
  std::vector<size_t> vertices;             // graph nodes, as vertex indices
  std::vector<std::array<size_t, 2>> edges; // indices into `vertices`, each an edge of the graph it was grown on
  // Per-vertex fields over the whole shape, kept for teaching views (NaN outside the source's component).
  std::vector<double> angleDeviation; // radians (see CutLocusOptions::everyAngle)
  std::vector<double> laplacian;      // h * Laplacian of the distance, negative on ridges
  size_t root = 0;                    // the vertex farthest from the source

  size_t components() const;
  size_t cycleRank() const { return edges.size() + components() - vertices.size(); }
};

// An undirected graph in compressed rows: vertex v's neighbours are neighbour[rowStart[v] ..
// rowStart[v + 1]), each reached by the edge of the same position in `edge`.
struct NeighbourGraph {
  std::vector<size_t> rowStart;
  std::vector<size_t> neighbour;
  std::vector<size_t> edge;
  std::vector<std::array<size_t, 2>> edgeVertices;

  size_t vertexCount() const { return rowStart.empty() ? 0 : rowStart.size() - 1; }
};

// Trees are stored as the edge to the parent of every vertex (kNoParent at the root and off the tree).
constexpr size_t kNoParent = std::numeric_limits<size_t>::max();

// The parent vertex of v, or kNoParent.
size_t treeParent(const NeighbourGraph& graph, const std::vector<size_t>& parentEdge, size_t v);

// Largest angle between any two of a ring's gradient directions (unit vectors in one tangent frame), as
// its cosine: across a ridge the gradients of the two sides point against each other.
double smallestCosine(const std::vector<std::array<double, 2>>& directions);

// A ring's angle deviation from its smallest cosine; NaN without options.everyAngle where the angle is
// below the threshold by far more than rounding (no arc cosine needed: the threshold is all that looks).
double ringAngle(double smallestCosine, const CutLocusOptions& options);

// Whether each vertex passes both tests, h * Laplacian <= -lambda and angle >= theta (never an `excluded` one).
std::vector<char> passingVertices(const std::vector<double>& angleDeviation, const std::vector<double>& laplacian,
                                  const std::vector<char>& excluded, const CutLocusOptions& options);

// Spanning tree of the root's component (vertices with a finite distance), grown Prim-style from the
// most ridge-like frontier vertex first, passing vertices ahead of all others (see ridge_tree.cpp).
std::vector<size_t> ridgeTree(const NeighbourGraph& graph, const std::vector<double>& laplacian,
                              const std::vector<char>& passing, const std::vector<double>& distance, size_t root);

// The vertices kept of the tree: see CutLocusRestriction.
std::vector<char> restrictTree(const NeighbourGraph& graph, const std::vector<size_t>& parent,
                               const std::vector<char>& passing, size_t root, CutLocusRestriction mode);

// The kept vertices with their tree edges and `extraEdges` (vertex pairs, e.g. homology generators),
// leaf branches shorter than pruneDepth edges removed, as the nodes and edges of `result`.
void assembleCutLocus(const NeighbourGraph& graph, const std::vector<size_t>& parent, std::vector<char> kept,
                      const std::vector<std::array<size_t, 2>>& extraEdges, int pruneDepth, CutLocus& result);

} // namespace cscd
