#include "scene/mesh_builder.h"

#include <cstring>
#include <unordered_map>

namespace rc {

MeshData makeRectangle() {
  MeshData m;
  m.positions = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}};
  m.normals.assign(4, Vec3(0, 0, 1));
  m.uvs = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  m.triangles = {{0, 1, 2}, {0, 2, 3}};
  return m;
}

MeshData makeCube() {
  MeshData m;
  // Each face: its normal axis and two tangent axes with t × b = n, so counter-clockwise
  // corners (−t−b, +t−b, +t+b, −t+b) wind outward.
  for (int axis = 0; axis < 3; ++axis) {
    for (float sign : {-1.0f, 1.0f}) {
      Vec3 n(0.0f), t(0.0f);
      n[axis] = sign;
      t[(axis + 1) % 3] = 1.0f;
      const Vec3 b = glm::cross(n, t);
      const uint32_t base = static_cast<uint32_t>(m.positions.size());
      const Vec2 c[4] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
      for (const Vec2& q : c) {
        m.positions.push_back(n + q.x * t + q.y * b);
        m.normals.push_back(n);
        m.uvs.push_back(0.5f * q + 0.5f);
      }
      m.triangles.push_back({base, base + 1, base + 2});
      m.triangles.push_back({base, base + 2, base + 3});
    }
  }
  return m;
}

MeshData makeDisk(int segments) {
  MeshData m;
  m.positions.push_back(Vec3(0.0f));
  m.normals.push_back(Vec3(0, 0, 1));
  m.uvs.push_back(Vec2(0.5f));
  for (int i = 0; i < segments; ++i) {
    const float phi = 2.0f * kPi * float(i) / float(segments);
    const Vec3 p(std::cos(phi), std::sin(phi), 0.0f);
    m.positions.push_back(p);
    m.normals.push_back(Vec3(0, 0, 1));
    m.uvs.push_back(Vec2(0.5f * p.x + 0.5f, 0.5f * p.y + 0.5f));
  }
  for (int i = 0; i < segments; ++i)
    m.triangles.push_back({0u, uint32_t(1 + i), uint32_t(1 + (i + 1) % segments)});
  return m;
}

namespace {

struct Vec3Hash {
  size_t operator()(const Vec3& v) const {
    const Vec3 k = v + Vec3(0.0f);  // −0 → +0: keys that compare equal must hash equal
    uint32_t b[3];
    std::memcpy(b, &k, sizeof(b));
    return (size_t(b[0]) * 73856093u) ^ (size_t(b[1]) * 19349663u) ^ (size_t(b[2]) * 83492791u);
  }
};

bool finite(const Vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// Angle at corner a of triangle (a, b, c), robust for small angles (atan2 of |cross| and dot).
float cornerAngle(const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 e1 = b - a, e2 = c - a;
  return std::atan2(glm::length(glm::cross(e1, e2)), glm::dot(e1, e2));
}

}  // namespace

std::vector<Vec3> angleWeightedNormals(const std::vector<Vec3>& positions, const std::vector<glm::uvec3>& triangles) {
  // Weld by exact position so vertices split only for uv/normal seams still get one smooth normal.
  std::unordered_map<Vec3, uint32_t, Vec3Hash> weld;
  std::vector<uint32_t> group(positions.size());
  for (size_t i = 0; i < positions.size(); ++i) group[i] = weld.emplace(positions[i], uint32_t(weld.size())).first->second;
  std::vector<Vec3> acc(weld.size(), Vec3(0.0f));
  std::vector<Vec3> fallback(weld.size(), Vec3(0.0f));  // a face normal, for vertices whose sum cancels
  for (const glm::uvec3& t : triangles) {
    const Vec3 p[3] = {positions[t.x], positions[t.y], positions[t.z]};
    const Vec3 n = unitTriangleNormal(p[0], p[1], p[2]);
    for (int k = 0; k < 3; ++k) {
      const uint32_t g = group[t[k]];
      acc[g] += n * cornerAngle(p[k], p[(k + 1) % 3], p[(k + 2) % 3]);
      if (fallback[g] == Vec3(0.0f)) fallback[g] = n;
    }
  }
  std::vector<Vec3> normals(positions.size());
  for (size_t i = 0; i < positions.size(); ++i) {
    const Vec3& a = acc[group[i]];
    const float len = glm::length(a);
    normals[i] = len > 0.0f && std::isfinite(len) ? a / len : fallback[group[i]];
    if (normals[i] == Vec3(0.0f)) normals[i] = Vec3(0, 0, 1);  // unreferenced vertex: any unit vector
  }
  return normals;
}

Mesh buildMesh(MeshData data, const Mat4& toWorld, const MeshPolicy& policy) {
  Mesh mesh;
  const Mat3 linear(toWorld);
  const Mat3 normalMatrix = glm::transpose(glm::inverse(linear));
  const bool mirrored = glm::determinant(linear) < 0.0f;

  mesh.positions.reserve(data.positions.size());
  for (const Vec3& p : data.positions) mesh.positions.push_back(Vec3(toWorld * Vec4(p, 1.0f)));
  mesh.uvs = std::move(data.uvs);

  mesh.triangles.reserve(data.triangles.size());
  // Face attributes follow their triangles through the filter below.
  mesh.attributes = std::move(data.attributes);
  std::vector<size_t> keptTriangles;
  for (glm::uvec3 t : data.triangles) {
    const Vec3 &a = mesh.positions[t.x], &b = mesh.positions[t.y], &c = mesh.positions[t.z];
    // In double: |cross|² of a triangle with 1e10 coordinates overflows float, and is not degenerate.
    const glm::dvec3 cr = glm::cross(glm::dvec3(b) - glm::dvec3(a), glm::dvec3(c) - glm::dvec3(a));
    const double area2 = glm::dot(cr, cr);
    if (!finite(a) || !finite(b) || !finite(c) || !(area2 > 0.0) || !std::isfinite(area2)) {
      ++mesh.degenerateSkipped;
      continue;
    }
    if (mirrored != policy.flipNormals) std::swap(t.y, t.z);
    keptTriangles.push_back(mesh.triangles.size() + mesh.degenerateSkipped);  // its index in data.triangles
    mesh.triangles.push_back(t);
  }
  for (MeshAttribute& a : mesh.attributes) {
    if (!a.perFace) continue;
    std::vector<float> kept;
    kept.reserve(keptTriangles.size() * a.channels);
    for (size_t i : keptTriangles) kept.insert(kept.end(), a.values.begin() + i * a.channels, a.values.begin() + (i + 1) * a.channels);
    a.values = std::move(kept);
  }

  if (policy.faceNormals) return mesh;
  if (!data.normals.empty()) {
    mesh.normals.reserve(data.normals.size());
    for (const Vec3& n : data.normals) {
      Vec3 w = normalMatrix * n;
      const float len = glm::length(w);
      w = len > 0.0f && std::isfinite(len) ? w / len : Vec3(0.0f);
      mesh.normals.push_back(policy.flipNormals ? -w : w);
    }
    // A file normal that is zero or NaN cannot shade: recompute that vertex from the geometry.
    std::vector<Vec3> computed;
    for (size_t i = 0; i < mesh.normals.size(); ++i) {
      if (mesh.normals[i] != Vec3(0.0f)) continue;
      if (computed.empty()) computed = angleWeightedNormals(mesh.positions, mesh.triangles);
      mesh.normals[i] = computed[i];
    }
  } else {
    // Computed from the final winding, so flip_normals and mirroring are already accounted for.
    mesh.normals = angleWeightedNormals(mesh.positions, mesh.triangles);
  }
  return mesh;
}

}  // namespace rc
