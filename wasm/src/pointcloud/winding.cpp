#include "pointcloud/winding.h"

#include <algorithm>
#include <cmath>
#include <array>
#include <map>
#include <numeric>
#include <queue>
#include <vector>

using namespace geometrycentral;
using namespace geometrycentral::pointcloud;

namespace cscd {

namespace {

// Points of a tree whose winding numbers decide its orientation, at most, and how far from 0 their mean
// must be, in standard errors, for them to decide (1 inside plus 0 outside, or 0 plus -1, where the tree
// is closed and well sampled; less on thin, sparse branches: 0.17 a point on tree_woodske_SW).
constexpr size_t kOrientationSamples = 256;
constexpr double kClearWinding = 3;

// Where the winding number is read across a point, in spacings along its normal on either side.
constexpr double kAcross = 0.5;

// Patches that may be turned on their own: the points of one tree in one cube of a grid this many spacings
// wide (wider, by kPatchGrowth at a time, until there are at most kMaxPatches: the patch-by-sample table
// holds at most 1024 x 8192 numbers, 64 MB), each sampled at up to kPatchSamples points. A patch is turned
// when that lowers the squared misfit by more than kTurnGain times what an inverted patch in an otherwise
// right cloud lowers it (below): twice, so that a part turned as a whole (SW's trunk: 5 to 12 times) is
// righted but not a lone patch that a noisy cloud's smeared sums merely suggest (horse_noise0.5's two turns
// were 0.6 and 1.0 times, and cost its skeleton a leaf). A patch is one dipole at its centre for a sample
// farther than kFarReaches times its radius.
constexpr double kPatchSpacings = 10;
constexpr size_t kMaxPatches = 1024;
constexpr double kPatchGrowth = 1.25;
constexpr size_t kPatchSamples = 8;
constexpr double kTurnGain = 2;
constexpr double kFarReaches = 4;

// A file's normals keep their signs when at most this share of the pairs of neighbours point against
// each other: 0-4.6% on the shared clouds with normals (the most on elephant_small, whose thin parts
// hold neighbours on opposite sides), 50% with every other normal flipped.
constexpr double kMaxOpposedShare = 0.1;

} // namespace

double PointWinding::opposedShare(const PointData<std::vector<Point>>& neighbours) const {
  size_t pairs = 0, opposed = 0;
  for (size_t p = 0; p < normal.size(); p++)
    for (Point q : neighbours[p]) {
      pairs++;
      opposed += dot(normal[p], normal[q.getIndex()]) < 0;
    }
  return pairs ? double(opposed) / double(pairs) : 0;
}

PointWinding::PointWinding(Cloud& cloud) : area(cloud.pointAreas()) {
  const double spacing = cloud.facts().meanSpacing;
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

  // A file's normals whose signs agree between neighbours keep them: propagating along the tree turns
  // them wrong across the creases of thin parts (elephant_small's tusks and tail, whose loops then failed
  // the centroid test). The whole cloud is then one tree for the sign and the patches.
  std::vector<size_t> treeOf(n, 0);
  if (cloud.facts().normalsFromFile && opposedShare(neighbours) <= kMaxOpposedShare) {
    std::vector<size_t> all(n);
    std::iota(all.begin(), all.end(), size_t(0));
    if (!outward(all, spacing))
      for (Vector3& v : normal) v = -v;
  } else {
    treeOf = orientAlongTrees(neighbours, spacing);
  }
  turnPatches(treeOf, spacing);
}

// Prim's tree from the topmost unvisited point; each point takes the orientation of the tree neighbour
// it is reached from. Ties in the weight go to the lower index, so the orientation is the same on every
// run. Each tree's sign is then chosen by its winding number (outward). Returns each point's tree.
std::vector<size_t> PointWinding::orientAlongTrees(const PointData<std::vector<Point>>& neighbours, double spacing) {
  const size_t n = normal.size();
  std::vector<char> oriented(n, 0);
  std::vector<size_t> tree, treeOf(n, 0);
  size_t trees = 0;
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
    if (!outward(tree, spacing))
      for (size_t p : tree) normal[p] = -normal[p];
    for (size_t p : tree) treeOf[p] = trees;
    trees++;
  }
  return treeOf;
}

// A tree's propagation can turn at a junction of thin parts: tree_woodske_SW's trunk came out inside out
// (winding about -1 on its axis) under a crown oriented right, whose many points decided the tree's sign.
// With one orientation the winding number is 1 just inside and 0 just outside, so w(x - d n) + w(x + d n)
// is about 1 at every point x: a patch is turned where that brings those sums at the samples clearly closer
// to 1 (w is linear in each patch's sign) and its own samples' sums are below 0, until a sweep turns none.
void PointWinding::turnPatches(const std::vector<size_t>& treeOf, double spacing) {
  const size_t n = position.size();
  if (n == 0) return;
  Vector3 low = position[0];
  for (const Vector3& p : position) low = componentwiseMin(low, p);
  std::vector<size_t> patch(n);
  std::vector<std::vector<size_t>> members;
  for (double cell = kPatchSpacings * spacing; members.empty() || members.size() > kMaxPatches; cell *= kPatchGrowth) {
    std::map<std::array<long, 4>, size_t> patchOf;
    members.clear();
    for (size_t p = 0; p < n; p++) {
      const Vector3 c = (position[p] - low) / cell;
      const std::array<long, 4> key{long(treeOf[p]), long(std::floor(c.x)), long(std::floor(c.y)), long(std::floor(c.z))};
      auto [it, added] = patchOf.emplace(key, members.size());
      if (added) members.emplace_back();
      patch[p] = it->second;
      members[it->second].push_back(p);
    }
  }
  const size_t patches = members.size();
  if (patches < 2) return;
  std::vector<size_t> samples, firstSample(patches + 1, 0);
  for (size_t k = 0; k < patches; k++) {
    const size_t every = std::max<size_t>(1, members[k].size() / kPatchSamples);
    for (size_t i = 0; i < members[k].size(); i += every) samples.push_back(members[k][i]);
    firstSample[k + 1] = samples.size();
  }
  // column[k][s]: patch k's share of w(x - d n) + w(x + d n) at sample s.
  std::vector<std::vector<double>> column(patches, std::vector<double>(samples.size(), 0));
  // A patch far from a sample counts as one dipole at its centre (Barill et al.'s far field, first order).
  std::vector<Vector3> centre(patches, Vector3{0, 0, 0}), dipole(patches, Vector3{0, 0, 0});
  std::vector<double> near(patches, spacing);
  for (size_t k = 0; k < patches; k++) {
    for (size_t p : members[k]) {
      centre[k] += position[p] / double(members[k].size());
      dipole[k] += area[p] * normal[p];
    }
    for (size_t p : members[k]) near[k] = std::max(near[k], kFarReaches * norm(position[p] - centre[k]));
  }
  auto share = [&](size_t k, const Vector3& q) {
    const Vector3 d = centre[k] - q;
    const double r = norm(d);
    if (r > near[k]) return dot(dipole[k], d) / (r * r * r);
    double sum = 0;
    for (size_t i : members[k]) sum += term(i, q);
    return sum;
  };
  for (size_t s = 0; s < samples.size(); s++) {
    const auto [in, out] = across(samples[s], spacing);
    for (size_t k = 0; k < patches; k++) column[k][s] = (share(k, in) + share(k, out)) / (4 * M_PI);
  }
  std::vector<double> residual(samples.size(), -1);
  for (const std::vector<double>& c : column)
    for (size_t s = 0; s < samples.size(); s++) residual[s] += c[s];
  std::vector<char> turned(patches, 0);
  // Turning patch k changes the residual by -2 c_k, the misfit by |r - 2 c|^2 - |r|^2 = 4 (cc - rc): an
  // inverted patch in a right cloud has r = 2 c plus the sums' noise, a gain of 4 cc.
  auto gain = [&](size_t k) {
    double rc = 0, cc = 0;
    for (size_t s = 0; s < samples.size(); s++) {
      rc += residual[s] * column[k][s];
      cc += column[k][s] * column[k][s];
    }
    return std::pair{4 * (rc - cc), 4 * cc};
  };
  for (bool changed = true; changed;) {
    changed = false;
    // Each sweep takes the patches by their gain at its start, the largest first: turning the most
    // clearly inverted ones makes their neighbours' sums clearer.
    std::vector<std::pair<double, size_t>> order;
    for (size_t k = 0; k < patches; k++) order.push_back({-gain(k).first, k});
    std::sort(order.begin(), order.end());
    for (const auto& [ignored, k] : order) {
      const auto [turnGain, inverted] = gain(k);
      if (!(turnGain > kTurnGain * inverted)) continue;
      // Only a patch that looks inside out itself: on noisy clouds the sums near the points are smeared,
      // and turns that fit 1 better overall inverted more points than they righted (the noisy bob, hand
      // and armadillo, measured against their meshes' normals: 38, 59, 256 of 1539 samples inverted
      // without patches, 133, 222, 446 with any turn allowed, 38, 59, 255 so).
      double own = 0;
      for (size_t s = firstSample[k]; s < firstSample[k + 1]; s++) own += residual[s] + 1;
      if (!(own < 0)) continue;
      turned[k] ^= 1;
      changed = true;
      for (size_t s = 0; s < samples.size(); s++) {
        residual[s] -= 2 * column[k][s];
        column[k][s] = -column[k][s];
      }
    }
  }
  for (size_t p = 0; p < n; p++)
    if (turned[patch[p]]) normal[p] = -normal[p];
}

// Whether a tree's normals point outwards. Its winding number is 1 inside and 0 outside with outward
// normals, 0 and -1 with inward ones: summed just inside and just outside sampled points (half a spacing
// along each normal) it has the sign of the orientation. Outward normals also enclose a positive volume
// (sum a_i n_i . (x_i - c) = 3 V, the divergence theorem), the rule used first, but on the thin, sparse,
// open scan tree_woodske_HS that sum came out negative and turned it inside out (the winding number about
// -1 inside every branch, so every loop failed the centroid test): it decides only where the winding
// numbers do not (an open sheet: about +-1/2 on either side, a sum near 0). The topmost point's own
// normal (PCA on the tip of an ear lies nearly flat) turned the whole horse_clean cloud inside out.
bool PointWinding::outward(const std::vector<size_t>& tree, double spacing) const {
  auto winding = [&](const Vector3& q) {
    double sum = 0;
    for (size_t i : tree) sum += term(i, q);
    return sum / (4 * M_PI);
  };
  const size_t every = std::max<size_t>(1, tree.size() / kOrientationSamples);
  std::vector<double> sums;
  for (size_t k = 0; k < tree.size(); k += every) {
    const auto [in, out] = across(tree[k], spacing);
    sums.push_back(winding(in) + winding(out));
  }
  double mean = 0, spread = 0;
  for (double a : sums) mean += a / double(sums.size());
  for (double a : sums) spread += (a - mean) * (a - mean) / double(sums.size());
  // The winding numbers decide when their mean is clearly off 0: kClearWinding standard errors.
  if (sums.size() > 1 && std::abs(mean) > kClearWinding * std::sqrt(spread / double(sums.size()))) return mean > 0;
  Vector3 centre{0, 0, 0};
  for (size_t p : tree) centre += position[p] / double(tree.size());
  double volume = 0;
  for (size_t p : tree) volume += area[p] * dot(normal[p], position[p] - centre);
  return volume >= 0;
}

std::array<Vector3, 2> PointWinding::across(size_t p, double spacing) const {
  return {position[p] - kAcross * spacing * normal[p], position[p] + kAcross * spacing * normal[p]};
}

double PointWinding::term(size_t i, const Vector3& q) const {
  const Vector3 d = position[i] - q;
  const double r = norm(d);
  return r > 0 ? area[i] * dot(normal[i], d) / (r * r * r) : 0;
}

double PointWinding::operator()(const Vector3& q) const {
  double sum = 0;
  for (size_t i = 0; i < position.size(); i++) sum += term(i, q);
  return sum / (4 * M_PI);
}

} // namespace cscd
