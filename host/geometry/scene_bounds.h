#pragma once
// The box the radiance caches' octrees start from: the vertices that triangles reference and
// the spheres, skipping anything non-finite. An unreferenced vertex (a hostile or sloppy file
// may hold `inf` or 1e39 there) or a sphere whose extent overflows must not make the box
// infinite: an octree rooted at an inf/NaN centre cannot separate anything and every insert
// would fill all eight children down to the maximum depth.
#include "core/math.h"
#include "scene/scene.h"

namespace rc {

// lo/hi of the finite geometry; a unit cube about the origin when there is none.
void finiteSceneBounds(const Scene& scene, Vec3& lo, Vec3& hi);

}  // namespace rc
