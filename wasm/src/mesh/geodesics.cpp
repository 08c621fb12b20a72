#include "mesh/geodesics.h"

#include "geometrycentral/surface/exact_geodesics.h"

#include <cmath>

using namespace geometrycentral;
using namespace geometrycentral::surface;

namespace cscd {

Geodesics::Geodesics(IntrinsicTriangulation& intrinsic_, std::vector<int> vertexComponent_)
    : intrinsic(intrinsic_), vertexComponent(vertexComponent_), heat(intrinsic_, std::move(vertexComponent_)) {}

std::vector<double> Geodesics::fromVertex(size_t vertex) {
  return fromPoints({SurfacePoint(intrinsic.inputMesh.vertex(vertex))});
}

std::vector<double> Geodesics::exactFromVertex(size_t vertex) {
  VertexData<double> exact = exactGeodesicDistance(intrinsic.inputMesh, intrinsic.inputGeom, intrinsic.inputMesh.vertex(vertex));
  std::vector<double> distance(vertexComponent.size(), INFINITY);
  for (size_t v = 0; v < distance.size(); v++)
    if (vertexComponent[v] == vertexComponent[vertex]) distance[v] = exact[v];
  return distance;
}

std::vector<double> Geodesics::fromPoints(const std::vector<SurfacePoint>& pointsOnInput) {
  std::vector<SurfacePoint> onIntrinsic;
  for (const SurfacePoint& p : pointsOnInput) onIntrinsic.push_back(intrinsic.equivalentPointOnIntrinsic(p));
  return heat.fromPoints(onIntrinsic);
}

} // namespace cscd
