// <texture type="checkerboard|bitmap|mesh_attribute"> (parameters: texture/texture.h), top level or nested in a
// <bsdf> under a parameter name.
#include <cmath>
#include <filesystem>

#include "core/regular_file.h"
#include "image/image_file.h"
#include "scene/loader.h"

namespace rc {

namespace {

// Mitsuba's to_uv is a 2-D affine map; a 4×4 <transform> contributes its x/y rows and translation.
UvTransform uvTransformOf(const Mat4& m) {
  UvTransform t;
  t.m[0] = Vec3(m[0][0], m[0][1], 0.0f);
  t.m[1] = Vec3(m[1][0], m[1][1], 0.0f);
  t.m[2] = Vec3(m[3][0], m[3][1], 1.0f);
  return t;
}

float srgbToLinear(float v) {
  return v <= 0.04045f ? v / 12.92f : std::pow((v + 0.055f) / 1.055f, 2.4f);
}

TexturePtr loadBitmap(Loader& loader, const Element& e, const UvTransform& toUv) {
  const std::string fn = e.located([&] { return e.props.getString("filename", ""); });
  if (fn.empty()) e.fail("missing parameter 'filename'");
  const bool raw = e.located([&] { return e.props.getBool("raw", false); });
  e.located([&] { return e.props.getBool("accel", true); });  // a GPU lookup hint in Mitsuba
  const std::string filter = e.located([&] { return e.props.getString("filter_type", "bilinear"); });
  const std::string wrap = e.located([&] { return e.props.getString("wrap_mode", "repeat"); });
  if (filter != "bilinear" && filter != "nearest") e.failParam("filter_type", "'filter_type' must be bilinear or nearest");
  if (wrap != "repeat" && wrap != "mirror" && wrap != "clamp") e.failParam("wrap_mode", "'wrap_mode' must be repeat, mirror or clamp");
  const std::string path = loader.resolvePath(e, fn);
  if (const std::string why = irregularFileReason(path); !why.empty())
    e.failParam("filename", "texture '" + path + (why == "not found" ? "' not found" : "': " + why));
  const ImageChannels img = e.located([&] { return readImageFile(path); });
  if (img.width <= 0 || img.height <= 0 || img.channels() == 0) e.failParam("filename", "texture '" + path + "' has no pixels");
  if (size_t(img.width) * size_t(img.height) > (size_t(1) << 28)) e.failParam("filename", "texture '" + path + "' is too large");
  int rgb[3];
  rgbChannelIndices(img, rgb);
  // As Mitsuba's RGB variants: 8-bit sRGB-encoded files are linearised unless `raw`.
  const bool decode = img.eightBitSrgb && !raw;
  std::vector<Color> px(size_t(img.width) * img.height);
  for (size_t i = 0; i < px.size(); ++i) {
    const float* p = &img.data[i * img.channels()];
    Color c(p[rgb[0]], p[rgb[1]], p[rgb[2]]);
    if (decode) c = Color(srgbToLinear(c.r), srgbToLinear(c.g), srgbToLinear(c.b));
    if (!isFinite(c)) e.failParam("filename", "texture '" + path + "' holds NaN or Inf");
    px[i] = c;
  }
  return makeBitmapTexture(img.width, img.height, std::move(px),
                           filter == "nearest" ? TextureFilter::Nearest : TextureFilter::Bilinear,
                           wrap == "mirror" ? TextureWrap::Mirror : wrap == "clamp" ? TextureWrap::Clamp : TextureWrap::Repeat,
                           toUv);
}

}  // namespace

TexturePtr Loader::buildTexture(const std::shared_ptr<XmlFile>& file, const pugi::xml_node& node) {
  const Element e = parseElement(file, node);
  if (e.type.empty()) e.fail("missing attribute 'type'");
  VolumePtr volume;  // a `volume` texture's nested <volume name="volume"> or <ref> to one
  for (const pugi::xml_node& child : e.children) {
    const std::string tag = child.name();
    if (e.type != "volume" || volume || (tag != "volume" && tag != "ref")) unexpectedChild(e, child);
    if (tag == "volume") {
      volume = buildVolume(file, child);
    } else {
      volume = resolveRefTo(file, child, Kind::Volume, "volume").volume;
    }
  }
  TexturePtr texture;
  if (e.type == "volume") {
    if (!volume) e.fail("missing the nested <volume name=\"volume\">");
    texture = makeVolumeTexture(volume);
  } else if (e.type == "checkerboard") {
    const Color c0 = e.located([&] { return e.props.getColor("color0", Color(0.4f)); });
    const Color c1 = e.located([&] { return e.props.getColor("color1", Color(0.2f)); });
    texture = makeCheckerboard(c0, c1, uvTransformOf(e.transform("to_uv")));
  } else if (e.type == "bitmap") {
    texture = loadBitmap(*this, e, uvTransformOf(e.transform("to_uv")));
  } else if (e.type == "mesh_attribute") {
    const std::string name = e.located([&] { return e.props.getString("name", ""); });
    // Mitsuba's test: the name contains one of the two (its attributes start with them).
    if (name.find("vertex_") == std::string::npos && name.find("face_") == std::string::npos)
      e.failParam("name", "a mesh attribute's name starts with 'vertex_' or 'face_', got '" + name + "'");
    const float scale = e.located([&] { return e.props.getFloat("scale", 1.0f); });
    texture = makeMeshAttributeTexture(name, scale);
  } else {
    unsupported(e.where() + ": unknown plugin '" + e.type + "' (known: checkerboard, bitmap, mesh_attribute, volume)");
    registerId(e, Kind::Texture);
    return nullptr;
  }
  checkUnused(e);
  registerId(e, Kind::Texture, nullptr, texture);
  return texture;
}

}  // namespace rc
