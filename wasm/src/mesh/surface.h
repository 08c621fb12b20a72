#pragma once

#include "mesh/cut_locus.h"
#include "mesh/geodesics.h"
#include "mesh/mesh_check.h"
#include "mesh/patch.h"
#include "mesh/winding.h"

#include "geometrycentral/surface/signpost_intrinsic_triangulation.h"
#include "geometrycentral/surface/manifold_surface_mesh.h"
#include "geometrycentral/surface/vertex_position_geometry.h"

#include <memory>

namespace cscd {

// Everything CSCD-M keeps per input mesh: the halfedge mesh, its intrinsic Delaunay triangulation and
// the prefactored geodesic solver. Built once, then queried for many sources.
class Surface {
public:
  // Throws InputError naming the first problem when the mesh is not a manifold surface.
  explicit Surface(const MeshArrays& arrays);

  const MeshFacts& facts() const { return check.facts; }
  size_t vertexCount() const { return check.facts.vertices; }
  size_t faceCount() const { return check.facts.faces; }
  // Connected component of every vertex.
  const std::vector<int>& vertexComponent() const { return check.vertexComponent; }

  geometrycentral::surface::ManifoldSurfaceMesh& mesh() { return *inputMesh; }
  geometrycentral::surface::VertexPositionGeometry& geometry() { return *inputGeometry; }
  geometrycentral::surface::SignpostIntrinsicTriangulation& intrinsic() { return *intrinsicTriangulation; }
  Geodesics& geodesics() { return *geodesicSolver; }
  // The boundary loops, each as its vertices in order (mesh/boundary.h).
  const std::vector<std::vector<size_t>>& boundaryLoops() const { return boundary; }
  // Per-mesh data of the cut-locus detector, built on first use (not every caller needs it).
  const CutLocusSolver& cutLocusSolver();
  // Builder of the intrinsic triangulation's patches that loops are shortened on, built on first use.
  PatchBuilder& patchBuilder();
  // Winding numbers of the input mesh (mesh/winding.h), built on first use.
  const WindingNumber& winding();

private:
  MeshCheck check;
  std::unique_ptr<geometrycentral::surface::ManifoldSurfaceMesh> inputMesh;
  std::unique_ptr<geometrycentral::surface::VertexPositionGeometry> inputGeometry;
  std::unique_ptr<geometrycentral::surface::SignpostIntrinsicTriangulation> intrinsicTriangulation;
  std::unique_ptr<Geodesics> geodesicSolver;
  std::unique_ptr<CutLocusSolver> cutLocus;
  std::unique_ptr<PatchBuilder> patches;
  std::unique_ptr<WindingNumber> windingNumber;
  std::vector<std::vector<size_t>> boundary;
};

} // namespace cscd
