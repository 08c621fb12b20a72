#include "mesh/geodesics.h"

#include "geometrycentral/surface/exact_geodesics.h"

#include <cmath>
#include <map>

using namespace geometrycentral;
using namespace geometrycentral::surface;

namespace cscd {

Geodesics::Geodesics(IntrinsicTriangulation& intrinsic_, std::vector<int> vertexComponent_)
    : intrinsic(intrinsic_), vertexComponent(std::move(vertexComponent_)) {
  intrinsic.requireEdgeLengths();
  intrinsic.requireVertexIndices();
  intrinsic.requireHalfedgeCotanWeights();
  intrinsic.requireHalfedgeVectorsInFace();
  intrinsic.requireVertexLumpedMassMatrix();
  intrinsic.requireCotanLaplacian();
  SurfaceMesh& mesh = intrinsic.mesh;

  double meanEdgeLength = 0;
  for (Edge e : mesh.edges()) meanEdgeLength += intrinsic.edgeLengths[e];
  meanEdgeLength /= mesh.nEdges();
  const double shortTime = meanEdgeLength * meanEdgeLength;
  SparseMatrix<double>& L = intrinsic.cotanLaplacian;
  SparseMatrix<double> heatOperator = intrinsic.vertexLumpedMassMatrix + shortTime * L;
  heatSolver = std::make_unique<PositiveDefiniteSolver<double>>(heatOperator);
  // The cotan Laplacian is only semidefinite: the shift makes Eigen's Cholesky factorization work.
  SparseMatrix<double> shifted = L + 1e-6 * identityMatrix<double>(mesh.nVertices());
  poissonSolver = std::make_unique<PositiveDefiniteSolver<double>>(shifted);

  for (Face f : mesh.faces()) {
    FaceOperators& ops = faces.emplace_back();
    int k = 0;
    for (Halfedge he : f.adjacentHalfedges()) {
      ops.vertex[k] = intrinsic.vertexIndices[he.vertex()];
      ops.heatGradient[k] = intrinsic.halfedgeVectorsInFace[he.next()].rotate90();
      ops.halfedge[k] = intrinsic.halfedgeVectorsInFace[he];
      ops.cotanWeight[k] = intrinsic.halfedgeCotanWeights[he];
      k++;
    }
  }
  intrinsic.unrequireHalfedgeCotanWeights();
  intrinsic.unrequireHalfedgeVectorsInFace();
  intrinsic.unrequireVertexLumpedMassMatrix();
  intrinsic.unrequireCotanLaplacian();
}

std::vector<double> Geodesics::fromVertex(size_t vertex) {
  return fromPoints({SurfacePoint(intrinsic.inputMesh.vertex(vertex))});
}

std::vector<double> Geodesics::exactFromVertex(size_t vertex) {
  VertexData<double> exact = exactGeodesicDistance(intrinsic.inputMesh, intrinsic.inputGeom, intrinsic.inputMesh.vertex(vertex));
  std::vector<double> distance(vertexComponent.size(), INFINITY);
  for (size_t v = 0; v < distance.size(); v++)
    if (vertexComponent[v] == vertexComponent[vertex]) distance[v] = exact[v];
  return distance;
}

std::vector<double> Geodesics::fromPoints(const std::vector<SurfacePoint>& pointsOnInput) {
  // The heat method fixes one additive constant for the whole solve, which is only right within one
  // connected component: solve once per component that holds a source.
  std::map<int, std::vector<SurfacePoint>> sourcesByComponent;
  for (const SurfacePoint& p : pointsOnInput) {
    SurfacePoint onIntrinsic = intrinsic.equivalentPointOnIntrinsic(p);
    Vertex anyVertex = onIntrinsic.inSomeFace().face.halfedge().vertex();
    sourcesByComponent[vertexComponent[anyVertex.getIndex()]].push_back(onIntrinsic);
  }

  std::vector<double> distance(vertexComponent.size(), INFINITY);
  for (const auto& [component, sources] : sourcesByComponent) {
    std::vector<double> solved = solve(sources);
    for (size_t v = 0; v < distance.size(); v++)
      if (vertexComponent[v] == component) distance[v] = std::max(0.0, solved[v]);
  }
  return distance;
}

std::vector<double> Geodesics::solve(const std::vector<SurfacePoint>& sources) {
  // Heat from the sources, spread to the corners of their faces by barycentric weight.
  Vector<double> heatSource = Vector<double>::Zero(vertexComponent.size());
  for (const SurfacePoint& p : sources) {
    SurfacePoint inFace = p.inSomeFace();
    Halfedge he = inFace.face.halfedge();
    heatSource[intrinsic.vertexIndices[he.vertex()]] += inFace.faceCoords.x;
    heatSource[intrinsic.vertexIndices[he.next().vertex()]] += inFace.faceCoords.y;
    heatSource[intrinsic.vertexIndices[he.next().next().vertex()]] += inFace.faceCoords.z;
  }
  Vector<double> heat = heatSolver->solve(heatSource);

  // Divergence of the heat gradient normalised per face (its magnitude does not matter).
  Vector<double> divergence = Vector<double>::Zero(vertexComponent.size());
  for (const FaceOperators& ops : faces) {
    Vector2 direction = Vector2::zero();
    for (int k = 0; k < 3; k++) direction += ops.heatGradient[k] * heat(ops.vertex[k]);
    direction = direction.normalizeCutoff();
    for (int k = 0; k < 3; k++) {
      double value = ops.cotanWeight[k] * dot(ops.halfedge[k], direction);
      divergence[ops.vertex[k]] += value;
      divergence[ops.vertex[(k + 1) % 3]] += -value;
    }
  }
  Vector<double> distance = poissonSolver->solve(divergence);

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
    std::array<double, 3> edgeLengths{intrinsic.edgeLengths[he0.edge()], intrinsic.edgeLengths[he0.next().edge()],
                                      intrinsic.edgeLengths[he0.next().next().edge()]};
    int i = 0;
    for (Halfedge he : inFace.face.adjacentHalfedges()) {
      Vector3 corner = Vector3::zero();
      corner[i] = 1.;
      double w = inFace.faceCoords[i];
      offset += (distance[intrinsic.vertexIndices[he.vertex()]] - baryDistance(inFace.faceCoords, corner, edgeLengths)) * w;
      weightSum += w;
      i++;
    }
  }
  offset /= weightSum;
  const double shift = -offset;
  distance = distance.array() + shift;
  return std::vector<double>(distance.data(), distance.data() + distance.size());
}

} // namespace cscd
