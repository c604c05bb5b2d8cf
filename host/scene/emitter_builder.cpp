// <emitter>: area (inside a shape), point, directional, constant, envmap.
#include "scene/envmap_loader.h"
#include "scene/loader.h"

namespace rc {

namespace {

Color nonNegativeColor(const Element& e, const std::string& name, const Color& fallback) {
  const Color c = e.located([&] { return e.props.getColor(name, fallback); });
  if (c.r < 0.0f || c.g < 0.0f || c.b < 0.0f) e.failParam(name, "'" + name + "' must be non-negative");
  return c;
}

}  // namespace

void Loader::buildEmitter(const std::shared_ptr<XmlFile>& file, const pugi::xml_node& node, int shapeMesh, int shapeSphere) {
  const Element e = parseElement(file, node);
  const bool inShape = shapeMesh >= 0 || shapeSphere >= 0;
  for (const pugi::xml_node& child : e.children) unexpectedChild(e, child);
  if (e.type.empty()) e.fail("missing attribute 'type'");

  Emitter em;
  if (e.type == "area") {
    if (!inShape) e.fail("an area emitter must be nested inside a <shape>");
    em.type = EmitterType::Area;
    em.radiance = nonNegativeColor(e, "radiance", Color(1.0f));
    em.mesh = shapeMesh;
    em.sphere = shapeSphere;
  } else if (inShape) {
    if (e.type == "point" || e.type == "directional" || e.type == "constant" || e.type == "envmap")
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
