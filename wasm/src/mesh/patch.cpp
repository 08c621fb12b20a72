#include "mesh/patch.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

using namespace geometrycentral;
using namespace geometrycentral::surface;

namespace cscd {
namespace {

// geometry-central keeps its constructor from halfedge arrays for its own copies.
struct ArrayMesh : ManifoldSurfaceMesh {
  ArrayMesh(const std::vector<size_t>& heNext, const std::vector<size_t>& heVertex, const std::vector<size_t>& heFace,
            const std::vector<size_t>& vHalfedge, const std::vector<size_t>& fHalfedge, size_t nBoundaryLoops)
      : ManifoldSurfaceMesh(heNext, heVertex, heFace, vHalfedge, fHalfedge, nBoundaryLoops) {}
};

} // namespace

PatchGeometry::PatchGeometry(ManifoldSurfaceMesh& mesh, EdgeData<double>& lengths, double scale_,
                             std::vector<uint32_t> wholeFace_, std::vector<uint32_t> wholeHalfedge_,
                             const std::vector<double>& wholeCornerAngle_, const std::vector<double>& wholeFaceArea_,
                             const std::vector<Vector2>& wholeHalfedgeVector_)
    : EdgeLengthGeometry(mesh, lengths), lengthScale(scale_), wholeFace(std::move(wholeFace_)), wholeHalfedge(std::move(wholeHalfedge_)),
      wholeCornerAngle(wholeCornerAngle_), wholeFaceArea(wholeFaceArea_), wholeHalfedgeVector(wholeHalfedgeVector_) {}

void PatchGeometry::computeCornerAngles() {
  cornerAngles = CornerData<double>(mesh);
  for (Corner c : mesh.corners()) cornerAngles[c] = wholeCornerAngle[wholeHalfedge[c.halfedge().getIndex()]];
}

void PatchGeometry::computeFaceAreas() {
  faceAreas = FaceData<double>(mesh);
  for (Face f : mesh.faces()) faceAreas[f] = wholeFaceArea[wholeFace[f.getIndex()]] / (lengthScale * lengthScale);
}

void PatchGeometry::computeHalfedgeVectorsInFace() {
  halfedgeVectorsInFace = HalfedgeData<Vector2>(mesh, Vector2::undefined());
  for (Halfedge h : mesh.interiorHalfedges()) halfedgeVectorsInFace[h] = wholeHalfedgeVector[wholeHalfedge[h.getIndex()]] / lengthScale;
}

Halfedge Patch::toIntrinsic(Halfedge patchHalfedge) const {
  const uint32_t whole = geometry->wholeHalfedgeOf(patchHalfedge);
  return whole == PatchGeometry::kNone ? Halfedge() : intrinsicMesh->halfedge(whole);
}

Halfedge Patch::fromIntrinsic(Halfedge intrinsicHalfedge) const {
  const std::vector<uint32_t>& faces = geometry->wholeFaces();
  const uint32_t face = uint32_t(intrinsicHalfedge.face().getIndex());
  auto at = std::lower_bound(faces.begin(), faces.end(), face);
  if (at == faces.end() || *at != face) throw std::out_of_range("patch: a halfedge of a face outside the patch");
  Halfedge first = intrinsicHalfedge.face().halfedge();
  const size_t k = intrinsicHalfedge == first ? 0 : intrinsicHalfedge == first.next() ? 1 : 2;
  return mesh->halfedge(cornerHalfedge[3 * size_t(at - faces.begin()) + k]);
}

PatchBuilder::PatchBuilder(SignpostIntrinsicTriangulation& intrinsic_, const VertexData<Vector3>& vertexPositions)
    : intrinsic(intrinsic_), positions(vertexPositions) {
  ManifoldSurfaceMesh& mesh = *intrinsic.intrinsicMesh;
  intrinsic.requireEdgeLengths();
  halfedgeFace.assign(mesh.nHalfedges(), kNone);
  halfedgeCorner.assign(mesh.nHalfedges(), 0);
  halfedgeTwin.resize(mesh.nHalfedges());
  halfedgeLength.resize(mesh.nHalfedges());
  for (Halfedge h : mesh.halfedges()) {
    halfedgeTwin[h.getIndex()] = uint32_t(h.twin().getIndex());
    halfedgeLength[h.getIndex()] = intrinsic.edgeLengths[h.edge()];
  }
  EdgeLengthGeometry whole(mesh, intrinsic.edgeLengths);
  whole.requireCornerAngles();
  whole.requireFaceAreas();
  whole.requireHalfedgeVectorsInFace();
  cornerAngle.resize(mesh.nHalfedges());
  halfedgeVector.resize(mesh.nHalfedges());
  faceArea.resize(mesh.nFaces());
  for (Face f : mesh.faces()) {
    faceArea[f.getIndex()] = whole.faceAreas[f];
    uint8_t k = 0;
    for (Halfedge h : f.adjacentHalfedges()) {
      faceHalfedge.push_back(uint32_t(h.getIndex()));
      faceVertex.push_back(uint32_t(h.tailVertex().getIndex()));
      halfedgeFace[h.getIndex()] = uint32_t(f.getIndex());
      halfedgeCorner[h.getIndex()] = k++;
      cornerAngle[h.getIndex()] = whole.cornerAngles[h.corner()];
      halfedgeVector[h.getIndex()] = whole.halfedgeVectorsInFace[h];
    }
  }
  slot.assign(mesh.nFaces(), kNone);
  chosen.assign(mesh.nFaces(), 0);
}

std::vector<uint32_t> PatchBuilder::facesFor(const std::optional<Sphere>& sphere, const std::vector<size_t>& loopVertices) {
  const size_t nFaces = slot.size();
  std::vector<uint32_t> faces;
  if (!sphere) {
    faces.resize(nFaces);
    for (size_t f = 0; f < nFaces; f++) faces[f] = uint32_t(f);
    return faces;
  }
  const double r2 = sphere->radius * sphere->radius * (1 + 1e-9);
  // Each vertex tested once (not once per face around it).
  std::vector<char> inside(positions.size());
  for (size_t v = 0; v < inside.size(); v++) inside[v] = norm2(positions[v] - sphere->center) <= r2;
  for (size_t f = 0; f < nFaces; f++)
    chosen[f] = inside[faceVertex[3 * f]] && inside[faceVertex[3 * f + 1]] && inside[faceVertex[3 * f + 2]];
  ManifoldSurfaceMesh& mesh = *intrinsic.intrinsicMesh;
  for (size_t v : loopVertices)
    for (Face f : mesh.vertex(v).adjacentFaces()) chosen[f.getIndex()] = 1;
  for (size_t f = 0; f < nFaces; f++)
    if (chosen[f]) {
      faces.push_back(uint32_t(f));
      chosen[f] = 0;
    }
  return faces;
}

Patch PatchBuilder::build(const std::vector<uint32_t>& faces) {
  const size_t nFaces = faces.size();
  for (size_t i = 0; i < nFaces; i++) slot[faces[i]] = uint32_t(i);
  struct ClearSlots { // the scratch is left clean whichever way build() ends
    std::vector<uint32_t>& slot;
    const std::vector<uint32_t>& faces;
    ~ClearSlots() {
      for (uint32_t f : faces) slot[f] = kNone;
    }
  } clear{slot, faces};

  // Corner of intrinsic halfedge h (of a patch face): the corner at h's tail in h's face.
  auto corner = [&](uint32_t h) { return 3 * size_t(slot[halfedgeFace[h]]) + halfedgeCorner[h]; };
  // The twin of h when its face is in the patch, else kNone.
  auto twinInPatch = [&](uint32_t h) {
    const uint32_t t = halfedgeTwin[h];
    return halfedgeFace[t] != kNone && slot[halfedgeFace[t]] != kNone ? t : kNone;
  };
  // The corner of the same vertex across the edge that leaves (arrives at) corner c's vertex in c's
  // face, when that edge's other face is in the patch; else INVALID_IND. A fan is a path or a cycle
  // of corners linked so.
  auto cornerAcrossOut = [&](size_t c) {
    const uint32_t t = twinInPatch(faceHalfedge[3 * size_t(faces[c / 3]) + c % 3]);
    return t == kNone ? INVALID_IND : corner(faceHalfedge[3 * size_t(halfedgeFace[t]) + (halfedgeCorner[t] + 1) % 3]);
  };
  auto cornerAcrossIn = [&](size_t c) {
    const uint32_t t = twinInPatch(faceHalfedge[3 * size_t(faces[c / 3]) + (c % 3 + 2) % 3]);
    return t == kNone ? INVALID_IND : corner(t);
  };
  // One patch vertex per fan, numbered in the order of the fans' first corners.
  std::vector<size_t> cornerVertex(3 * nFaces, INVALID_IND);
  size_t nPatchVertices = 0;
  for (size_t c = 0; c < 3 * nFaces; c++) {
    if (cornerVertex[c] != INVALID_IND) continue;
    const size_t vertex = nPatchVertices++;
    cornerVertex[c] = vertex;
    for (size_t d = cornerAcrossOut(c); d != INVALID_IND && cornerVertex[d] == INVALID_IND; d = cornerAcrossOut(d)) cornerVertex[d] = vertex;
    for (size_t d = cornerAcrossIn(c); d != INVALID_IND && cornerVertex[d] == INVALID_IND; d = cornerAcrossIn(d)) cornerVertex[d] = vertex;
  }

  // The halfedge arrays, numbered as ManifoldSurfaceMesh(polygons, twins) numbers them (face by face,
  // a new edge when the twin is not made yet, then the boundary loops), built directly: that
  // constructor's hash map of twins was most of the time spent on a patch. Twins come from the
  // triangulation, which can have several edges between the same two vertices.
  std::vector<size_t> heNext, heVertex, heFace, vHalfedge(nPatchVertices, INVALID_IND), fHalfedge(nFaces, INVALID_IND);
  std::vector<size_t> cornerHalfedge(3 * nFaces, INVALID_IND); // patch halfedge leaving each corner
  for (auto* array : {&heNext, &heVertex, &heFace}) array->reserve(6 * nFaces);
  for (size_t i = 0; i < nFaces; i++) {
    for (size_t k = 0; k < 3; k++) {
      const size_t tail = cornerVertex[3 * i + k], tip = cornerVertex[3 * i + (k + 1) % 3];
      if (tail == tip) throw std::runtime_error("patch: a self-edge");
      const uint32_t t = twinInPatch(faceHalfedge[3 * size_t(faces[i]) + k]);
      const size_t twin = t != kNone ? cornerHalfedge[corner(t)] : INVALID_IND;
      size_t he;
      if (twin == INVALID_IND) {
        he = heNext.size();
        heNext.resize(he + 2, INVALID_IND);
        heFace.resize(he + 2, INVALID_IND);
        heVertex.push_back(tail);
        heVertex.push_back(tip);
      } else {
        he = twin ^ 1;
      }
      cornerHalfedge[3 * i + k] = he;
      heFace[he] = i;
      vHalfedge[tail] = he;
      if (k == 0) fHalfedge[i] = he;
      else heNext[cornerHalfedge[3 * i + k - 1]] = he;
    }
    heNext[cornerHalfedge[3 * i + 2]] = cornerHalfedge[3 * i];
  }
  // Boundary loops, walked as the constructor walks them.
  size_t nBoundaryLoops = 0;
  for (size_t first = 0; first < heNext.size(); first++) {
    if (heFace[first] != INVALID_IND) continue;
    const size_t loop = nFaces + nBoundaryLoops++;
    fHalfedge.push_back(first);
    size_t current = first, steps = 0;
    do {
      heFace[current] = loop;
      vHalfedge[heVertex[current ^ 1]] = current ^ 1;
      size_t previous = current;
      current = heNext[current ^ 1] ^ 1;
      while (heFace[current] != INVALID_IND && current != first) current = heNext[current] ^ 1;
      heNext[current] = previous;
      if (++steps > heNext.size()) throw std::runtime_error("patch: a boundary that does not close");
    } while (current != first);
  }

  Patch patch;
  patch.intrinsicMesh = intrinsic.intrinsicMesh.get();
  patch.mesh = std::make_unique<ArrayMesh>(heNext, heVertex, heFace, vHalfedge, fHalfedge, nBoundaryLoops);
  EdgeData<double> lengths(*patch.mesh, 0.);
  std::vector<uint32_t> wholeHalfedge(patch.mesh->nHalfedges(), kNone);
  for (size_t c = 0; c < 3 * nFaces; c++) {
    const uint32_t ih = faceHalfedge[3 * size_t(faces[c / 3]) + c % 3];
    wholeHalfedge[cornerHalfedge[c]] = ih;
    lengths[patch.mesh->halfedge(cornerHalfedge[c]).edge()] = halfedgeLength[ih];
  }
  double sum = 0;
  for (Edge e : patch.mesh->edges()) sum += lengths[e];
  // A power of two, so that the patch's lengths, angles and areas are the triangulation's scaled exactly.
  const double scale = sum > 0 ? std::exp2(std::round(std::log2(sum / patch.mesh->nEdges()))) : 1.;
  for (Edge e : patch.mesh->edges()) lengths[e] /= scale;
  patch.geometry = std::make_unique<PatchGeometry>(*patch.mesh, lengths, scale, faces, std::move(wholeHalfedge),
                                                   cornerAngle, faceArea, halfedgeVector);
  patch.cornerHalfedge = std::move(cornerHalfedge);
  return patch;
}

} // namespace cscd
