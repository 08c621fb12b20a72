#include "mesh/cut_locus.h"

#include "mesh/mesh_arrays.h"
#include "cscd/union_find.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <queue>
#include <stdexcept>
#include <string>

using namespace geometrycentral;
using namespace geometrycentral::surface;

namespace cscd {

namespace {

constexpr size_t NONE = kNoParent;

using Vec2 = std::array<double, 2>;

Vec2 rotate(const Vec2& v, const Vec2& unitComplex) {
  return {v[0] * unitComplex[0] - v[1] * unitComplex[1], v[0] * unitComplex[1] + v[1] * unitComplex[0]};
}

Vec2 toVec2(const Vector2& v) { return {v.x, v.y}; }

} // namespace

CutLocusSolver::CutLocusSolver(IntrinsicTriangulation& intrinsic) {
  ManifoldSurfaceMesh& mesh = *intrinsic.intrinsicMesh;
  nVertices = mesh.nVertices();

  // The graph is reported on input vertex indices: only valid while no vertex was inserted.
  if (nVertices != intrinsic.inputMesh.nVertices())
    throw std::logic_error("cut locus: the intrinsic triangulation has inserted vertices");
  for (Vertex v : mesh.vertices()) {
    const SurfacePoint& at = intrinsic.vertexLocations[v];
    if (at.type != SurfacePointType::Vertex || at.vertex.getIndex() != v.getIndex())
      throw std::logic_error("cut locus: intrinsic vertex " + std::to_string(v.getIndex()) + " is not input vertex " +
                             std::to_string(v.getIndex()));
  }

  intrinsic.requireEdgeLengths();
  intrinsic.requireFaceAreas();
  intrinsic.requireVertexDualAreas();
  intrinsic.requireEdgeCotanWeights();
  intrinsic.requireHalfedgeVectorsInFace();
  intrinsic.requireHalfedgeVectorsInVertex();
  intrinsic.requireTransportVectorsAlongHalfedge();

  VertexData<size_t> vIndex = mesh.getVertexIndices();
  FaceData<size_t> fIndex = mesh.getFaceIndices();
  EdgeData<size_t> eIndex = mesh.getEdgeIndices();

  faceVertices.resize(mesh.nFaces());
  faceHatGradients.resize(mesh.nFaces());
  faceEdges.resize(mesh.nFaces());
  for (Face f : mesh.faces()) {
    size_t i = fIndex[f];
    Halfedge ab = f.halfedge(), bc = ab.next(), ca = bc.next();
    faceVertices[i] = {vIndex[ab.vertex()], vIndex[bc.vertex()], vIndex[ca.vertex()]};
    faceEdges[i] = {eIndex[ab.edge()], eIndex[bc.edge()], eIndex[ca.edge()]};
    // The hat function of a corner rises towards it from the opposite edge: its gradient is that edge
    // rotated a quarter turn inwards (faces are CCW), over twice the area.
    double twiceArea = 2 * intrinsic.faceAreas[f];
    const Halfedge opposite[3] = {bc, ca, ab};
    for (int k = 0; k < 3; k++) {
      Vector2 e = intrinsic.halfedgeVectorsInFace[opposite[k]];
      faceHatGradients[i][k] = twiceArea > 0 ? Vec2{-e.y / twiceArea, e.x / twiceArea} : Vec2{0, 0};
    }
  }

  std::vector<std::array<size_t, 2>>& edgeVertices = graph.edgeVertices;
  edgeVertices.resize(mesh.nEdges());
  edgeFaces.resize(mesh.nEdges());
  double lengthSum = 0;
  for (Edge e : mesh.edges()) {
    size_t i = eIndex[e];
    edgeVertices[i] = {vIndex[e.firstVertex()], vIndex[e.secondVertex()]};
    Halfedge he = e.halfedge();
    edgeFaces[i] = {he.isInterior() ? fIndex[he.face()] : NONE,
                    he.twin().isInterior() ? fIndex[he.twin().face()] : NONE};
    lengthSum += intrinsic.edgeLengths[e];
  }
  meanEdge = mesh.nEdges() > 0 ? lengthSum / mesh.nEdges() : 1;

  graph.rowStart.assign(nVertices + 1, 0);
  cornerStart.assign(nVertices + 1, 0);
  vertexArea.resize(nVertices);
  for (Vertex v : mesh.vertices()) {
    size_t i = vIndex[v];
    vertexArea[i] = intrinsic.vertexDualAreas[v];
    for (Halfedge he : v.outgoingHalfedges()) {
      graph.neighbour.push_back(vIndex[he.tipVertex()]);
      graph.edge.push_back(eIndex[he.edge()]);
      cotanWeight.push_back(intrinsic.edgeCotanWeights[he.edge()]);
      transportToCenter.push_back(toVec2(intrinsic.transportVectorsAlongHalfedge[he.twin()]));
      if (!he.isInterior()) continue;
      // The outgoing halfedge is known in both frames, which fixes the face -> vertex rotation.
      Vector2 rotation = unit(intrinsic.halfedgeVectorsInVertex[he] / intrinsic.halfedgeVectorsInFace[he]);
      corners.push_back({fIndex[he.face()], intrinsic.faceAreas[he.face()], toVec2(rotation)});
    }
    graph.rowStart[i + 1] = graph.neighbour.size();
    cornerStart[i + 1] = corners.size();
  }

  // Connected components and their genus, for the homology step.
  UnionFind sets(nVertices);
  for (const auto& e : edgeVertices) sets.unite(e[0], e[1]);
  vertexComponent.assign(nVertices, -1);
  int nComponents = 0;
  for (size_t v = 0; v < nVertices; v++)
    if (sets.find(v) == v) vertexComponent[v] = nComponents++;
  for (size_t v = 0; v < nVertices; v++) vertexComponent[v] = vertexComponent[sets.find(v)];
  std::vector<long> chi(nComponents, 0);
  std::vector<bool> hasBoundary(nComponents, false);
  for (size_t v = 0; v < nVertices; v++) chi[vertexComponent[v]]++;
  for (size_t e = 0; e < edgeVertices.size(); e++) {
    int c = vertexComponent[edgeVertices[e][0]];
    chi[c]--;
    if (edgeFaces[e][0] == NONE || edgeFaces[e][1] == NONE) hasBoundary[c] = true;
  }
  onBoundary.assign(nVertices, 0);
  for (size_t e = 0; e < edgeVertices.size(); e++)
    if (edgeFaces[e][0] == NONE || edgeFaces[e][1] == NONE) onBoundary[edgeVertices[e][0]] = onBoundary[edgeVertices[e][1]] = 1;
  for (const auto& f : faceVertices) chi[vertexComponent[f[0]]]++;
  componentGenus.resize(nComponents);
  for (int c = 0; c < nComponents; c++) componentGenus[c] = hasBoundary[c] ? -1 : (2 - chi[c]) / 2;

  intrinsic.unrequireEdgeLengths();
  intrinsic.unrequireFaceAreas();
  intrinsic.unrequireVertexDualAreas();
  intrinsic.unrequireEdgeCotanWeights();
  intrinsic.unrequireHalfedgeVectorsInFace();
  intrinsic.unrequireHalfedgeVectorsInVertex();
  intrinsic.unrequireTransportVectorsAlongHalfedge();
}

// Step 1: the distance is linear on each intrinsic triangle; its gradient in the face's own frame.
Vec2 CutLocusSolver::faceGradient(size_t f, const std::vector<double>& distance) const {
  const auto& fv = faceVertices[f];
  Vec2 gradient{0, 0};
  if (!std::isfinite(distance[fv[0]])) return gradient; // a face of another component
  for (int k = 0; k < 3; k++) {
    gradient[0] += distance[fv[k]] * faceHatGradients[f][k][0];
    gradient[1] += distance[fv[k]] * faceHatGradients[f][k][1];
  }
  return gradient;
}

// Step 2: area-weighted mean of the incident face gradients, each rotated into the vertex frame.
Vec2 CutLocusSolver::vertexGradient(size_t v, const std::vector<double>& distance) const {
  Vec2 gradient{0, 0};
  double weightSum = 0;
  for (size_t c = cornerStart[v]; c < cornerStart[v + 1]; c++) {
    Vec2 g = rotate(faceGradient(corners[c].face, distance), corners[c].faceToVertex);
    gradient[0] += corners[c].weight * g[0];
    gradient[1] += corners[c].weight * g[1];
    weightSum += corners[c].weight;
  }
  if (weightSum > 0) gradient = {gradient[0] / weightSum, gradient[1] / weightSum};
  return gradient;
}

// Step 3: across the cut locus, geodesics from different directions collide and the gradient turns
// sharply. Largest angle between any two gradients of the closed one-ring, all transported into the
// vertex's frame: a vertex right on the ridge has an averaged (meaningless) gradient of its own, but
// its neighbours on the two sides point against each other.
std::vector<double> CutLocusSolver::angleDeviations(const std::vector<double>& distance, const std::vector<double>& laplacian,
                                                    const CutLocusOptions& options) const {
  // Directions only, each gradient normalised once (transport is a rotation), and only where asked:
  // for a skeleton, at the vertices the Laplacian test lets pass and their rings (a few percent of the
  // mesh; the gradients of every vertex were a quarter of the cut locus's time on the horse).
  enum : char { Unknown, Some, None };
  std::vector<Vec2> direction(nVertices, Vec2{0, 0});
  std::vector<char> known(nVertices, Unknown);
  auto directionOf = [&](size_t v) -> const Vec2* {
    if (known[v] == Unknown) {
      const Vec2 g = std::isfinite(distance[v]) ? vertexGradient(v, distance) : Vec2{0, 0};
      const double length = std::sqrt(g[0] * g[0] + g[1] * g[1]);
      known[v] = length > 0 ? Some : None;
      if (length > 0) direction[v] = {g[0] / length, g[1] / length};
    }
    return known[v] == Some ? &direction[v] : nullptr;
  };
  std::vector<double> deviation(nVertices, std::numeric_limits<double>::quiet_NaN());
  std::vector<Vec2> ring;
  for (size_t v = 0; v < nVertices; v++) {
    if (!std::isfinite(distance[v])) continue;
    if (!options.everyAngle && !(mayPass(v, laplacian, options))) continue;
    ring.clear();
    if (const Vec2* d = directionOf(v)) ring.push_back(*d);
    for (size_t n = graph.rowStart[v]; n < graph.rowStart[v + 1]; n++)
      if (const Vec2* d = directionOf(graph.neighbour[n])) ring.push_back(rotate(*d, transportToCenter[n]));
    deviation[v] = ringAngle(smallestCosine(ring), options);
  }
  return deviation;
}

// Step 4: cotan Laplacian over the dual area, times h to make it scale-free. A ridge of the distance
// is a concave kink, so the Laplacian is strongly negative on the cut locus (and ~h/r elsewhere).
std::vector<double> CutLocusSolver::distanceLaplacian(const std::vector<double>& distance) const {
  std::vector<double> laplacian(nVertices, std::numeric_limits<double>::quiet_NaN());
  for (size_t v = 0; v < nVertices; v++) {
    if (!std::isfinite(distance[v]) || vertexArea[v] <= 0) continue;
    double sum = 0;
    for (size_t n = graph.rowStart[v]; n < graph.rowStart[v + 1]; n++)
      sum += cotanWeight[n] * (distance[graph.neighbour[n]] - distance[v]);
    laplacian[v] = meanEdge * sum / vertexArea[v];
  }
  return laplacian;
}

bool CutLocusSolver::mayPass(size_t v, const std::vector<double>& laplacian, const CutLocusOptions& options) const {
  return !onBoundary[v] && laplacian[v] <= -options.laplacianThreshold;
}

// Step 7a: the primal tree of the homology step. The kept vertices keep their ridge-tree edges; the
// rest is grown from them by Prim, farthest vertex first, each hanging from its farthest tree neighbour.
// Climbing this tree from anywhere goes uphill in distance, i.e. towards and then along the ridges,
// even where they are too weak to pass the thresholds.
std::vector<size_t> CutLocusSolver::linkingTree(const std::vector<size_t>& ridgeParent, const std::vector<char>& kept,
                                                const std::vector<double>& distance) const {
  std::vector<size_t> parent(nVertices, NONE);
  std::vector<char> inTree(kept), queued(kept);
  using Entry = std::pair<double, size_t>;
  std::priority_queue<Entry> frontier;
  for (size_t v = 0; v < nVertices; v++) {
    if (!kept[v]) continue;
    parent[v] = ridgeParent[v];
    for (size_t n = graph.rowStart[v]; n < graph.rowStart[v + 1]; n++) {
      size_t w = graph.neighbour[n];
      if (!queued[w] && std::isfinite(distance[w])) {
        queued[w] = 1;
        frontier.push({distance[w], w});
      }
    }
  }
  while (!frontier.empty()) {
    size_t v = frontier.top().second;
    frontier.pop();
    inTree[v] = 1;
    double best = -INFINITY;
    for (size_t n = graph.rowStart[v]; n < graph.rowStart[v + 1]; n++) {
      size_t w = graph.neighbour[n];
      if (inTree[w] && w != v && distance[w] > best) {
        best = distance[w];
        parent[v] = graph.edge[n];
      }
      if (!queued[w] && std::isfinite(distance[w])) {
        queued[w] = 1;
        frontier.push({distance[w], w});
      }
    }
  }
  return parent;
}

// Step 7b (closed genus g > 0): tree-cotree. The primal tree is the linking tree; the dual cotree grows
// over faces from the source outwards by distance and never crosses a primal tree edge. The 2g edges
// in neither are homology generators, and the cotree leaves them where the fronts meet: on the cut locus.
std::vector<size_t> CutLocusSolver::homologyGenerators(const std::vector<size_t>& parent,
                                                       const std::vector<double>& distance, size_t source) const {
  // By edge, not by endpoints: intrinsic triangulations can have two edges between the same vertices.
  std::vector<char> treeEdge(graph.edgeVertices.size(), 0);
  for (size_t v = 0; v < nVertices; v++)
    if (parent[v] != NONE) treeEdge[parent[v]] = 1;
  auto isTreeEdge = [&](size_t e) { return treeEdge[e] != 0; };
  auto faceKey = [&](size_t f) {
    const auto& fv = faceVertices[f];
    return distance[fv[0]] + distance[fv[1]] + distance[fv[2]];
  };

  std::vector<char> faceIn(faceVertices.size(), 0), edgeUsed(graph.edgeVertices.size(), 0);
  using Entry = std::pair<double, size_t>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> frontier;
  size_t start = corners[cornerStart[source]].face;
  frontier.push({faceKey(start), start});
  faceIn[start] = 1;
  while (!frontier.empty()) {
    size_t f = frontier.top().second;
    frontier.pop();
    for (size_t e : faceEdges[f]) {
      if (edgeUsed[e] || isTreeEdge(e)) continue;
      size_t g = edgeFaces[e][0] == f ? edgeFaces[e][1] : edgeFaces[e][0];
      if (g == NONE || faceIn[g]) continue;
      edgeUsed[e] = 1;
      faceIn[g] = 1;
      frontier.push({faceKey(g), g});
    }
  }

  std::vector<size_t> generators;
  for (size_t e = 0; e < graph.edgeVertices.size(); e++)
    if (std::isfinite(distance[graph.edgeVertices[e][0]]) && !edgeUsed[e] && !isTreeEdge(e)) generators.push_back(e);
  return generators;
}

CutLocus CutLocusSolver::compute(const std::vector<double>& distance, size_t source,
                                 const CutLocusOptions& options) const {
  if (distance.size() != nVertices) throw InputError("cut locus: one distance per vertex is needed");
  if (source >= nVertices) throw InputError("cut locus: source vertex " + std::to_string(source) + " does not exist");
  const int component = vertexComponent[source];
  std::vector<double> dist(distance);
  for (size_t v = 0; v < nVertices; v++)
    if (vertexComponent[v] != component || std::isnan(dist[v])) dist[v] = INFINITY;

  CutLocus result;
  result.laplacian = distanceLaplacian(dist);
  result.angleDeviation = angleDeviations(dist, result.laplacian, options);
  result.root = source;
  for (size_t v = 0; v < nVertices; v++)
    if (std::isfinite(dist[v]) && dist[v] > dist[result.root]) result.root = v;
  if (cornerStart[source] == cornerStart[source + 1]) { // a vertex used by no face
    result.vertices = {source};
    return result;
  }

  std::vector<char> passing = passingVertices(result.angleDeviation, result.laplacian, onBoundary, options);
  std::vector<size_t> parent = ridgeTree(graph, result.laplacian, passing, dist, result.root);
  std::vector<char> kept = restrictTree(graph, parent, passing, result.root, options.restriction);

  // Link every generator to the restricted set by climbing the tree from both ends: each adds exactly
  // one cycle, since everything else added is tree edges hanging from the (parent-closed) kept set.
  std::vector<size_t> generators;
  if (componentGenus[component] > 0) {
    parent = linkingTree(parent, kept, dist);
    generators = homologyGenerators(parent, dist, source);
  }
  for (size_t e : generators)
    for (size_t v : graph.edgeVertices[e])
      for (; !kept[v]; v = treeParent(graph, parent, v)) kept[v] = 1;

  // Graph of kept vertices: tree edges to their parents plus the generators (step 8 prunes it).
  std::vector<std::array<size_t, 2>> generatorEdges;
  for (size_t e : generators) generatorEdges.push_back(graph.edgeVertices[e]);
  assembleCutLocus(graph, parent, std::move(kept), generatorEdges, options.pruneDepth, result);
  return result;
}

} // namespace cscd
