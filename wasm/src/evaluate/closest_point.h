#pragma once

#include "geometrycentral/utilities/vector3.h"

#include <array>
#include <cstdint>
#include <vector>

namespace cscd {

using geometrycentral::Vector3;

// Closest point of triangle abc to p (Ericson, Real-Time Collision Detection, 5.1.5).
Vector3 closestPointOnTriangle(const Vector3& p, const Vector3& a, const Vector3& b, const Vector3& c);

// Parameter t in [0, 1] of the point of segment ab closest to p.
double closestParameterOnSegment(const Vector3& p, const Vector3& a, const Vector3& b);

// Nearest-primitive queries over triangles or segments (simplices of K vertices, K = 3 or 2) in a
// bounding-box tree: median splits along the longest axis, depth-first search that visits the nearer
// child first and skips boxes farther than the best distance found.
template <size_t K>
class ClosestPointTree {
public:
  struct Hit {
    size_t primitive = 0;
    Vector3 point{0, 0, 0};
    double distance2 = 0;
  };

  ClosestPointTree(std::vector<Vector3> vertices, std::vector<std::array<uint32_t, K>> primitives);

  bool empty() const { return primitives.empty(); }
  // The primitive closest to p; must not be called on an empty tree.
  Hit closest(const Vector3& p) const;

private:
  struct Node {
    Vector3 lower, upper;
    uint32_t begin, end; // range in `order` (leaves)
    int32_t left = -1, right = -1;
  };

  int32_t build(uint32_t begin, uint32_t end);
  Vector3 closestOnPrimitive(size_t primitive, const Vector3& p) const;
  void search(int32_t node, const Vector3& p, Hit& best) const;

  std::vector<Vector3> vertices;
  std::vector<std::array<uint32_t, K>> primitives;
  std::vector<uint32_t> order;
  std::vector<Vector3> centroids;
  std::vector<Node> nodes;
};

using TriangleTree = ClosestPointTree<3>;
using SegmentTree = ClosestPointTree<2>;

} // namespace cscd
