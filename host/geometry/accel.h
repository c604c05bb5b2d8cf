#pragma once
// Ray-scene intersection over an Embree 3 BVH (triangle meshes, analytic spheres and cylinders as
// user geometry, Embree's round curves).
#include <cstdint>
#include <limits>
#include <memory>

#include "core/frame.h"
#include "core/math.h"
#include "scene/scene.h"

namespace rc {

struct Ray {
  Vec3 o{0.0f}, d{0, 0, 1};
  float tMin = 0.0f;
  float tMax = std::numeric_limits<float>::infinity();
};

// Everything shading needs about a hit.
struct Hit {
  float t = std::numeric_limits<float>::infinity();  // inf = miss
  Vec3 p{0.0f};
  Vec3 ng{0, 0, 1};        // geometric normal (unit), as the shape is oriented (not flipped toward ray)
  Vec3 ns{0, 0, 1};        // interpolated shading normal (unit), same side as ng
  Vec3 dpdu{0.0f};         // mesh tangent from uvs when available, else zero
  Vec3 dpdv{0.0f};         // the partial along v, likewise (a bumpmap's frame reads both)
  TexturePoint uv;         // surface coordinates; on a sphere only where its material reads them (textured), else 0;
                           // on a mesh with attributes also its triangle and barycentrics (mesh_attribute)
  int bsdf = -1;
  int emitter = -1;        // area emitter index or -1
  int mesh = -1, sphere = -1, prim = -1;
  int curve = -1;          // index into Scene::curves (prim: its segment), or -1
  float pError = 0.0f;     // absolute bound on the error of p (from the shape's coordinate magnitudes)
  bool valid() const { return t < std::numeric_limits<float>::infinity(); }
  // Shading frame: built from ns (and dpdu when anisotropic materials need it).
  Frame frame() const { return glm::dot(dpdu, dpdu) > 0.0f ? Frame::fromNormalTangent(ns, dpdu) : Frame::fromNormal(ns); }
};

// How a batch of independent (incoherent) rays goes to Embree: one rtcIntersect1/rtcOccluded1 per ray,
// one rtcIntersect1M/rtcOccluded1M stream, or rtcIntersect16/rtcOccluded16 packets of 16 SoA rays.
// All three give the same answers; they differ only in speed (bench/RESULTS.md "Batched core").
enum class BatchQuery { Single, Stream, Packet16 };

class Accel {
 public:
  explicit Accel(const Scene& scene);  // throws rc::Error on Embree failure (with Embree's message)
  ~Accel();
  Accel(const Accel&) = delete;
  Accel& operator=(const Accel&) = delete;

  Hit intersect(const Ray& ray) const;
  bool occluded(const Ray& ray) const;
  // Batched; hits[i].t = inf on miss. coherent: the rays are similar (camera rays of
  // neighbouring samples) and go to Embree as one stream, traced in packets; otherwise one by one.
  void intersect(const Ray* rays, Hit* hits, size_t count, bool coherent = false) const;
  // Batched queries of independent rays (a wave of path segments or shadow rays).
  // occludedBatch: blocked[i] = 1 when something lies on ray i within [tMin, tMax], else 0.
  void intersectBatch(const Ray* rays, Hit* hits, size_t count, BatchQuery query) const;
  void occludedBatch(const Ray* rays, uint8_t* blocked, size_t count, BatchQuery query) const;

  // Offset origin for a ray leaving surface point p with geometric normal ng toward d,
  // robust against self-intersection at any scene scale.
  static Vec3 offsetOrigin(const Vec3& p, const Vec3& ng, const Vec3& d);
  // Preferred: also uses the hit's position error bound (robust where p is near the origin but the
  // shape's coordinates are large).
  static Vec3 offsetOrigin(const Hit& hit, const Vec3& d);
  // Ray leaving a surface hit toward direction d (unit), offset against self-intersection.
  static Ray spawnRay(const Hit& hit, const Vec3& d);
  // Shadow ray from a surface hit to point `target` (stopping just short of it).
  static Ray spawnRayTo(const Hit& hit, const Vec3& target);

  const Scene& scene() const { return scene_; }
  bool robustIntersections() const;  // Embree's robust mode is on (Scene::embreeRobust)
  uint64_t raysTraced() const;           // total rays (intersect + occluded), for statistics
  uint64_t occlusionRaysTraced() const;  // of these, the occlusion (shadow) rays

 private:
  struct Impl;
  // The Hit of Embree's answer (geomID, primID, u, v, tfar) for `ray`.
  Hit hitOf(const Ray& ray, unsigned geomID, unsigned primID, float u, float v, float tfar) const;
  // Closest hits through rtcIntersect1M streams (with Embree's coherent flag when `coherent`).
  void intersectStream(const Ray* rays, Hit* hits, size_t count, bool coherent) const;
  const Scene& scene_;
  std::unique_ptr<Impl> impl_;
};

// The offset of a spawned ray's origin (geometry/offset_origin.cpp explains it). spawnRay is inline:
// every path vertex calls it, and a Ray returned through memory stalls the loads that read it back.
namespace offset {
// 2^-16 · max|p| ≈ 256 float ulps: well above the few ulps of interpolation/intersection error,
// well below any feature size that matters (1.5e-5 relative).
constexpr float kRelativeOffset = 1.0f / 65536.0f;
// Keeps the offset non-zero for p exactly at the origin of a tiny scene (smallest normal float ×2^20).
constexpr float kAbsoluteFloor = 1e-32f;

inline Vec3 offsetBy(const Vec3& p, const Vec3& ng, const Vec3& d, float magnitude) {
  const float side = glm::dot(ng, d) >= 0.0f ? 1.0f : -1.0f;
  return p + ng * (side * magnitude);
}
}  // namespace offset

inline Vec3 Accel::offsetOrigin(const Hit& hit, const Vec3& d) {
  return offset::offsetBy(hit.p, hit.ng, d,
                          std::max({offset::kRelativeOffset * maxAbs(hit.p), 4.0f * hit.pError, offset::kAbsoluteFloor}));
}

inline Ray Accel::spawnRay(const Hit& hit, const Vec3& d) {
  Ray r;
  r.o = offsetOrigin(hit, d);
  r.d = d;
  return r;
}

}  // namespace rc
