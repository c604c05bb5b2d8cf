// <emitter>: area (inside a shape), point, spot, projector, directional, constant, envmap.
#include <cmath>

#include "scene/field_of_view.h"
#include "scene/envmap_loader.h"
#include "scene/loader.h"

namespace rc {

namespace {

Color nonNegativeColor(const Element& e, const std::string& name, const Color& fallback) {
  const Color c = e.located([&] { return e.props.getColor(name, fallback); });
  if (c.r < 0.0f || c.g < 0.0f || c.b < 0.0f) e.failParam(name, "'" + name + "' must be non-negative");
  return c;
}

// A spot's or projector's frame: to_world's origin and the inverse of its linear part.
void placeInFrame(const Element& e, Emitter& em) {
  em.toWorld = e.transform("to_world");
  const Mat3 linear(em.toWorld);
  if (!(std::fabs(glm::determinant(linear)) > 0.0f)) e.failParam("to_world", "the " + e.type + "'s to_world is singular");
  em.spotWorldToLocal = glm::inverse(linear);
  em.position = Vec3(em.toWorld[3]);
}

// Mitsuba's spot: at to_world's origin, pointing along its +z. Parameters:
//   intensity     spectrum  on-axis radiant intensity (W/sr), default 1; not spatially varying
//   cutoff_angle  float     degrees from the axis beyond which it is black, default 20
//   beam_width    float     degrees of full intensity, default 3/4 of cutoff_angle; linear
//                           falloff in the angle between the two
//   to_world      transform placement
//   texture       texture   projected image (a <texture> or a <ref>), spanning tan(cutoff_angle) on
//                           the local z = 1 plane around the axis (render/spot_light.h)
void buildSpot(const Element& e, Emitter& em) {
  em.type = EmitterType::Spot;
  em.intensity = nonNegativeColor(e, "intensity", Color(1.0f));
  const float cutoff = e.located([&] { return e.props.getFloat("cutoff_angle", 20.0f); });
  if (!(cutoff > 0.0f && cutoff <= 180.0f))
    e.failParam("cutoff_angle", "'cutoff_angle' must be in (0, 180] degrees, got " + std::to_string(cutoff));
  const float beam = e.located([&] { return e.props.getFloat("beam_width", cutoff * 0.75f); });
  if (!(beam >= 0.0f && beam <= cutoff))
    e.failParam("beam_width", "'beam_width' must be in [0, cutoff_angle] degrees, got " + std::to_string(beam));
  em.spotCutoffRad = cutoff * kPi / 180.0f;
  em.spotBeamRad = beam * kPi / 180.0f;
  em.spotCosCutoff = std::cos(em.spotCutoffRad);
  em.spotCosBeam = std::cos(em.spotBeamRad);
  placeInFrame(e, em);
}

// Mitsuba's projector (src/emitters/projector.cpp): a pinhole at to_world's origin projecting an
// image along its +z, the reciprocal of the perspective sensor. Parameters:
//   irradiance    rgb / texture  irradiance on the image plane at z = 1, default 1
//   scale         float          factor on it, default 1
//   fov, fov_axis / focal_length as the perspective sensor (the axis resolved with the image's aspect)
//   to_world      transform      placement
void buildProjector(const Element& e, Emitter& em) {
  em.type = EmitterType::Projector;
  if (!em.projection) em.irradiance = nonNegativeColor(e, "irradiance", Color(1.0f));
  em.scale = e.located([&] { return e.props.getFloat("scale", 1.0f); });
  if (!(em.scale >= 0.0f && std::isfinite(em.scale))) e.failParam("scale", "'scale' must be finite and non-negative");
  const auto [w, h] = em.projection ? em.projection->resolution() : std::pair<int, int>(1, 1);
  em.projectorAspect = static_cast<float>(w) / static_cast<float>(h);
  const FieldOfView fov = readFieldOfView(e);
  const float fovX = e.located([&] { return horizontalFovDegrees(fov.degrees, fov.axis, em.projectorAspect); });
  if (!(fovX > 0.0f && fovX < 180.0f)) e.failParam("fov", "the projector's horizontal field of view must be in (0, 180) degrees");
  em.projectorCot = 1.0f / std::tan(0.5f * fovX * kPi / 180.0f);
  placeInFrame(e, em);
}

}  // namespace

void Loader::buildEmitter(const std::shared_ptr<XmlFile>& file, const pugi::xml_node& node, int shapeMesh, int shapeSphere) {
  const Element e = parseElement(file, node);
  const bool inShape = shapeMesh >= 0 || shapeSphere >= 0;
  if (e.type.empty()) e.fail("missing attribute 'type'");
  Emitter em;
  // The projected image: the spot's `texture`, the projector's `irradiance` (<texture> or <ref>).
  const std::string imageParameter = e.type == "spot" ? "texture" : e.type == "projector" ? "irradiance" : "";
  for (const pugi::xml_node& child : e.children) {
    const std::string tag = child.name();
    if (imageParameter.empty() || child.attribute("name").value() != imageParameter || (tag != "texture" && tag != "ref"))
      unexpectedChild(e, child);
    if (tag == "texture") {
      em.projection = buildTexture(file, child);
    } else {
      const Named& n = resolveRef(file, child);
      if (n.kind != Kind::Texture)
        throw LocatedError(whereOf(*file, child) + ": id '" + std::string(child.attribute("id").value()) +
                           "' (defined at " + n.where + ") is not a texture");
      em.projection = n.texture;
    }
    if (em.projection && !em.projection->meshAttribute().empty())
      throw LocatedError(whereOf(*file, child) + ": a mesh_attribute texture reads the shape it shades; an emitter's image has none");
  }
  if (e.type == "area") {
    if (!inShape) e.fail("an area emitter must be nested inside a <shape>");
    em.type = EmitterType::Area;
    em.radiance = nonNegativeColor(e, "radiance", Color(1.0f));
    em.mesh = shapeMesh;
    em.sphere = shapeSphere;
  } else if (inShape) {
    if (e.type == "point" || e.type == "spot" || e.type == "projector" || e.type == "directional" || e.type == "constant" ||
        e.type == "envmap")
      e.fail("only an area emitter can be nested inside a <shape>");
    unsupported(e.where() + ": unknown plugin '" + e.type + "'");
    return;
  } else if (e.type == "point") {
    em.type = EmitterType::Point;
    em.intensity = nonNegativeColor(e, "intensity", Color(1.0f));
    if (e.props.has("position") && e.hasTransform("to_world"))
      e.fail("give either 'position' or 'to_world', not both");
    em.position = e.props.has("position") ? e.located([&] { return e.props.getVector("position", Vec3(0.0f)); })
                                          : Vec3(e.transform("to_world")[3]);
  } else if (e.type == "spot") {
    buildSpot(e, em);
  } else if (e.type == "projector") {
    buildProjector(e, em);
  } else if (e.type == "directional") {
    em.type = EmitterType::Directional;
    em.irradiance = nonNegativeColor(e, "irradiance", Color(1.0f));
    if (e.props.has("direction") && e.hasTransform("to_world"))
      e.fail("give either 'direction' or 'to_world', not both");
    // Mitsuba: the light travels along the emitter's local +z.
    const Vec3 d = e.props.has("direction") ? e.located([&] { return e.props.getVector("direction", Vec3(0, 0, 1)); })
                                            : Vec3(e.transform("to_world") * Vec4(0, 0, 1, 0));
    if (!(glm::dot(d, d) > 0.0f)) e.failParam(e.props.has("direction") ? "direction" : "to_world", "direction is zero");
    em.direction = glm::normalize(d);
  } else if (e.type == "constant" || e.type == "envmap") {
    if (environments_++ > 0) e.fail("only one environment emitter (constant or envmap) is allowed");
    if (e.type == "constant") {
      em.type = EmitterType::Constant;
      em.radiance = nonNegativeColor(e, "radiance", Color(1.0f));
    } else {
      em.type = EmitterType::Envmap;
      const std::string fn = e.located([&] { return e.props.getString("filename", ""); });
      if (fn.empty()) e.fail("missing parameter 'filename'");
      em.filename = resolvePath(e, fn);
      em.scale = e.located([&] { return e.props.getFloat("scale", 1.0f); });
      if (!(em.scale >= 0.0f)) e.failParam("scale", "'scale' must be non-negative");
      em.toWorld = e.transform("to_world");
      EnvImage img = e.located([&] { return loadEnvImage(em.filename); });
      em.envWidth = img.width;
      em.envHeight = img.height;
      em.envPixels = std::move(img.pixels);
    }
  } else {
    unsupported(e.where() + ": unknown plugin '" + e.type + "'");
    return;
  }
  checkUnused(e);
  // A shared top-level area emitter is built once per shape referring to it; its id is registered once.
  if (!(inShape && areaEmitter(e.id) && ids_.count(e.id))) registerId(e, Kind::Emitter);
  const int index = static_cast<int>(scene_.emitters.size());
  scene_.emitters.push_back(std::move(em));
  if (shapeMesh >= 0) scene_.meshes[shapeMesh].emitter = index;
  if (shapeSphere >= 0) scene_.spheres[shapeSphere].emitter = index;
}

}  // namespace rc
