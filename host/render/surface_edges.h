#pragma once
// Pixels whose footprint may hold more than one surface: the surface seen through the pixel's
// centre differs from one seen through a neighbour's centre (another shape or material, a
// crease, a depth jump, or sky on one side). The radiance cache's last fill pass looks up several
// points inside such pixels, so that the final pass's jittered samples find records on every
// surface the pixel shows; inside a surface one point per pixel suffices.
#include <cstdint>
#include <vector>

#include "geometry/accel.h"
#include "render/camera.h"

namespace rc {

// Whether the surfaces hit at two neighbouring pixel centres may differ (exposed for tests).
bool surfacesDiffer(const Hit& a, const Hit& b);

// One flag per pixel (row-major, width × height): 1 where a pixel centre of the 8-neighbourhood
// (as far as the image reaches) sees a different surface than the pixel's own centre
// (surfacesDiffer). Traces one camera ray per pixel.
std::vector<uint8_t> surfaceEdgePixels(const Accel& accel, const CameraModel& camera, int width, int height);

}  // namespace rc
