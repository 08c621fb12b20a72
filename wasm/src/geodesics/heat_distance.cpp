#include "geodesics/heat_distance.h"

#include "geometrycentral/numerical/linear_algebra_utilities.h"

#include <algorithm>
#include <cmath>
#include <map>

using namespace geometrycentral;
using namespace geometrycentral::surface;

namespace cscd {

HeatDistance::HeatDistance(IntrinsicGeometryInterface& geometry_, std::vector<int> vertexComponent_)
    : geometry(geometry_), vertexComponent(std::move(vertexComponent_)) {
  geometry.requireEdgeLengths();
  geometry.requireVertexIndices();
  geometry.requireHalfedgeCotanWeights();
  geometry.requireHalfedgeVectorsInFace();
  geometry.requireVertexLumpedMassMatrix();
  geometry.requireCotanLaplacian();
  SurfaceMesh& mesh = geometry.mesh;

  double meanEdgeLength = 0;
  for (Edge e : mesh.edges()) meanEdgeLength += geometry.edgeLengths[e];
  meanEdgeLength /= mesh.nEdges();
  const double shortTime = meanEdgeLength * meanEdgeLength;
  SparseMatrix<double>& L = geometry.cotanLaplacian;
  SparseMatrix<double> heatOperator = geometry.vertexLumpedMassMatrix + shortTime * L;
  heatSolver = std::make_unique<OrderedLDLT>(heatOperator);
  // The cotan Laplacian is only semidefinite: the shift makes Eigen's Cholesky factorization work.
  SparseMatrix<double> shifted = L + 1e-6 * identityMatrix<double>(mesh.nVertices());
  poissonSolver = std::make_unique<OrderedLDLT>(shifted);

  for (Face f : mesh.faces()) {
    FaceOperators& ops = faces.emplace_back();
    int k = 0;
    for (Halfedge he : f.adjacentHalfedges()) {
      const size_t vertex = geometry.vertexIndices[he.vertex()];
      ops.inHeat[k] = heatSolver->position(vertex);
      ops.inPoisson[k] = poissonSolver->position(vertex);
      ops.heatGradient[k] = geometry.halfedgeVectorsInFace[he.next()].rotate90();
      ops.halfedge[k] = geometry.halfedgeVectorsInFace[he];
      ops.cotanWeight[k] = geometry.halfedgeCotanWeights[he];
      k++;
    }
  }
  geometry.unrequireHalfedgeCotanWeights();
  geometry.unrequireHalfedgeVectorsInFace();
  geometry.unrequireVertexLumpedMassMatrix();
  geometry.unrequireCotanLaplacian();
}

std::vector<double> HeatDistance::fromPoints(const std::vector<SurfacePoint>& sources) {
  // The heat method fixes one additive constant for the whole solve, which is only right within one
  // connected component: solve once per component that holds a source.
  std::map<int, std::vector<SurfacePoint>> sourcesByComponent;
  for (const SurfacePoint& p : sources) {
    Vertex anyVertex = p.inSomeFace().face.halfedge().vertex();
    sourcesByComponent[vertexComponent[anyVertex.getIndex()]].push_back(p);
  }
  std::vector<double> distance(vertexComponent.size(), INFINITY);
  for (const auto& [component, inComponent] : sourcesByComponent) {
    std::vector<double> solved = solve(inComponent);
    for (size_t v = 0; v < distance.size(); v++)
      if (vertexComponent[v] == component) distance[v] = std::max(0.0, solved[v]);
  }
  return distance;
}

std::vector<double> HeatDistance::solve(const std::vector<SurfacePoint>& sources) {
  // Heat from the sources, spread to the corners of their faces by barycentric weight.
  auto heatAt = [&](Vertex v) { return heatSolver->position(geometry.vertexIndices[v]); };
  Eigen::VectorXd heat = Eigen::VectorXd::Zero(vertexComponent.size());
  for (const SurfacePoint& p : sources) {
    SurfacePoint inFace = p.inSomeFace();
    Halfedge he = inFace.face.halfedge();
    heat[heatAt(he.vertex())] += inFace.faceCoords.x;
    heat[heatAt(he.next().vertex())] += inFace.faceCoords.y;
    heat[heatAt(he.next().next().vertex())] += inFace.faceCoords.z;
  }
  heatSolver->solveInPlace(heat);

  // Divergence of the heat gradient normalised per face (its magnitude does not matter).
  Eigen::VectorXd distance = Eigen::VectorXd::Zero(vertexComponent.size());
  for (const FaceOperators& ops : faces) {
    Vector2 direction = Vector2::zero();
    for (int k = 0; k < 3; k++) direction += ops.heatGradient[k] * heat[ops.inHeat[k]];
    direction = direction.normalizeCutoff();
    for (int k = 0; k < 3; k++) {
      double value = ops.cotanWeight[k] * dot(ops.halfedge[k], direction);
      distance[ops.inPoisson[k]] += value;
      distance[ops.inPoisson[(k + 1) % 3]] += -value;
    }
  }
  poissonSolver->solveInPlace(distance);
  auto distanceAt = [&](Vertex v) { return distance[poissonSolver->position(geometry.vertexIndices[v])]; };

  // Poisson fixes the distance up to a constant: the one that makes it right at the sources, by the
  // exact distance from a point of a triangle to its corners (Schindler & Chen 2012, Sec. 3.2).
  auto baryDistance = [](Vector3 from, Vector3 to, const std::array<double, 3>& edgeLengths) {
    Vector3 d = to - from;
    double d2 = 0;
    for (int i = 0; i < 3; i++) d2 += edgeLengths[i] * edgeLengths[i] * d[i] * d[(i + 1) % 3];
    if (!(d2 <= 0)) d2 = 0.;
    return std::sqrt(-d2);
  };
  double offset = 0, weightSum = 0;
  for (const SurfacePoint& p : sources) {
    SurfacePoint inFace = p.inSomeFace();
    Halfedge he0 = inFace.face.halfedge();
    std::array<double, 3> edgeLengths{geometry.edgeLengths[he0.edge()], geometry.edgeLengths[he0.next().edge()],
                                      geometry.edgeLengths[he0.next().next().edge()]};
    int i = 0;
    for (Halfedge he : inFace.face.adjacentHalfedges()) {
      Vector3 corner = Vector3::zero();
      corner[i] = 1.;
      double w = inFace.faceCoords[i];
      offset += (distanceAt(he.vertex()) - baryDistance(inFace.faceCoords, corner, edgeLengths)) * w;
      weightSum += w;
      i++;
    }
  }
  offset /= weightSum;
  const double shift = -offset;
  std::vector<double> byVertex(vertexComponent.size());
  for (size_t v = 0; v < byVertex.size(); v++) byVertex[v] = distance[poissonSolver->position(v)] + shift;
  return byVertex;
}

} // namespace cscd
