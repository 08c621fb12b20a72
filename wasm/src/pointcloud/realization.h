#pragma once

#include "cscd/pipeline.h"
#include "cscd/sampling.h"
#include "pointcloud/cloud.h"
#include "pointcloud/winding.h"

#include <array>
#include <vector>

namespace cscd {

// CSCD-PC: the representation-specific steps of the pipeline on a point cloud (the counterpart of
// MeshRealization). Stage 1 per source: the cloud's separator stages as far as the approximate loop
// (pointcloud/separator.h), then the loop shortened on the MLS surface inside the paper's sphere
// (pointcloud/shorten.h). Stage 2 uses the framework's steps on the cloud's points: overlap by distance
// in space, regions grown over the neighbourhood graph from one multi-source heat distance, Cloud::inside
// for the inside tests (the winding number of oriented points; on a noisy cloud the exterior flood).
class PointCloudRealization {
public:
  // A separator on the cloud: the loop also as its nearest cloud points, where regions and coverage
  // grow from, and what it covers (computed with the separator; released once covered).
  struct Candidate : cscd::Candidate {
    std::vector<size_t> points;
    std::vector<double> reach;
  };

  PointCloudRealization(Cloud& cloud, const Options& options);

  Candidate separator(size_t source);
  size_t nextSource() { return sampler.next(); }
  void cover(Candidate& candidate);
  double coverage() const;
  double resolution() const { return cloud.facts().meanSpacing; }
  std::vector<std::vector<size_t>> overlaps(const Selection<Candidate>& kept) const;
  Regions regions(const Selection<Candidate>& packed);
  void centre(SkeletonGraph& graph, const Selection<Candidate>& packed) const;
  // The points, their areas and the neighbourhood graph's edges.
  const Samples& samples() const { return pointSamples; }
  size_t sourceCount() const { return pointSamples.positions.size(); }
  bool inside(const geometrycentral::Vector3& p) const { return cloud.inside(p); }
  bool noisy() const { return cloud.neighbourhood().noisyCloud(); }
  void fitRadii(SkeletonGraph& graph) const;

private:
  Cloud& cloud;
  Options options;
  Samples pointSamples;
  SourceSampler sampler;
};

using PointCloudPipeline = Pipeline<PointCloudRealization>;

} // namespace cscd
