#pragma once

#include "cscd/options.h"
#include "cscd/separator_status.h"
#include "mesh/cut_locus.h"
#include "mesh/shorten.h"
#include "mesh/surface.h"
#include "mesh/trace.h"

#include <array>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace cscd {

// Stage 1 of CSCD-M for one source, with every intermediate result kept for the teaching views.
struct SeparatorResult {
  size_t source = 0;
  SeparatorStatus status = SeparatorStatus::Ok;
  std::string message;

  std::vector<double> distance;
  CutLocus cutLocus;
  // Boundary vertices where the distance gradient is normal to the boundary (mesh/boundary.h).
  std::vector<size_t> boundaryExtremities;
  // The separator runs through a cut-locus target (a closed loop) or between two boundary extremities
  // on one boundary loop (an open path, closed = false); the nearer of the two kinds is tried first.
  std::optional<size_t> target;
  std::optional<std::array<size_t, 2>> ends;
  bool closed = true;
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
// everyAngle: the cut locus's angle field complete (teaching views) or only where its threshold looks.
SeparatorResult computeSeparator(Surface& surface, size_t source, const Options& options, bool everyAngle = true);

} // namespace cscd
