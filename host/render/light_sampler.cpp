#include "render/light_sampler.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "geometry/face_normal.h"
#include "render/distribution.h"
#include "render/envmap_light.h"
#include "render/spot_light.h"

namespace rc {

namespace {

// Uniform direction on the unit sphere.
Vec3 uniformSphere(Vec2 u) {
  const float z = 1.0f - 2.0f * u.x;
  const float r = std::sqrt(std::max(0.0f, 1.0f - z * z));
  const float phi = 2.0f * kPi * u.y;
  return Vec3(r * std::cos(phi), r * std::sin(phi), z);
}

struct Entry {
  EmitterType type;
  int emitter = -1;
  // area on a mesh
  int mesh = -1;
  Distribution1D triangles;
  std::vector<Vec3> normals;  // orientedFaceNormal per triangle (computed once, not per sample)
  double area = 0.0;
  Vec3 boundCenter{0.0f};  // bounding sphere of an area emitter (solidAngleBound)
  float boundRadius = 0.0f;
  // area on a sphere
  int sphere = -1;
  std::shared_ptr<const EnvmapLight> envmap;
};

}  // namespace

struct LightSampler::Impl {
  const Scene& scene;
  const std::vector<Emitter>& emitters;  // scene.emitters, or a same-indexed replacement
  std::vector<Entry> entries;
  Distribution1D select;
  std::vector<int> meshEntry, sphereEntry;  // shape → entry (area emitters), −1
  std::vector<int> infinite;                // entries of constant/envmap emitters

  Impl(const Scene& s, const std::vector<Emitter>& em) : scene(s), emitters(em) {}

  float selectProb(int e) const { return static_cast<float>(select.probability(static_cast<size_t>(e))); }

  // Radiance and density (selection included) of all infinite emitters along dir, summed in entry
  // order; entry `known` (an envmap just sampled toward dir) contributes *knownValue instead of
  // being looked up again.
  // A constant environment's light-sampling density (uniform over the sphere, times its selection).
  float constantPdf(int k) const { return selectProb(k) * (1.0f / (4.0f * kPi)); }

  EnvironmentLookup environmentAt(const Vec3& dir, int known = -1, const EnvmapLight::Lookup* knownValue = nullptr) const {
    EnvironmentLookup out;
    for (int k : infinite) {
      const Entry& e = entries[k];
      if (e.type == EmitterType::Constant) {
        out.radiance += emitters[e.emitter].radiance;
        out.pdf += constantPdf(k);
      } else {
        const EnvmapLight::Lookup v = k == known ? *knownValue : e.envmap->lookup(dir);
        out.radiance += v.radiance;
        out.pdf += selectProb(k) * v.pdf;
      }
    }
    return out;
  }
};

LightSampler::LightSampler(const Scene& scene) : LightSampler(scene, scene.emitters) {}

namespace {

// Radius of the scene's bounding sphere: infinite lights' power is measured through a disc of it.
double sceneRadius(const Scene& scene, const std::vector<Emitter>& emitters) {
  Vec3 lo(INFINITY), hi(-INFINITY);
  for (const Mesh& m : scene.meshes)
    for (const Vec3& p : m.positions) lo = glm::min(lo, p), hi = glm::max(hi, p);
  for (const Sphere& s : scene.spheres) lo = glm::min(lo, s.center - s.radius), hi = glm::max(hi, s.center + s.radius);
  for (const Emitter& e : emitters)
    if (e.type == EmitterType::Point || e.type == EmitterType::Spot || e.type == EmitterType::Projector) lo = glm::min(lo, e.position), hi = glm::max(hi, e.position);
  return lo.x <= hi.x ? std::max(1e-6, 0.5 * static_cast<double>(glm::length(hi - lo))) : 1.0;
}

// An area emitter on a mesh: triangles by area, their normals, its bounding sphere. Empty area →
// no entry (std::nullopt).
std::optional<Entry> meshEntry(const Mesh& mesh, int meshIndex) {
  Entry e;
  e.type = EmitterType::Area;
  e.emitter = mesh.emitter;
  e.mesh = meshIndex;
  std::vector<double> areas(mesh.triangles.size());
  for (size_t t = 0; t < mesh.triangles.size(); ++t) {
    const glm::uvec3 tri = mesh.triangles[t];
    const glm::dvec3 p0(mesh.positions[tri.x]), p1(mesh.positions[tri.y]), p2(mesh.positions[tri.z]);
    areas[t] = 0.5 * glm::length(glm::cross(p1 - p0, p2 - p0));
    e.area += areas[t];
    e.normals.push_back(orientedFaceNormal(mesh, t));
  }
  e.triangles = Distribution1D(areas);
  if (!(e.area > 0.0)) return std::nullopt;
  Vec3 lo(INFINITY), hi(-INFINITY);
  for (const glm::uvec3& tri : mesh.triangles)
    for (int k = 0; k < 3; ++k) lo = glm::min(lo, mesh.positions[tri[k]]), hi = glm::max(hi, mesh.positions[tri[k]]);
  e.boundCenter = 0.5f * (lo + hi);
  e.boundRadius = 0.5f * glm::length(hi - lo);
  return e;
}

}  // namespace

LightSampler::LightSampler(const Scene& scene, const std::vector<Emitter>& emitters)
    : impl_(std::make_unique<Impl>(scene, emitters)) {
  if (emitters.size() != scene.emitters.size()) throw Error("light sampler: emitter list does not match the scene");
  Impl& im = *impl_;
  im.meshEntry.assign(scene.meshes.size(), -1);
  im.sphereEntry.assign(scene.spheres.size(), -1);
  std::vector<double> power;
  auto addEntry = [&](Entry&& e, double p) {
    im.entries.push_back(std::move(e));
    power.push_back(p);
    return static_cast<int>(im.entries.size() - 1);
  };
  // Area emitters: found from the shapes that carry them.
  for (size_t m = 0; m < scene.meshes.size(); ++m) {
    const Mesh& mesh = scene.meshes[m];
    if (mesh.emitter < 0 || mesh.triangles.empty()) continue;
    if (mesh.emitter >= static_cast<int>(emitters.size())) throw Error("mesh '" + mesh.name + "': bad emitter index");
    std::optional<Entry> e = meshEntry(mesh, static_cast<int>(m));
    if (!e) continue;
    const double p = kPiD * e->area * luminance(emitters[mesh.emitter].radiance);
    im.meshEntry[m] = addEntry(std::move(*e), p);
  }
  for (size_t s = 0; s < scene.spheres.size(); ++s) {
    const Sphere& sp = scene.spheres[s];
    if (sp.emitter < 0) continue;
    if (sp.emitter >= static_cast<int>(emitters.size())) throw Error("sphere '" + sp.name + "': bad emitter index");
    Entry e;
    e.type = EmitterType::Area;
    e.emitter = sp.emitter;
    e.sphere = static_cast<int>(s);
    e.boundCenter = sp.center;
    e.boundRadius = sp.radius;
    const double area = 4.0 * kPiD * sp.radius * sp.radius;
    im.sphereEntry[s] = addEntry(std::move(e), kPiD * area * luminance(emitters[sp.emitter].radiance));
  }
  const double r = sceneRadius(scene, emitters), discArea = kPiD * r * r;
  for (size_t i = 0; i < emitters.size(); ++i) {
    const Emitter& em = emitters[i];
    Entry e;
    e.type = em.type;
    e.emitter = static_cast<int>(i);
    if (em.type == EmitterType::Point) addEntry(std::move(e), 4.0 * kPiD * luminance(em.intensity));
    // A spot's power: its cone at full intensity (an upper bound is enough for light selection).
    else if (em.type == EmitterType::Spot)
      addEntry(std::move(e), 2.0 * kPiD * (1.0 - em.spotCosCutoff) * luminance(em.intensity) *
                                 (em.projection ? luminance(em.projection->mean()) : 1.0));
    // A projector's power: π·scale·(mean image irradiance)·(image area on the z = 1 plane).
    else if (em.type == EmitterType::Projector)
      addEntry(std::move(e), kPiD * em.scale * luminance(em.projection ? em.projection->mean() : em.irradiance) * 4.0 /
                                 (double(em.projectorCot) * em.projectorCot * em.projectorAspect));
    else if (em.type == EmitterType::Directional) addEntry(std::move(e), discArea * luminance(em.irradiance));
    else if (em.type == EmitterType::Constant)
      im.infinite.push_back(addEntry(std::move(e), discArea * kPiD * luminance(em.radiance)));
    else if (em.type == EmitterType::Envmap) {
      if (em.envWidth <= 0 || em.envHeight <= 0 ||
          em.envPixels.size() != static_cast<size_t>(em.envWidth) * em.envHeight)
        throw Error("envmap '" + em.filename + "': image not loaded");
      e.envmap = std::make_shared<const EnvmapLight>(em.envWidth, em.envHeight, em.envPixels, em.scale, Mat3(em.toWorld));
      const double meanLum = e.envmap->meanLuminance();
      im.infinite.push_back(addEntry(std::move(e), discArea * kPiD * meanLum));
    }  // area emitters are handled with their shapes
  }
  if (!im.entries.empty()) im.select = Distribution1D(power);
}

LightSampler::~LightSampler() = default;

float LightSampler::solidAngleBound(const Vec3& p) const {
  const Impl& im = *impl_;
  if (!im.infinite.empty()) return 4.0f * kPi;
  // Called per shading point: with many emitters (a mesh per emissive panel of a big room) the sum
  // would cost more than the ray it saves, so beyond kMaxBoundedEmitters the answer is "not small".
  constexpr size_t kMaxBoundedEmitters = 16;
  if (im.entries.size() > kMaxBoundedEmitters) return 4.0f * kPi;
  float total = 0.0f;
  for (const Entry& e : im.entries) {
    if (e.type != EmitterType::Area) continue;  // point and directional lights subtend none
    const float d2 = glm::dot(p - e.boundCenter, p - e.boundCenter), r2 = e.boundRadius * e.boundRadius;
    if (!(d2 > r2)) return 4.0f * kPi;
    // Cap of a sphere of radius r seen from distance d: 2π(1 − √(1 − r²/d²)).
    total += 2.0f * kPi * (1.0f - std::sqrt(1.0f - r2 / d2));
  }
  return total;
}

const std::vector<Emitter>& LightSampler::emitters() const { return impl_->emitters; }
bool LightSampler::empty() const { return impl_->entries.empty(); }
size_t LightSampler::emitterCount() const { return impl_->entries.size(); }
bool LightSampler::hasEnvironment() const { return !impl_->infinite.empty(); }

namespace {

// The segment from a shading point to a light point and its length (computed once per sample:
// the density and the light sample both need it).
struct ToLight {
  Vec3 v;
  float dist2, dist;
  ToLight(const Vec3& p, const Vec3& q) : v(q - p), dist2(glm::dot(v, v)), dist(std::sqrt(dist2)) {}
};

// Area light at point q with normal n, seen along `to`, sampled with solid-angle density
// pdfSolidNoSel (emitter selection pSel not included): the light sample, empty when it carries nothing.
inline std::optional<LightSample> areaSample(const Vec3& q, const Vec3& n, const ToLight& to, float pdfSolidNoSel,
                                             float pSel, const Color& radiance) {
  LightSample ls;
  if (!(to.dist2 > 0.0f)) return std::nullopt;
  const float dist = to.dist;
  ls.wi = to.v / dist;
  ls.dist = dist;
  if (!(glm::dot(n, -ls.wi) > 0.0f)) return std::nullopt;  // emits toward +n only
  ls.pdf = pdfSolidNoSel * pSel;
  if (!(ls.pdf > 0.0f) || !std::isfinite(ls.pdf)) return std::nullopt;
  ls.radiance = radiance / ls.pdf;
  ls.lightPoint = q;
  ls.lightNormal = n;
  return ls;
}

// A uniform point on a mesh emitter's area (triangle by area).
std::optional<LightSample> sampleMesh(const Mesh& mesh, const Entry& e, const Vec3& p, Vec2 u, float pSel,
                                      const Color& radiance) {
  float ux;
  const size_t t = e.triangles.sample(u.x, &ux);
  const glm::uvec3 tri = mesh.triangles[t];
  const float su = std::sqrt(ux);
  const float b0 = 1.0f - su, b1 = u.y * su;
  const Vec3 q = b0 * mesh.positions[tri.x] + b1 * mesh.positions[tri.y] + (1.0f - b0 - b1) * mesh.positions[tri.z];
  const Vec3 n = e.normals[t];
  const ToLight to(p, q);
  const float cosL = std::fabs(glm::dot(n, to.v)) / to.dist;
  return areaSample(q, n, to, static_cast<float>(to.dist2 / (e.area * cosL)), pSel, radiance);
}

// A sphere emitter: uniform in the cone of directions that see it from outside, uniform on its
// area from inside (or on) it.
std::optional<LightSample> sampleSphere(const Sphere& s, const Vec3& p, Vec2 u, float pSel, const Color& radiance) {
  const Vec3 toCenter = s.center - p;
  const float dc2 = glm::dot(toCenter, toCenter);
  const float r2 = s.radius * s.radius;
  if (dc2 > r2 * 1.0001f) {
    const float dc = std::sqrt(dc2);
    const float sin2Max = r2 / dc2;
    const float cosMax = std::sqrt(std::max(0.0f, 1.0f - sin2Max));
    const float oneMinusCosMax = sin2Max / (1.0f + cosMax);  // no cancellation for small cones
    const float cosT = 1.0f - u.x * oneMinusCosMax;
    const float sinT = std::sqrt(std::max(0.0f, 1.0f - cosT * cosT));
    const float phi = 2.0f * kPi * u.y;
    const Frame f = Frame::fromNormal(toCenter / dc);
    const Vec3 w = f.toWorld(Vec3(sinT * std::cos(phi), sinT * std::sin(phi), cosT));
    // Distance to the near intersection along w (clamped at the silhouette).
    const float ds = dc * cosT - std::sqrt(std::max(0.0f, r2 - dc2 * sinT * sinT));
    const Vec3 q = p + ds * w;
    Vec3 n = glm::normalize(q - s.center);
    if (s.flipNormals) n = -n;
    return areaSample(q, n, ToLight(p, q), 1.0f / (2.0f * kPi * oneMinusCosMax), pSel, radiance);
  }
  const Vec3 dirOut = uniformSphere(u);
  const Vec3 q = s.center + s.radius * dirOut;
  const Vec3 n = s.flipNormals ? -dirOut : dirOut;
  const ToLight to(p, q);
  const float cosL = std::fabs(glm::dot(n, to.v)) / to.dist;
  return areaSample(q, n, to, to.dist2 / (4.0f * kPi * r2 * cosL), pSel, radiance);
}

std::optional<LightSample> samplePoint(const Emitter& em, const Vec3& p, float pSel) {
  LightSample ls;
  const Vec3 toLight = em.position - p;
  const float dist2 = glm::dot(toLight, toLight);
  if (!(dist2 > 0.0f)) return std::nullopt;
  ls.dist = std::sqrt(dist2);
  ls.wi = toLight / ls.dist;
  ls.delta = true;
  ls.pdf = 0.0f;
  if (em.type == EmitterType::Projector) {
    ls.radiance = projectorEmission(em, p) / pSel;
  } else {
    const Color profile = em.type == EmitterType::Spot ? spotProfile(em, -ls.wi) : Color(1.0f);
    ls.radiance = em.intensity * profile / (dist2 * pSel);
  }
  if (!(ls.radiance.r > 0.0f || ls.radiance.g > 0.0f || ls.radiance.b > 0.0f)) return std::nullopt;
  ls.lightPoint = em.position;
  return ls;
}

// An infinite light's sample toward wi, weighted by the density summed over all infinite
// emitters (MIS-consistent with environmentPdf).
std::optional<LightSample> infiniteSample(const Vec3& wi, const LightSampler::EnvironmentLookup& env) {
  if (!(env.pdf > 0.0f) || !std::isfinite(env.pdf)) return std::nullopt;
  LightSample ls;
  ls.wi = wi;
  ls.pdf = env.pdf;
  ls.radiance = env.radiance / env.pdf;
  return ls;
}

}  // namespace

std::optional<LightSample> LightSampler::sample(const Vec3& p, Vec2 u, float uLight) const {
  const Impl& im = *impl_;
  if (im.entries.empty()) return std::nullopt;
  const int k = static_cast<int>(im.select.sample(uLight));
  const float pSel = im.selectProb(k);
  if (!(pSel > 0.0f)) return std::nullopt;
  const Entry& e = im.entries[k];
  const Emitter& em = im.emitters[e.emitter];
  switch (e.type) {
    case EmitterType::Area:
      if (e.mesh >= 0) return sampleMesh(im.scene.meshes[e.mesh], e, p, u, pSel, em.radiance);
      return sampleSphere(im.scene.spheres[e.sphere], p, u, pSel, em.radiance);
    case EmitterType::Point:
    case EmitterType::Spot:
    case EmitterType::Projector:
      return samplePoint(em, p, pSel);
    case EmitterType::Directional: {
      LightSample ls;
      ls.wi = -glm::normalize(em.direction);
      ls.delta = true;
      ls.radiance = em.irradiance / pSel;
      return ls;
    }
    case EmitterType::Constant: {
      const Vec3 wi = uniformSphere(u);
      return infiniteSample(wi, im.environmentAt(wi));
    }
    case EmitterType::Envmap: {
      const EnvmapLight::Sample s = e.envmap->sample(u);
      if (!(s.value.pdf > 0.0f)) return std::nullopt;
      return infiniteSample(s.dir, im.environmentAt(s.dir, k, &s.value));
    }
  }
  return std::nullopt;
}

float LightSampler::pdf(const Hit& lightHit, const Vec3& from) const {
  const Impl& im = *impl_;
  if (!lightHit.valid() || lightHit.emitter < 0) return 0.0f;
  int k = -1;
  if (lightHit.mesh >= 0) k = im.meshEntry[lightHit.mesh];
  else if (lightHit.sphere >= 0) k = im.sphereEntry[lightHit.sphere];
  if (k < 0) return 0.0f;
  const float pSel = im.selectProb(k);
  const Entry& e = im.entries[k];
  const Vec3 toLight = lightHit.p - from;
  const float dist2 = glm::dot(toLight, toLight);
  if (!(dist2 > 0.0f)) return 0.0f;
  const float cosL = std::fabs(glm::dot(lightHit.ng, toLight)) / std::sqrt(dist2);
  if (!(cosL > 0.0f)) return 0.0f;
  if (e.mesh >= 0) return pSel * static_cast<float>(dist2 / (e.area * cosL));
  const Sphere& s = im.scene.spheres[e.sphere];
  const Vec3 toCenter = s.center - from;
  const float dc2 = glm::dot(toCenter, toCenter), r2 = s.radius * s.radius;
  if (dc2 > r2 * 1.0001f) {
    const float sin2Max = r2 / dc2;
    const float cosMax = std::sqrt(std::max(0.0f, 1.0f - sin2Max));
    return pSel / (2.0f * kPi * (sin2Max / (1.0f + cosMax)));
  }
  return pSel * dist2 / (4.0f * kPi * r2 * cosL);
}

Color LightSampler::environment(const Vec3& dir) const {
  // Radiance alone (what an escaping camera ray needs): the envmaps' densities are not looked up.
  Color radiance(0.0f);
  for (int k : impl_->infinite) {
    const Entry& e = impl_->entries[k];
    radiance += e.type == EmitterType::Constant ? impl_->emitters[e.emitter].radiance : e.envmap->eval(dir);
  }
  return radiance;
}
float LightSampler::environmentPdf(const Vec3& dir) const { return impl_->environmentAt(dir).pdf; }
LightSampler::EnvironmentLookup LightSampler::environmentLookup(const Vec3& dir) const {
  return impl_->environmentAt(dir);
}

void LightSampler::EnvironmentWave::fit(size_t n) {
  for (std::vector<float>* v : {&x, &y, &z, &r, &g, &b, &pdf})
    if (v->size() < n) v->resize(n);
}

void LightSampler::environmentLookups(EnvironmentWave& w, size_t n, bool withPdf) const {
  // environmentAt's sums, in its order of entries, one entry at a time over all directions.
  const Impl& im = *impl_;
  std::fill_n(w.r.begin(), n, 0.0f);
  std::fill_n(w.g.begin(), n, 0.0f);
  std::fill_n(w.b.begin(), n, 0.0f);
  std::fill_n(w.pdf.begin(), n, 0.0f);
  for (int k : im.infinite) {
    const Entry& e = im.entries[k];
    if (e.type == EmitterType::Envmap) {
      e.envmap->lookupAdd(w.x.data(), w.y.data(), w.z.data(), n, im.selectProb(k), w.r.data(), w.g.data(), w.b.data(),
                          withPdf ? w.pdf.data() : nullptr);
      continue;
    }
    const Color radiance = im.emitters[e.emitter].radiance;
    const float pdf = im.constantPdf(k);
    for (size_t j = 0; j < n; ++j) {
      w.r[j] += radiance.r;
      w.g[j] += radiance.g;
      w.b[j] += radiance.b;
      if (withPdf) w.pdf[j] += pdf;
    }
  }
}

}  // namespace rc
