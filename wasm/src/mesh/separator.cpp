#include "mesh/separator.h"

#include "cscd/stage_clock.h"
#include "cscd/target.h"
#include "mesh/boundary.h"
#include "cscd/measures.h"

#include <algorithm>

using namespace geometrycentral;
using namespace geometrycentral::surface;

namespace cscd {
namespace {

// An intrinsic vertex path as a polyline on the input surface (each intrinsic edge traced across it).
std::vector<Vector3> tracePolyline(Surface& surface, const std::vector<size_t>& vertices, bool closed) {
  IntrinsicTriangulation& intrinsic = surface.intrinsic();
  std::vector<Vector3> points;
  const size_t steps = closed ? vertices.size() : vertices.size() - 1;
  for (size_t i = 0; i < steps; i++) {
    Halfedge he = intrinsicHalfedge(*intrinsic.intrinsicMesh, vertices[i], vertices[(i + 1) % vertices.size()]);
    std::vector<SurfacePoint> trace = intrinsic.traceIntrinsicHalfedgeAlongInput(he);
    for (size_t k = points.empty() ? 0 : 1; k < trace.size(); k++)
      points.push_back(trace[k].interpolate(surface.geometry().vertexPositions));
  }
  if (closed && points.size() > 1) points.pop_back(); // back at the first vertex
  return points;
}

double intrinsicLength(Surface& surface, const std::vector<size_t>& loop, bool closed) {
  IntrinsicTriangulation& intrinsic = surface.intrinsic();
  intrinsic.requireEdgeLengths();
  double length = 0;
  for (size_t i = 0; i + (closed ? 0 : 1) < loop.size(); i++)
    length += intrinsic.edgeLengths[intrinsicHalfedge(*intrinsic.intrinsicMesh, loop[i], loop[(i + 1) % loop.size()]).edge()];
  return length;
}

SeparatorResult& fail(SeparatorResult& result, SeparatorStatus status, std::string message) {
  result.status = status;
  result.message = std::move(message);
  return result;
}

} // namespace

// Boundary extremities are minima of the distance along the boundary within this many mean edge
// lengths on either side.
constexpr double kExtremityWindow = 3;

namespace {

// Where a separator can pass: a cut-locus target (a loop) or two boundary extremities (a path).
struct Extremity {
  double key; // targetKey of the target, or of the farther boundary end
  size_t target;
  std::optional<std::array<size_t, 2>> ends;
};

// Cut-locus targets and boundary pairs together, nearest first (ties: cut-locus targets first).
std::vector<Extremity> rankExtremities(Surface& surface, size_t source, const Options& options, SeparatorResult& result) {
  VertexPositionGeometry& geometry = surface.geometry();
  std::vector<Extremity> ranked;
  for (size_t t : rankTargets(result.cutLocus, result.distance, geometry.vertexPositions, source, options.target, kMinDetour))
    ranked.push_back({targetKey(geometry.vertexPositions, result.distance, source, t, options.target), t, std::nullopt});

  std::vector<BoundaryExtremity> extremities =
      boundaryExtremities(surface.boundaryLoops(), geometry, result.distance,
                          kExtremityWindow * surface.facts().meanEdgeLength);
  for (const BoundaryExtremity& e : extremities) result.boundaryExtremities.push_back(e.vertex);
  // The winding-number test costs a pass over the faces: only made when two loops have extremities.
  bool severalLoops = std::any_of(extremities.begin(), extremities.end(),
                                  [&](const BoundaryExtremity& e) { return e.loop != extremities.front().loop; });
  bool acrossLoops = severalLoops && sheetAround(geometry, surface.winding(), source, kExtremityWindow * surface.facts().meanEdgeLength);
  for (const BoundaryPair& pair :
       opposedExtremities(extremities, geometry, result.distance, source, options.target, acrossLoops))
    ranked.push_back({pair.key, pair.ends[0], pair.ends});
  std::stable_sort(ranked.begin(), ranked.end(), [](const Extremity& a, const Extremity& b) { return a.key < b.key; });
  return ranked;
}

// Trace, constrain and shorten the loop (or path) through one extremity; returns the failure status,
// or Ok. Every per-attempt field is set afresh, so a result never mixes two attempts.
SeparatorStatus loopThrough(Surface& surface, size_t source, const Extremity& extremity, const Options& options,
                        SeparatorResult& result, ShortenedLoop& shortened) {
  result.target = extremity.ends ? std::nullopt : std::optional<size_t>(extremity.target);
  result.ends = extremity.ends;
  result.closed = !extremity.ends;
  result.firstPath.clear();
  result.secondPath.clear();
  result.approxLoop.clear();
  result.approxLength = 0;
  result.sphere.reset();
  ManifoldSurfaceMesh& intrinsicMesh = *surface.intrinsic().intrinsicMesh;
  result.traced = extremity.ends
                      ? traceApproximatePath(intrinsicMesh, result.distance, *extremity.ends, source)
                      : traceApproximateLoop(intrinsicMesh, result.distance, result.cutLocus, extremity.target, source);
  if (!result.traced.failure.empty()) {
    result.message = result.traced.failure;
    return SeparatorStatus::TraceFailed;
  }
  result.firstPath = tracePolyline(surface, result.traced.firstPath, false);
  result.secondPath = tracePolyline(surface, result.traced.secondPath, false);
  result.approxLoop = tracePolyline(surface, result.traced.loop, result.closed);
  result.approxLength = intrinsicLength(surface, result.traced.loop, result.closed);

  // The sphere reaches exactly the farthest point of the approximate loop (paper Sec. 4.1.6).
  if (options.sphere) {
    const Vector3 center = surface.geometry().vertexPositions[source];
    double radius = 0;
    for (const Vector3& p : result.approxLoop) radius = std::max(radius, norm(p - center));
    result.sphere = Sphere{center, radius};
  }
  shortened = shortenLoop(surface.intrinsic(), surface.patchBuilder(), result.traced.loop, result.closed, result.sphere);
  result.message = shortened.failure;
  if (shortened.failureKind != ShortenedLoop::Failure::None)
    return shortened.failureKind == ShortenedLoop::Failure::Degenerate ? SeparatorStatus::DegenerateLoop
                                                                        : SeparatorStatus::ShortenFailed;
  // Both ends on one boundary loop separate the surface, but not always the constraint region: the
  // boundary may leave the sphere between them. Then the sides (and the score) are not defined.
  if (!result.closed && !(shortened.areas[0] > 0)) {
    result.message = "the path between the boundary ends does not separate the region around the source";
    return SeparatorStatus::NotSeparating;
  }
  return SeparatorStatus::Ok;
}

} // namespace

SeparatorResult computeSeparator(Surface& surface, size_t source, const Options& options, bool everyAngle) {
  SeparatorResult result;
  result.source = source;
  StageClock clock(result.timings);

  result.distance = surface.geodesics().fromVertex(source);
  clock.lap("distance");

  const CutLocusSolver& cutLocusSolver = surface.cutLocusSolver();
  CutLocusOptions cutLocusOptions = cutLocusOptionsOf(options);
  cutLocusOptions.everyAngle = everyAngle;
  result.cutLocus = cutLocusSolver.compute(result.distance, source, cutLocusOptions);
  clock.lap("cutLocus");

  std::vector<Extremity> extremities = rankExtremities(surface, source, options, result);
  clock.lap("target");
  if (extremities.empty()) {
    if (result.cutLocus.vertices.empty() && result.boundaryExtremities.empty())
      return fail(result, SeparatorStatus::NoCutLocus, "no cut locus was found for this source");
    return fail(result, SeparatorStatus::NoTarget, "no point of the cut locus is reached around a feature, and no two boundary points face each other");
  }

  // The paper's target is the nearest; should its loop enclose nothing (a spurious ridge), farther ones
  // are tried, each clearly farther than the last failure.
  ShortenedLoop shortened;
  SeparatorStatus status = SeparatorStatus::Ok;
  double lastFailedKey = 0;
  for (size_t i = 0; i < extremities.size() && result.attempts < kMaxTargets; i++) {
    if (result.attempts > 0 && extremities[i].key < kFallbackGrowth * lastFailedKey) continue;
    result.attempts++;
    status = loopThrough(surface, source, extremities[i], options, result, shortened);
    if (status == SeparatorStatus::Ok) break;
    lastFailedKey = extremities[i].key;
  }
  clock.lap("loop");
  if (status != SeparatorStatus::Ok) return fail(result, status, result.message);

  for (const SurfacePoint& p : shortened.loop) result.loop.push_back(p.interpolate(surface.geometry().vertexPositions));
  result.loopPoints = std::move(shortened.loop);
  result.length = shortened.length;
  result.areas = shortened.areas;
  result.score = separatorScore(result.areas, result.length);
  // The test drops loops that wind around the outside of a concave bend. A path ending on the boundary
  // lies across a sheet, which has no inside (its winding number is about 0 everywhere): it passes.
  result.centroidInside = !result.closed || surface.winding()(loopCentroid(result.loop, true)) > 0.5;
  clock.lap("measures");
  return result;
}

} // namespace cscd
