#include "pointcloud/winding.h"

#include <cmath>
#include <queue>

using namespace geometrycentral;
using namespace geometrycentral::pointcloud;

namespace cscd {

PointWinding::PointWinding(Cloud& cloud) : area(cloud.pointAreas()) {
  PointPositionGeometry& geometry = cloud.geometry();
  geometry.requireNeighbors();
  geometry.requireNormals();
  const size_t n = cloud.pointCount();
  const PointData<std::vector<Point>>& neighbours = geometry.neighbors->neighbors;
  position.resize(n);
  normal.resize(n);
  for (size_t p = 0; p < n; p++) {
    position[p] = geometry.positions[p];
    normal[p] = geometry.normals[p];
  }

  // Prim's tree from the topmost unvisited point; each point takes the orientation of the tree
  // neighbour it is reached from. Ties in the weight go to the lower index, so the orientation is the
  // same on every run. Each tree's sign is then chosen by its enclosed volume (below).
  std::vector<char> oriented(n, 0);
  std::vector<size_t> tree;
  using Entry = std::pair<double, std::pair<size_t, size_t>>; // weight, (point, from)
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> frontier;
  auto reach = [&](size_t p) {
    for (Point q : neighbours[p]) {
      const size_t i = q.getIndex();
      if (!oriented[i]) frontier.push({1 - std::abs(dot(normal[p], normal[i])), {i, p}});
    }
  };
  for (size_t left = n; left > 0;) {
    size_t top = SIZE_MAX;
    for (size_t p = 0; p < n; p++)
      if (!oriented[p] && (top == SIZE_MAX || position[p].z > position[top].z)) top = p;
    tree.assign(1, top);
    oriented[top] = 1;
    left--;
    reach(top);
    while (!frontier.empty()) {
      const auto [weight, link] = frontier.top();
      frontier.pop();
      const auto [p, from] = link;
      if (oriented[p]) continue;
      if (dot(normal[p], normal[from]) < 0) normal[p] = -normal[p];
      oriented[p] = 1;
      tree.push_back(p);
      left--;
      reach(p);
    }
    // Outward normals enclose a positive volume: sum a_i n_i . (x_i - c) = 3 V by the divergence
    // theorem. The topmost point's own normal (PCA on the tip of an ear lies nearly flat) was not
    // reliable enough: it turned the whole horse_clean cloud inside out.
    Vector3 centre{0, 0, 0};
    for (size_t p : tree) centre += position[p] / double(tree.size());
    double volume = 0;
    for (size_t p : tree) volume += area[p] * dot(normal[p], position[p] - centre);
    if (volume < 0)
      for (size_t p : tree) normal[p] = -normal[p];
  }
}

double PointWinding::operator()(const Vector3& q) const {
  double sum = 0;
  for (size_t i = 0; i < position.size(); i++) {
    const Vector3 d = position[i] - q;
    const double r = norm(d);
    if (r > 0) sum += area[i] * dot(normal[i], d) / (r * r * r);
  }
  return sum / (4 * M_PI);
}

} // namespace cscd
