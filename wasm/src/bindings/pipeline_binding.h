#pragma once

// The binding of Pipeline<Realization>, one template for every realization: a resumable job over a shape
// (which must outlive it) whose step() streams the new candidates' loops and whose finish() returns the
// skeleton record (lib/core/types.ts: Skeleton). For a pool of workers, each with its own module and
// shape, one pipeline draws the sources (draw), the others compute their separators (separators) and
// the first takes them back in draw order (accept); candidates cross as records
// (CandidateRecord below, exact: the same bits whichever worker computed them). A realization's module
// registers it with bindPipeline<Realization, ShapeBinding>("Pipeline"); ShapeBinding::shape() is the
// realization's shape, or null when it could not be opened, and CandidateRecord<its Candidate> says how
// its candidates cross.
#include "bindings/convert.h"
#include "cscd/pipeline.h"

#include <emscripten/bind.h>

#include <algorithm>
#include <memory>
#include <optional>
#include <string>

namespace cscd {
namespace binding {

inline const char* fateName(Fate fate) {
  switch (fate) {
  case Fate::Packed: return "packed";
  case Fate::Overlapping: return "overlapping";
  case Fate::Short: return "short";
  case Fate::Outside: return "outside";
  case Fate::Failed: return "failed";
  }
  return "failed";
}

// A candidate as a record of the JS heap and back (lib/core/types.ts: CandidateRecord). The generic
// fields are written here; a realization's specialisation adds its own (on a mesh, the surface points).
template <class C>
struct CandidateRecord;

inline val baseRecord(const Candidate& c) {
  val o = val::object();
  o.set("source", c.source);
  o.set("found", c.found);
  o.set("loop", toFloat64Array(c.loop));
  o.set("closed", c.closed);
  o.set("length", c.length);
  o.set("score", c.score);
  o.set("centroidInside", c.centroidInside);
  return o;
}

inline void readBaseRecord(const val& o, Candidate& c) {
  c.source = o["source"].as<size_t>();
  c.found = o["found"].as<bool>();
  const std::vector<double> flat = emscripten::convertJSArrayToNumberVector<double>(o["loop"]);
  for (size_t i = 0; i + 2 < flat.size(); i += 3) c.loop.push_back({flat[i], flat[i + 1], flat[i + 2]});
  c.closed = o["closed"].as<bool>();
  c.length = o["length"].as<double>();
  c.score = o["score"].as<double>();
  c.centroidInside = o["centroidInside"].as<bool>();
}

template <>
struct CandidateRecord<Candidate> {
  template <class Shape>
  static val write(const Candidate& c, const Shape&) { return baseRecord(c); }
  template <class Shape>
  static Candidate read(const val& o, const Shape&) {
    Candidate c;
    readBaseRecord(o, c);
    return c;
  }
};

template <class C>
val toVal(const Skeleton& skeleton, const std::vector<C>& drawn, const Options& options) {
  const SkeletonGraph& g = skeleton.graph;
  val o = val::object();
  o.set("nodes", toFloat64Array(g.nodes));
  o.set("radii", toFloat64Array(g.radii));
  o.set("edges", toPairArray(g.edges));
  o.set("vertexToNode", toTypedArray("Uint32Array", skeleton.vertexToNode));

  std::vector<uint32_t> sources;
  std::vector<double> scores;
  std::vector<uint8_t> closed;
  val loops = val::array(), fates = val::array();
  for (size_t i = 0; i < drawn.size(); i++) {
    const Candidate& c = drawn[i];
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
  stats.set("n", drawn.size());
  stats.set("candidates", size_t(std::count_if(drawn.begin(), drawn.end(), [](const Candidate& c) { return c.found; })));
  stats.set("pruned", skeleton.pruned);
  stats.set("packed", skeleton.packed.size());
  stats.set("cycles", g.cycleRank());
  stats.set("seed", options.seed);
  stats.set("timings", toVal(skeleton.timings));
  o.set("stats", stats);
  return o;
}

template <class Realization, class ShapeBinding>
class PipelineBinding {
  using Candidate = typename Realization::Candidate;
  using Record = CandidateRecord<Candidate>;

public:
  PipelineBinding(ShapeBinding& shape_, const val& options) : shape(shape_) {
    open(options, [&](const Options& settings) { return std::make_unique<Realization>(*shape.shape(), settings); });
  }

  // Multiscale (meshes): stage 1 on `working` (sources and candidate records are its), stage 2 and the
  // skeleton on `given`, the mesh as given.
  PipelineBinding(ShapeBinding& working, const val& options, ShapeBinding& given) : shape(working) {
    open(options, [&](const Options& settings) {
      if (!given.shape()) throw InputError("the shape could not be opened");
      return std::make_unique<Realization>(*given.shape(), settings, shape.shape());
    });
  }

  val error() const { return failure ? toVal(*failure) : val::null(); }

  // Stage 1 for `count` more sources; the loops drawn since the last call come along for display.
  val step(double count) {
    return reportingErrors([&] { return progressRecord(pipeline->step(size_t(std::max(1.0, count)))); });
  }

  // The sources drawn since the last call (after accept() takes candidates, as many new ones; none once
  // stage 1 is done).
  val draw() {
    return reportingErrors([&] {
      std::vector<size_t> sources = pipeline->draw();
      return toTypedArray("Uint32Array", std::vector<uint32_t>(sources.begin(), sources.end()));
    });
  }

  // Stage 1 from the given sources, here, without drawing or keeping anything: a pool worker's share.
  val separators(const val& sources) {
    return reportingErrors([&] {
      val records = val::array();
      for (uint32_t source : emscripten::convertJSArrayToNumberVector<uint32_t>(sources))
        records.call<void>("push", Record::write(realization->separator(checkedSource(source)), *shape.shape()));
      return records;
    });
  }

  // The candidates of the oldest sources draw() gave and accept() did not take yet, as records, in draw order.
  val accept(const val& records) {
    return reportingErrors([&] {
      std::vector<Candidate> candidates;
      const size_t count = records["length"].as<size_t>();
      for (size_t i = 0; i < count; i++) candidates.push_back(Record::read(records[i], *shape.shape()));
      return progressRecord(pipeline->accept(std::move(candidates)));
    });
  }

  val finish() {
    return reportingErrors([&] { return toVal(pipeline->finish(), pipeline->candidates(), settings); });
  }

private:
  template <class Make>
  void open(const val& options, Make make) {
    try {
      if (!shape.shape()) throw InputError("the shape could not be opened");
      settings = toOptions(options);
      realization = make(settings);
      pipeline = std::make_unique<Pipeline<Realization>>(*realization, settings);
    } catch (...) {
      failure = failureOf(std::current_exception());
    }
  }

  // Progress, with the loops taken since the last report (for display): those of accepted candidates
  // only, since the auto stop may still drop a source drawn ahead.
  val progressRecord(const Progress& progress) {
    val newLoops = val::array();
    std::vector<uint8_t> newClosed;
    const auto& taken = pipeline->candidates();
    for (size_t i = loopsReported; i < taken.size(); i++) {
      newLoops.call<void>("push", toFloat64Array(taken[i].loop));
      newClosed.push_back(taken[i].closed);
    }
    loopsReported = taken.size();
    val o = val::object();
    o.set("done", progress.done);
    o.set("total", progress.total);
    o.set("finished", progress.finished);
    o.set("newLoops", newLoops);
    o.set("newClosed", toTypedArray("Uint8Array", newClosed));
    return o;
  }

  size_t checkedSource(uint32_t source) const {
    if (source >= realization->sourceCount())
      throw InputError("source " + std::to_string(source) + " is out of range");
    return source;
  }

  ShapeBinding& shape;
  Options settings;
  std::unique_ptr<Realization> realization;
  std::unique_ptr<Pipeline<Realization>> pipeline;
  size_t loopsReported = 0;
  std::optional<Failure> failure;
};

// multiscale: the realization also runs stage 1 on a working copy of the shape (a third argument).
template <class Realization, class ShapeBinding, bool multiscale = false>
void bindPipeline(const char* name) {
  using Binding = PipelineBinding<Realization, ShapeBinding>;
  auto bound = emscripten::class_<Binding>(name).template constructor<ShapeBinding&, const val&>();
  if constexpr (multiscale) bound.template constructor<ShapeBinding&, const val&, ShapeBinding&>();
  bound.function("error", &Binding::error)
      .function("step", &Binding::step)
      .function("draw", &Binding::draw)
      .function("separators", &Binding::separators)
      .function("accept", &Binding::accept)
      .function("finish", &Binding::finish);
}

} // namespace binding
} // namespace cscd
