#pragma once
// --crop X,Y,W,H: the film's crop window from the command line (overrides the scene's hdrfilm
// crop_offset_x/y, crop_width/height), checked against the sensor size once the scene is loaded.
#include <string>

#include "scene/scene.h"

namespace rc {

struct CropFlag {
  bool given = false;
  int x = 0, y = 0, width = 0, height = 0;
};

// Throws rc::Error naming --crop for anything but four non-negative integers (W, H positive).
CropFlag parseCropFlag(const std::string& text);
// Throws rc::Error when the window does not lie inside the film.
void applyCropFlag(const CropFlag& crop, FilmSettings& film);

}  // namespace rc
