#include "mesh/shorten.h"

#include "mesh/patch.h"

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

// A point of the patch as a point of the intrinsic triangulation: a vertex as the matching vertex (a
// face point at a corner would be traced across the face, which lands off the corner on the boundary),
// other points barycentric in the matching face.
SurfacePoint toIntrinsic(const Patch& patch, const SurfacePoint& onPatch) {
  if (onPatch.type == SurfacePointType::Vertex) return SurfacePoint(patch.toIntrinsic(onPatch.vertex.halfedge()).tailVertex());
  SurfacePoint p = onPatch.inSomeFace();
  Halfedge ph = p.face.halfedge();
  Halfedge ih[3] = {patch.toIntrinsic(ph), patch.toIntrinsic(ph.next()), patch.toIntrinsic(ph.next().next())};
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

ShortenedLoop shortenLoop(SignpostIntrinsicTriangulation& intrinsic, PatchBuilder& patches,
                          const std::vector<size_t>& loopVertices, bool closed, const std::optional<Sphere>& sphere) {
  ManifoldSurfaceMesh& mesh = *intrinsic.intrinsicMesh;
  ShortenedLoop result;
  const size_t n = loopVertices.size();

  std::unique_ptr<Patch> patch;
  std::vector<Halfedge> loop;
  try {
    patch = std::make_unique<Patch>(patches.build(patches.facesFor(sphere, loopVertices)));
    for (size_t i = 0; i + (closed ? 0 : 1) < n; i++) {
      Halfedge ih = intrinsicHalfedge(mesh, loopVertices[i], loopVertices[(i + 1) % n]);
      if (ih == Halfedge()) throw std::runtime_error("the loop jumps between vertices that share no edge");
      Halfedge ph = ih.isInterior() ? patch->fromIntrinsic(ih) : patch->fromIntrinsic(ih.twin()).twin();
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
  result.length = network.length() * patch->scale();

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
  for (double& a : result.areas) a *= patch->scale() * patch->scale();
  return result;
}

} // namespace cscd
