#pragma once

#include "geometrycentral/surface/intrinsic_triangulation.h"

#include <array>
#include <vector>

namespace cscd {

// How the ridge tree is cut down to the vertices that pass the thresholds.
enum class CutLocusRestriction {
  Growing, // breadth-first from the root through passing vertices: passing parts not reached are lost
  Pruning, // every passing vertex with its tree path to the root: weak stretches of ridge are bridged
};

// Thresholds of the practical cut locus (Mancinelli, Livesu, Puppo 2021), all scale-free.
struct CutLocusOptions {
  // theta, radians in [0, pi]: a vertex can be on the cut locus only if the gradient of the distance
  // turns by at least this much towards one of its neighbours (gradients collide across a ridge).
  double angleThreshold = 1.75;
  // lambda >= 0: a vertex can be on the cut locus only if h * (Laplacian of the distance) <= -lambda,
  // h the mean intrinsic edge length. The distance has a ridge (a concave kink) on the cut locus.
  double laplacianThreshold = 0.2;
  CutLocusRestriction restriction = CutLocusRestriction::Pruning;
  // Leaf branches with fewer edges than this are removed (0 keeps everything).
  int pruneDepth = 3;
  // Every vertex's angle deviation, for teaching views. Without it, only vertices that pass the other
  // tests and whose gradients turn by nearly the threshold or more get theirs (NaN elsewhere): the only
  // ones the thresholds look at.
  bool everyAngle = true;
};

// The cut locus of one source as a graph on mesh vertices.
struct CutLocus {
  std::vector<size_t> vertices;             // graph nodes, as input (== intrinsic) vertex indices
  std::vector<std::array<size_t, 2>> edges; // indices into `vertices`, each edge an intrinsic edge
  // Per-vertex fields over the whole mesh, kept for teaching views (NaN outside the source's component).
  std::vector<double> angleDeviation; // radians (see CutLocusOptions::everyAngle)
  std::vector<double> laplacian;      // h * Laplacian of the distance, negative on ridges
  size_t root = 0;                    // the vertex farthest from the source

  size_t components() const;
  size_t cycleRank() const { return edges.size() + components() - vertices.size(); }
};

// Precomputes everything that does not depend on the source (gradient operators, tangent frames and
// transport, cotan Laplacian, vertex areas, adjacency, per-component topology) from an intrinsic
// Delaunay triangulation whose vertices are the input vertices. The data is copied, so later
// mutation of the triangulation (e.g. loop shortening by flips) does not affect the solver.
class CutLocusSolver {
public:
  explicit CutLocusSolver(geometrycentral::surface::IntrinsicTriangulation& intrinsic);

  // distance: per vertex, +infinity outside the source's component. Const and allocation-local, so one
  // solver serves any number of sources.
  CutLocus compute(const std::vector<double>& distance, size_t source, const CutLocusOptions& options = {}) const;

  double meanEdgeLength() const { return meanEdge; }

private:
  using Vec2 = std::array<double, 2>;

  // Sparse rows over vertices: neighbours plus one value per neighbour.
  struct VertexNeighbour {
    size_t vertex;
    size_t edge;
    double cotanWeight;
    Vec2 transportToCenter; // unit complex number: neighbour frame -> this vertex's frame
  };
  struct Corner {
    size_t face;
    double weight;      // face area
    Vec2 faceToVertex;  // unit complex number: face frame -> vertex frame
  };

  Vec2 faceGradient(size_t face, const std::vector<double>& distance) const;
  Vec2 vertexGradient(size_t vertex, const std::vector<double>& distance) const;
  std::vector<double> angleDeviations(const std::vector<double>& distance, const std::vector<double>& laplacian,
                                      const CutLocusOptions& options) const;
  // Whether a vertex passes every test but the angle's (which costs its ring's gradients).
  bool mayPass(size_t vertex, const std::vector<double>& laplacian, const CutLocusOptions& options) const;
  std::vector<double> distanceLaplacian(const std::vector<double>& distance) const;
  // Trees are stored as the edge to the parent of every vertex (NONE at the root and off the component);
  // up() is the parent vertex (or NONE).
  size_t up(const std::vector<size_t>& parentEdge, size_t v) const;
  std::vector<char> passingVertices(const std::vector<double>& angleDeviation, const std::vector<double>& laplacian,
                                    const CutLocusOptions& options) const;
  std::vector<size_t> ridgeTree(const std::vector<double>& laplacian, const std::vector<char>& passing,
                                const std::vector<double>& distance, size_t root) const;
  std::vector<char> restrictTree(const std::vector<size_t>& parent, const std::vector<char>& passing, size_t root,
                                 CutLocusRestriction mode) const;
  std::vector<size_t> linkingTree(const std::vector<size_t>& parent, const std::vector<char>& kept,
                                  const std::vector<double>& distance) const;
  std::vector<size_t> homologyGenerators(const std::vector<size_t>& parent, const std::vector<double>& distance,
                                         size_t source) const;

  size_t nVertices = 0;
  double meanEdge = 0;
  std::vector<std::array<size_t, 3>> faceVertices;
  std::vector<std::array<Vec2, 3>> faceHatGradients; // gradient of each barycentric hat function, face frame
  std::vector<std::array<size_t, 3>> faceEdges;
  std::vector<std::array<size_t, 2>> edgeVertices;
  std::vector<std::array<size_t, 2>> edgeFaces; // SIZE_MAX on the boundary side
  std::vector<size_t> rowStart;                 // CSR offsets into neighbours and corners (same per vertex)
  std::vector<VertexNeighbour> neighbours;
  std::vector<size_t> cornerStart;
  std::vector<Corner> corners;
  std::vector<double> vertexArea;
  // Boundary vertices never pass the thresholds: their one-sided Laplacian measures the flux through
  // the boundary, not a ridge, and would line every hole with cut locus. Separators reach the boundary
  // through boundary extremities instead (mesh/boundary.h).
  std::vector<char> onBoundary;
  std::vector<int> vertexComponent;
  std::vector<long> componentGenus; // -1 for components with boundary: no homology step there
};

} // namespace cscd
