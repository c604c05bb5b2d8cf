#include "geometry/curve_geometry.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "core/error.h"
#include "geometry/embree_attach.h"
#include "core/frame.h"

namespace rc {

namespace {

// Mitsuba's consistent frame around the axis direction t: `rot` is world z made orthogonal to t
// (world y where t is ±z), `rad` = rot × t. u = 0 lies along rad, u = ¼ along rot.
struct AxisFrame {
  Vec3 rot, rad;
};
AxisFrame axisFrame(const Vec3& t) {
  const Vec3 guide(0, 0, 1);
  AxisFrame f;
  f.rot = std::fabs(glm::dot(guide, t)) == 1.0f ? Vec3(0, 1, 0) : glm::normalize(guide - t * glm::dot(t, guide));
  f.rad = glm::cross(f.rot, t);
  return f;
}

float angleParameter(const AxisFrame& f, const Vec3& radial) {
  float u = std::atan2(glm::dot(f.rot, radial), glm::dot(f.rad, radial));
  if (u < 0.0f) u += 2.0f * kPi;
  return u / (2.0f * kPi);
}

// The uniform cubic B-spline of four control points at local parameter v: the centre, its first
// three derivatives, the radius and its first two derivatives.
struct CubicPoint {
  Vec3 c, dc, ddc, dddc;
  float r, dr, ddr;
};
CubicPoint cubicBSpline(const Vec4* cp, float v) {
  const float v2 = v * v, v3 = v2 * v;
  const float b[4] = {(-v3 + 3 * v2 - 3 * v + 1) / 6, (3 * v3 - 6 * v2 + 4) / 6, (-3 * v3 + 3 * v2 + 3 * v + 1) / 6,
                      v3 / 6};
  const float db[4] = {(-3 * v2 + 6 * v - 3) / 6, (9 * v2 - 12 * v) / 6, (-9 * v2 + 6 * v + 3) / 6, 3 * v2 / 6};
  const float ddb[4] = {1 - v, 3 * v - 2, 1 - 3 * v, v};
  const float dddb[4] = {-1, 3, -3, 1};
  CubicPoint q{Vec3(0.0f), Vec3(0.0f), Vec3(0.0f), Vec3(0.0f), 0.0f, 0.0f, 0.0f};
  for (int i = 0; i < 4; ++i) {
    const Vec3 p(cp[i]);
    q.c += b[i] * p;
    q.dc += db[i] * p;
    q.ddc += ddb[i] * p;
    q.dddc += dddb[i] * p;
    q.r += b[i] * cp[i].w;
    q.dr += db[i] * cp[i].w;
    q.ddr += ddb[i] * cp[i].w;
  }
  return q;
}

CurveHitGeometry linearHit(const Curve& c, unsigned segment, float v, const Vec3& p) {
  const Vec4 &c0 = c.points[c.segments[segment]], &c1 = c.points[c.segments[segment] + 1];
  const Vec3 p0(c0), p1(c1);
  const Vec3 axis = glm::normalize(p1 - p0);
  // Embree's v already accounts for the changing radius: the normal is p − centre(v).
  const Vec3 centre = p0 * (1.0f - v) + p1 * v;
  const Vec3 radial = glm::normalize(p - centre);
  CurveHitGeometry g;
  g.n = radial;
  g.uv = Vec2(angleParameter(axisFrame(axis), radial), (v + static_cast<float>(segment)) / c.segments.size());
  // Mitsuba 3.9.1's linearcurve leaves dp/du and dp/dv zero (its shading frame comes from the
  // normal alone); so does this one (bench/mitsuba_curve_values.py).
  return g;
}

CurveHitGeometry bsplineHit(const Curve& c, unsigned segment, float v, const Vec3& p) {
  const CubicPoint q = cubicBSpline(&c.points[c.segments[segment]], v);
  const Vec3 radial = p - q.c;
  CurveHitGeometry g;
  // The normal of the swept surface, with the curvature correction of Mitsuba's bsplinecurve.
  g.n = glm::normalize((glm::dot(q.dc, q.dc) - glm::dot(radial, q.ddc)) * radial - (q.dr * q.r) * q.dc);
  const float speed = glm::length(q.dc);
  const Vec3 t = q.dc / speed;
  const AxisFrame axis = axisFrame(t);
  const float u = angleParameter(axis, glm::normalize(radial));
  g.uv = Vec2(u, (v + static_cast<float>(segment)) / c.segments.size());

  // Partials from the Frenet frame (T, N, B), curvature κ and torsion τ, as Mitsuba's partials().
  const Vec3 cross1 = glm::cross(q.dc, q.ddc);
  const float crossLen = glm::length(cross1);
  float kappa = crossLen / (speed * speed * speed);
  float tau = crossLen < 1e-6f || glm::length(q.dddc) < 1e-6f ? 0.0f : glm::dot(q.dddc, cross1) / (crossLen * crossLen);
  Vec3 fn, fb;
  if (kappa < 5.96046448e-8f) {  // straight here (below Dr.Jit's float epsilon): any frame around T
    kappa = tau = 0.0f;
    const Frame f = Frame::fromNormal(t);
    fn = f.t;
    fb = f.b;
  } else {
    fn = glm::normalize(glm::cross(cross1, q.dc));
    fb = glm::normalize(glm::cross(t, fn));
  }
  const float phi = 2.0f * kPi * u;
  const Vec3 rad = std::cos(phi) * axis.rad + std::sin(phi) * axis.rot;
  const float cosT = glm::dot(fn, rad), sinT = glm::dot(fb, rad);
  const Vec3 radu = -sinT * fn + cosT * fb;
  const Vec3 radv = speed * cosT * (-kappa * t + tau * fb) + speed * sinT * (-tau * fn);
  g.dpdu = 2.0f * kPi * q.r * radu;
  g.dpdv = static_cast<float>(c.segments.size()) * (q.dc + q.dr * rad + q.r * radv);
  return g;
}

}  // namespace

CurveHitGeometry curveHitGeometry(const Curve& c, unsigned segment, float vLocal, const Vec3& p) {
  return c.basis == CurveBasis::Linear ? linearHit(c, segment, vLocal, p) : bsplineHit(c, segment, vLocal, p);
}

void curveBounds(const Curve& c, Vec3& lo, Vec3& hi) {
  lo = Vec3(INFINITY);
  hi = Vec3(-INFINITY);
  for (const Vec4& p : c.points) {
    lo = glm::min(lo, Vec3(p) - Vec3(p.w));
    hi = glm::max(hi, Vec3(p) + Vec3(p.w));
  }
}

namespace {

// Embree 3 reports a ray leaving a round curve from inside; Mitsuba drops such hits (its curves'
// "backfaces are always culled"), so a ray from inside the tube passes on to what lies beyond.
// Embree's Ng points out of the tube.
void cullInside(const RTCFilterFunctionNArguments* args) {
  const unsigned N = args->N;
  for (unsigned i = 0; i < N; ++i) {
    if (args->valid[i] != -1) continue;
    const float dot = RTCRayN_dir_x(args->ray, N, i) * RTCHitN_Ng_x(args->hit, N, i) +
                      RTCRayN_dir_y(args->ray, N, i) * RTCHitN_Ng_y(args->hit, N, i) +
                      RTCRayN_dir_z(args->ray, N, i) * RTCHitN_Ng_z(args->hit, N, i);
    if (dot > 0.0f) args->valid[i] = 0;
  }
}

}  // namespace

unsigned attachCurve(RTCDevice device, RTCScene scene, const Curve& c) {
  RTCGeometry g = rtcNewGeometry(device, c.basis == CurveBasis::Linear ? RTC_GEOMETRY_TYPE_ROUND_LINEAR_CURVE
                                                                       : RTC_GEOMETRY_TYPE_ROUND_BSPLINE_CURVE);
  if (!g) throw Error("Embree: cannot create the geometry of curve '" + c.name + "'");
  auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT4,
                                                        4 * sizeof(float), c.points.size()));
  auto* idx = static_cast<unsigned*>(
      rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT, sizeof(unsigned), c.segments.size()));
  if (!v || !idx) {
    rtcReleaseGeometry(g);
    throw Error("Embree: cannot allocate buffers for curve '" + c.name + "'");
  }
  std::memcpy(v, c.points.data(), c.points.size() * sizeof(Vec4));
  std::memcpy(idx, c.segments.data(), c.segments.size() * sizeof(unsigned));
  rtcSetGeometryIntersectFilterFunction(g, &cullInside);
  rtcSetGeometryOccludedFilterFunction(g, &cullInside);
  return commitAndAttach(scene, g);
}

}  // namespace rc
