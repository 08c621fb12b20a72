#include "mesh/regions.h"

#include <cmath>

using namespace geometrycentral;
using namespace geometrycentral::surface;

namespace cscd {

Regions assignRegions(Surface& surface, const Samples& samples, const std::vector<std::vector<SurfacePoint>>& loops) {
  ManifoldSurfaceMesh& mesh = surface.mesh();
  VertexPositionGeometry& geometry = surface.geometry();
  const size_t nV = surface.vertexCount();
  std::vector<uint32_t> seeds(nV, kNoRegion);
  std::vector<double> distance(nV, INFINITY);
  std::vector<SurfacePoint> all;
  for (const auto& loop : loops) all.insert(all.end(), loop.begin(), loop.end());
  if (!all.empty()) distance = surface.geodesics().fromPoints(all);

  // Seeds: the corners of the faces each loop runs through, labelled by the loop closest in space.
  std::vector<double> seedDistance(nV, INFINITY);
  for (uint32_t k = 0; k < loops.size(); k++)
    for (const SurfacePoint& p : loops[k]) {
      Vector3 at = p.interpolate(geometry.vertexPositions);
      for (Vertex v : p.inSomeFace().face.adjacentVertices()) {
        double d = norm(geometry.vertexPositions[v] - at);
        if (d < seedDistance[v.getIndex()]) {
          seedDistance[v.getIndex()] = d;
          seeds[v.getIndex()] = k;
        }
      }
    }

  std::vector<std::vector<uint32_t>> neighbours(nV);
  for (Vertex v : mesh.vertices())
    for (Vertex w : v.adjacentVertices()) neighbours[v.getIndex()].push_back(uint32_t(w.getIndex()));
  std::vector<std::array<uint32_t, 3>> triangles;
  for (Face f : mesh.faces()) {
    std::array<uint32_t, 3> t;
    size_t k = 0;
    for (Vertex v : f.adjacentVertices()) t[k++] = uint32_t(v.getIndex());
    triangles.push_back(t);
  }
  const ElementGraph graph{samples.positions, samples.weights, neighbours, samples.edges, surface.vertexComponent(), triangles};
  return growRegions(graph, std::move(distance), std::move(seeds), loops.size());
}

} // namespace cscd
