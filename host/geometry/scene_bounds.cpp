#include "geometry/scene_bounds.h"

#include <cmath>

#include "geometry/curve_geometry.h"
#include "geometry/cylinder_geometry.h"
#include "geometry/sdf_grid_geometry.h"

namespace rc {

namespace {

bool finite(const Vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

}  // namespace

void finiteSceneBounds(const Scene& scene, Vec3& lo, Vec3& hi) {
  lo = Vec3(INFINITY);
  hi = Vec3(-INFINITY);
  auto add = [&](const Vec3& p) {
    if (!finite(p)) return;
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  };
  for (const Mesh& m : scene.meshes)
    for (const glm::uvec3& t : m.triangles)
      for (int k = 0; k < 3; ++k)
        if (t[k] < m.positions.size()) add(m.positions[t[k]]);
  // A shape's box counts only when both corners are finite.
  auto addBox = [&](const Vec3& a, const Vec3& b) {
    if (!finite(a) || !finite(b)) return;
    add(a);
    add(b);
  };
  for (const Sphere& s : scene.spheres) addBox(s.center - Vec3(s.radius), s.center + Vec3(s.radius));
  Vec3 a, b;
  for (const Cylinder& c : scene.cylinders) {
    cylinderBounds(c, a, b);
    addBox(a, b);
  }
  for (const Curve& c : scene.curves) {
    curveBounds(c, a, b);
    addBox(a, b);
  }
  for (const SdfGrid& g : scene.sdfGrids) {
    sdfGridBounds(g, a, b);
    addBox(a, b);
  }
  if (!(lo.x <= hi.x) || !finite(hi - lo)) {
    lo = Vec3(-1.0f);
    hi = Vec3(1.0f);
  }
}

}  // namespace rc
