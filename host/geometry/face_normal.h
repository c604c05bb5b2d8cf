#pragma once
// The geometric normal of a mesh triangle as Accel reports it: from the winding, turned to agree with
// the vertex normals when the mesh has them. Light sampling uses the same function so that the side
// an area emitter emits toward is the same whether it is hit or sampled.
#include "scene/mesh_builder.h"
#include "scene/scene.h"

namespace rc {

inline Vec3 orientedFaceNormal(const Mesh& mesh, size_t triangle) {
  const glm::uvec3 t = mesh.triangles[triangle];
  const Vec3 &p0 = mesh.positions[t.x], &p1 = mesh.positions[t.y], &p2 = mesh.positions[t.z];
  Vec3 ng = unitTriangleNormal(p0, p1, p2);
  if (!mesh.normals.empty() && glm::dot(ng, mesh.normals[t.x] + mesh.normals[t.y] + mesh.normals[t.z]) < 0.0f) ng = -ng;
  return ng;
}

}  // namespace rc
