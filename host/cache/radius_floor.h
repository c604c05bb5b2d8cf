#pragma once
// The fill's progress guarantee. A record must cover the point it was made for, or the fill
// would make records for that point forever: its influence sphere (a·R)² has to be a positive
// float and the sphere must be resolvable at the record's position. Radii come from pixel
// footprints, which a tiny fov (1e-20) or a crafted cache file can push below float
// resolution; this floor, a few ulps of the position (or of the scene's extent near the
// origin), keeps every record able to cover its own point and those within float rounding of it.
#include <algorithm>
#include <cfloat>
#include <cmath>

#include "core/math.h"

namespace rc {

// Multiple of float resolution: distances near a record are computed from differences of
// positions, each rounded to half an ulp; 16 ulps leaves room for the squares and sums of the
// weight test.
constexpr float kReachResolutionUlps = 16.0f;

// Smallest influence radius a·R allowed at p in a scene of the given extent (largest side).
inline float minimumReach(const Vec3& p, float sceneExtent) {
  const float magnitude = std::max({std::fabs(p.x), std::fabs(p.y), std::fabs(p.z), 1e-6f * sceneExtent});
  // 1e-15 keeps (a·R)² a normal float even at the origin of a degenerate scene.
  return std::max(kReachResolutionUlps * FLT_EPSILON * magnitude, 1e-15f);
}

}  // namespace rc
