#include "mesh/boundary.h"

#include "cscd/target.h"

#include <algorithm>
#include <cmath>

using namespace geometrycentral;
using namespace geometrycentral::surface;

namespace cscd {
namespace {

// Gradient of the piecewise-linear distance at a vertex: the area-weighted mean of the gradients of
// its faces, 1/(2A) sum_i d_i (N x e_i) per face with e_i the edge opposite corner i.
Vector3 vertexGradient(VertexPositionGeometry& geometry, const std::vector<double>& distance, Vertex v) {
  Vector3 sum{0, 0, 0};
  for (Face f : v.adjacentFaces()) {
    Halfedge h = f.halfedge();
    Vertex corner[3] = {h.vertex(), h.next().vertex(), h.next().next().vertex()};
    Vector3 p[3];
    for (int k = 0; k < 3; k++) p[k] = geometry.vertexPositions[corner[k]];
    Vector3 areaNormal = cross(p[1] - p[0], p[2] - p[0]); // 2A N
    double twiceArea = norm(areaNormal);
    if (!(twiceArea > 0)) continue;
    Vector3 n = areaNormal / twiceArea, faceSum{0, 0, 0};
    for (int k = 0; k < 3; k++) faceSum += distance[corner[k].getIndex()] * cross(n, p[(k + 2) % 3] - p[(k + 1) % 3]);
    sum += faceSum / 2; // area x (faceSum / 2A)
  }
  double length = norm(sum);
  return length > 0 ? sum / length : Vector3{0, 0, 0};
}

} // namespace

std::vector<std::vector<size_t>> boundaryLoops(ManifoldSurfaceMesh& mesh) {
  std::vector<std::vector<size_t>> loops;
  for (BoundaryLoop loop : mesh.boundaryLoops()) {
    std::vector<size_t> vertices;
    for (Vertex v : loop.adjacentVertices()) vertices.push_back(v.getIndex());
    loops.push_back(std::move(vertices));
  }
  return loops;
}

std::vector<BoundaryExtremity> boundaryExtremities(const std::vector<std::vector<size_t>>& loops,
                                                   VertexPositionGeometry& geometry, const std::vector<double>& distance,
                                                   double window) {
  std::vector<BoundaryExtremity> extremities;
  for (size_t l = 0; l < loops.size(); l++) {
    const std::vector<size_t>& loop = loops[l];
    const size_t n = loop.size();
    auto at = [&](size_t i) { return geometry.vertexPositions[loop[i % n]]; };
    for (size_t i = 0; i < n; i++) {
      const double d = distance[loop[i]];
      if (!std::isfinite(d) || d < window) continue;
      // Walk both ways along the loop over `window` of arc length; a lower vertex (or an equal one
      // earlier in the loop, so that a flat stretch yields one extremity) rules this one out.
      bool minimum = true;
      std::vector<size_t> neighbourhood{loop[i]};
      for (int direction : {1, -1}) {
        double arc = 0;
        for (size_t step = 1; step < n && minimum; step++) {
          size_t j = (i + n + direction * long(step)) % n, previous = (j + n - direction) % n;
          arc += norm(at(j) - at(previous));
          if (arc > window) break;
          const double dj = distance[loop[j]];
          if (dj < d || (dj == d && j < i)) minimum = false;
          neighbourhood.push_back(loop[j]);
        }
      }
      if (!minimum) continue;
      // The direction is averaged over the window: a jagged boundary (a lattice cut by a curve, a
      // scan's ragged edge) turns the gradient of single vertices by tens of degrees.
      Vector3 gradient{0, 0, 0};
      for (size_t w : neighbourhood) gradient += vertexGradient(geometry, distance, geometry.mesh.vertex(w));
      double length = norm(gradient);
      if (length > 0) extremities.push_back({loop[i], l, gradient / length});
    }
  }
  return extremities;
}

std::vector<BoundaryPair> opposedExtremities(const std::vector<BoundaryExtremity>& extremities,
                                             VertexPositionGeometry& geometry, const std::vector<double>& distance,
                                             size_t source, TargetMode mode, bool acrossLoops) {
  std::vector<BoundaryPair> pairs;
  for (size_t a = 0; a < extremities.size(); a++)
    for (size_t b = a + 1; b < extremities.size(); b++) {
      const BoundaryExtremity &ea = extremities[a], &eb = extremities[b];
      if ((ea.loop != eb.loop && !acrossLoops) || !(norm(ea.gradient + eb.gradient) < kMaxGradientSum)) continue;
      double key = std::max(targetKey(geometry.vertexPositions, distance, source, ea.vertex, mode),
                            targetKey(geometry.vertexPositions, distance, source, eb.vertex, mode));
      pairs.push_back({{ea.vertex, eb.vertex}, key});
    }
  std::stable_sort(pairs.begin(), pairs.end(), [](const BoundaryPair& x, const BoundaryPair& y) { return x.key < y.key; });
  return pairs;
}

bool sheetAround(VertexPositionGeometry& geometry, const WindingNumber& winding, size_t vertex, double offset) {
  geometry.requireVertexNormals();
  const Vector3 p = geometry.vertexPositions[vertex], n = geometry.vertexNormals[vertex];
  return std::abs(winding(p + offset * n) + winding(p - offset * n)) < 0.5;
}

} // namespace cscd
