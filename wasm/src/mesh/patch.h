#pragma once

#include "cscd/sphere.h"

#include "geometrycentral/surface/edge_length_geometry.h"
#include "geometrycentral/surface/signpost_intrinsic_triangulation.h"

#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

namespace cscd {

// A patch's geometry: its edge lengths, and what FlipOut's signpost triangulation asks of its input that
// depends on one face alone (corner angles, face areas, halfedge vectors in the face), copied from the
// whole triangulation's instead of computed again: an arc cosine per corner and a square root per face,
// a third of the time geometry-central spent on the patch's input geometry. The patch's lengths are the
// triangulation's divided by a power of two, so the copies are the numbers it would compute.
class PatchGeometry : public geometrycentral::surface::EdgeLengthGeometry {
public:
  // wholeFace / wholeHalfedge: the triangulation's face of each patch face and halfedge of each patch
  // halfedge (kNone for boundary ones); wholeX: the triangulation's quantities; lengths are divided by
  // `scale`.
  PatchGeometry(geometrycentral::surface::ManifoldSurfaceMesh& mesh, geometrycentral::surface::EdgeData<double>& lengths,
                double scale, std::vector<uint32_t> wholeFace, std::vector<uint32_t> wholeHalfedge,
                const std::vector<double>& wholeCornerAngle, const std::vector<double>& wholeFaceArea,
                const std::vector<geometrycentral::Vector2>& wholeHalfedgeVector);

  static constexpr uint32_t kNone = UINT32_MAX;
  double scale() const { return lengthScale; }
  const std::vector<uint32_t>& wholeFaces() const { return wholeFace; }
  uint32_t wholeHalfedgeOf(geometrycentral::surface::Halfedge patchHalfedge) const { return wholeHalfedge[patchHalfedge.getIndex()]; }

protected:
  void computeCornerAngles() override;
  void computeFaceAreas() override;
  void computeHalfedgeVectorsInFace() override;

private:
  double lengthScale;
  std::vector<uint32_t> wholeFace, wholeHalfedge;
  const std::vector<double>& wholeCornerAngle;
  const std::vector<double>& wholeFaceArea;
  const std::vector<geometrycentral::Vector2>& wholeHalfedgeVector;
};

// A patch of the intrinsic triangulation as a mesh of its own, with the maps back to the triangulation.
// Its edge lengths are the triangulation's divided by the power of two nearest their mean (scale()):
// FlipOut's angle and length tolerances are absolute, and a mesh at 1e30 (or 1e-30) would make it flip
// forever.
struct Patch {
  geometrycentral::surface::ManifoldSurfaceMesh* intrinsicMesh = nullptr;
  std::unique_ptr<geometrycentral::surface::ManifoldSurfaceMesh> mesh;
  std::unique_ptr<PatchGeometry> geometry; // also the faces of the triangulation it was made of, increasing
  std::vector<size_t> cornerHalfedge;      // patch halfedge leaving corner k of patch face i, at 3 i + k

  double scale() const { return geometry->scale(); }
  // The intrinsic halfedge of an interior patch halfedge (a null Halfedge for a boundary one).
  geometrycentral::surface::Halfedge toIntrinsic(geometrycentral::surface::Halfedge patchHalfedge) const;
  // The patch halfedge of an intrinsic halfedge of one of the patch's faces; throws std::out_of_range
  // for a face outside the patch.
  geometrycentral::surface::Halfedge fromIntrinsic(geometrycentral::surface::Halfedge intrinsicHalfedge) const;
};

// Builds patches of one intrinsic triangulation, which must not change afterwards. Its connectivity,
// edge lengths and vertex positions are copied once into flat arrays, so that choosing and building a
// patch costs time in proportion to the patch (and one pass over the vertices for the sphere), not to
// geometry-central's halfedge navigation over the whole triangulation for every loop.
class PatchBuilder {
public:
  // vertexPositions: of the triangulation's input mesh (the same vertices), kept by reference.
  PatchBuilder(geometrycentral::surface::SignpostIntrinsicTriangulation& intrinsic,
               const geometrycentral::surface::VertexData<geometrycentral::Vector3>& vertexPositions);

  // The faces whose corners all lie inside the sphere (every face without one), and the faces around
  // the loop's vertices, so that the loop is a path of the patch through single fans. Increasing.
  std::vector<uint32_t> facesFor(const std::optional<Sphere>& sphere, const std::vector<size_t>& loopVertices);

  // The patch of those faces. A vertex whose faces in the patch form several fans (a bow-tie inside
  // the patch) becomes one patch vertex per fan, so the patch is always a manifold. Throws
  // std::runtime_error when the faces cannot make one (a self-edge, a boundary that does not close).
  Patch build(const std::vector<uint32_t>& faces);

private:
  static constexpr uint32_t kNone = PatchGeometry::kNone;
  geometrycentral::surface::SignpostIntrinsicTriangulation& intrinsic;
  const geometrycentral::surface::VertexData<geometrycentral::Vector3>& positions;
  std::vector<uint32_t> faceHalfedge; // 3 per face, from face.halfedge() on
  std::vector<uint32_t> faceVertex;   // tails of those halfedges
  std::vector<uint32_t> halfedgeFace; // kNone on the boundary
  std::vector<uint8_t> halfedgeCorner; // position of the halfedge in its face
  std::vector<uint32_t> halfedgeTwin;
  std::vector<double> halfedgeLength;
  // The triangulation's quantities that PatchGeometry copies, as geometry-central computes them.
  std::vector<double> cornerAngle;     // per halfedge: the angle at its tail in its face
  std::vector<double> faceArea;
  std::vector<geometrycentral::Vector2> halfedgeVector; // per halfedge, in its face
  // Scratch, sized to the triangulation and left clean after each call.
  std::vector<uint32_t> slot; // per face: its index in the patch being built
  std::vector<char> chosen;   // per face: in the patch being chosen
};

} // namespace cscd
