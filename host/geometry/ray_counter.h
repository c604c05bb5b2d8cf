#pragma once
// Counts traced rays without contention: each thread increments its own cache-line-sized slot
// (slot chosen once per thread), and the total is the sum over slots.
#include <array>
#include <atomic>
#include <cstddef>
#include <cstdint>

namespace rc {

class RayCounter {
 public:
  void add(uint64_t n = 1) { slots_[threadSlot()].value.fetch_add(n, std::memory_order_relaxed); }
  uint64_t total() const {
    uint64_t sum = 0;
    for (const auto& s : slots_) sum += s.value.load(std::memory_order_relaxed);
    return sum;
  }

 private:
  static constexpr size_t kSlots = 64;
  struct alignas(64) Slot { std::atomic<uint64_t> value{0}; };
  static size_t threadSlot();
  std::array<Slot, kSlots> slots_{};
};

}  // namespace rc
