#include "scene/instance_placement.h"

#include <utility>

#include "core/error.h"
#include "scene/similarity_transform.h"

namespace rc {

namespace {

void placeMesh(Mesh& p, const Mat4& toWorld, const Mat3& normalMatrix, bool mirrored) {
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
}

// Copies every shape of `from` into `into`, placed by `place` and renamed with the suffix.
template <class Shape, class Place>
void placeAll(const std::vector<Shape>& from, std::vector<Shape>& into, const std::string& suffix, const Place& place) {
  for (const Shape& shape : from) {
    Shape copy = shape;
    place(copy);
    copy.name += suffix;
    into.push_back(std::move(copy));
  }
}

// Spheres and curves stay round only under a similarity.
void requireRound(bool keepsRound, const std::string& what, const std::string& name, const std::string& consequence) {
  if (!keepsRound)
    throw Error("the instance's to_world is not a rotation with a uniform scale, which would make " + what + " '" +
                name + "' " + consequence);
}

}  // namespace

void placeInstance(const ShapeLists& group, const Mat4& toWorld, const std::string& instanceName, ShapeLists& into) {
  const Mat3 linear(toWorld);
  const Mat3 normalMatrix = glm::transpose(glm::inverse(linear));
  const bool mirrored = glm::determinant(linear) < 0.0f;
  const std::string suffix = " in " + instanceName;
  float scale = 1.0f;
  const bool keepsRound = similarity(toWorld, scale);

  placeAll(group.meshes, into.meshes, suffix, [&](Mesh& m) { placeMesh(m, toWorld, normalMatrix, mirrored); });
  placeAll(group.spheres, into.spheres, suffix, [&](Sphere& s) {
    requireRound(keepsRound, "sphere", s.name, "an ellipsoid, which rcache does not render (use a mesh)");
    s.center = Vec3(toWorld * Vec4(s.center, 1.0f));
    s.radius *= scale;
    s.emitter = -1;
  });
  placeAll(group.cylinders, into.cylinders, suffix, [&](Cylinder& c) {
    c.toWorld = toWorld * c.toWorld;
    c.toObject = glm::inverse(c.toWorld);
    // geometry/cylinder_geometry's normal is cross(dp/du, dp/dv), which a mirror turns against
    // the inverse-transposed normal Mitsuba's instance gives.
    c.flipNormals = c.flipNormals != mirrored;
  });
  placeAll(group.curves, into.curves, suffix, [&](Curve& c) {
    requireRound(keepsRound, "curve", c.name, "an elliptical tube (rcache's curves are round)");
    for (Vec4& q : c.points) q = Vec4(Vec3(toWorld * Vec4(Vec3(q), 1.0f)), q.w * scale);
  });
  placeAll(group.sdfGrids, into.sdfGrids, suffix, [&](SdfGrid& g) {
    g.toWorld = toWorld * g.toWorld;
    g.toObject = glm::inverse(g.toWorld);
  });
}

size_t instancePrimitives(const ShapeLists& group) {
  size_t n = group.spheres.size() + group.cylinders.size();
  for (const Mesh& m : group.meshes) n += m.triangles.size();
  for (const Curve& c : group.curves) n += c.segments.size();
  for (const SdfGrid& g : group.sdfGrids) n += g.voxels->size();
  return n;
}

}  // namespace rc
