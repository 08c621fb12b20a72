#include "geodesics/heat_distance.h"

#include "geometrycentral/numerical/linear_algebra_utilities.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>

using namespace geometrycentral;
using namespace geometrycentral::surface;

namespace cscd {

namespace {

// A cloud's tufted cover holds most triangles several times over (both sheets of each local triangulation
// that has it: 240,000 faces for 20,000 points, 65,000 distinct), and copies of one triangle, the same
// corners joined by edges of the same lengths, add the same divergence in every solve. Per face: how many
// copies it stands for (its weights are multiplied by that), 0 for a copy of an earlier face. A mesh's
// intrinsic triangulation has no copies (all 1).
std::vector<int> faceCopies(IntrinsicGeometryInterface& geometry) {
  struct Copy {
    std::array<double, 6> key; // the corners' vertex indices, increasing, and the lengths of the edges between them
    uint32_t face;
    bool operator<(const Copy& other) const { return std::tie(key, face) < std::tie(other.key, other.face); }
  };
  std::vector<Copy> distinctCorners;
  for (Face f : geometry.mesh.faces()) {
    std::array<size_t, 3> corner;
    std::array<double, 3> length; // of the edge from corner i to corner i + 1
    int k = 0;
    for (Halfedge he : f.adjacentHalfedges()) {
      corner[k] = geometry.vertexIndices[he.vertex()];
      length[k++] = geometry.edgeLengths[he.edge()];
    }
    if (corner[0] == corner[1] || corner[1] == corner[2] || corner[0] == corner[2]) continue;
    std::array<int, 3> order{0, 1, 2};
    std::sort(order.begin(), order.end(), [&](int i, int j) { return corner[i] < corner[j]; });
    auto between = [&](int i, int j) { return length[j == (i + 1) % 3 ? i : j]; };
    distinctCorners.push_back({{double(corner[order[0]]), double(corner[order[1]]), double(corner[order[2]]),
                                between(order[0], order[1]), between(order[1], order[2]), between(order[0], order[2])},
                               uint32_t(f.getIndex())});
  }
  std::sort(distinctCorners.begin(), distinctCorners.end());
  std::vector<int> copies(geometry.mesh.nFaces(), 1);
  for (size_t first = 0, next; first < distinctCorners.size(); first = next) {
    for (next = first + 1; next < distinctCorners.size() && distinctCorners[next].key == distinctCorners[first].key; next++)
      copies[distinctCorners[next].face] = 0;
    copies[distinctCorners[first].face] = int(next - first);
  }
  return copies;
}

} // namespace

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

  const std::vector<int> copies = faceCopies(geometry);
  for (Face f : mesh.faces()) {
    const int copiesOfFace = copies[f.getIndex()];
    if (copiesOfFace == 0) continue;
    FaceOperators& ops = faces.emplace_back();
    int k = 0;
    for (Halfedge he : f.adjacentHalfedges()) {
      const size_t vertex = geometry.vertexIndices[he.vertex()];
      ops.inHeat[k] = heatSolver->position(vertex);
      ops.inPoisson[k] = poissonSolver->position(vertex);
      ops.heatGradient[k] = geometry.halfedgeVectorsInFace[he.next()].rotate90();
      ops.halfedge[k] = geometry.halfedgeVectorsInFace[he];
      ops.cotanWeight[k] = copiesOfFace * geometry.halfedgeCotanWeights[he];
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
