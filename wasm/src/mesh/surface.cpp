#include "mesh/surface.h"

#include "mesh/boundary.h"

using namespace geometrycentral;
using namespace geometrycentral::surface;

namespace cscd {

Surface::Surface(const MeshArrays& arrays) : check(checkMesh(arrays)) {
  if (!check.blockingProblems.empty())
    throw InputError("the mesh is not a manifold surface: " + check.blockingProblems.front());

  const size_t nV = arrays.vertexCount(), nF = arrays.faceCount();
  std::vector<std::vector<size_t>> polygons(nF);
  for (size_t f = 0; f < nF; f++)
    polygons[f] = {arrays.triangles[3 * f], arrays.triangles[3 * f + 1], arrays.triangles[3 * f + 2]};
  inputMesh = std::make_unique<ManifoldSurfaceMesh>(polygons);
  boundary = cscd::boundaryLoops(*inputMesh);

  VertexData<Vector3> positions(*inputMesh);
  for (size_t v = 0; v < nV; v++)
    positions[v] = Vector3{arrays.positions[3 * v], arrays.positions[3 * v + 1], arrays.positions[3 * v + 2]};
  inputGeometry = std::make_unique<VertexPositionGeometry>(*inputMesh, positions);

  // The intrinsic Delaunay triangulation gives well-shaped triangles on any input triangulation without
  // moving the surface: it is what makes the distances (and later the loops) robust to bad meshing.
  intrinsicTriangulation = std::make_unique<SignpostIntrinsicTriangulation>(*inputMesh, *inputGeometry);
  intrinsicTriangulation->flipToDelaunay();

  geodesicSolver = std::make_unique<Geodesics>(*intrinsicTriangulation, check.vertexComponent);
}

const CutLocusSolver& Surface::cutLocusSolver() {
  if (!cutLocus) cutLocus = std::make_unique<CutLocusSolver>(*intrinsicTriangulation);
  return *cutLocus;
}

PatchBuilder& Surface::patchBuilder() {
  if (!patches) patches = std::make_unique<PatchBuilder>(*intrinsicTriangulation, inputGeometry->vertexPositions);
  return *patches;
}

const WindingNumber& Surface::winding() {
  if (!windingNumber) windingNumber = std::make_unique<WindingNumber>(*inputGeometry);
  return *windingNumber;
}

} // namespace cscd
