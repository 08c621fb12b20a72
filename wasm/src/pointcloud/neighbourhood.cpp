#include "pointcloud/neighbourhood.h"

#include "cscd/union_find.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

using namespace geometrycentral;
using namespace geometrycentral::pointcloud;

namespace cscd {
namespace {

// An edge is a bridge when it leaves the tangent plane of either end by more than this. Along a
// surface sampled at spacing h with curvature radius r an edge leaves it by about h / 2r (10 degrees
// where a finger is three spacings thick); across a gap between two sheets, by nearly 90 degrees.
constexpr double kMaxElevation = 45 * M_PI / 180;

// On a noisy cloud, an edge that leaves a tangent plane by more than this is a bridge whatever the MLS
// surface says: noise tilts edges of the surface less, edges across a gap run at nearly 90 degrees.
constexpr double kMaxNoisyElevation = 70 * M_PI / 180;

} // namespace

CloudNeighbourhood::CloudNeighbourhood(PointPositionGeometry& geometry, const MlsSurface& mls, const NoiseTest& noise_,
                                       const LocalTriangulations& triangles)
    : noise(noise_) {
  PointCloud& cloud = geometry.cloud;
  const size_t n = cloud.nPoints();
  geometry.requireNormals();
  geometry.requireTangentBasis();
  pointPositions.resize(n);
  normals.resize(n);
  tangentBasis.resize(n);
  for (size_t p = 0; p < n; p++) {
    pointPositions[p] = geometry.positions[p];
    normals[p] = geometry.normals[p];
    tangentBasis[p] = geometry.tangentBasis[p];
  }

  // Every point joined to the points next to it in its own local triangulation.
  std::map<std::pair<size_t, size_t>, size_t> edgeIndex;
  const double maxSine = std::sin(kMaxElevation), maxNoisySine = std::sin(kMaxNoisyElevation);
  // Whether the edge ab leaves the plane of normal normalA at a or that of normalB at b by more than asin(sine).
  auto leaves = [&](const Vector3& a, const Vector3& normalA, const Vector3& b, const Vector3& normalB, double sine) {
    const Vector3 direction = unit(b - a);
    return std::abs(dot(direction, normalA)) > sine || std::abs(dot(direction, normalB)) > sine;
  };
  // Points on the MLS surface, projected when first asked for: on a noisy cloud, the ends of the edges
  // that leave a tangent plane.
  std::vector<MlsPoint> projected(n);
  std::vector<char> isProjected(n, 0);
  auto onMls = [&](size_t p) -> const MlsPoint& {
    if (!isProjected[p]) projected[p] = mls.project(pointPositions[p]), isProjected[p] = 1;
    return projected[p];
  };
  auto leavesTangentPlane = [&](size_t a, size_t b) {
    if (!leaves(pointPositions[a], normals[a], pointPositions[b], normals[b], maxSine)) return false;
    if (!noise.noisy || leaves(pointPositions[a], normals[a], pointPositions[b], normals[b], maxNoisySine)) return true;
    // The same test where the noise is averaged out: the ends' projections and the MLS normals.
    const MlsPoint &pa = onMls(a), &pb = onMls(b);
    if (!(norm(pb.position - pa.position) > 0) || leaves(pa.position, pa.normal, pb.position, pb.normal, maxSine)) return true;
    alongMls++;
    return false;
  };
  for (size_t p = 0; p < n; p++)
    for (const auto& triangle : triangles[p])
      for (size_t q : {triangle[1], triangle[2]}) {
        const std::pair<size_t, size_t> key{std::min(p, q), std::max(p, q)};
        if (p == q || edgeIndex.count(key)) continue;
        if (leavesTangentPlane(p, q)) {
          edgeIndex.emplace(key, kNoParent);
          bridges++;
          continue;
        }
        edgeIndex.emplace(key, neighbourGraph.edgeVertices.size());
        neighbourGraph.edgeVertices.push_back({key.first, key.second});
      }

  // Rows sorted by the angle around the point in its tangent plane, so that a row is a ring.
  std::vector<std::vector<std::pair<double, size_t>>> rows(n);
  for (size_t e = 0; e < neighbourGraph.edgeVertices.size(); e++) {
    const auto [a, b] = neighbourGraph.edgeVertices[e];
    const Vector2 ab = inTangentPlane(a, pointPositions[b] - pointPositions[a]), ba = inTangentPlane(b, pointPositions[a] - pointPositions[b]);
    rows[a].push_back({std::atan2(ab.y, ab.x), e});
    rows[b].push_back({std::atan2(ba.y, ba.x), e});
  }
  neighbourGraph.rowStart.assign(n + 1, 0);
  for (size_t p = 0; p < n; p++) {
    std::sort(rows[p].begin(), rows[p].end());
    for (const auto& [angle, e] : rows[p]) {
      const auto& ends = neighbourGraph.edgeVertices[e];
      neighbourGraph.neighbour.push_back(ends[0] == p ? ends[1] : ends[0]);
      neighbourGraph.edge.push_back(e);
    }
    neighbourGraph.rowStart[p + 1] = neighbourGraph.neighbour.size();
  }

  UnionFind joined(n);
  for (const auto& e : neighbourGraph.edgeVertices) joined.unite(uint32_t(e[0]), uint32_t(e[1]));
  component.assign(n, -1);
  std::vector<int> componentOfRoot(n, -1);
  for (size_t p = 0; p < n; p++) {
    int& id = componentOfRoot[joined.find(uint32_t(p))];
    if (id < 0) id = int(components++);
    component[p] = id;
  }
}

Vector2 CloudNeighbourhood::inTangentPlane(size_t p, const Vector3& v) const {
  return Vector2{dot(v, tangentBasis[p][0]), dot(v, tangentBasis[p][1])};
}

Vector3 CloudNeighbourhood::inSpace(size_t p, const Vector2& v) const {
  return v.x * tangentBasis[p][0] + v.y * tangentBasis[p][1];
}

} // namespace cscd
