#pragma once

#include "cscd/options.h"
#include "mesh/cut_locus.h"
#include "mesh/shorten.h"
#include "mesh/surface.h"
#include "mesh/trace.h"

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace cscd {

// Stage 1 of CSCD-M for one source, with every intermediate result kept for the teaching views.
struct SeparatorResult {
  size_t source = 0;
  std::string status = "ok"; // or no-cut-locus | no-target | trace-failed | degenerate-loop | shorten-failed
  std::string message;

  std::vector<double> distance;
  CutLocus cutLocus;
  std::optional<size_t> target;
  int attempts = 0; // targets tried (the nearest first; farther ones when a loop was degenerate)
  TracedLoop traced;
  std::vector<geometrycentral::Vector3> firstPath, secondPath, approxLoop, loop; // polylines on the surface
  std::vector<geometrycentral::surface::SurfacePoint> loopPoints;                 // the loop on the input mesh
  std::optional<Sphere> sphere;
  double approxLength = 0;
  double length = 0;
  std::array<double, 2> areas{0, 0};
  double score = 0;
  bool centroidInside = false;
  std::vector<std::pair<std::string, double>> timings; // milliseconds per stage, in order
};

// Alg. 2 of the paper: distance -> cut locus -> target -> two traced paths -> shortened loop -> measures.
// Reads only per-mesh data of the surface, so sources can be processed in any order or batch.
SeparatorResult computeSeparator(Surface& surface, size_t source, const Options& options);

} // namespace cscd
