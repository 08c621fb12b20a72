#include "mesh/realization.h"

#include "cscd/centre.h"
#include "evaluate/tube_radii.h"
#include "cscd/measures.h"
#include "cscd/overlap.h"
#include "mesh/regions.h"
#include "mesh/separator.h"

#include <algorithm>
#include <cmath>

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

// The surface's input mesh as plain arrays (closest points, tube radii).
TriangleMesh triangleMeshOf(Surface& surface) {
  TriangleMesh mesh;
  const auto& geometry = surface.geometry();
  for (size_t v = 0; v < surface.vertexCount(); v++) mesh.vertices.push_back(geometry.vertexPositions[v]);
  for (auto f : surface.mesh().faces()) {
    std::array<uint32_t, 3> t;
    size_t k = 0;
    for (auto v : f.adjacentVertices()) t[k++] = uint32_t(v.getIndex());
    mesh.triangles.push_back(t);
  }
  return mesh;
}

SourceSampler samplerOf(const Samples& samples, double diagonal, uint32_t seed) {
  return SourceSampler(samples.positions, samples.weights, diagonal, seed);
}

// Barycentric coordinates of p (a point of triangle abc) on its corners.
geometrycentral::Vector3 barycentric(const geometrycentral::Vector3& p, const geometrycentral::Vector3& a,
                                     const geometrycentral::Vector3& b, const geometrycentral::Vector3& c) {
  const geometrycentral::Vector3 ab = b - a, ac = c - a, ap = p - a;
  const double d00 = dot(ab, ab), d01 = dot(ab, ac), d11 = dot(ac, ac), d20 = dot(ap, ab), d21 = dot(ap, ac);
  const double det = d00 * d11 - d01 * d01;
  if (!(det > 0)) return {1, 0, 0};
  const double v = std::clamp((d11 * d20 - d01 * d21) / det, 0.0, 1.0);
  const double w = std::clamp((d00 * d21 - d01 * d20) / det, 0.0, 1.0 - v);
  return {1 - v - w, v, w};
}

} // namespace

MeshRealization::MeshRealization(Surface& surface_, const Options& options_, Surface* working_)
    : surface(surface_), working(working_ ? *working_ : surface_), options(options_), vertexSamples(vertexSamplesOf(surface_)),
      sampler(samplerOf(working_ ? vertexSamplesOf(*working_) : vertexSamples, working.facts().bboxDiagonal, options_.seed)) {
  if (&working == &surface) return;
  TriangleMesh mesh = triangleMeshOf(surface);
  closestFace = std::make_unique<TriangleTree>(std::move(mesh.vertices), std::move(mesh.triangles));
}

MeshRealization::Candidate MeshRealization::separator(size_t source) {
  SeparatorResult result = computeSeparator(working, source, options, /*everyAngle=*/false);
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
  covered.emplace_back(working.mesh().vertex(source));
  candidate.reach = working.geodesics().fromPoints(covered);
  return candidate;
}

double MeshRealization::coverage() const { return sampler.coverage(kCoverageRadius * working.facts().bboxDiagonal); }

std::vector<std::vector<size_t>> MeshRealization::overlaps(const Selection<Candidate>& kept) const {
  std::vector<std::vector<geometrycentral::Vector3>> loops;
  std::vector<char> closed;
  for (const Candidate* c : kept) {
    loops.push_back(c->loop);
    closed.push_back(c->closed);
  }
  // In edges of the mesh the regions grow on (see kOverlapTolerance), whichever mesh the loops came from.
  return overlappingLoops(loops, closed, kOverlapTolerance * surface.facts().meanEdgeLength);
}

std::vector<geometrycentral::surface::SurfacePoint> MeshRealization::pointsOnSurface(const Candidate& candidate) const {
  if (!closestFace) return candidate.points;
  const double step = 0.5 * surface.facts().meanEdgeLength;
  const auto& loop = candidate.loop;
  std::vector<geometrycentral::surface::SurfacePoint> points;
  auto add = [&](const geometrycentral::Vector3& p) {
    const TriangleTree::Hit hit = closestFace->closest(p);
    const auto& corner = vertexSamples.positions;
    auto f = surface.mesh().face(hit.primitive);
    geometrycentral::Vector3 at[3];
    size_t k = 0;
    for (auto v : f.adjacentVertices()) at[k++] = corner[v.getIndex()];
    points.emplace_back(f, barycentric(hit.point, at[0], at[1], at[2]));
  };
  const size_t segments = candidate.closed ? loop.size() : loop.size() - 1;
  if (loop.size() == 1) add(loop[0]);
  for (size_t i = 0; i < segments && loop.size() > 1; i++) {
    const geometrycentral::Vector3 &a = loop[i], &b = loop[(i + 1) % loop.size()];
    const size_t steps = std::max<size_t>(1, size_t(std::ceil(norm(b - a) / step)));
    for (size_t j = 0; j < steps; j++) add(a + (b - a) * (double(j) / steps));
  }
  if (!candidate.closed && loop.size() > 1) add(loop.back());
  return points;
}

Regions MeshRealization::regions(const Selection<Candidate>& packed) {
  std::vector<std::vector<geometrycentral::surface::SurfacePoint>> points;
  for (const Candidate* c : packed) points.push_back(pointsOnSurface(*c));
  return assignRegions(surface, vertexSamples, points);
}

geometrycentral::Vector3 MeshRealization::separatorNormal(const Candidate& candidate) const {
  if (candidate.closed) return loopNormal(candidate.loop);
  auto& geometry = working.geometry(); // the path's points are on the working surface
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
  const TriangleMesh mesh = triangleMeshOf(surface);
  SkeletonCurves curves{graph.nodes, {}, {}};
  for (const auto& e : graph.edges) curves.edges.push_back({uint32_t(e[0]), uint32_t(e[1])});
  graph.radii = tubeRadii(mesh, curves);
}

} // namespace cscd
