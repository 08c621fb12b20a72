#include "pointcloud/mls.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>

using namespace geometrycentral;

namespace cscd {
namespace {

// The quadratic has 6 coefficients: it is fitted only when the weights spread over more points (the
// effective count (sum w)^2 / sum w^2 is about 14 for 30 evenly spread neighbours, and lower where they
// clump) and its normal equations, in coordinates scaled by h, are well conditioned (the points not all
// near a line). It is used where the cloud is clean: where it explains most of what the plane leaves
// (its weighted RMS residual at most half the plane's, so the heights are curvature, not noise; on a
// noisy cloud it would follow the noise and make the surface rough), and where its correction stays
// within a bandwidth of the plane (beyond, it extrapolates).
constexpr double kQuadraticMinEffectiveNeighbours = 8;
constexpr double kQuadraticMinRcond = 1e-3;
constexpr double kQuadraticMaxResidualRatio = 0.5;
// The Gaussian's value at the farthest neighbour, two bandwidths away.
const double kFarthestWeight = std::exp(-4.);
// Fits around the query, then around the previous round's answer: a fixed number, not "until it
// settles", so that nearby queries get nearby answers (the loop's descent compares energies of nearby
// projections; on a noisy cloud the rounds need not settle, and how many ran would make answers jump).
constexpr int kRounds = 3;
// A neighbour cache holds this many times k candidates: about 1.4 times the k-th neighbour's distance on a
// surface, so a query can move about 0.4 of that (over a spacing at k = 30) before it is refilled.
constexpr size_t kCandidateFactor = 2;

Eigen::Matrix<double, 6, 1> monomials(double u, double v) {
  Eigen::Matrix<double, 6, 1> m;
  m << 1, u, v, u * u, u * v, v * v;
  return m;
}

// A fit's weighted neighbours lie along a line when their second axis of spread is under this share of
// the first (scanLines).
constexpr double kLineSpread = 0.1;
// scanLines looks for a line-like point's next line among this many times k nearest.
constexpr size_t kLineSearchFactor = 8;

// The points the noise test and scanLines look at: every 16th, which gives their shares to within a
// few percent at a fraction of the opening's time (each is a fit).
constexpr size_t kSampleStep = 16;
// The noise test's threshold (NoiseTest).
constexpr double kMinQuadraticShare = 0.2;

// projectOnPatches blends the fits of this many nearest cloud points (16 gave rougher skeletons, not
// smoother ones: docs/pointcloud.md, "Loops on patches").
constexpr size_t kBlendedPatches = 8;

Eigen::Vector3d toEigen(Vector3 v) { return {v.x, v.y, v.z}; }
Vector3 fromEigen(const Eigen::Vector3d& v) { return Vector3{v.x(), v.y(), v.z()}; }

} // namespace

MlsSurface::MlsSurface(std::vector<Vector3> points_, size_t neighbours_, std::vector<uint32_t> nearestOthers_)
    : points(std::move(points_)), neighbours(neighbours_), nearestOthers(std::move(nearestOthers_)),
      finder(std::make_unique<NearestNeighborFinder>(points)) {}

void MlsSurface::kNearest(Vector3 at, size_t k, MlsNeighbourCache* cache, std::vector<size_t>& near) const {
  if (!cache) {
    near = finder->kNearest(at, k);
    return;
  }
  // The candidates sorted by their distances from `at`, from the order of the last query's: nearby queries
  // order them nearly alike, so an insertion sort moves few (a selection and a sort of the k were over a
  // tenth of a noisy cloud's run). The order of (distance, index) pairs is total: the k first are those a
  // sort gives.
  std::vector<std::pair<double, size_t>>& byDistance = cache->byDistance;
  auto sortByDistance = [&]() {
    for (auto& [distance2, i] : byDistance) distance2 = norm2(points[i] - at);
    for (size_t j = 1; j < byDistance.size(); j++)
      for (size_t m = j; m > 0 && byDistance[m] < byDistance[m - 1]; m--) std::swap(byDistance[m], byDistance[m - 1]);
  };
  bool held = false;
  if (cache->reach >= 0) {
    sortByDistance();
    held = std::sqrt(byDistance[k - 1].first) + norm(at - cache->centre) < cache->reach;
    if (!held) held = refillAroundNearest(at, k, *cache);
  }
  if (!held) {
    const size_t count = std::min(kCandidateFactor * k, points.size());
    const std::vector<size_t> candidates = finder->kNearest(at, count); // nearest first
    cache->centre = at;
    // Every point left out is at least as far as the farthest candidate; all of them are in when count is every point.
    cache->reach = count == points.size() ? INFINITY : norm(points[candidates.back()] - at);
    byDistance.clear();
    for (size_t i : candidates) byDistance.push_back({0, i});
    sortByDistance();
  }
  near.resize(k);
  for (size_t j = 0; j < k; j++) near[j] = byDistance[j].second;
}

// The candidates refilled from the nearest one's own neighbours (the point and its `neighbours` nearest
// others, known since the cloud was opened) instead of from the kd-tree: any point left out lies at least
// that list's reach from the point, so at least that less the query's offset from the query, and at least
// as far as the first candidate left out. Exact, as the kd-tree's refill: false, and the cache as it was,
// when the k nearest are not certainly among them (a query farther than the list reaches).
bool MlsSurface::refillAroundNearest(Vector3 at, size_t k, MlsNeighbourCache& cache) const {
  const size_t count = kCandidateFactor * k;
  if (count >= neighbours + 1) return false;
  const size_t nearest = cache.byDistance.front().second;
  const uint32_t* others = nearestOthers.data() + nearest * neighbours;
  std::vector<std::pair<double, size_t>>& listed = cache.refill;
  listed.clear();
  listed.push_back({norm2(points[nearest] - at), nearest});
  for (size_t j = 0; j < neighbours; j++) listed.push_back({norm2(points[others[j]] - at), others[j]});
  std::nth_element(listed.begin(), listed.begin() + count, listed.end());
  const double reach = std::min(std::sqrt(listed[count].first),
                                norm(points[others[neighbours - 1]] - points[nearest]) - norm(at - points[nearest]));
  std::sort(listed.begin(), listed.begin() + count);
  if (!(std::sqrt(listed[k - 1].first) < reach)) return false;
  cache.centre = at;
  cache.reach = reach;
  cache.byDistance.assign(listed.begin(), listed.begin() + count);
  return true;
}

MlsSurface::Spread MlsSurface::spread(Vector3 at, const std::vector<size_t>& near) const {
  Spread result;
  double farthest2 = 0;
  for (size_t i : near) farthest2 = std::max(farthest2, norm2(points[i] - at));
  result.h = std::sqrt(farthest2) / 2;
  const double h = result.h;
  if (!(h > 0)) return result; // all k points coincide

  // Weighted plane: centroid, then the covariance's eigenvectors (the least one the normal).
  const size_t k = near.size();
  result.weights.resize(k);
  Vector3 centroid{0, 0, 0};
  for (size_t j = 0; j < k; j++) {
    // The Gaussian less its value at the farthest neighbour: a point entering or leaving the k nearest
    // does so with weight 0, so the surface moves continuously with the query (a step of the loop's
    // descent would otherwise jump by a share of the noise as neighbours change, and stall it).
    const double w = std::exp(-norm2(points[near[j]] - at) / (h * h)) - kFarthestWeight;
    result.weights[j] = w;
    result.weightSum += w;
    result.weightSquares += w * w;
    centroid += w * points[near[j]];
  }
  centroid /= result.weightSum;
  result.centroid = centroid;
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
  for (size_t j = 0; j < k; j++) {
    const Eigen::Vector3d d = toEigen(points[near[j]] - centroid);
    covariance += result.weights[j] * d * d.transpose();
  }
  result.axes.computeDirect(covariance);
  return result;
}

MlsSurface::Fit MlsSurface::fit(Vector3 at, const std::vector<size_t>& near, bool tryQuadratic) const {
  Fit result;
  const Spread around = spread(at, near);
  result.h = around.h;
  const double h = result.h;
  if (!(h > 0)) return result;
  const size_t k = near.size();
  const std::vector<double>& weights = around.weights;
  const double weightSum = around.weightSum, weightSquares = around.weightSquares;
  const Vector3 centroid = around.centroid;
  result.centroid = centroid;
  result.normal = fromEigen(around.axes.eigenvectors().col(0)).normalize();
  result.e1 = fromEigen(around.axes.eigenvectors().col(2)).normalize();
  result.e2 = cross(result.normal, result.e1);
  if (!tryQuadratic || weightSum * weightSum / weightSquares < kQuadraticMinEffectiveNeighbours) return result;

  // Height over the plane: a weighted quadratic in coordinates scaled by h (so its system is of order 1).
  std::vector<double> heights(k);
  std::vector<Eigen::Matrix<double, 6, 1>> local(k); // the quadratic's monomials at each neighbour
  Eigen::Matrix<double, 6, 6> system = Eigen::Matrix<double, 6, 6>::Zero();
  Eigen::Matrix<double, 6, 1> rhs = Eigen::Matrix<double, 6, 1>::Zero();
  for (size_t j = 0; j < k; j++) {
    const Vector3 d = points[near[j]] - centroid;
    local[j] = monomials(dot(d, result.e1) / h, dot(d, result.e2) / h);
    heights[j] = dot(d, result.normal);
    system.selfadjointView<Eigen::Lower>().rankUpdate(local[j], weights[j]); // LDLT reads the lower half
    rhs += weights[j] * heights[j] * local[j];
  }
  const Eigen::LDLT<Eigen::Matrix<double, 6, 6>> solver(system);
  if (solver.info() != Eigen::Success || !(solver.rcond() > kQuadraticMinRcond)) return result;
  const Eigen::Matrix<double, 6, 1> a = solver.solve(rhs);
  double planeResidual = 0, quadraticResidual = 0; // weighted sums of squares
  for (size_t j = 0; j < k; j++) {
    const double f = heights[j], r = f - a.dot(local[j]);
    planeResidual += weights[j] * f * f;
    quadraticResidual += weights[j] * r * r;
  }
  const double ratio = kQuadraticMaxResidualRatio;
  if (quadraticResidual > ratio * ratio * planeResidual) return result;
  result.quadratic = true;
  result.a = a;
  return result;
}

MlsPoint MlsSurface::Fit::at(Vector3 query) const {
  const Vector3 fromCentroid = query - centroid;
  Vector3 position = centroid + fromCentroid - dot(fromCentroid, normal) * normal;
  if (!quadratic) return MlsPoint{position, normal, false};
  const double uq = dot(fromCentroid, e1) / h, vq = dot(fromCentroid, e2) / h;
  const double height = a.dot(monomials(uq, vq));
  // Beyond a bandwidth from the plane, the quadratic extrapolates.
  if (!(std::abs(height) <= h)) return MlsPoint{position, normal, false};
  position += height * normal;
  const double slopeU = (a[1] + 2 * a[3] * uq + a[4] * vq) / h, slopeV = (a[2] + a[4] * uq + 2 * a[5] * vq) / h;
  return MlsPoint{position, (normal - slopeU * e1 - slopeV * e2).normalize(), true};
}

MlsPoint MlsSurface::project(Vector3 query, MlsNeighbourCache* cache, bool tryQuadratic) const {
  MlsPoint result{query, Vector3{0, 0, 1}, false};
  Vector3 at = query;
  const size_t k = std::min(neighbours, points.size());
  std::vector<size_t> near;
  for (int round = 0; round < kRounds; round++) {
    kNearest(at, k, cache, near);
    const Fit around = fit(at, near, tryQuadratic);
    if (!(around.h > 0)) return MlsPoint{points[near.front()], result.normal, false};
    result = around.at(query);
    at = result.position;
  }
  return result;
}

MlsPoint MlsSurface::projectOnPatches(Vector3 query, MlsNeighbourCache* cache) const {
  if (patchOf.empty()) patchOf.assign(points.size(), kNoPatch);
  const size_t k = std::min(neighbours, points.size()), blended = std::min(kBlendedPatches, points.size() - 1);
  std::vector<size_t> near;
  kNearest(query, blended + 1, cache, near);
  // The weights are the fits' Gaussian, 0 at the first point left out: the blend moves continuously with the query.
  const double outside2 = norm2(points[near.back()] - query);
  Vector3 position{0, 0, 0}, normal{0, 0, 0};
  double weightSum = 0;
  size_t used = 0, quadratics = 0;
  for (size_t j = 0; j < blended; j++) {
    const size_t i = near[j];
    if (patchOf[i] == kNoPatch) {
      patchOf[i] = uint32_t(patches.size());
      patches.push_back(fit(points[i], ownNeighbours(i, k), true));
    }
    const Fit& patch = patches[patchOf[i]];
    const double w = std::exp(-4 * norm2(points[i] - query) / outside2) - kFarthestWeight;
    if (!(patch.h > 0) || !(w > 0)) continue;
    const MlsPoint on = patch.at(query);
    position += w * on.position;
    // A fit's normal has no sign: each is turned to agree with the blend so far.
    normal += w * (dot(on.normal, normal) < 0 ? -on.normal : on.normal);
    weightSum += w;
    used++;
    quadratics += on.quadratic;
  }
  if (!(weightSum > 0)) return project(query, cache); // the nearest points all as far as the one left out
  return MlsPoint{position / weightSum, normal.normalize(), 2 * quadratics > used};
}

std::vector<size_t> MlsSurface::ownNeighbours(size_t i, size_t k) const {
  std::vector<size_t> own{i};
  own.insert(own.end(), nearestOthers.begin() + i * neighbours, nearestOthers.begin() + i * neighbours + (k - 1));
  return own;
}

ScanLines MlsSurface::scanLines() const {
  const size_t k = std::min(neighbours, points.size());
  // The next line is looked for among this many nearest, which reach 4k points either way along a line:
  // lines farther apart than 4k of their points' spacings stay unmeasured.
  const size_t reach = std::min(kLineSearchFactor * k, points.size());
  size_t sampled = 0, lineLike = 0;
  std::vector<double> apart, keptShare;
  for (size_t i = 0; i < points.size(); i += kSampleStep, sampled++) {
    const Spread around = spread(points[i], ownNeighbours(i, k)); // as its patch is fitted (projectOnPatches)
    if (!(around.h > 0)) continue;
    const Eigen::Vector3d extent = around.axes.eigenvalues(); // increasing
    if (!(extent[1] < kLineSpread * kLineSpread * extent[2])) continue;
    lineLike++;
    const Vector3 along = fromEigen(around.axes.eigenvectors().col(2));
    double nearest = INFINITY, across = INFINITY;
    for (size_t j : finder->kNearest(points[i], reach)) {
      const Vector3 offset = points[j] - points[i];
      const double distance = norm(offset);
      if (!(distance > 0)) continue;
      nearest = std::min(nearest, distance);
      if (std::abs(dot(offset, along)) < distance * std::sqrt(0.5)) across = std::min(across, distance);
    }
    if (std::isfinite(across)) apart.push_back(across), keptShare.push_back(nearest / across);
  }
  ScanLines lines;
  lines.lineLikeShare = double(lineLike) / double(sampled);
  auto median = [](std::vector<double>& values) {
    std::nth_element(values.begin(), values.begin() + long(values.size() / 2), values.end());
    return values[values.size() / 2];
  };
  if (!apart.empty()) lines.lineSpacing = median(apart), lines.keptAtLineSpacing = median(keptShare);
  return lines;
}

NoiseTest MlsSurface::testNoise() const {
  NoiseTest test;
  for (size_t p = 0; p < points.size(); p += kSampleStep, test.sampled++) test.quadratics += project(points[p]).quadratic;
  test.noisy = double(test.quadratics) < kMinQuadraticShare * double(test.sampled);
  return test;
}

size_t MlsSurface::nearestPoint(Vector3 query) const { return finder->kNearest(query, 1).front(); }

} // namespace cscd
