#pragma once

#include "cscd/options.h"
#include "mesh/cut_locus.h"

#include "geometrycentral/surface/vertex_position_geometry.h"

#include <vector>

namespace cscd {

// Cut-locus vertices ordered from nearest to farthest from the source, by Euclidean distance in space
// (the paper's default: a protrusion's cut locus is close in space but far along the surface) or by
// geodesic distance.
// Only detours qualify: cut-locus vertices whose geodesic distance is at least `minDetour` times their
// Euclidean distance from the source. Around any feature the surface bends between the source and its
// cut locus (pi/2 across a round limb, on a sphere, around a torus tube), while spurious ridge points
// next to the source or on flat stretches are about as far along the surface as in space.
// The first one is the paper's target; the others are fall-backs when its loop turns out degenerate.
std::vector<size_t> rankTargets(const CutLocus& cutLocus, const std::vector<double>& distance,
                                geometrycentral::surface::VertexPositionGeometry& geometry, size_t source,
                                TargetMode mode, double minDetour);

// What the targets are ranked by: Euclidean or geodesic distance from the source.
double targetKey(geometrycentral::surface::VertexPositionGeometry& geometry, const std::vector<double>& distance,
                 size_t source, size_t target, TargetMode mode);

} // namespace cscd
