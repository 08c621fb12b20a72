#pragma once

#include "cscd/descent.h"

#include "geometrycentral/surface/manifold_surface_mesh.h"

#include <array>
#include <vector>

namespace cscd {

// The approximate loop (cscd/descent.h) on the intrinsic triangulation.
// intrinsicMesh: the (Delaunay, unmodified) intrinsic triangulation whose vertices are the input
// vertices; distance: to the source, per vertex.
TracedLoop traceApproximateLoop(geometrycentral::surface::ManifoldSurfaceMesh& intrinsicMesh,
                                const std::vector<double>& distance, const CutLocus& cutLocus, size_t target,
                                size_t source);

// The open path between two boundary extremities: their descents towards the source, joined where they meet.
TracedLoop traceApproximatePath(geometrycentral::surface::ManifoldSurfaceMesh& intrinsicMesh,
                                const std::vector<double>& distance, std::array<size_t, 2> ends, size_t source);

} // namespace cscd
