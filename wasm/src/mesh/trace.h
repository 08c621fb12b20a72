#pragma once

#include "mesh/cut_locus.h"

#include "geometrycentral/surface/manifold_surface_mesh.h"

#include <array>
#include <string>
#include <vector>

namespace cscd {

// The approximate loop of paper Sec. 4.1.4 / Alg. 3: from the target, two steepest-descent paths of
// the distance towards the source, started on the two sides of the cut locus and cut where they meet.
// On a surface with boundary it can be an open path instead: the two descents start at two boundary
// extremities (mesh/boundary.h).
struct TracedLoop {
  std::vector<size_t> firstPath;  // target (or first boundary end) ... meeting vertex (vertex indices)
  std::vector<size_t> secondPath; // target (or second boundary end) ... meeting vertex
  // Closed: target, first path, meeting vertex, second path back (target not repeated).
  // Open: first end, first path, meeting vertex, second path back to the second end.
  std::vector<size_t> loop;
  bool closed = true;
  std::string failure; // why no loop could be traced; empty on success
};

// intrinsicMesh: the (Delaunay, unmodified) intrinsic triangulation whose vertices are the input
// vertices; distance: to the source, per vertex.
TracedLoop traceApproximateLoop(geometrycentral::surface::ManifoldSurfaceMesh& intrinsicMesh,
                                const std::vector<double>& distance, const CutLocus& cutLocus, size_t target,
                                size_t source);

// The open path between two boundary extremities: their descents towards the source, joined where they meet.
TracedLoop traceApproximatePath(geometrycentral::surface::ManifoldSurfaceMesh& intrinsicMesh,
                                const std::vector<double>& distance, std::array<size_t, 2> ends, size_t source);

} // namespace cscd
