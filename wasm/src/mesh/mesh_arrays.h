#pragma once

#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <vector>

namespace cscd {

// An indexed triangle mesh as it crosses the WASM boundary: xyz per vertex, three indices per face.
struct MeshArrays {
  std::vector<double> positions;
  std::vector<uint32_t> triangles;

  size_t vertexCount() const { return positions.size() / 3; }
  size_t faceCount() const { return triangles.size() / 3; }
};

// Input the core cannot work with; the message is written for the user.
class InputError : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

} // namespace cscd
