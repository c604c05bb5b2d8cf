#include "scene/instance_placement.h"

#include <utility>

#include "core/error.h"
#include "scene/similarity_transform.h"

namespace rc {

namespace {

Mesh placedMesh(const Mesh& m, const Mat4& toWorld, const Mat3& normalMatrix, bool mirrored) {
  Mesh p = m;
  for (Vec3& v : p.positions) v = Vec3(toWorld * Vec4(v, 1.0f));
  for (Vec3& n : p.normals) {
    const Vec3 w = normalMatrix * n;
    const float len = glm::length(w);
    n = len > 0.0f && std::isfinite(len) ? w / len : n;
  }
  // A mirroring map reverses the winding, so the face normal keeps agreeing with the normals.
  if (mirrored)
    for (glm::uvec3& t : p.triangles) std::swap(t.y, t.z);
  p.emitter = -1;
  return p;
}

}  // namespace

void placeInstance(const ShapeLists& group, const Mat4& toWorld, const std::string& instanceName, ShapeLists& into) {
  const Mat3 linear(toWorld);
  const Mat3 normalMatrix = glm::transpose(glm::inverse(linear));
  const bool mirrored = glm::determinant(linear) < 0.0f;
  const std::string suffix = " in " + instanceName;
  float scale = 1.0f;
  const bool keepsRound = similarity(toWorld, scale);

  for (const Mesh& m : group.meshes) {
    into.meshes.push_back(placedMesh(m, toWorld, normalMatrix, mirrored));
    into.meshes.back().name += suffix;
  }
  for (const Sphere& s : group.spheres) {
    if (!keepsRound)
      throw Error("the instance's to_world turns sphere '" + s.name +
                  "' into an ellipsoid, which rcache does not render (use a mesh)");
    Sphere p = s;
    p.center = Vec3(toWorld * Vec4(s.center, 1.0f));
    p.radius = s.radius * scale;
    p.emitter = -1;
    p.name += suffix;
    into.spheres.push_back(std::move(p));
  }
  for (const Cylinder& c : group.cylinders) {
    Cylinder p = c;
    p.toWorld = toWorld * c.toWorld;
    p.toObject = glm::inverse(p.toWorld);
    // geometry/cylinder_geometry's normal is cross(dp/du, dp/dv), which a mirror turns against
    // the inverse-transposed normal Mitsuba's instance gives.
    p.flipNormals = c.flipNormals != mirrored;
    p.name += suffix;
    into.cylinders.push_back(std::move(p));
  }
  for (const Curve& c : group.curves) {
    if (!keepsRound)
      throw Error("the instance's to_world scales curve '" + c.name +
                  "' non-uniformly, which would make its tube elliptical (rcache's curves are round)");
    Curve p = c;
    for (Vec4& q : p.points) q = Vec4(Vec3(toWorld * Vec4(Vec3(q), 1.0f)), q.w * scale);
    p.name += suffix;
    into.curves.push_back(std::move(p));
  }
  for (const SdfGrid& g : group.sdfGrids) {
    SdfGrid p = g;
    p.toWorld = toWorld * g.toWorld;
    p.toObject = glm::inverse(p.toWorld);
    p.name += suffix;
    into.sdfGrids.push_back(std::move(p));
  }
}

size_t instancePrimitives(const ShapeLists& group) {
  size_t n = group.spheres.size() + group.cylinders.size();
  for (const Mesh& m : group.meshes) n += m.triangles.size();
  for (const Curve& c : group.curves) n += c.segments.size();
  for (const SdfGrid& g : group.sdfGrids) n += g.voxels->size();
  return n;
}

}  // namespace rc
