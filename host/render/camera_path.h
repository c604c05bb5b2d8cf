#pragma once
// Camera paths for walk-throughs (`rcache SCENE.xml --frames N --camera-path keys.json`). The
// keyframes live beside the scene, so the scene file stays a valid Mitsuba 3 file:
//   {"keyframes": [{"origin": [x, y, z], "target": [x, y, z], "up": [0, 1, 0], "fov": 45}, ...]}
// | member  | default            | meaning                                     |
// |---------|--------------------|---------------------------------------------|
// | origin  | required           | camera position (lookat origin)             |
// | target  | required           | point looked at (lookat target)             |
// | up      | [0, 1, 0]          | up vector (lookat up)                       |
// | fov     | the scene's fov    | field of view in degrees, along the scene's fov_axis |
// Keyframes are spaced evenly over the frames (frame 0 at the first, frame N−1 at the last) and
// interpolated with uniform Catmull-Rom splines on origin, target, up and fov (C¹, passes through
// every keyframe; end tangents from the duplicated end keys), up renormalised; the sensor's
// to_world is the lookat of the interpolated values.
#include <string>
#include <vector>

#include "core/math.h"
#include "scene/scene.h"

namespace rc {

struct CameraKey {
  Vec3 origin{0.0f}, target{0.0f, 0.0f, -1.0f}, up{0.0f, 1.0f, 0.0f};
  float fov = 0.0f;  // degrees; 0 = the scene's
};

// Throws rc::Error("<path>:<line>: ...") for a malformed file or degenerate keys.
std::vector<CameraKey> readCameraPath(const std::string& path);

// The key at parameter t ∈ [0, 1] along the path.
CameraKey interpolateCameraPath(const std::vector<CameraKey>& keys, float t);

// `base` (near/far clip, fov axis) moved to frame `frame` of `frames`.
Camera cameraOfFrame(const Camera& base, const std::vector<CameraKey>& keys, int frame, int frames);

}  // namespace rc
