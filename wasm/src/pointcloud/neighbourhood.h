#pragma once

#include "cscd/ridge_tree.h"
#include "pointcloud/mls.h"

#include "geometrycentral/pointcloud/point_cloud.h"
#include "geometrycentral/pointcloud/point_position_geometry.h"
#include "geometrycentral/utilities/vector2.h"
#include "geometrycentral/utilities/vector3.h"

#include <array>
#include <vector>

namespace cscd {

// Each point's local triangulation (geometry-central's buildLocalTriangulations): triangles (point, a, b).
using LocalTriangulations = geometrycentral::pointcloud::PointData<std::vector<std::array<size_t, 3>>>;

// The graph CSCD-PC's cut locus and loops run on (paper App. "Our adaptation on point clouds": a
// neighbourhood pruned of the edges that join separate parts of the shape). Its edges are those of the
// points' local triangulations (each point's k nearest neighbours projected to its tangent plane and
// Delaunay-triangulated, the triangulations the tufted one is built from) that join a point to a
// neighbour of its own ring, less the edges that leave the tangent planes: an edge across a thin gap
// between two sheets of the surface runs along their normals, an edge of the surface along it. On a
// noisy cloud (the MLS surface finds no curvature under the noise at most points) an edge of the
// surface leaves the planes through its ends' noise too: there an edge that leaves them, by less than
// 70 degrees, is tested again between its ends' projections on the MLS surface (`mls`), with the MLS
// normals, where the noise is averaged out, and kept if it runs along the surface there. A clean cloud's graph is the test alone.
class CloudNeighbourhood {
public:
  // triangles: the points' local triangulations, those the tufted triangulation was built from; noise:
  // the MLS surface's noise test.
  CloudNeighbourhood(geometrycentral::pointcloud::PointPositionGeometry& geometry, const MlsSurface& mls, const NoiseTest& noise,
                     const LocalTriangulations& triangles);

  // Each point's neighbours in their order around it in its tangent plane (so a ring, as on a mesh).
  const NeighbourGraph& graph() const { return neighbourGraph; }
  // Connected component of every point in the graph (may split a component of the tufted triangulation
  // where only bridging edges held it together).
  const std::vector<int>& pointComponent() const { return component; }
  size_t componentCount() const { return components; }
  // Edges of the local triangulations left out as bridges.
  size_t bridgesRemoved() const { return bridges; }
  // Whether the cloud was found noisy, and the edges kept then because they run along the MLS surface
  // though they leave their ends' tangent planes.
  bool noisyCloud() const { return noise.noisy; }
  size_t keptOnMls() const { return alongMls; }
  // Whether the MLS surface's quadratic was fitted at any point of the noise test's sample (on the shared
  // noisy clouds it was at none; on the trees' scans, at 9%).
  bool curvatureSampled() const { return noise.quadratics > 0; }

  const std::vector<geometrycentral::Vector3>& positions() const { return pointPositions; }
  const geometrycentral::Vector3& position(size_t p) const { return pointPositions[p]; }
  const geometrycentral::Vector3& normal(size_t p) const { return normals[p]; }
  // A 3D vector in point p's tangent plane, in the coordinates of its tangent basis.
  geometrycentral::Vector2 inTangentPlane(size_t p, const geometrycentral::Vector3& v) const;
  // Coordinates of point p's tangent basis back to a vector in space.
  geometrycentral::Vector3 inSpace(size_t p, const geometrycentral::Vector2& v) const;

private:
  NeighbourGraph neighbourGraph;
  std::vector<int> component;
  size_t components = 0;
  size_t bridges = 0;
  NoiseTest noise;
  size_t alongMls = 0;
  std::vector<geometrycentral::Vector3> pointPositions;
  std::vector<geometrycentral::Vector3> normals;
  std::vector<std::array<geometrycentral::Vector3, 2>> tangentBasis;
};

} // namespace cscd
