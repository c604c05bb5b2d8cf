#include "cache/record_octree.h"

#include <algorithm>
#include <cmath>

namespace rc {

RecordOctree::RecordOctree(const Vec3& lo, const Vec3& hi) : root_(std::make_unique<Node>()) {
  center_ = 0.5f * (lo + hi);
  const Vec3 ext = hi - lo;
  half_ = std::max(0.5f * std::max(ext.x, std::max(ext.y, ext.z)), 1e-6f) * 1.01f;
  // Non-finite bounds would make every cell's centre NaN (see insertBox): start from a unit cube
  // instead; grow() enlarges it toward the records.
  if (!finiteVec(center_) || !std::isfinite(half_)) {
    center_ = Vec3(0.0f);
    half_ = 1.0f;
  }
}

RecordOctree::~RecordOctree() = default;

size_t RecordOctree::nodeCount() const {
  size_t n = 0;
  std::vector<const Node*> stack{root_.get()};
  while (!stack.empty()) {
    const Node* node = stack.back();
    stack.pop_back();
    ++n;
    for (const auto& c : node->child)
      if (c) stack.push_back(c.get());
  }
  return n;
}

bool RecordOctree::grow(const Vec3& p) {
  // Double the root toward p until it contains p; the old root becomes one child. The old
  // root's own records (bigger than it) stay in the root, where every query sees them.
  while (std::fabs(p.x - center_.x) > half_ || std::fabs(p.y - center_.y) > half_ ||
         std::fabs(p.z - center_.z) > half_) {
    const int ix = p.x < center_.x ? 0 : 1, iy = p.y < center_.y ? 0 : 1, iz = p.z < center_.z ? 0 : 1;
    const Vec3 newCenter = center_ + Vec3(ix ? half_ : -half_, iy ? half_ : -half_, iz ? half_ : -half_);
    // A root that would overflow float cannot hold p: the caller keeps the record in the root.
    if (!finiteVec(newCenter) || !std::isfinite(2.0f * half_)) return false;
    auto newRoot = std::make_unique<Node>();
    const int oldChild = (ix ? 0 : 1) | (iy ? 0 : 2) | (iz ? 0 : 4);
    newRoot->ids.swap(root_->ids);
    newRoot->child[oldChild] = std::move(root_);
    root_ = std::move(newRoot);
    center_ = newCenter;
    half_ *= 2.0f;
  }
  return true;
}

void RecordOctree::insertBox(Node* node, const Vec3& c, float h, int depthLeft, const Vec3& lo, const Vec3& hi,
                             uint32_t id) {
  // Refuse to descend where children could not be told apart: a non-finite box or cell, or a
  // cell so small that its children's centres round to its own (every child would then overlap
  // the box and each level would multiply the nodes by eight).
  const float ch = 0.5f * h;
  const bool separable = finiteVec(lo) && finiteVec(hi) && std::isfinite(h) && c.x + 0.5f * ch != c.x &&
                         c.y + 0.5f * ch != c.y && c.z + 0.5f * ch != c.z;
  if (depthLeft == 0 || !separable) {
    node->ids.push_back(id);
    return;
  }
  // The children the box reaches, decided by the same comparison with the centre that query()
  // walks by (childIndex), so a point of the box always meets the record on its path, even on
  // a cell boundary where child extents computed as centre ± half would round differently.
  const bool below[3] = {lo.x < c.x, lo.y < c.y, lo.z < c.z}, above[3] = {hi.x >= c.x, hi.y >= c.y, hi.z >= c.z};
  for (int k = 0; k < 8; ++k) {
    bool reaches = true;
    for (int axis = 0; axis < 3; ++axis) reaches = reaches && ((k >> axis) & 1 ? above[axis] : below[axis]);
    if (!reaches) continue;
    if (!node->child[k]) node->child[k] = std::make_unique<Node>();
    insertBox(node->child[k].get(), childCenter(c, h, k), ch, depthLeft - 1, lo, hi, id);
  }
}

void RecordOctree::insert(uint32_t id, const Vec3& p, float radius) {
  if (!finiteVec(p)) return;
  ++count_;
  // Not finite, at least as big as the root, or beyond the float range: a root record, a
  // candidate for every query.
  if (!grow(p) || !(radius < half_)) {
    root_->ids.push_back(id);
    return;
  }
  const Vec3 lo = p - Vec3(radius), hi = p + Vec3(radius);
  if (!grow(lo) || !grow(hi)) {
    root_->ids.push_back(id);
    return;
  }
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
