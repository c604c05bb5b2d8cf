#include "render/camera.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"

namespace rc {

namespace {
constexpr float kDegToRad = kPi / 180.0f;
}

CameraModel::CameraModel(const Camera& camera, int width, int height)
    : toWorld_(camera.toWorld), width_(width), height_(height), nearClip_(camera.nearClip), farClip_(camera.farClip),
      principalPointOffset_(camera.principalPointOffset) {
  if (width <= 0 || height <= 0) throw Error("film: width and height must be positive");
  if (!(camera.fovDegrees > 0.0f && camera.fovDegrees < 180.0f))
    throw Error("perspective sensor: fov must be in (0, 180) degrees");
  const float aspect = static_cast<float>(width) / static_cast<float>(height);
  fovX_ = horizontalFovDegrees(camera.fovDegrees, camera.fovAxis, aspect);
  tanHalfX_ = std::tan(0.5f * fovX_ * kDegToRad);
  tanHalfY_ = tanHalfX_ / aspect;
  origin_ = Vec3(toWorld_ * Vec4(0, 0, 0, 1));
  forward_ = glm::normalize(Vec3(toWorld_ * Vec4(0, 0, 1, 0)));
}

CameraModel::CameraModel(const Camera& camera, const FilmSettings& film) : CameraModel(camera, film.width, film.height) {
  cropOffset_ = Vec2(static_cast<float>(film.cropX), static_cast<float>(film.cropY));
}

Ray CameraModel::generate(Vec2 cropPos) const {
  const Vec2 filmPos = cropPos + cropOffset_;
  // Mitsuba 3 perspective_projection: sample x = 0.5·(1 − x_ndc), y = 0.5·(1 − aspect·y_ndc) with
  // x_ndc = x/(z·tan(fov_x/2)); so image left (u = 0) is local +x and image top is local +y.
  const float sx = filmPos.x / static_cast<float>(width_) + principalPointOffset_.x;
  const float sy = filmPos.y / static_cast<float>(height_) + principalPointOffset_.y;
  const Vec3 local((1.0f - 2.0f * sx) * tanHalfX_, (1.0f - 2.0f * sy) * tanHalfY_, 1.0f);
  Ray r;
  r.o = origin_;
  r.d = glm::normalize(Vec3(toWorld_ * Vec4(local, 0.0f)));
  // Clip planes are depths along the view axis, as in Mitsuba: t = clip / cos(angle to the axis).
  const float len = glm::length(local);
  r.tMin = nearClip_ * len;
  r.tMax = farClip_ * len;
  return r;
}

float CameraModel::pixelFootprint(float distance) const {
  return 2.0f * tanHalfX_ * distance / static_cast<float>(width_);
}

float CameraModel::squareFilmPixelFootprint(float distance) const {
  const float squareSide = std::sqrt(static_cast<float>(width_) * static_cast<float>(height_));
  return std::max(pixelFootprint(distance), 2.0f * tanHalfX_ * distance / squareSide);
}

}  // namespace rc
