#pragma once
// Small programmatic scenes and a render helper for the cache tests (no scene files needed, so
// these tests pin the integrator, not the parser). A Cornell-like box: glossy (or diffuse) floor,
// coloured diffuse walls, a square area light under the ceiling, camera looking in.
#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "bsdf/bsdf_factory.h"
#include "cache/rcache_integrator.h"
#include "cl/sh_backend.h"
#include "common/property_builders.h"
#include "core/properties.h"
#include "geometry/accel.h"
#include "render/direct_integrator.h"
#include "render/integrator.h"
#include "render/light_sampler.h"
#include "render/path_integrator.h"
#include "scene/param_reader.h"
#include "scene/scene.h"

namespace rc::test {

inline BsdfPtr diffuse(float r, float g, float b) {
  Properties props;
  props.pluginType = "diffuse";
  props.set("reflectance", rgbProp(r, g, b));
  return createBsdf(props, {});
}

// "plastic" (alpha unused) or "roughplastic" (GGX α) over a diffuse base of reflectance `base`.
inline BsdfPtr layeredPlastic(const std::string& type, float alpha, Color base) {
  Properties props;
  props.pluginType = type;
  if (type == "roughplastic") {
    props.set("distribution", stringProp("ggx"));
    props.set("alpha", floatProp(alpha));
  }
  props.set("diffuse_reflectance", rgbProp(base.r, base.g, base.b));
  return createBsdf(props, {});
}

// alpha ≤ 0 → diffuse grey floor instead.
inline BsdfPtr glossy(float alpha) {
  Properties props;
  props.pluginType = "roughconductor";
  props.set("distribution", stringProp("ggx"));
  props.set("alpha", floatProp(alpha));
  props.set("material", stringProp("none"));
  props.set("specular_reflectance", rgbProp(0.8f, 0.8f, 0.8f));
  return createBsdf(props, {});
}

// Quad p0,p1,p2,p3 (counter-clockwise seen from the side its normal faces).
inline void addQuad(Scene& s, Vec3 p0, Vec3 p1, Vec3 p2, Vec3 p3, int bsdf, int emitter = -1) {
  Mesh m;
  m.name = "quad#" + std::to_string(s.meshes.size());
  m.positions = {p0, p1, p2, p3};
  m.triangles = {glm::uvec3(0, 1, 2), glm::uvec3(0, 2, 3)};
  m.bsdf = bsdf;
  m.emitter = emitter;
  s.meshes.push_back(m);
}

// The test scenes' camera and film: Mitsuba look-at from eye to target (+y up, local +z the view
// direction), 45° fov, box filter, 1 spp, max_depth 3.
inline void setTestCamera(Scene& s, Vec3 eye, Vec3 target, int width, int height) {
  const Vec3 up(0, 1, 0);
  const Vec3 dir = glm::normalize(target - eye);
  const Vec3 left = glm::normalize(glm::cross(up, dir));
  const Vec3 newUp = glm::cross(dir, left);
  s.camera.toWorld = Mat4(Vec4(left, 0), Vec4(newUp, 0), Vec4(dir, 0), Vec4(eye, 1));
  s.camera.fovDegrees = 45.0f;
  s.film.width = width;
  s.film.height = height;
  s.film.filter = "box";
  s.sampler.sampleCount = 1;
  s.integrator.maxDepth = 3;
}

// Box [-1,1]×[0,2]×[-1,1] open toward +z where the camera stands; floor at y = 0.
inline Scene boxScene(float floorAlpha, int width = 32, int height = 24) {
  Scene s;
  s.bsdfs.push_back(floorAlpha > 0 ? glossy(floorAlpha) : diffuse(0.6f, 0.6f, 0.6f));  // 0 floor
  s.bsdfs.push_back(diffuse(0.7f, 0.1f, 0.1f));                                          // 1 red
  s.bsdfs.push_back(diffuse(0.1f, 0.6f, 0.1f));                                          // 2 green
  s.bsdfs.push_back(diffuse(0.7f, 0.7f, 0.2f));                                          // 3 yellow
  s.bsdfs.push_back(diffuse(0.0f, 0.0f, 0.0f));                                          // 4 light body
  addQuad(s, {-1, 0, 1}, {1, 0, 1}, {1, 0, -1}, {-1, 0, -1}, 0);     // floor, normal +y
  addQuad(s, {-1, 0, -1}, {1, 0, -1}, {1, 2, -1}, {-1, 2, -1}, 3);   // back wall, +z
  addQuad(s, {-1, 0, 1}, {-1, 0, -1}, {-1, 2, -1}, {-1, 2, 1}, 1);   // left wall, +x
  addQuad(s, {1, 0, -1}, {1, 0, 1}, {1, 2, 1}, {1, 2, -1}, 2);       // right wall, −x
  addQuad(s, {-1, 2, -1}, {1, 2, -1}, {1, 2, 1}, {-1, 2, 1}, 3);     // ceiling, −y
  Emitter light;
  light.type = EmitterType::Area;
  light.radiance = Color(12.0f);
  light.mesh = static_cast<int>(s.meshes.size());
  s.emitters.push_back(light);
  addQuad(s, {-0.3f, 1.98f, -0.3f}, {0.3f, 1.98f, -0.3f}, {0.3f, 1.98f, 0.3f}, {-0.3f, 1.98f, 0.3f}, 4, 0);  // light, −y
  // Camera at z = 3.2 looking toward −z.
  setTestCamera(s, Vec3(0, 1, 3.2f), Vec3(0, 0.8f, 0), width, height);
  return s;
}

struct RenderResult {
  Image image;
  RenderStats stats;
};

inline RenderResult renderScene(const Scene& scene, const IntegratorSettings& settings, int spp, uint64_t seed = 0,
                                const std::string& cacheSave = "", const std::string& cacheLoad = "",
                                std::vector<std::string> aovs = {}, AdaptiveSettings adaptive = {}) {
  Accel accel(scene);
  LightSampler lights(scene);
  auto backend = makeScalarBackend();
  RenderOptions opt;
  opt.spp = spp;
  opt.seed = seed;
  opt.aovs = aovs;
  opt.adaptive = adaptive;
  RenderContext ctx{scene, accel, lights, opt};
  std::unique_ptr<Integrator> integ;
  if (settings.type == "path") {
    integ = makePathIntegrator(settings);
  } else if (settings.type == "direct") {
    integ = makeDirectIntegrator(settings);
  } else {
    auto rcache = std::make_unique<RcacheIntegrator>(settings);
    rcache->setBackend(backend.get());
    rcache->setCacheFiles({cacheSave, cacheLoad, false});
    integ = std::move(rcache);
  }
  RenderResult r;
  r.image = integ->render(ctx, r.stats);
  return r;
}

// Block means of an image (16-px blocks for the per-block bias checks against the path tracer).
struct BlockStats {
  std::vector<double> mean;  // per block, per channel: 3 values each
};
inline BlockStats blockMeans(const Image& img, int block) {
  BlockStats b;
  for (int by = 0; by < img.height / block; ++by)
    for (int bx = 0; bx < img.width / block; ++bx) {
      double m[3] = {};
      for (int y = by * block; y < (by + 1) * block; ++y)
        for (int x = bx * block; x < (bx + 1) * block; ++x)
          for (int c = 0; c < 3; ++c) m[c] += img.pixels[static_cast<size_t>(y) * img.width + x][c];
      for (double v : m) b.mean.push_back(v / (block * block));
    }
  return b;
}

// The worst block mean's difference from the reference's, over the tolerance rel·mean + abs of that
// block and channel (< 1: every block agrees).
inline double worstBlockError(const BlockStats& ref, const BlockStats& img, double rel, double abs) {
  double worst = 0.0;
  for (size_t i = 0; i < ref.mean.size(); ++i)
    worst = std::max(worst, std::fabs(img.mean[i] - ref.mean[i]) / (rel * ref.mean[i] + abs));
  return worst;
}

inline IntegratorSettings rcacheSettings(const Scene& s, std::map<std::string, std::string> params = {}) {
  IntegratorSettings is = s.integrator;
  is.type = "rcache";
  for (const auto& [name, value] : params) is.props.set(name, textProperty(value));
  return is;
}
inline IntegratorSettings pathSettings(const Scene& s) {
  IntegratorSettings is = s.integrator;
  is.type = "path";
  return is;
}

// A text statistic of a render ("" when absent).
inline std::string statText(const RenderStats& st, const std::string& key) {
  for (const auto& [k, v] : st.texts)
    if (k == key) return v;
  return "";
}

// A synthetic sky envmap of kEnvW×kEnvH texels: luminance rising toward the zenith, dark ground
// below the horizon, optionally a sun (a 2×2-texel block `sunLum` bright, 30° above the horizon).
constexpr int kEnvW = 64, kEnvH = 33;
inline std::vector<Color> skyTexels(float sunLum) {
  std::vector<Color> px(static_cast<size_t>(kEnvW) * kEnvH);
  for (int y = 0; y < kEnvH; ++y)
    for (int x = 0; x < kEnvW; ++x) {
      const float cosTheta = std::cos(kPi * y / (kEnvH - 1));
      px[static_cast<size_t>(y) * kEnvW + x] =
          cosTheta > 0.0f ? Color(0.6f, 0.8f, 1.2f) * (0.5f + cosTheta) : Color(0.08f, 0.07f, 0.06f);
    }
  if (sunLum > 0.0f)
    for (int y = 10; y < 12; ++y)
      for (int x = 20; x < 22; ++x) px[static_cast<size_t>(y) * kEnvW + x] = Color(sunLum);
  return px;
}
inline Emitter skyEmitter(float sunLum) {
  Emitter e;
  e.type = EmitterType::Envmap;
  e.filename = "synthetic-sky";
  e.envWidth = kEnvW;
  e.envHeight = kEnvH;
  e.envPixels = skyTexels(sunLum);
  return e;
}

// A sphere of material `bsdf`.
inline void addSphere(Scene& s, const std::string& name, Vec3 center, float radius, int bsdf) {
  Sphere sp;
  sp.name = name;
  sp.center = center;
  sp.radius = radius;
  sp.bsdf = bsdf;
  s.spheres.push_back(sp);
}

// A floor (material 0) and two spheres (materials 1 and 2) under the synthetic sky with a sun, seen
// from above at res×res; `s` brings the three materials.
inline Scene twoSpheresUnderSky(Scene s, const std::string& sphere1, const std::string& sphere2, int res) {
  addQuad(s, {-4, 0, 4}, {4, 0, 4}, {4, 0, -4}, {-4, 0, -4}, 0);
  addSphere(s, sphere1, Vec3(-0.55f, 0.5f, 0.0f), 0.5f, 1);
  addSphere(s, sphere2, Vec3(0.6f, 0.4f, 0.3f), 0.4f, 2);
  s.emitters.push_back(skyEmitter(400.0f));
  setTestCamera(s, Vec3(0, 1.6f, 3.2f), Vec3(0, 0.3f, 0), res, res);
  return s;
}

}  // namespace rc::test
