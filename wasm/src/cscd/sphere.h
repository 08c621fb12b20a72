#pragma once

#include "geometrycentral/utilities/vector3.h"

namespace cscd {

// The locality constraint of paper Sec. 4.1.6: a Euclidean ball around the source, on meshes and clouds.
struct Sphere {
  geometrycentral::Vector3 center;
  double radius;
};

} // namespace cscd
