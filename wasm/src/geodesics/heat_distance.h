#pragma once

#include "geodesics/ordered_ldlt.h"

#include "geometrycentral/surface/intrinsic_geometry_interface.h"
#include "geometrycentral/surface/surface_point.h"

#include <array>
#include <memory>
#include <vector>

namespace cscd {

// Geodesic distance by the heat method (Crane, Weischedel, Wardetzky 2013) on a triangulation known by
// its edge lengths: a mesh's intrinsic Delaunay triangulation, a cloud's tufted cover. As
// geometry-central's HeatMethodDistanceSolver computes it (t = mean edge length², the same
// factorizations, the same sums in the same order, so the same numbers on a mesh). The two linear
// systems are factored once and each query costs two back-substitutions; the step between them
// (normalised heat gradient, its divergence) runs on per-face arrays copied at construction, a third of
// the query's time in geometry-central's halfedge-container loop, which index the vectors in the
// factors' orders (no permutation of whole vectors per solve), and hold each distinct face once (a
// cloud's tufted cover repeats most of its faces: the loop is then 3.7 times shorter, the numbers the
// same up to rounding). The triangulation must not change afterwards.
class HeatDistance {
public:
  // vertexComponent: connected component of every vertex, so that each component is solved on its own.
  HeatDistance(geometrycentral::surface::IntrinsicGeometryInterface& geometry, std::vector<int> vertexComponent);

  // Distance from the nearest of several points of the triangulation to every vertex; +infinity in
  // components without one.
  std::vector<double> fromPoints(const std::vector<geometrycentral::surface::SurfacePoint>& sources);

private:
  // One heat-method solve from points of one component.
  std::vector<double> solve(const std::vector<geometrycentral::surface::SurfacePoint>& sources);

  struct FaceOperators {
    // Tail of each halfedge, from face.halfedge(), where it is in each factor's order.
    std::array<size_t, 3> inHeat, inPoisson;
    std::array<geometrycentral::Vector2, 3> heatGradient; // next halfedge's vector turned a quarter: times u at the tail
    std::array<geometrycentral::Vector2, 3> halfedge;     // the halfedge's vector in the face
    std::array<double, 3> cotanWeight;                    // the halfedge's cotan weight
  };

  geometrycentral::surface::IntrinsicGeometryInterface& geometry;
  std::vector<int> vertexComponent;
  std::vector<FaceOperators> faces;
  std::unique_ptr<OrderedLDLT> heatSolver, poissonSolver;
};

} // namespace cscd
