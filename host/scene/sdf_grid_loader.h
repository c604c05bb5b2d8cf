#pragma once
// Mitsuba's `sdfgrid` data: a single-channel `.vol` file (scene/volume_grid_file.h) read as the
// samples of a signed distance over the unit cube (scene.h SdfGrid), and the voxels the surface
// can pass through.
#include <string>

#include "scene/scene.h"

namespace rc {

// The grid of `path` with res, values and voxels set (name, placement, normals and bsdf are the
// builder's). Throws rc::Error("<path>: ...") for a file readVolumeGrid refuses, a channel count
// other than 1, fewer than 2 samples along an axis (no voxel), or a grid without an occupied voxel
// (Mitsuba: "SDFGrid should at least have one non-empty voxel").
SdfGrid loadSdfGrid(const std::string& path);

// Mitsuba's occupancy: the voxels whose eight corner values are neither all > 0 nor all < 0 (a
// trilinear interpolant is a convex combination of its corners, so the others hold no zero).
std::vector<uint32_t> occupiedVoxels(const SdfGrid& grid);

}  // namespace rc
