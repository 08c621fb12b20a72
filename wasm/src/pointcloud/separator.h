#pragma once

#include "cscd/descent.h"
#include "cscd/options.h"
#include "cscd/separator_status.h"
#include "cscd/sphere.h"
#include "pointcloud/cloud.h"
#include "pointcloud/cut_locus.h"

#include <array>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace cscd {

// Stage 1 of CSCD-PC for one source (paper Sec. 4.1 for clouds), with every intermediate result kept
// for tests and teaching views: distance -> cut locus -> targets -> two descending paths -> approximate
// loop -> the loop shortened on the MLS surface inside the sphere (pointcloud/shorten.h) -> measures.
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

  // The sphere through the approximate loop's farthest point (paper Sec. 4.1.6), when options.sphere.
  std::optional<Sphere> sphere;
  std::vector<geometrycentral::Vector3> loop; // shortened, on the MLS surface; empty unless Ok
  double length = 0;
  std::array<double, 2> areas{0, 0};
  double score = 0;
  bool centroidInside = false;
  int iterations = 0; // of the shortening
  std::vector<std::vector<geometrycentral::Vector3>> iterates; // its steps, when recordFrames > 0 (shorten.h)
  std::vector<std::pair<std::string, double>> timings; // milliseconds per stage, in order
};

// `shorten` false: stop at the approximate loop (the cut-locus views and tests need no more).
// `recordFrames` > 0 keeps that many of the shortening's steps for the page to show (shortenLoop).
// `everyAngle`: the cut locus's angle field complete (teaching views) or only where its threshold looks.
CloudSeparatorStages computeCloudSeparatorStages(Cloud& cloud, size_t source, const Options& options, bool shorten = true,
                                                 int recordFrames = 0, bool everyAngle = true);

} // namespace cscd
