#include "cache/record_octree.h"

#include <algorithm>
#include <cmath>

namespace rc {

RecordOctree::RecordOctree(const Vec3& lo, const Vec3& hi) : root_(std::make_unique<Node>()) {
  center_ = 0.5f * (lo + hi);
  const Vec3 ext = hi - lo;
  half_ = std::max(0.5f * std::max(ext.x, std::max(ext.y, ext.z)), 1e-6f) * 1.01f;
}

RecordOctree::~RecordOctree() = default;

void RecordOctree::grow(const Vec3& p) {
  // Double the root toward p until it contains p; the old root becomes one child. The old
  // root's own records (bigger than it) stay in the root, where every query sees them.
  while (std::fabs(p.x - center_.x) > half_ || std::fabs(p.y - center_.y) > half_ ||
         std::fabs(p.z - center_.z) > half_) {
    const int ix = p.x < center_.x ? 0 : 1, iy = p.y < center_.y ? 0 : 1, iz = p.z < center_.z ? 0 : 1;
    const Vec3 newCenter = center_ + Vec3(ix ? half_ : -half_, iy ? half_ : -half_, iz ? half_ : -half_);
    auto newRoot = std::make_unique<Node>();
    const int oldChild = (ix ? 0 : 1) | (iy ? 0 : 2) | (iz ? 0 : 4);
    newRoot->ids.swap(root_->ids);
    newRoot->child[oldChild] = std::move(root_);
    root_ = std::move(newRoot);
    center_ = newCenter;
    half_ *= 2.0f;
  }
}

void RecordOctree::insertBox(Node* node, const Vec3& c, float h, int depthLeft, const Vec3& lo, const Vec3& hi,
                             uint32_t id) {
  if (depthLeft == 0) {
    node->ids.push_back(id);
    return;
  }
  for (int k = 0; k < 8; ++k) {
    const Vec3 cc = childCenter(c, h, k);
    const float ch = 0.5f * h;
    if (hi.x < cc.x - ch || lo.x > cc.x + ch || hi.y < cc.y - ch || lo.y > cc.y + ch || hi.z < cc.z - ch ||
        lo.z > cc.z + ch)
      continue;
    if (!node->child[k]) node->child[k] = std::make_unique<Node>();
    insertBox(node->child[k].get(), cc, ch, depthLeft - 1, lo, hi, id);
  }
}

void RecordOctree::insert(uint32_t id, const Vec3& p, float radius) {
  if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) return;
  ++count_;
  grow(p);
  // Not finite, or at least as big as the root: a root record, a candidate for every query.
  if (!(radius < half_)) {
    root_->ids.push_back(id);
    return;
  }
  const Vec3 lo = p - Vec3(radius), hi = p + Vec3(radius);
  grow(lo);
  grow(hi);
  // Depth whose cells (width 2h) satisfy radius ≤ 2h < 2·radius: the box spans ≤ 3 cells an axis.
  int depth = 0;
  for (float h = half_; depth < kMaxDepth && h >= radius; h *= 0.5f) ++depth;
  if (depth == 0) {
    root_->ids.push_back(id);
    return;
  }
  insertBox(root_.get(), center_, half_, depth, lo, hi, id);
}

}  // namespace rc
