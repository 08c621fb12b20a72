#pragma once

#include "cscd/sphere.h"
#include "pointcloud/cloud.h"

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace cscd {

// The point-cloud counterpart of the mesh's ShortenedLoop (mesh/shorten.h).
struct ShortenedCloudLoop {
  // Points on the cloud's MLS surface; the last is joined to the first, not repeated. Empty when degenerate.
  std::vector<geometrycentral::Vector3> loop;
  double length = 0;
  std::array<double, 2> areas{0, 0}; // the two sides inside the constraint region, smaller first; as on meshes,
                                     // (0, area flooded) when the loop does not separate it even near itself
  // Why there is no converged loop: it shrank to nothing (it enclosed no feature), or it was still moving
  // when the iterations ran out (the loop and its measures are then those of the last iterate).
  enum class Failure { None, Degenerate, NotConverged } failureKind = Failure::None;
  std::string failure; // what happened, for the user; empty on success
  int iterations = 0;  // gradient steps taken
  // For animating the shortening: the loop as resampled from the input, evenly spaced steps after it and
  // the last one, at most recordFrames loops in all. Empty unless asked for.
  std::vector<std::vector<geometrycentral::Vector3>> iterates;
};

// Shortens a closed polyline on a cloud into a locally shortest loop (paper Sec. 4.1.5 and appendix
// "Curve shortening using optimization based framework", after Yuan et al.): projected gradient descent
// of sum H(|x_i - x_{i+1}| / spacing), H(s) = e^{s^2} - 1, the gradient projected on the MLS surface's
// tangent plane and every step projected back onto that surface, the loop resampled to about one spacing.
// With a sphere, points outside it pay the paper's penalty lambda max(0, |x_i - c| - r)^2 (lambda = 10, in
// spacings). Choices and measurements: docs/pointcloud.md, "Loop shortening on clouds".
// recordFrames is 0 or at least 2. Throws InputError when the polyline has fewer than 3 points or
// non-finite ones, or the sphere no positive radius.
ShortenedCloudLoop shortenLoop(Cloud& cloud, const std::vector<geometrycentral::Vector3>& polyline,
                               const std::optional<Sphere>& sphere, int recordFrames = 0);

} // namespace cscd
