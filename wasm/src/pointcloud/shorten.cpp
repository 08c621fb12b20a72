#include "pointcloud/shorten.h"

#include "cscd/errors.h"
#include "cscd/measures.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <numeric>
#include <queue>

using namespace geometrycentral;

namespace cscd {
namespace {

// Lengths below are in units of the cloud's mean spacing, so that every constant is scale-free.
constexpr double kPenaltyWeight = 10; // lambda of the paper's sphere penalty
// Steps are preconditioned (LoopEnergy::descent) and scaled down to at most kMaxMove per point, which
// keeps the MLS projection local; a step is halved while the energy does not decrease.
constexpr int kMaxHalvings = 10;
constexpr double kMaxMove = 0.5;
// The steps move pre-images of the loop's points (shortenLoop); one farther than this from its point starts
// again on the loop (they stay about as far from the surface as the first chords were, unless tangent
// steps around a bend take them farther).
constexpr double kFarthestPreimage = 0.25;
constexpr double kShortest = 0.5, kLongest = 1.5; // a segment outside these lengths resamples the loop
constexpr size_t kMinPoints = 6;
// Converged when no point moves farther than kSettledMove across the loop in a step, or when a full step
// lowers the energy by less than kSettledDecrease: a Newton decrement (the step is preconditioned by a bound
// on the Hessian), about 2e-5 spacing of length (H'(1) = 2e per spacing), where a loop on a flat stretch of
// the energy (one on bob) would otherwise creep on for 150 steps at a constant length.
constexpr double kSettledMove = 1e-3;
constexpr double kSettledDecrease = 1e-4;
constexpr int kMaxIterations = 5000;
// A loop that jitters is given up as not converging, as kMaxIterations would give it up: over kStallWindow
// steps it got shorter by less than kStalledShare of its length while its length varied by more. On some
// clouds (armadillo_noise1.0; one sampled from elk.ply, where 18 of 80 sources' loops ran all 5000 steps)
// a loop at its shortest jitters by about 1% of its length for good, each step lowering the energy and a
// resampling or a restart of the pre-images raising it again. A loop that creeps (along bob's tube) varies
// by less and goes on; a window of 200 steps also gave up a loop of horse_nonuniform that settled after
// 1252, and accepting jittering loops as converged changed skeletons both ways, up to 3.8 times the error
// (docs/pointcloud.md, "Loops that jitter").
constexpr int kStallWindow = 1000;
constexpr double kStalledShare = 1e-3;
// A loop that grows past this many times its length after the first projection is not being shortened:
// on a rough, sparse cloud (tree_woodske_SW, one source of 20,594 points) each resampled loop projected
// onto the MLS surface of other branches zig-zagged to twice the length of the one before, 68 points to
// a million in 40 steps, until the core ran out of memory. Such a loop is given up as not converging.
constexpr double kMaxGrowth = 4;
// A loop that keeps a segment longer than kGapLength spacings for kMaxGapSteps steps crosses a gap of the
// cloud: the points resampling puts into the gap project back to its two sides, so the step that shortens
// the segment is undone at every step. On tree_woodske_SW (a sparse scan, branches seen from one side)
// such loops cycled at a constant length until kMaxIterations, 1.7-9.6 s a loop; over 40 sources each of
// six clouds sampled from meshes (clean and noisy), no loop kept such a segment for even 5 steps.
constexpr double kGapLength = 3;
constexpr int kMaxGapSteps = 20;
// A loop shorter than this encloses nothing the cloud resolves: a tube that thin has under one spacing
// of radius, and the mesh prunes loops shorter than 3 mean edge lengths by default (pruneLengthFactor).
constexpr double kDegenerateLength = 3;
// A loop on a noisy cloud whose sides meet even near it is measured by its plane, but only where the
// surface's normals along it lie across that plane: their mean |cosine| with the plane's normal at most
// that of random directions (sideAreas).
constexpr double kMaxPlaneTilt = 0.5;

using Polyline = std::vector<Vector3>;

// Projects a loop's points on the cloud's surface. Each point keeps its candidate neighbours between
// steps (it moves at most kMaxMove per step): the projections are those without the caches, found without
// most of the kd-tree queries. On a clean cloud the points go on the blended fits of their nearest points
// (MlsSurface::projectOnPatches), on a noisy one on the MLS surface itself: there the fits are planes whose
// heights carry the noise, and a blend of a few of them is rough (docs/pointcloud.md, "Loops on patches").
// Where the noise test fitted the quadratic at none of its sample, it is not tried either: it is then
// rejected at nearly every loop point (none of 757 on hand_noise0.5, 1 of 598 on armadillo_gel_pts), and
// trying it took a third of the shortening's time.
class LoopProjector {
public:
  explicit LoopProjector(Cloud& cloud)
      : mls(cloud.mls()), onPatches(!cloud.neighbourhood().noisyCloud()),
        tryQuadratic(cloud.neighbourhood().curvatureSampled()) {}

  std::vector<MlsPoint> operator()(const Polyline& points) {
    caches.resize(points.size());
    std::vector<MlsPoint> result;
    result.reserve(points.size());
    for (size_t i = 0; i < points.size(); i++)
      result.push_back(onPatches ? mls.projectOnPatches(points[i], &caches[i]) : mls.project(points[i], &caches[i], tryQuadratic));
    return result;
  }

private:
  const MlsSurface& mls;
  bool onPatches, tryQuadratic;
  std::vector<MlsNeighbourCache> caches;
};

Polyline positionsOf(const std::vector<MlsPoint>& points) {
  Polyline result;
  result.reserve(points.size());
  for (const MlsPoint& p : points) result.push_back(p.position);
  return result;
}

// The closed polyline resampled at equal arc lengths, about one spacing apart (to be projected on the surface).
Polyline resampled(const Polyline& loop, double spacing) {
  const double length = loopLength(loop);
  const size_t count = std::max(kMinPoints, size_t(std::lround(length / spacing)));
  Polyline points;
  points.reserve(count);
  size_t segment = 0;
  double start = 0; // arc length at the start of `segment`
  for (size_t k = 0; k < count; k++) {
    const double at = length * double(k) / double(count);
    double segmentLength = norm(loop[(segment + 1) % loop.size()] - loop[segment]);
    while (start + segmentLength < at && segment + 1 < loop.size()) {
      start += segmentLength;
      segment++;
      segmentLength = norm(loop[(segment + 1) % loop.size()] - loop[segment]);
    }
    const double t = segmentLength > 0 ? std::clamp((at - start) / segmentLength, 0., 1.) : 0;
    points.push_back((1 - t) * loop[segment] + t * loop[(segment + 1) % loop.size()]);
  }
  return points;
}

// Solves M x = rhs, M the symmetric cyclic tridiagonal matrix with `diagonal` whose point i is coupled to
// point i + 1 (mod n) by -coupling[i]: the Thomas algorithm on M less its corner pair, corrected by
// Sherman-Morrison; M is strictly diagonally dominant, so it needs no pivoting. O(n): a sparse LDLT of
// the same matrix, ordered and analysed anew at every step, cost 4-5% more shortening time (bob_clean).
Polyline solveCyclicTridiagonal(std::vector<double> diagonal, const std::vector<double>& coupling, const Polyline& rhs) {
  const size_t n = diagonal.size();
  const double gamma = -diagonal[0], corner = -coupling[n - 1];
  diagonal[0] -= gamma;
  diagonal[n - 1] -= corner * corner / gamma;
  std::vector<double> upper(n, 0), pivot(n);
  pivot[0] = diagonal[0];
  for (size_t i = 1; i < n; i++) {
    upper[i - 1] = -coupling[i - 1] / pivot[i - 1];
    pivot[i] = diagonal[i] + coupling[i - 1] * upper[i - 1];
  }
  auto solve = [&](auto b) {
    b[0] = b[0] / pivot[0];
    for (size_t i = 1; i < n; i++) b[i] = (b[i] + coupling[i - 1] * b[i - 1]) / pivot[i];
    for (size_t i = n - 1; i-- > 0;) b[i] = b[i] - upper[i] * b[i + 1];
    return b;
  };
  std::vector<double> u(n, 0);
  u[0] = gamma;
  u[n - 1] = corner;
  const Polyline y = solve(rhs);
  const std::vector<double> z = solve(std::move(u));
  const Vector3 share = (y[0] + corner / gamma * y[n - 1]) / (1 + z[0] + corner / gamma * z[n - 1]);
  Polyline x(n);
  for (size_t i = 0; i < n; i++) x[i] = y[i] - z[i] * share;
  return x;
}

// The energy of the paper with the loop measured in spacings: sum H(s_i) + lambda sum max(0, d_i - r)^2.
struct LoopEnergy {
  double spacing;
  std::optional<Sphere> sphere;

  double value(const Polyline& x) const {
    double e = 0;
    for (size_t i = 0; i < x.size(); i++) {
      const double s = norm(x[(i + 1) % x.size()] - x[i]) / spacing;
      e += std::expm1(s * s);
    }
    if (sphere)
      for (const Vector3& p : x) {
        const double excess = std::max(0., (norm(p - sphere->center) - sphere->radius) / spacing);
        e += kPenaltyWeight * excess * excess;
      }
    return e;
  }

  // The descent direction at x (in spacings): the gradient with respect to x / spacing projected on the
  // surface's tangent planes, then preconditioned by a matrix that bounds the energy's Hessian, so that
  // a step of 1 is safe for every wavelength along the loop. Plain gradient descent would need a step
  // small enough for the shortest wavelength, and then moves a loop of N points in about N^2 steps.
  // The matrix: the loop's Laplacian weighted by H''(s) per segment (it bounds each segment's Hessian
  // block, H''(s) along the segment and H'(s) / s across it), plus 2 lambda at points outside the sphere
  // and, on the diagonal, the loop's slowest bending mode's eigenvalue (mean weight (2 pi / N)^2): the
  // step that moves the whole loop at once (sliding along a tube) is then as fast as that mode, not
  // unbounded. With 1e-3 of the mean weight instead, that step took over on noisy clouds, where the
  // surface is rough at its scale, and the descent stalled. The direction is projected on the tangent
  // planes again; it still descends, as the tangential gradient is orthogonal to what that removes.
  Polyline descent(const Polyline& x, const std::vector<MlsPoint>& onSurface) const {
    const size_t n = x.size();
    Polyline g(n, Vector3{0, 0, 0});
    std::vector<double> weight(n), penalty(n, 0);
    for (size_t i = 0; i < n; i++) {
      const size_t j = (i + 1) % n;
      const Vector3 d = (x[i] - x[j]) / spacing;
      const double s2 = norm2(d), grow = std::exp(s2);
      g[i] += 2 * grow * d; // H'(s) d / s
      g[j] -= 2 * grow * d;
      weight[i] = (2 + 4 * s2) * grow; // H''(s)
    }
    if (sphere)
      for (size_t i = 0; i < n; i++) {
        const Vector3 out = (x[i] - sphere->center) / spacing;
        const double distance = norm(out), excess = distance - sphere->radius / spacing;
        if (!(excess > 0)) continue;
        g[i] += 2 * kPenaltyWeight * excess * out / distance;
        penalty[i] = 2 * kPenaltyWeight;
      }
    auto tangential = [&](size_t i, Vector3 v) { return v - dot(v, onSurface[i].normal) * onSurface[i].normal; };

    const double slowestMode = std::pow(2 * M_PI / double(n), 2) * std::accumulate(weight.begin(), weight.end(), 0.) / double(n);
    std::vector<double> diagonal(n);
    Polyline rhs(n);
    for (size_t i = 0; i < n; i++) {
      diagonal[i] = weight[i] + weight[(i + n - 1) % n] + penalty[i] + slowestMode;
      rhs[i] = -tangential(i, g[i]);
    }
    Polyline direction = solveCyclicTridiagonal(std::move(diagonal), weight, rhs);
    for (size_t i = 0; i < n; i++) direction[i] = tangential(i, direction[i]);
    return direction;
  }
};

// The largest move of a point across the loop: sliding along it moves the points, not the curve (a loop
// at its shortest creeps along itself at a few thousandths of a spacing per step as its spacings even out).
double largestMoveAcross(const Polyline& x, const std::vector<MlsPoint>& next) {
  const size_t n = x.size();
  double largest = 0;
  for (size_t i = 0; i < n; i++) {
    const Vector3 along = (x[(i + 1) % n] - x[(i + n - 1) % n]).normalize();
    const Vector3 move = next[i].position - x[i];
    largest = std::max(largest, norm(move - dot(move, along) * along));
  }
  return largest;
}

bool farFromLoop(const Polyline& y, const Polyline& x, double spacing) {
  for (size_t i = 0; i < x.size(); i++)
    if (norm(y[i] - x[i]) > kFarthestPreimage * spacing) return true;
  return false;
}

double longestSegment(const Polyline& loop) {
  double longest = 0;
  for (size_t i = 0; i < loop.size(); i++) longest = std::max(longest, norm(loop[(i + 1) % loop.size()] - loop[i]));
  return longest;
}

bool needsResampling(const Polyline& loop, double spacing) {
  for (size_t i = 0; i < loop.size(); i++) {
    const double s = norm(loop[(i + 1) % loop.size()] - loop[i]) / spacing;
    if (s < kShortest || s > kLongest) return true;
  }
  return false;
}

// Areas of the two sides of the loop: the points of the constraint region (the sphere, and the points
// within a spacing of the loop) flooded from either side of the loop along the edges of the tufted
// triangulation, never across the loop, each weighted by the area it stands for. An edge pq crosses the
// loop only if both ends lie within |pq| of it, on its two sides, where the loop lies on the edge's
// surface; on a noisy cloud it passes the edge up to the noise away, which a spacing more allows for where
// the noise is well under a spacing (beyond, splitByPlane below).
// The side of a point is that of the surface's direction across the loop at the nearest point of the loop. A loop whose sides meet is
// measured, as on meshes, over the points within one loop radius of it along the edges (mesh/shorten.cpp),
// and on a noisy cloud, where they meet there too, by its plane (splitByPlane below).
std::array<double, 2> sideAreas(Cloud& cloud, const std::vector<MlsPoint>& loop, const std::optional<Sphere>& sphere,
                                double spacing) {
  const size_t n = loop.size(), pointCount = cloud.pointCount();
  const pointcloud::PointData<Vector3>& positions = cloud.geometry().positions;
  // Normals oriented along the loop (their signs are arbitrary), then each segment's direction across the loop.
  auto toward = [](Vector3 v, Vector3 reference) { return dot(v, reference) < 0 ? -v : v; };
  std::vector<Vector3> normals(n), across(n);
  for (size_t i = 0; i < n; i++) normals[i] = i == 0 ? loop[0].normal : toward(loop[i].normal, normals[i - 1]);
  for (size_t i = 0; i < n; i++) {
    const Vector3 along = loop[(i + 1) % n].position - loop[i].position;
    across[i] = cross(along, normals[i] + toward(normals[(i + 1) % n], normals[i]));
  }

  // Only points in the region are measured: with a sphere, none farther from its centre than the loop's
  // farthest point and a spacing (every point of the loop is within that less a spacing).
  double regionReach = INFINITY;
  if (sphere) {
    regionReach = sphere->radius;
    for (const MlsPoint& p : loop) regionReach = std::max(regionReach, norm(p.position - sphere->center));
    regionReach += spacing;
  }
  std::vector<char> inRegion(pointCount, 0), positiveSide(pointCount, 0);
  std::vector<double> distance(pointCount, INFINITY);
  for (size_t p = 0; p < pointCount; p++) {
    const Vector3 x = positions[p];
    if (sphere && norm(x - sphere->center) > regionReach) continue;
    size_t nearest = 0;
    Vector3 foot = loop[0].position;
    for (size_t i = 0; i < n; i++) {
      const Vector3 a = loop[i].position, b = loop[(i + 1) % n].position;
      const double t = norm2(b - a) > 0 ? std::clamp(dot(x - a, b - a) / norm2(b - a), 0., 1.) : 0;
      const Vector3 y = a + t * (b - a);
      if (norm2(x - y) < distance[p]) distance[p] = norm2(x - y), nearest = i, foot = y;
    }
    distance[p] = std::sqrt(distance[p]);
    positiveSide[p] = dot(x - foot, across[nearest]) >= 0;
    inRegion[p] = !sphere || distance[p] <= spacing || norm(x - sphere->center) <= sphere->radius;
  }

  const std::vector<std::vector<uint32_t>>& adjacent = cloud.tuftedNeighbours();
  auto crossesLoop = [&](size_t p, size_t q) {
    const double reach = norm(positions[p] - positions[q]) + spacing;
    return distance[p] <= reach && distance[q] <= reach && positiveSide[p] != positiveSide[q];
  };

  const std::vector<double>& pointAreas = cloud.pointAreas();
  auto flood = [&](const std::vector<char>& reached, std::array<double, 2>& area) {
    std::vector<int> side(pointCount, -1);
    bool separates = true;
    area = {0, 0};
    for (int s = 0; s < 2; s++) {
      std::queue<size_t> queue;
      auto enter = [&](size_t p) {
        if (side[p] == 1 - s) separates = false;
        if (side[p] < 0) {
          side[p] = s;
          area[s] += pointAreas[p];
          queue.push(p);
        }
      };
      for (size_t p = 0; p < pointCount; p++)
        if (reached[p] && distance[p] <= spacing && bool(positiveSide[p]) == (s == 0)) enter(p);
      while (!queue.empty()) {
        const size_t p = queue.front();
        queue.pop();
        for (size_t q : adjacent[p])
          if (reached[q] && !crossesLoop(p, q)) enter(q);
      }
    }
    return separates;
  };

  // On a noisy cloud the floods meet beside most loops: the points beside a loop lie up to the noise above
  // and below the surface, as far off it as across the loop, so their side is noise and a flood steps over
  // the loop through them. A loop that cuts across a part of the shape has the points of the region on
  // either side of its plane as its sides; one around a bump of the noise, or so bent that its plane is
  // no cut, has surface normals along it no more across its plane than random directions, and is left
  // unmeasured (docs/pointcloud.md, "Sides of a loop on a noisy cloud").
  auto splitByPlane = [&](std::array<double, 2>& area) {
    const Polyline x = positionsOf(loop);
    const Vector3 centre = loopCentroid(x, true), planeNormal = loopNormal(x);
    double tilt = 0;
    for (const MlsPoint& p : loop) tilt += std::abs(dot(p.normal, planeNormal));
    if (tilt > kMaxPlaneTilt * double(n)) return false;
    area = {0, 0};
    for (size_t p = 0; p < pointCount; p++)
      if (inRegion[p]) area[dot(positions[p] - centre, planeNormal) > 0] += pointAreas[p];
    return true;
  };

  std::array<double, 2> area;
  if (!flood(inRegion, area)) {
    // Around a handle that lies whole in the region: measure near the loop, within one loop radius along the edges.
    const double radius = loopLength(positionsOf(loop)) / (2 * M_PI);
    std::vector<double> along(pointCount, INFINITY);
    using Entry = std::pair<double, size_t>;
    std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> frontier;
    for (size_t p = 0; p < pointCount; p++)
      if (inRegion[p] && distance[p] <= spacing) frontier.push({along[p] = distance[p], p});
    while (!frontier.empty()) {
      const auto [d, p] = frontier.top();
      frontier.pop();
      if (d > along[p]) continue;
      for (size_t q : adjacent[p]) {
        if (!inRegion[q]) continue;
        const double through = d + norm(positions[p] - positions[q]);
        if (through < along[q]) frontier.push({along[q] = through, q});
      }
    }
    std::vector<char> near(pointCount);
    for (size_t p = 0; p < pointCount; p++) near[p] = along[p] <= radius;
    if (!flood(near, area) && (!cloud.neighbourhood().noisyCloud() || !splitByPlane(area))) return {0, area[0] + area[1]};
  }
  return {std::min(area[0], area[1]), std::max(area[0], area[1])};
}

// Keeps the first loop, every stride-th step after it and the last, at most `capacity` loops in all: when
// more would be kept, every other one is dropped and the stride doubles, so they stay evenly spaced in
// steps without knowing beforehand how many steps there will be. Capacity 0 keeps nothing.
class IterateRecorder {
public:
  explicit IterateRecorder(int capacity) : capacity_(capacity) {}

  void record(int iteration, const Polyline& x) {
    if (capacity_ == 0 || iteration % stride_ != 0) return;
    kept_.push_back(x);
    if (int(kept_.size()) < capacity_) return; // a place stays free for the last loop
    for (size_t i = 1; 2 * i < kept_.size(); i++) kept_[i] = std::move(kept_[2 * i]);
    kept_.resize((kept_.size() + 1) / 2);
    stride_ *= 2;
  }

  std::vector<Polyline> finish(int iteration, const Polyline& x) {
    if (capacity_ > 0 && (kept_.empty() || int(kept_.size() - 1) * stride_ != iteration)) kept_.push_back(x);
    return std::move(kept_);
  }

private:
  int capacity_;
  int stride_ = 1;
  std::vector<Polyline> kept_; // kept_[j] is the loop after j * stride_ steps
};

} // namespace

ShortenedCloudLoop shortenLoop(Cloud& cloud, const Polyline& polyline, const std::optional<Sphere>& sphere, int recordFrames) {
  if (polyline.size() < 3) throw InputError("a loop needs at least 3 points");
  for (const Vector3& p : polyline)
    if (!isfinite(p)) throw InputError("the loop has a non-finite coordinate");
  if (sphere && !(sphere->radius > 0 && std::isfinite(sphere->radius) && isfinite(sphere->center)))
    throw InputError("the sphere needs a finite centre and a positive radius");

  ShortenedCloudLoop result;
  const double spacing = cloud.facts().meanSpacing;
  LoopProjector projected(cloud);
  const LoopEnergy energy{spacing, sphere};
  // The loop is the projection of its pre-images `y`, which the steps move: a step of length t then moves
  // the loop continuously from where it is, however noisy the cloud (projecting the projected loop again,
  // as each step once did, moves it a little there), and each step projects the loop once, not twice.
  Polyline y = resampled(positionsOf(projected(polyline)), spacing);
  std::vector<MlsPoint> loop = projected(y);
  Polyline x = positionsOf(loop);
  IterateRecorder recorder(recordFrames);
  recorder.record(0, x);
  const double longestLoop = kMaxGrowth * loopLength(x);
  std::string givenUp; // why the loop was given up as not converging, if it was
  int gapSteps = 0;    // consecutive steps after which a segment still crossed a gap

  Polyline trial;
  double step = 1;
  bool settled = false;
  // The shortest length so far, as it was at the end of the last window, and the longest in this window.
  double shortest = loopLength(x), shortestBefore = shortest, windowLongest = 0;
  while (!settled && loopLength(x) >= kDegenerateLength * spacing && result.iterations < kMaxIterations) {
    const double before = energy.value(x);
    Polyline direction = energy.descent(x, loop);
    double longest = 0;
    for (const Vector3& d : direction) longest = std::max(longest, norm(d));
    std::vector<MlsPoint> next;
    double after = INFINITY;
    int halvings = 0;
    bool full = false; // the step as preconditioned, neither shortened to kMaxMove nor halved
    for (;; halvings++) {
      full = step >= 1 && longest <= kMaxMove;
      step = std::min(step, kMaxMove / longest);
      trial.resize(x.size());
      for (size_t i = 0; i < x.size(); i++) trial[i] = y[i] + step * spacing * direction[i];
      next = projected(trial);
      after = energy.value(positionsOf(next));
      if (after < before || halvings == kMaxHalvings) break;
      step /= 2;
    }
    // No step lowers the energy: the loop is at a minimum, up to how well the MLS surface is known.
    if (!(after < before)) break;
    // A step that had to be halved is kept: doubling it back would fail again and cost a projection.
    if (halvings == 0) step = std::min(1., 2 * step);
    settled = largestMoveAcross(x, next) < kSettledMove * spacing || (full && before - after < kSettledDecrease);
    y = trial;
    loop = std::move(next);
    x = positionsOf(loop);
    if (needsResampling(x, spacing)) {
      y = resampled(x, spacing);
      loop = projected(y);
      x = positionsOf(loop);
    } else if (farFromLoop(y, x, spacing)) {
      // Tangent steps on a curved surface take the pre-images away from it: they start again on the loop.
      y = x;
      loop = projected(y);
      x = positionsOf(loop);
    }
    result.iterations++;
    recorder.record(result.iterations, x);
    const double length = loopLength(x);
    shortest = std::min(shortest, length);
    windowLongest = std::max(windowLongest, length);
    if (result.iterations % kStallWindow == 0 && !settled) {
      if (shortest > (1 - kStalledShare) * shortestBefore && windowLongest > (1 + kStalledShare) * shortest) {
        char share[16];
        std::snprintf(share, sizeof share, "%g", 100 * kStalledShare);
        givenUp = "the loop jitters without getting shorter (by under " + std::string(share) + "% in " +
                  std::to_string(kStallWindow) + " steps: the cloud's surface is too rough here)";
        break;
      }
      shortestBefore = shortest;
      windowLongest = 0;
    }
    if (length > longestLoop) {
      givenUp = "the loop grew instead of shortening (the cloud's surface is too rough or sparse here)";
      break;
    }
    gapSteps = longestSegment(x) > kGapLength * spacing ? gapSteps + 1 : 0;
    if (gapSteps == kMaxGapSteps) {
      givenUp = "the loop crosses a gap of the cloud: a segment stayed longer than " + std::to_string(int(kGapLength)) +
                " spacings for " + std::to_string(kMaxGapSteps) + " steps";
      break;
    }
  }
  result.iterates = recorder.finish(result.iterations, x);

  result.length = loopLength(x);
  if (result.length < kDegenerateLength * spacing) {
    result.failureKind = ShortenedCloudLoop::Failure::Degenerate;
    result.failure = "the loop shrank to a point: it encloses no feature inside the constraint region";
    result.length = 0;
    return result;
  }
  if (!givenUp.empty()) {
    result.failureKind = ShortenedCloudLoop::Failure::NotConverged;
    result.failure = givenUp;
    result.loop = x;
    return result;
  }
  if (result.iterations == kMaxIterations && !settled) {
    result.failureKind = ShortenedCloudLoop::Failure::NotConverged;
    result.failure = "the loop was still moving after " + std::to_string(kMaxIterations) + " steps";
  }
  result.loop = x;
  result.areas = sideAreas(cloud, loop, sphere, spacing);
  return result;
}

} // namespace cscd
