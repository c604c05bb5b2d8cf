#pragma once
// Mitsuba 3's `sdfgrid` surface (src/shapes/sdfgrid.cpp), in the grid's object space [0,1]³:
// the trilinear interpolant of the samples, its exact ray intersection per voxel, and the two
// normals Mitsuba defines. All in double: the intersection is a cubic's root, and float leaves
// holes at grazing rays and voxel faces.
#include <glm/glm.hpp>

#include "scene/scene.h"

namespace rc {

// The interpolant at object point p: sample (i, j, k) sits at (i, j, k) / (res − 1) (the voxel
// corners: Mitsuba rescales its texture lookups so that texel centres land there), trilinear in
// between; outside [0,1]³ the value at the nearest point of the cube (the texture's clamp mode).
double sdfValue(const SdfGrid& grid, const glm::dvec3& p);

// Mitsuba's voxel_grad: per axis, the difference of the interpolant across voxel v's two faces on
// the lines through p, over the voxel size. Inside v it is the interpolant's exact gradient.
glm::dvec3 sdfVoxelGradient(const SdfGrid& grid, const glm::dvec3& p, const glm::ivec3& voxel);

// Mitsuba's `smooth` normal at p (Hansson-Söderlund, Evans and Akenine-Möller, JCGT 11(3), 2022):
// the unit voxel gradients at p of the 2×2×2 voxels whose centres surround p, interpolated
// trilinearly between those centres; voxels with a negative index are left out (their axis takes
// the other side's weight), voxels past the far end are kept with the clamped values. Not
// normalised (Mitsuba normalises after to_world).
glm::dvec3 sdfSmoothNormal(const SdfGrid& grid, const glm::dvec3& p);

// The voxel of index `voxel` (x + (nx−1)·(y + (ny−1)·z)) as integer coordinates.
glm::ivec3 sdfVoxelCoords(const SdfGrid& grid, uint32_t voxel);

// The first t in [tMin, tMax] where the object-space ray o + t·d crosses the zero of the
// interpolant inside the (closed) voxel; false if it does not. Exact up to double rounding: the
// interpolant along the ray is a cubic in t, split at its extrema into monotone pieces, and the
// first piece whose ends differ in sign is solved by safeguarded Newton. A tangent touch (no sign
// change) is not a hit, as in Mitsuba.
bool intersectSdfVoxel(const SdfGrid& grid, const glm::ivec3& voxel, const glm::dvec3& o, const glm::dvec3& d,
                       double tMin, double tMax, double& t);

struct SdfHitGeometry {
  Vec3 ng{0, 0, 1};  // unit: the interpolant's gradient in the hit voxel, as a world normal
  Vec3 ns{0, 0, 1};  // unit: ng (`analytic`) or the smooth normal, on ng's side
};
// The normals at world point p of a hit in `voxel` (world normals: the inverse transpose of
// to_world's linear part).
SdfHitGeometry sdfHitGeometry(const SdfGrid& grid, const glm::ivec3& voxel, const Vec3& p);

}  // namespace rc
