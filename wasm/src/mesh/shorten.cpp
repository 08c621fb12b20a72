#include "mesh/shorten.h"

#include "cscd/union_find.h"

#include "geometrycentral/surface/edge_length_geometry.h"
#include "geometrycentral/surface/flip_geodesics.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <set>
#include <stdexcept>
#include <queue>

using namespace geometrycentral;
using namespace geometrycentral::surface;

namespace cscd {
namespace {

// A patch of the intrinsic triangulation as a mesh of its own, with the maps back to the triangulation.
struct Patch {
  std::unique_ptr<ManifoldSurfaceMesh> mesh;
  std::unique_ptr<EdgeLengthGeometry> geometry;
  HalfedgeData<Halfedge> toIntrinsic;  // patch halfedge -> intrinsic halfedge (interior halfedges)
  HalfedgeData<Halfedge> fromIntrinsic; // intrinsic halfedge -> patch halfedge (selected faces only)
  // Edge lengths are divided by their mean: FlipOut's angle and length tolerances are absolute, and a
  // mesh at 1e30 (or 1e-30) would make it flip forever.
  double scale = 1;
};

// geometry-central keeps its constructor from halfedge arrays for its own copies.
struct ArrayMesh : ManifoldSurfaceMesh {
  ArrayMesh(const std::vector<size_t>& heNext, const std::vector<size_t>& heVertex, const std::vector<size_t>& heFace,
            const std::vector<size_t>& vHalfedge, const std::vector<size_t>& fHalfedge, size_t nBoundaryLoops)
      : ManifoldSurfaceMesh(heNext, heVertex, heFace, vHalfedge, fHalfedge, nBoundaryLoops) {}
};

// Builds the patch of the selected faces. A vertex whose selected faces form several fans (a bow-tie
// inside the patch) becomes one patch vertex per fan, so the patch is always a manifold.
Patch buildPatch(IntrinsicTriangulation& intrinsic, const std::vector<char>& selected) {
  ManifoldSurfaceMesh& mesh = *intrinsic.intrinsicMesh;
  std::vector<Face> faces;
  FaceData<size_t> slot(mesh, SIZE_MAX);
  for (Face f : mesh.faces())
    if (selected[f.getIndex()]) {
      slot[f] = faces.size();
      faces.push_back(f);
    }

  // Corner of halfedge h: the corner at h's tail in h's face.
  auto corner = [&](Halfedge h) {
    Halfedge first = h.face().halfedge();
    size_t k = h == first ? 0 : h == first.next() ? 1 : 2;
    return 3 * slot[h.face()] + k;
  };
  UnionFind fans(3 * faces.size());
  for (Face f : faces)
    for (Halfedge h : f.adjacentHalfedges()) {
      Halfedge t = h.twin();
      if (!t.isInterior() || slot[t.face()] == SIZE_MAX) continue;
      fans.unite(uint32_t(corner(h)), uint32_t(corner(t.next())));
      fans.unite(uint32_t(corner(h.next())), uint32_t(corner(t)));
    }

  // One patch vertex per fan, numbered in corner order.
  const size_t nFaces = faces.size();
  std::vector<size_t> cornerVertex(3 * nFaces), patchVertexOfFan(3 * nFaces, SIZE_MAX);
  size_t nPatchVertices = 0;
  for (size_t c = 0; c < 3 * nFaces; c++) {
    size_t fan = fans.find(uint32_t(c));
    if (patchVertexOfFan[fan] == SIZE_MAX) patchVertexOfFan[fan] = nPatchVertices++;
    cornerVertex[c] = patchVertexOfFan[fan];
  }

  // The halfedge arrays, numbered as ManifoldSurfaceMesh(polygons, twins) numbers them (face by face,
  // a new edge when the twin is not made yet, then the boundary loops), built directly: that
  // constructor's hash map of twins was most of the time spent on a patch. Twins come from the
  // triangulation, which can have several edges between the same two vertices.
  std::vector<std::array<Halfedge, 3>> faceHalfedges(nFaces);
  std::vector<size_t> heNext, heVertex, heFace, vHalfedge(nPatchVertices, INVALID_IND), fHalfedge(nFaces, INVALID_IND);
  std::vector<size_t> cornerHalfedge(3 * nFaces, INVALID_IND); // patch halfedge leaving each corner
  for (size_t i = 0; i < nFaces; i++) {
    size_t k = 0;
    for (Halfedge h : faces[i].adjacentHalfedges()) faceHalfedges[i][k++] = h;
    for (k = 0; k < 3; k++) {
      const size_t tail = cornerVertex[3 * i + k], tip = cornerVertex[3 * i + (k + 1) % 3];
      if (tail == tip) throw std::runtime_error("patch: a self-edge");
      Halfedge t = faceHalfedges[i][k].twin();
      size_t twin = t.isInterior() && slot[t.face()] != SIZE_MAX ? cornerHalfedge[corner(t)] : INVALID_IND;
      size_t he;
      if (twin == INVALID_IND) {
        he = heNext.size();
        heNext.insert(heNext.end(), {INVALID_IND, INVALID_IND});
        heVertex.insert(heVertex.end(), {tail, tip});
        heFace.insert(heFace.end(), {INVALID_IND, INVALID_IND});
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
  patch.mesh = std::make_unique<ArrayMesh>(heNext, heVertex, heFace, vHalfedge, fHalfedge, nBoundaryLoops);
  patch.toIntrinsic = HalfedgeData<Halfedge>(*patch.mesh);
  patch.fromIntrinsic = HalfedgeData<Halfedge>(mesh);
  EdgeData<double> lengths(*patch.mesh, 0.);
  intrinsic.requireEdgeLengths();
  for (size_t c = 0; c < 3 * nFaces; c++) {
    Halfedge ph = patch.mesh->halfedge(cornerHalfedge[c]), ih = faceHalfedges[c / 3][c % 3];
    patch.toIntrinsic[ph] = ih;
    patch.fromIntrinsic[ih] = ph;
    lengths[ph.edge()] = intrinsic.edgeLengths[ih.edge()];
  }
  double sum = 0;
  for (Edge e : patch.mesh->edges()) sum += lengths[e];
  if (sum > 0) patch.scale = sum / patch.mesh->nEdges();
  for (Edge e : patch.mesh->edges()) lengths[e] /= patch.scale;
  patch.geometry = std::make_unique<EdgeLengthGeometry>(*patch.mesh, lengths);
  return patch;
}

// A point of the patch as a point of the intrinsic triangulation: a vertex as the matching vertex (a
// face point at a corner would be traced across the face, which lands off the corner on the boundary),
// other points barycentric in the matching face.
SurfacePoint toIntrinsic(const Patch& patch, const SurfacePoint& onPatch) {
  if (onPatch.type == SurfacePointType::Vertex) return SurfacePoint(patch.toIntrinsic[onPatch.vertex.halfedge()].tailVertex());
  SurfacePoint p = onPatch.inSomeFace();
  Halfedge ph = p.face.halfedge();
  Halfedge ih[3] = {patch.toIntrinsic[ph], patch.toIntrinsic[ph.next()], patch.toIntrinsic[ph.next().next()]};
  Halfedge first = ih[0].face().halfedge();
  Vector3 bary{0, 0, 0};
  for (int k = 0; k < 3; k++) bary[ih[k] == first ? 0 : ih[k] == first.next() ? 1 : 2] = p.faceCoords[k];
  return SurfacePoint(ih[0].face(), bary);
}

// Areas of the two sides of the loop: faces flooded from the left and from the right of the loop,
// never across it, nor into a face that `reached` rejects. A loop that does not separate them
// reports (0, area flooded).
template <class Reached>
std::array<double, 2> sideAreas(FlipEdgeNetwork& network, const std::vector<Halfedge>& path, Reached reached) {
  SignpostIntrinsicTriangulation& tri = *network.tri;
  tri.requireFaceAreas();
  FaceData<int> side(network.mesh, -1);
  std::array<double, 2> area{0, 0};
  bool separates = true;
  for (int s = 0; s < 2; s++) {
    std::queue<Face> queue;
    auto enter = [&](Face f) {
      if (side[f] == 1 - s) separates = false;
      if (side[f] < 0 && reached(f)) {
        side[f] = s;
        queue.push(f);
      }
    };
    for (Halfedge he : path) {
      Halfedge seed = s == 0 ? he : he.twin();
      if (seed.isInterior()) enter(seed.face());
    }
    while (!queue.empty()) {
      Face f = queue.front();
      queue.pop();
      area[s] += tri.faceAreas[f];
      for (Halfedge h : f.adjacentHalfedges())
        if (h.twin().isInterior() && !network.edgeInPath(h.edge())) enter(h.twin().face());
    }
  }
  if (!separates) return {0, area[0] + area[1]};
  return {std::min(area[0], area[1]), std::max(area[0], area[1])};
}

// Distance along the triangulation's edges from the loop's vertices (Dijkstra).
VertexData<double> distanceFromPath(FlipEdgeNetwork& network, const std::vector<Halfedge>& path) {
  SignpostIntrinsicTriangulation& tri = *network.tri;
  tri.requireEdgeLengths();
  VertexData<double> distance(network.mesh, INFINITY);
  using Entry = std::pair<double, size_t>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> frontier;
  for (Halfedge he : path) {
    distance[he.tailVertex()] = 0;
    frontier.push({0, he.tailVertex().getIndex()});
  }
  while (!frontier.empty()) {
    auto [d, index] = frontier.top();
    frontier.pop();
    Vertex v = network.mesh.vertex(index);
    if (d > distance[v]) continue;
    for (Halfedge he : v.outgoingHalfedges()) {
      const double through = d + tri.edgeLengths[he.edge()];
      if (through < distance[he.tipVertex()]) {
        distance[he.tipVertex()] = through;
        frontier.push({through, he.tipVertex().getIndex()});
      }
    }
  }
  return distance;
}

} // namespace

Halfedge intrinsicHalfedge(ManifoldSurfaceMesh& mesh, size_t a, size_t b) {
  for (Halfedge he : mesh.vertex(a).outgoingHalfedges())
    if (he.tipVertex().getIndex() == b) return he;
  return Halfedge();
}

ShortenedLoop shortenLoop(SignpostIntrinsicTriangulation& intrinsic, VertexPositionGeometry& inputGeometry,
                          const std::vector<size_t>& loopVertices, bool closed, const std::optional<Sphere>& sphere) {
  ManifoldSurfaceMesh& mesh = *intrinsic.intrinsicMesh;
  ShortenedLoop result;
  const size_t n = loopVertices.size();

  std::vector<char> selected(mesh.nFaces(), sphere ? 0 : 1);
  if (sphere) {
    const double r2 = sphere->radius * sphere->radius * (1 + 1e-9);
    // Each vertex tested once (not once per face around it): this pass runs over the whole mesh.
    std::vector<char> inside(mesh.nVertices());
    for (size_t v = 0; v < inside.size(); v++) inside[v] = norm2(inputGeometry.vertexPositions[v] - sphere->center) <= r2;
    for (Face f : mesh.faces()) {
      bool all = true;
      for (Vertex v : f.adjacentVertices()) all = all && inside[v.getIndex()];
      selected[f.getIndex()] = all;
    }
    // The loop's own one-ring stays in, so that the loop is a path of the patch through single fans.
    for (size_t v : loopVertices)
      for (Face f : mesh.vertex(v).adjacentFaces()) selected[f.getIndex()] = 1;
  }

  std::unique_ptr<Patch> patch;
  std::vector<Halfedge> loop;
  try {
    patch = std::make_unique<Patch>(buildPatch(intrinsic, selected));
    for (size_t i = 0; i + (closed ? 0 : 1) < n; i++) {
      Halfedge ih = intrinsicHalfedge(mesh, loopVertices[i], loopVertices[(i + 1) % n]);
      if (ih == Halfedge()) throw std::runtime_error("the loop jumps between vertices that share no edge");
      Halfedge ph = ih.isInterior() ? patch->fromIntrinsic[ih] : patch->fromIntrinsic[ih.twin()].twin();
      loop.push_back(ph);
    }
  } catch (const std::exception&) {
    // geometry-central's assertion texts name source files: not for users.
    result.failureKind = ShortenedLoop::Failure::Region;
    result.failure = "could not build the constraint region around this loop (degenerate intrinsic triangles)";
    return result;
  }

  FlipEdgeNetwork network(*patch->mesh, *patch->geometry, {loop});
  const double initialLength = network.length();
  network.iterativeShorten(100000);
  // A loop around no feature shrinks to nothing, or to a path that runs back over its own edges.
  std::vector<Halfedge> path = network.paths.empty() ? std::vector<Halfedge>() : network.paths[0]->getHalfedgeList();
  std::set<Halfedge> onPath(path.begin(), path.end());
  bool doubledBack = closed && std::all_of(path.begin(), path.end(), [&](Halfedge he) { return onPath.count(he.twin()) > 0; });
  if (path.empty() || doubledBack || !(network.length() > 1e-9 * initialLength)) {
    result.failureKind = ShortenedLoop::Failure::Degenerate;
    result.failure = "the loop shrank to a point: it encloses no feature inside the constraint region";
    return result;
  }
  // One intrinsic edge may be the whole loop (e.g. a meridian of a torus as a self-edge): that is fine.
  result.length = network.length() * patch->scale;

  std::vector<std::vector<SurfacePoint>> polylines = network.getPathPolyline();
  std::vector<SurfacePoint>& onPatch = polylines.front();
  const SurfacePoint &first = onPatch.front(), &last = onPatch.back();
  if (closed && onPatch.size() > 1 && first.type == SurfacePointType::Vertex && last.type == SurfacePointType::Vertex &&
      first.vertex == last.vertex)
    onPatch.pop_back(); // closed: the last point repeats the first
  for (const SurfacePoint& p : onPatch) result.loop.push_back(intrinsic.equivalentPointOnInput(toIntrinsic(*patch, p)));
  result.areas = sideAreas(network, path, [](Face) { return true; });
  // A loop around a handle that lies whole in the region (the tube of a ring) separates nothing there:
  // its sides meet around the handle, and its score would be 0, so it could never be packed and the
  // handle's cycle was lost (hanger's eyelet, at 7 seeds of 8). Near the loop it still separates: its
  // sides are then measured over the faces within one loop radius of it.
  if (closed && !(result.areas[0] > 0)) {
    const VertexData<double> distance = distanceFromPath(network, path);
    const double radius = network.length() / (2 * M_PI);
    result.areas = sideAreas(network, path, [&](Face f) {
      for (Vertex v : f.adjacentVertices())
        if (distance[v] > radius) return false;
      return true;
    });
  }
  for (double& a : result.areas) a *= patch->scale * patch->scale;
  return result;
}

} // namespace cscd
