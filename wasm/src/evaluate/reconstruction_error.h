#pragma once

#include "evaluate/convolution_surface.h"
#include "mesh/mesh_arrays.h"

#include <string>
#include <utility>
#include <vector>

namespace cscd {

// The paper's reconstruction error (Sec. 5, App. "Evaluation metric") of a skeleton against the mesh
// it was made from, in the paper's unit: squared distances on the mesh scaled to unit bounding-box
// diagonal, times 1000.
struct Evaluation {
  // Over the vertices used by faces: the squared distance to the nearest point of the reconstructed
  // surface (on its triangles, not only its vertices), mean, median and 95th percentile.
  double reconError = 0, median = 0, p95 = 0;
  std::vector<double> vertexError; // per input vertex (0 for vertices used by no face)
  std::vector<double> radii;       // the radii the reconstruction used
  bool radiiDerived = false;
  size_t nodes = 0;
  size_t cycles = 0; // independent cycles, E - V + components, without self-loops and repeated edges
  TriangleMesh surface;
  SampleGrid grid;
  std::vector<std::pair<std::string, double>> timings; // milliseconds per step
};

// Radii for a skeleton that has none: every mesh vertex is attributed to its closest point on the
// skeleton's segments and lends its distance to the segment's two nodes, weighted linearly by where
// that point lies (all to a node when it is the point); a node's radius is the weighted mean. It is
// the radius of the tube that best fits the surface around the node, the same notion as the mean
// distance to a region the CSCD skeleton reports. Nodes that no vertex chose get the distance to the
// surface.
std::vector<double> deriveRadii(const MeshArrays& mesh, const SkeletonCurves& skeleton);

// Throws InputError for a mesh that is not one (see checkMesh) or a skeleton with no nodes, edges
// naming missing nodes, non-finite coordinates, or radii of the wrong count or sign. Empty radii are
// derived (deriveRadii).
Evaluation evaluateSkeleton(const MeshArrays& mesh, SkeletonCurves skeleton);

} // namespace cscd
