// embind surface of the core. Arrays cross as typed arrays (one copy in, one copy out: JS owns every
// result, so heap growth cannot invalidate it). Nothing here throws into JS: a call that fails returns
// {coreError: kind, message} (ErrorKind below), which lib/core turns into a CoreError of that kind.
#include "cscd/pipeline.h"
#include "evaluate/reconstruction_error.h"
#include "mesh/realization.h"
#include "mesh/separator.h"
#include "mesh/surface.h"

#include <emscripten/bind.h>
#include <emscripten/val.h>

#include <algorithm>
#include <cmath>
#include <exception>
#include <memory>
#include <optional>
#include <sstream>
#include <string>

using namespace emscripten;
using geometrycentral::surface::SurfacePoint;

namespace cscd {
namespace {

MeshArrays toArrays(const val& positions, const val& triangles) {
  MeshArrays arrays;
  arrays.positions = convertJSArrayToNumberVector<double>(positions);
  arrays.triangles = convertJSArrayToNumberVector<uint32_t>(triangles);
  return arrays;
}

val toFloat64Array(const std::vector<double>& values) {
  return val::global("Float64Array").new_(typed_memory_view(values.size(), values.data()));
}

template <class T>
val toTypedArray(const char* type, const std::vector<T>& values) {
  return val::global(type).new_(typed_memory_view(values.size(), values.data()));
}

val toFloat64Array(const std::vector<geometrycentral::Vector3>& points) {
  std::vector<double> flat;
  flat.reserve(3 * points.size());
  for (const auto& p : points) flat.insert(flat.end(), {p.x, p.y, p.z});
  return toFloat64Array(flat);
}

val toArray3(const geometrycentral::Vector3& v) {
  val a = val::array();
  for (double x : {v.x, v.y, v.z}) a.call<void>("push", x);
  return a;
}

val toArray3(const std::array<double, 3>& v) {
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
  o.set("bboxMin", toArray3(f.bboxMin));
  o.set("bboxMax", toArray3(f.bboxMax));
  o.set("bboxDiagonal", f.bboxDiagonal);
  o.set("meanEdgeLength", f.meanEdgeLength);
  return o;
}

val toVal(const std::vector<std::pair<std::string, double>>& timings) {
  val o = val::object();
  for (const auto& [stage, ms] : timings) o.set(stage, ms);
  return o;
}

const OptionRange& rangeOf(const std::string& name) {
  for (const OptionRange& range : kOptionRanges)
    if (name == range.name) return range;
  throw std::logic_error("no range for option " + name);
}

Options toOptions(const val& given) {
  Options options;
  if (given.isUndefined() || given.isNull()) return options;
  auto number = [&](const char* name, double fallback) {
    val v = given[name];
    if (v.isUndefined()) return fallback;
    const auto [_, low, high] = rangeOf(name);
    double x = v.as<double>();
    if (!(x >= low && x <= high)) {
      std::ostringstream msg;
      msg << "option " << name << " must be between " << low << " and " << high << ", got " << x;
      throw InputError(msg.str());
    }
    return x;
  };
  if (!given["target"].isUndefined()) {
    std::string target = given["target"].as<std::string>();
    if (target != "euclid" && target != "geodesic")
      throw InputError("option target must be 'euclid' or 'geodesic', got '" + target + "'");
    options.target = target == "euclid" ? TargetMode::Euclidean : TargetMode::Geodesic;
  }
  if (!given["sphere"].isUndefined()) options.sphere = given["sphere"].as<bool>();
  options.seed = uint32_t(number("seed", options.seed));
  options.angleThreshold = number("angleThreshold", options.angleThreshold);
  options.laplacianThreshold = number("laplacianThreshold", options.laplacianThreshold);
  options.pruneDepth = int(number("pruneDepth", options.pruneDepth));
  val n = given["n"];
  if (!n.isUndefined()) {
    if (n.isString()) {
      if (n.as<std::string>() != "auto") throw InputError("option n must be a number of sources or 'auto'");
      options.n = 0;
    } else {
      options.n = int(number("n", options.n));
    }
  }
  options.pruneLengthFactor = number("pruneLengthFactor", options.pruneLengthFactor);
  return options;
}

// The core's option defaults, ranges and auto-N constants, for the test that holds lib/core/options.ts to them.
val optionLimits() {
  const Options d;
  val defaults = val::object();
  defaults.set("target", std::string(d.target == TargetMode::Euclidean ? "euclid" : "geodesic"));
  defaults.set("sphere", d.sphere);
  defaults.set("seed", d.seed);
  defaults.set("angleThreshold", d.angleThreshold);
  defaults.set("laplacianThreshold", d.laplacianThreshold);
  defaults.set("pruneDepth", d.pruneDepth);
  defaults.set("n", d.n == 0 ? val("auto") : val(d.n));
  defaults.set("pruneLengthFactor", d.pruneLengthFactor);
  val ranges = val::object();
  for (const OptionRange& range : kOptionRanges) {
    val pair = val::array();
    pair.call<void>("push", range.low);
    pair.call<void>("push", range.high);
    ranges.set(range.name, pair);
  }
  val autoN = val::object();
  autoN.set("covered", kAutoCovered);
  autoN.set("window", double(kAutoWindow));
  autoN.set("minGain", kAutoMinGain);
  autoN.set("max", double(kMaxAutoSources));
  val limits = val::object();
  limits.set("defaults", defaults);
  limits.set("ranges", ranges);
  limits.set("autoN", autoN);
  return limits;
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
  const CutLocus& c = r.cutLocus;
  std::vector<uint32_t> vertices(c.vertices.begin(), c.vertices.end()), edges;
  for (const auto& e : c.edges) edges.insert(edges.end(), {uint32_t(e[0]), uint32_t(e[1])});
  val cutLocus = val::object();
  cutLocus.set("vertices", toTypedArray("Uint32Array", vertices));
  cutLocus.set("points", positionsOf(c.vertices));
  cutLocus.set("edges", toTypedArray("Uint32Array", edges));
  cutLocus.set("angleDeviation", toFloat64Array(c.angleDeviation));
  cutLocus.set("laplacian", toFloat64Array(c.laplacian));
  cutLocus.set("root", c.root);
  cutLocus.set("cycleRank", c.vertices.empty() ? 0 : c.cycleRank());
  o.set("cutLocus", cutLocus);

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
  if (r.sphere) {
    val sphere = val::object();
    sphere.set("center", toArray3(r.sphere->center));
    sphere.set("radius", r.sphere->radius);
    o.set("sphere", sphere);
  } else {
    o.set("sphere", val::null());
  }
  o.set("approxLength", r.approxLength);
  o.set("length", r.length);
  val areas = val::array();
  areas.call<void>("push", r.areas[0]);
  areas.call<void>("push", r.areas[1]);
  o.set("areas", areas);
  o.set("score", r.score);
  o.set("centroidInside", r.centroidInside);
  o.set("timings", toVal(r.timings));
  return o;
}

const char* fateName(Fate fate) {
  switch (fate) {
  case Fate::Packed: return "packed";
  case Fate::Overlapping: return "overlapping";
  case Fate::Short: return "short";
  case Fate::Outside: return "outside";
  case Fate::Failed: return "failed";
  }
  return "failed";
}

val toVal(const Skeleton& skeleton, const Options& options) {
  const SkeletonGraph& g = skeleton.graph;
  val o = val::object();
  o.set("nodes", toFloat64Array(g.nodes));
  o.set("radii", toFloat64Array(g.radii));
  std::vector<uint32_t> edges;
  for (const auto& e : g.edges) edges.insert(edges.end(), {uint32_t(e[0]), uint32_t(e[1])});
  o.set("edges", toTypedArray("Uint32Array", edges));
  o.set("vertexToNode", toTypedArray("Uint32Array", skeleton.vertexToNode));

  std::vector<uint32_t> sources;
  std::vector<double> scores;
  std::vector<uint8_t> closed;
  val loops = val::array(), fates = val::array();
  for (size_t i = 0; i < skeleton.candidates.size(); i++) {
    const Candidate& c = skeleton.candidates[i];
    sources.push_back(uint32_t(c.source));
    scores.push_back(c.score);
    closed.push_back(c.closed);
    loops.call<void>("push", toFloat64Array(c.loop));
    fates.call<void>("push", std::string(fateName(skeleton.fates[i])));
  }
  val candidates = val::object();
  candidates.set("sources", toTypedArray("Uint32Array", sources));
  candidates.set("loops", loops);
  candidates.set("closed", toTypedArray("Uint8Array", closed));
  candidates.set("scores", toFloat64Array(scores));
  candidates.set("fates", fates);
  o.set("candidates", candidates);
  std::vector<uint32_t> packed(skeleton.packed.begin(), skeleton.packed.end());
  o.set("packed", toTypedArray("Uint32Array", packed));

  val stats = val::object();
  stats.set("n", skeleton.candidates.size());
  stats.set("candidates", size_t(std::count_if(skeleton.candidates.begin(), skeleton.candidates.end(),
                                               [](const Candidate& c) { return c.found; })));
  stats.set("pruned", skeleton.pruned);
  stats.set("packed", skeleton.packed.size());
  stats.set("cycles", g.cycleRank());
  stats.set("seed", options.seed);
  stats.set("timings", toVal(skeleton.timings));
  o.set("stats", stats);
  return o;
}

// What went wrong, as the caller can act on it: its input or arguments (InputError), the heap (a failed
// allocation), or anything else (a library's failure or a bug).
enum class ErrorKind { Input, Memory, Internal };

struct Failure {
  ErrorKind kind;
  std::string message;
};

Failure failureOf(std::exception_ptr error) {
  try {
    std::rethrow_exception(error);
  } catch (const std::bad_alloc&) {
    return {ErrorKind::Memory, "out of memory: the mesh is too large for the WebAssembly heap"};
  } catch (const InputError& e) {
    return {ErrorKind::Input, e.what()};
  } catch (const std::exception& e) {
    return {ErrorKind::Internal, e.what()};
  } catch (...) {
    return {ErrorKind::Internal, "the core failed with an unknown error"};
  }
}

val toVal(const Failure& failure) {
  static const char* const kNames[] = {"input", "memory", "internal"};
  val o = val::object();
  o.set("coreError", std::string(kNames[int(failure.kind)]));
  o.set("message", failure.message);
  return o;
}

template <class Body>
val reportingErrors(Body&& body) {
  try {
    return body();
  } catch (...) {
    return toVal(failureOf(std::current_exception()));
  }
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
val evaluate(const val& positions, const val& triangles, const val& nodes, const val& edges, const val& radii) {
  return reportingErrors([&] {
    std::vector<double> xyz = convertJSArrayToNumberVector<double>(nodes);
    std::vector<uint32_t> pairs = convertJSArrayToNumberVector<uint32_t>(edges);
    if (xyz.size() % 3 != 0) throw InputError("skeleton nodes must be xyz triples");
    if (pairs.size() % 2 != 0) throw InputError("skeleton edges must be pairs of node indices");
    SkeletonCurves skeleton;
    for (size_t i = 0; i < xyz.size(); i += 3) skeleton.nodes.push_back({xyz[i], xyz[i + 1], xyz[i + 2]});
    for (size_t i = 0; i < pairs.size(); i += 2) skeleton.edges.push_back({pairs[i], pairs[i + 1]});
    if (!radii.isNull() && !radii.isUndefined()) skeleton.radii = convertJSArrayToNumberVector<double>(radii);

    return toVal(evaluateSkeleton(toArrays(positions, triangles), std::move(skeleton)));
  });
}

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
  size_t checkedVertex(double vertex) const {
    if (!(vertex >= 0) || vertex != std::floor(vertex) || vertex >= double(surface->vertexCount())) {
      std::ostringstream msg;
      msg << "vertex " << vertex << " is out of range (the mesh has " << surface->vertexCount() << " vertices)";
      throw InputError(msg.str());
    }
    return size_t(vertex);
  }

  std::unique_ptr<Surface> surface;
  std::optional<Failure> failure;
  friend class PipelineBinding;
};

// The whole pipeline as a resumable job over a surface (which must outlive it).
class PipelineBinding {
public:
  PipelineBinding(SurfaceBinding& surface, const val& options) {
    try {
      if (!surface.surface) throw InputError("the surface could not be opened");
      settings = toOptions(options);
      realization = std::make_unique<MeshRealization>(*surface.surface, settings);
      pipeline = std::make_unique<MeshPipeline>(*realization, settings);
    } catch (...) {
      failure = failureOf(std::current_exception());
    }
  }

  val error() const { return failure ? toVal(*failure) : val::null(); }

  val step(double count) {
    return reportingErrors([&] {
      size_t before = loopsReported;
      Progress progress = pipeline->step(size_t(std::max(1.0, count)));
      val newLoops = val::array();
      std::vector<uint8_t> newClosed;
      for (size_t i = before; i < progress.done; i++) {
        newLoops.call<void>("push", toFloat64Array(realization->loop(i)));
        newClosed.push_back(realization->closedAt(i));
      }
      loopsReported = progress.done;
      val o = val::object();
      o.set("done", progress.done);
      o.set("total", progress.total);
      o.set("finished", progress.finished);
      o.set("newLoops", newLoops);
      o.set("newClosed", toTypedArray("Uint8Array", newClosed));
      return o;
    });
  }

  val finish() {
    return reportingErrors([&] { return toVal(pipeline->finish(), settings); });
  }

private:
  Options settings;
  std::unique_ptr<MeshRealization> realization;
  std::unique_ptr<MeshPipeline> pipeline;
  size_t loopsReported = 0;
  std::optional<Failure> failure;
};

} // namespace
} // namespace cscd

EMSCRIPTEN_BINDINGS(cscd) {
  using namespace cscd;
  function("inspect", &inspect);
  function("evaluate", &evaluate);
  function("optionLimits", &optionLimits); // test-only: tests/unit/options.test.ts
  class_<SurfaceBinding>("Surface")
      .constructor<const val&, const val&>()
      .function("error", &SurfaceBinding::error)
      .function("facts", &SurfaceBinding::facts)
      .function("distanceFromVertex", &SurfaceBinding::distanceFromVertex)
      .function("exactDistanceFromVertex", &SurfaceBinding::exactDistanceFromVertex)
      .function("separator", &SurfaceBinding::separator)
      .function("distanceFromPoints", &SurfaceBinding::distanceFromPoints);
  class_<PipelineBinding>("Pipeline")
      .constructor<SurfaceBinding&, const val&>()
      .function("error", &PipelineBinding::error)
      .function("step", &PipelineBinding::step)
      .function("finish", &PipelineBinding::finish);
}
