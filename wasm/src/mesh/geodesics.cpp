#include "mesh/geodesics.h"

#include "geometrycentral/surface/exact_geodesics.h"

#include <cmath>
#include <map>

using namespace geometrycentral::surface;

namespace cscd {

Geodesics::Geodesics(IntrinsicTriangulation& intrinsic_, std::vector<int> vertexComponent_)
    : intrinsic(intrinsic_), vertexComponent(std::move(vertexComponent_)), solver(intrinsic_) {}

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
  // The heat method fixes one additive constant for the whole solve, which is only right within one
  // connected component: solve once per component that holds a source.
  std::map<int, std::vector<SurfacePoint>> sourcesByComponent;
  for (const SurfacePoint& p : pointsOnInput) {
    SurfacePoint onIntrinsic = intrinsic.equivalentPointOnIntrinsic(p);
    Vertex anyVertex = onIntrinsic.inSomeFace().face.halfedge().vertex();
    sourcesByComponent[vertexComponent[anyVertex.getIndex()]].push_back(onIntrinsic);
  }

  std::vector<double> distance(vertexComponent.size(), INFINITY);
  for (const auto& [component, sources] : sourcesByComponent) {
    VertexData<double> solved = solver.computeDistance(sources);
    for (size_t v = 0; v < distance.size(); v++)
      if (vertexComponent[v] == component) distance[v] = std::max(0.0, solved[v]);
  }
  return distance;
}

} // namespace cscd
