#pragma once

#include "geometrycentral/surface/heat_method_distance.h"
#include "geometrycentral/surface/intrinsic_triangulation.h"

#include <vector>

namespace cscd {

// Geodesic distance by the heat method on an intrinsic Delaunay triangulation: the two linear systems
// are factored once per mesh, each query costs two back-substitutions.
class Geodesics {
public:
  // vertexComponent: connected component of every vertex, so that each component is solved on its own.
  Geodesics(geometrycentral::surface::IntrinsicTriangulation& intrinsic, std::vector<int> vertexComponent);

  // Distance from one vertex to every vertex; +infinity in other components.
  std::vector<double> fromVertex(size_t vertex);

  // Exact polyhedral distance (MMP) on the input mesh: slower, the reference the heat method approximates.
  std::vector<double> exactFromVertex(size_t vertex);

  // Distance from the nearest of several points of the *input* mesh; +infinity in components without one.
  std::vector<double> fromPoints(const std::vector<geometrycentral::surface::SurfacePoint>& pointsOnInput);

private:
  geometrycentral::surface::IntrinsicTriangulation& intrinsic;
  std::vector<int> vertexComponent;
  geometrycentral::surface::HeatMethodDistanceSolver solver;
};

} // namespace cscd
