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

Eigen::Vector3d toEigen(Vector3 v) { return {v.x, v.y, v.z}; }
Vector3 fromEigen(const Eigen::Vector3d& v) { return Vector3{v.x(), v.y(), v.z()}; }

} // namespace

MlsSurface::MlsSurface(std::vector<Vector3> points_, size_t neighbours_)
    : points(std::move(points_)), neighbours(neighbours_), finder(std::make_unique<NearestNeighborFinder>(points)) {}

void MlsSurface::kNearest(Vector3 at, size_t k, MlsNeighbourCache* cache, std::vector<size_t>& near) const {
  if (!cache) {
    near = finder->kNearest(at, k);
    return;
  }
  if (cache->reach >= 0) {
    std::vector<std::pair<double, size_t>>& byDistance = cache->byDistance;
    byDistance.clear();
    for (size_t i : cache->candidates) byDistance.push_back({norm2(points[i] - at), i});
    // The k nearest in order: selected, then sorted (a heap's partial sort of all candidates cost twice as much).
    std::nth_element(byDistance.begin(), byDistance.begin() + (k - 1), byDistance.end());
    if (std::sqrt(byDistance[k - 1].first) + norm(at - cache->centre) < cache->reach) {
      std::sort(byDistance.begin(), byDistance.begin() + k);
      near.resize(k);
      for (size_t j = 0; j < k; j++) near[j] = byDistance[j].second;
      return;
    }
  }
  const size_t count = std::min(kCandidateFactor * k, points.size());
  cache->centre = at;
  cache->candidates = finder->kNearest(at, count);
  // Every point left out is at least as far as the farthest candidate; all of them are in when count is every point.
  cache->reach = count == points.size() ? INFINITY : norm(points[cache->candidates.back()] - at);
  near.assign(cache->candidates.begin(), cache->candidates.begin() + k);
}

MlsPoint MlsSurface::project(Vector3 query, MlsNeighbourCache* cache) const {
  MlsPoint result{query, Vector3{0, 0, 1}, false};
  Vector3 at = query;
  const size_t k = std::min(neighbours, points.size());
  std::vector<double> weights(k), heights(k); // heights over the plane
  std::vector<Eigen::Matrix<double, 6, 1>> local(k); // the quadratic's monomials at each neighbour
  std::vector<size_t> near;
  for (int round = 0; round < kRounds; round++) {
    kNearest(at, k, cache, near);
    double farthest2 = 0;
    for (size_t i : near) farthest2 = std::max(farthest2, norm2(points[i] - at));
    const double h = std::sqrt(farthest2) / 2;
    if (!(h > 0)) return MlsPoint{points[near.front()], result.normal, false}; // all k points coincide

    // Weighted plane: centroid, then the covariance's least eigenvector as the normal.
    double weightSum = 0, weightSquares = 0;
    Vector3 centroid{0, 0, 0};
    for (size_t j = 0; j < near.size(); j++) {
      // The Gaussian less its value at the farthest neighbour: a point entering or leaving the k nearest
      // does so with weight 0, so the surface moves continuously with the query (a step of the loop's
      // descent would otherwise jump by a share of the noise as neighbours change, and stall it).
      weights[j] = std::exp(-norm2(points[near[j]] - at) / (h * h)) - kFarthestWeight;
      weightSum += weights[j];
      weightSquares += weights[j] * weights[j];
      centroid += weights[j] * points[near[j]];
    }
    centroid /= weightSum;
    Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
    for (size_t j = 0; j < near.size(); j++) {
      const Eigen::Vector3d d = toEigen(points[near[j]] - centroid);
      covariance += weights[j] * d * d.transpose();
    }
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen;
    eigen.computeDirect(covariance);
    const Vector3 normal = fromEigen(eigen.eigenvectors().col(0)).normalize();
    const Vector3 e1 = fromEigen(eigen.eigenvectors().col(2)).normalize(), e2 = cross(normal, e1);

    // Height over the plane: a weighted quadratic in coordinates scaled by h (so its system is of order 1).
    auto monomials = [](double u, double v) {
      Eigen::Matrix<double, 6, 1> m;
      m << 1, u, v, u * u, u * v, v * v;
      return m;
    };
    const Vector3 fromCentroid = query - centroid;
    const double uq = dot(fromCentroid, e1) / h, vq = dot(fromCentroid, e2) / h;
    Vector3 position = centroid + fromCentroid - dot(fromCentroid, normal) * normal, surfaceNormal = normal;
    bool quadratic = false;
    if (weightSum * weightSum / weightSquares >= kQuadraticMinEffectiveNeighbours) {
      Eigen::Matrix<double, 6, 6> system = Eigen::Matrix<double, 6, 6>::Zero();
      Eigen::Matrix<double, 6, 1> rhs = Eigen::Matrix<double, 6, 1>::Zero();
      for (size_t j = 0; j < near.size(); j++) {
        const Vector3 d = points[near[j]] - centroid;
        local[j] = monomials(dot(d, e1) / h, dot(d, e2) / h);
        heights[j] = dot(d, normal);
        system.selfadjointView<Eigen::Lower>().rankUpdate(local[j], weights[j]); // LDLT reads the lower half
        rhs += weights[j] * heights[j] * local[j];
      }
      const Eigen::LDLT<Eigen::Matrix<double, 6, 6>> solver(system);
      if (solver.info() == Eigen::Success && solver.rcond() > kQuadraticMinRcond) {
        const Eigen::Matrix<double, 6, 1> a = solver.solve(rhs);
        double planeResidual = 0, quadraticResidual = 0; // weighted sums of squares
        for (size_t j = 0; j < near.size(); j++) {
          const double f = heights[j], r = f - a.dot(local[j]);
          planeResidual += weights[j] * f * f;
          quadraticResidual += weights[j] * r * r;
        }
        const double height = a.dot(monomials(uq, vq));
        const double ratio = kQuadraticMaxResidualRatio;
        if (quadraticResidual <= ratio * ratio * planeResidual && std::abs(height) <= h) {
          quadratic = true;
          position += height * normal;
          const double slopeU = (a[1] + 2 * a[3] * uq + a[4] * vq) / h, slopeV = (a[2] + a[4] * uq + 2 * a[5] * vq) / h;
          surfaceNormal = (normal - slopeU * e1 - slopeV * e2).normalize();
        }
      }
    }
    result = MlsPoint{position, surfaceNormal, quadratic};
    at = position;
  }
  return result;
}

size_t MlsSurface::nearestPoint(Vector3 query) const { return finder->kNearest(query, 1).front(); }

} // namespace cscd
