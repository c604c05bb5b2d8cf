#include "geometry/ray_counter.h"

namespace rc {

size_t RayCounter::threadSlot() {
  // Threads are numbered in order of first use; more than kSlots threads share slots (still correct,
  // the slot is atomic).
  static std::atomic<size_t> nextSlot{0};
  thread_local const size_t slot = nextSlot.fetch_add(1, std::memory_order_relaxed) % kSlots;
  return slot;
}

}  // namespace rc
