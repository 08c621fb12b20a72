#pragma once

#include "mesh/cut_locus.h"

#include "geometrycentral/surface/manifold_surface_mesh.h"

#include <string>
#include <vector>

namespace cscd {

// The approximate loop of paper Sec. 4.1.4 / Alg. 3: from the target, two steepest-descent paths of
// the distance towards the source, started on the two sides of the cut locus and cut where they meet.
struct TracedLoop {
  std::vector<size_t> firstPath;  // target ... meeting vertex (vertex indices)
  std::vector<size_t> secondPath; // target ... meeting vertex
  std::vector<size_t> loop;       // closed: target, first path, meeting vertex, second path back (target not repeated)
  std::string failure;            // why no loop could be traced; empty on success
};

// intrinsicMesh: the (Delaunay, unmodified) intrinsic triangulation whose vertices are the input
// vertices; distance: to the source, per vertex.
TracedLoop traceApproximateLoop(geometrycentral::surface::ManifoldSurfaceMesh& intrinsicMesh,
                                const std::vector<double>& distance, const CutLocus& cutLocus, size_t target,
                                size_t source);

} // namespace cscd
