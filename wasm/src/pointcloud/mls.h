#pragma once

#include "geometrycentral/utilities/knn.h"
#include "geometrycentral/utilities/vector3.h"

#include <Eigen/Core>
#include <Eigen/Eigenvalues>

#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

namespace cscd {

// A point of the moving-least-squares surface, with the surface's unit normal there. The normal's sign
// is arbitrary (a cloud's normals carry none that can be trusted); only its direction means anything.
struct MlsPoint {
  geometrycentral::Vector3 position;
  geometrycentral::Vector3 normal;
  bool quadratic = false; // the height fit was a quadratic (else the plane alone)
};

// The moving-least-squares surface of a cloud (Levin 2003; the paper cites Fleishman et al. 2005),
// queried by projecting points onto it. Around the current estimate, the k nearest points are weighted
// by a Gaussian whose bandwidth h is half the distance to the farthest of them (about 1.5 local
// spacings at k = 30, so it follows the density), lowered to 0 at that farthest one; a weighted plane
// through their weighted centroid (its normal the weighted covariance's least eigenvector) gives a
// frame, and a weighted quadratic height over that plane refines it where the cloud is clean and the
// fit well posed. The query is projected on that surface, and the weights re-centred at the result for
// two more rounds, so that the answer hardly depends on how far off the surface the query was.
// Candidates for the k nearest points of queries near one place (a point of a loop being shortened, which
// moves a little per step): the cloud's points nearest to `centre`, every point within `reach` of it among
// them. A query q whose k-th nearest candidate lies within reach - |q - centre| has its k nearest points
// among them, so they are found without the kd-tree, and exactly as it would find them.
struct MlsNeighbourCache {
  geometrycentral::Vector3 centre{0, 0, 0};
  double reach = -1; // none yet
  // The candidates with their squared distances from the last query, nearest first.
  std::vector<std::pair<double, size_t>> byDistance;
  std::vector<std::pair<double, size_t>> refill; // scratch of MlsSurface::refillAroundNearest
};

// What MlsSurface::scanLines finds: the share of line-like fits and, over those, how far apart the lines
// lie and how thinly to sample along them to match (0 where no fit sees a line, or no line has a
// neighbour line within the search).
struct ScanLines {
  double lineLikeShare = 0;
  // The median distance from a line-like point to the nearest point across its line (more across than along).
  double lineSpacing = 0;
  // The median of each such point's distance to its nearest point over that across distance: thinned along
  // the lines to their spacing, the cloud keeps about this share of its points.
  double keptAtLineSpacing = 0;
};

// Whether a cloud is noisy, from its MLS surface: it is when the quadratic height is fitted at fewer than
// a fifth of a sample of its points (every 16th): the clean clouds measured fit it at 34-100% of their
// points, the noisy ones (0.5-1% of the diagonal) at none (docs/pointcloud.md, "Noisy clouds").
struct NoiseTest {
  size_t sampled = 0;
  size_t quadratics = 0; // sampled points where the quadratic was fitted
  bool noisy = false;
};

class MlsSurface {
public:
  // nearestOthers: each point's k = `neighbours` nearest other points, nearest first, k entries a point
  // (the cloud's neighbour lists, from the same search the surface's own kd-tree makes).
  MlsSurface(std::vector<geometrycentral::Vector3> points, size_t neighbours, std::vector<uint32_t> nearestOthers);

  // With a cache, the k nearest points come from it while it holds them, and it is refilled when not.
  // Without tryQuadratic, the plane alone: what a noisy cloud's fits come to anyway, found cheaper.
  MlsPoint project(geometrycentral::Vector3 query, MlsNeighbourCache* cache = nullptr, bool tryQuadratic = true) const;

  // A cheaper surface through the same fits, for the loop's descent: each cloud point's fit (one round of
  // `project`'s, centred at the point) is made once and kept, and a query is projected on the fits of its
  // nearest points, their results blended with weights that fall to 0 at the first point left out. About
  // 7 times cheaper than `project` on a loop; on a clean cloud the two surfaces lie within a small share
  // of a spacing of each other (docs/pointcloud.md, "Loops on patches").
  MlsPoint projectOnPatches(geometrycentral::Vector3 query, MlsNeighbourCache* cache) const;

  NoiseTest testNoise() const;

  // The points (of a sample) whose own fit (the point and its k - 1 nearest, weighted as every fit weighs
  // them) has its neighbours along a line, not spread over a patch: such a fit cannot tell the surface's
  // normal from a direction in it (a cloud scanned in lines farther apart than its points along them).
  ScanLines scanLines() const;

  // The index of the cloud point nearest to `query`.
  size_t nearestPoint(geometrycentral::Vector3 query) const;

private:
  // The Gaussian weights of the k nearest around `at` (bandwidth h, half the farthest one's distance),
  // their weighted centroid and the principal axes of their weighted covariance.
  struct Spread {
    double h = 0;
    std::vector<double> weights;
    double weightSum = 0, weightSquares = 0;
    geometrycentral::Vector3 centroid{0, 0, 0};
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> axes;
  };
  Spread spread(geometrycentral::Vector3 at, const std::vector<size_t>& near) const;

  // One round's fit around `at`: a frame at the weighted centroid and the height over its plane.
  struct Fit {
    geometrycentral::Vector3 centroid, normal, e1, e2;
    double h = 0;
    Eigen::Matrix<double, 6, 1> a = Eigen::Matrix<double, 6, 1>::Zero(); // the height's quadratic in (u, v) / h
    bool quadratic = false;
    MlsPoint at(geometrycentral::Vector3 query) const;
  };
  Fit fit(geometrycentral::Vector3 at, const std::vector<size_t>& near, bool tryQuadratic) const;

  // The k nearest points of `at` into `near`, the nearest first.
  void kNearest(geometrycentral::Vector3 at, size_t k, MlsNeighbourCache* cache, std::vector<size_t>& near) const;
  bool refillAroundNearest(geometrycentral::Vector3 at, size_t k, MlsNeighbourCache& cache) const;
  // Point i and its k - 1 nearest others: its k nearest, as the kd-tree would list them (its own fit's).
  std::vector<size_t> ownNeighbours(size_t i, size_t k) const;

  std::vector<geometrycentral::Vector3> points;
  size_t neighbours;
  std::vector<uint32_t> nearestOthers;
  // Its queries are not const, though they change nothing we can see.
  std::unique_ptr<geometrycentral::NearestNeighborFinder> finder;
  // The fits of the points whose patches were used, made on first use (loops visit a small part of a large
  // cloud): point i's is patches[patchOf[i]], unless that is kNoPatch.
  static constexpr uint32_t kNoPatch = UINT32_MAX;
  mutable std::vector<uint32_t> patchOf;
  mutable std::vector<Fit> patches;
};

} // namespace cscd
