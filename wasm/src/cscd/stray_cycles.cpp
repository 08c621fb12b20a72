#include "cscd/stray_cycles.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <queue>

using geometrycentral::Vector3;

namespace cscd {
namespace {

// Samples of the cone from the centroid to each point, at these shares of the way (the points
// themselves are on the skeleton, inside by construction).
constexpr double kConeSteps[] = {0, 0.25, 0.5, 0.75};

// Measured (docs/skeleton.md, "Cycles through the air"): on 57 cloud and 92 mesh skeletons with cycles
// round real holes (and a noisy cloud's rings the noise joins), no point of an edge on a cycle lies
// farther than 1.68 times its nodes' larger radius from the shape (a noisy hanger's chord across its
// ring's wire; meshes at most 1.20); the tree scans' stray cycles reach 3.05-12.96 at five of six runs
// (1.80 at the sixth).
constexpr double kAirInRadii = 2.5;
// Where along an edge it is tested for air (its ends are nodes, within the shape).
constexpr double kEdgeSteps[] = {0.5, 0.25, 0.75, 0.125, 0.375, 0.625, 0.875};

constexpr size_t kNone = std::numeric_limits<size_t>::max();

// The nodes of the shortest path from `from` to `to` over the graph without edge `skipped`, in order;
// empty when there is none.
std::vector<size_t> shortestOtherPath(const SkeletonGraph& graph, const std::vector<std::vector<size_t>>& edgesAt, size_t skipped,
                                      size_t from, size_t to) {
  std::vector<double> distance(graph.nodes.size(), INFINITY);
  std::vector<size_t> previous(graph.nodes.size(), kNone);
  using Entry = std::pair<double, size_t>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> queue;
  distance[from] = 0;
  queue.push({0, from});
  while (!queue.empty()) {
    const auto [d, node] = queue.top();
    queue.pop();
    if (node == to) break;
    if (d > distance[node]) continue;
    for (size_t e : edgesAt[node]) {
      if (e == skipped) continue;
      const size_t next = graph.edges[e][0] == node ? graph.edges[e][1] : graph.edges[e][0];
      const double through = d + norm(graph.nodes[next] - graph.nodes[node]);
      if (through < distance[next]) {
        distance[next] = through;
        previous[next] = node;
        queue.push({through, next});
      }
    }
  }
  std::vector<size_t> path;
  if (previous[to] == kNone) return path;
  for (size_t node = to; node != kNone; node = previous[node]) path.push_back(node);
  return path;
}

// Each edge, longest first, that lies on a cycle: dropped when `drop(edge, cycle's nodes)` says so.
// Returns whether one was.
bool openCycles(SkeletonGraph& graph, const std::function<bool(size_t, const std::vector<size_t>&)>& drop) {
  if (graph.cycleRank() == 0) return false;
  const auto length = [&](size_t e) { return norm(graph.nodes[graph.edges[e][0]] - graph.nodes[graph.edges[e][1]]); };
  std::vector<size_t> order(graph.edges.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) { return length(a) > length(b); });
  std::vector<std::vector<size_t>> edgesAt(graph.nodes.size());
  for (size_t e = 0; e < graph.edges.size(); e++) {
    edgesAt[graph.edges[e][0]].push_back(e);
    edgesAt[graph.edges[e][1]].push_back(e);
  }
  std::vector<char> dropped(graph.edges.size(), 0);
  for (size_t e : order) {
    const std::vector<size_t> path = shortestOtherPath(graph, edgesAt, e, graph.edges[e][0], graph.edges[e][1]);
    if (path.empty() || !drop(e, path)) continue;
    dropped[e] = 1;
    for (size_t end : graph.edges[e]) edgesAt[end].erase(std::find(edgesAt[end].begin(), edgesAt[end].end(), e));
  }
  std::vector<std::array<size_t, 2>> kept;
  for (size_t e = 0; e < graph.edges.size(); e++)
    if (!dropped[e]) kept.push_back(graph.edges[e]);
  const bool any = kept.size() < graph.edges.size();
  graph.edges = std::move(kept);
  return any;
}

bool diskInside(const std::vector<Vector3>& cycle, const std::function<bool(const Vector3&)>& inside) {
  Vector3 centroid{0, 0, 0};
  for (const Vector3& p : cycle) centroid += p;
  centroid /= double(cycle.size());
  for (double t : kConeSteps)
    for (size_t i = 0; i < cycle.size(); i++) {
      const Vector3 corner = cycle[i], middle = (cycle[i] + cycle[(i + 1) % cycle.size()]) / 2;
      if (!inside(centroid + t * (corner - centroid)) || !inside(centroid + t * (middle - centroid))) return false;
    }
  return true;
}

bool farFromAll(const Vector3& p, double distance, const std::vector<Vector3>& surface) {
  const double distance2 = distance * distance;
  for (const Vector3& q : surface)
    if (norm2(q - p) <= distance2) return false;
  return true;
}

} // namespace

void openFilledCycles(SkeletonGraph& graph, const std::function<bool(const Vector3&)>& inside) {
  openCycles(graph, [&](size_t, const std::vector<size_t>& path) {
    std::vector<Vector3> cycle;
    for (size_t node : path) cycle.push_back(graph.nodes[node]);
    return diskInside(cycle, inside);
  });
}

bool openCyclesThroughAir(SkeletonGraph& graph, const std::vector<Vector3>& surface) {
  return openCycles(graph, [&](size_t e, const std::vector<size_t>&) {
    const auto [a, b] = graph.edges[e];
    const double reach = kAirInRadii * std::max(graph.radii[a], graph.radii[b]);
    for (double t : kEdgeSteps)
      if (farFromAll(graph.nodes[a] + t * (graph.nodes[b] - graph.nodes[a]), reach, surface)) return true;
    return false;
  });
}

} // namespace cscd
