// The core's module: the mesh functions (inspect, evaluate), the Surface of CSCD-M and its Pipeline, and
// the Cloud of CSCD-PC.
// Arrays come in as typed arrays (one copy in); conversions out and failures as values: convert.h.
#include "bindings/convert.h"
#include "bindings/pipeline_binding.h"
#include "evaluate/reconstruction_error.h"
#include "mesh/realization.h"
#include "mesh/separator.h"
#include "mesh/surface.h"
#include "pointcloud/cloud.h"
#include "pointcloud/realization.h"
#include "pointcloud/winding.h"
#include "pointcloud/shorten.h"
#include "pointcloud/separator.h"

#include "geometrycentral/pointcloud/point_cloud_heat_solver.h"

#include <emscripten/bind.h>
#include <emscripten/val.h>

#include <cmath>
#include <memory>
#include <optional>
#include <sstream>
#include <string>

using namespace emscripten;
using geometrycentral::surface::SurfacePoint;

// The module's own conversions live beside convert.h's in one namespace, so that every toVal overload is seen.
namespace cscd {
namespace binding {

MeshArrays toArrays(const val& positions, const val& triangles) {
  MeshArrays arrays;
  arrays.positions = convertJSArrayToNumberVector<double>(positions);
  arrays.triangles = convertJSArrayToNumberVector<uint32_t>(triangles);
  return arrays;
}

// An element index given from JS (a double), refused unless it is a whole number below `count`.
size_t checkedIndex(double index, size_t count, const char* element, const char* plural, const char* shape) {
  if (!(index >= 0) || index != std::floor(index) || index >= double(count)) {
    std::ostringstream msg;
    msg << element << " " << index << " is out of range (the " << shape << " has " << count << " " << plural << ")";
    throw InputError(msg.str());
  }
  return size_t(index);
}

template <size_t N>
val toArray(const std::array<double, N>& v) {
  val a = val::array();
  for (double x : v) a.call<void>("push", x);
  return a;
}

val toVal(const MeshFacts& f) {
  val o = val::object();
  o.set("vertices", f.vertices);
  o.set("faces", f.faces);
  o.set("edges", f.edges);
  o.set("components", f.components);
  o.set("boundaryLoops", f.boundaryLoops);
  o.set("eulerCharacteristic", f.eulerCharacteristic);
  o.set("genus", f.genus ? val(*f.genus) : val::null());
  o.set("manifold", f.manifold);
  o.set("consistentlyOriented", f.consistentlyOriented);
  o.set("nonManifoldEdges", f.nonManifoldEdges);
  o.set("nonManifoldVertices", f.nonManifoldVertices);
  o.set("unreferencedVertices", f.unreferencedVertices);
  o.set("degenerateFaces", f.degenerateFaces);
  o.set("bboxMin", toArray(f.bboxMin));
  o.set("bboxMax", toArray(f.bboxMax));
  o.set("bboxDiagonal", f.bboxDiagonal);
  o.set("meanEdgeLength", f.meanEdgeLength);
  return o;
}

// A cut locus's graph and per-vertex fields; positionsOf gives the xyz of a list of vertex indices.
template <class PositionsOf>
val cutLocusRecord(const CutLocus& c, PositionsOf&& positionsOf) {
  std::vector<uint32_t> vertices(c.vertices.begin(), c.vertices.end());
  val cutLocus = val::object();
  cutLocus.set("vertices", toTypedArray("Uint32Array", vertices));
  cutLocus.set("points", positionsOf(c.vertices));
  cutLocus.set("edges", toPairArray(c.edges));
  cutLocus.set("angleDeviation", toFloat64Array(c.angleDeviation));
  cutLocus.set("laplacian", toFloat64Array(c.laplacian));
  cutLocus.set("root", c.root);
  cutLocus.set("cycleRank", c.vertices.empty() ? 0 : c.cycleRank());
  return cutLocus;
}

val toUint32Array(const std::vector<size_t>& indices) {
  return toTypedArray("Uint32Array", std::vector<uint32_t>(indices.begin(), indices.end()));
}

// The sphere constraint as {center, radius}, or null.
val toVal(const std::optional<Sphere>& sphere) {
  if (!sphere) return val::null();
  val o = val::object();
  o.set("center", toArray3(sphere->center));
  o.set("radius", sphere->radius);
  return o;
}

val toVal(const SeparatorResult& r, Surface& surface) {
  val o = val::object();
  o.set("source", r.source);
  o.set("status", std::string(separatorStatusName(r.status)));
  o.set("message", r.message);
  o.set("distance", toFloat64Array(r.distance));

  auto positionsOf = [&](const auto& vertices) {
    std::vector<geometrycentral::Vector3> p;
    for (size_t v : vertices) p.push_back(surface.geometry().vertexPositions[v]);
    return toFloat64Array(p);
  };
  o.set("cutLocus", cutLocusRecord(r.cutLocus, positionsOf));

  val extremities = val::object();
  extremities.set("vertices", toTypedArray("Uint32Array", std::vector<uint32_t>(r.boundaryExtremities.begin(),
                                                                                  r.boundaryExtremities.end())));
  extremities.set("points", positionsOf(r.boundaryExtremities));
  o.set("boundaryExtremities", extremities);

  o.set("target", r.target ? val(*r.target) : val::null());
  o.set("attempts", r.attempts);
  o.set("targetPoint", r.target ? toArray3(surface.geometry().vertexPositions[*r.target]) : val::null());
  o.set("ends", r.ends ? toTypedArray("Uint32Array", std::vector<uint32_t>(r.ends->begin(), r.ends->end())) : val::null());
  o.set("endPoints", r.ends ? positionsOf(*r.ends) : val::null());
  o.set("closed", r.closed);
  val paths = val::array();
  paths.call<void>("push", toFloat64Array(r.firstPath));
  paths.call<void>("push", toFloat64Array(r.secondPath));
  o.set("paths", paths);
  o.set("approxLoop", toFloat64Array(r.approxLoop));
  o.set("loop", toFloat64Array(r.loop));
  o.set("sphere", toVal(r.sphere));
  o.set("approxLength", r.approxLength);
  o.set("length", r.length);
  o.set("areas", toArray(r.areas));
  o.set("score", r.score);
  o.set("centroidInside", r.centroidInside);
  o.set("timings", toVal(r.timings));
  return o;
}

val inspect(const val& positions, const val& triangles) {
  return reportingErrors([&] { return toVal(checkMesh(toArrays(positions, triangles)).facts); });
}

val toVal(const Evaluation& e) {
  val o = val::object();
  o.set("reconError", e.reconError);
  o.set("median", e.median);
  o.set("p95", e.p95);
  o.set("nodes", e.nodes);
  o.set("cycles", e.cycles);
  o.set("radiiSource", std::string(e.radiiDerived ? "derived" : "given"));
  o.set("radii", toFloat64Array(e.radii));
  o.set("vertexError", toFloat64Array(e.vertexError));
  std::vector<float> surfacePositions;
  surfacePositions.reserve(3 * e.surface.vertices.size());
  for (const auto& p : e.surface.vertices) surfacePositions.insert(surfacePositions.end(), {float(p.x), float(p.y), float(p.z)});
  std::vector<uint32_t> surfaceTriangles;
  surfaceTriangles.reserve(3 * e.surface.triangles.size());
  for (const auto& t : e.surface.triangles) surfaceTriangles.insert(surfaceTriangles.end(), t.begin(), t.end());
  val surface = val::object();
  surface.set("positions", toTypedArray("Float32Array", surfacePositions));
  surface.set("triangles", toTypedArray("Uint32Array", surfaceTriangles));
  o.set("surface", surface);
  val grid = val::object();
  grid.set("cell", e.grid.cell);
  val dims = val::array();
  for (size_t d : e.grid.dims) dims.call<void>("push", d);
  grid.set("dims", dims);
  o.set("grid", grid);
  o.set("timings", toVal(e.timings));
  return o;
}

// Reconstruction error of a skeleton (nodes xyz, edges as node pairs, radii or null) against a mesh.
SkeletonCurves toSkeletonCurves(const val& nodes, const val& edges, const val& radii) {
  std::vector<double> xyz = convertJSArrayToNumberVector<double>(nodes);
  std::vector<uint32_t> pairs = convertJSArrayToNumberVector<uint32_t>(edges);
  if (xyz.size() % 3 != 0) throw InputError("skeleton nodes must be xyz triples");
  if (pairs.size() % 2 != 0) throw InputError("skeleton edges must be pairs of node indices");
  SkeletonCurves skeleton;
  for (size_t i = 0; i < xyz.size(); i += 3) skeleton.nodes.push_back({xyz[i], xyz[i + 1], xyz[i + 2]});
  for (size_t i = 0; i < pairs.size(); i += 2) skeleton.edges.push_back({pairs[i], pairs[i + 1]});
  if (!radii.isNull() && !radii.isUndefined()) skeleton.radii = convertJSArrayToNumberVector<double>(radii);
  return skeleton;
}

val evaluate(const val& positions, const val& triangles, const val& nodes, const val& edges, const val& radii) {
  return reportingErrors([&] { return toVal(evaluateSkeleton(toArrays(positions, triangles), toSkeletonCurves(nodes, edges, radii))); });
}

// The reconstruction error against a point cloud's points (xyz triples).
val evaluateCloud(const val& positions, const val& nodes, const val& edges, const val& radii) {
  return reportingErrors([&] {
    const std::vector<double> xyz = convertJSArrayToNumberVector<double>(positions);
    if (xyz.size() % 3 != 0) throw InputError("point positions must be xyz triples");
    std::vector<geometrycentral::Vector3> points;
    for (size_t i = 0; i < xyz.size(); i += 3) points.push_back({xyz[i], xyz[i + 1], xyz[i + 2]});
    return toVal(evaluateSkeleton(points, toSkeletonCurves(nodes, edges, radii)));
  });
}

// A mesh candidate's surface points cross exactly: each point's kind (0 vertex, 1 edge, 2 face), its
// element's index and its coordinates (t along the edge; barycentric in the face); and its reach.
template <>
struct CandidateRecord<MeshRealization::Candidate> {
  static val write(const MeshRealization::Candidate& c, const Surface&) {
    val o = baseRecord(c);
    std::vector<uint8_t> kinds;
    std::vector<uint32_t> elements;
    std::vector<double> coords;
    for (const SurfacePoint& p : c.points) {
      switch (p.type) {
      case geometrycentral::surface::SurfacePointType::Vertex:
        kinds.push_back(0), elements.push_back(uint32_t(p.vertex.getIndex())), coords.insert(coords.end(), {0, 0, 0});
        break;
      case geometrycentral::surface::SurfacePointType::Edge:
        kinds.push_back(1), elements.push_back(uint32_t(p.edge.getIndex())), coords.insert(coords.end(), {p.tEdge, 0, 0});
        break;
      case geometrycentral::surface::SurfacePointType::Face:
        kinds.push_back(2), elements.push_back(uint32_t(p.face.getIndex()));
        coords.insert(coords.end(), {p.faceCoords.x, p.faceCoords.y, p.faceCoords.z});
        break;
      }
    }
    val points = val::object();
    points.set("kinds", toTypedArray("Uint8Array", kinds));
    points.set("elements", toTypedArray("Uint32Array", elements));
    points.set("coords", toFloat64Array(coords));
    o.set("points", points);
    o.set("reach", toFloat64Array(c.reach));
    return o;
  }

  static MeshRealization::Candidate read(const val& o, Surface& surface) {
    MeshRealization::Candidate c;
    readBaseRecord(o, c);
    const val points = o["points"];
    const std::vector<uint8_t> kinds = convertJSArrayToNumberVector<uint8_t>(points["kinds"]);
    const std::vector<uint32_t> elements = convertJSArrayToNumberVector<uint32_t>(points["elements"]);
    const std::vector<double> coords = convertJSArrayToNumberVector<double>(points["coords"]);
    if (elements.size() != kinds.size() || coords.size() != 3 * kinds.size()) throw InputError("a candidate's points are malformed");
    auto& mesh = surface.mesh();
    for (size_t i = 0; i < kinds.size(); i++) {
      const size_t limit = kinds[i] == 0 ? mesh.nVertices() : kinds[i] == 1 ? mesh.nEdges() : mesh.nFaces();
      if (kinds[i] > 2 || elements[i] >= limit) throw InputError("a candidate's point lies on no element of this mesh");
      const double* x = &coords[3 * i];
      if (kinds[i] == 0) c.points.emplace_back(mesh.vertex(elements[i]));
      else if (kinds[i] == 1) c.points.emplace_back(mesh.edge(elements[i]), x[0]);
      else c.points.emplace_back(mesh.face(elements[i]), geometrycentral::Vector3{x[0], x[1], x[2]});
    }
    c.reach = convertJSArrayToNumberVector<double>(o["reach"]);
    if (c.reach.size() != surface.vertexCount()) throw InputError("a candidate's reach does not match this mesh");
    return c;
  }
};

class SurfaceBinding {
public:
  SurfaceBinding(const val& positions, const val& triangles) {
    try {
      surface = std::make_unique<Surface>(toArrays(positions, triangles));
    } catch (...) {
      failure = failureOf(std::current_exception());
    }
  }

  val error() const { return failure ? toVal(*failure) : val::null(); }

  // The shape a Pipeline runs on (null when it could not be opened).
  Surface* shape() const { return surface.get(); }

  val facts() const { return surface ? toVal(surface->facts()) : val::null(); }

  val distanceFromVertex(double vertex) {
    return reportingErrors([&] {
      return toFloat64Array(surface->geodesics().fromVertex(checkedVertex(vertex)));
    });
  }

  // Test-only (tests/unit/core-geodesics.test.ts): the exact reference the heat method is held to.
  val exactDistanceFromVertex(double vertex) {
    return reportingErrors([&] {
      return toFloat64Array(surface->geodesics().exactFromVertex(checkedVertex(vertex)));
    });
  }

  val separator(double source, const val& options) {
    return reportingErrors([&] { return toVal(computeSeparator(*surface, checkedVertex(source), toOptions(options)), *surface); });
  }

  // Test-only: the multi-source solve that regions and sampling use inside the core.
  // faces: one input face index per point; barycentric: three coordinates per point.
  val distanceFromPoints(const val& faces, const val& barycentric) {
    return reportingErrors([&] {
      std::vector<uint32_t> faceIds = convertJSArrayToNumberVector<uint32_t>(faces);
      std::vector<double> bary = convertJSArrayToNumberVector<double>(barycentric);
      if (faceIds.empty()) throw InputError("no source points given");
      if (bary.size() != 3 * faceIds.size()) throw InputError("three barycentric coordinates are needed per point");
      std::vector<SurfacePoint> points;
      for (size_t i = 0; i < faceIds.size(); i++) {
        if (faceIds[i] >= surface->faceCount())
          throw InputError("source point " + std::to_string(i) + " names face " + std::to_string(faceIds[i]) +
                           ", but the mesh has only " + std::to_string(surface->faceCount()) + " faces");
        geometrycentral::Vector3 b{bary[3 * i], bary[3 * i + 1], bary[3 * i + 2]};
        double sum = b.x + b.y + b.z;
        if (!std::isfinite(sum) || b.x < -1e-9 || b.y < -1e-9 || b.z < -1e-9 || std::abs(sum - 1) > 1e-6)
          throw InputError("source point " + std::to_string(i) + " has barycentric coordinates outside its face");
        points.emplace_back(surface->mesh().face(faceIds[i]), b / sum);
      }
      return toFloat64Array(surface->geodesics().fromPoints(points));
    });
  }

private:
  size_t checkedVertex(double vertex) const { return checkedIndex(vertex, surface->vertexCount(), "vertex", "vertices", "mesh"); }

  std::unique_ptr<Surface> surface;
  std::optional<Failure> failure;
};

CloudArrays toCloudArrays(const val& positions, const val& normals) {
  CloudArrays arrays;
  arrays.positions = convertJSArrayToNumberVector<double>(positions);
  if (!normals.isNull() && !normals.isUndefined()) arrays.normals = convertJSArrayToNumberVector<double>(normals);
  return arrays;
}

val toVal(const CloudFacts& f) {
  val o = val::object();
  o.set("points", f.points);
  o.set("neighbours", f.neighbours);
  o.set("meanFlatNeighbours", f.meanFlatNeighbours);
  o.set("components", f.components);
  o.set("lineLikeShare", f.lineLikeShare);
  o.set("lineSpacing", f.lineSpacing);
  o.set("pointsAtLineSpacing", f.pointsAtLineSpacing);
  o.set("bboxMin", toArray(f.bboxMin));
  o.set("bboxMax", toArray(f.bboxMax));
  o.set("bboxDiagonal", f.bboxDiagonal);
  o.set("meanSpacing", f.meanSpacing);
  o.set("normalsFromFile", f.normalsFromFile);
  return o;
}

// Points given from JS as xyz triples.
std::vector<geometrycentral::Vector3> toPoints(const val& xyz, const char* what) {
  const std::vector<double> flat = convertJSArrayToNumberVector<double>(xyz);
  if (flat.size() % 3 != 0) throw InputError(std::string(what) + " must be xyz triples");
  std::vector<geometrycentral::Vector3> points;
  for (size_t i = 0; i < flat.size(); i += 3) points.push_back({flat[i], flat[i + 1], flat[i + 2]});
  return points;
}

val iteratesOf(const std::vector<std::vector<geometrycentral::Vector3>>& loops) {
  val iterates = val::array();
  for (const auto& loop : loops) iterates.call<void>("push", toFloat64Array(loop));
  return iterates;
}

// How many loops of a shortening to record: 0, or a whole number from 2 (the first and the last) up.
int checkedFrames(double frames) {
  if (!(frames == 0 || (frames >= 2 && frames <= 1e6)) || frames != std::floor(frames))
    throw InputError("recordFrames must be 0 (record nothing) or a whole number of loops from 2 up");
  return int(frames);
}

const char* shortenStatusName(ShortenedCloudLoop::Failure failure) {
  switch (failure) {
  case ShortenedCloudLoop::Failure::None: return "ok";
  case ShortenedCloudLoop::Failure::Degenerate: return "degenerate-loop";
  case ShortenedCloudLoop::Failure::NotConverged: return "not-converged";
  }
  return "ok";
}

val toVal(const ShortenedCloudLoop& r) {
  val o = val::object();
  o.set("status", std::string(shortenStatusName(r.failureKind)));
  o.set("message", r.failure);
  o.set("loop", toFloat64Array(r.loop));
  o.set("length", r.length);
  o.set("areas", toArray(r.areas));
  o.set("iterations", r.iterations);
  o.set("iterates", iteratesOf(r.iterates));
  return o;
}

// The sphere constraint given from JS ({center: [x, y, z], radius}), or none.
std::optional<Sphere> toSphere(const val& sphere) {
  if (sphere.isUndefined() || sphere.isNull()) return std::nullopt;
  const std::vector<double> center = convertJSArrayToNumberVector<double>(sphere["center"]);
  if (center.size() != 3 || !sphere["radius"].isNumber()) throw InputError("a sphere is {center: [x, y, z], radius}");
  return Sphere{{center[0], center[1], center[2]}, sphere["radius"].as<double>()};
}

// Stage 1 of CSCD-PC for one source; paths and the approximate loop as point indices and polylines.
val toVal(const CloudSeparatorStages& r, const CloudNeighbourhood& neighbourhood) {
  auto positionsOf = [&](const std::vector<size_t>& points) {
    std::vector<geometrycentral::Vector3> p;
    for (size_t i : points) p.push_back(neighbourhood.position(i));
    return toFloat64Array(p);
  };
  val o = val::object();
  o.set("source", r.source);
  o.set("status", std::string(separatorStatusName(r.status)));
  o.set("message", r.message);
  o.set("distance", toFloat64Array(r.distance));
  val cutLocus = cutLocusRecord(r.cutLocus.graph, positionsOf);
  cutLocus.set("passingPoints", r.cutLocus.passingPoints);
  cutLocus.set("passingPieces", r.cutLocus.passingPieces);
  o.set("cutLocus", cutLocus);
  o.set("gradient", toFloat64Array(r.cutLocus.gradient));
  o.set("targets", toUint32Array(r.targets));
  o.set("target", r.target ? val(*r.target) : val::null());
  o.set("targetPoint", r.target ? toArray3(neighbourhood.position(*r.target)) : val::null());
  o.set("attempts", r.attempts);
  val paths = val::array(), pathPoints = val::array();
  for (const std::vector<size_t>* path : {&r.traced.firstPath, &r.traced.secondPath}) {
    paths.call<void>("push", positionsOf(*path));
    pathPoints.call<void>("push", toUint32Array(*path));
  }
  o.set("paths", paths);
  o.set("pathPoints", pathPoints);
  o.set("approxLoop", positionsOf(r.traced.loop));
  o.set("approxLoopPoints", toUint32Array(r.traced.loop));
  o.set("sphere", toVal(r.sphere));
  o.set("loop", toFloat64Array(r.loop));
  o.set("length", r.length);
  o.set("areas", toArray(r.areas));
  o.set("score", r.score);
  o.set("centroidInside", r.centroidInside);
  o.set("iterations", r.iterations);
  o.set("iterates", iteratesOf(r.iterates));
  o.set("timings", toVal(r.timings));
  return o;
}

val toVal(const CloudNeighbourhood& n) {
  val o = val::object();
  o.set("edges", toPairArray(n.graph().edgeVertices));
  o.set("bridgesRemoved", n.bridgesRemoved());
  o.set("noisy", n.noisyCloud());
  o.set("keptOnMls", n.keptOnMls());
  o.set("components", n.componentCount());
  return o;
}

template <>
struct CandidateRecord<PointCloudRealization::Candidate> {
  static val write(const PointCloudRealization::Candidate& c, const Cloud&) {
    val o = baseRecord(c);
    o.set("points", toTypedArray("Uint32Array", std::vector<uint32_t>(c.points.begin(), c.points.end())));
    o.set("reach", toFloat64Array(c.reach));
    return o;
  }

  static PointCloudRealization::Candidate read(const val& o, Cloud& cloud) {
    PointCloudRealization::Candidate c;
    readBaseRecord(o, c);
    for (uint32_t p : convertJSArrayToNumberVector<uint32_t>(o["points"])) {
      if (p >= cloud.pointCount()) throw InputError("a candidate's point is not a point of this cloud");
      c.points.push_back(p);
    }
    if (c.points.size() != c.loop.size()) throw InputError("a candidate's points do not match its loop");
    c.reach = convertJSArrayToNumberVector<double>(o["reach"]);
    if (c.reach.size() != cloud.pointCount()) throw InputError("a candidate's reach does not match this cloud");
    return c;
  }
};

// The Cloud of CSCD-PC, opened with the options (only `neighbours` matters to it).
class CloudBinding {
public:
  CloudBinding(const val& positions, const val& normals, const val& options) {
    try {
      cloud = std::make_unique<Cloud>(toCloudArrays(positions, normals), toOptions(options).neighbours);
    } catch (...) {
      failure = failureOf(std::current_exception());
    }
  }

  val error() const { return failure ? toVal(*failure) : val::null(); }

  val facts() const { return cloud ? toVal(cloud->facts()) : val::null(); }
  Cloud* shape() const { return cloud.get(); }

  val distance(double point) {
    return reportingErrors([&] { return toFloat64Array(cloud->geodesics().fromPoint(checkedPoint(point))); });
  }

  // Test-only (tests/unit/cloud-geodesics.test.ts): geometry-central's PointCloudHeatSolver, the
  // solver CloudGeodesics replaces, which it is held to; built on first use.
  val referenceDistance(double point) {
    return reportingErrors([&] {
      const size_t source = checkedPoint(point);
      if (!reference) reference = std::make_unique<geometrycentral::pointcloud::PointCloudHeatSolver>(cloud->cloud(), cloud->geometry());
      const Eigen::VectorXd distance = reference->computeDistance(cloud->cloud().point(source)).toVector();
      return toFloat64Array(std::vector<double>(distance.data(), distance.data() + distance.size()));
    });
  }

  // The graph the cloud's cut locus and loops run on.
  val neighbourhood() {
    return reportingErrors([&] { return toVal(cloud->neighbourhood()); });
  }

  // Stage 1 for one source, every step kept (tests, teaching views), with at most recordFrames loops of
  // the shortening (0: none).
  val separatorStages(double source, const val& options, double recordFrames) {
    return reportingErrors([&] {
      return toVal(computeCloudSeparatorStages(*cloud, checkedPoint(source), toOptions(options), true, checkedFrames(recordFrames)),
                   cloud->neighbourhood());
    });
  }

  // Test-only: the multi-source solve that regions will use inside the core.
  val distanceFromPoints(const val& points) {
    return reportingErrors([&] {
      std::vector<size_t> sources;
      for (double p : convertJSArrayToNumberVector<double>(points)) sources.push_back(checkedPoint(p));
      if (sources.empty()) throw InputError("no source points given");
      return toFloat64Array(cloud->geodesics().fromPoints(sources));
    });
  }

  // Test-only: generalised winding numbers of the cloud's oriented points at the given xyz positions.
  val windingNumbers(const val& points) {
    return reportingErrors([&] {
      const std::vector<double> xyz = convertJSArrayToNumberVector<double>(points);
      std::vector<double> numbers;
      for (size_t i = 0; i + 2 < xyz.size(); i += 3) numbers.push_back(cloud->winding()({xyz[i], xyz[i + 1], xyz[i + 2]}));
      return toFloat64Array(numbers);
    });
  }

  // Whether each of the given xyz positions is inside the shape (Cloud::inside): 1 or 0.
  val inside(const val& points) {
    return reportingErrors([&] {
      const std::vector<double> xyz = convertJSArrayToNumberVector<double>(points);
      std::vector<uint8_t> flags;
      for (size_t i = 0; i + 2 < xyz.size(); i += 3) flags.push_back(cloud->inside({xyz[i], xyz[i + 1], xyz[i + 2]}));
      return toTypedArray("Uint8Array", flags);
    });
  }

  // Points (xyz triples) projected on the cloud's MLS surface: {points, normals (of arbitrary sign),
  // quadratic (1 where the quadratic height was fitted, 0 where the plane alone)}.
  val project(const val& points) {
    return reportingErrors([&] {
      std::vector<geometrycentral::Vector3> projected, normals;
      std::vector<uint8_t> quadratic;
      for (const auto& p : toPoints(points, "points")) {
        if (!isfinite(p)) throw InputError("a point to project has a non-finite coordinate");
        const MlsPoint onSurface = cloud->mls().project(p);
        projected.push_back(onSurface.position);
        normals.push_back(onSurface.normal);
        quadratic.push_back(onSurface.quadratic);
      }
      val o = val::object();
      o.set("points", toFloat64Array(projected));
      o.set("normals", toFloat64Array(normals));
      o.set("quadratic", toTypedArray("Uint8Array", quadratic));
      return o;
    });
  }

  // A closed polyline (xyz triples) shortened on the cloud; options: {sphere: {center, radius}, recordFrames}.
  val shortenLoop(const val& polyline, const val& options) {
    return reportingErrors([&] {
      const bool given = !options.isUndefined() && !options.isNull();
      const std::optional<Sphere> sphere = toSphere(given ? options["sphere"] : val::undefined());
      const val frames = given ? options["recordFrames"] : val::undefined();
      return toVal(cscd::shortenLoop(*cloud, toPoints(polyline, "a loop's points"), sphere,
                                     checkedFrames(frames.isUndefined() ? 0 : frames.as<double>())));
    });
  }

private:
  size_t checkedPoint(double point) const { return checkedIndex(point, cloud->pointCount(), "point", "points", "cloud"); }

  std::unique_ptr<Cloud> cloud;
  std::unique_ptr<geometrycentral::pointcloud::PointCloudHeatSolver> reference;
  std::optional<Failure> failure;
};

} // namespace binding
} // namespace cscd

EMSCRIPTEN_BINDINGS(cscd) {
  using namespace cscd;
  using namespace cscd::binding;
  function("inspect", &inspect);
  function("evaluate", &evaluate);
  function("evaluateCloud", &evaluateCloud);
  function("optionLimits", &optionLimits); // test-only: tests/unit/options.test.ts
  class_<SurfaceBinding>("Surface")
      .constructor<const val&, const val&>()
      .function("error", &SurfaceBinding::error)
      .function("facts", &SurfaceBinding::facts)
      .function("distanceFromVertex", &SurfaceBinding::distanceFromVertex)
      .function("exactDistanceFromVertex", &SurfaceBinding::exactDistanceFromVertex)
      .function("separator", &SurfaceBinding::separator)
      .function("distanceFromPoints", &SurfaceBinding::distanceFromPoints);
  bindPipeline<MeshRealization, SurfaceBinding, /*multiscale=*/true>("Pipeline");
  bindPipeline<PointCloudRealization, CloudBinding>("CloudPipeline");
  class_<CloudBinding>("Cloud")
      .constructor<const val&, const val&, const val&>()
      .function("error", &CloudBinding::error)
      .function("facts", &CloudBinding::facts)
      .function("distance", &CloudBinding::distance)
      .function("referenceDistance", &CloudBinding::referenceDistance)
      .function("distanceFromPoints", &CloudBinding::distanceFromPoints)
      .function("windingNumbers", &CloudBinding::windingNumbers)
      .function("inside", &CloudBinding::inside)
      .function("project", &CloudBinding::project)
      .function("shortenLoop", &CloudBinding::shortenLoop)
      .function("neighbourhood", &CloudBinding::neighbourhood)
      .function("separatorStages", &CloudBinding::separatorStages);
}
