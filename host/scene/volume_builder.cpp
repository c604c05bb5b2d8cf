// <volume>: gridvolume (a `.vol` file, scene/volume_grid_file.h) and constvolume, as Mitsuba 3's
// src/volumes/{grid,const}.cpp read them (parameters: texture/volume.h); a float or rgb parameter
// where a volume is expected is a constant volume.
#include <algorithm>
#include <cmath>

#include "scene/loader.h"
#include "scene/volume_grid_file.h"

namespace rc {

VolumePtr Loader::buildVolume(const std::shared_ptr<XmlFile>& file, const pugi::xml_node& node) {
  const Element e = parseElement(file, node);
  if (e.type.empty()) e.fail("missing attribute 'type'");
  for (const pugi::xml_node& child : e.children) unexpectedChild(e, child);
  VolumePtr volume;
  if (e.type == "constvolume") {
    volume = makeConstVolume(e.located([&] { return e.props.getColor("value", Color(1.0f)); }), e.transform("to_world"));
  } else if (e.type == "gridvolume") {
    const std::string fn = e.located([&] { return e.props.getString("filename", ""); });
    if (fn.empty()) e.fail("missing parameter 'filename'");
    const std::string filter = e.located([&] { return e.props.getString("filter_type", "trilinear"); });
    const std::string wrap = e.located([&] { return e.props.getString("wrap_mode", "clamp"); });
    if (filter != "trilinear" && filter != "nearest") e.failParam("filter_type", "'filter_type' must be trilinear or nearest");
    if (wrap != "repeat" && wrap != "mirror" && wrap != "clamp")
      e.failParam("wrap_mode", "'wrap_mode' must be repeat, mirror or clamp");
    // Mitsuba's RGB variants use a 3-channel grid as stored with or without `raw` (only its
    // spectral variants convert).
    e.located([&] { return e.props.getBool("raw", false); });
    VolumeGrid grid = e.located([&] { return readVolumeGrid(resolvePath(e, fn)); });
    if (grid.channels != 1 && grid.channels != 3)
      e.failParam("filename", "'" + fn + "' has " + std::to_string(grid.channels) +
                                  " channels; a gridvolume read as a colour needs 1 or 3");
    Mat4 toWorld = e.transform("to_world");
    if (e.located([&] { return e.props.getBool("use_grid_bbox", false); })) {
      // Mitsuba's VolumeGrid::bbox_transform: the file's bounds are the unit cube, to_world follows.
      Mat4 boundsToCube(1.0f);
      for (int a = 0; a < 3; ++a) boundsToCube[a][a] = grid.boundsMax[a] - grid.boundsMin[a];
      boundsToCube[3] = Vec4(grid.boundsMin[0], grid.boundsMin[1], grid.boundsMin[2], 1.0f);
      toWorld = toWorld * boundsToCube;
    }
    const float det = glm::determinant(toWorld);
    if (!(std::fabs(det) > 0.0f) || !std::isfinite(det))
      e.failParam("to_world", "the volume's to_world (with the file's bounds where use_grid_bbox) is singular");
    GridVolumeData data;
    for (int a = 0; a < 3; ++a) data.size[a] = grid.size[a];
    data.channels = grid.channels;
    data.values = std::move(grid.values);
    if (e.props.has("max_value")) {
      // Mitsuba takes it as the majorant as given; below the data it would not bound the density.
      data.maxValue = e.located([&] { return e.props.getFloat("max_value", 0.0f); });
      float dataMax = 0.0f;
      for (const float v : data.values) dataMax = std::max(dataMax, v);
      if (!(data.maxValue >= dataMax) || !std::isfinite(data.maxValue))
        e.failParam("max_value", "'max_value' must be finite and at least the grid's largest value " + std::to_string(dataMax));
    }
    volume = makeGridVolume(std::move(data), filter == "nearest" ? VolumeFilter::Nearest : VolumeFilter::Trilinear,
                            wrap == "mirror" ? TextureWrap::Mirror : wrap == "clamp" ? TextureWrap::Clamp : TextureWrap::Repeat,
                            glm::inverse(toWorld));
  } else {
    e.fail("unknown volume plugin '" + e.type + "' (known: gridvolume, constvolume)");
  }
  checkUnused(e);
  Named& n = registerId(e, Kind::Volume);
  n.volume = volume;
  return volume;
}

VolumePtr Loader::volumeParameter(const Element& e, const std::string& name, const Color& fallback,
                                  const std::map<std::string, VolumePtr>& nested) const {
  const auto it = nested.find(name);
  if (it != nested.end()) {
    if (e.props.has(name)) e.failParam(name, "'" + name + "' is given twice (a value and a <volume>)");
    return it->second;
  }
  return makeConstVolume(e.located([&] { return e.props.getColor(name, fallback); }));
}

}  // namespace rc
