#include "app/crop_flag.h"

#include <sstream>
#include <vector>

#include "app/cli_args.h"
#include "core/error.h"

namespace rc {

CropFlag parseCropFlag(const std::string& text) {
  std::vector<std::string> parts;
  std::stringstream ss(text);
  for (std::string item; std::getline(ss, item, ',');) parts.push_back(item);
  if (parts.size() != 4 || text.empty() || text.back() == ',')
    throw Error("--crop: expected X,Y,W,H (four integers), got '" + text + "'");
  CropFlag c;
  c.given = true;
  c.x = static_cast<int>(parseInteger("--crop", parts[0], 0, 16383));
  c.y = static_cast<int>(parseInteger("--crop", parts[1], 0, 16383));
  c.width = static_cast<int>(parseInteger("--crop", parts[2], 1, 16384));
  c.height = static_cast<int>(parseInteger("--crop", parts[3], 1, 16384));
  return c;
}

void applyCropFlag(const CropFlag& crop, FilmSettings& film) {
  if (!crop.given) return;
  if (crop.x + crop.width > film.width || crop.y + crop.height > film.height)
    throw Error("--crop: window " + std::to_string(crop.x) + "," + std::to_string(crop.y) + " + " +
                std::to_string(crop.width) + "x" + std::to_string(crop.height) + " exceeds the film of " +
                std::to_string(film.width) + "x" + std::to_string(film.height));
  film.cropX = crop.x;
  film.cropY = crop.y;
  film.cropWidth = crop.width;
  film.cropHeight = crop.height;
}

}  // namespace rc
