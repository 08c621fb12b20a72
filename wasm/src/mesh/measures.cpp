#include "mesh/measures.h"

#include <cmath>

using namespace geometrycentral;
using namespace geometrycentral::surface;

namespace cscd {

Vector3 loopCentroid(const std::vector<Vector3>& loop, bool closed) {
  Vector3 sum{0, 0, 0};
  double total = 0;
  for (size_t i = 0; i + (closed ? 0 : 1) < loop.size(); i++) {
    const Vector3 &a = loop[i], &b = loop[(i + 1) % loop.size()];
    double length = norm(b - a);
    sum += length * (a + b) / 2;
    total += length;
  }
  return total > 0 ? sum / total : (loop.empty() ? sum : loop.front());
}

Vector3 loopNormal(const std::vector<Vector3>& loop) {
  Vector3 c = loopCentroid(loop, true), area{0, 0, 0};
  for (size_t i = 0; i < loop.size(); i++) area += cross(loop[i] - c, loop[(i + 1) % loop.size()] - c) / 2;
  double length = norm(area);
  return length > 0 ? area / length : Vector3{0, 0, 0};
}

Vector3 pathNormal(const std::vector<Vector3>& path, Vector3 surfaceNormal) {
  if (path.size() < 2) return Vector3{0, 0, 0};
  Vector3 across = cross(path.back() - path.front(), surfaceNormal);
  double length = norm(across);
  return length > 0 ? across / length : Vector3{0, 0, 0};
}

TriangleSoup triangleSoup(VertexPositionGeometry& geometry) {
  TriangleSoup triangles;
  for (Face f : geometry.mesh.faces()) {
    Halfedge h = f.halfedge();
    triangles.push_back({geometry.vertexPositions[h.vertex()], geometry.vertexPositions[h.next().vertex()],
                         geometry.vertexPositions[h.next().next().vertex()]});
  }
  return triangles;
}

double windingNumber(const TriangleSoup& triangles, Vector3 point) {
  double solidAngle = 0;
  for (const auto& corners : triangles) {
    Vector3 a = corners[0] - point, b = corners[1] - point, c = corners[2] - point;
    double la = norm(a), lb = norm(b), lc = norm(c);
    // Van Oosterom & Strackee: tan(omega / 2) = det[a b c] / (|a||b||c| + (a.b)|c| + (b.c)|a| + (c.a)|b|)
    double numerator = dot(a, cross(b, c));
    double denominator = la * lb * lc + dot(a, b) * lc + dot(b, c) * la + dot(c, a) * lb;
    solidAngle += 2 * std::atan2(numerator, denominator);
  }
  return solidAngle / (4 * M_PI);
}

double separatorScore(const std::array<double, 2>& areas, double length) {
  return areas[1] > 0 && length > 0 ? areas[0] / (areas[1] * length) : 0;
}

} // namespace cscd
