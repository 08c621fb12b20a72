#include "mesh/trace.h"

#include <algorithm>

using namespace geometrycentral::surface;

namespace cscd {
namespace {

bool descendOnMesh(ManifoldSurfaceMesh& mesh, const std::vector<double>& distance, size_t source, std::vector<size_t>& path) {
  auto forEachNeighbour = [&](size_t v, auto&& visit) {
    for (Vertex w : mesh.vertex(v).adjacentVertices()) visit(w.getIndex());
  };
  return descend(forEachNeighbour, distance, source, path);
}

} // namespace

TracedLoop traceApproximateLoop(ManifoldSurfaceMesh& mesh, const std::vector<double>& distance,
                                const CutLocus& cutLocus, size_t target, size_t source) {
  TracedLoop traced;
  std::vector<size_t> ring;
  for (Vertex w : mesh.vertex(target).adjacentVertices()) ring.push_back(w.getIndex());
  std::vector<size_t> starts = incomingNeighbours(ring, distance, cutLocusNeighbours(cutLocus), target);
  if (starts.size() != 2) {
    traced.failure = "no two incoming directions at the target";
    return traced;
  }
  traced.firstPath = {target, starts[0]};
  traced.secondPath = {target, starts[1]};
  if (!descendOnMesh(mesh, distance, source, traced.firstPath) || !descendOnMesh(mesh, distance, source, traced.secondPath)) {
    traced.failure = "steepest descent stopped at a local minimum of the distance";
    return traced;
  }
  joinDescents(traced);
  if (traced.loop.size() < 3) traced.failure = "the traced loop is degenerate";
  return traced;
}

TracedLoop traceApproximatePath(ManifoldSurfaceMesh& mesh, const std::vector<double>& distance,
                                std::array<size_t, 2> ends, size_t source) {
  TracedLoop traced;
  traced.closed = false;
  traced.firstPath = {ends[0]};
  traced.secondPath = {ends[1]};
  if (!descendOnMesh(mesh, distance, source, traced.firstPath) || !descendOnMesh(mesh, distance, source, traced.secondPath)) {
    traced.failure = "steepest descent stopped at a local minimum of the distance";
    return traced;
  }
  auto passes = [](const std::vector<size_t>& path, size_t v) { return std::find(path.begin(), path.end(), v) != path.end(); };
  if (passes(traced.firstPath, ends[1]) || passes(traced.secondPath, ends[0])) {
    traced.failure = "one boundary end lies on the descent from the other";
    return traced;
  }
  joinDescents(traced);
  return traced;
}

} // namespace cscd
