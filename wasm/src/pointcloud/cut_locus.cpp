#include "pointcloud/cut_locus.h"

#include "cscd/errors.h"
#include "cscd/union_find.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

using namespace geometrycentral;
using namespace geometrycentral::surface;

namespace cscd {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// The direction of v, or nothing when v is 0.
bool unitDirection(const Vector2& v, std::array<double, 2>& direction) {
  const double length = norm(v);
  if (!(length > 0)) return false;
  direction = {v.x / length, v.y / length};
  return true;
}

} // namespace

CloudCutLocusSolver::CloudCutLocusSolver(const CloudNeighbourhood& neighbourhood, EdgeLengthGeometry& tufted,
                                         double meanSpacing)
    : neighbourhood(neighbourhood), meanSpacing(meanSpacing) {
  const NeighbourGraph& graph = neighbourhood.graph();
  const size_t n = graph.vertexCount();

  // The gradient that fits the distance's differences to the ring best (least squares in the tangent
  // plane, as geometry-central's point-cloud gradient does over all k neighbours): only the ring, so
  // that the gradients on the two sides of a ridge stay apart (docs/pointcloud.md).
  gradientWeight.assign(graph.neighbour.size(), Vector2{0, 0});
  for (size_t p = 0; p < n; p++) {
    double xx = 0, xy = 0, yy = 0;
    std::vector<Vector2> offsets;
    for (size_t k = graph.rowStart[p]; k < graph.rowStart[p + 1]; k++) {
      const Vector2 c = neighbourhood.inTangentPlane(p, neighbourhood.position(graph.neighbour[k]) - neighbourhood.position(p));
      offsets.push_back(c);
      xx += c.x * c.x, xy += c.x * c.y, yy += c.y * c.y;
    }
    const double det = xx * yy - xy * xy;
    if (!(det > 1e-12 * (xx + yy) * (xx + yy))) continue; // the ring lies on a line: no gradient
    for (size_t k = graph.rowStart[p], i = 0; k < graph.rowStart[p + 1]; k++, i++)
      gradientWeight[k] = Vector2{(yy * offsets[i].x - xy * offsets[i].y) / det, (xx * offsets[i].y - xy * offsets[i].x) / det};
  }

  tufted.requireCotanLaplacian();
  tufted.requireVertexLumpedMassMatrix();
  const Eigen::SparseMatrix<double>& L = tufted.cotanLaplacian; // symmetric: a column is a row
  laplacianStart.assign(n + 1, 0);
  mass.resize(n);
  for (size_t p = 0; p < n; p++) {
    for (Eigen::SparseMatrix<double>::InnerIterator it(L, Eigen::Index(p)); it; ++it)
      if (size_t(it.row()) != p) {
        laplacianColumn.push_back(size_t(it.row()));
        laplacianWeight.push_back(-it.value());
      }
    laplacianStart[p + 1] = laplacianColumn.size();
    mass[p] = tufted.vertexLumpedMassMatrix.coeff(Eigen::Index(p), Eigen::Index(p));
  }
  tufted.unrequireCotanLaplacian();
  tufted.unrequireVertexLumpedMassMatrix();
}

std::vector<Vector3> CloudCutLocusSolver::gradients(const std::vector<double>& distance) const {
  const NeighbourGraph& graph = neighbourhood.graph();
  std::vector<Vector3> gradient(graph.vertexCount(), Vector3::zero());
  for (size_t p = 0; p < gradient.size(); p++) {
    if (!std::isfinite(distance[p])) continue;
    Vector2 g{0, 0};
    for (size_t k = graph.rowStart[p]; k < graph.rowStart[p + 1]; k++)
      g += gradientWeight[k] * (distance[graph.neighbour[k]] - distance[p]);
    gradient[p] = neighbourhood.inSpace(p, g);
  }
  return gradient;
}

// h * (cotan Laplacian of the distance) / (lumped mass): negative on ridges, as on a mesh. The tufted
// mass is about 6 times the area and the Laplacian about as much, so the ratio is a mesh's.
std::vector<double> CloudCutLocusSolver::distanceLaplacian(const std::vector<double>& distance) const {
  std::vector<double> laplacian(mass.size(), kNaN);
  for (size_t p = 0; p < mass.size(); p++) {
    if (!std::isfinite(distance[p]) || !(mass[p] > 0)) continue;
    double sum = 0;
    for (size_t k = laplacianStart[p]; k < laplacianStart[p + 1]; k++)
      sum += laplacianWeight[k] * (distance[laplacianColumn[k]] - distance[p]);
    laplacian[p] = meanSpacing * sum / mass[p];
  }
  return laplacian;
}

double CloudCutLocusSolver::angleBetween(const std::vector<Vector3>& gradient, size_t at, size_t a, size_t b) const {
  std::array<double, 2> da, db;
  if (!unitDirection(neighbourhood.inTangentPlane(at, gradient[a]), da) ||
      !unitDirection(neighbourhood.inTangentPlane(at, gradient[b]), db))
    return kNaN;
  return std::acos(std::clamp(da[0] * db[0] + da[1] * db[1], -1.0, 1.0));
}

CloudCutLocus CloudCutLocusSolver::compute(const std::vector<double>& distance, size_t source,
                                           const CutLocusOptions& options) const {
  const NeighbourGraph& graph = neighbourhood.graph();
  const size_t n = graph.vertexCount();
  if (distance.size() != n) throw InputError("cut locus: one distance per point is needed");
  if (source >= n) throw InputError("cut locus: source point " + std::to_string(source) + " does not exist");

  // The tufted triangulation may join parts the graph does not (through bridges): the cut locus stays
  // in the source's part of the graph, where the descents can reach it.
  const int component = neighbourhood.pointComponent()[source];
  std::vector<double> dist(distance);
  for (size_t p = 0; p < n; p++)
    if (neighbourhood.pointComponent()[p] != component || std::isnan(dist[p])) dist[p] = INFINITY;

  CloudCutLocus result;
  CutLocus& cutLocus = result.graph;
  cutLocus.laplacian = distanceLaplacian(distance);
  result.gradient = gradients(dist);
  cutLocus.angleDeviation.assign(n, kNaN);
  std::vector<std::array<double, 2>> ring;
  for (size_t p = 0; p < n; p++) {
    if (!std::isfinite(dist[p])) {
      cutLocus.laplacian[p] = kNaN;
      continue;
    }
    // For a skeleton, only where the Laplacian test lets the point pass (as on meshes, mesh/cut_locus.cpp).
    if (!options.everyAngle && !(cutLocus.laplacian[p] <= -options.laplacianThreshold)) continue;
    ring.clear();
    std::array<double, 2> direction;
    if (unitDirection(neighbourhood.inTangentPlane(p, result.gradient[p]), direction)) ring.push_back(direction);
    for (size_t k = graph.rowStart[p]; k < graph.rowStart[p + 1]; k++)
      if (unitDirection(neighbourhood.inTangentPlane(p, result.gradient[graph.neighbour[k]]), direction)) ring.push_back(direction);
    cutLocus.angleDeviation[p] = ringAngle(smallestCosine(ring), options);
  }

  cutLocus.root = source;
  for (size_t p = 0; p < n; p++)
    if (std::isfinite(dist[p]) && dist[p] > dist[cutLocus.root]) cutLocus.root = p;

  const std::vector<char> passing = passingVertices(cutLocus.angleDeviation, cutLocus.laplacian, std::vector<char>(n, 0), options);
  UnionFind pieces(n);
  for (const auto& e : graph.edgeVertices)
    if (passing[e[0]] && passing[e[1]]) pieces.unite(uint32_t(e[0]), uint32_t(e[1]));
  for (size_t p = 0; p < n; p++)
    if (passing[p]) {
      result.passingPoints++;
      if (pieces.find(uint32_t(p)) == p) result.passingPieces++;
    }

  const std::vector<size_t> parent = ridgeTree(graph, cutLocus.laplacian, passing, dist, cutLocus.root);
  std::vector<char> kept = restrictTree(graph, parent, passing, cutLocus.root, options.restriction);
  assembleCutLocus(graph, parent, std::move(kept), {}, options.pruneDepth, cutLocus);
  return result;
}

} // namespace cscd
