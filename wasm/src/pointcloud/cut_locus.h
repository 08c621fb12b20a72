#pragma once

#include "cscd/ridge_tree.h"
#include "pointcloud/neighbourhood.h"

#include "geometrycentral/surface/edge_length_geometry.h"
#include "geometrycentral/utilities/vector2.h"
#include "geometrycentral/utilities/vector3.h"

#include <vector>

namespace cscd {

// The cut locus of one source on a cloud, with what the loop's stages read of it.
struct CloudCutLocus {
  CutLocus graph;                                // nodes are point indices, edges neighbourhood-graph edges
  std::vector<geometrycentral::Vector3> gradient; // of the distance at every point, in space (0 outside the component)
  size_t passingPoints = 0; // points that pass both tests
  size_t passingPieces = 0; // connected pieces they form in the neighbourhood graph, before the tree bridges them
};

// CSCD-PC's cut locus (paper App. "Our adaptation on point clouds"): the practical cut locus of
// Mancinelli et al. on the cloud's neighbourhood graph (pointcloud/neighbourhood.h). Per point, the
// gradient of the distance by least squares over its ring (a gradient operator prefactored once), the
// largest angle between the ring's gradients, and the tufted Laplacian of the distance; then the ridge
// tree, its restriction and pruning shared with meshes (cscd/ridge_tree.h). No homology step: the
// tree's cycles are not added (docs/pointcloud.md).
class CloudCutLocusSolver {
public:
  // tufted: the cloud's tufted triangulation (vertex i is point i), whose Laplacian the heat method uses;
  // meanSpacing: its mean edge length, which makes the Laplacian scale-free.
  CloudCutLocusSolver(const CloudNeighbourhood& neighbourhood, geometrycentral::surface::EdgeLengthGeometry& tufted,
                      double meanSpacing);

  // distance: per point, +infinity outside the source's component.
  CloudCutLocus compute(const std::vector<double>& distance, size_t source, const CutLocusOptions& options) const;

  // Angle between the gradients at points a and b, both seen in point `at`'s tangent plane (NaN where one is 0).
  double angleBetween(const std::vector<geometrycentral::Vector3>& gradient, size_t at, size_t a, size_t b) const;

private:
  const CloudNeighbourhood& neighbourhood;
  double meanSpacing;
  // Per entry of the graph's rows: d(gradient at the point) / d(distance at that neighbour - distance at
  // the point), in the point's tangent basis (the least-squares fit of a linear function to its ring).
  std::vector<geometrycentral::Vector2> gradientWeight;
  // The tufted cotan Laplacian in rows (off-diagonal weights) and the lumped mass of each point.
  std::vector<size_t> laplacianStart;
  std::vector<size_t> laplacianColumn;
  std::vector<double> laplacianWeight;
  std::vector<double> mass;

  std::vector<geometrycentral::Vector3> gradients(const std::vector<double>& distance) const;
  std::vector<double> distanceLaplacian(const std::vector<double>& distance) const;
};

} // namespace cscd
