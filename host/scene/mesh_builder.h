#pragma once
// Turns object-space MeshData into a world-space Mesh, and builds the analytic primitives
// (rectangle, cube, disk) as meshes with Mitsuba's geometry and orientation.
#include <cmath>
#include <string>

#include "scene/mesh_data.h"
#include "scene/scene.h"

namespace rc {

// Unit normal of the triangle (p0, p1, p2), computed in double: in float |cross|² overflows for
// coordinates beyond ~1e9 and the normal would come out zero. (0, 0, 1) for a degenerate one.
inline Vec3 unitTriangleNormal(const Vec3& p0, const Vec3& p1, const Vec3& p2) {
  const glm::dvec3 n = glm::cross(glm::dvec3(p1) - glm::dvec3(p0), glm::dvec3(p2) - glm::dvec3(p0));
  const double len = glm::length(n);
  return len > 0.0 && std::isfinite(len) ? Vec3(n / len) : Vec3(0, 0, 1);
}

MeshData makeRectangle();            // [-1,1]² at z=0, normal +z, uv [0,1]²
MeshData makeCube();                 // [-1,1]³, 24 vertices (flat faces), outward normals
MeshData makeDisk(int segments = 128);  // unit radius at z=0, normal +z, planar uv

struct MeshPolicy {
  bool faceNormals = false;  // drop vertex normals: flat shading
  bool flipNormals = false;  // reverse the orientation (winding and normals)
};

// Applies toWorld (positions; normals with the inverse transpose), then the normal policy:
// file normals are kept unless faceNormals; without them angle-weighted vertex normals are
// computed (vertices at identical positions share one normal, so uv seams do not crease).
// Triangles with zero area or non-finite positions are dropped and counted. When toWorld
// mirrors (det < 0) the winding is reversed so the geometric normal keeps agreeing with the
// transformed normals (and with Mitsuba's rectangle/cube under a mirror).
Mesh buildMesh(MeshData data, const Mat4& toWorld, const MeshPolicy& policy);

// Angle-weighted vertex normals of a world-space mesh (Thürmer & Wüthrich 1998, as Mitsuba).
std::vector<Vec3> angleWeightedNormals(const std::vector<Vec3>& positions, const std::vector<glm::uvec3>& triangles);

}  // namespace rc
