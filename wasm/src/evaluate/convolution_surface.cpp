#include "evaluate/convolution_surface.h"

#include "mesh/mesh_arrays.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <unordered_map>

namespace cscd {
namespace {

constexpr double kappa = 8;
// Beyond 1.6 radii a kernel adds less than e^-50 of the surface value: nothing.
constexpr double support = 1.6;
// Sum of Gaussians 1.5 standard deviations apart along the axis: ripple below 1e-3 of the field.
constexpr double sampleSpacing = 1.5 / kappa;
// Field value written where no kernel reaches: as far outside as the support.
constexpr float outside = float(support - 1);
constexpr size_t maxGridPoints = 40'000'000;

// Radii below one cell are raised to it: a thinner tube cannot be polygonised on the grid.
double effectiveRadius(double radius, double cell) { return std::max(radius, cell); }

} // namespace

SampleGrid reconstructionGrid(const SkeletonCurves& skeleton, const Vector3& meshLower, const Vector3& meshUpper) {
  double diagonal = norm(meshUpper - meshLower);
  std::vector<double> radii = skeleton.radii;
  size_t tenth = radii.size() / 10;
  std::nth_element(radii.begin(), radii.begin() + tenth, radii.end());
  double cell = std::clamp(radii[tenth] / 3, diagonal / 400, diagonal / 100);

  Vector3 clipLower = meshLower - Vector3{1, 1, 1} * (diagonal / 2);
  Vector3 clipUpper = meshUpper + Vector3{1, 1, 1} * (diagonal / 2);
  double inf = std::numeric_limits<double>::infinity();
  Vector3 lower{inf, inf, inf}, upper{-inf, -inf, -inf};
  for (size_t i = 0; i < skeleton.nodes.size(); i++) {
    double reach = support * effectiveRadius(skeleton.radii[i], cell) + 2 * cell;
    for (int axis = 0; axis < 3; axis++) {
      lower[axis] = std::max(std::min(lower[axis], skeleton.nodes[i][axis] - reach), clipLower[axis]);
      upper[axis] = std::min(std::max(upper[axis], skeleton.nodes[i][axis] + reach), clipUpper[axis]);
    }
  }
  SampleGrid grid;
  for (;;) {
    grid.origin = lower;
    grid.cell = cell;
    for (int axis = 0; axis < 3; axis++)
      grid.dims[axis] = size_t(std::max(2.0, std::ceil((upper[axis] - lower[axis]) / cell) + 1));
    if (grid.points() <= maxGridPoints) return grid;
    cell *= 1.25; // only for long thin boxes at the finest cell: keeps memory bounded
  }
}

namespace {

// F (see the header) accumulated on the grid, kernel by kernel, each only inside its support.
std::vector<float> convolutionField(const SkeletonCurves& skeleton, const SampleGrid& grid) {
  std::vector<float> field(grid.points(), 0.0f);
  const double cell = grid.cell;
  const double halfKappa2 = kappa * kappa / 2;

  // Adds weight * exp(kappa^2 (1 - |p - center|^2 / rho^2) / 2) to every grid point p within support.
  auto splat = [&](const Vector3& center, double rho, double weight) {
    double reach = support * rho;
    Vector3 local = (center - grid.origin) / cell;
    auto range = [&](int axis, double halfWidth) {
      long low = long(std::ceil(local[axis] - halfWidth / cell));
      long high = long(std::floor(local[axis] + halfWidth / cell));
      return std::make_pair(std::max(low, 0L), std::min(high, long(grid.dims[axis]) - 1));
    };
    double logWeight = std::log(weight);
    auto [i0, i1] = range(0, reach);
    for (long i = i0; i <= i1; i++) {
      double dx = (grid.origin.x + i * cell) - center.x;
      double restX = reach * reach - dx * dx;
      if (restX < 0) continue;
      auto [j0, j1] = range(1, std::sqrt(restX));
      for (long j = j0; j <= j1; j++) {
        double dy = (grid.origin.y + j * cell) - center.y;
        double restY = restX - dy * dy;
        if (restY < 0) continue;
        auto [k0, k1] = range(2, std::sqrt(restY));
        size_t row = (size_t(i) * grid.dims[1] + size_t(j)) * grid.dims[2];
        for (long k = k0; k <= k1; k++) {
          double dz = (grid.origin.z + k * cell) - center.z;
          double x2 = (dx * dx + dy * dy + dz * dz) / (rho * rho);
          field[row + size_t(k)] += float(std::exp(logWeight + halfKappa2 * (1 - x2)));
        }
      }
    }
  };

  std::vector<size_t> degree(skeleton.nodes.size(), 0);
  const double lineNormalisation = kappa / std::sqrt(2 * M_PI);
  for (const auto& [a, b] : skeleton.edges) {
    degree[a]++;
    degree[b]++;
    double ra = effectiveRadius(skeleton.radii[a], cell), rb = effectiveRadius(skeleton.radii[b], cell);
    double length = norm(skeleton.nodes[b] - skeleton.nodes[a]);
    size_t samples = size_t(std::ceil(length / (sampleSpacing * std::min(ra, rb))));
    if (samples == 0) continue; // a = b: the node's ball comes from its other edges, or below
    double dt = length / double(samples);
    for (size_t s = 0; s < samples; s++) {
      double t = (double(s) + 0.5) / double(samples); // midpoint rule
      double rho = (1 - t) * ra + t * rb;
      splat((1 - t) * skeleton.nodes[a] + t * skeleton.nodes[b], rho, lineNormalisation * dt / rho);
    }
  }
  // A node on no segment is a ball: F = 1 at distance rho.
  for (size_t i = 0; i < skeleton.nodes.size(); i++)
    if (degree[i] == 0) splat(skeleton.nodes[i], effectiveRadius(skeleton.radii[i], cell), 1.0);

  // The same level set as a distance-like field: negative inside, 0 on the surface.
  for (float& value : field)
    value = value > 0 ? float(std::sqrt(std::max(0.0, 1 - std::log(double(value)) / halfKappa2)) - 1) : outside;
  return field;
}

// Kuhn's six tetrahedra of the unit cube: corners are bit masks (x = 1, y = 2, z = 4), each tetrahedron
// walks from corner 0 to corner 7 adding one axis at a time, so neighbouring cubes cut their shared
// faces along the same diagonal and the surface has no cracks.
constexpr int tetrahedra[6][4] = {{0, 1, 3, 7}, {0, 1, 5, 7}, {0, 2, 3, 7}, {0, 2, 6, 7}, {0, 4, 5, 7}, {0, 4, 6, 7}};

} // namespace

TriangleMesh convolutionSurface(const SkeletonCurves& skeleton, const SampleGrid& grid) {
  std::vector<float> field = convolutionField(skeleton, grid);
  const auto& dims = grid.dims;
  auto pointIndex = [&](size_t i, size_t j, size_t k) { return (i * dims[1] + j) * dims[2] + k; };

  TriangleMesh mesh;
  // One output vertex per crossed grid edge, shared by every tetrahedron around it. Tetrahedron edges
  // join corners u and v with u a subset of v, so (grid point of u, v ^ u) names the edge uniquely.
  std::unordered_map<uint64_t, uint32_t> edgeVertex;
  size_t corner[8];
  Vector3 position[8];
  float value[8];
  auto vertexOn = [&](int u, int v) {
    uint64_t key = uint64_t(corner[u]) * 7 + uint64_t((u ^ v) - 1);
    auto [it, inserted] = edgeVertex.try_emplace(key, uint32_t(mesh.vertices.size()));
    if (inserted) {
      double t = double(value[u]) / (double(value[u]) - double(value[v]));
      mesh.vertices.push_back((1 - t) * position[u] + t * position[v]);
    }
    return it->second;
  };
  // Triangle (a, b, c) facing away from the inside corners.
  auto emit = [&](uint32_t a, uint32_t b, uint32_t c, const Vector3& outward) {
    const auto& v = mesh.vertices;
    if (dot(cross(v[b] - v[a], v[c] - v[a]), outward) < 0) std::swap(b, c);
    mesh.triangles.push_back({a, b, c});
  };

  for (size_t i = 0; i + 1 < dims[0]; i++)
    for (size_t j = 0; j + 1 < dims[1]; j++)
      for (size_t k = 0; k + 1 < dims[2]; k++) {
        bool anyInside = false, anyOutside = false;
        for (int c = 0; c < 8; c++) {
          size_t ci = i + (c & 1), cj = j + ((c >> 1) & 1), ck = k + ((c >> 2) & 1);
          corner[c] = pointIndex(ci, cj, ck);
          value[c] = field[corner[c]];
          (value[c] < 0 ? anyInside : anyOutside) = true;
        }
        if (!anyInside || !anyOutside) continue;
        for (int c = 0; c < 8; c++)
          position[c] = grid.origin + grid.cell * Vector3{double(i + (c & 1)), double(j + ((c >> 1) & 1)), double(k + ((c >> 2) & 1))};

        for (const auto& tet : tetrahedra) {
          int inside[4], outsideCorners[4], nIn = 0, nOut = 0;
          for (int c : tet) (value[c] < 0 ? inside[nIn++] : outsideCorners[nOut++]) = c;
          if (nIn == 0 || nOut == 0) continue;
          Vector3 outward{0, 0, 0};
          for (int o = 0; o < nOut; o++) outward += position[outsideCorners[o]] / double(nOut);
          for (int n = 0; n < nIn; n++) outward -= position[inside[n]] / double(nIn);
          // Edges are named from the smaller corner mask (the subset) to the larger.
          auto cut = [&](int a, int b) { return a < b ? vertexOn(a, b) : vertexOn(b, a); };
          if (nIn == 1) {
            emit(cut(inside[0], outsideCorners[0]), cut(inside[0], outsideCorners[1]), cut(inside[0], outsideCorners[2]), outward);
          } else if (nIn == 3) {
            emit(cut(outsideCorners[0], inside[0]), cut(outsideCorners[0], inside[1]), cut(outsideCorners[0], inside[2]), outward);
          } else {
            uint32_t a = cut(inside[0], outsideCorners[0]), b = cut(inside[0], outsideCorners[1]);
            uint32_t c = cut(inside[1], outsideCorners[1]), d = cut(inside[1], outsideCorners[0]);
            emit(a, b, c, outward);
            emit(a, c, d, outward);
          }
        }
      }
  return mesh;
}

} // namespace cscd
