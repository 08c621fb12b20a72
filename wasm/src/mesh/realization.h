#pragma once

#include "cscd/pipeline.h"
#include "cscd/sampling.h"
#include "evaluate/closest_point.h"
#include "mesh/surface.h"

#include <memory>

#include <vector>

namespace cscd {

// CSCD-M: the representation-specific steps of the pipeline on a triangle mesh.
class MeshRealization {
public:
  // A separator on the mesh: the loop also as points on the surface, where regions and coverage grow
  // from, and what it covers (the geodesic distance from the source and the loop: computed with the
  // separator, so that a pool computes it in parallel; released once covered).
  struct Candidate : cscd::Candidate {
    std::vector<geometrycentral::surface::SurfacePoint> points;
    std::vector<double> reach;
  };

  // `working`: the surface stage 1 runs on when it is not `surface` itself (multiscale: a simplified
  // copy of a large mesh, see docs/multiscale.md); its separators are mapped back onto `surface`, where
  // stage 2 runs. Null: stage 1 on `surface`.
  MeshRealization(Surface& surface, const Options& options, Surface* working = nullptr);

  Candidate separator(size_t source);
  size_t nextSource() { return sampler.next(); }
  void cover(Candidate& candidate) {
    sampler.cover(candidate.reach);
    candidate.reach = {};
  }
  double coverage() const;
  // Loops are shortened on the working surface: their length is measured against its edges.
  double resolution() const { return working.facts().meanEdgeLength; }
  // Sources are vertices of the working surface.
  size_t sourceCount() const { return working.vertexCount(); }
  std::vector<std::vector<size_t>> overlaps(const Selection<Candidate>& kept) const;
  Regions regions(const Selection<Candidate>& packed);
  // A separator's node keeps its region centroid's position along the loop's normal (so end regions
  // reach towards their tips) but takes the loop centroid's position across it: on a bent tube the
  // outer side has more area and drags the region centroid outwards (by r^2 / 2R on a torus), while
  // the centroid of a loop around the tube stays on its axis. A node that still falls outside the
  // shape moves to the loop centroid, which is inside (loops with an outside centroid were pruned); a
  // branch node outside moves to its heaviest neighbour's position.
  // A path across a sheet (open separator) has no inside: its node keeps the region centroid along the
  // path's normal and the path centroid across it, and so do junctions next to such paths.
  void centre(SkeletonGraph& graph, const Selection<Candidate>& packed) const;
  // The vertices, their dual areas and the mesh edges.
  const Samples& samples() const { return vertexSamples; }
  bool inside(const geometrycentral::Vector3& p) const;
  bool noisy() const { return false; }
  // Radii fitted to the surface around the final skeleton (tubeRadii), the same rule as for other tools'
  // skeletons: the mean distance to a whole region overestimates a long region's tube.
  void fitRadii(SkeletonGraph& graph) const;

private:
  // A loop's normal, or for a path its direction across the sheet (measures.h).
  geometrycentral::Vector3 separatorNormal(const Candidate& candidate) const;

  // The loop as points of `surface`: its own points, or (multiscale) the polyline resampled at half
  // an edge of `surface` and each sample's closest point on it, so that the faces it crosses all seed.
  std::vector<geometrycentral::surface::SurfacePoint> pointsOnSurface(const Candidate& candidate) const;

  Surface& surface;
  Surface& working;
  Options options;
  Samples vertexSamples;
  SourceSampler sampler;
  std::unique_ptr<TriangleTree> closestFace; // of `surface`, when stage 1 runs elsewhere
};

using MeshPipeline = Pipeline<MeshRealization>;

} // namespace cscd
