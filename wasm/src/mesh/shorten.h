#pragma once

#include "cscd/sphere.h"
#include "mesh/patch.h"

#include "geometrycentral/surface/signpost_intrinsic_triangulation.h"

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace cscd {

struct ShortenedLoop {
  // Polyline on the input mesh; closed ones do not repeat the first point at the end.
  std::vector<geometrycentral::surface::SurfacePoint> loop;
  double length = 0;                  // geodesic length
  std::array<double, 2> areas{0, 0};  // the two sides inside the constraint region, smaller first;
                                      // (0, area of the region) when it does not separate the region
  // Why there is no loop: the constraint region could not be built, or the loop shrank to nothing.
  enum class Failure { None, Region, Degenerate } failureKind = Failure::None;
  std::string failure;                // what happened, for the user; empty on success
};

// Shortens a closed loop of vertices of the intrinsic Delaunay triangulation into a geodesic loop by
// intrinsic edge flips (Sharp & Crane 2020, geometry-central's FlipEdgeNetwork). With a sphere, the
// flips run on the patch of triangles whose corners lie inside it, together with the triangles
// around the loop's own vertices: no flip can involve a vertex outside, and the patch boundary stops
// the loop from sliding away. Without one, the patch is the whole surface. The patch is built per
// loop by `patches` (built on `intrinsic`), so the cost follows the size of the constraint region, and
// `intrinsic` is never modified.
// An open path (closed = false, from a boundary extremity to another) is shortened with its two ends
// held: they are minima of the distance along the boundary, where a geodesic from the source meets
// the boundary at a right angle, as a shortest cross-section does.
ShortenedLoop shortenLoop(geometrycentral::surface::SignpostIntrinsicTriangulation& intrinsic, PatchBuilder& patches,
                          const std::vector<size_t>& loopVertices, bool closed, const std::optional<Sphere>& sphere);

// The intrinsic halfedge from a to b (the first one, should the triangulation have parallel edges).
geometrycentral::surface::Halfedge intrinsicHalfedge(geometrycentral::surface::ManifoldSurfaceMesh& mesh, size_t a,
                                                     size_t b);

} // namespace cscd
