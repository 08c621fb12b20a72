// A toy realization for testing the generic pipeline (tests/unit/pipeline-toy.test.ts) in milliseconds:
// prune, pack, regions to graph, clique to star, bands and the auto stop, through the same binding
// template as CSCD-M's. The shape is a graph of points one unit apart on the axes of tubes of radius 1:
//   "star"      three arms of kArm points from a centre point, the first point of each arm joined to
//               the other two (as the ring of triangles around a mesh's junction joins its three parts);
//   "ring"      a circle of kRing points;
//   "lopsided"  the star, but sources are never drawn on its third arm, so coverage stalls below 99%.
// Its rules, which the test restates:
//   separator(s)  no loop within 2 of the star's centre (failed); at an arm's last point a loop of
//                 radius 0.2 (shorter than 3 units: pruned as short); elsewhere a circle of radius 1
//                 around the axis at s, score 1, its centroid outside the shape when s % 7 == 3;
//   nextSource    uniform over the drawable points (std::mt19937 seeded with the seed option);
//   cover/coverage  points within 2 units of a drawn source, as a share of all points;
//   overlaps      loops whose sources lie within 3 units along the graph;
//   regions       each point goes to its nearest packed source along the graph (ties: lower region).
#include "bindings/pipeline_binding.h"

#include <emscripten/bind.h>

#include <cmath>
#include <deque>
#include <limits>
#include <random>
#include <string>

namespace cscd {
namespace {

using geometrycentral::Vector3;

constexpr size_t kArm = 20;
constexpr size_t kRing = 60;
constexpr double kCoverHops = 2;
constexpr double kOverlapHops = 3;

struct ToyShape {
  explicit ToyShape(const std::string& kind) : kind(kind) {
    if (kind == "ring") {
      const double radius = kRing / (2 * M_PI);
      for (size_t i = 0; i < kRing; i++) {
        const double a = 2 * M_PI * double(i) / kRing;
        add({radius * std::cos(a), radius * std::sin(a), 0}, {-std::sin(a), std::cos(a), 0});
        if (i > 0) join(i - 1, i);
      }
      join(kRing - 1, 0);
    } else if (kind == "star" || kind == "lopsided") {
      add({0, 0, 0}, {1, 0, 0});
      for (size_t arm = 0; arm < 3; arm++) {
        const double a = 2 * M_PI * double(arm) / 3;
        const Vector3 axis{std::cos(a), std::sin(a), 0};
        for (size_t k = 1; k <= kArm; k++) {
          add(double(k) * axis, axis);
          join(k == 1 ? 0 : samples.positions.size() - 2, samples.positions.size() - 1);
        }
      }
      join(1, 1 + kArm);
      join(1, 1 + 2 * kArm);
      join(1 + kArm, 1 + 2 * kArm);
    } else {
      throw InputError("toy shape must be 'star', 'ring' or 'lopsided', got '" + kind + "'");
    }
  }

  size_t size() const { return samples.positions.size(); }
  bool star() const { return kind != "ring"; }
  bool tip(size_t s) const { return star() && s > 0 && (s - 1) % kArm == kArm - 1; }
  bool drawable(size_t s) const { return kind != "lopsided" || s <= 2 * kArm; }

  // Distances along the graph from the given points (each its own label); ties go to the lower label.
  void distances(const std::vector<size_t>& from, std::vector<double>& distance, std::vector<uint32_t>& label) const {
    distance.assign(size(), std::numeric_limits<double>::infinity());
    label.assign(size(), uint32_t(from.size()));
    std::deque<size_t> queue;
    for (size_t i = 0; i < from.size(); i++) {
      if (distance[from[i]] == 0) continue;
      distance[from[i]] = 0;
      label[from[i]] = uint32_t(i);
      queue.push_back(from[i]);
    }
    while (!queue.empty()) { // unit edges: breadth first is Dijkstra
      const size_t v = queue.front();
      queue.pop_front();
      for (size_t w : neighbours[v]) {
        if (distance[w] < distance[v] + 1 || (distance[w] == distance[v] + 1 && label[w] <= label[v])) continue;
        if (distance[w] == std::numeric_limits<double>::infinity()) queue.push_back(w);
        distance[w] = distance[v] + 1;
        label[w] = label[v];
      }
    }
  }

  std::string kind;
  Samples samples;
  std::vector<Vector3> axes;
  std::vector<std::vector<size_t>> neighbours;

private:
  void add(const Vector3& p, const Vector3& axis) {
    samples.positions.push_back(p);
    samples.weights.push_back(1);
    axes.push_back(axis);
    neighbours.emplace_back();
  }
  void join(size_t a, size_t b) {
    samples.edges.push_back({uint32_t(a), uint32_t(b)});
    neighbours[a].push_back(b);
    neighbours[b].push_back(a);
  }
};

class ToyRealization {
public:
  using Candidate = cscd::Candidate;

  ToyRealization(const ToyShape& shape, const Options& options) : shape(shape), random(options.seed), covered(shape.size(), 0) {
    for (size_t s = 0; s < shape.size(); s++)
      if (shape.drawable(s)) drawable.push_back(s);
  }

  Candidate separator(size_t source) {
    Candidate c;
    c.source = source;
    const Vector3 centre = shape.samples.positions[source];
    if (shape.star() && norm(centre) <= 2) return c;
    c.found = true;
    const double radius = shape.tip(source) ? 0.2 : 1;
    const Vector3 axis = shape.axes[source], side = cross(axis, Vector3{0, 0, 1}), up = cross(side, axis);
    for (size_t k = 0; k < 12; k++) {
      const double a = 2 * M_PI * double(k) / 12;
      c.loop.push_back(centre + radius * (std::cos(a) * side + std::sin(a) * up));
    }
    c.length = 2 * M_PI * radius;
    c.score = 1;
    c.centroidInside = source % 7 != 3;
    return c;
  }

  size_t nextSource() { return drawable[std::uniform_int_distribution<size_t>(0, drawable.size() - 1)(random)]; }

  void cover(const Candidate& c) {
    drawn.push_back(c.source);
    std::vector<double> distance;
    std::vector<uint32_t> label;
    shape.distances(drawn, distance, label);
    for (size_t s = 0; s < shape.size(); s++) covered[s] = distance[s] <= kCoverHops;
  }

  double coverage() const {
    size_t n = 0;
    for (char c : covered) n += c;
    return double(n) / double(shape.size());
  }

  double resolution() const { return 1; }
  bool noisy() const { return false; }

  std::vector<std::vector<size_t>> overlaps(const Selection<Candidate>& kept) const {
    std::vector<std::vector<size_t>> overlapping(kept.size());
    for (size_t i = 0; i < kept.size(); i++) {
      std::vector<double> distance;
      std::vector<uint32_t> label;
      shape.distances({kept[i]->source}, distance, label);
      for (size_t j = 0; j < kept.size(); j++)
        if (j != i && distance[kept[j]->source] <= kOverlapHops) overlapping[i].push_back(j);
    }
    return overlapping;
  }

  Regions regions(const Selection<Candidate>& packed) const {
    std::vector<size_t> from;
    for (const Candidate* c : packed) from.push_back(c->source);
    Regions r;
    shape.distances(from, r.distance, r.label);
    r.count = std::max<size_t>(packed.size(), 1); // no separator: the whole shape is one region
    for (uint32_t& l : r.label) l = std::min<uint32_t>(l, uint32_t(r.count - 1));
    r.centroid.assign(r.count, Vector3{0, 0, 0});
    r.area.assign(r.count, 0);
    for (size_t s = 0; s < shape.size(); s++) {
      r.centroid[r.label[s]] += shape.samples.positions[s];
      r.area[r.label[s]] += 1;
    }
    for (size_t i = 0; i < r.count; i++) r.centroid[i] /= r.area[i];
    for (const auto& e : shape.samples.edges) {
      const size_t a = r.label[e[0]], b = r.label[e[1]];
      if (a != b) r.adjacent.insert({std::min(a, b), std::max(a, b)});
    }
    for (size_t s = 0; s < shape.size(); s++) { // a point that sees three regions is where they meet
      std::set<size_t> seen{r.label[s]};
      for (size_t w : shape.neighbours[s]) seen.insert(r.label[w]);
      if (seen.size() == 3)
        r.junctions.emplace(std::array<size_t, 3>{*seen.begin(), *std::next(seen.begin()), *seen.rbegin()},
                            shape.samples.positions[s]);
    }
    return r;
  }

  void centre(SkeletonGraph&, const Selection<Candidate>&) const {} // region centroids lie on the axes

  const Samples& samples() const { return shape.samples; }
  size_t sourceCount() const { return shape.samples.positions.size(); }

  // Within the tube of radius 1 around the nearest point's axis.
  bool inside(const Vector3& p) const {
    for (size_t s = 0; s < shape.size(); s++) {
      const Vector3 d = p - shape.samples.positions[s];
      if (norm(d - dot(d, shape.axes[s]) * shape.axes[s]) <= 1 && std::abs(dot(d, shape.axes[s])) <= 0.5) return true;
    }
    return false;
  }

  void fitRadii(SkeletonGraph& graph) const { graph.radii.assign(graph.nodes.size(), 1); }

private:
  const ToyShape& shape;
  std::mt19937 random;
  std::vector<size_t> drawable, drawn;
  std::vector<char> covered;
};

// Opens the toy shape the way SurfaceBinding opens a mesh: a bad kind is an error value, not a throw.
class ToyShapeBinding {
public:
  explicit ToyShapeBinding(const std::string& kind) {
    try {
      toy = std::make_unique<ToyShape>(kind);
    } catch (...) {
      failure = binding::failureOf(std::current_exception());
    }
  }
  emscripten::val error() const { return failure ? binding::toVal(*failure) : emscripten::val::null(); }
  const ToyShape* shape() const { return toy.get(); }

private:
  std::unique_ptr<ToyShape> toy;
  std::optional<binding::Failure> failure;
};

} // namespace
} // namespace cscd

EMSCRIPTEN_BINDINGS(cscd_toy) {
  using namespace cscd;
  emscripten::class_<ToyShapeBinding>("ToyShape")
      .constructor<const std::string&>()
      .function("error", &ToyShapeBinding::error);
  binding::bindPipeline<ToyRealization, ToyShapeBinding>("Pipeline");
}
