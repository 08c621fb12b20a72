#include "pointcloud/exterior.h"

#include "cscd/measures.h"

#include <algorithm>
#include <cmath>

using namespace geometrycentral;

namespace cscd {
namespace {

// A grid of at most this many cubes (16 MB for the two flags kept, 24 MB while they are built): a cloud
// whose box holds more cubes of a spacing (clusters far apart) gets cubes wider by kGrowth at a time, a
// coarser test.
constexpr double kMaxCells = 8e6;
constexpr double kGrowth = 1.25;
// Empty cubes around the box, so that the border is outside wherever the cloud does not reach it.
constexpr long kMargin = 2;
// A cross-section of a tube open at an end (enclosesCrossSection): every point of the loop within this
// share of its radius (its length over 2 pi) of its plane, and between these shares of it from its
// centroid; the shell met by every one of this many rays in its plane within this many radii; and by
// all but this share of this many directions in space (a tube's opening seen from one radius inside it
// is 15% of them; a hole's rim lets out at least the half on its open side).
constexpr double kFlat = 0.2;
constexpr double kRoundLow = 0.6, kRoundHigh = 1.5;
constexpr int kPlaneRays = 32;
constexpr double kPlaneReach = 2.0;
constexpr int kSpaceRays = 64;
constexpr double kEscapeShare = 0.25;
// ... and the shell about as deep on both sides of the loop: open space (a cube the flood reached, or
// next to one) no more than this many cubes farther away on one side than on the other, a median over
// the loop's points (a shell's faces lie on cube boundaries, so the two sides differ by up to a cube at
// a point; over cross-sections of open tubes the median was at most half a cube, 0.75 for one loop on a
// made cylinder with noise of a tenth of its radius, over loops round the holes of rings with walls 7
// noise deviations thick 1.25-4.25 cubes; docs/pointcloud.md).
constexpr double kWallCubes = 1.0;

} // namespace

ExteriorGrid::ExteriorGrid(const std::vector<Vector3>& points, double spacing) {
  Vector3 low{INFINITY, INFINITY, INFINITY}, high{-INFINITY, -INFINITY, -INFINITY};
  for (const Vector3& p : points)
    for (int a = 0; a < 3; a++) low[a] = std::min(low[a], p[a]), high[a] = std::max(high[a], p[a]);
  // A spacing of 0 (every point on one spot) would make no grid: a 64th of the box instead, or 1.
  double extent = 0;
  for (int a = 0; a < 3; a++) extent = std::max(extent, high[a] - low[a]);
  cellSize = spacing > 0 ? spacing : extent > 0 ? extent / 64 : 1;
  auto cubes = [&] {
    double count = 1;
    for (int a = 0; a < 3; a++) count *= std::floor((high[a] - low[a]) / cellSize) + 1 + 2 * kMargin;
    return count;
  };
  while (cubes() > kMaxCells) cellSize *= kGrowth;
  for (int a = 0; a < 3; a++) dims[a] = long(std::floor((high[a] - low[a]) / cellSize)) + 1 + 2 * kMargin;
  origin = low - double(kMargin) * cellSize * Vector3{1, 1, 1};

  solid.assign(size_t(dims[0] * dims[1] * dims[2]), 0);
  for (const Vector3& p : points) {
    const std::array<long, 3> c = cellOf(p);
    for (long dz = -1; dz <= 1; dz++)
      for (long dy = -1; dy <= 1; dy++)
        for (long dx = -1; dx <= 1; dx++) solid[cellIndex({c[0] + dx, c[1] + dy, c[2] + dz})] = 1;
  }
  // Flood the empty cubes from the border by face steps (a diagonal step could slip through the shell).
  std::vector<uint8_t> outside(solid.size(), 0);
  std::vector<size_t> stack;
  auto reach = [&](std::array<long, 3> c) {
    for (int a = 0; a < 3; a++)
      if (c[a] < 0 || c[a] >= dims[a]) return;
    const size_t i = cellIndex(c);
    if (solid[i] || outside[i]) return;
    outside[i] = 1;
    stack.push_back(i);
  };
  for (long z = 0; z < dims[2]; z++)
    for (long y = 0; y < dims[1]; y++)
      for (long x = 0; x < dims[0]; x++)
        if (x == 0 || y == 0 || z == 0 || x == dims[0] - 1 || y == dims[1] - 1 || z == dims[2] - 1) reach({x, y, z});
  while (!stack.empty()) {
    const size_t i = stack.back();
    stack.pop_back();
    const long x = long(i % size_t(dims[0])), y = long(i / size_t(dims[0]) % size_t(dims[1])), z = long(i / size_t(dims[0] * dims[1]));
    reach({x - 1, y, z});
    reach({x + 1, y, z});
    reach({x, y - 1, z});
    reach({x, y + 1, z});
    reach({x, y, z - 1});
    reach({x, y, z + 1});
  }
  // The outside grown back by the cube the shell was grown by (a closing): the cubes of the outer points
  // stay inside, the ring the growth added does not.
  inner.assign(solid.size(), 1);
  for (long z = 0; z < dims[2]; z++)
    for (long y = 0; y < dims[1]; y++)
      for (long x = 0; x < dims[0]; x++) {
        if (!outside[cellIndex({x, y, z})]) continue;
        for (long dz = -1; dz <= 1; dz++)
          for (long dy = -1; dy <= 1; dy++)
            for (long dx = -1; dx <= 1; dx++) {
              const std::array<long, 3> c{x + dx, y + dy, z + dz};
              if (c[0] >= 0 && c[1] >= 0 && c[2] >= 0 && c[0] < dims[0] && c[1] < dims[1] && c[2] < dims[2]) inner[cellIndex(c)] = 0;
            }
      }
}

std::array<long, 3> ExteriorGrid::cellOf(const Vector3& p) const {
  std::array<long, 3> c;
  for (int a = 0; a < 3; a++) c[a] = long(std::floor((p[a] - origin[a]) / cellSize));
  return c;
}

bool ExteriorGrid::meetsShell(const Vector3& p, const Vector3& d, double reach) const {
  for (double t = 0; t <= reach; t += cellSize / 2) {
    const std::array<long, 3> c = cellOf(p + t * d);
    for (int a = 0; a < 3; a++)
      if (!(c[a] >= 0 && c[a] < dims[a])) return false;
    if (solid[cellIndex(c)]) return true;
  }
  return false;
}

double ExteriorGrid::toOpenSpace(const Vector3& p, const Vector3& d, double reach) const {
  for (double t = 0; t < reach; t += cellSize / 4) {
    const std::array<long, 3> c = cellOf(p + t * d);
    for (int a = 0; a < 3; a++)
      if (!(c[a] >= 0 && c[a] < dims[a])) return t;
    if (!inner[cellIndex(c)]) return t;
  }
  return reach;
}

bool ExteriorGrid::enclosesCrossSection(const std::vector<Vector3>& loop) const {
  if (loop.size() < 3) return false;
  const double radius = loopLength(loop) / (2 * M_PI);
  const Vector3 centre = loopCentroid(loop, true), normal = loopNormal(loop);
  if (!(radius > 0) || !isfinite(centre) || norm(normal) == 0) return false;
  for (const Vector3& p : loop) {
    const double across = std::abs(dot(p - centre, normal)), away = norm(p - centre);
    if (across > kFlat * radius || away < kRoundLow * radius || away > kRoundHigh * radius) return false;
  }
  Vector3 u = cross(normal, Vector3{1, 0, 0});
  if (norm(u) < 0.5) u = cross(normal, Vector3{0, 1, 0});
  u = u.normalize();
  const Vector3 w = cross(normal, u);
  for (int k = 0; k < kPlaneRays; k++) {
    const double angle = 2 * M_PI * k / kPlaneRays;
    if (!meetsShell(centre, std::cos(angle) * u + std::sin(angle) * w, kPlaneReach * radius)) return false;
  }
  // A cross-section lies on one shell with open space just inside it (the tube's axis, reached through
  // its opening) and just outside; a loop round the hole of a ring lies on one face of the ring's wall,
  // and on the wall's side the shell runs on through the wall to its other face. (Round and flat, every
  // point lies well away from the centroid within the loop's plane.)
  std::vector<double> lopsided;
  for (const Vector3& p : loop) {
    const Vector3 away = (p - centre - dot(p - centre, normal) * normal).normalize();
    lopsided.push_back(std::abs(toOpenSpace(p, away, kPlaneReach * radius) - toOpenSpace(p, -away, kPlaneReach * radius)));
  }
  std::nth_element(lopsided.begin(), lopsided.begin() + lopsided.size() / 2, lopsided.end());
  if (lopsided[lopsided.size() / 2] >= kWallCubes * cellSize) return false;
  // Directions spread evenly over the sphere (a Fibonacci lattice); a ray that leaves the grid escapes.
  int escaped = 0;
  for (int k = 0; k < kSpaceRays; k++) {
    const double z = 1 - (2 * k + 1.0) / kSpaceRays, r = std::sqrt(1 - z * z), phi = k * M_PI * (3 - std::sqrt(5.0));
    if (!meetsShell(centre, Vector3{r * std::cos(phi), r * std::sin(phi), z}, INFINITY)) escaped++;
  }
  return escaped <= kEscapeShare * kSpaceRays;
}

bool ExteriorGrid::inside(const Vector3& p) const {
  if (!isfinite(p)) return false;
  const std::array<long, 3> c = cellOf(p);
  for (int a = 0; a < 3; a++)
    if (!(c[a] >= 0 && c[a] < dims[a])) return false;
  return inner[cellIndex(c)];
}

} // namespace cscd
