#pragma once
// Scenes built in code for the render tests (no dependency on the XML loader): meshes, spheres,
// emitters and BSDFs made through createBsdf with Properties, as the loader would.
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "bsdf/bsdf_factory.h"
#include "common/property_builders.h"
#include "geometry/accel.h"
#include "render/camera.h"
#include "render/integrator.h"
#include "render/light_sampler.h"
#include "render/path_integrator.h"
#include "scene/scene.h"

namespace rc::test {

inline BsdfPtr diffuse(const Color& reflectance) {
  Properties props;
  props.pluginType = "diffuse";
  props.set("reflectance", rgbProp(reflectance));
  return createBsdf(props, {});
}

// Rough conductor with F ≡ 1 (material none), GGX.
inline BsdfPtr roughMirror(float alpha) {
  Properties props;
  props.pluginType = "roughconductor";
  props.set("distribution", stringProp("ggx"));
  props.set("alpha", floatProp(alpha));
  props.set("material", stringProp("none"));
  return createBsdf(props, {});
}

inline int addBsdf(Scene& s, BsdfPtr b) {
  s.bsdfs.push_back(std::move(b));
  return static_cast<int>(s.bsdfs.size() - 1);
}

inline int addEmitter(Scene& s, const Emitter& e) {
  s.emitters.push_back(e);
  return static_cast<int>(s.emitters.size() - 1);
}

inline Emitter areaEmitter(const Color& radiance) {
  Emitter e;
  e.type = EmitterType::Area;
  e.radiance = radiance;
  return e;
}

inline Emitter pointEmitter(const Vec3& position, const Color& intensity) {
  Emitter e;
  e.type = EmitterType::Point;
  e.position = position;
  e.intensity = intensity;
  return e;
}

inline Emitter constantEmitter(const Color& radiance) {
  Emitter e;
  e.type = EmitterType::Constant;
  e.radiance = radiance;
  return e;
}

// Quad p0,p1,p2,p3 (counter-clockwise seen from the side its normal points to).
inline Mesh quad(const Vec3& p0, const Vec3& p1, const Vec3& p2, const Vec3& p3, int bsdf, int emitter = -1) {
  Mesh m;
  m.name = "quad";
  m.positions = {p0, p1, p2, p3};
  m.triangles = {glm::uvec3(0, 1, 2), glm::uvec3(0, 2, 3)};
  m.bsdf = bsdf;
  m.emitter = emitter;
  return m;
}

// The six inward-facing walls of the box [lo, hi], one mesh per wall.
inline std::vector<Mesh> insideOfBox(const Vec3& lo, const Vec3& hi, int bsdf, int emitter = -1) {
  const Vec3 c[8] = {{lo.x, lo.y, lo.z}, {hi.x, lo.y, lo.z}, {hi.x, hi.y, lo.z}, {lo.x, hi.y, lo.z},
                     {lo.x, lo.y, hi.z}, {hi.x, lo.y, hi.z}, {hi.x, hi.y, hi.z}, {lo.x, hi.y, hi.z}};
  return {
      quad(c[0], c[1], c[2], c[3], bsdf, emitter),  // z = lo, normal +z
      quad(c[4], c[7], c[6], c[5], bsdf, emitter),  // z = hi, normal −z
      quad(c[0], c[4], c[5], c[1], bsdf, emitter),  // y = lo, normal +y
      quad(c[3], c[2], c[6], c[7], bsdf, emitter),  // y = hi, normal −y
      quad(c[0], c[3], c[7], c[4], bsdf, emitter),  // x = lo, normal +x
      quad(c[1], c[5], c[6], c[2], bsdf, emitter),  // x = hi, normal −x
  };
}

// A ray from o through target (unit direction).
inline Ray rayAt(const Vec3& o, const Vec3& target) {
  Ray r;
  r.o = o;
  r.d = glm::normalize(target - o);
  return r;
}

// Mitsuba's look_at: columns (left, up, dir, origin).
inline Mat4 lookAt(const Vec3& origin, const Vec3& target, const Vec3& up) {
  const Vec3 dir = glm::normalize(target - origin);
  const Vec3 left = glm::normalize(glm::cross(up, dir));
  const Vec3 newUp = glm::cross(dir, left);
  Mat4 m(1.0f);
  m[0] = Vec4(left, 0);
  m[1] = Vec4(newUp, 0);
  m[2] = Vec4(dir, 0);
  m[3] = Vec4(origin, 1);
  return m;
}

// A small Cornell-like box: white floor/ceiling/back, red left, green right, a white sphere and a
// square light under the ceiling. Camera looks into the open front.
inline Scene cornellLike(int width, int height) {
  Scene s;
  const int white = addBsdf(s, diffuse(Color(0.75f)));
  const int red = addBsdf(s, diffuse(Color(0.75f, 0.1f, 0.1f)));
  const int green = addBsdf(s, diffuse(Color(0.1f, 0.75f, 0.1f)));
  const int glossy = addBsdf(s, roughMirror(0.3f));
  const int light = addEmitter(s, areaEmitter(Color(15.0f)));
  const Vec3 lo(-1, 0, -1), hi(1, 2, 1);
  auto walls = insideOfBox(lo, hi, white);
  walls[4].bsdf = red;    // x = −1
  walls[5].bsdf = green;  // x = +1
  walls[0].bsdf = glossy;  // back wall z = −1
  for (int i : {0, 2, 3, 4, 5}) s.meshes.push_back(walls[i]);  // no front wall (z = +1)
  // Light: faces down (−y), slightly below the ceiling.
  s.meshes.push_back(quad({-0.25f, 1.98f, -0.25f}, {0.25f, 1.98f, -0.25f}, {0.25f, 1.98f, 0.25f}, {-0.25f, 1.98f, 0.25f},
                          white, light));
  Sphere sp;
  sp.name = "ball";
  sp.center = Vec3(0.3f, 0.4f, -0.2f);
  sp.radius = 0.4f;
  sp.bsdf = white;
  s.spheres.push_back(sp);
  s.camera.toWorld = lookAt({0, 1, 3.6f}, {0, 1, 0}, {0, 1, 0});
  s.camera.fovDegrees = 40.0f;
  s.film.width = width;
  s.film.height = height;
  s.film.filter = "box";
  s.sampler.sampleCount = 4;
  return s;
}

// Running mean and standard error per channel of Monte Carlo estimates (Welford).
struct Stat {
  double mean[3] = {0, 0, 0}, m2[3] = {0, 0, 0};
  int n = 0;
  void add(const Color& c) {
    ++n;
    for (int k = 0; k < 3; ++k) {
      const double d = c[k] - mean[k];
      mean[k] += d / n;
      m2[k] += d * (c[k] - mean[k]);
    }
  }
  double stderr_(int k) const { return std::sqrt(m2[k] / (n - 1) / n); }
};

struct World {
  Scene scene;
  std::unique_ptr<Accel> accel;
  std::unique_ptr<LightSampler> lights;
  explicit World(Scene s) : scene(std::move(s)) {
    accel = std::make_unique<Accel>(scene);
    lights = std::make_unique<LightSampler>(scene);
  }
  RenderContext context() const { return RenderContext{scene, *accel, *lights, {}, nullptr, {}}; }
  // The surface hits (with a material) of the pixel centres of a size×size view of the world's camera.
  std::vector<Hit> pixelCentreHits(int size) const {
    const CameraModel camera(scene.camera, size, size);
    std::vector<Hit> hits;
    for (int y = 0; y < size; ++y)
      for (int x = 0; x < size; ++x) {
        const Hit h = accel->intersect(camera.generate(Vec2(x + 0.5f, y + 0.5f)));
        if (h.valid() && h.bsdf >= 0) hits.push_back(h);
      }
    return hits;
  }
  // The path tracer's image of this world with the given options (spp, seed, sampler, adaptive…).
  Image renderPath(const RenderOptions& options, RenderStats* statsOut = nullptr) const {
    RenderContext ctx = context();
    ctx.options = options;
    RenderStats stats;
    Image img = makePathIntegrator(scene.integrator)->render(ctx, stats);
    if (statsOut) *statsOut = stats;
    return img;
  }
};

}  // namespace rc::test
