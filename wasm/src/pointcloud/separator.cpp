#include "pointcloud/separator.h"

#include "cscd/measures.h"
#include "cscd/stage_clock.h"
#include "pointcloud/shorten.h"
#include "pointcloud/target.h"
#include "pointcloud/trace.h"
#include "pointcloud/winding.h"

#include <algorithm>

namespace cscd {
namespace {

// Targets tried at most, as on a mesh.
constexpr int kMaxTargets = 6;

CloudSeparatorStages& fail(CloudSeparatorStages& result, SeparatorStatus status, std::string message) {
  result.status = status;
  result.message = std::move(message);
  return result;
}

} // namespace

CloudSeparatorStages computeCloudSeparatorStages(Cloud& cloud, size_t source, const Options& options, bool shorten,
                                                 int recordFrames) {
  CloudSeparatorStages result;
  result.source = source;
  StageClock clock(result.timings);

  result.distance = cloud.geodesics().fromPoint(source);
  clock.lap("distance");

  const CloudCutLocusSolver& solver = cloud.cutLocusSolver();
  result.cutLocus = solver.compute(result.distance, source, cutLocusOptionsOf(options));
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

  // The nearest target whose descents reach the source and make a loop.
  for (const CloudTarget& t : targets) {
    if (result.attempts == kMaxTargets) break;
    result.attempts++;
    TracedLoop traced = traceCloudLoop(neighbourhood.graph(), result.distance, t.point, t.starts, source);
    if (!traced.failure.empty()) {
      result.message = traced.failure;
      continue;
    }
    result.target = t.point;
    result.traced = std::move(traced);
    result.message.clear();
    break;
  }
  if (!result.target) {
    clock.lap("loop");
    return fail(result, SeparatorStatus::TraceFailed, result.message);
  }
  if (!shorten) {
    clock.lap("loop");
    return result;
  }

  std::vector<geometrycentral::Vector3> approximate;
  for (size_t p : result.traced.loop) approximate.push_back(neighbourhood.position(p));
  if (options.sphere) {
    const geometrycentral::Vector3 centre = neighbourhood.position(source);
    double radius = 0;
    for (const geometrycentral::Vector3& p : approximate) radius = std::max(radius, norm(p - centre));
    result.sphere = Sphere{centre, radius};
  }
  if (approximate.size() < 3) {
    clock.lap("loop");
    return fail(result, SeparatorStatus::DegenerateLoop, "the approximate loop has fewer than 3 points");
  }
  ShortenedCloudLoop shortened = shortenLoop(cloud, approximate, result.sphere, recordFrames);
  clock.lap("loop");
  result.iterations = shortened.iterations;
  result.iterates = std::move(shortened.iterates);
  if (shortened.failureKind == ShortenedCloudLoop::Failure::Degenerate)
    return fail(result, SeparatorStatus::DegenerateLoop, shortened.failure);
  if (shortened.failureKind == ShortenedCloudLoop::Failure::NotConverged)
    return fail(result, SeparatorStatus::ShortenFailed, shortened.failure);

  result.loop = std::move(shortened.loop);
  result.length = shortened.length;
  result.areas = shortened.areas;
  result.score = separatorScore(result.areas, result.length);
  result.centroidInside = cloud.winding()(loopCentroid(result.loop, true)) > 0.5;
  clock.lap("measures");
  return result;
}

} // namespace cscd
