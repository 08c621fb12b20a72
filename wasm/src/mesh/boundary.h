#pragma once

#include "cscd/options.h"
#include "mesh/winding.h"

#include "geometrycentral/surface/manifold_surface_mesh.h"
#include "geometrycentral/surface/vertex_position_geometry.h"

#include <array>
#include <vector>

namespace cscd {

// Separator extremities on the boundary (paper Sec. 3.2 and App. "Results on Meshes with Holes"): on
// a surface with boundary a local separator can be a path that ends on the boundary, at two points
// where the gradients of the distance from the source point in opposite directions (they cancel, as
// the gradients arriving from both sides of a cut locus do).
//
// Choices where the paper is silent, for several boundaries: both ends on the *same* boundary loop
// always qualify: such a path separates the surface (a chord of a disk does). Ends on two different
// loops (the paper's appendix: "could act as local separator too") qualify only where the surface is a
// sheet rather than the wall of a solid (sheetAround): across the bar of a flat frame or a washer they
// are the only separators, while on a closed shape with small holes (torus_two_holes_open) such a
// path would cut the tube between two holes, and the loop around the tube comes from the cut locus.

// The boundary loops of the mesh, each as its vertices in order.
std::vector<std::vector<size_t>> boundaryLoops(geometrycentral::surface::ManifoldSurfaceMesh& mesh);

struct BoundaryExtremity {
  size_t vertex;
  size_t loop;                       // index into the boundary loops
  geometrycentral::Vector3 gradient; // unit gradient of the distance (tangent to the surface)
};

// Boundary vertices where the distance has a local minimum along their loop, over `window` of arc
// length on either side (heat distances ripple by a fraction of an edge along a boundary): there the
// gradient of the distance is normal to the boundary; it is averaged over the same window. Vertices
// closer to the source than `window` are left out: the heat method smooths the distance over a few
// edges, so directions there are unreliable.
std::vector<BoundaryExtremity> boundaryExtremities(const std::vector<std::vector<size_t>>& loops,
                                                   geometrycentral::surface::VertexPositionGeometry& geometry,
                                                   const std::vector<double>& distance, double window);

struct BoundaryPair {
  std::array<size_t, 2> ends;
  double key; // targetKey of the farther end
};

// The gradients of a pair "cancel" when their sum is shorter than one, i.e. they are more than 120
// degrees apart: across a strip they are opposite, across a tapering sheet (a leaf, a wedge of up to
// 60 degrees) nearly so, while at a square corner of a sheet (90 degrees) they are not.
constexpr double kMaxGradientSum = 1.0;

// Pairs of extremities whose unit gradients cancel, on one loop (or on any two with `acrossLoops`),
// nearest first.
std::vector<BoundaryPair> opposedExtremities(const std::vector<BoundaryExtremity>& extremities,
                                             geometrycentral::surface::VertexPositionGeometry& geometry,
                                             const std::vector<double>& distance, size_t source, TargetMode mode,
                                             bool acrossLoops);

// Whether the surface at a vertex is a sheet rather than the wall of a solid. The generalised winding
// number jumps by one across any surface; beside the wall of a solid (closed, or with small holes) it
// goes from about 0 outside to about 1 inside, beside a sheet from about -1/2 to 1/2. It is taken at
// `offset` along the vertex normal on either side; a sum below 1/2 is a sheet.
bool sheetAround(geometrycentral::surface::VertexPositionGeometry& geometry, const WindingNumber& winding, size_t vertex,
                 double offset);

} // namespace cscd
