#pragma once

#include "mesh/mesh_arrays.h"

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace cscd {

// Facts about a mesh, computed without assuming it is manifold (mirrors MeshFacts in lib/core/types.ts).
struct MeshFacts {
  size_t vertices = 0;
  size_t faces = 0;
  size_t edges = 0;
  size_t components = 0; // of the faces; vertices used by no face are not counted
  size_t boundaryLoops = 0;
  long eulerCharacteristic = 0; // V - E + F over the vertices used by faces
  std::optional<long> genus;    // sum over components of (2 - chi - b) / 2; empty if not manifold
  bool manifold = false;
  bool consistentlyOriented = false;
  size_t nonManifoldEdges = 0;
  size_t nonManifoldVertices = 0;
  size_t unreferencedVertices = 0;
  size_t degenerateFaces = 0; // a repeated vertex or (numerically) zero area
  std::array<double, 3> bboxMin{};
  std::array<double, 3> bboxMax{};
  double bboxDiagonal = 0;
  double meanEdgeLength = 0;
};

struct MeshCheck {
  MeshFacts facts;
  // Why the mesh cannot be turned into a manifold surface, one sentence each, naming example elements.
  std::vector<std::string> blockingProblems;
  // Connected component of every vertex (-1 for vertices used by no face).
  std::vector<int> vertexComponent;
};

// Throws InputError when the arrays are not a mesh at all (empty, bad lengths, indices out of range,
// non-finite coordinates); otherwise reports facts and what stands in the way of a manifold surface.
MeshCheck checkMesh(const MeshArrays& mesh);

} // namespace cscd
