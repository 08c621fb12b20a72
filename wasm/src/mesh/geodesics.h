#pragma once

#include "geometrycentral/numerical/linear_solvers.h"
#include "geometrycentral/surface/intrinsic_triangulation.h"

#include <array>
#include <memory>
#include <vector>

namespace cscd {

// Geodesic distance by the heat method (Crane, Weischedel, Wardetzky 2013) on an intrinsic Delaunay
// triangulation, as geometry-central's HeatMethodDistanceSolver computes it (t = mean edge length²,
// the same factorizations, the same sums in the same order, so the same numbers). The two linear
// systems are factored once per mesh and each query costs two back-substitutions; the step between
// them (normalised heat gradient, its divergence) runs on per-face arrays copied at construction,
// a third of the query's time in geometry-central's halfedge-container loop. The triangulation must
// not change afterwards (loop shortening works on copies).
class Geodesics {
public:
  // vertexComponent: connected component of every vertex, so that each component is solved on its own.
  Geodesics(geometrycentral::surface::IntrinsicTriangulation& intrinsic, std::vector<int> vertexComponent);

  // Distance from one vertex to every vertex; +infinity in other components.
  std::vector<double> fromVertex(size_t vertex);

  // Exact polyhedral distance (MMP) on the input mesh: slower, the reference the heat method approximates.
  std::vector<double> exactFromVertex(size_t vertex);

  // Distance from the nearest of several points of the *input* mesh; +infinity in components without one.
  std::vector<double> fromPoints(const std::vector<geometrycentral::surface::SurfacePoint>& pointsOnInput);

private:
  // One heat-method solve from points of the intrinsic triangulation (all in one component).
  std::vector<double> solve(const std::vector<geometrycentral::surface::SurfacePoint>& sources);

  struct FaceOperators {
    std::array<size_t, 3> vertex;                        // tail of each halfedge, from face.halfedge()
    std::array<geometrycentral::Vector2, 3> heatGradient; // next halfedge's vector turned a quarter: times u at `vertex`
    std::array<geometrycentral::Vector2, 3> halfedge;     // the halfedge's vector in the face
    std::array<double, 3> cotanWeight;                    // the halfedge's cotan weight
  };

  geometrycentral::surface::IntrinsicTriangulation& intrinsic;
  std::vector<int> vertexComponent;
  std::vector<FaceOperators> faces;
  std::unique_ptr<geometrycentral::PositiveDefiniteSolver<double>> heatSolver, poissonSolver;
};

} // namespace cscd
