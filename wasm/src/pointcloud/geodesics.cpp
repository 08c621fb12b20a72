#include "pointcloud/geodesics.h"

using namespace geometrycentral;
using namespace geometrycentral::surface;

namespace cscd {

// Every triangle stands in up to three local triangulations and the tufted cover doubles them, so the
// mass matrix is about 6 times the area; the Laplacian, summed over the same triangles, grows about as
// much. So t = h² keeps its meaning (the heat system is scaled nearly as a whole), and the Poisson
// step, whose two sides grow alike, is unchanged: the accuracy is a mesh's (docs/pointcloud.md).
CloudGeodesics::CloudGeodesics(EdgeLengthGeometry& tufted, std::vector<int> pointComponent)
    : tuftedMesh(tufted.mesh), heat(tufted, std::move(pointComponent)) {}

std::vector<double> CloudGeodesics::fromPoint(size_t point) { return fromPoints({point}); }

std::vector<double> CloudGeodesics::fromPoints(const std::vector<size_t>& points) {
  std::vector<SurfacePoint> sources;
  for (size_t p : points) sources.push_back(SurfacePoint(tuftedMesh.vertex(p)));
  return heat.fromPoints(sources);
}

} // namespace cscd
