#pragma once

#include "cscd/pipeline.h"
#include "mesh/sampling.h"
#include "mesh/surface.h"

#include <vector>

namespace cscd {

// CSCD-M: the representation-specific steps of the pipeline on a triangle mesh.
class MeshRealization {
public:
  MeshRealization(Surface& surface, const Options& options);

  Candidate separator(size_t source);
  size_t nextSource() { return sampler.next(); }
  void cover(size_t candidate);
  double coverage() const;
  double resolution() const { return surface.facts().meanEdgeLength; }
  std::vector<std::vector<size_t>> overlaps(const std::vector<size_t>& candidates) const;
  Regions regions(const std::vector<size_t>& packed);
  // The centroid of a curved region (a bent tube, a thin curved ear) can fall outside the shape: such a
  // node moves to its separator loop's centroid, which is inside (loops with an outside centroid were
  // pruned); a branch node outside moves to its heaviest neighbour's position.
  void centre(SkeletonGraph& graph, const std::vector<size_t>& packed) const;

  // The loop of a candidate as the last stage-1 call produced it (for progressive display).
  const std::vector<geometrycentral::Vector3>& loop(size_t candidate) const { return loops[candidate]; }

private:
  Surface& surface;
  Options options;
  SourceSampler sampler;
  std::vector<size_t> sources;
  std::vector<std::vector<geometrycentral::Vector3>> loops;
  std::vector<std::vector<geometrycentral::surface::SurfacePoint>> loopPoints;
};

using MeshPipeline = Pipeline<MeshRealization>;

} // namespace cscd
