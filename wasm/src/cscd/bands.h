#pragma once

#include "cscd/graph.h"
#include "cscd/regions.h"

#include <array>
#include <cstdint>
#include <functional>
#include <vector>

namespace cscd {

// The elements of a shape (mesh vertices, cloud points) as stage 2 sees them.
struct Samples {
  std::vector<geometrycentral::Vector3> positions;
  std::vector<double> weights;                // the area each element stands for
  std::vector<std::array<uint32_t, 2>> edges; // neighbouring elements
};

// Bands (stage 2, after the region graph): one node per region is one node per separator, so a long
// tapering region would be one straight tube with one radius, and a region's node sits halfway to its
// tip. Each region is therefore cut into bands of its distance to the separators (the distance of the
// region step), `width[r]` wide; every connected piece of a band becomes a node (the Reeb graph of
// that distance inside the region). Pieces of the same band that split around an obstacle and join
// again are one node, so the skeleton keeps exactly the cycles of the region graph. A node sits at the
// centroid of the middle slice of its band (the slice has unit distance gradient across it, so this is
// the centroid of the level curve: no pull to the outer side of a bend). A leaf branch that does not
// reach more than its junction's radius beyond the surface it sticks out of is a bump, not a branch,
// and is merged into the junction; a leaf's node moves to the centre of its tip's end sphere. Last,
// each element goes to its nearest node along the skeleton (the vertex map) and each node of a solid
// part moves to the centre of the sphere that best fits its elements (a leaf across its edge only),
// twice, so that nodes lie on the medial axis where slices are no round cross-sections.
//
// The graph comes in with region nodes 0..regions.count-1 (positioned by the realization) followed by
// branch nodes; these keep their indices, the band nodes are appended. In a `solid` region (one whose
// separator is a closed loop: the shape has an inside there) a node that `inside` rejects moves to a
// safer place. Radii are left to the realization. Returns, per element, its node.
std::vector<uint32_t> refineIntoBands(SkeletonGraph& graph, const Regions& regions, const Samples& samples,
                                      const std::vector<double>& width, const std::vector<char>& solid,
                                      const std::function<bool(const geometrycentral::Vector3&)>& inside);

// On a noisy cloud a packed separator may go round a bump of the noise, and its region makes a spur
// that refineIntoBands keeps (a separator marks a feature there). Measured with the fitted radii, a leaf
// branch none of whose elements lies farther from its junction's node than two of the junction's radii
// (refineIntoBands' bump rule) is merged into the junction, separator or not. Needs the graph's radii;
// clears them when it merges (they are fitted again). Returns whether a branch was merged.
// (docs/pointcloud.md, "Spurs of the noise")
bool mergeNoiseSpurs(SkeletonGraph& graph, std::vector<uint32_t>& nodeOfElement, const Samples& samples);

} // namespace cscd
