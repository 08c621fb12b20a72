#include "evaluate/closest_point.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace cscd {

Vector3 closestPointOnTriangle(const Vector3& p, const Vector3& a, const Vector3& b, const Vector3& c) {
  Vector3 ab = b - a, ac = c - a, ap = p - a;
  double d1 = dot(ab, ap), d2 = dot(ac, ap);
  if (d1 <= 0 && d2 <= 0) return a;
  Vector3 bp = p - b;
  double d3 = dot(ab, bp), d4 = dot(ac, bp);
  if (d3 >= 0 && d4 <= d3) return b;
  double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return a + ab * (d1 / (d1 - d3));
  Vector3 cp = p - c;
  double d5 = dot(ab, cp), d6 = dot(ac, cp);
  if (d6 >= 0 && d5 <= d6) return c;
  double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return a + ac * (d2 / (d2 - d6));
  double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) return b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)));
  double sum = va + vb + vc;
  if (!(sum > 0)) return a; // degenerate triangle: every case above failed only through rounding
  return a + ab * (vb / sum) + ac * (vc / sum);
}

double closestParameterOnSegment(const Vector3& p, const Vector3& a, const Vector3& b) {
  Vector3 ab = b - a;
  double length2 = dot(ab, ab);
  if (!(length2 > 0)) return 0;
  return std::clamp(dot(p - a, ab) / length2, 0.0, 1.0);
}

namespace {

double boxDistance2(const Vector3& p, const Vector3& lower, const Vector3& upper) {
  double d2 = 0;
  for (int axis = 0; axis < 3; axis++) {
    double excess = std::max({lower[axis] - p[axis], 0.0, p[axis] - upper[axis]});
    d2 += excess * excess;
  }
  return d2;
}

constexpr uint32_t leafSize = 4;

} // namespace

template <size_t K>
ClosestPointTree<K>::ClosestPointTree(std::vector<Vector3> vertices_, std::vector<std::array<uint32_t, K>> primitives_)
    : vertices(std::move(vertices_)), primitives(std::move(primitives_)) {
  if (primitives.empty()) return;
  order.resize(primitives.size());
  centroids.resize(primitives.size());
  for (size_t i = 0; i < primitives.size(); i++) {
    order[i] = uint32_t(i);
    Vector3 sum{0, 0, 0};
    for (uint32_t v : primitives[i]) sum += vertices[v];
    centroids[i] = sum / double(K);
  }
  nodes.reserve(2 * primitives.size() / leafSize + 2);
  build(0, uint32_t(primitives.size()));
}

template <size_t K>
int32_t ClosestPointTree<K>::build(uint32_t begin, uint32_t end) {
  Node node;
  double inf = std::numeric_limits<double>::infinity();
  node.lower = {inf, inf, inf};
  node.upper = {-inf, -inf, -inf};
  for (uint32_t i = begin; i < end; i++)
    for (uint32_t v : primitives[order[i]])
      for (int axis = 0; axis < 3; axis++) {
        node.lower[axis] = std::min(node.lower[axis], vertices[v][axis]);
        node.upper[axis] = std::max(node.upper[axis], vertices[v][axis]);
      }
  node.begin = begin;
  node.end = end;
  int32_t index = int32_t(nodes.size());
  nodes.push_back(node);
  if (end - begin <= leafSize) return index;

  Vector3 extent = node.upper - node.lower;
  int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : extent.y >= extent.z ? 1 : 2;
  uint32_t middle = begin + (end - begin) / 2;
  std::nth_element(order.begin() + begin, order.begin() + middle, order.begin() + end,
                   [&](uint32_t a, uint32_t b) { return centroids[a][axis] < centroids[b][axis]; });
  int32_t left = build(begin, middle);
  int32_t right = build(middle, end);
  nodes[index].left = left;
  nodes[index].right = right;
  return index;
}

template <size_t K>
Vector3 ClosestPointTree<K>::closestOnPrimitive(size_t primitive, const Vector3& p) const {
  const auto& s = primitives[primitive];
  if constexpr (K == 3) {
    return closestPointOnTriangle(p, vertices[s[0]], vertices[s[1]], vertices[s[2]]);
  } else {
    const Vector3 &a = vertices[s[0]], &b = vertices[s[1]];
    return a + (b - a) * closestParameterOnSegment(p, a, b);
  }
}

template <size_t K>
void ClosestPointTree<K>::search(int32_t index, const Vector3& p, Hit& best) const {
  const Node& node = nodes[index];
  if (node.left < 0) {
    for (uint32_t i = node.begin; i < node.end; i++) {
      Vector3 q = closestOnPrimitive(order[i], p);
      double d2 = norm2(q - p);
      if (d2 < best.distance2) best = {order[i], q, d2};
    }
    return;
  }
  double left = boxDistance2(p, nodes[node.left].lower, nodes[node.left].upper);
  double right = boxDistance2(p, nodes[node.right].lower, nodes[node.right].upper);
  int32_t first = node.left, second = node.right;
  if (right < left) {
    std::swap(first, second);
    std::swap(left, right);
  }
  if (left < best.distance2) search(first, p, best);
  if (right < best.distance2) search(second, p, best);
}

template <size_t K>
typename ClosestPointTree<K>::Hit ClosestPointTree<K>::closest(const Vector3& p) const {
  Hit best;
  best.distance2 = std::numeric_limits<double>::infinity();
  search(0, p, best);
  return best;
}

template class ClosestPointTree<2>;
template class ClosestPointTree<3>;

} // namespace cscd
