#pragma once

#include "geodesics/heat_distance.h"

#include "geometrycentral/surface/edge_length_geometry.h"

#include <vector>

namespace cscd {

// Geodesic distance between the points of a cloud: the heat method (geodesics/heat_distance.h, the
// mesh's solver) on its tufted intrinsic triangulation, t = h² with h the triangulation's mean edge
// length (the mean spacing of neighbouring points), also the default of geometry-central's
// PointCloudHeatSolver. Prefactored once per cloud; each query costs two back-substitutions.
//
// The same numbers as PointCloudHeatSolver's up to rounding (2.4e-15 of the largest distance,
// tests/unit/cloud-geodesics.test.ts: copies of a tufted face are summed once), whose robust option
// copies the tufted triangulation and mollifies and flips it again to no effect.
// Not using that class keeps one triangulation in memory, factors when the cloud is opened (as a
// mesh's Surface does), solves each component on its own, and leaves the scalar solver alone when a
// vector heat solver is added later (PointCloudHeatSolver rebuilds and refactors it then).
class CloudGeodesics {
public:
  // tufted: the cloud's tufted triangulation, vertex i being point i; pointComponent: the connected
  // component of every point in it, so that each component is solved on its own.
  CloudGeodesics(geometrycentral::surface::EdgeLengthGeometry& tufted, std::vector<int> pointComponent);

  // Distance from one point to every point; +infinity in other components.
  std::vector<double> fromPoint(size_t point);

  // Distance from the nearest of several points to every point; +infinity in components without one.
  std::vector<double> fromPoints(const std::vector<size_t>& points);

private:
  geometrycentral::surface::SurfaceMesh& tuftedMesh;
  HeatDistance heat;
};

} // namespace cscd
