#include "mesh/regions.h"

#include "cscd/union_find.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

using namespace geometrycentral;
using namespace geometrycentral::surface;

namespace cscd {

Regions assignRegions(Surface& surface, const std::vector<std::vector<SurfacePoint>>& loops) {
  constexpr uint32_t kNone = std::numeric_limits<uint32_t>::max();
  ManifoldSurfaceMesh& mesh = surface.mesh();
  VertexPositionGeometry& geometry = surface.geometry();
  const size_t nV = surface.vertexCount();
  Regions regions;
  regions.label.assign(nV, kNone);

  std::vector<double>& distance = regions.distance;
  distance.assign(nV, INFINITY);
  std::vector<SurfacePoint> all;
  for (const auto& loop : loops) all.insert(all.end(), loop.begin(), loop.end());
  if (!all.empty()) distance = surface.geodesics().fromPoints(all);

  // Seeds: the corners of the faces each loop runs through, labelled by the loop closest in space.
  std::vector<double> seedDistance(nV, INFINITY);
  for (uint32_t k = 0; k < loops.size(); k++)
    for (const SurfacePoint& p : loops[k]) {
      Vector3 at = p.interpolate(geometry.vertexPositions);
      for (Vertex v : p.inSomeFace().face.adjacentVertices()) {
        double d = norm(geometry.vertexPositions[v] - at);
        if (d < seedDistance[v.getIndex()]) {
          seedDistance[v.getIndex()] = d;
          regions.label[v.getIndex()] = k;
        }
      }
    }

  // Watershed in order of increasing distance; a vertex with no labelled neighbour yet waits.
  std::vector<size_t> order(nV);
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) { return distance[a] < distance[b]; });
  auto labelFromNeighbours = [&](size_t v) {
    uint32_t best = kNone;
    double bestDistance = INFINITY;
    for (Vertex w : mesh.vertex(v).adjacentVertices()) {
      size_t i = w.getIndex();
      if (regions.label[i] != kNone && (best == kNone || distance[i] < bestDistance)) {
        best = regions.label[i];
        bestDistance = distance[i];
      }
    }
    return best;
  };
  std::vector<size_t> waiting;
  auto floodWaiting = [&]() {
    for (bool changed = true; changed;) {
      changed = false;
      for (size_t v : waiting)
        if (regions.label[v] == kNone && (regions.label[v] = labelFromNeighbours(v)) != kNone) changed = true;
    }
  };
  for (size_t v : order) {
    if (regions.label[v] != kNone || !std::isfinite(distance[v])) continue;
    regions.label[v] = labelFromNeighbours(v);
    if (regions.label[v] == kNone) waiting.push_back(v);
  }
  floodWaiting();

  // Seeds of close loops can interleave and cut off islands of a label: each label keeps its largest
  // piece; the vertices of other pieces join the regions around them, so every region is connected.
  UnionFind pieces(nV);
  for (Edge e : mesh.edges()) {
    size_t a = e.firstVertex().getIndex(), b = e.secondVertex().getIndex();
    if (regions.label[a] == regions.label[b]) pieces.unite(uint32_t(a), uint32_t(b));
  }
  std::vector<size_t> pieceSize(nV, 0);
  for (size_t v = 0; v < nV; v++) pieceSize[pieces.find(uint32_t(v))]++;
  std::vector<size_t> largestPiece(loops.size(), SIZE_MAX);
  for (size_t v = 0; v < nV; v++) {
    uint32_t label = regions.label[v];
    if (label == kNone) continue;
    size_t piece = pieces.find(uint32_t(v)), best = largestPiece[label];
    if (best == SIZE_MAX || pieceSize[piece] > pieceSize[best] || (pieceSize[piece] == pieceSize[best] && piece < best))
      largestPiece[label] = piece;
  }
  waiting.clear();
  for (size_t v : order)
    if (regions.label[v] != kNone && pieces.find(uint32_t(v)) != largestPiece[regions.label[v]]) {
      regions.label[v] = kNone;
      waiting.push_back(v);
    }
  floodWaiting();

  // Components that no separator reached: one region each.
  regions.count = loops.size();
  std::vector<uint32_t> componentRegion;
  for (size_t v = 0; v < nV; v++) {
    if (regions.label[v] != kNone) continue;
    size_t c = size_t(surface.vertexComponent()[v]);
    if (componentRegion.size() <= c) componentRegion.resize(c + 1, kNone);
    if (componentRegion[c] == kNone) componentRegion[c] = uint32_t(regions.count++);
    regions.label[v] = componentRegion[c];
  }

  geometry.requireVertexDualAreas();
  regions.centroid.assign(regions.count, Vector3{0, 0, 0});
  regions.area.assign(regions.count, 0);
  for (size_t v = 0; v < nV; v++) {
    regions.centroid[regions.label[v]] += geometry.vertexDualAreas[v] * geometry.vertexPositions[v];
    regions.area[regions.label[v]] += geometry.vertexDualAreas[v];
  }
  for (size_t r = 0; r < regions.count; r++)
    if (regions.area[r] > 0) regions.centroid[r] /= regions.area[r];

  for (Face f : mesh.faces()) {
    std::array<size_t, 3> l;
    size_t k = 0;
    for (Vertex v : f.adjacentVertices()) l[k++] = regions.label[v.getIndex()];
    std::sort(l.begin(), l.end());
    if (l[0] != l[1]) regions.adjacent.insert({l[0], l[1]});
    if (l[1] != l[2]) regions.adjacent.insert({l[1], l[2]});
    if (l[0] != l[2]) regions.adjacent.insert({l[0], l[2]});
    if (l[0] != l[1] && l[1] != l[2]) regions.junctions.insert(l);
  }
  return regions;
}

} // namespace cscd
