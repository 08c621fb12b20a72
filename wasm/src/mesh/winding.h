#pragma once

#include "geometrycentral/surface/vertex_position_geometry.h"

#include <array>
#include <cstdint>
#include <vector>

namespace cscd {

// Generalised winding number of a triangle mesh around a point: 1 inside a closed outward-oriented
// mesh, 0 outside, fractional near holes. A run asks for thousands (every loop centroid, every band
// piece, every tip move), and the exact sum of solid angles is a pass over all triangles: near
// triangles are summed exactly, far clusters of a bounding-volume tree by their dipole term (Barill,
// Dickson, Schmidt, Levin, Jacobson 2018, "Fast winding numbers for soups and clouds", order 1), and
// a value near the threshold 1/2 is summed exactly (winding.cpp): inside/outside answers as exact.
class WindingNumber {
public:
  explicit WindingNumber(geometrycentral::surface::VertexPositionGeometry& geometry);
  double operator()(geometrycentral::Vector3 point) const;

private:
  struct Cluster {
    geometrycentral::Vector3 centre;     // area-weighted centroid of its triangles
    geometrycentral::Vector3 vectorArea; // sum of the triangles' area-weighted normals
    double radius = 0;                   // farthest corner from the centre
    uint32_t begin = 0, end = 0;         // its triangles, a range of `triangles`
    uint32_t left = 0, right = 0;        // children; 0 for a leaf (the root is no one's child)
  };
  uint32_t build(uint32_t begin, uint32_t end);

  std::vector<std::array<geometrycentral::Vector3, 3>> triangles;
  std::vector<Cluster> clusters;
};

} // namespace cscd
