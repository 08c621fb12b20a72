#include "mesh/mesh_check.h"

#include "cscd/union_find.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace cscd {
namespace {

constexpr uint32_t kNone = std::numeric_limits<uint32_t>::max();

// One side of an edge: the face corner it starts at, keyed by the edge's sorted vertex pair.
struct HalfedgeRecord {
  uint64_t key;
  uint32_t face;
  uint8_t corner;
  bool forward; // runs from the smaller to the larger vertex index

  bool operator<(const HalfedgeRecord& o) const { return key < o.key || (key == o.key && face < o.face); }
};

double squaredDistance(const double* a, const double* b) {
  double dx = a[0] - b[0], dy = a[1] - b[1], dz = a[2] - b[2];
  return dx * dx + dy * dy + dz * dz;
}

// Twice the triangle area, and its longest squared edge, for a scale-free degeneracy test.
bool isZeroArea(const double* a, const double* b, const double* c) {
  double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
  double v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
  double n[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
  double twiceArea = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  double longest = std::max({squaredDistance(a, b), squaredDistance(b, c), squaredDistance(c, a)});
  return twiceArea <= 1e-12 * longest;
}

void validateArrays(const MeshArrays& mesh) {
  if (mesh.positions.size() % 3 != 0) throw InputError("positions must hold three coordinates per vertex");
  if (mesh.triangles.size() % 3 != 0) throw InputError("triangles must hold three vertex indices per face");
  const size_t nV = mesh.vertexCount();
  if (nV == 0) throw InputError("the mesh has no vertices");
  if (mesh.faceCount() == 0) throw InputError("the mesh has no faces");
  if (nV >= kNone) throw InputError("the mesh has too many vertices");
  for (size_t i = 0; i < mesh.positions.size(); i++) {
    if (!std::isfinite(mesh.positions[i])) {
      std::ostringstream msg;
      msg << "vertex " << i / 3 << " has a non-finite coordinate (" << mesh.positions[i] << ")";
      throw InputError(msg.str());
    }
  }
  for (size_t i = 0; i < mesh.triangles.size(); i++) {
    if (mesh.triangles[i] >= nV) {
      std::ostringstream msg;
      msg << "face " << i / 3 << " refers to vertex " << mesh.triangles[i] << ", but the mesh has only " << nV
          << " vertices";
      throw InputError(msg.str());
    }
  }
}

} // namespace

MeshCheck checkMesh(const MeshArrays& mesh) {
  validateArrays(mesh);
  const size_t nV = mesh.vertexCount(), nF = mesh.faceCount();
  const uint32_t* tri = mesh.triangles.data();
  const double* pos = mesh.positions.data();

  MeshCheck check;
  MeshFacts& facts = check.facts;
  facts.vertices = nV;
  facts.faces = nF;

  // Faces that repeat a vertex have no well-defined edges: they are reported and left out of the topology.
  std::vector<char> faceUsable(nF, 1);
  size_t repeatedVertexFaces = 0;
  uint32_t repeatedExample = kNone;
  std::vector<char> referenced(nV, 0);
  for (uint32_t f = 0; f < nF; f++) {
    uint32_t a = tri[3 * f], b = tri[3 * f + 1], c = tri[3 * f + 2];
    if (a == b || b == c || a == c) {
      faceUsable[f] = 0;
      repeatedVertexFaces++;
      if (repeatedExample == kNone) repeatedExample = f;
      facts.degenerateFaces++;
    } else if (isZeroArea(pos + 3 * a, pos + 3 * b, pos + 3 * c)) {
      facts.degenerateFaces++;
    }
    referenced[a] = referenced[b] = referenced[c] = 1;
  }

  facts.bboxMin = {INFINITY, INFINITY, INFINITY};
  facts.bboxMax = {-INFINITY, -INFINITY, -INFINITY};
  uint32_t unreferencedExample = kNone;
  for (uint32_t v = 0; v < nV; v++) {
    if (!referenced[v]) {
      facts.unreferencedVertices++;
      if (unreferencedExample == kNone) unreferencedExample = v;
      continue;
    }
    for (int k = 0; k < 3; k++) {
      facts.bboxMin[k] = std::min(facts.bboxMin[k], pos[3 * v + k]);
      facts.bboxMax[k] = std::max(facts.bboxMax[k], pos[3 * v + k]);
    }
  }
  facts.bboxDiagonal = std::sqrt(squaredDistance(facts.bboxMin.data(), facts.bboxMax.data()));

  std::vector<HalfedgeRecord> halfedges;
  halfedges.reserve(3 * nF);
  for (uint32_t f = 0; f < nF; f++) {
    if (!faceUsable[f]) continue;
    for (uint8_t k = 0; k < 3; k++) {
      uint32_t from = tri[3 * f + k], to = tri[3 * f + (k + 1) % 3];
      uint64_t lo = std::min(from, to), hi = std::max(from, to);
      halfedges.push_back({(lo << 32) | hi, f, k, from < to});
    }
  }
  std::sort(halfedges.begin(), halfedges.end());

  // Corners of one vertex that are joined across manifold edges form a fan; a manifold vertex has one.
  UnionFind corners(3 * nF);
  auto cornerOf = [&](uint32_t f, uint32_t v) {
    for (uint32_t k = 0; k < 3; k++)
      if (tri[3 * f + k] == v) return 3 * f + k;
    return kNone;
  };
  UnionFind vertexSets(nV);
  UnionFind boundarySets(nV);
  std::vector<char> onBoundary(nV, 0);
  double edgeLengthSum = 0;
  std::vector<uint64_t> edgeKeys;
  std::ostringstream nonManifoldEdgeExample, orientationExample;
  bool orientationOk = true;

  for (size_t i = 0; i < halfedges.size();) {
    size_t j = i;
    while (j < halfedges.size() && halfedges[j].key == halfedges[i].key) j++;
    const size_t count = j - i;
    const uint32_t a = uint32_t(halfedges[i].key >> 32), b = uint32_t(halfedges[i].key & 0xffffffffu);
    edgeKeys.push_back(halfedges[i].key);
    edgeLengthSum += std::sqrt(squaredDistance(pos + 3 * a, pos + 3 * b));
    vertexSets.unite(a, b);
    if (count == 1) {
      boundarySets.unite(a, b);
      onBoundary[a] = onBoundary[b] = 1;
    } else if (count == 2) {
      const HalfedgeRecord &h0 = halfedges[i], &h1 = halfedges[i + 1];
      if (h0.forward == h1.forward && orientationOk) {
        orientationOk = false;
        orientationExample << "faces " << h0.face << " and " << h1.face << " both run along edge " << a << "-" << b
                           << " in the same direction";
      }
      corners.unite(cornerOf(h0.face, a), cornerOf(h1.face, a));
      corners.unite(cornerOf(h0.face, b), cornerOf(h1.face, b));
    } else {
      if (facts.nonManifoldEdges == 0) {
        nonManifoldEdgeExample << "edge " << a << "-" << b << " in faces";
        for (size_t k = i; k < j; k++) nonManifoldEdgeExample << " " << halfedges[k].face;
      }
      facts.nonManifoldEdges++;
    }
    i = j;
  }
  facts.edges = edgeKeys.size();
  facts.meanEdgeLength = facts.edges ? edgeLengthSum / double(facts.edges) : 0;
  facts.consistentlyOriented = orientationOk;

  std::vector<uint32_t> firstFan(nV, kNone);
  std::vector<char> nonManifoldVertex(nV, 0);
  uint32_t nonManifoldVertexExample = kNone;
  for (uint32_t f = 0; f < nF; f++) {
    if (!faceUsable[f]) continue;
    for (uint32_t k = 0; k < 3; k++) {
      uint32_t v = tri[3 * f + k], fan = corners.find(3 * f + k);
      if (firstFan[v] == kNone) {
        firstFan[v] = fan;
      } else if (firstFan[v] != fan && !nonManifoldVertex[v]) {
        nonManifoldVertex[v] = 1;
        facts.nonManifoldVertices++;
        if (nonManifoldVertexExample == kNone || v < nonManifoldVertexExample) nonManifoldVertexExample = v;
      }
    }
  }

  // Components numbered in order of their smallest vertex, so results do not depend on hashing.
  check.vertexComponent.assign(nV, -1);
  std::vector<int> componentOfRoot(nV, -1);
  for (uint32_t v = 0; v < nV; v++) {
    if (!referenced[v]) continue;
    uint32_t root = vertexSets.find(v);
    if (componentOfRoot[root] < 0) componentOfRoot[root] = int(facts.components++);
    check.vertexComponent[v] = componentOfRoot[root];
  }

  const size_t nC = facts.components;
  std::vector<long> chi(nC, 0), loops(nC, 0);
  for (uint32_t v = 0; v < nV; v++)
    if (referenced[v]) chi[check.vertexComponent[v]]++;
  for (uint64_t key : edgeKeys) chi[check.vertexComponent[uint32_t(key >> 32)]]--;
  for (uint32_t f = 0; f < nF; f++) chi[check.vertexComponent[tri[3 * f]]]++;
  std::vector<char> loopCounted(nV, 0);
  for (uint32_t v = 0; v < nV; v++) {
    if (!onBoundary[v]) continue;
    uint32_t root = boundarySets.find(v);
    if (!loopCounted[root]) {
      loopCounted[root] = 1;
      loops[check.vertexComponent[v]]++;
      facts.boundaryLoops++;
    }
  }
  for (long c : chi) facts.eulerCharacteristic += c;

  facts.manifold = facts.nonManifoldEdges == 0 && facts.nonManifoldVertices == 0 && repeatedVertexFaces == 0;
  if (facts.manifold) {
    long genus = 0;
    bool wellDefined = true;
    for (size_t c = 0; c < nC; c++) {
      long twiceGenus = 2 - chi[c] - loops[c];
      if (twiceGenus < 0 || twiceGenus % 2 != 0) wellDefined = false; // e.g. a non-orientable component
      genus += twiceGenus / 2;
    }
    if (wellDefined) facts.genus = genus;
  }

  auto problem = [&](size_t count, const char* what, const std::string& example) {
    std::ostringstream msg;
    msg << count << " " << what << " (e.g. " << example << ")";
    check.blockingProblems.push_back(msg.str());
  };
  if (facts.nonManifoldEdges)
    problem(facts.nonManifoldEdges, "non-manifold edges are shared by more than two faces",
            nonManifoldEdgeExample.str());
  if (facts.nonManifoldVertices)
    problem(facts.nonManifoldVertices, "non-manifold vertices join faces that share no edge there",
            "vertex " + std::to_string(nonManifoldVertexExample));
  if (repeatedVertexFaces)
    problem(repeatedVertexFaces, "faces use the same vertex twice", "face " + std::to_string(repeatedExample));
  if (!orientationOk) check.blockingProblems.push_back("faces are not consistently oriented: " + orientationExample.str());
  if (facts.unreferencedVertices)
    problem(facts.unreferencedVertices, "vertices are used by no face",
            "vertex " + std::to_string(unreferencedExample));
  return check;
}

} // namespace cscd
