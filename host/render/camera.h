#pragma once
// Pinhole camera with Mitsuba 3 `perspective` conventions: the camera looks down local +z, local +y is
// up, and image x grows toward local −x (Mitsuba's look_at puts local +x on the image's left), so an
// image rendered here matches Mitsuba's pixel for pixel, not mirrored.
#include "scene/field_of_view.h"
#include "core/math.h"
#include "geometry/accel.h"
#include "scene/scene.h"

namespace rc {

class CameraModel {
 public:
  CameraModel(const Camera& camera, int width, int height);
  // The sensor of `film`; film positions are then in pixels of its crop window (the image).
  CameraModel(const Camera& camera, const FilmSettings& film);

  // Primary ray through a film position in pixels, (0,0) = top-left corner of the image,
  // (width, height) = bottom-right (of the crop window, which lies at cropOffset on the sensor). Direction is unit, tMin/tMax from near/far clip along it.
  Ray generate(Vec2 filmPos) const;

  // World-space size of one sensor pixel (the same with or without a crop window) on a plane facing the camera at `distance` along the view axis.
  float pixelFootprint(float distance) const;
  // The same for a pixel of the square film with as many pixels and the same horizontal field of
  // view, or the real pixel where that is larger: a resolution that follows the pixel count and the
  // view, not the film's aspect ratio. A 16384×1 strip has pixels 128× smaller than a 128×128
  // film's although it resolves no more of the scene off its thin view.
  float squareFilmPixelFootprint(float distance) const;

  float fovXDegrees() const { return fovX_; }
  Vec3 position() const { return origin_; }
  Vec3 forward() const { return forward_; }

 private:
  Mat4 toWorld_;
  Vec3 origin_, forward_;
  int width_, height_;  // the sensor
  Vec2 cropOffset_{0.0f};
  float fovX_;        // horizontal field of view in degrees (fov_axis already resolved)
  float tanHalfX_;    // tan(fovX/2): half-width of the image plane at z = 1
  float tanHalfY_;    // half-height at z = 1
  float nearClip_, farClip_;
  Vec2 principalPointOffset_;  // Mitsuba's principal_point_offset_x/y, fractions of the film size
};

}  // namespace rc
