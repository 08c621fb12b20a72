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

// Throws InputError for a mesh that is not one (see checkMesh) or a skeleton with no nodes, edges
// naming missing nodes, non-finite coordinates, or radii of the wrong count or sign. Empty radii are
// derived from the mesh (tubeRadii).
Evaluation evaluateSkeleton(const MeshArrays& mesh, SkeletonCurves skeleton);

// The same against a point cloud's points (CSCD-PC's skeletons scored by the cloud, radii derived
// around the points); throws InputError for no points or non-finite ones.
Evaluation evaluateSkeleton(const std::vector<Vector3>& points, SkeletonCurves skeleton);

} // namespace cscd
