#include "pointcloud/realization.h"

#include "cscd/centre.h"
#include "cscd/measures.h"
#include "cscd/overlap.h"
#include "evaluate/tube_radii.h"
#include "pointcloud/separator.h"

#include <algorithm>
#include <cmath>

using namespace geometrycentral;

namespace cscd {

namespace {

// Two regions of a cloud touch where their contact holds at least this many points on either side (about
// the shortest loop that encloses anything, kDegenerateLength in pointcloud/shorten.cpp, in spacings), or
// where they meet a third: the graph keeps a few edges across the gap between two parts here and there
// (two fingers of a noisy hand), through which regions touched in 1 or 2 points and closed spurious
// cycles. Borders hold a dozen points or more. (docs/pointcloud.md, "Where regions touch")
constexpr size_t kMinContactPoints = 3;

Samples pointSamplesOf(Cloud& cloud) {
  Samples samples;
  const CloudNeighbourhood& neighbourhood = cloud.neighbourhood();
  samples.positions = neighbourhood.positions();
  samples.weights = cloud.pointAreas();
  for (const auto& [a, b] : neighbourhood.graph().edgeVertices) samples.edges.push_back({uint32_t(a), uint32_t(b)});
  return samples;
}

} // namespace

PointCloudRealization::PointCloudRealization(Cloud& cloud_, const Options& options_)
    : cloud(cloud_), options(options_), pointSamples(pointSamplesOf(cloud_)),
      sampler(pointSamples.positions, pointSamples.weights, cloud_.facts().bboxDiagonal, options_.seed) {}

PointCloudRealization::Candidate PointCloudRealization::separator(size_t source) {
  Candidate candidate;
  candidate.source = source;
  CloudSeparatorStages stages =
      computeCloudSeparatorStages(cloud, source, options, /*shorten=*/true, /*recordFrames=*/0, /*everyAngle=*/false);
  if (stages.status != SeparatorStatus::Ok) {
    // Only the source is covered: its distance is the one stage 1 started from (the same solve).
    candidate.reach = std::move(stages.distance);
    return candidate;
  }
  candidate.found = true;
  candidate.loop = std::move(stages.loop);
  candidate.length = stages.length;
  candidate.score = stages.score;
  candidate.centroidInside = stages.centroidInside;
  for (const Vector3& p : candidate.loop) candidate.points.push_back(cloud.mls().nearestPoint(p));
  std::vector<size_t> covered = candidate.points;
  covered.push_back(source);
  candidate.reach = cloud.geodesics().fromPoints(covered);
  return candidate;
}

void PointCloudRealization::cover(Candidate& candidate) {
  sampler.cover(candidate.reach);
  candidate.reach = {};
}

double PointCloudRealization::coverage() const { return sampler.coverage(kCoverageRadius * cloud.facts().bboxDiagonal); }

std::vector<std::vector<size_t>> PointCloudRealization::overlaps(const Selection<Candidate>& kept) const {
  std::vector<std::vector<Vector3>> loops;
  for (const Candidate* c : kept) loops.push_back(c->loop);
  return overlappingLoops(loops, std::vector<char>(kept.size(), 1), kOverlapTolerance * cloud.facts().meanSpacing);
}

Regions PointCloudRealization::regions(const Selection<Candidate>& packed) {
  const size_t n = cloud.pointCount();
  std::vector<uint32_t> seeds(n, kNoRegion);
  std::vector<double> seedDistance(n, INFINITY), distance(n, INFINITY);
  std::vector<size_t> all;
  for (uint32_t k = 0; k < packed.size(); k++)
    for (size_t i = 0; i < packed[k]->points.size(); i++) {
      const size_t p = packed[k]->points[i];
      const double d = norm(pointSamples.positions[p] - packed[k]->loop[i]);
      if (d < seedDistance[p]) {
        seedDistance[p] = d;
        seeds[p] = k;
      }
      all.push_back(p);
    }
  if (!all.empty()) distance = cloud.geodesics().fromPoints(all);

  const CloudNeighbourhood& neighbourhood = cloud.neighbourhood();
  const NeighbourGraph& graph = neighbourhood.graph();
  std::vector<std::vector<uint32_t>> neighbours(n);
  for (size_t p = 0; p < n; p++)
    for (size_t k = graph.rowStart[p]; k < graph.rowStart[p + 1]; k++) neighbours[p].push_back(uint32_t(graph.neighbour[k]));
  // Regions touch where a triangle of the tufted triangulation (the points' local triangulations) has
  // points of both; only triangles whose three edges the neighbourhood graph kept, so that no region
  // touches another across a gap the graph does not bridge (two fingers side by side).
  auto inGraph = [&](size_t a, size_t b) {
    return std::find(neighbours[a].begin(), neighbours[a].end(), uint32_t(b)) != neighbours[a].end();
  };
  // Three regions meet where a tufted triangle has a point of each, whether or not the graph kept its
  // edges: the graph leaves holes at creases and in noise, where three regions met unseen and their
  // triangle stayed a cycle of the skeleton (horse_clean).
  std::vector<std::array<uint32_t, 3>> triangles, tufted;
  for (surface::Face f : cloud.tufted().mesh.faces()) {
    std::array<uint32_t, 3> t;
    size_t k = 0;
    for (surface::Vertex v : f.adjacentVertices()) t[k++] = uint32_t(v.getIndex());
    if (inGraph(t[0], t[1]) && inGraph(t[1], t[2]) && inGraph(t[0], t[2])) triangles.push_back(t);
    tufted.push_back(t);
  }
  // Pieces of the graph under k points are a few points the bridge test cut off at a crease or in noise:
  // each point of one is adopted by its nearest point (among its k nearest) in a larger piece, else it
  // would become a skeleton node with no edge (7 on armadillo_clean at seed 1). Adopted, not linked by an
  // edge, so that no label flows through them across the gap the test found (docs/pointcloud.md,
  // "Cut-off points and what the lone nodes hid").
  const std::vector<int>& component = neighbourhood.pointComponent();
  std::vector<size_t> pieceSize(neighbourhood.componentCount(), 0);
  for (int c : component) pieceSize[size_t(c)]++;
  const size_t smallPiece = cloud.facts().neighbours;
  const auto& nearest = cloud.geometry().neighbors->neighbors;
  std::vector<uint32_t> adoptive(n, kNoRegion);
  for (size_t p = 0; p < n; p++) {
    if (pieceSize[size_t(component[p])] >= smallPiece) continue;
    double closest = INFINITY;
    for (pointcloud::Point q : nearest[p]) {
      const size_t i = q.getIndex();
      const double d = norm2(pointSamples.positions[i] - pointSamples.positions[p]);
      if (pieceSize[size_t(component[i])] >= smallPiece && d < closest) closest = d, adoptive[p] = uint32_t(i);
    }
  }
  const ElementGraph elements{pointSamples.positions, pointSamples.weights, neighbours, pointSamples.edges,
                              component, triangles, kMinContactPoints, &tufted, &adoptive};
  return growRegions(elements, std::move(distance), std::move(seeds), packed.size());
}

void PointCloudRealization::centre(SkeletonGraph& graph, const Selection<Candidate>& packed) const {
  centreNodes(graph, packed, [](const Candidate& c) { return loopNormal(c.loop); },
              [&](const Vector3& p) { return inside(p); });
}

void PointCloudRealization::fitRadii(SkeletonGraph& graph) const {
  SkeletonCurves curves{graph.nodes, {}, {}};
  for (const auto& e : graph.edges) curves.edges.push_back({uint32_t(e[0]), uint32_t(e[1])});
  graph.radii = tubeRadii(pointSamples.positions, curves);
}

} // namespace cscd
