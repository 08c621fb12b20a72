#pragma once

// The CSCD framework (paper Alg. 1), independent of the shape's representation. A Realization (CSCD-M:
// MeshRealization in mesh/realization.h) supplies the representation-specific steps; its Candidate is a
// cscd::Candidate with whatever the realization needs to remember of a separator (on a mesh, the loop's
// surface points). The pipeline owns the candidates and hands them to the steps that need them:
//   Candidate separator(size_t source)          stage 1 from one source (Alg. 2)
//   size_t nextSource()                         adaptive sampling (Sec. 4.1.7), away from what is covered
//                                               and from the sources drawn and not covered yet
//   void cover(Candidate& c)                    what the candidate's source and loop now cover (it may
//                                               release what only covering needed); in draw order
//   double coverage()                           share of the shape near what is covered
//   double resolution()                         mean sample spacing (edge length)
//   std::vector<std::vector<size_t>> overlaps(const Selection<Candidate>& kept)   overlap graph of kept
//   Regions regions(const Selection<Candidate>& packed)
//   void centre(SkeletonGraph& graph, const Selection<Candidate>& packed)   region and branch node positions
//   const Samples& samples()                    the shape's elements, their areas and neighbours
//   size_t sourceCount()                        how many elements sources are drawn from (a mesh's
//                                               working copy may have fewer than the shape)
//   bool inside(const Vector3& p)               whether p lies inside the shape (for closed separators)
//   bool noisy()                                whether separators may go round the shape's noise (a noisy
//                                               cloud): a separator then does not make a short leaf a feature,
//                                               and many regions round a deep middle may be tiles
//   void fitRadii(SkeletonGraph& graph)         node radii fitted to the shape around the final skeleton

#include "cscd/bands.h"
#include "cscd/graph.h"
#include "cscd/measures.h"
#include "cscd/options.h"
#include "cscd/pack.h"
#include "cscd/regions.h"
#include "cscd/stage_clock.h"
#include "cscd/stray_cycles.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <deque>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace cscd {

// A separator found in stage 1, as stage 2 needs it.
struct Candidate {
  size_t source = 0;
  bool found = false;                           // stage 1 produced a loop
  std::vector<geometrycentral::Vector3> loop;   // polyline on the shape
  bool closed = true;                           // false: a path whose ends lie on the shape's boundary
  double length = 0;
  double score = 0;
  bool centroidInside = false;
};

// Some of the pipeline's candidates, in the order a step works on them (stage 2: the kept, the packed).
template <class C>
using Selection = std::vector<const C*>;

enum class Fate { Packed, Overlapping, Short, Outside, Failed };

// Stage 2's result; the candidates it speaks of stay with the pipeline (Pipeline::candidates()).
struct Skeleton {
  SkeletonGraph graph;
  std::vector<uint32_t> vertexToNode; // per element of the shape: its region's node
  std::vector<Fate> fates;            // per candidate
  std::vector<size_t> packed; // candidate indices; packed separator i owns region i (its vertices nearest to it)
  size_t pruned = 0;
  std::vector<std::pair<std::string, double>> timings; // milliseconds per stage
};

struct Progress {
  size_t done = 0;
  size_t total = 0;
  bool finished = false;
};

// Auto mode: sampling stops when the shape is covered (99% of it near a source or separator, as the
// realization measures it) or when the last 20 sources added less than 0.5% coverage; never past
// kMaxAutoSources. The front ends state the rule from AUTO_N in lib/core/options.ts, held to these.
constexpr size_t kMaxAutoSources = 400;
constexpr size_t kAutoWindow = 20;
constexpr double kAutoCovered = 0.99;
constexpr double kAutoMinGain = 0.005;

// Bands are one separator radius wide (bands.h): nodes about a radius apart along a tube, as dense as
// the shape can show (a thinner slice has no new cross-section to tell) and each node's vertices
// within about a radius of it.
constexpr double kBandWidth = 1.0;

// The radius of the tube a separator goes around: a loop is its circumference; a path across a sheet
// is half the circumference of the flattened tube the sheet is.
inline double separatorRadius(const Candidate& c) { return c.length / (c.closed ? 2 * M_PI : M_PI); }

// The Realization interface, checked by the compiler (a C++17 stand-in for a concept): each step with
// the signature the pipeline calls it with.
template <class R>
struct IsRealization {
  using C = typename R::Candidate;
  static constexpr bool value =
      std::is_base_of_v<Candidate, C> && std::is_same_v<decltype(std::declval<R&>().separator(size_t())), C> &&
      std::is_convertible_v<decltype(std::declval<R&>().nextSource()), size_t> &&
      std::is_void_v<decltype(std::declval<R&>().cover(std::declval<C&>()))> &&
      std::is_convertible_v<decltype(std::declval<R&>().coverage()), double> &&
      std::is_convertible_v<decltype(std::declval<R&>().resolution()), double> &&
      std::is_same_v<decltype(std::declval<R&>().overlaps(std::declval<const Selection<C>&>())),
                     std::vector<std::vector<size_t>>> &&
      std::is_same_v<decltype(std::declval<R&>().regions(std::declval<const Selection<C>&>())), Regions> &&
      std::is_void_v<decltype(std::declval<R&>().centre(std::declval<SkeletonGraph&>(),
                                                         std::declval<const Selection<C>&>()))> &&
      std::is_same_v<decltype(std::declval<R&>().samples()), const Samples&> &&
      std::is_convertible_v<decltype(std::declval<R&>().sourceCount()), size_t> &&
      std::is_convertible_v<decltype(std::declval<R&>().inside(std::declval<const geometrycentral::Vector3&>())), bool> &&
      std::is_convertible_v<decltype(std::declval<R&>().noisy()), bool> &&
      std::is_void_v<decltype(std::declval<R&>().fitRadii(std::declval<SkeletonGraph&>()))>;
};

template <class Realization>
class Pipeline {
  static_assert(IsRealization<Realization>::value,
                "a Realization needs every step listed at the top of cscd/pipeline.h, with those signatures");

public:
  using Candidate = typename Realization::Candidate;

  Pipeline(Realization& realization, const Options& options) : realization(realization), options(options) {}

  // Every candidate of stage 1 so far, in draw order (stage 2 keeps them: its fates index them).
  const std::vector<Candidate>& candidates() const { return drawn; }

  // Stage 1 with sources drawn ahead: the pipeline keeps `drawAhead` sources drawn whose candidates it
  // has not taken yet, and draws the next one right after taking each candidate, so the draw of source i
  // knows the candidates of sources 0 .. i - drawAhead and keeps away from the sources in between. Their
  // separators do not depend on each other, so they may be computed anywhere and in any order (a worker
  // pool: draw, then accept) and the skeleton stays the same; step() computes them here.

  // The sources drawn since the last call, in draw order (none once stage 1 is done).
  std::vector<size_t> draw() {
    if (drawn.empty() && pending.empty()) stage1Start = std::chrono::steady_clock::now();
    fillWindow();
    return std::exchange(fresh, {});
  }

  // The candidates of the oldest sources drawn and not taken yet, as many as given, in draw order. In auto
  // mode the stop rule is applied after each one, so stage 1 may end before the last (the later
  // candidates and the sources still drawn ahead are dropped).
  Progress accept(std::vector<Candidate> candidates) {
    if (candidates.size() > pending.size()) throw std::logic_error("more candidates than sources drawn");
    for (size_t k = 0; k < candidates.size() && !done; k++) {
      if (candidates[k].source != pending.front()) throw std::logic_error("candidates must come in draw order");
      pending.pop_front();
      drawn.push_back(std::move(candidates[k]));
      realization.cover(drawn.back());
      coverageHistory.push_back(realization.coverage());
      done = options.n > 0 ? drawn.size() >= size_t(options.n) : autoSaturated();
      fillWindow();
    }
    if (done) {
      pending.clear();
      fresh.clear();
      stage1Ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - stage1Start).count();
    }
    return progress();
  }

  // Stage 1 here, `count` more sources (or until stage 1 is done), one at a time.
  Progress step(size_t count) {
    for (size_t k = 0; k < count && !done; k++) {
      draw();
      accept({realization.separator(pending.front())});
    }
    return progress();
  }

  // Sources done: their candidates taken.
  Progress progress() const { return {drawn.size(), done ? drawn.size() : total(), done}; }

  // Stage 2 (after the remaining sources of stage 1): prune, pack, regions, graph, clique to star, bands,
  // and cycles that bound no hole opened.
  Skeleton finish() {
    while (!done) step(1);
    Skeleton skeleton;
    skeleton.timings.emplace_back("separators", stage1Ms);
    StageClock clock(skeleton.timings);

    skeleton.fates.assign(drawn.size(), Fate::Overlapping);
    std::vector<size_t> kept;
    const double shortest = options.pruneLengthFactor * realization.resolution();
    for (size_t i = 0; i < drawn.size(); i++) {
      const Candidate& c = drawn[i];
      Fate& fate = skeleton.fates[i];
      fate = !c.found ? Fate::Failed : c.length < shortest ? Fate::Short : !c.centroidInside ? Fate::Outside : fate;
      if (fate == Fate::Overlapping) kept.push_back(i);
      else if (fate != Fate::Failed) skeleton.pruned++;
    }
    clock.lap("prune");

    std::vector<std::vector<size_t>> overlaps = realization.overlaps(select(kept));
    std::vector<double> scores;
    for (size_t i : kept) scores.push_back(drawn[i].score);
    for (size_t j : packSeparators(scores, overlaps)) {
      skeleton.packed.push_back(kept[j]);
      skeleton.fates[kept[j]] = Fate::Packed;
    }
    clock.lap("pack");

    const Selection<Candidate> packed = select(skeleton.packed);
    Regions regions = realization.regions(packed);
    clock.lap("regions");

    SkeletonGraph& graph = skeleton.graph;
    graph.nodes = regions.centroid;
    graph.weights = regions.area;
    graph.edges.assign(regions.adjacent.begin(), regions.adjacent.end());
    std::vector<SeparatorFrame> frames;
    for (const Candidate* c : packed)
      frames.push_back(c->closed ? SeparatorFrame{loopCentroid(c->loop, true), loopNormal(c->loop), separatorRadius(*c)} : SeparatorFrame{});
    const auto inside = [&](const geometrycentral::Vector3& p) { return realization.inside(p); };
    cliquesToStars(graph, regions.junctions, frames, realization.samples().positions, inside, realization.noisy());
    realization.centre(graph, packed);
    clock.lap("graph");

    std::vector<double> width(regions.count, 0);
    std::vector<char> solid(regions.count, 0);
    for (size_t r = 0; r < packed.size(); r++) {
      width[r] = kBandWidth * separatorRadius(*packed[r]);
      solid[r] = packed[r]->closed;
    }
    skeleton.vertexToNode = refineIntoBands(graph, regions, realization.samples(), width, solid, inside);
    // On the final graph, not on the region graph where such cycles arise: its cone is then sampled between
    // the centred nodes along the cycle, not between a few region centroids.
    openFilledCycles(graph, inside);
    realization.fitRadii(graph);
    if (openCyclesThroughAir(graph, realization.samples().positions)) realization.fitRadii(graph);
    // Radii fitted again after a merge may leave another spur within its junction's two radii: until none is.
    while (realization.noisy() && mergeNoiseSpurs(graph, skeleton.vertexToNode, realization.samples())) realization.fitRadii(graph);
    clock.lap("bands");
    return skeleton;
  }

private:
  Selection<Candidate> select(const std::vector<size_t>& indices) const {
    Selection<Candidate> selection;
    for (size_t i : indices) selection.push_back(&drawn[i]);
    return selection;
  }

  // Draws until drawAhead sources are pending (or every source of stage 1 is drawn).
  void fillWindow() {
    while (!done && pending.size() < size_t(options.drawAhead) && drawn.size() + pending.size() < total()) {
      pending.push_back(realization.nextSource());
      fresh.push_back(pending.back());
    }
  }

  size_t total() const { return options.n > 0 ? size_t(options.n) : kMaxAutoSources; }

  bool autoSaturated() const {
    const size_t k = coverageHistory.size();
    if (k >= kMaxAutoSources || coverageHistory.back() >= kAutoCovered) return true;
    return k > kAutoWindow && coverageHistory.back() - coverageHistory[k - 1 - kAutoWindow] < kAutoMinGain;
  }

  Realization& realization;
  Options options;
  std::vector<Candidate> drawn;
  std::deque<size_t> pending; // sources drawn, their candidates not taken yet
  std::vector<size_t> fresh;  // sources drawn since draw() last gave them
  std::vector<double> coverageHistory;
  std::chrono::steady_clock::time_point stage1Start; // the first draw
  double stage1Ms = 0;                               // from the first draw to the last candidate taken, wherever computed
  bool done = false;
};

} // namespace cscd
