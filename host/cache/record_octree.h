#pragma once
// Octree over record influence spheres (centre p_i, radius a_i·R_i), Ward 1988 style: a record
// lives in the deepest node whose half-size is ≥ its radius and that contains its centre, so
// its sphere lies inside the node grown by the half-size. Queries descend only nodes whose grown
// box contains the query point (or touches the query sphere).
// Radii may shrink after insertion (neighbour clamping, adaptive caching) without re-insertion:
// the node stays a conservative home. Not thread-safe by itself; RadianceCache guards it.
#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

#include "core/math.h"

namespace rc {

class RecordOctree {
 public:
  // Bounds of the root (grown to a cube). Points outside still work: the root is enlarged.
  RecordOctree(const Vec3& lo, const Vec3& hi);
  ~RecordOctree();

  void insert(uint32_t id, const Vec3& center, float radius);
  // Calls visit(id) for every record whose node may hold a sphere containing p (candidates;
  // the caller applies the exact weight test).
  void query(const Vec3& p, const std::function<void(uint32_t)>& visit) const;
  // Candidates whose sphere may intersect the sphere (p, r).
  void querySphere(const Vec3& p, float r, const std::function<void(uint32_t)>& visit) const;
  size_t size() const { return count_; }

 private:
  struct Node;
  std::unique_ptr<Node> root_;
  Vec3 center_;
  float half_;
  size_t count_ = 0;
  float rootRadius_ = 0.0f;  // largest radius stored in the root itself
  void grow(const Vec3& p);
};

}  // namespace rc
