#pragma once

#include "cscd/ridge_tree.h"

#include "geometrycentral/surface/intrinsic_triangulation.h"

#include <array>
#include <vector>

namespace cscd {

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
  std::vector<size_t> linkingTree(const std::vector<size_t>& parent, const std::vector<char>& kept,
                                  const std::vector<double>& distance) const;
  std::vector<size_t> homologyGenerators(const std::vector<size_t>& parent, const std::vector<double>& distance,
                                         size_t source) const;

  size_t nVertices = 0;
  double meanEdge = 0;
  std::vector<std::array<size_t, 3>> faceVertices;
  std::vector<std::array<Vec2, 3>> faceHatGradients; // gradient of each barycentric hat function, face frame
  std::vector<std::array<size_t, 3>> faceEdges;
  std::vector<std::array<size_t, 2>> edgeFaces; // SIZE_MAX on the boundary side
  NeighbourGraph graph;                         // the intrinsic edges, each vertex's in its one-ring's order
  // Per entry of the graph's rows: the edge's cotan weight, and the unit complex number that rotates the
  // neighbour's frame into this vertex's.
  std::vector<double> cotanWeight;
  std::vector<Vec2> transportToCenter;
  std::vector<size_t> cornerStart; // CSR offsets into corners
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
