#include "pointcloud/separator.h"

#include "cscd/stage_clock.h"
#include "pointcloud/target.h"
#include "pointcloud/trace.h"

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

CloudSeparatorStages computeCloudSeparatorStages(Cloud& cloud, size_t source, const Options& options) {
  CloudSeparatorStages result;
  result.source = source;
  StageClock clock(result.timings);

  result.distance = cloud.geodesics().fromPoint(source);
  clock.lap("distance");

  CutLocusOptions cutLocusOptions;
  cutLocusOptions.angleThreshold = options.angleThreshold;
  cutLocusOptions.laplacianThreshold = options.laplacianThreshold;
  cutLocusOptions.pruneDepth = options.pruneDepth;
  const CloudCutLocusSolver& solver = cloud.cutLocusSolver();
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
  clock.lap("loop");
  if (!result.target) return fail(result, SeparatorStatus::TraceFailed, result.message);
  return result;
}

} // namespace cscd
