#include "mesh/separator.h"

#include "cscd/stage_clock.h"
#include "mesh/measures.h"
#include "mesh/target.h"

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

double intrinsicLength(Surface& surface, const std::vector<size_t>& loop) {
  IntrinsicTriangulation& intrinsic = surface.intrinsic();
  intrinsic.requireEdgeLengths();
  double length = 0;
  for (size_t i = 0; i < loop.size(); i++)
    length += intrinsic.edgeLengths[intrinsicHalfedge(*intrinsic.intrinsicMesh, loop[i], loop[(i + 1) % loop.size()]).edge()];
  return length;
}

SeparatorResult& fail(SeparatorResult& result, const char* status, std::string message) {
  result.status = status;
  result.message = std::move(message);
  return result;
}

} // namespace

// Targets must be reached by a detour: geodesic >= 1.2 x Euclidean distance (see rankTargets).
constexpr double kMinDetour = 1.2;
// When a target's loop is degenerate, the next target tried is at least this much farther away...
constexpr double kFallbackGrowth = 1.5;
// ...up to this many targets in all.
constexpr int kMaxTargets = 6;

namespace {

// Trace, constrain and shorten the loop of one target; returns the failure status, or "" on success.
// Every per-target field is set afresh, so a result never mixes two attempts.
const char* loopThroughTarget(Surface& surface, size_t source, size_t target, const Options& options,
                              SeparatorResult& result, ShortenedLoop& shortened) {
  result.target = target;
  result.firstPath.clear();
  result.secondPath.clear();
  result.approxLoop.clear();
  result.approxLength = 0;
  result.sphere.reset();
  result.traced = traceApproximateLoop(*surface.intrinsic().intrinsicMesh, result.distance, result.cutLocus, target, source);
  if (!result.traced.failure.empty()) {
    result.message = result.traced.failure;
    return "trace-failed";
  }
  result.firstPath = tracePolyline(surface, result.traced.firstPath, false);
  result.secondPath = tracePolyline(surface, result.traced.secondPath, false);
  result.approxLoop = tracePolyline(surface, result.traced.loop, true);
  result.approxLength = intrinsicLength(surface, result.traced.loop);

  // The sphere reaches exactly the farthest point of the approximate loop (paper Sec. 4.1.6).
  if (options.sphere) {
    const Vector3 center = surface.geometry().vertexPositions[source];
    double radius = 0;
    for (const Vector3& p : result.approxLoop) radius = std::max(radius, norm(p - center));
    result.sphere = Sphere{center, radius};
  }
  shortened = shortenLoop(surface.intrinsic(), surface.geometry(), result.traced.loop, result.sphere);
  result.message = shortened.failure;
  if (shortened.failure.empty()) return "";
  return shortened.failure.rfind("the loop shrank", 0) == 0 ? "degenerate-loop" : "shorten-failed";
}

} // namespace

SeparatorResult computeSeparator(Surface& surface, size_t source, const Options& options) {
  SeparatorResult result;
  result.source = source;
  StageClock clock(result.timings);

  result.distance = surface.geodesics().fromVertex(source);
  clock.lap("distance");

  const CutLocusSolver& cutLocusSolver = surface.cutLocusSolver();
  CutLocusOptions cutLocusOptions;
  cutLocusOptions.angleThreshold = options.angleThreshold;
  cutLocusOptions.laplacianThreshold = options.laplacianThreshold;
  cutLocusOptions.pruneDepth = options.pruneDepth;
  result.cutLocus = cutLocusSolver.compute(result.distance, source, cutLocusOptions);
  clock.lap("cutLocus");
  if (result.cutLocus.vertices.empty()) return fail(result, "no-cut-locus", "no cut locus was found for this source");

  std::vector<size_t> targets = rankTargets(result.cutLocus, result.distance, surface.geometry(), source,
                                            options.target, kMinDetour);
  clock.lap("target");
  if (targets.empty()) return fail(result, "no-target", "no point of the cut locus is reached around a feature");

  // The paper's target is the nearest; should its loop enclose nothing (a spurious ridge), farther ones
  // are tried, each clearly farther than the last failure.
  ShortenedLoop shortened;
  const char* status = "";
  double lastFailedKey = 0;
  for (size_t i = 0; i < targets.size() && result.attempts < kMaxTargets; i++) {
    double key = targetKey(surface.geometry(), result.distance, source, targets[i], options.target);
    if (result.attempts > 0 && key < kFallbackGrowth * lastFailedKey) continue;
    result.attempts++;
    status = loopThroughTarget(surface, source, targets[i], options, result, shortened);
    if (!*status) break;
    lastFailedKey = key;
  }
  clock.lap("loop");
  if (*status) return fail(result, status, result.message);

  for (const SurfacePoint& p : shortened.loop) result.loop.push_back(p.interpolate(surface.geometry().vertexPositions));
  result.loopPoints = std::move(shortened.loop);
  result.length = shortened.length;
  result.areas = shortened.areas;
  result.score = separatorScore(result.areas, result.length);
  result.centroidInside = windingNumber(surface.geometry(), loopCentroid(result.loop)) > 0.5;
  clock.lap("measures");
  return result;
}

} // namespace cscd
