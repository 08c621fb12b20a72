#include "pointcloud/cloud.h"

#include "cscd/errors.h"
#include "cscd/measures.h"
#include "cscd/union_find.h"
#include "pointcloud/exterior.h"
#include "pointcloud/flat_neighbours.h"
#include "pointcloud/winding.h"

#include "geometrycentral/pointcloud/local_triangulation.h"
#include "geometrycentral/pointcloud/point_position_normal_geometry.h"
#include "geometrycentral/surface/intrinsic_mollification.h"
#include "geometrycentral/surface/simple_idt.h"
#include "geometrycentral/surface/surface_mesh_factories.h"
#include "geometrycentral/surface/tufted_laplacian.h"
#include "geometrycentral/surface/vertex_position_geometry.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <tuple>

using namespace geometrycentral;
using namespace geometrycentral::pointcloud;

namespace cscd {
namespace {

void validateArrays(const CloudArrays& arrays, int neighbours) {
  if (arrays.positions.size() % 3 != 0) throw InputError("positions must hold three coordinates per point");
  if (!arrays.normals.empty() && arrays.normals.size() != arrays.positions.size())
    throw InputError("normals must hold three coordinates per point, for every point or for none");
  const size_t n = arrays.pointCount();
  for (size_t p = 0; p < n; p++) {
    const double* x = &arrays.positions[3 * p];
    if (!(std::isfinite(x[0]) && std::isfinite(x[1]) && std::isfinite(x[2])))
      throw InputError("point " + std::to_string(p) + " has a non-finite coordinate");
    if (arrays.normals.empty()) continue;
    const double* normal = &arrays.normals[3 * p];
    const double length = std::hypot(normal[0], normal[1], normal[2]);
    if (!(length > 0 && std::isfinite(length))) throw InputError("point " + std::to_string(p) + " has a non-finite or zero normal");
  }
  // The k-nearest-neighbour search finds k points besides each point itself.
  if (n <= size_t(neighbours)) {
    std::ostringstream msg;
    msg << "the cloud has " << n << (n == 1 ? " point" : " points") << ", too few for the neighbour count k = " << neighbours
        << ": every point needs k others";
    throw InputError(msg.str());
  }
}

// The tufted intrinsic triangulation of the local triangulations (Sharp & Crane 2020), made as
// geometry-central's PointPositionGeometry::computeTuftedTriangulation makes it: one mesh of every local
// triangle, its edge lengths mollified, the tufted cover, intrinsic Delaunay flips.
std::tuple<std::unique_ptr<surface::SurfaceMesh>, std::unique_ptr<surface::EdgeLengthGeometry>>
tuftedCover(const LocalTriangulations& local, const PointData<Vector3>& positions) {
  const size_t n = positions.size();
  std::vector<std::vector<size_t>> triangles;
  std::vector<Vector3> points(n);
  for (size_t p = 0; p < n; p++) {
    points[p] = positions[p];
    for (const std::array<size_t, 3>& t : local[p]) triangles.push_back({t[0], t[1], t[2]});
  }
  std::unique_ptr<surface::SurfaceMesh> mesh;
  std::unique_ptr<surface::VertexPositionGeometry> embedded;
  std::tie(mesh, embedded) = surface::makeSurfaceMeshAndGeometry(triangles, points);
  embedded->requireEdgeLengths();
  surface::EdgeData<double> lengths = embedded->edgeLengths;
  surface::mollifyIntrinsic(*mesh, lengths, 1e-5);
  surface::buildIntrinsicTuftedCover(*mesh, lengths);
  surface::flipToDelaunay(*mesh, lengths);
  auto geometry = std::make_unique<surface::EdgeLengthGeometry>(*mesh, lengths);
  return {std::move(mesh), std::move(geometry)};
}

} // namespace

Cloud::Cloud(const CloudArrays& arrays, int neighbours) {
  validateArrays(arrays, neighbours);
  const size_t n = arrays.pointCount();
  pointCloud = std::make_unique<PointCloud>(n);
  PointData<Vector3> positions(*pointCloud);
  for (size_t p = 0; p < n; p++) positions[p] = Vector3{arrays.positions[3 * p], arrays.positions[3 * p + 1], arrays.positions[3 * p + 2]};

  // Normals only give each point the tangent plane its neighbours are triangulated in; their sign is not
  // trusted (PCA normals have none, and files flip some), and the tufted cover needs none: flipping half
  // of them moves distances by 0.03% of the diagonal on average (tests/unit/cloud-geodesics.test.ts).
  // A file's normals are used when it has them, else geometry-central's PCA normals of the k neighbours.
  if (arrays.normals.empty()) {
    cloudGeometry = std::make_unique<PointPositionGeometry>(*pointCloud, positions);
  } else {
    PointData<Vector3> normals(*pointCloud);
    for (size_t p = 0; p < n; p++) normals[p] = Vector3{arrays.normals[3 * p], arrays.normals[3 * p + 1], arrays.normals[3 * p + 2]}.normalize();
    cloudGeometry = std::make_unique<PointPositionNormalGeometry>(*pointCloud, positions, normals);
  }
  cloudGeometry->kNeighborSize = unsigned(neighbours);
  cloudGeometry->requireNeighbors();

  // The MLS surface and the points' areas from the k nearest, and the noise test on that surface.
  std::vector<Vector3> points(n);
  std::vector<uint32_t> nearestOthers;
  nearestOthers.reserve(n * size_t(neighbours));
  areas.assign(n, 0);
  for (size_t p = 0; p < n; p++) {
    points[p] = positions[p];
    double farthest2 = 0;
    for (Point q : cloudGeometry->neighbors->neighbors[p]) {
      farthest2 = std::max(farthest2, norm2(positions[q] - positions[p]));
      nearestOthers.push_back(uint32_t(q.getIndex()));
    }
    areas[p] = M_PI * farthest2 / neighbours;
  }
  mlsSurface = std::make_unique<MlsSurface>(std::move(points), size_t(neighbours), std::move(nearestOthers));
  noise = mlsSurface->testNoise();
  const ScanLines lines = mlsSurface->scanLines();
  // On a clean cloud each point's neighbours are trimmed to those that lie flat before its local
  // triangulation (and PCA normal) is made from them; a noisy cloud's are never flat, and all k average
  // its noise out.
  const size_t trimmed = noise.noisy ? 0 : trimToFlat(cloudGeometry->neighbors->neighbors, positions);
  localTriangulations = handleToInds(*pointCloud, buildLocalTriangulations(*pointCloud, *cloudGeometry, true));
  std::tie(tuftedMesh, tuftedGeometry) = tuftedCover(localTriangulations, positions);
  surface::EdgeLengthGeometry& tufted = *tuftedGeometry;
  tufted.requireEdgeLengths();

  UnionFind joined(n);
  double spacing = 0;
  for (surface::Edge e : tuftedMesh->edges()) {
    joined.unite(uint32_t(e.firstVertex().getIndex()), uint32_t(e.secondVertex().getIndex()));
    spacing += tufted.edgeLengths[e];
  }
  // Components numbered in the order of their first point.
  component.assign(n, -1);
  std::vector<int> componentOfRoot(n, -1);
  int componentCount = 0;
  for (size_t p = 0; p < n; p++) {
    int& id = componentOfRoot[joined.find(uint32_t(p))];
    if (id < 0) id = componentCount++;
    component[p] = id;
  }

  CloudFacts& facts = cloudFacts;
  facts.points = n;
  facts.neighbours = size_t(neighbours);
  facts.meanFlatNeighbours = double(n * size_t(neighbours) - trimmed) / double(n);
  facts.components = size_t(componentCount);
  facts.lineLikeShare = lines.lineLikeShare;
  facts.lineSpacing = lines.lineSpacing;
  facts.pointsAtLineSpacing = std::min(n, size_t(std::ceil(lines.keptAtLineSpacing * double(n))));
  Vector3 low = positions[0], high = positions[0];
  for (size_t p = 1; p < n; p++) low = componentwiseMin(low, positions[p]), high = componentwiseMax(high, positions[p]);
  facts.bboxMin = {low.x, low.y, low.z};
  facts.bboxMax = {high.x, high.y, high.z};
  facts.bboxDiagonal = norm(high - low);
  facts.meanSpacing = spacing / tuftedMesh->nEdges();
  facts.normalsFromFile = !arrays.normals.empty();

  geodesicSolver = std::make_unique<CloudGeodesics>(tufted, component);
}

const CloudNeighbourhood& Cloud::neighbourhood() {
  if (!neighbourGraph) {
    neighbourGraph = std::make_unique<CloudNeighbourhood>(*cloudGeometry, *mlsSurface, noise, localTriangulations);
    localTriangulations = LocalTriangulations();
  }
  return *neighbourGraph;
}

const CloudCutLocusSolver& Cloud::cutLocusSolver() {
  if (!cutLocus) cutLocus = std::make_unique<CloudCutLocusSolver>(neighbourhood(), *tuftedGeometry, cloudFacts.meanSpacing);
  return *cutLocus;
}

const PointWinding& Cloud::winding() {
  if (!windingNumber) windingNumber = std::make_unique<PointWinding>(*this);
  return *windingNumber;
}

const ExteriorGrid& Cloud::exteriorGrid() {
  if (!exterior) exterior = std::make_unique<ExteriorGrid>(neighbourhood().positions(), cloudFacts.meanSpacing);
  return *exterior;
}

bool Cloud::inside(const geometrycentral::Vector3& p) {
  return neighbourhood().noisyCloud() ? exteriorGrid().inside(p) : winding()(p) > 0.5;
}

bool Cloud::loopInside(const std::vector<geometrycentral::Vector3>& loop) {
  if (inside(loopCentroid(loop, true))) return true;
  return neighbourhood().noisyCloud() && exteriorGrid().enclosesCrossSection(loop);
}

const std::vector<std::vector<uint32_t>>& Cloud::tuftedNeighbours() {
  if (!tuftedAdjacency.empty()) return tuftedAdjacency;
  tuftedAdjacency.resize(pointCount());
  for (geometrycentral::surface::Edge e : tuftedMesh->edges()) {
    const uint32_t a = uint32_t(e.firstVertex().getIndex()), b = uint32_t(e.secondVertex().getIndex());
    if (a == b) continue;
    tuftedAdjacency[a].push_back(b);
    tuftedAdjacency[b].push_back(a);
  }
  for (std::vector<uint32_t>& around : tuftedAdjacency) {
    std::sort(around.begin(), around.end());
    around.erase(std::unique(around.begin(), around.end()), around.end());
  }
  return tuftedAdjacency;
}

Cloud::~Cloud() = default;

} // namespace cscd
