#pragma once

#include "pointcloud/cut_locus.h"
#include "pointcloud/geodesics.h"
#include "pointcloud/mls.h"
#include "pointcloud/neighbourhood.h"

#include "geometrycentral/pointcloud/point_cloud.h"
#include "geometrycentral/pointcloud/point_position_geometry.h"
#include "geometrycentral/surface/edge_length_geometry.h"
#include "geometrycentral/surface/surface_mesh.h"

#include <array>
#include <cstdint>
#include <memory>
#include <vector>

namespace cscd {

class ExteriorGrid;
class PointWinding;

// A point cloud as it crosses the WASM boundary: xyz per point, and nx ny nz per point or nothing.
struct CloudArrays {
  std::vector<double> positions;
  std::vector<double> normals;

  size_t pointCount() const { return positions.size() / 3; }
};

// Facts about a cloud once opened (mirrors CloudFacts in lib/core/types.ts).
struct CloudFacts {
  size_t points = 0;
  size_t neighbours = 0; // k of the k-nearest-neighbour search
  // The neighbours each point's local triangulation is made from, on average: k where every neighbourhood
  // lies flat (and on a noisy cloud), fewer where parts are thinner than it (pointcloud/flat_neighbours.h).
  double meanFlatNeighbours = 0;
  size_t components = 0; // of the tufted triangulation: heat flows within each one only
  // The share of the points (every 16th) whose own MLS fit has its weighted neighbours along a line (their
  // spread across it under a tenth of along it; MlsSurface::scanLines): a surface has its neighbours
  // around each point, a cloud scanned in lines farther apart than its points along them has them in the
  // line, and the fits there cannot find the surface.
  double lineLikeShare = 0;
  // Over those points: the lines' spacing (the median distance to the nearest point across the line) and
  // about how many points the cloud keeps when thinned along its lines to that spacing; 0 when none is
  // line-like or no next line lies within 8k nearest.
  double lineSpacing = 0;
  size_t pointsAtLineSpacing = 0;
  std::array<double, 3> bboxMin{};
  std::array<double, 3> bboxMax{};
  double bboxDiagonal = 0;
  // Mean edge length of the tufted triangulation (its edges join neighbouring points): the cloud's
  // counterpart of a mesh's mean edge length, and the length scale of the heat method's time step.
  double meanSpacing = 0;
  bool normalsFromFile = false;
};

// Everything CSCD-PC keeps per input cloud, the counterpart of Surface: the points, their k nearest
// neighbours, the tufted intrinsic triangulation built from them (Sharp & Crane 2020) and the
// prefactored geodesic solver on it. Built once, then queried for many sources.
class Cloud {
public:
  // Throws InputError when the arrays are not a usable cloud (bad lengths, non-finite values, k + 1 points or fewer).
  Cloud(const CloudArrays& arrays, int neighbours);

  const CloudFacts& facts() const { return cloudFacts; }
  size_t pointCount() const { return cloudFacts.points; }
  // Connected component of every point in the tufted triangulation.
  const std::vector<int>& pointComponent() const { return component; }

  geometrycentral::pointcloud::PointCloud& cloud() { return *pointCloud; }
  geometrycentral::pointcloud::PointPositionGeometry& geometry() { return *cloudGeometry; }
  // The tufted intrinsic triangulation (vertex i is point i), Delaunay, built once from the points'
  // local triangulations.
  geometrycentral::surface::EdgeLengthGeometry& tufted() { return *tuftedGeometry; }
  CloudGeodesics& geodesics() { return *geodesicSolver; }
  const MlsSurface& mls() const { return *mlsSurface; }
  // The surface area each point stands for, pi R^2 / k with R the distance to its k-th neighbour: the
  // disc of its k neighbours holds k points' worth of area (unbiased for uniform random sampling).
  const std::vector<double>& pointAreas() const { return areas; }
  // The graph the cut locus and the loops run on, and the cut locus's per-cloud operators: built on
  // first use (opening a cloud for its distances alone does not pay for them).
  const CloudNeighbourhood& neighbourhood();
  const CloudCutLocusSolver& cutLocusSolver();
  // Inside or outside the cloud (pointcloud/winding.h), built on first use.
  const PointWinding& winding();
  // Whether p is inside the shape: the winding number over one half on a clean cloud; on a noisy one
  // (CloudNeighbourhood::noisyCloud) not joined to the outside by empty space (pointcloud/exterior.h),
  // since PCA normals cannot be oriented on parts as thin as the noise. Built on first use.
  bool inside(const geometrycentral::Vector3& p);
  // Whether a closed loop on the cloud goes round its inside (the centroid test of paper Sec. 4.2.2): its
  // centroid inside, or, on a noisy cloud, the loop a cross-section of a tube the scan left open at an
  // end, through which the exterior flood reached its axis (ExteriorGrid::enclosesCrossSection).
  bool loopInside(const std::vector<geometrycentral::Vector3>& loop);
  // The tufted triangulation's edges as each point's neighbours, each once (the cover repeats them): the
  // surface graph a loop's sides are flooded over (pointcloud/shorten.cpp), built on first use.
  const std::vector<std::vector<uint32_t>>& tuftedNeighbours();

  ~Cloud();

private:
  // The noisy cloud's inside test (pointcloud/exterior.h), built on first use.
  const ExteriorGrid& exteriorGrid();

  CloudFacts cloudFacts;
  std::vector<int> component;
  std::vector<double> areas;
  std::unique_ptr<geometrycentral::pointcloud::PointCloud> pointCloud;
  std::unique_ptr<geometrycentral::pointcloud::PointPositionGeometry> cloudGeometry;
  // Every point's local triangulation, made once for the tufted cover and kept until the neighbourhood
  // graph is built from it too (geometry-central's tufted triangulation would make its own).
  LocalTriangulations localTriangulations;
  std::unique_ptr<geometrycentral::surface::SurfaceMesh> tuftedMesh;
  std::unique_ptr<geometrycentral::surface::EdgeLengthGeometry> tuftedGeometry;
  std::unique_ptr<CloudGeodesics> geodesicSolver;
  std::unique_ptr<MlsSurface> mlsSurface;
  NoiseTest noise;
  std::unique_ptr<CloudNeighbourhood> neighbourGraph;
  std::unique_ptr<CloudCutLocusSolver> cutLocus;
  std::unique_ptr<PointWinding> windingNumber;
  std::unique_ptr<ExteriorGrid> exterior;
  std::vector<std::vector<uint32_t>> tuftedAdjacency; // empty until first used
};

} // namespace cscd
