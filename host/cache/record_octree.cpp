#include "cache/record_octree.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace rc {

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

}  // namespace rc
