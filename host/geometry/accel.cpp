// Embree 3 scene: one triangle geometry per mesh, one user geometry holding every analytic sphere,
// one holding every cylinder (geometry/cylinder_geometry.h), one round-curve geometry per curve
// shape (geometry/curve_geometry.h), one user geometry per sdfgrid (geometry/sdf_grid_geometry.h).
#include "geometry/accel.h"

#include <embree3/rtcore.h>

#include <algorithm>
#include <atomic>
#include <cstring>
#include <mutex>
#include <new>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "core/error.h"
#include "geometry/curve_geometry.h"
#include "geometry/cylinder_geometry.h"
#include "geometry/embree_attach.h"
#include "geometry/face_normal.h"
#include "geometry/ray_counter.h"
#include "geometry/sdf_grid_geometry.h"
#include "geometry/sdf_grid_math.h"
#include "geometry/sphere_intersect.h"
#include "geometry/user_geometry_hit.h"

namespace rc {

namespace {

constexpr float kFloatEps = 5.96046448e-8f;  // 2^-24
// Error bound of a point reconstructed from barycentrics (a handful of roundings) or on a sphere,
// relative to the magnitude of the coordinates involved, with a generous safety factor.
constexpr float kPointErrorUlps = 32.0f;

struct SphereData {
  const std::vector<Sphere>* spheres;
};

void sphereBounds(const RTCBoundsFunctionArguments* args) {
  const auto* data = static_cast<const SphereData*>(args->geometryUserPtr);
  const Sphere& s = (*data->spheres)[args->primID];
  // Pad by a relative ulp margin so the exact surface is always inside the box.
  const float pad = s.radius * (1.0f + 1e-6f) + kPointErrorUlps * kFloatEps * maxAbs(s.center);
  RTCBounds* b = args->bounds_o;
  b->lower_x = s.center.x - pad; b->lower_y = s.center.y - pad; b->lower_z = s.center.z - pad;
  b->upper_x = s.center.x + pad; b->upper_y = s.center.y + pad; b->upper_z = s.center.z + pad;
}

void sphereIntersect(const RTCIntersectFunctionNArguments* args) {
  const auto* data = static_cast<const SphereData*>(args->geometryUserPtr);
  const Sphere& s = (*data->spheres)[args->primID];
  const unsigned N = args->N;
  RTCRayN* ray = RTCRayHitN_RayN(args->rayhit, N);
  RTCHitN* hit = RTCRayHitN_HitN(args->rayhit, N);
  for (unsigned i = 0; i < N; ++i) {
    if (args->valid[i] != -1) continue;
    const Vec3 o(RTCRayN_org_x(ray, N, i), RTCRayN_org_y(ray, N, i), RTCRayN_org_z(ray, N, i));
    const Vec3 d(RTCRayN_dir_x(ray, N, i), RTCRayN_dir_y(ray, N, i), RTCRayN_dir_z(ray, N, i));
    float t;
    if (!intersectSphere(o, d, s.center, s.radius, RTCRayN_tnear(ray, N, i), RTCRayN_tfar(ray, N, i), t)) continue;
    recordUserHit(args, ray, hit, i, t, (o + t * d) - s.center);
  }
}

void sphereOccluded(const RTCOccludedFunctionNArguments* args) {
  const auto* data = static_cast<const SphereData*>(args->geometryUserPtr);
  const Sphere& s = (*data->spheres)[args->primID];
  const unsigned N = args->N;
  RTCRayN* ray = args->ray;
  for (unsigned i = 0; i < N; ++i) {
    if (args->valid[i] != -1) continue;
    const Vec3 o(RTCRayN_org_x(ray, N, i), RTCRayN_org_y(ray, N, i), RTCRayN_org_z(ray, N, i));
    const Vec3 d(RTCRayN_dir_x(ray, N, i), RTCRayN_dir_y(ray, N, i), RTCRayN_dir_z(ray, N, i));
    float t;
    if (intersectSphere(o, d, s.center, s.radius, RTCRayN_tnear(ray, N, i), RTCRayN_tfar(ray, N, i), t))
      RTCRayN_tfar(ray, N, i) = -INFINITY;
  }
}

RTCRay toEmbree(const Ray& r) {
  RTCRay e;
  e.org_x = r.o.x; e.org_y = r.o.y; e.org_z = r.o.z;
  e.dir_x = r.d.x; e.dir_y = r.d.y; e.dir_z = r.d.z;
  e.tnear = r.tMin;
  e.tfar = r.tMax;
  e.time = 0.0f;
  e.mask = 0xFFFFFFFFu;
  e.id = 0;
  e.flags = 0;
  return e;
}

// Per-triangle constants of a mesh, computed once when the BVH is built (they were computed per
// hit: the cross product, normalisation and tangent solve made triangleHit 13 % of a render), side
// by side so that a hit reads them from one place.
struct TriangleConstant {
  Vec3 faceNormal;   // orientedFaceNormal
  float pointError;  // the hit point's error bound (Hit::pError): from the vertices' magnitudes alone
  Vec3 dpdu, dpdv;   // from the uvs, zero when the mesh has none or the map is degenerate
};
using TriangleConstants = std::vector<TriangleConstant>;

// dp/du and dp/dv of a triangle from its uvs; zero when the mesh has none or the map is degenerate.
std::pair<Vec3, Vec3> triangleUvPartials(const Mesh& mesh, const glm::uvec3& tri) {
  const std::pair<Vec3, Vec3> none(Vec3(0.0f), Vec3(0.0f));
  if (mesh.uvs.empty()) return none;
  const Vec3 &p0 = mesh.positions[tri.x], &p1 = mesh.positions[tri.y], &p2 = mesh.positions[tri.z];
  const Vec2 &t0 = mesh.uvs[tri.x], &t1 = mesh.uvs[tri.y], &t2 = mesh.uvs[tri.z];
  const Vec2 duv02 = t0 - t2, duv12 = t1 - t2;
  const Vec3 dp02 = p0 - p2, dp12 = p1 - p2;
  const float det = duv02.x * duv12.y - duv02.y * duv12.x;
  if (!(std::fabs(det) > 1e-12f)) return none;
  const Vec3 dpdu = (duv12.y * dp02 - duv02.y * dp12) / det;
  const Vec3 dpdv = (duv02.x * dp12 - duv12.x * dp02) / det;
  const auto finite = [](const Vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); };
  return finite(dpdu) && finite(dpdv) ? std::make_pair(dpdu, dpdv) : none;
}

// What an Embree geometry is: which kind of shape, and its index in the scene's list of that kind
// (meshes, curves, sdfgrids; all spheres share one geometry, all cylinders another). One table
// lookup per hit picks the Hit's constructor.
struct GeometryRef {
  enum Kind : uint8_t { kMesh, kSpheres, kCylinders, kCurve, kSdfGrid } kind = kMesh;
  int index = -1;
};

void mapGeometry(std::vector<GeometryRef>& table, unsigned id, GeometryRef::Kind kind, int index) {
  if (table.size() <= id) table.resize(id + 1);
  table[id] = GeometryRef{kind, index};
}

TriangleConstants triangleConstants(const Mesh& mesh) {
  TriangleConstants c(mesh.triangles.size());
  for (size_t i = 0; i < mesh.triangles.size(); ++i) {
    const glm::uvec3 tri = mesh.triangles[i];
    c[i].faceNormal = orientedFaceNormal(mesh, i);
    c[i].pointError = kPointErrorUlps * kFloatEps *
                      std::max({maxAbs(mesh.positions[tri.x]), maxAbs(mesh.positions[tri.y]), maxAbs(mesh.positions[tri.z])});
    std::tie(c[i].dpdu, c[i].dpdv) = triangleUvPartials(mesh, tri);
  }
  return c;
}

}  // namespace

struct Accel::Impl {
  RTCDevice device = nullptr;
  RTCScene scene = nullptr;
  std::vector<GeometryRef> geometries;  // per Embree geomID
  std::vector<TriangleConstants> meshConstants;  // per mesh (empty for meshes not in the BVH)
  SphereData sphereData{};
  // Per sphere: whether its material reads the hit's uv (a textured factor, Bsdf::tint). The
  // sphere's uv costs an atan2 and an acos, so hits on other spheres leave it zero.
  std::vector<uint8_t> sphereUv;
  mutable RayCounter rays;
  mutable RayCounter occlusionRays;  // the part of `rays` that asked occluded()

  std::mutex errorMutex;
  std::string errorMessage;
  std::atomic<bool> failed{false};

  static void onError(void* user, RTCError code, const char* str) {
    auto* self = static_cast<Impl*>(user);
    std::lock_guard<std::mutex> lock(self->errorMutex);
    if (self->failed.load()) return;  // keep the first message
    self->errorMessage = "Embree error " + std::to_string(static_cast<int>(code)) + ": " + (str ? str : "");
    self->failed = true;
  }
  // Embree reports through the callback; C++ throws once the call has returned.
  void check(const char* what) {
    if (!failed.load(std::memory_order_relaxed)) return;
    std::lock_guard<std::mutex> lock(errorMutex);
    throw Error(std::string(what) + ": " + errorMessage);
  }

  ~Impl() {
    if (scene) rtcReleaseScene(scene);
    if (device) rtcReleaseDevice(device);
  }
};

Accel::Accel(const Scene& scene) : scene_(scene), impl_(std::make_unique<Impl>()) {
  Impl& im = *impl_;
  im.device = rtcNewDevice(nullptr);
  if (!im.device) throw Error("Embree: cannot create device (" + std::to_string(rtcGetDeviceError(nullptr)) + ")");
  rtcSetDeviceErrorFunction(im.device, &Impl::onError, &im);

  im.scene = rtcNewScene(im.device);
  // Mitsuba's default: Embree's fast mode. Its robust mode (watertight triangle tests, no leaks
  // through shared edges) only where the scene asks for it (Scene::embreeRobust).
  rtcSetSceneFlags(im.scene, scene.embreeRobust ? RTC_SCENE_FLAG_ROBUST : RTC_SCENE_FLAG_NONE);
  rtcSetSceneBuildQuality(im.scene, RTC_BUILD_QUALITY_HIGH);
  im.check("building the scene BVH");

  im.meshConstants.resize(scene.meshes.size());
  for (size_t m = 0; m < scene.meshes.size(); ++m) {
    const Mesh& mesh = scene.meshes[m];
    if (mesh.triangles.empty() || mesh.positions.empty()) continue;
    RTCGeometry g = rtcNewGeometry(im.device, RTC_GEOMETRY_TYPE_TRIANGLE);
    // Copies (not shared buffers): Embree may read 16 bytes past the last float3.
    auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                          3 * sizeof(float), mesh.positions.size()));
    auto* idx = static_cast<unsigned*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                               3 * sizeof(unsigned), mesh.triangles.size()));
    im.check(("mesh '" + mesh.name + "'").c_str());
    if (!v || !idx) throw Error("Embree: cannot allocate buffers for mesh '" + mesh.name + "'");
    for (size_t i = 0; i < mesh.positions.size(); ++i) std::memcpy(v + 3 * i, &mesh.positions[i], 3 * sizeof(float));
    for (size_t i = 0; i < mesh.triangles.size(); ++i) {
      const glm::uvec3& t = mesh.triangles[i];
      if (t.x >= mesh.positions.size() || t.y >= mesh.positions.size() || t.z >= mesh.positions.size())
        throw Error("mesh '" + mesh.name + "': triangle " + std::to_string(i) + " indexes a missing vertex");
      idx[3 * i] = t.x; idx[3 * i + 1] = t.y; idx[3 * i + 2] = t.z;
    }
    const unsigned id = commitAndAttach(im.scene, g);
    im.check(("mesh '" + mesh.name + "'").c_str());
    mapGeometry(im.geometries, id, GeometryRef::kMesh, static_cast<int>(m));
    im.meshConstants[m] = triangleConstants(mesh);
  }

  if (!scene.spheres.empty()) {
    for (const Sphere& s : scene.spheres)
      if (!(s.radius > 0.0f) || !std::isfinite(s.radius))
        throw Error("sphere '" + s.name + "': radius must be positive and finite");
    im.sphereData.spheres = &scene.spheres;
    for (const Sphere& s : scene.spheres) {
      const bool known = s.bsdf >= 0 && s.bsdf < static_cast<int>(scene.bsdfs.size()) && scene.bsdfs[s.bsdf];
      im.sphereUv.push_back(known && (scene.bsdfs[s.bsdf]->tinted() || scene.bsdfs[s.bsdf]->spatiallyVarying() || scene.bsdfs[s.bsdf]->perturbsFrame()) ? 1 : 0);
    }
    RTCGeometry g = rtcNewGeometry(im.device, RTC_GEOMETRY_TYPE_USER);
    rtcSetGeometryUserPrimitiveCount(g, static_cast<unsigned>(scene.spheres.size()));
    rtcSetGeometryUserData(g, &im.sphereData);
    rtcSetGeometryBoundsFunction(g, &sphereBounds, nullptr);
    rtcSetGeometryIntersectFunction(g, &sphereIntersect);
    rtcSetGeometryOccludedFunction(g, &sphereOccluded);
    const unsigned id = commitAndAttach(im.scene, g);
    im.check("spheres");
    mapGeometry(im.geometries, id, GeometryRef::kSpheres, 0);
  }

  if (!scene.cylinders.empty()) {
    const unsigned id = attachCylinders(im.device, im.scene, scene.cylinders);
    im.check("cylinders");
    mapGeometry(im.geometries, id, GeometryRef::kCylinders, 0);
  }

  for (size_t c = 0; c < scene.curves.size(); ++c) {
    const unsigned id = attachCurve(im.device, im.scene, scene.curves[c]);
    im.check(("curve '" + scene.curves[c].name + "'").c_str());
    mapGeometry(im.geometries, id, GeometryRef::kCurve, static_cast<int>(c));
  }

  for (size_t g = 0; g < scene.sdfGrids.size(); ++g) {
    const unsigned id = attachSdfGrid(im.device, im.scene, scene.sdfGrids[g]);
    im.check(("sdfgrid '" + scene.sdfGrids[g].name + "'").c_str());
    mapGeometry(im.geometries, id, GeometryRef::kSdfGrid, static_cast<int>(g));
  }

  rtcCommitScene(im.scene);
  im.check("building the scene BVH");
}

Accel::~Accel() = default;

uint64_t Accel::raysTraced() const { return impl_->rays.total(); }
bool Accel::robustIntersections() const { return (rtcGetSceneFlags(impl_->scene) & RTC_SCENE_FLAG_ROBUST) != 0; }
uint64_t Accel::occlusionRaysTraced() const { return impl_->occlusionRays.total(); }

namespace {

Hit triangleHit(const Mesh& mesh, const TriangleConstant& tc, int meshIndex, unsigned prim, float u, float v,
                float t) {
  Hit h;
  h.t = t;
  h.mesh = meshIndex;
  h.prim = static_cast<int>(prim);
  h.bsdf = mesh.bsdf;
  h.emitter = mesh.emitter;
  const glm::uvec3 tri = mesh.triangles[prim];
  const Vec3 &p0 = mesh.positions[tri.x], &p1 = mesh.positions[tri.y], &p2 = mesh.positions[tri.z];
  const float w = 1.0f - u - v;
  // From barycentrics, not o + t·d: the error is then relative to the triangle's coordinates only.
  h.p = w * p0 + u * p1 + v * p2;
  h.uv.position = h.p;
  h.pError = tc.pointError;
  const Vec3 ng = tc.faceNormal;
  if (!mesh.normals.empty()) {
    const Vec3 &n0 = mesh.normals[tri.x], &n1 = mesh.normals[tri.y], &n2 = mesh.normals[tri.z];
    Vec3 ns = w * n0 + u * n1 + v * n2;
    const float nl = glm::length(ns);
    ns = nl > 0.0f ? ns / nl : ng;
    if (glm::dot(ns, ng) < 0.0f) ns = -ns;
    h.ns = ns;
  } else {
    h.ns = ng;
  }
  h.ng = ng;
  if (!mesh.uvs.empty()) {
    const Vec2 &t0 = mesh.uvs[tri.x], &t1 = mesh.uvs[tri.y], &t2 = mesh.uvs[tri.z];
    h.uv = w * t0 + u * t1 + v * t2;
    h.dpdu = tc.dpdu;
    h.dpdv = tc.dpdv;
  } else {
    h.uv = Vec2(u, v);
  }
  if (!mesh.attributes.empty()) {
    h.uv.attributes = &mesh.attributes;
    h.uv.vertices = tri;
    h.uv.face = prim;
    h.uv.bary = Vec2(u, v);
  }
  return h;
}

Hit sphereHit(const Sphere& s, int index, const Ray& ray, float t, bool withUv) {
  Hit h;
  h.t = t;
  h.sphere = index;
  h.prim = 0;
  h.bsdf = s.bsdf;
  h.emitter = s.emitter;
  Vec3 n = ray.o + t * ray.d - s.center;
  const float len = glm::length(n);
  n = len > 0.0f ? n / len : Vec3(0, 0, 1);
  h.p = s.center + s.radius * n;  // re-projected onto the sphere
  h.uv.position = h.p;
  h.pError = kPointErrorUlps * kFloatEps * (maxAbs(s.center) + s.radius);
  if (withUv) {
    const float phi = std::atan2(n.y, n.x);
    h.uv = Vec2((phi < 0.0f ? phi + 2.0f * kPi : phi) / (2.0f * kPi), std::acos(glm::clamp(n.z, -1.0f, 1.0f)) / kPi);
  }
  h.dpdu = Vec3(-n.y, n.x, 0.0f) * (2.0f * kPi * s.radius);
  // dp/dv along θ = πv: πr·(cos θ cos φ, cos θ sin φ, −sin θ); at the poles φ = 0.
  const float sinTheta = std::sqrt(n.x * n.x + n.y * n.y);
  h.dpdv = kPi * s.radius *
           (sinTheta > 0.0f ? Vec3(n.z * n.x / sinTheta, n.z * n.y / sinTheta, -sinTheta) : Vec3(n.z, 0.0f, 0.0f));
  if (s.flipNormals) n = -n;
  h.ng = h.ns = n;
  return h;
}

// An analytic shape's hit geometry (one normal, the partials and uv; cylinder and curve geometry
// share these fields) into the hit, after h.p is set: texture lookups read the point too.
template <class Geometry>
void setAnalyticFrame(Hit& h, const Geometry& g) {
  h.ng = h.ns = g.n;
  h.dpdu = g.dpdu;
  h.dpdv = g.dpdv;
  h.uv = g.uv;
  h.uv.position = h.p;
}

Hit cylinderHit(const Cylinder& c, const Ray& ray, float t) {
  const CylinderHitGeometry g = cylinderHitGeometry(c, ray.o + t * ray.d);
  Hit h;
  h.t = t;
  h.prim = 0;
  h.bsdf = c.bsdf;
  h.p = g.p;
  h.pError = kPointErrorUlps * kFloatEps * (maxAbs(g.p) + maxAbs(Vec3(c.toWorld[3])) + glm::length(Vec3(c.toWorld[0])) +
                                            glm::length(Vec3(c.toWorld[2])));
  setAnalyticFrame(h, g);
  return h;
}

// Embree's curve parameter u on segment `prim`; the point is o + t·d (Mitsuba's too), whose error
// is relative to the ray's coordinates (tests/render curve_test.cpp: with the offset this gives,
// rays spawned from curve hits never find the tube again).
Hit curveHit(const Curve& c, int index, const Ray& ray, unsigned prim, float u, float t) {
  Hit h;
  h.t = t;
  h.curve = index;
  h.prim = static_cast<int>(prim);
  h.bsdf = c.bsdf;
  h.p = ray.o + t * ray.d;
  h.pError = kPointErrorUlps * kFloatEps * (maxAbs(ray.o) + t * maxAbs(ray.d));
  const CurveHitGeometry g = curveHitGeometry(c, prim, u, h.p);
  setAnalyticFrame(h, g);
  return h;
}

// The point is o + t·d, as on curves (t is the interpolant's root to double precision); prim is
// the voxel's index in the grid.
Hit sdfGridHit(const SdfGrid& g, const Ray& ray, unsigned prim, float t) {
  Hit h;
  h.t = t;
  h.prim = static_cast<int>((*g.voxels)[prim]);
  h.bsdf = g.bsdf;
  h.p = ray.o + t * ray.d;
  h.uv.position = h.p;
  h.pError = kPointErrorUlps * kFloatEps * (maxAbs(ray.o) + t * maxAbs(ray.d));
  const SdfHitGeometry geometry = sdfHitGeometry(g, sdfVoxelCoords(g, (*g.voxels)[prim]), h.p);
  h.ng = geometry.ng;
  h.ns = geometry.ns;
  return h;
}

}  // namespace

namespace {
RTCRayHit emptyRayHit(const Ray& ray) {
  RTCRayHit rh;
  rh.ray = toEmbree(ray);
  rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rh.hit.primID = RTC_INVALID_GEOMETRY_ID;
  rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  return rh;
}
}  // namespace

Hit Accel::hitOf(const Ray& ray, unsigned geomID, unsigned primID, float u, float v, float tfar) const {
  if (geomID == RTC_INVALID_GEOMETRY_ID) return Hit{};
  const GeometryRef g = impl_->geometries[geomID];
  switch (g.kind) {
    case GeometryRef::kMesh:
      return triangleHit(scene_.meshes[g.index], impl_->meshConstants[g.index][primID], g.index, primID, u, v, tfar);
    case GeometryRef::kSpheres: {
      const int s = static_cast<int>(primID);
      return sphereHit(scene_.spheres[s], s, ray, tfar, impl_->sphereUv[s] != 0);
    }
    case GeometryRef::kCylinders:
      return cylinderHit(scene_.cylinders[primID], ray, tfar);
    case GeometryRef::kCurve:
      return curveHit(scene_.curves[g.index], g.index, ray, primID, u, tfar);
    case GeometryRef::kSdfGrid:
      return sdfGridHit(scene_.sdfGrids[g.index], ray, primID, tfar);
  }
  return Hit{};
}

Hit Accel::intersect(const Ray& ray) const {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRayHit rh = emptyRayHit(ray);
  rtcIntersect1(impl_->scene, &context, &rh);
  impl_->rays.add();
  impl_->check("intersect");
  return hitOf(ray, rh.hit.geomID, rh.hit.primID, rh.hit.u, rh.hit.v, rh.ray.tfar);
}

bool Accel::occluded(const Ray& ray) const {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRay r = toEmbree(ray);
  rtcOccluded1(impl_->scene, &context, &r);
  impl_->rays.add();
  impl_->occlusionRays.add();
  impl_->check("occluded");
  return r.tfar < 0.0f && std::isinf(r.tfar);
}

void Accel::intersect(const Ray* rays, Hit* hits, size_t count, bool coherent) const {
  if (!coherent) {
    for (size_t i = 0; i < count; ++i) hits[i] = intersect(rays[i]);
    return;
  }
  // Coherent rays (a pixel's camera rays, neighbouring pixels') go to Embree as a stream with the
  // coherent flag: it traces them in packets, sharing the traversal.
  intersectStream(rays, hits, count, true);
}

void Accel::intersectStream(const Ray* rays, Hit* hits, size_t count, bool coherent) const {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  if (coherent) context.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
  constexpr size_t kStream = 256;
  RTCRayHit rh[kStream];
  for (size_t b = 0; b < count; b += kStream) {
    const size_t n = std::min(kStream, count - b);
    for (size_t i = 0; i < n; ++i) rh[i] = emptyRayHit(rays[b + i]);
    rtcIntersect1M(impl_->scene, &context, rh, static_cast<unsigned>(n), sizeof(RTCRayHit));
    impl_->check("intersect");
    for (size_t i = 0; i < n; ++i) {
      const RTCHit& h = rh[i].hit;
      new (&hits[b + i]) Hit(hitOf(rays[b + i], h.geomID, h.primID, h.u, h.v, rh[i].ray.tfar));  // in place: no copy
    }
  }
  impl_->rays.add(count);
}

namespace {
// One Embree packet of 16 rays, the lanes past `count` marked invalid.
struct alignas(64) Packet16 {
  RTCRayHit16 rh;
  alignas(64) int valid[16];
  void load(const Ray* rays, size_t count) {
    for (size_t i = 0; i < 16; ++i) {
      const bool live = i < count;
      const Ray& r = rays[live ? i : 0];
      valid[i] = live ? -1 : 0;
      rh.ray.org_x[i] = r.o.x; rh.ray.org_y[i] = r.o.y; rh.ray.org_z[i] = r.o.z;
      rh.ray.dir_x[i] = r.d.x; rh.ray.dir_y[i] = r.d.y; rh.ray.dir_z[i] = r.d.z;
      rh.ray.tnear[i] = r.tMin;
      rh.ray.tfar[i] = r.tMax;
      rh.ray.time[i] = 0.0f;
      rh.ray.mask[i] = 0xFFFFFFFFu;
      rh.ray.id[i] = 0;
      rh.ray.flags[i] = 0;
      rh.hit.geomID[i] = RTC_INVALID_GEOMETRY_ID;
      rh.hit.primID[i] = RTC_INVALID_GEOMETRY_ID;
      rh.hit.instID[0][i] = RTC_INVALID_GEOMETRY_ID;
    }
  }
};
constexpr size_t kOcclusionStream = 256;

// Runs `query(packet, first, n)` over the rays in packets of 16 (the last one partial).
template <class Query>
void forEachPacket16(const Ray* rays, size_t count, const Query& query) {
  Packet16 p;
  for (size_t b = 0; b < count; b += 16) {
    const size_t n = std::min<size_t>(16, count - b);
    p.load(rays + b, n);
    query(p, b, n);
  }
}
}  // namespace

void Accel::intersectBatch(const Ray* rays, Hit* hits, size_t count, BatchQuery query) const {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  switch (query) {
    case BatchQuery::Single:
      for (size_t i = 0; i < count; ++i) hits[i] = intersect(rays[i]);
      return;
    case BatchQuery::Stream:
      intersectStream(rays, hits, count, false);
      return;
    case BatchQuery::Packet16:
      forEachPacket16(rays, count, [&](Packet16& p, size_t b, size_t n) {
        rtcIntersect16(p.valid, impl_->scene, &context, &p.rh);
        impl_->check("intersect");
        for (size_t i = 0; i < n; ++i)
          new (&hits[b + i]) Hit(hitOf(rays[b + i], p.rh.hit.geomID[i], p.rh.hit.primID[i], p.rh.hit.u[i],
                                       p.rh.hit.v[i], p.rh.ray.tfar[i]));  // in place: no copy
      });
      break;
  }
  impl_->rays.add(count);
}

void Accel::occludedBatch(const Ray* rays, uint8_t* blocked, size_t count, BatchQuery query) const {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  // Embree marks an occluded ray by setting its tfar to −∞.
  auto isBlocked = [](float tfar) { return tfar < 0.0f && std::isinf(tfar); };
  switch (query) {
    case BatchQuery::Single:
      for (size_t i = 0; i < count; ++i) blocked[i] = occluded(rays[i]) ? 1 : 0;
      return;
    case BatchQuery::Stream: {
      RTCRay r[kOcclusionStream];
      for (size_t b = 0; b < count; b += kOcclusionStream) {
        const size_t n = std::min(kOcclusionStream, count - b);
        for (size_t i = 0; i < n; ++i) r[i] = toEmbree(rays[b + i]);
        rtcOccluded1M(impl_->scene, &context, r, static_cast<unsigned>(n), sizeof(RTCRay));
        impl_->check("occluded");
        for (size_t i = 0; i < n; ++i) blocked[b + i] = isBlocked(r[i].tfar) ? 1 : 0;
      }
      break;
    }
    case BatchQuery::Packet16:
      forEachPacket16(rays, count, [&](Packet16& p, size_t b, size_t n) {
        rtcOccluded16(p.valid, impl_->scene, &context, &p.rh.ray);
        impl_->check("occluded");
        for (size_t i = 0; i < n; ++i) blocked[b + i] = isBlocked(p.rh.ray.tfar[i]) ? 1 : 0;
      });
      break;
  }
  impl_->rays.add(count);
  impl_->occlusionRays.add(count);
}

}  // namespace rc
