#pragma once

// The binding of Pipeline<Realization>, one template for every realization: a resumable job over a shape
// (which must outlive it) whose step() streams the new candidates' loops and whose finish() returns the
// skeleton record (lib/core/types.ts: Skeleton). A realization's module registers it with
// bindPipeline<Realization, ShapeBinding>("Pipeline"); ShapeBinding::shape() is the realization's shape,
// or null when it could not be opened.
#include "bindings/convert.h"
#include "cscd/pipeline.h"

#include <emscripten/bind.h>

#include <algorithm>
#include <memory>
#include <optional>

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
public:
  PipelineBinding(ShapeBinding& shape, const val& options) {
    try {
      if (!shape.shape()) throw InputError("the shape could not be opened");
      settings = toOptions(options);
      realization = std::make_unique<Realization>(*shape.shape(), settings);
      pipeline = std::make_unique<Pipeline<Realization>>(*realization, settings);
    } catch (...) {
      failure = failureOf(std::current_exception());
    }
  }

  val error() const { return failure ? toVal(*failure) : val::null(); }

  // Stage 1 for `count` more sources; the loops drawn since the last call come along for display.
  val step(double count) {
    return reportingErrors([&] {
      Progress progress = pipeline->step(size_t(std::max(1.0, count)));
      val newLoops = val::array();
      std::vector<uint8_t> newClosed;
      for (size_t i = loopsReported; i < progress.done; i++) {
        newLoops.call<void>("push", toFloat64Array(pipeline->candidates()[i].loop));
        newClosed.push_back(pipeline->candidates()[i].closed);
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
    return reportingErrors([&] { return toVal(pipeline->finish(), pipeline->candidates(), settings); });
  }

private:
  Options settings;
  std::unique_ptr<Realization> realization;
  std::unique_ptr<Pipeline<Realization>> pipeline;
  size_t loopsReported = 0;
  std::optional<Failure> failure;
};

template <class Realization, class ShapeBinding>
void bindPipeline(const char* name) {
  using Binding = PipelineBinding<Realization, ShapeBinding>;
  emscripten::class_<Binding>(name)
      .template constructor<ShapeBinding&, const val&>()
      .function("error", &Binding::error)
      .function("step", &Binding::step)
      .function("finish", &Binding::finish);
}

} // namespace binding
} // namespace cscd
