#include "cache/record_octree.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace rc {

struct RecordOctree::Node {
  std::vector<uint32_t> ids;
  std::array<std::unique_ptr<Node>, 8> child;
};

namespace {
constexpr int kMaxDepth = 40;  // half-size shrinks 2^40: far below float resolution of any scene
}


RecordOctree::RecordOctree(const Vec3& lo, const Vec3& hi) : root_(std::make_unique<Node>()) {
  center_ = 0.5f * (lo + hi);
  const Vec3 ext = hi - lo;
  half_ = std::max(0.5f * std::max(ext.x, std::max(ext.y, ext.z)), 1e-6f) * 1.01f;
}

RecordOctree::~RecordOctree() = default;

void RecordOctree::grow(const Vec3& p) {
  // Double the root toward p until it contains p; the old root becomes one child.
  while (std::fabs(p.x - center_.x) > half_ || std::fabs(p.y - center_.y) > half_ ||
         std::fabs(p.z - center_.z) > half_) {
    const int ix = p.x < center_.x ? 0 : 1, iy = p.y < center_.y ? 0 : 1, iz = p.z < center_.z ? 0 : 1;
    // The new centre is offset toward p; the old root is the child on the opposite side.
    const Vec3 newCenter = center_ + Vec3(ix ? half_ : -half_, iy ? half_ : -half_, iz ? half_ : -half_);
    auto newRoot = std::make_unique<Node>();
    const int oldChild = (ix ? 0 : 1) | (iy ? 0 : 2) | (iz ? 0 : 4);
    // Records held by the old root may exceed its half-size: they move down one level, where
    // the bound rootRadius_ no longer applies, so push them to the new root instead.
    newRoot->ids.swap(root_->ids);
    newRoot->child[oldChild] = std::move(root_);
    root_ = std::move(newRoot);
    center_ = newCenter;
    half_ *= 2.0f;
  }
}

void RecordOctree::insert(uint32_t id, const Vec3& p, float radius) {
  if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) return;
  grow(p);
  Node* node = root_.get();
  Vec3 c = center_;
  float h = half_;
  for (int depth = 0; depth < kMaxDepth && 0.5f * h >= radius; ++depth) {
    const int ix = p.x < c.x ? 0 : 1, iy = p.y < c.y ? 0 : 1, iz = p.z < c.z ? 0 : 1;
    const int k = ix | (iy << 1) | (iz << 2);
    h *= 0.5f;
    c += Vec3(ix ? h : -h, iy ? h : -h, iz ? h : -h);
    if (!node->child[k]) node->child[k] = std::make_unique<Node>();
    node = node->child[k].get();
  }
  node->ids.push_back(id);
  if (node == root_.get()) rootRadius_ = std::max(rootRadius_, radius);
  ++count_;
}

void RecordOctree::query(const Vec3& p, const std::function<void(uint32_t)>& visit) const {
  querySphere(p, 0.0f, visit);
}

void RecordOctree::querySphere(const Vec3& p, float r, const std::function<void(uint32_t)>& visit) const {
  struct Item { const Node* node; Vec3 c; float h; };
  std::vector<Item> stack;
  stack.reserve(64);
  stack.push_back({root_.get(), center_, half_});
  while (!stack.empty()) {
    const Item it = stack.back();
    stack.pop_back();
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
      stack.push_back({it.node->child[k].get(), cc, ch});
    }
  }
}

}  // namespace rc
