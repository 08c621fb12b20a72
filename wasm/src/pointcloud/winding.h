#pragma once

#include "pointcloud/cloud.h"

#include <array>
#include <vector>

namespace cscd {

// Inside or outside a point cloud: the generalised winding number of oriented points (Barill et al.
// 2018, "Fast winding numbers for soups and clouds"), w(q) = sum_i a_i n_i . (x_i - q) / (4 pi |x_i - q|^3),
// about 1 inside a closed cloud and 0 outside; the counterpart of a mesh's WindingNumber, used by the
// centroid test (a loop around the outside of a bend has its centroid outside) and by node placement.
//
// It needs normals of one orientation, which neither PCA nor every scan gives: they are oriented by
// propagation along a minimum spanning tree of the neighbour graph weighted by 1 - |n_i . n_j| (Hoppe et
// al. 1992), each tree's sign chosen so that its winding number is positive just inside its points, or
// where that does not decide (an open sheet) so that its normals enclose a positive volume (sum a_i n_i .
// x_i = 3 V, divergence theorem); then patches of a tree are turned where the whole cloud's winding
// number is clearly nearer 1 inside and 0 outside that way (a propagation that turned at a junction).
// Areas: the cloud's point areas.
class PointWinding {
public:
  explicit PointWinding(Cloud& cloud);

  double operator()(const geometrycentral::Vector3& q) const;

  // The oriented normals (outward where the cloud is closed).
  const std::vector<geometrycentral::Vector3>& normals() const { return normal; }

private:
  // The share of the pairs of neighbours whose normals point against each other.
  double opposedShare(const geometrycentral::pointcloud::PointData<std::vector<geometrycentral::pointcloud::Point>>& neighbours) const;
  // Orients the normals by propagation along spanning trees of the neighbour graph; each point's tree.
  std::vector<size_t> orientAlongTrees(
      const geometrycentral::pointcloud::PointData<std::vector<geometrycentral::pointcloud::Point>>& neighbours, double spacing);
  bool outward(const std::vector<size_t>& tree, double spacing) const;
  void turnPatches(const std::vector<size_t>& treeOf, double spacing);
  // The points just inside and just outside point p (with its normal outward), where the sums are read.
  std::array<geometrycentral::Vector3, 2> across(size_t p, double spacing) const;
  // Point i's share of the winding number at q, before the division by 4 pi.
  double term(size_t i, const geometrycentral::Vector3& q) const;

  std::vector<geometrycentral::Vector3> position;
  std::vector<geometrycentral::Vector3> normal;
  const std::vector<double>& area; // the cloud's point areas
};

} // namespace cscd
