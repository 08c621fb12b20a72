#pragma once

#include "geodesics/heat_distance.h"

#include "geometrycentral/surface/intrinsic_triangulation.h"

#include <vector>

namespace cscd {

// Geodesic distance on a mesh: the heat method on its intrinsic Delaunay triangulation
// (geodesics/heat_distance.h), from vertices and points of the input mesh. The triangulation must not
// change afterwards (loop shortening works on copies).
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
  HeatDistance heat;
};

} // namespace cscd
