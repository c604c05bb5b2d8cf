#include "render/camera_path.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "core/json_reader.h"
#include "scene/transform_parser.h"

namespace rc {

namespace {

Vec3 readVec3(const JsonValue& key, const char* name, const std::string& where, const Vec3* fallback) {
  const JsonValue* v = key.find(name);
  if (!v) {
    if (fallback) return *fallback;
    throw Error(where + ":" + std::to_string(key.line) + ": keyframe needs '" + name + "'");
  }
  if (!v->isArray() || v->array.size() != 3 || !v->array[0].isNumber() || !v->array[1].isNumber() ||
      !v->array[2].isNumber())
    throw Error(where + ":" + std::to_string(v->line) + ": '" + name + "' must be an array of three numbers");
  return Vec3(static_cast<float>(v->array[0].number), static_cast<float>(v->array[1].number),
              static_cast<float>(v->array[2].number));
}

template <typename T>
T catmullRom(const T& p0, const T& p1, const T& p2, const T& p3, float u) {
  const float u2 = u * u, u3 = u2 * u;
  return 0.5f * ((2.0f * p1) + (p2 - p0) * u + (2.0f * p0 - 5.0f * p1 + 4.0f * p2 - p3) * u2 +
                 (3.0f * p1 - p0 - 3.0f * p2 + p3) * u3);
}

}  // namespace

std::vector<CameraKey> readCameraPath(const std::string& path) {
  const JsonValue doc = readJsonFile(path);
  const JsonValue* keys = doc.isObject() ? doc.find("keyframes") : nullptr;
  if (!keys || !keys->isArray() || keys->array.empty())
    throw Error(path + ":" + std::to_string(doc.line) + ": expected {\"keyframes\": [ ... ]} with at least one keyframe");
  std::vector<CameraKey> out;
  const Vec3 defaultUp(0.0f, 1.0f, 0.0f);
  for (const JsonValue& k : keys->array) {
    const std::string at = path + ":" + std::to_string(k.line);
    if (!k.isObject()) throw Error(at + ": a keyframe must be an object");
    for (const auto& [name, v] : k.object)
      if (name != "origin" && name != "target" && name != "up" && name != "fov")
        throw Error(path + ":" + std::to_string(v.line) + ": unknown keyframe member '" + name +
                    "' (origin, target, up, fov)");
    CameraKey key;
    key.origin = readVec3(k, "origin", path, nullptr);
    key.target = readVec3(k, "target", path, nullptr);
    key.up = readVec3(k, "up", path, &defaultUp);
    if (const JsonValue* f = k.find("fov")) {
      if (!f->isNumber() || !(f->number > 0.0 && f->number < 180.0))
        throw Error(path + ":" + std::to_string(f->line) + ": 'fov' must be a number in (0, 180)");
      key.fov = static_cast<float>(f->number);
    }
    const Vec3 dir = key.target - key.origin;
    if (!(glm::dot(dir, dir) > 0.0f)) throw Error(at + ": origin and target coincide");
    const Vec3 c = glm::cross(glm::normalize(key.up), glm::normalize(dir));
    if (!(glm::dot(key.up, key.up) > 0.0f) || !(glm::dot(c, c) > 1e-12f))
      throw Error(at + ": 'up' is zero or parallel to the view direction");
    out.push_back(key);
  }
  const bool anyFov = std::any_of(out.begin(), out.end(), [](const CameraKey& k) { return k.fov > 0.0f; });
  const bool allFov = std::all_of(out.begin(), out.end(), [](const CameraKey& k) { return k.fov > 0.0f; });
  if (anyFov && !allFov) throw Error(path + ": give 'fov' in every keyframe or in none");
  return out;
}

CameraKey interpolateCameraPath(const std::vector<CameraKey>& keys, float t) {
  if (keys.size() == 1) return keys[0];
  const int last = static_cast<int>(keys.size()) - 1;
  const float x = std::clamp(t, 0.0f, 1.0f) * static_cast<float>(last);
  const int i = std::min(last - 1, static_cast<int>(std::floor(x)));
  const float u = x - static_cast<float>(i);
  const CameraKey& k0 = keys[std::max(0, i - 1)];
  const CameraKey& k1 = keys[i];
  const CameraKey& k2 = keys[i + 1];
  const CameraKey& k3 = keys[std::min(last, i + 2)];
  CameraKey out;
  out.origin = catmullRom(k0.origin, k1.origin, k2.origin, k3.origin, u);
  out.target = catmullRom(k0.target, k1.target, k2.target, k3.target, u);
  out.up = glm::normalize(catmullRom(k0.up, k1.up, k2.up, k3.up, u));
  out.fov = catmullRom(k0.fov, k1.fov, k2.fov, k3.fov, u);
  return out;
}

Camera cameraOfFrame(const Camera& base, const std::vector<CameraKey>& keys, int frame, int frames) {
  const float t = frames > 1 ? static_cast<float>(frame) / static_cast<float>(frames - 1) : 0.0f;
  const CameraKey k = interpolateCameraPath(keys, t);
  Camera cam = base;
  const Vec3 dir = k.target - k.origin;
  const Vec3 c = glm::cross(k.up, glm::normalize(dir));
  // Interpolation can only degenerate between keys that are each valid when the path turns back on
  // itself; then the frame is an error rather than a NaN camera.
  if (!(glm::dot(dir, dir) > 0.0f) || !(glm::dot(c, c) > 1e-12f) || !(k.fov >= 0.0f && k.fov < 180.0f))
    throw Error("camera path: frame " + std::to_string(frame) + " interpolates to a degenerate camera");
  cam.toWorld = lookAt(k.origin, k.target, k.up);
  if (k.fov > 0.0f) cam.fovDegrees = k.fov;
  return cam;
}

}  // namespace rc
