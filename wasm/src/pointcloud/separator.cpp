#include "pointcloud/separator.h"

#include "cscd/measures.h"
#include "cscd/stage_clock.h"
#include "cscd/target.h"
#include "pointcloud/shorten.h"
#include "pointcloud/target.h"
#include "pointcloud/trace.h"
#include "pointcloud/winding.h"

#include <algorithm>

namespace cscd {
namespace {

CloudSeparatorStages& fail(CloudSeparatorStages& result, SeparatorStatus status, std::string message) {
  result.status = status;
  result.message = std::move(message);
  return result;
}

// Trace the loop through one target and shorten it (unless `shorten` is false); returns the failure
// status, or Ok. Every per-attempt field is set afresh, so a result never mixes two attempts.
SeparatorStatus loopThrough(Cloud& cloud, PathsToSource& toSource, const CloudTarget& target, const Options& options,
                            bool shorten, int recordFrames, CloudSeparatorStages& result) {
  const size_t source = toSource.source();
  const CloudNeighbourhood& neighbourhood = cloud.neighbourhood();
  result.target = target.point;
  result.sphere.reset();
  result.loop.clear();
  result.iterates.clear();
  result.iterations = 0;
  result.traced = traceCloudLoop(neighbourhood.graph(), result.distance, target.point, target.starts, toSource);
  result.message = result.traced.failure;
  if (!result.traced.failure.empty()) return SeparatorStatus::TraceFailed;
  if (!shorten) return SeparatorStatus::Ok;

  std::vector<geometrycentral::Vector3> approximate;
  for (size_t p : result.traced.loop) approximate.push_back(neighbourhood.position(p));
  if (options.sphere) {
    const geometrycentral::Vector3 centre = neighbourhood.position(source);
    double radius = 0;
    for (const geometrycentral::Vector3& p : approximate) radius = std::max(radius, norm(p - centre));
    result.sphere = Sphere{centre, radius};
  }
  if (approximate.size() < 3) {
    result.message = "the approximate loop has fewer than 3 points";
    return SeparatorStatus::DegenerateLoop;
  }
  ShortenedCloudLoop shortened = shortenLoop(cloud, approximate, result.sphere, recordFrames);
  result.iterations = shortened.iterations;
  result.iterates = std::move(shortened.iterates);
  result.message = shortened.failure;
  if (shortened.failureKind == ShortenedCloudLoop::Failure::Degenerate) return SeparatorStatus::DegenerateLoop;
  if (shortened.failureKind == ShortenedCloudLoop::Failure::NotConverged) return SeparatorStatus::ShortenFailed;
  result.loop = std::move(shortened.loop);
  result.length = shortened.length;
  result.areas = shortened.areas;
  return SeparatorStatus::Ok;
}

} // namespace

CloudSeparatorStages computeCloudSeparatorStages(Cloud& cloud, size_t source, const Options& options, bool shorten,
                                                 int recordFrames, bool everyAngle) {
  CloudSeparatorStages result;
  result.source = source;
  StageClock clock(result.timings);

  result.distance = cloud.geodesics().fromPoint(source);
  clock.lap("distance");

  const CloudCutLocusSolver& solver = cloud.cutLocusSolver();
  CutLocusOptions cutLocusOptions = cutLocusOptionsOf(options);
  cutLocusOptions.everyAngle = everyAngle;
  result.cutLocus = solver.compute(result.distance, source, cutLocusOptions);
  clock.lap("cutLocus");

  const CloudNeighbourhood& neighbourhood = cloud.neighbourhood();
  const std::vector<CloudTarget> targets =
      rankCloudTargets(neighbourhood, solver, result.cutLocus, result.distance, source, options.target);
  for (const CloudTarget& t : targets) result.targets.push_back(t.point);
  clock.lap("target");
  if (targets.empty()) {
    if (result.cutLocus.graph.vertices.size() <= 1)
      return fail(result, SeparatorStatus::NoCutLocus, "no cut locus was found for this source");
    return fail(result, SeparatorStatus::NoTarget,
                "no point of the cut locus is reached around a feature with opposite gradients on its two sides");
  }

  // The paper's target is the nearest; when its descents make no loop, the next is traced. On a noisy
  // cloud most of the nearest targets are ridges of the noise, whose loops enclose nothing: there, as on a
  // mesh, a failed loop of any kind sends the search on to a target clearly farther than the failure
  // (docs/pointcloud.md, "Noisy clouds"). A clean cloud's failed loop ends the search: farther targets
  // made its skeletons worse (fewer sources in auto mode).
  const bool fallBack = neighbourhood.noisyCloud();
  SeparatorStatus status = SeparatorStatus::Ok;
  double lastFailedKey = 0;
  PathsToSource toSource(neighbourhood.graph(), neighbourhood.positions(), source);
  for (const CloudTarget& t : targets) {
    if (result.attempts == kMaxTargets) break;
    const double key = targetKey(neighbourhood.positions(), result.distance, source, t.point, options.target);
    if (fallBack && result.attempts > 0 && key < kFallbackGrowth * lastFailedKey) continue;
    result.attempts++;
    status = loopThrough(cloud, toSource, t, options, shorten, recordFrames, result);
    if (status == SeparatorStatus::Ok || (!fallBack && status != SeparatorStatus::TraceFailed)) break;
    lastFailedKey = key;
  }
  clock.lap("loop");
  if (status != SeparatorStatus::Ok) return fail(result, status, result.message);
  if (!shorten) return result;

  result.score = separatorScore(result.areas, result.length);
  result.centroidInside = cloud.loopInside(result.loop);
  clock.lap("measures");
  return result;
}

} // namespace cscd
