#include "cscd/bands.h"

#include "cscd/union_find.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>
#include <optional>
#include <set>
#include <utility>

using geometrycentral::Vector3;

namespace cscd {
namespace {

constexpr uint32_t kNone = std::numeric_limits<uint32_t>::max();
// A leaf branch is a bump unless some part of it lies farther from its junction's node than this many
// junction radii: one radius to the junction's surface, one more beyond it.
constexpr double kBranchReach = 2.0;
// A leaf that touches pieces other than its neighbour is a branch of its own only when it reaches this
// many of the neighbour's radii from the neighbour's node: a radius past a bump's reach (at two radii an
// ear of armadillo_gel_pts that grazed its head stayed a spur).
constexpr double kTwigReach = 3.0;
// A leaf's node moves to its tip only when that is worth a tenth of its radius.
constexpr double kTipMove = 0.1;
// A leaf piece that lies within this many radii of its neighbour's node is the neighbour's end cap.
constexpr double kCapReach = 1.5;
// A node is centred on its elements when it has this many (fewer say little about a sphere), by this
// many fixed-point iterations, in this many rounds with the vertex map; a branch node moves at most
// this share of its fitted radius.
constexpr size_t kFitElements = 8;
constexpr int kFitIterations = 50;
constexpr int kFitRounds = 2;
constexpr double kBranchNodeFit = 0.5;
// A node farther from every element it owns than this many times their spread about their centroid
// stands apart from them (on a ring of elements round a node the ratio is at most 1); whether the way
// to them leaves the shape is asked at this many points less one, evenly along it.
constexpr double kDetached = 2.0;
constexpr int kDetachedProbes = 8;
// A loop is 2 pi band widths long (kBandWidth = 1): a region with less area than that many band widths
// times the element spacing does not hold a strip of elements along its loop.
constexpr double kIslandStrip = M_PI;

// A connected piece of one band of one region.
struct Piece {
  uint32_t region = 0;
  int64_t level = 0;
  uint32_t deepest = kNone; // its element farthest from the separators
  uint32_t nearest = kNone; // ... and nearest to them
  std::vector<uint32_t> elements;
};

struct Pieces {
  std::vector<uint32_t> of; // per element
  std::vector<Piece> list;
  std::map<std::array<uint32_t, 2>, uint32_t> contacts; // sorted piece pairs -> element edges between them
};

Pieces collectPieces(UnionFind& sets, const Regions& regions, const std::vector<int64_t>& level, const Samples& samples) {
  const size_t count = samples.positions.size();
  const std::vector<double>& distance = regions.distance;
  Pieces pieces;
  pieces.of.assign(count, kNone);
  std::vector<uint32_t> pieceOfRoot(count, kNone);
  for (uint32_t v = 0; v < count; v++) {
    uint32_t& p = pieceOfRoot[sets.find(v)];
    if (p == kNone) {
      p = uint32_t(pieces.list.size());
      pieces.list.push_back({regions.label[v], level[v], v, v, {}});
    }
    pieces.of[v] = p;
    Piece& piece = pieces.list[p];
    piece.elements.push_back(v);
    if (distance[v] > distance[piece.deepest]) piece.deepest = v;
    if (distance[v] < distance[piece.nearest]) piece.nearest = v;
  }
  for (const auto& [a, b] : samples.edges) {
    uint32_t pa = pieces.of[a], pb = pieces.of[b];
    if (pa != pb) pieces.contacts[{std::min(pa, pb), std::max(pa, pb)}]++;
  }
  return pieces;
}

struct Slice {
  Vector3 centroid;
  double radius = 0; // mean distance of the slice's elements to its centroid
};

// The weighted centroid of the elements of `piece` whose distance lies in [low, high] (all of them if
// none does), and their mean distance to it.
Slice slice(const Piece& piece, const Samples& samples, const std::vector<double>& distance, double low, double high) {
  auto centroidOf = [&](bool all) {
    Vector3 sum{0, 0, 0};
    double weight = 0;
    for (uint32_t v : piece.elements)
      if (all || (distance[v] >= low && distance[v] <= high)) {
        sum += samples.weights[v] * samples.positions[v];
        weight += samples.weights[v];
      }
    return std::make_pair(weight > 0 ? sum / weight : samples.positions[piece.elements[0]], weight);
  };
  auto [centroid, weight] = centroidOf(false);
  const bool all = weight == 0;
  if (all) centroid = centroidOf(true).first;
  double spread = 0, total = 0;
  for (uint32_t v : piece.elements)
    if (all || (distance[v] >= low && distance[v] <= high)) {
      spread += samples.weights[v] * norm(samples.positions[v] - centroid);
      total += samples.weights[v];
    }
  return {centroid, total > 0 ? spread / total : 0};
}

// Each element goes to the nearest of its node and that node's neighbours, until none moves: a band
// piece is a cross-section of the distance to the separators, which runs slanted to the skeleton near
// junctions and region borders, so some elements of a piece lie nearer the next node along the
// skeleton than their own. Nearest-node cells are slabs across the tube, the cross-sections a user
// reads from the vertex map (segmentation, skinning), and a node's own elements then lie about one
// radius from it. Moves only go along graph edges, so an element never leaves its part of the shape;
// a node that the moves split keeps its largest piece, and the elements of its other pieces flow to
// the nearest node beside them, so every node's elements stay connected.
void compactVertexMap(std::vector<uint32_t>& nodeOfElement, const SkeletonGraph& graph, const Samples& samples) {
  std::vector<std::vector<uint32_t>> adj(graph.nodes.size());
  for (const auto& [a, b] : graph.edges) {
    adj[a].push_back(b);
    adj[b].push_back(a);
  }
  for (size_t v = 0; v < nodeOfElement.size(); v++) {
    const Vector3& p = samples.positions[v];
    uint32_t node = nodeOfElement[v];
    for (bool moved = true; moved;) {
      moved = false;
      double best = norm2(graph.nodes[node] - p);
      for (uint32_t n : adj[node]) {
        const double d = norm2(graph.nodes[n] - p);
        if (d < best) {
          best = d;
          node = n;
          moved = true;
        }
      }
    }
    nodeOfElement[v] = node;
  }

  const size_t count = nodeOfElement.size();
  UnionFind pieces(count);
  for (const auto& [a, b] : samples.edges)
    if (nodeOfElement[a] == nodeOfElement[b]) pieces.unite(a, b);
  std::vector<double> pieceWeight(count, 0);
  for (uint32_t v = 0; v < count; v++) pieceWeight[pieces.find(v)] += samples.weights[v];
  std::vector<uint32_t> largest(graph.nodes.size(), kNone);
  for (uint32_t v = 0; v < count; v++) {
    uint32_t& best = largest[nodeOfElement[v]];
    const uint32_t piece = pieces.find(v);
    if (best == kNone || pieceWeight[piece] > pieceWeight[best]) best = piece;
  }
  std::vector<uint32_t> orphans;
  for (uint32_t v = 0; v < count; v++)
    if (pieces.find(v) != largest[nodeOfElement[v]]) orphans.push_back(v);
  if (orphans.empty()) return;
  std::vector<std::vector<uint32_t>> neighbours(count);
  for (const auto& [a, b] : samples.edges) {
    neighbours[a].push_back(b);
    neighbours[b].push_back(a);
  }
  std::vector<uint32_t> moved(orphans.size());
  for (size_t k = 0; k < orphans.size(); k++) moved[k] = std::exchange(nodeOfElement[orphans[k]], kNone);
  // Growing a connected set by elements beside it keeps it connected.
  for (bool changed = true; changed;) {
    changed = false;
    for (uint32_t v : orphans) {
      if (nodeOfElement[v] != kNone) continue;
      uint32_t best = kNone;
      double nearest = INFINITY;
      for (uint32_t w : neighbours[v]) {
        const uint32_t node = nodeOfElement[w];
        if (node == kNone) continue;
        const double d = norm2(graph.nodes[node] - samples.positions[v]);
        if (d < nearest) {
          nearest = d;
          best = node;
        }
      }
      if (best != kNone) {
        nodeOfElement[v] = best;
        changed = true;
      }
    }
  }
  // An element with no neighbour at all (an isolated point) keeps its nearest node.
  for (size_t k = 0; k < orphans.size(); k++)
    if (nodeOfElement[orphans[k]] == kNone) nodeOfElement[orphans[k]] = moved[k];
}

// A skeleton graph's edges as each node's neighbours, for joining and dropping nodes.
using Adjacency = std::vector<std::set<uint32_t>>;

Adjacency adjacencyOf(const SkeletonGraph& graph) {
  Adjacency adj(graph.nodes.size());
  for (const auto& [a, b] : graph.edges) {
    adj[a].insert(uint32_t(b));
    adj[b].insert(uint32_t(a));
  }
  return adj;
}

// `from` joins its neighbour `into`, which takes its other edges. Refused when the two are not neighbours
// (joining them would close a cycle) or close a triangle (two of its edges would become one, losing a cycle).
bool contract(Adjacency& adj, uint32_t into, uint32_t from) {
  if (into == from || !adj[into].count(from)) return false;
  for (uint32_t n : adj[from])
    if (n != into && adj[into].count(n)) return false;
  for (uint32_t n : adj[from]) {
    adj[n].erase(from);
    if (n != into) {
      adj[n].insert(into);
      adj[into].insert(n);
    }
  }
  adj[from].clear();
  return true;
}

// The chain of degree-2 nodes from `leaf` into the graph, `leaf` first, as far as `through` lets it pass;
// returns the node it stops at (a junction, another leaf, or one `through` refused).
template <class Through>
uint32_t walkFromLeaf(const Adjacency& adj, uint32_t leaf, std::vector<uint32_t>& chain, Through through) {
  chain.assign(1, leaf);
  uint32_t previous = leaf, at = *adj[leaf].begin();
  while (adj[at].size() == 2 && through(at)) {
    chain.push_back(at);
    const uint32_t onward = *adj[at].begin() == previous ? *adj[at].rbegin() : *adj[at].begin();
    previous = at;
    at = onward;
  }
  return at;
}

// The node that `node` was merged into, through any chain of merges (itself if it was not merged).
uint32_t mergedRoot(const std::vector<uint32_t>& mergedInto, uint32_t node) {
  while (mergedInto[node] != kNone) node = mergedInto[node];
  return node;
}

// The graph keeps the nodes not merged into another, in their order, with the edges of `adj`; an element
// of a merged node goes to the node it was merged into.
void keepUnmerged(SkeletonGraph& graph, const Adjacency& adj, const std::vector<uint32_t>& mergedInto,
                  std::vector<uint32_t>& nodeOfElement) {
  const size_t nodeCount = graph.nodes.size();
  std::vector<uint32_t> index(nodeCount, kNone);
  std::vector<Vector3> kept;
  for (uint32_t node = 0; node < nodeCount; node++)
    if (mergedInto[node] == kNone) {
      index[node] = uint32_t(kept.size());
      kept.push_back(graph.nodes[node]);
    }
  graph.nodes = std::move(kept);
  graph.edges.clear();
  for (uint32_t a = 0; a < nodeCount; a++)
    for (uint32_t b : adj[a])
      if (a < b) graph.edges.push_back({index[a], index[b]});
  for (uint32_t& node : nodeOfElement) node = index[mergedRoot(mergedInto, node)];
}

// A leaf that owns no element after the vertex map stands for no part of the shape: every element
// lies nearer another node. It is the end of a hook (tree_coarse, rounds of 8: a packed loop hugging
// a tip left its region node 1.2% of the diagonal back from the tip, beside the chain that reaches
// it) and is dropped, and so is the leaf that leaves behind when it owns nothing either. Nodes keep
// their order; the vertex map is renumbered.
void dropEmptyLeaves(SkeletonGraph& graph, std::vector<uint32_t>& nodeOfElement) {
  const size_t nodeCount = graph.nodes.size();
  std::vector<size_t> owned(nodeCount, 0);
  for (uint32_t node : nodeOfElement) owned[node]++;
  Adjacency adj = adjacencyOf(graph);
  std::vector<uint32_t> droppedFor(nodeCount, kNone);
  std::vector<uint32_t> pending;
  for (uint32_t node = 0; node < nodeCount; node++)
    if (owned[node] == 0 && adj[node].size() == 1) pending.push_back(node);
  bool any = false;
  while (!pending.empty()) {
    const uint32_t leaf = pending.back();
    pending.pop_back();
    if (droppedFor[leaf] != kNone || adj[leaf].size() != 1) continue;
    const uint32_t next = *adj[leaf].begin();
    contract(adj, next, leaf);
    droppedFor[leaf] = next;
    any = true;
    if (owned[next] == 0 && adj[next].size() == 1) pending.push_back(next);
  }
  if (any) keepUnmerged(graph, adj, droppedFor, nodeOfElement);
}

// Two nodes joined by an edge and at one place are one node: an edge of no length is no part of the
// skeleton. They arise where centreNodes puts a branch node whose regions' centroid is outside the shape
// on its heaviest neighbour and neither moves after (trees' junctions: 7 of the 141 skeletons measured on
// 2026-12-06 had such a pair). Not when the two share a neighbour: that would fold a cycle into a double edge.
void mergeCoincidentNodes(SkeletonGraph& graph, std::vector<uint32_t>& nodeOfElement) {
  Adjacency adj = adjacencyOf(graph);
  std::vector<uint32_t> mergedInto(graph.nodes.size(), kNone);
  bool any = false;
  for (const auto& edge : graph.edges) {
    const uint32_t a = mergedRoot(mergedInto, uint32_t(edge[0])), b = mergedRoot(mergedInto, uint32_t(edge[1]));
    const uint32_t keep = std::min(a, b), gone = std::max(a, b);
    if (norm(graph.nodes[keep] - graph.nodes[gone]) > 0 || !contract(adj, keep, gone)) continue;
    mergedInto[gone] = keep;
    any = true;
  }
  if (any) keepUnmerged(graph, adj, mergedInto, nodeOfElement);
}

// The elements each node owns, and per node whether all of them lie in solid parts.
struct OwnedElements {
  std::vector<std::vector<uint32_t>> of;
  std::vector<char> solid;
};

OwnedElements ownedElements(size_t nodeCount, const std::vector<uint32_t>& nodeOfElement,
                            const std::function<bool(uint32_t)>& solidElement) {
  OwnedElements owned{std::vector<std::vector<uint32_t>>(nodeCount), std::vector<char>(nodeCount, 1)};
  for (uint32_t v = 0; v < nodeOfElement.size(); v++) {
    owned.of[nodeOfElement[v]].push_back(v);
    if (!solidElement(v)) owned.solid[nodeOfElement[v]] = 0;
  }
  return owned;
}

// The weighted mean of elements and their total weight (the mean is meaningless where that is not positive).
std::pair<Vector3, double> weightedMean(const std::vector<uint32_t>& elements, const Samples& samples) {
  Vector3 mean{0, 0, 0};
  double total = 0;
  for (uint32_t v : elements) {
    mean += samples.weights[v] * samples.positions[v];
    total += samples.weights[v];
  }
  if (total > 0) mean /= total;
  return {mean, total};
}

// A node of a solid part that stands apart from every element it owns, the way from it to them leaving
// the shape, is given a node among them. The bands place a node at a region's centroid or its separator's
// loop, and a branch node outside the shape at its heaviest neighbour; on a tree scan a region of sparse
// twigs has its centroid in the air between them, and such nodes sat on the trunk or between branches,
// 20-100 spacings from the twigs whose vertex map they held (docs/skeleton.md, "Detached nodes"). A leaf
// moves to the element nearest its elements' centroid; a node with more edges stays where its edges
// need it (on a trunk's chain) and a new leaf at that element takes its elements. A node round which
// its elements lie (a cross-section, a cap) is never so far from them, nor a node deep in a body that
// owns a patch of its surface: the way to them stays inside. Nor does a node leave the shape: where that
// element is not inside (a mesh's vertex can fall either way), nothing is done. Whether any node changed.
bool reattachDetachedNodes(SkeletonGraph& graph, std::vector<uint32_t>& nodeOfElement, const Samples& samples,
                           const std::function<bool(uint32_t)>& solidElement,
                           const std::function<bool(const Vector3&)>& inside) {
  const size_t nodeCount = graph.nodes.size();
  const OwnedElements owned = ownedElements(nodeCount, nodeOfElement, solidElement);
  std::vector<int> degree(nodeCount, 0);
  for (const auto& [a, b] : graph.edges) degree[a]++, degree[b]++;
  bool changed = false;
  for (uint32_t node = 0; node < nodeCount; node++) {
    if (!owned.solid[node] || owned.of[node].size() < 2) continue;
    const auto [mean, total] = weightedMean(owned.of[node], samples);
    if (!(total > 0)) continue;
    double spread = 0, nearestToNode = INFINITY, nearestToMean = INFINITY;
    uint32_t central = owned.of[node][0];
    for (uint32_t v : owned.of[node]) {
      const Vector3& p = samples.positions[v];
      spread += samples.weights[v] * norm2(p - mean);
      nearestToNode = std::min(nearestToNode, norm(p - graph.nodes[node]));
      if (norm(p - mean) < nearestToMean) nearestToMean = norm(p - mean), central = v;
    }
    spread = std::sqrt(spread / total);
    if (!(nearestToNode > kDetached * spread)) continue;
    const Vector3 from = graph.nodes[node], to = samples.positions[central];
    bool leaves = false;
    for (int k = 1; k < kDetachedProbes && !leaves; k++) leaves = !inside(from + (to - from) * (double(k) / kDetachedProbes));
    if (!leaves || !inside(to)) continue;
    if (degree[node] <= 1) {
      graph.nodes[node] = to;
    } else {
      const uint32_t leaf = uint32_t(graph.nodes.size());
      graph.nodes.push_back(to);
      graph.edges.push_back({node, leaf});
      for (uint32_t v : owned.of[node]) nodeOfElement[v] = leaf;
    }
    changed = true;
  }
  return changed;
}

// Each node of a solid part moves to the centre of the sphere that best fits its elements (least
// squares of their distances to it: Landau's fixed-point iteration, from where the node is). A band
// piece's slice centroid lies off the axis wherever the piece is not a round cross-section (a bend, a
// taper, a blob, a junction), and a node off the axis is a tube that sticks out on one side and falls
// short on the other; centred, the tube around a node is as round as its elements allow. On a ring
// of elements the iteration does not move along the axis, so nodes keep their spacing along a tube,
// and a leaf moves across its edge only, keeping its reach into its tip. A branch node's elements are
// the first stretch of each of its branches, seldom alike, so it moves at most half its fitted radius
// (farther, it left the junction for one branch: on star8_coarse a stub beside an arm then grew
// longer than the arm's radius). A move that leaves the shape, or goes farther than the fitted
// radius, is not made. New positions are taken all at once, so node order does not matter.
void centreOnElements(SkeletonGraph& graph, const std::vector<uint32_t>& nodeOfElement, const Samples& samples,
                      const std::function<bool(uint32_t)>& solidElement,
                      const std::function<bool(const Vector3&)>& inside) {
  const size_t nodeCount = graph.nodes.size();
  const OwnedElements owned = ownedElements(nodeCount, nodeOfElement, solidElement);
  std::vector<int> degree(nodeCount, 0);
  std::vector<uint32_t> neighbour(nodeCount, 0);
  for (const auto& [a, b] : graph.edges) {
    degree[a]++, degree[b]++;
    neighbour[a] = b, neighbour[b] = a;
  }
  std::vector<Vector3> centred = graph.nodes;
  for (size_t node = 0; node < nodeCount; node++) {
    if (!owned.solid[node] || owned.of[node].size() < kFitElements) continue;
    const Vector3 at = graph.nodes[node];
    const auto [mean, total] = weightedMean(owned.of[node], samples);
    if (!(total > 0)) continue;
    Vector3 centre = at;
    double fitted = 0;
    for (int k = 0; k < kFitIterations; k++) {
      Vector3 away{0, 0, 0};
      fitted = 0;
      for (uint32_t v : owned.of[node]) {
        const Vector3 d = centre - samples.positions[v];
        const double length = norm(d);
        fitted += samples.weights[v] * length;
        if (length > 0) away += samples.weights[v] * d / length;
      }
      fitted /= total;
      centre = mean + fitted * away / total;
    }
    const Vector3 edge = at - graph.nodes[neighbour[node]];
    if (degree[node] == 1 && norm(edge) > 0) {
      const Vector3 axis = edge / norm(edge);
      centre -= dot(centre - at, axis) * axis;
    }
    const double reach = (degree[node] > 2 ? kBranchNodeFit : 1.0) * fitted;
    if (norm(centre - at) <= reach && inside(centre)) centred[node] = centre;
  }
  graph.nodes = std::move(centred);
}

} // namespace

std::vector<uint32_t> refineIntoBands(SkeletonGraph& graph, const Regions& regions, const Samples& samples,
                                      const std::vector<double>& width, const std::vector<char>& solid,
                                      const std::function<bool(const Vector3&)>& inside) {
  const size_t count = samples.positions.size();
  const std::vector<double>& distance = regions.distance;
  const std::vector<uint32_t>& label = regions.label;

  std::vector<int64_t> level(count, 0);
  for (size_t v = 0; v < count; v++) {
    const double w = width[label[v]];
    if (w > 0 && std::isfinite(distance[v])) level[v] = int64_t(std::floor(distance[v] / w));
  }
  UnionFind sets(count);
  for (const auto& [a, b] : samples.edges)
    if (label[a] == label[b] && level[a] == level[b]) sets.unite(a, b);
  Pieces pieces = collectPieces(sets, regions, level, samples);

  // Pieces of one band that touch the same piece below and the same piece above went around something
  // (a bump, a smaller region) and are one cross-section: joined, they keep the region's graph a tree.
  {
    std::map<std::array<uint64_t, 3>, uint32_t> firstAround;
    std::vector<std::vector<uint32_t>> below(pieces.list.size()), above(pieces.list.size());
    for (const auto& [pair, n] : pieces.contacts) {
      const Piece &a = pieces.list[pair[0]], &b = pieces.list[pair[1]];
      if (a.region != b.region) continue;
      (a.level < b.level ? above : below)[pair[0]].push_back(pair[1]);
      (b.level < a.level ? above : below)[pair[1]].push_back(pair[0]);
    }
    bool joined = false;
    for (uint32_t p = 0; p < pieces.list.size(); p++)
      for (uint32_t low : below[p])
        for (uint32_t high : above[p]) {
          auto [it, fresh] = firstAround.emplace(std::array<uint64_t, 3>{uint64_t(pieces.list[p].level), low, high}, p);
          if (!fresh) {
            sets.unite(pieces.list[p].elements[0], pieces.list[it->second].elements[0]);
            joined = true;
          }
        }
    if (joined) pieces = collectPieces(sets, regions, level, samples);
  }
  const size_t pieceCount = pieces.list.size();
  double spacing = 0;
  for (const auto& [a, b] : samples.edges) spacing += norm(samples.positions[a] - samples.positions[b]);
  spacing /= std::max<size_t>(1, samples.edges.size());

  // Node of every piece: a region's piece nearest its separator (the largest, where none is nearer) is
  // the region's node, the others new; but pieces that no element edges join to that one within the
  // region are the region's too. They hold elements the realization gave the region across a gap (points
  // a cloud's neighbourhood graph cut off: ElementGraph::adoptive), which would be nodes with no edge.
  std::vector<uint32_t> mainPiece(regions.count, kNone);
  for (uint32_t p = 0; p < pieceCount; p++) {
    uint32_t& m = mainPiece[pieces.list[p].region];
    const double nearest = distance[pieces.list[p].nearest];
    if (m == kNone || nearest < distance[pieces.list[m].nearest] ||
        (nearest == distance[pieces.list[m].nearest] && pieces.list[p].elements.size() > pieces.list[m].elements.size()))
      m = p;
  }
  UnionFind withinRegions(pieceCount);
  for (const auto& [pair, n] : pieces.contacts)
    if (pieces.list[pair[0]].region == pieces.list[pair[1]].region) withinRegions.unite(pair[0], pair[1]);
  auto acrossGap = [&](uint32_t p) {
    return withinRegions.find(p) != withinRegions.find(mainPiece[pieces.list[p].region]);
  };
  const size_t oldNodes = graph.nodes.size();
  std::vector<uint32_t> nodeOf(pieceCount);
  std::vector<std::vector<uint32_t>> piecesOf(oldNodes);
  for (uint32_t p = 0; p < pieceCount; p++) {
    const uint32_t region = pieces.list[p].region;
    nodeOf[p] = mainPiece[region] == p || acrossGap(p) ? region : uint32_t(piecesOf.size());
    if (nodeOf[p] == piecesOf.size()) piecesOf.emplace_back();
    if (!acrossGap(p)) piecesOf[nodeOf[p]].push_back(p);
  }
  const size_t nodeCount = piecesOf.size();

  // Positions and radii: region and branch nodes as the realization placed them, band pieces at the
  // centroid of their middle slice.
  std::vector<Vector3> position(nodeCount);
  std::vector<double> radius(nodeCount, 0);
  for (size_t node = 0; node < oldNodes; node++) position[node] = graph.nodes[node];
  for (uint32_t p = 0; p < pieceCount; p++) {
    if (acrossGap(p)) continue;
    const Piece& piece = pieces.list[p];
    const double low = distance[piece.nearest], high = distance[piece.deepest];
    const double middle = (low + high) / 2, half = std::max(width[piece.region], high - low) / 4;
    const Slice middleSlice = slice(piece, samples, distance, middle - half, middle + half);
    const uint32_t node = nodeOf[p];
    radius[node] = middleSlice.radius;
    if (node < oldNodes) continue;
    position[node] = middleSlice.centroid;
    if (solid[piece.region] && !inside(position[node])) {
      Vector3 whole = slice(piece, samples, distance, INFINITY, -INFINITY).centroid;
      if (inside(whole)) position[node] = whole;
    }
  }

  // Edges: inside each region a spanning tree of the contacts between its pieces (most contact first);
  // every edge of the region graph joins the two pieces with most contact across it.
  std::set<std::array<uint32_t, 2>> edges;
  auto addEdge = [&](uint32_t a, uint32_t b) {
    if (a != b) edges.insert({std::min(a, b), std::max(a, b)});
  };
  {
    std::vector<std::pair<uint32_t, std::array<uint32_t, 2>>> inner;
    for (const auto& [pair, n] : pieces.contacts)
      if (pieces.list[pair[0]].region == pieces.list[pair[1]].region) inner.push_back({n, pair});
    std::stable_sort(inner.begin(), inner.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
    UnionFind tree(pieceCount);
    for (const auto& [n, pair] : inner)
      if (tree.find(pair[0]) != tree.find(pair[1])) {
        tree.unite(pair[0], pair[1]);
        addEdge(nodeOf[pair[0]], nodeOf[pair[1]]);
      }
  }
  std::vector<std::vector<size_t>> members(oldNodes); // of each branch node: the regions it joins
  for (const auto& e : graph.edges)
    for (int k = 0; k < 2; k++)
      if (e[k] >= regions.count && e[1 - k] < regions.count) members[e[k]].push_back(e[1 - k]);
  // The piece of `region` with the most element edges to a piece of a region that `accepts` takes.
  auto touching = [&](size_t region, auto&& accepts) {
    std::array<uint32_t, 2> best{mainPiece[region], kNone};
    uint32_t most = 0;
    for (const auto& [pair, n] : pieces.contacts)
      for (int k = 0; k < 2; k++)
        if (pieces.list[pair[k]].region == region && accepts(pieces.list[pair[1 - k]].region) && n > most) {
          best = {pair[k], pair[1 - k]};
          most = n;
        }
    return best;
  };
  for (const auto& e : graph.edges) {
    const size_t a = std::min(e[0], e[1]), b = std::max(e[0], e[1]);
    if (b < regions.count) {
      auto [pa, pb] = touching(a, [&](size_t r) { return r == b; });
      addEdge(nodeOf[pa], pb == kNone ? uint32_t(b) : nodeOf[pb]);
    } else if (a < regions.count) {
      const std::vector<size_t>& joined = members[b];
      const uint32_t pa = touching(a, [&](size_t r) { return r != a && std::count(joined.begin(), joined.end(), r); })[0];
      addEdge(nodeOf[pa], uint32_t(b));
    } else {
      addEdge(uint32_t(a), uint32_t(b));
    }
  }

  // Graph operations: a node absorbs a neighbour (its pieces and its other edges), unless `contract`
  // refuses (the two close a triangle).
  Adjacency adj(nodeCount);
  for (const auto& [a, b] : edges) {
    adj[a].insert(b);
    adj[b].insert(a);
  }
  std::vector<uint32_t> mergedInto(nodeCount, kNone);
  auto resolve = [&](uint32_t node) { return mergedRoot(mergedInto, node); };
  auto absorb = [&](uint32_t into, uint32_t from) {
    if (!contract(adj, into, from)) return false;
    piecesOf[into].insert(piecesOf[into].end(), piecesOf[from].begin(), piecesOf[from].end());
    piecesOf[from].clear();
    mergedInto[from] = into;
    return true;
  };
  auto isHub = [&](uint32_t node) { return node >= regions.count && node < oldNodes; };
  auto weightOf = [&](uint32_t node) {
    double w = 0;
    for (uint32_t p : piecesOf[node])
      for (uint32_t v : pieces.list[p].elements) w += samples.weights[v];
    return w;
  };

  // A piece that reaches a region border is cut by it, no cross-section: it joins its neighbour below
  // in its region (the last whole cross-section before the border), which keeps its place.
  std::vector<std::vector<std::pair<uint32_t, uint32_t>>> contactsOf(pieceCount); // (piece, element edges)
  for (const auto& [pair, n] : pieces.contacts) {
    contactsOf[pair[0]].push_back({pair[1], n});
    contactsOf[pair[1]].push_back({pair[0], n});
  }
  {
    std::vector<uint32_t> outermostFirst(pieceCount);
    std::iota(outermostFirst.begin(), outermostFirst.end(), 0u);
    std::stable_sort(outermostFirst.begin(), outermostFirst.end(),
                     [&](uint32_t a, uint32_t b) { return pieces.list[a].level > pieces.list[b].level; });
    for (uint32_t p : outermostFirst) {
      const Piece& piece = pieces.list[p];
      if (mainPiece[piece.region] == p) continue;
      uint32_t below = kNone, most = 0;
      bool border = false;
      for (const auto& [q, n] : contactsOf[p]) {
        const Piece& other = pieces.list[q];
        border = border || other.region != piece.region;
        if (other.region == piece.region && other.level < piece.level && n > most &&
            adj[resolve(nodeOf[q])].count(resolve(nodeOf[p]))) {
          below = q;
          most = n;
        }
      }
      if (border && below != kNone) absorb(resolve(nodeOf[below]), resolve(nodeOf[p]));
    }
  }

  // Branch nodes stay where the realization put them (the centroid of the regions they join); their
  // radius, for telling bumps from branches, is their widest neighbour's.
  for (uint32_t hub = uint32_t(regions.count); hub < oldNodes; hub++)
    for (uint32_t n : adj[hub]) radius[hub] = std::max(radius[hub], radius[n]);

  // Leaves that are no branches join their neighbours: a region too small to hold a strip of elements
  // along its separator (the watershed gave its separator's elements to a neighbour); a leaf piece that
  // lies outside the shape (a few elements at the very end of a thin tip: its neighbour moves into the
  // tip instead) or touches a piece other than its one neighbour (across a region border or a cut
  // cycle), unless it is a twig (below: outside, it stands at its element nearest its slice centroid);
  // a leaf piece within kCapReach of its neighbour's radius from its node (the end cap of the neighbour's
  // cross-section: on a blunt end whose separator is tilted, the last band is a crescent on one side, and
  // as a leaf it bent the skeleton sideways there); a leaf branch of band pieces that spans less than one
  // band (no cross-section of its own) or does not reach more than its junction's radius beyond the
  // junction's surface (a bump).
  // How far the elements of `node` reach from `from`.
  auto reachOf = [&](uint32_t node, const Vector3& from) {
    double reach = 0;
    for (uint32_t p : piecesOf[node])
      for (uint32_t v : pieces.list[p].elements) reach = std::max(reach, norm(samples.positions[v] - from));
    return reach;
  };
  // A leaf that touches pieces other than its neighbour is a sliver of a cross-section, unless it is a twig,
  // a branch that grazes another as the twigs of a tree scan cross in its crown (docs/skeleton.md, "Grazing
  // twigs"): it reaches kTwigReach of its neighbour's radii from the neighbour's node (at least as many
  // element spacings: a slice of one or two elements has no radius) and holds to the neighbour by at least
  // as many element edges as to the other pieces it touches.
  struct Contacts {
    size_t held = 0, grazed = 0;
  };
  auto contactsWith = [&](uint32_t leaf, uint32_t neighbour) {
    Contacts tally;
    for (uint32_t p : piecesOf[leaf])
      for (const auto& [q, n] : contactsOf[p]) {
        const uint32_t other = resolve(nodeOf[q]);
        if (other == neighbour) tally.held += n;
        else if (other != leaf) tally.grazed += n;
      }
    return tally;
  };
  auto twig = [&](uint32_t leaf, uint32_t neighbour, const Contacts& tally) {
    return tally.held >= tally.grazed &&
           reachOf(leaf, position[neighbour]) >= kTwigReach * std::max(radius[neighbour], spacing);
  };
  // A twig bent within its band has its slice centroid in the air: it stands at its element nearest the
  // centroid instead, if that is inside.
  auto insideElementNear = [&](uint32_t leaf) -> std::optional<Vector3> {
    double nearest = INFINITY;
    Vector3 at{0, 0, 0};
    for (uint32_t p : piecesOf[leaf])
      for (uint32_t v : pieces.list[p].elements) {
        const double d = norm(samples.positions[v] - position[leaf]);
        if (d < nearest) {
          nearest = d;
          at = samples.positions[v];
        }
      }
    if (nearest < INFINITY && inside(at)) return at;
    return std::nullopt;
  };
  for (bool changed = true; changed;) {
    changed = false;
    for (uint32_t leaf = 0; leaf < nodeCount; leaf++) {
      if (mergedInto[leaf] != kNone || isHub(leaf) || adj[leaf].size() != 1) continue;
      const uint32_t next = *adj[leaf].begin();
      const bool regionNode = leaf < regions.count;
      if (regionNode && weightOf(leaf) < kIslandStrip * width[leaf] * spacing) {
        changed = absorb(next, leaf) || changed;
        continue;
      }
      if (!regionNode) {
        const Contacts tally = contactsWith(leaf, next);
        bool outside = solid[pieces.list[piecesOf[leaf][0]].region] && !inside(position[leaf]);
        const bool isTwig = (outside || tally.grazed > 0) && twig(leaf, next, tally);
        if (outside && isTwig)
          if (const std::optional<Vector3> at = insideElementNear(leaf)) {
            position[leaf] = *at;
            outside = false;
          }
        if (outside || (tally.grazed > 0 && !isTwig)) {
          changed = absorb(next, leaf) || changed;
          continue;
        }
      }
      // A region node is an end cap too when its neighbour is a band of its own region, which then
      // reaches past it (star8_coarse, rounds of 8: a loop tilted across a curling arm left its region
      // node a stub beside the band node that holds the tip). Next to another region's node it is the
      // end of a tube, which stays (the hand cut open at the wrist: two loops near the rim).
      const bool ownBand = next >= oldNodes && pieces.list[piecesOf[next][0]].region == leaf;
      if (!isHub(next) && (!regionNode || ownBand)) {
        if (reachOf(leaf, position[next]) < kCapReach * radius[next]) {
          changed = absorb(next, leaf) || changed;
          continue;
        }
      }
      if (regionNode) continue;
      const double bandWidth = width[pieces.list[piecesOf[leaf][0]].region];
      std::vector<uint32_t> chain;
      const uint32_t at = walkFromLeaf(adj, leaf, chain, [&](uint32_t node) { return !isHub(node) && node >= regions.count; });
      double reach = 0, low = INFINITY, high = -INFINITY;
      for (uint32_t c : chain)
        for (uint32_t p : piecesOf[c])
          for (uint32_t v : pieces.list[p].elements) {
            reach = std::max(reach, norm(samples.positions[v] - position[at]));
            low = std::min(low, distance[v]);
            high = std::max(high, distance[v]);
          }
      const bool thin = high - low < bandWidth;
      if (!thin && (adj[at].size() < 3 || reach >= kBranchReach * radius[at])) continue;
      for (auto c = chain.rbegin(); c != chain.rend(); ++c) changed = absorb(at, *c) || changed;
    }
  }

  // Leaves reach into their tips: to the centre of the sphere through the tip (the centroid of the
  // leaf's elements within a quarter band of the farthest from the separators, beyond the node: the
  // middle of a flat end, not its corner) and the node's slice, or one radius in from the tip when the
  // slice is farther back than that; never back from where the slice put them, never out of the shape.
  for (uint32_t leaf = 0; leaf < nodeCount; leaf++) {
    if (mergedInto[leaf] != kNone || isHub(leaf) || adj[leaf].size() != 1 || !(radius[leaf] > 0)) continue;
    const Vector3 at = position[leaf], axis = at - position[*adj[leaf].begin()];
    const double bandWidth = width[pieces.list[piecesOf[leaf][0]].region];
    auto beyond = [&](uint32_t v) { return dot(samples.positions[v] - at, axis) > 0; };
    double deepest = -INFINITY;
    for (uint32_t p : piecesOf[leaf])
      for (uint32_t v : pieces.list[p].elements)
        if (beyond(v)) deepest = std::max(deepest, distance[v]);
    Vector3 sum{0, 0, 0};
    double total = 0;
    for (uint32_t p : piecesOf[leaf])
      for (uint32_t v : pieces.list[p].elements)
        if (beyond(v) && distance[v] >= deepest - bandWidth / 4) {
          sum += samples.weights[v] * samples.positions[v];
          total += samples.weights[v];
        }
    if (!(total > 0)) continue;
    const Vector3 toTip = sum / total - at;
    const double h = norm(toTip), rho = radius[leaf];
    const double tipRadius = h < rho ? (rho * rho + h * h) / (2 * h) : rho;
    // A move that would leave the shape is halved (a thin tip bends out of the straight line).
    const bool solidLeaf = solid[pieces.list[piecesOf[leaf][0]].region];
    for (double move = h - tipRadius; move >= kTipMove * rho; move /= 2) {
      const Vector3 centre = at + move / h * toTip;
      if (solidLeaf && !inside(centre)) continue;
      position[leaf] = centre;
      break;
    }
  }

  // The refined graph, its nodes in their old order.
  std::vector<uint32_t> index(nodeCount, kNone);
  graph.nodes.clear();
  for (uint32_t node = 0; node < nodeCount; node++)
    if (mergedInto[node] == kNone) {
      index[node] = uint32_t(graph.nodes.size());
      graph.nodes.push_back(position[node]);
    }
  graph.edges.clear();
  for (uint32_t a = 0; a < nodeCount; a++)
    for (uint32_t b : adj[a])
      if (a < b) graph.edges.push_back({index[a], index[b]});
  std::vector<uint32_t> nodeOfElement(count);
  for (size_t v = 0; v < count; v++) nodeOfElement[v] = index[resolve(nodeOf[pieces.of[v]])];
  compactVertexMap(nodeOfElement, graph, samples);
  dropEmptyLeaves(graph, nodeOfElement);
  const auto solidElement = [&](uint32_t v) { return bool(solid[label[v]]); };
  // Before the centring and after it, as centred nodes own other elements.
  const auto reattach = [&] {
    if (!reattachDetachedNodes(graph, nodeOfElement, samples, solidElement, inside)) return;
    compactVertexMap(nodeOfElement, graph, samples);
    dropEmptyLeaves(graph, nodeOfElement);
  };
  reattach();
  // Centred nodes own other elements than before, whose sphere is centred again: twice (a third and
  // fourth round drifted, and lost as many meshes as they won).
  for (int round = 0; round < kFitRounds; round++) {
    centreOnElements(graph, nodeOfElement, samples, solidElement, inside);
    compactVertexMap(nodeOfElement, graph, samples);
    dropEmptyLeaves(graph, nodeOfElement);
  }
  reattach();
  mergeCoincidentNodes(graph, nodeOfElement);
  graph.weights.assign(graph.nodes.size(), 0);
  for (size_t v = 0; v < count; v++) graph.weights[nodeOfElement[v]] += samples.weights[v];
  graph.radii.clear();
  return nodeOfElement;
}

bool mergeNoiseSpurs(SkeletonGraph& graph, std::vector<uint32_t>& nodeOfElement, const Samples& samples) {
  const size_t nodeCount = graph.nodes.size();
  if (graph.radii.size() != nodeCount) return false;
  std::vector<std::vector<uint32_t>> owned(nodeCount);
  for (uint32_t v = 0; v < nodeOfElement.size(); v++) owned[nodeOfElement[v]].push_back(v);
  Adjacency adj = adjacencyOf(graph);
  std::vector<uint32_t> mergedInto(nodeCount, kNone);
  bool any = false;
  for (bool changed = true; changed;) {
    changed = false;
    for (uint32_t leaf = 0; leaf < nodeCount; leaf++) {
      if (mergedInto[leaf] != kNone || adj[leaf].size() != 1) continue;
      std::vector<uint32_t> chain;
      const uint32_t at = walkFromLeaf(adj, leaf, chain, [](uint32_t) { return true; });
      if (adj[at].size() < 3) continue; // the piece is one path: its ends are the shape's
      double reach = 0;
      for (uint32_t c : chain)
        for (uint32_t v : owned[c]) reach = std::max(reach, norm(samples.positions[v] - graph.nodes[at]));
      if (!(reach < kBranchReach * graph.radii[at])) continue;
      for (auto c = chain.rbegin(); c != chain.rend(); ++c) {
        if (!contract(adj, at, *c)) break;
        mergedInto[*c] = at;
        owned[at].insert(owned[at].end(), owned[*c].begin(), owned[*c].end());
        owned[*c].clear();
        changed = any = true;
      }
    }
  }
  if (!any) return false;
  keepUnmerged(graph, adj, mergedInto, nodeOfElement);
  graph.weights.assign(graph.nodes.size(), 0);
  for (size_t v = 0; v < nodeOfElement.size(); v++) graph.weights[nodeOfElement[v]] += samples.weights[v];
  graph.radii.clear();
  return true;
}

} // namespace cscd
