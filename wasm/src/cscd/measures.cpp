#include "cscd/measures.h"

#include <cmath>

using namespace geometrycentral;

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

double loopLength(const std::vector<Vector3>& loop) {
  double length = 0;
  for (size_t i = 0; i < loop.size(); i++) length += norm(loop[(i + 1) % loop.size()] - loop[i]);
  return length;
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

double separatorScore(const std::array<double, 2>& areas, double length) {
  return areas[1] > 0 && length > 0 ? areas[0] / (areas[1] * length) : 0;
}

} // namespace cscd
