#pragma once
// Octree over record influence spheres (centre p_i, radius a_i·R_i), Ward 1988 style: a record
// lives in the deepest node whose half-size is ≥ its radius and that contains its centre, so
// its sphere lies inside the node grown by the half-size. Queries descend only nodes whose grown
// box contains the query point (or touches the query sphere).
// Radii may shrink after insertion (neighbour clamping, adaptive caching) without re-insertion:
// the node stays a conservative home. Not thread-safe by itself; RadianceCache guards it.
#include <array>
#include <cmath>
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
  // the caller applies the exact weight test). Templates, not std::function: lookups are the
  // innermost loop of rendering (one per shading point) and the indirect call per candidate
  // showed up at ~10 % of the final pass in perf.
  template <class Visit>
  void query(const Vec3& p, Visit&& visit) const { querySphere(p, 0.0f, visit); }
  // Candidates whose sphere may intersect the sphere (p, r).
  template <class Visit>
  void querySphere(const Vec3& p, float r, Visit&& visit) const;
  size_t size() const { return count_; }

 private:
  struct Node {
    std::vector<uint32_t> ids;
    std::array<std::unique_ptr<Node>, 8> child;
  };
  static constexpr int kMaxDepth = 40;  // half-size shrinks 2^40: far below float resolution of any scene
  std::unique_ptr<Node> root_;
  Vec3 center_;
  float half_;
  size_t count_ = 0;
  float rootRadius_ = 0.0f;  // largest radius stored in the root itself
  void grow(const Vec3& p);
};

template <class Visit>
void RecordOctree::querySphere(const Vec3& p, float r, Visit&& visit) const {
  struct Item {
    const Node* node;
    Vec3 c;
    float h;
  };
  // Depth-first over a fixed local stack (no allocation per lookup, reentrant), spilling to the
  // heap only in trees deeper than ~36 levels (the root doubles toward far points). Visit order
  // does not matter: callers sort or accumulate.
  constexpr size_t kFixed = 256;
  Item fixed[kFixed];
  std::vector<Item> spill;
  size_t top = 0;
  fixed[top++] = {root_.get(), center_, half_};
  while (top > 0 || !spill.empty()) {
    Item it;
    if (!spill.empty()) {
      it = spill.back();
      spill.pop_back();
    } else {
      it = fixed[--top];
    }
    // Records here have radius ≤ h and centre inside the node: their spheres lie in the box grown
    // by h (the root may also hold bigger ones: rootRadius_).
    const float grown = it.node == root_.get() ? std::max(it.h, rootRadius_) : it.h;
    const float g = it.h + grown + r;
    if (std::fabs(p.x - it.c.x) > g || std::fabs(p.y - it.c.y) > g || std::fabs(p.z - it.c.z) > g) continue;
    for (uint32_t id : it.node->ids) visit(id);
    const float ch = 0.5f * it.h;
    for (int k = 0; k < 8; ++k) {
      if (!it.node->child[k]) continue;
      const Vec3 cc = it.c + Vec3((k & 1) ? ch : -ch, (k & 2) ? ch : -ch, (k & 4) ? ch : -ch);
      const Item next{it.node->child[k].get(), cc, ch};
      if (top < kFixed) fixed[top++] = next;
      else spill.push_back(next);
    }
  }
}

}  // namespace rc
