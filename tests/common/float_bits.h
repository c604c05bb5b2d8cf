#pragma once
// A float's bit pattern, for tests that compare a vectorised pass with its scalar code to the bit
// (0 ulps, signed zeros and NaN payloads included).
#include <cstdint>
#include <cstring>

namespace rc::test {

inline uint32_t bits(float f) {
  uint32_t u;
  std::memcpy(&u, &f, sizeof u);
  return u;
}

}  // namespace rc::test
