#include "pointcloud/geodesics.h"

#include <algorithm>
#include <cmath>
#include <map>

using namespace geometrycentral;
using namespace geometrycentral::surface;

namespace cscd {

CloudGeodesics::CloudGeodesics(EdgeLengthGeometry& tufted, std::vector<int> pointComponent_)
    : tuftedMesh(tufted.mesh), pointComponent(std::move(pointComponent_)) {
  // Every triangle stands in up to three local triangulations and the tufted cover doubles them, so the
  // mass matrix is about 6 times the area; the Laplacian, summed over the same triangles, grows about as
  // much. So t = h² keeps its meaning (the heat system is scaled nearly as a whole), and the Poisson
  // step, whose two sides grow alike, is unchanged: the accuracy is a mesh's (docs/pointcloud.md).
  solver = std::make_unique<HeatMethodDistanceSolver>(tufted, 1.0, false);
}

std::vector<double> CloudGeodesics::fromPoint(size_t point) { return fromPoints({point}); }

std::vector<double> CloudGeodesics::fromPoints(const std::vector<size_t>& points) {
  // The heat method fixes one additive constant per solve, right within one component only.
  std::map<int, std::vector<Vertex>> sourcesByComponent;
  for (size_t p : points) sourcesByComponent[pointComponent[p]].push_back(tuftedMesh.vertex(p));

  std::vector<double> distance(pointComponent.size(), INFINITY);
  for (const auto& [component, sources] : sourcesByComponent) {
    VertexData<double> solved = solver->computeDistance(sources);
    for (size_t p = 0; p < distance.size(); p++)
      if (pointComponent[p] == component) distance[p] = std::max(0.0, solved[p]);
  }
  return distance;
}

} // namespace cscd
