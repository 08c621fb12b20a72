#pragma once

#include "cscd/errors.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace cscd {

// An indexed triangle mesh as it crosses the WASM boundary: xyz per vertex, three indices per face.
struct MeshArrays {
  std::vector<double> positions;
  std::vector<uint32_t> triangles;

  size_t vertexCount() const { return positions.size() / 3; }
  size_t faceCount() const { return triangles.size() / 3; }
};

} // namespace cscd
