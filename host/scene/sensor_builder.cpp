// <sensor type="perspective"> with its <film type="hdrfilm"> (and <rfilter>) and <sampler> (nested, or a
// top-level one it refers to by id).
#include <cmath>
#include <cstdlib>

#include "scene/field_of_view.h"
#include "scene/loader.h"

namespace rc {

namespace {

void buildRfilter(Loader& loader, const Element& e, FilmSettings& film) {
  for (const pugi::xml_node& child : e.children) loader.unexpectedChild(e, child);
  // Mitsuba 3's filters: box (radius 0.5), tent (radius, default 1), gaussian (stddev, default 0.5,
  // radius 4·stddev).
  if (e.type == "box") {
    film.filter = "box";
  } else if (e.type == "tent") {
    film.filter = "tent";
    film.tentRadius = e.located([&] { return e.props.getFloat("radius", 1.0f); });
    if (!(film.tentRadius > 0.0f && film.tentRadius <= 64.0f)) e.failParam("radius", "'radius' must be in (0, 64] pixels");
  } else if (e.type == "gaussian") {
    film.filter = "gaussian";
    film.gaussianStddev = e.located([&] { return e.props.getFloat("stddev", 0.5f); });
    if (!(film.gaussianStddev > 0.0f)) e.failParam("stddev", "'stddev' must be positive");
  } else {
    loader.unsupported(e.where() + ": unknown plugin '" + e.type + "' (known: box, tent, gaussian)");
    return;
  }
  loader.checkUnused(e);
}

// Mitsuba 3 (Film::Film, set_crop_window): the window defaults to the whole sensor and must lie
// inside it.
void readCropWindow(const Element& e, FilmSettings& film) {
  film.cropX = e.located([&] { return e.props.getInt("crop_offset_x", 0); });
  film.cropY = e.located([&] { return e.props.getInt("crop_offset_y", 0); });
  film.cropWidth = e.located([&] { return e.props.getInt("crop_width", film.width); });
  film.cropHeight = e.located([&] { return e.props.getInt("crop_height", film.height); });
  if (film.cropX < 0) e.failParam("crop_offset_x", "'crop_offset_x' must be non-negative");
  if (film.cropY < 0) e.failParam("crop_offset_y", "'crop_offset_y' must be non-negative");
  if (film.cropWidth <= 0) e.failParam("crop_width", "'crop_width' must be positive");
  if (film.cropHeight <= 0) e.failParam("crop_height", "'crop_height' must be positive");
  const std::string window = std::to_string(film.cropX) + "," + std::to_string(film.cropY) + " + " +
                             std::to_string(film.cropWidth) + "x" + std::to_string(film.cropHeight);
  if (static_cast<long long>(film.cropX) + film.cropWidth > film.width)
    e.failParam("crop_width", "crop window " + window + " exceeds the film width " + std::to_string(film.width));
  if (static_cast<long long>(film.cropY) + film.cropHeight > film.height)
    e.failParam("crop_height", "crop window " + window + " exceeds the film height " + std::to_string(film.height));
}

void buildFilm(Loader& loader, const Element& e, FilmSettings& film) {
  if (e.type != "hdrfilm") {
    loader.unsupported(e.where() + ": unknown plugin '" + e.type + "'");
    return;
  }
  film.width = e.located([&] { return e.props.getInt("width", 768); });
  film.height = e.located([&] { return e.props.getInt("height", 576); });
  // Limits: a side over 16384 or more than 2^26 pixels (a 8192² image) is a typo, not a render.
  const long long pixels = static_cast<long long>(film.width) * film.height;
  if (film.width <= 0 || film.width > 16384) e.failParam("width", "'width' must be in 1..16384, got " + std::to_string(film.width));
  if (film.height <= 0 || film.height > 16384) e.failParam("height", "'height' must be in 1..16384, got " + std::to_string(film.height));
  if (pixels > (1ll << 26)) e.fail("film of " + std::to_string(pixels) + " pixels exceeds the limit of 2^26");
  readCropWindow(e, film);
  // Output format is decided by the -o file; Mitsuba's format strings are validated as Mitsuba does
  // and otherwise have no effect, so scenes stay portable.
  auto oneOf = [&](const char* name, const char* fallback, std::initializer_list<const char*> allowed) {
    const std::string v = e.located([&] { return e.props.getString(name, fallback); });
    std::string list;
    for (const char* a : allowed) {
      if (v == a) return;
      list += std::string(list.empty() ? "" : ", ") + a;
    }
    e.failParam(name, std::string("'") + name + "' must be one of " + list + ", got '" + v + "'");
  };
  oneOf("file_format", "openexr", {"openexr", "exr", "rgbe", "pfm"});
  oneOf("pixel_format", "rgb", {"rgb", "rgba", "luminance", "luminance_alpha", "xyz", "xyza"});
  oneOf("component_format", "float16", {"float16", "float32", "uint32"});
  e.located([&] { return e.props.getBool("banner", false); });  // Mitsuba 3 draws no banner
  for (const pugi::xml_node& child : e.children) {
    if (std::string(child.name()) != "rfilter") loader.unexpectedChild(e, child);
    buildRfilter(loader, parseElement(e.file, child), film);
  }
  loader.checkUnused(e);
}

void buildSampler(Loader& loader, const Element& e, Scene& scene) {
  for (const pugi::xml_node& child : e.children) loader.unexpectedChild(e, child);
  // Mitsuba's stratified samplers are served by the low-discrepancy one: per pixel it stratifies
  // every pair of dimensions jointly (a (0,m,2)-net per pair), which is what they are for. Their
  // jitter/strength settings are read and have no effect (our points are always randomised: a
  // sampler without jitter would bias the image).
  const bool stratifiedFamily = e.type == "stratified" || e.type == "multijitter" || e.type == "orthogonal";
  if (e.type != "independent" && e.type != "ldsampler" && !stratifiedFamily) {
    loader.unsupported(e.where() + ": unknown plugin '" + e.type + "' (known: independent, ldsampler, stratified, "
                       "multijitter, orthogonal)");
    return;
  }
  if (stratifiedFamily) {
    e.located([&] { return e.props.getBool("jitter", true); });
    if (e.type == "orthogonal") e.located([&] { return e.props.getFloat("strength", 2.0f); });
  }
  scene.sampler.type = e.type == "independent" ? "independent" : "ldsampler";
  const int count = e.located([&] { return e.props.getInt("sample_count", 4); });
  if (count <= 0) e.failParam("sample_count", "'sample_count' must be positive, got " + std::to_string(count));
  const int seed = e.located([&] { return e.props.getInt("seed", 0); });
  if (seed < 0) e.failParam("seed", "'seed' must be non-negative");
  scene.sampler.sampleCount = count;
  scene.sampler.seed = static_cast<uint64_t>(seed);
  loader.checkUnused(e);
}

}  // namespace

void Loader::useSampler(const Named& n, const std::shared_ptr<XmlFile>& file, const pugi::xml_node& ref) {
  if (n.kind != Kind::Sampler)
    throw LocatedError(whereOf(*file, ref) + ": id '" + std::string(ref.attribute("id").value()) + "' (defined at " +
                       n.where + ") is not a sampler");
  scene_.sampler = n.sampler;
}

void Loader::buildTopLevelSampler(const std::shared_ptr<XmlFile>& file, const pugi::xml_node& node) {
  // Mitsuba makes a top-level <sampler> like any object: a sensor uses it through <ref id>, and
  // without a reference it has no effect. Its parameters are checked here either way.
  const Element e = parseElement(file, node);
  if (e.type.empty()) e.fail("missing attribute 'type'");
  Scene settings;
  buildSampler(*this, e, settings);
  Named& n = registerId(e, Kind::Sampler);
  n.sampler = settings.sampler;
}

void Loader::buildSensor(const std::shared_ptr<XmlFile>& file, const pugi::xml_node& node) {
  const Element e = parseElement(file, node);
  if (e.type.empty()) e.fail("missing attribute 'type'");
  if (e.type != "perspective") {
    unsupported(e.where() + ": unknown plugin '" + e.type + "'");
    return;
  }
  if (sensors_++ > 0) {
    unsupported(e.where() + ": only one sensor is supported (the first one is used)");
    return;
  }
  Camera& cam = scene_.camera;
  const FieldOfView fov = readFieldOfView(e);
  cam.fovDegrees = fov.degrees;
  cam.fovAxis = fov.axis;
  // Read and without effect, as in Mitsuba's perspective sensor: a pinhole has no focus, and a
  // static scene does not depend on the shutter interval.
  e.located([&] { return e.props.getFloat("focus_distance", 0.0f); });
  e.located([&] { return e.props.getFloat("shutter_open", 0.0f); });
  e.located([&] { return e.props.getFloat("shutter_close", 0.0f); });
  // Principal point offset, in fractions of the film size (Mitsuba adds it to the film sample).
  cam.principalPointOffset = e.located([&] {
    return Vec2(e.props.getFloat("principal_point_offset_x", 0.0f), e.props.getFloat("principal_point_offset_y", 0.0f));
  });
  if (std::fabs(cam.principalPointOffset.x) > 1e3f || std::fabs(cam.principalPointOffset.y) > 1e3f)
    e.fail("'principal_point_offset_x/y' beyond ±1000 film sizes");
  cam.nearClip = e.located([&] { return e.props.getFloat("near_clip", 1e-2f); });
  cam.farClip = e.located([&] { return e.props.getFloat("far_clip", 1e4f); });
  if (!(cam.nearClip > 0.0f)) e.failParam("near_clip", "'near_clip' must be positive");
  if (!(cam.farClip > cam.nearClip)) e.failParam("far_clip", "'far_clip' must exceed 'near_clip'");
  cam.toWorld = e.transform("to_world");
  // As Mitsuba 3: the camera frame must be orthonormal up to a mirror; a scale would distort
  // the ray directions. Tolerance 1e-3 on squared column lengths, Mitsuba's has_scale() test.
  for (int c = 0; c < 3; ++c)
    if (std::fabs(glm::dot(Vec3(cam.toWorld[c]), Vec3(cam.toWorld[c])) - 1.0f) > 1e-3f)
      e.failParam("to_world", "the camera's to_world must not scale");
  for (const pugi::xml_node& child : e.children) {
    const std::string tag = child.name();
    if (tag == "film") buildFilm(*this, parseElement(file, child), scene_.film);
    else if (tag == "sampler") buildSampler(*this, parseElement(file, child), scene_);
    else if (tag == "medium" || (tag == "ref" && resolveRef(file, child).kind == Kind::Medium)) {
      // Mitsuba's sensor takes any medium object among its children as the one it sits in.
      if (scene_.cameraMedium >= 0) throw LocatedError(whereOf(*file, child) + ": the sensor's medium is given twice");
      scene_.cameraMedium = mediumOf(file, child);
    } else if (tag == "ref") useSampler(resolveRef(file, child), file, child);
    else unexpectedChild(e, child);
  }
  checkUnused(e);
}

}  // namespace rc
