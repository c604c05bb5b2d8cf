#pragma once
// A triangle mesh as read from a file or generated, in object space, before the shape's
// transform, normal policy and degeneracy filtering (mesh_builder.h) turn it into a Mesh.
#include <vector>

#include "core/math.h"
#include "texture/mesh_attribute.h"

namespace rc {

struct MeshData {
  std::vector<Vec3> positions;
  std::vector<Vec3> normals;          // per vertex, or empty
  std::vector<Vec2> uvs;              // per vertex, or empty
  std::vector<glm::uvec3> triangles;  // indices into the vertex arrays, all in range
  MeshAttributes attributes;          // per vertex, or per triangle (PLY files only)
};

}  // namespace rc
