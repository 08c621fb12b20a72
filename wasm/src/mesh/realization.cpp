#include "mesh/realization.h"

#include "cscd/centre.h"
#include "evaluate/tube_radii.h"
#include "cscd/measures.h"
#include "cscd/overlap.h"
#include "mesh/regions.h"
#include "mesh/separator.h"

namespace cscd {

namespace {

Samples vertexSamplesOf(Surface& surface) {
  Samples samples;
  auto& geometry = surface.geometry();
  geometry.requireVertexDualAreas();
  for (size_t v = 0; v < surface.vertexCount(); v++) {
    samples.positions.push_back(geometry.vertexPositions[v]);
    samples.weights.push_back(geometry.vertexDualAreas[v]);
  }
  for (auto e : surface.mesh().edges())
    samples.edges.push_back({uint32_t(e.firstVertex().getIndex()), uint32_t(e.secondVertex().getIndex())});
  return samples;
}

} // namespace

MeshRealization::MeshRealization(Surface& surface_, const Options& options_)
    : surface(surface_), options(options_), vertexSamples(vertexSamplesOf(surface_)),
      sampler(vertexSamples.positions, vertexSamples.weights, surface_.facts().bboxDiagonal, options_.seed) {}

MeshRealization::Candidate MeshRealization::separator(size_t source) {
  SeparatorResult result = computeSeparator(surface, source, options, /*everyAngle=*/false);
  Candidate candidate;
  candidate.source = source;
  candidate.found = result.status == SeparatorStatus::Ok;
  candidate.loop = std::move(result.loop);
  candidate.closed = result.closed;
  candidate.length = result.length;
  candidate.score = result.score;
  candidate.centroidInside = result.centroidInside;
  candidate.points = std::move(result.loopPoints);
  std::vector<geometrycentral::surface::SurfacePoint> covered = candidate.points;
  covered.emplace_back(surface.mesh().vertex(source));
  candidate.reach = surface.geodesics().fromPoints(covered);
  return candidate;
}

double MeshRealization::coverage() const { return sampler.coverage(kCoverageRadius * surface.facts().bboxDiagonal); }

std::vector<std::vector<size_t>> MeshRealization::overlaps(const Selection<Candidate>& kept) const {
  std::vector<std::vector<geometrycentral::Vector3>> loops;
  std::vector<char> closed;
  for (const Candidate* c : kept) {
    loops.push_back(c->loop);
    closed.push_back(c->closed);
  }
  return overlappingLoops(loops, closed, kOverlapTolerance * surface.facts().meanEdgeLength);
}

Regions MeshRealization::regions(const Selection<Candidate>& packed) {
  std::vector<std::vector<geometrycentral::surface::SurfacePoint>> points;
  for (const Candidate* c : packed) points.push_back(c->points);
  return assignRegions(surface, vertexSamples, points);
}

geometrycentral::Vector3 MeshRealization::separatorNormal(const Candidate& candidate) const {
  if (candidate.closed) return loopNormal(candidate.loop);
  auto& geometry = surface.geometry();
  geometry.requireFaceNormals();
  geometrycentral::Vector3 surfaceNormal{0, 0, 0};
  for (const auto& p : candidate.points) surfaceNormal += geometry.faceNormals[p.inSomeFace().face];
  return pathNormal(candidate.loop, surfaceNormal);
}

bool MeshRealization::inside(const geometrycentral::Vector3& p) const { return surface.winding()(p) > 0.5; }

void MeshRealization::centre(SkeletonGraph& graph, const Selection<Candidate>& packed) const {
  centreNodes(graph, packed, [&](const Candidate& c) { return separatorNormal(c); },
              [&](const geometrycentral::Vector3& p) { return inside(p); });
}

void MeshRealization::fitRadii(SkeletonGraph& graph) const {
  TriangleMesh mesh;
  const auto& geometry = surface.geometry();
  for (size_t v = 0; v < surface.vertexCount(); v++) mesh.vertices.push_back(geometry.vertexPositions[v]);
  for (auto f : surface.mesh().faces()) {
    std::array<uint32_t, 3> t;
    size_t k = 0;
    for (auto v : f.adjacentVertices()) t[k++] = uint32_t(v.getIndex());
    mesh.triangles.push_back(t);
  }
  SkeletonCurves curves{graph.nodes, {}, {}};
  for (const auto& e : graph.edges) curves.edges.push_back({uint32_t(e[0]), uint32_t(e[1])});
  graph.radii = tubeRadii(mesh, curves);
}

} // namespace cscd
