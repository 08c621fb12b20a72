#pragma once

#include "cscd/descent.h"
#include "cscd/options.h"
#include "cscd/separator_status.h"
#include "pointcloud/cloud.h"
#include "pointcloud/cut_locus.h"

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace cscd {

// Stage 1 of CSCD-PC for one source as far as the approximate loop (paper Sec. 4.1.2-4.1.4 for clouds),
// with every intermediate result kept for tests and teaching views: distance -> cut locus -> targets ->
// two descending paths -> approximate loop. Its shortening and measures are not here yet.
struct CloudSeparatorStages {
  size_t source = 0;
  SeparatorStatus status = SeparatorStatus::Ok;
  std::string message;

  std::vector<double> distance;
  CloudCutLocus cutLocus;
  std::vector<size_t> targets;  // ranked, the nearest first (pointcloud/target.h)
  std::optional<size_t> target; // the one the loop runs through
  int attempts = 0;             // targets traced: the nearest first, the next when its descents made no loop
  TracedLoop traced;            // its paths and loop are point indices
  std::vector<std::pair<std::string, double>> timings; // milliseconds per stage, in order
};

CloudSeparatorStages computeCloudSeparatorStages(Cloud& cloud, size_t source, const Options& options);

} // namespace cscd
