#pragma once

#include "geometrycentral/utilities/vector3.h"

#include <array>
#include <cstdint>
#include <vector>

namespace cscd {

// Inside or outside a noisy cloud, without normals: a point is outside when empty space joins it to the
// far side of the cloud's bounding box. Space is a grid of cubes about a spacing wide; a cube is solid
// when it or one of its 26 neighbours holds a point of the cloud, so the noisy shell is closed; the
// empty cubes reached from the box's border by face steps are the outside, grown back by the one cube
// the shell was grown by (a closing); every other cube is inside, the cubes of the points included: the
// axis of a leg as thin as the noise lies in them.
//
// Why not the winding number there: it needs normals of one orientation, and PCA normals on a part as
// thin as the noise lie across it in any direction (docs/pointcloud.md, "Inside a noisy cloud").
class ExteriorGrid {
public:
  ExteriorGrid(const std::vector<geometrycentral::Vector3>& points, double spacing);

  bool inside(const geometrycentral::Vector3& p) const;

  // Whether a closed loop whose centroid the flood reached goes round a tube open at an end: the flood
  // comes in through the opening of a scan that is open (a trunk at the ground, a pipe, a statue without
  // its base) and would put the axis of the whole tube outside. Such a loop is a cross-section: round and
  // flat, the shell all round its centroid in its plane, and the shell in most directions from its
  // centroid in space too (the flood's way in is a narrow cone). A loop round the rim of a hole or round
  // the hole of a handle is round, flat and enclosed in its plane as well, but a hemisphere or more of
  // the directions from its centroid leads out. A loop round the hole of a ring whose wall is thick (a
  // napkin ring) sees little open space from its centroid too, but it lies on a face of the wall: the
  // shell is much deeper on the wall's side of the loop than on the other.
  bool enclosesCrossSection(const std::vector<geometrycentral::Vector3>& loop) const;

private:
  size_t cellIndex(std::array<long, 3> cell) const { return (size_t(cell[2]) * dims[1] + size_t(cell[1])) * dims[0] + size_t(cell[0]); }
  std::array<long, 3> cellOf(const geometrycentral::Vector3& p) const;
  // Marches from p along the unit direction d (half a cube a step) for at most `reach`: whether it meets
  // a solid cube (the shell) before that and before it leaves the grid.
  bool meetsShell(const geometrycentral::Vector3& p, const geometrycentral::Vector3& d, double reach) const;
  // How far from p along the unit direction d (a quarter cube a step) open space begins: a cube the flood
  // reached or next to one, or the grid's border; `reach` if none is met before it.
  double toOpenSpace(const geometrycentral::Vector3& p, const geometrycentral::Vector3& d, double reach) const;

  geometrycentral::Vector3 origin;
  double cellSize = 0;
  std::array<long, 3> dims{};
  std::vector<uint8_t> solid; // per cube: 1 where it or one of its 26 neighbours holds a point (the shell)
  std::vector<uint8_t> inner; // per cube: 0 where empty space joins it to the border, or next to such a cube
};

} // namespace cscd
