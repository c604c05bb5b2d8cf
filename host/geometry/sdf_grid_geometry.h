#pragma once
// Mitsuba 3's `sdfgrid` as Embree user geometry: one primitive per occupied voxel (world bounds of
// its box), ray tests in the grid's object space (geometry/sdf_grid_math.h, exact for any affine
// to_world).
#include <embree3/rtcore.h>

#include "core/math.h"
#include "scene/scene.h"

namespace rc {

// World-space bounds of the grid's unit cube.
void sdfGridBounds(const SdfGrid& grid, Vec3& lo, Vec3& hi);

// One user geometry holding the occupied voxels of `grid` (which must outlive the scene), attached
// to `scene`; returns its geomID. Embree's primID is the index into grid.voxels.
unsigned attachSdfGrid(RTCDevice device, RTCScene scene, const SdfGrid& grid);

}  // namespace rc
