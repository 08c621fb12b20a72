#pragma once

#include "geometrycentral/surface/edge_length_geometry.h"
#include "geometrycentral/surface/heat_method_distance.h"

#include <memory>
#include <vector>

namespace cscd {

// Geodesic distance between the points of a cloud by the heat method (Crane, Weischedel, Wardetzky
// 2013) on its tufted intrinsic triangulation, with t = h², h the triangulation's mean edge length
// (the mean spacing of neighbouring points): the mesh rule (mesh/geodesics.h) and the default of
// geometry-central's PointCloudHeatSolver. Prefactored once per cloud; each query costs two
// back-substitutions.
//
// geometry-central's HeatMethodDistanceSolver does the work, on the tufted geometry itself: the same
// numbers as PointCloudHeatSolver's, to the last bit (tests/unit/cloud-geodesics.test.ts), whose robust
// option copies the tufted triangulation and mollifies and flips it again to no effect. Not using that
// class keeps one triangulation in memory, factors when the cloud is opened (as a mesh's Surface does),
// solves each component on its own, and leaves the scalar solver alone when a vector heat solver is
// added later (PointCloudHeatSolver rebuilds and refactors it then).
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
  std::vector<int> pointComponent;
  std::unique_ptr<geometrycentral::surface::HeatMethodDistanceSolver> solver;
};

} // namespace cscd
