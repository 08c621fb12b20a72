#include "pointcloud/flat_neighbours.h"

#include <Eigen/Dense>

#include <algorithm>

using namespace geometrycentral;
using namespace geometrycentral::pointcloud;

namespace cscd {
namespace {

// Twelve neighbours keep a point's ring (six on a flat surface) with room to spare; the share is the
// flatness of a disc of a surface whose curvature radius is a few times the disc's (a median 0.15-0.6% on
// the clean shared clouds at 30 neighbours, 1.4% on the spider's legs at 20). Measured on clouds
// from 24 meshes, seeds 1-3: docs/pointcloud.md, "A neighbour count per point".
constexpr size_t kMinFlatNeighbours = 12;
constexpr double kMaxFlatness = 0.01;

} // namespace

size_t trimToFlat(PointData<std::vector<Point>>& neighbours, const PointData<Vector3>& positions) {
  size_t removed = 0;
  for (size_t p = 0; p < neighbours.size(); p++) {
    std::vector<Point>& nearest = neighbours[p];
    // Sums of the offsets from p and of their outer products: the covariance of p and its first m
    // neighbours for every m in one pass.
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    Eigen::Matrix3d outer = Eigen::Matrix3d::Zero();
    size_t keep = std::min(kMinFlatNeighbours, nearest.size());
    for (size_t m = 1; m <= nearest.size(); m++) {
      const Vector3 d = positions[nearest[m - 1]] - positions[p];
      const Eigen::Vector3d v(d.x, d.y, d.z);
      sum += v;
      outer += v * v.transpose();
      if (m <= kMinFlatNeighbours) continue;
      const double count = double(m + 1);
      const Eigen::Vector3d mean = sum / count;
      const Eigen::Matrix3d covariance = outer / count - mean * mean.transpose();
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen;
      eigen.computeDirect(covariance, Eigen::EigenvaluesOnly);
      const Eigen::Vector3d values = eigen.eigenvalues(); // ascending
      if (values[0] <= kMaxFlatness * values.sum()) keep = m;
    }
    removed += nearest.size() - keep;
    nearest.resize(keep);
  }
  return removed;
}

} // namespace cscd
