#pragma once

#include "geometrycentral/utilities/vector3.h"

#include <array>
#include <cstdint>
#include <vector>

namespace cscd {

using geometrycentral::Vector3;

// A curve skeleton as the evaluation sees it: nodes with a radius each, segments between them.
struct SkeletonCurves {
  std::vector<Vector3> nodes;
  std::vector<std::array<uint32_t, 2>> edges;
  std::vector<double> radii;
};

struct TriangleMesh {
  std::vector<Vector3> vertices;
  std::vector<std::array<uint32_t, 3>> triangles;
};

// A regular grid: points origin + cell * (i, j, k) for 0 <= i < dims[0] etc.
struct SampleGrid {
  Vector3 origin{0, 0, 0};
  double cell = 0;
  std::array<size_t, 3> dims{0, 0, 0};

  size_t points() const { return dims[0] * dims[1] * dims[2]; }
};

// The grid the surface is polygonised on. Its cell is a third of the 10th percentile of the radii
// (so thin branches are at least six cells across), bounded to [diagonal / 400, diagonal / 100] of the
// mesh's bounding box; it covers the skeleton's tubes, clipped to the mesh box grown by half its
// diagonal (a stray node of another tool's skeleton must not blow up the grid).
SampleGrid reconstructionGrid(const SkeletonCurves& skeleton, const Vector3& meshLower, const Vector3& meshUpper);

// The convolution surface of the skeleton, polygonised on the grid.
//
// Kernel: a Gaussian in the distance divided by the local radius, integrated along each segment with
// the radius interpolated linearly and the integrand divided by that radius (the scale-invariant
// integral surfaces of Zanni et al. 2013, with the Gaussian kernel of Bloomenthal & Shoemake 1991):
//   F(p) = C * sum over segments of  integral  exp(-kappa^2 |p - c(t)|^2 / (2 rho(t)^2)) / rho(t) dt,
// with C chosen so that F = 1 at distance rho from an infinite segment of constant radius rho: the
// surface F = 1 of a tube is exactly the tube. kappa = 8 makes the kernel sharp, so an end reaches
// 0.9 of its radius past its node (measured on a capsule; a wide kernel stops at a quarter of it) and
// junctions barely bulge. Isolated
// nodes are balls. Marching cubes runs on sqrt(1 - 2 ln(F) / kappa^2) - 1, the same level set written
// as a distance-like field (the distance to the axis over rho for a tube), so the linear
// interpolation along grid edges is accurate; each cube is cut into six tetrahedra (marching
// tetrahedra), which needs no case table and never leaves holes at ambiguous cubes.
TriangleMesh convolutionSurface(const SkeletonCurves& skeleton, const SampleGrid& grid);

} // namespace cscd
