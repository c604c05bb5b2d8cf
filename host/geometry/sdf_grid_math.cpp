#include "geometry/sdf_grid_math.h"

#include <algorithm>
#include <cmath>

namespace rc {

namespace {

glm::dvec3 voxelSize(const SdfGrid& g) {
  return glm::dvec3(1.0 / (g.res[0] - 1.0), 1.0 / (g.res[1] - 1.0), 1.0 / (g.res[2] - 1.0));
}

// Unit vector, or zero for a zero (or non-finite) one: Mitsuba's normalize would give NaN there.
glm::dvec3 unitOrZero(const glm::dvec3& v) {
  const double len = glm::length(v);
  return len > 0.0 && std::isfinite(len) ? v / len : glm::dvec3(0.0);
}

// A polynomial in s, c[0] + c[1]·s + c[2]·s² + c[3]·s³.
struct Cubic {
  double c[4] = {0, 0, 0, 0};
  double at(double s) const { return ((c[3] * s + c[2]) * s + c[1]) * s + c[0]; }
  double slope(double s) const { return (3.0 * c[3] * s + 2.0 * c[2]) * s + c[1]; }
};

// p + (q − p)·(a + b·s): one linear interpolation of the trilinear interpolant, along the ray.
Cubic lerp(const Cubic& p, const Cubic& q, double a, double b) {
  Cubic r;
  for (int k = 0; k < 4; ++k) {
    const double diff = q.c[k] - p.c[k];
    r.c[k] += p.c[k] + diff * a;
    if (k < 3) r.c[k + 1] += diff * b;
  }
  return r;
}

// The roots of c0 + c1·s + c2·s² in (0, sMax), ascending (at most two).
int quadraticRootsInside(double c0, double c1, double c2, double sMax, double roots[2]) {
  double r[2];
  int n = 0;
  if (c2 == 0.0) {
    if (c1 != 0.0) r[n++] = -c0 / c1;
  } else {
    const double disc = c1 * c1 - 4.0 * c2 * c0;
    if (disc >= 0.0) {
      const double q = -0.5 * (c1 + std::copysign(std::sqrt(disc), c1));
      r[n++] = q / c2;
      if (q != 0.0) r[n++] = c0 / q;
    }
  }
  if (n == 2 && r[0] > r[1]) std::swap(r[0], r[1]);
  int inside = 0;
  for (int i = 0; i < n; ++i)
    if (r[i] > 0.0 && r[i] < sMax) roots[inside++] = r[i];
  return inside;
}

// The root of f in [lo, hi] where f(lo) and f(hi) differ in sign: Newton steps kept inside the
// bracket (bisection where a step would leave it), to double precision.
double refineRoot(const Cubic& f, double lo, double hi, double fLo) {
  double x = 0.5 * (lo + hi);
  for (int it = 0; it < 100; ++it) {
    const double fx = f.at(x);
    if (fx == 0.0) return x;
    if ((fx < 0.0) == (fLo < 0.0)) lo = x, fLo = fx;
    else hi = x;
    const double slope = f.slope(x);
    double next = slope != 0.0 ? x - fx / slope : 0.5 * (lo + hi);
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    if (std::fabs(next - x) <= 1e-15 * std::max(std::fabs(x), std::fabs(hi)) || hi - lo <= 0.0) return next;
    x = next;
  }
  return x;
}

}  // namespace

double sdfValue(const SdfGrid& grid, const glm::dvec3& p) {
  int i[3];
  double w[3];
  for (int a = 0; a < 3; ++a) {
    const double n1 = grid.res[a] - 1.0;
    const double g = std::clamp(p[a], 0.0, 1.0) * n1;
    i[a] = std::min(static_cast<int>(std::floor(g)), static_cast<int>(grid.res[a]) - 2);
    w[a] = g - i[a];
  }
  double value = 0.0;
  for (int c = 0; c < 8; ++c) {
    const int bx = c & 1, by = (c >> 1) & 1, bz = (c >> 2) & 1;
    const double weight = (bx ? w[0] : 1.0 - w[0]) * (by ? w[1] : 1.0 - w[1]) * (bz ? w[2] : 1.0 - w[2]);
    value += weight * grid.at(i[0] + bx, i[1] + by, i[2] + bz);
  }
  return value;
}

glm::dvec3 sdfVoxelGradient(const SdfGrid& grid, const glm::dvec3& p, const glm::ivec3& voxel) {
  const glm::dvec3 size = voxelSize(grid);
  glm::dvec3 gradient;
  for (int a = 0; a < 3; ++a) {
    glm::dvec3 near = p, far = p;
    near[a] = voxel[a] * size[a];
    far[a] = (voxel[a] + 1) * size[a];
    gradient[a] = (sdfValue(grid, far) - sdfValue(grid, near)) / size[a];
  }
  return gradient;
}

glm::dvec3 sdfSmoothNormal(const SdfGrid& grid, const glm::dvec3& p) {
  const glm::dvec3 scaled = p * glm::dvec3(grid.res[0] - 1.0, grid.res[1] - 1.0, grid.res[2] - 1.0);
  const glm::ivec3 nearest(std::nearbyint(scaled.x), std::nearbyint(scaled.y), std::nearbyint(scaled.z));
  const glm::ivec3 first = nearest - glm::ivec3(1);
  // The upper voxel's weight per axis: p's distance from the lower voxel's centre, in voxels.
  glm::dvec3 w = scaled - glm::dvec3(nearest) + glm::dvec3(0.5);
  glm::dvec3 normals[8];
  bool valid[8];
  for (int c = 0; c < 8; ++c) {
    const glm::ivec3 v = first + glm::ivec3(c & 1, (c >> 1) & 1, (c >> 2) & 1);
    valid[c] = v.x >= 0 && v.y >= 0 && v.z >= 0;
    normals[c] = valid[c] ? unitOrZero(sdfVoxelGradient(grid, p, v)) : glm::dvec3(0.0);
  }
  for (int a = 0; a < 3; ++a) {
    bool lowerValid = false, upperValid = false;
    for (int c = 0; c < 8; ++c) ((c >> a) & 1 ? upperValid : lowerValid) |= valid[c];
    if (!lowerValid) w[a] = 1.0;
    if (!upperValid) w[a] = 0.0;
  }
  glm::dvec3 n(0.0);
  for (int c = 0; c < 8; ++c) {
    const double weight = ((c & 1) ? w.x : 1.0 - w.x) * ((c >> 1) & 1 ? w.y : 1.0 - w.y) * ((c >> 2) & 1 ? w.z : 1.0 - w.z);
    n += weight * normals[c];
  }
  return n;
}

glm::ivec3 sdfVoxelCoords(const SdfGrid& grid, uint32_t voxel) {
  const uint32_t vx = grid.res[0] - 1, vy = grid.res[1] - 1;
  return glm::ivec3(voxel % vx, (voxel / vx) % vy, voxel / (vx * vy));
}

bool intersectSdfVoxel(const SdfGrid& grid, const glm::ivec3& voxel, const glm::dvec3& o, const glm::dvec3& d,
                       double tMin, double tMax, double& t) {
  const glm::dvec3 size = voxelSize(grid);
  // The ray's span inside the closed voxel box.
  double t0 = tMin, t1 = tMax;
  for (int a = 0; a < 3; ++a) {
    const double lo = voxel[a] * size[a], hi = (voxel[a] + 1) * size[a];
    if (d[a] == 0.0) {
      if (o[a] < lo || o[a] > hi) return false;
      continue;
    }
    double ta = (lo - o[a]) / d[a], tb = (hi - o[a]) / d[a];
    if (ta > tb) std::swap(ta, tb);
    t0 = std::max(t0, ta);
    t1 = std::min(t1, tb);
  }
  if (!(t0 <= t1)) return false;

  // The interpolant along the ray, in s = t − t0 (voxel coordinates a + b·s in [0,1]³ there):
  // lerps of the corner values along x, then y, then z.
  const glm::dvec3 a = (o + t0 * d) / size - glm::dvec3(voxel);
  const glm::dvec3 b = d / size;
  Cubic alongX[2][2];
  for (int z = 0; z < 2; ++z)
    for (int y = 0; y < 2; ++y) {
      Cubic low, high;
      low.c[0] = grid.at(voxel.x, voxel.y + y, voxel.z + z);
      high.c[0] = grid.at(voxel.x + 1, voxel.y + y, voxel.z + z);
      alongX[z][y] = lerp(low, high, a.x, b.x);
    }
  const Cubic f = lerp(lerp(alongX[0][0], alongX[0][1], a.y, b.y), lerp(alongX[1][0], alongX[1][1], a.y, b.y), a.z, b.z);

  // Monotone pieces between the cubic's extrema; the first with a sign change holds the hit.
  const double sMax = t1 - t0;
  double ends[4] = {0.0};
  const int extrema = quadraticRootsInside(f.c[1], 2.0 * f.c[2], 3.0 * f.c[3], sMax, ends + 1);
  ends[extrema + 1] = sMax;
  double fLo = f.at(0.0);
  for (int piece = 0; piece <= extrema; ++piece) {
    const double lo = ends[piece], hi = ends[piece + 1];
    const double fHi = f.at(hi);
    if (fLo == 0.0) {
      t = t0 + lo;
      return true;
    }
    if (fHi == 0.0 || (fHi < 0.0) != (fLo < 0.0)) {
      t = t0 + (fHi == 0.0 ? hi : refineRoot(f, lo, hi, fLo));
      return true;
    }
    fLo = fHi;
  }
  return false;
}

SdfHitGeometry sdfHitGeometry(const SdfGrid& grid, const glm::ivec3& voxel, const Vec3& p) {
  const glm::dmat4 toObject(grid.toObject);
  const glm::dvec3 local = glm::dvec3(toObject * glm::dvec4(glm::dvec3(p), 1.0));
  // Normals go to world space by the inverse transpose of to_world's linear part.
  const glm::dmat3 normalMatrix = glm::transpose(glm::dmat3(toObject));
  SdfHitGeometry g;
  const glm::dvec3 ng = unitOrZero(normalMatrix * sdfVoxelGradient(grid, local, voxel));
  if (ng != glm::dvec3(0.0)) g.ng = Vec3(ng);
  g.ns = g.ng;
  if (grid.smoothNormals) {
    const glm::dvec3 ns = unitOrZero(normalMatrix * sdfSmoothNormal(grid, local));
    if (ns != glm::dvec3(0.0)) g.ns = Vec3(glm::dot(ns, glm::dvec3(g.ng)) < 0.0 ? -ns : ns);
  }
  return g;
}

}  // namespace rc
