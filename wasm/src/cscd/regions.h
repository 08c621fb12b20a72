#pragma once

#include "geometrycentral/utilities/vector3.h"

#include <limits>
#include <array>
#include <cstdint>
#include <map>
#include <set>
#include <vector>

namespace cscd {

// The shape divided among the packed separators (paper Sec. 4.2.4): every element (vertex, point)
// belongs to its geodesically nearest separator; parts of the shape no separator reaches become one
// region each.
struct Regions {
  std::vector<uint32_t> label;    // per element: regions 0..separators-1 are the separators', then the rest
  std::vector<double> distance;   // per element: to the nearest separator (+infinity where none reaches)
  size_t count = 0;
  std::vector<geometrycentral::Vector3> centroid; // area-weighted
  std::vector<double> area;
  std::set<std::array<size_t, 2>> adjacent;  // regions that touch (sorted pairs)
  // Regions that meet in one place (sorted triples), and where: the mean centroid of the triangles that
  // have one element of each.
  std::map<std::array<size_t, 3>, geometrycentral::Vector3> junctions;
};

constexpr uint32_t kNoRegion = std::numeric_limits<uint32_t>::max();

// The shape's elements as region growing needs them: positions and areas, each element's neighbours
// (in a fixed order: ties go to the first), the connected component of each, and the triangles that
// tell which regions touch and where three meet: two regions touch where triangles have elements of
// both, at least `minContact` of each (1: any triangle will do) unless the two meet a third there;
// three meet where a triangle of `junctionTriangles` (when given, else of `triangles`) has one of each.
// `adoptive` (when given) names, per element of a piece too small to be a part of the shape, an element of
// a larger piece (kNoRegion: none): such an element that no separator reaches joins that one's region
// instead of making one of its own, and tells nothing of where regions touch.
struct ElementGraph {
  const std::vector<geometrycentral::Vector3>& positions;
  const std::vector<double>& areas;
  const std::vector<std::vector<uint32_t>>& neighbours;
  const std::vector<std::array<uint32_t, 2>>& edges;
  const std::vector<int>& component;
  const std::vector<std::array<uint32_t, 3>>& triangles;
  size_t minContact = 1;
  const std::vector<std::array<uint32_t, 3>>* junctionTriangles = nullptr;
  const std::vector<uint32_t>* adoptive = nullptr;
};

// Regions from the distance to the nearest of `separators` separators (+infinity where none reaches)
// and the elements each separator runs through (`seeds`: its index, kNoRegion elsewhere). Labels flow
// from the seeds outwards in order of increasing distance (a watershed), each element taking the label
// of its nearest already-labelled neighbour; every region is connected (a label's smaller pieces join
// the regions around them) but for adopted elements; elements that no separator reaches become one
// region per component, but for those with an adoptive element, which join its region.
Regions growRegions(const ElementGraph& graph, std::vector<double> distance, std::vector<uint32_t> seeds,
                    size_t separators);

} // namespace cscd
