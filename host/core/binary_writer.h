#pragma once
// Appending plain values to a byte string in host byte order: the writers of the cache file, the
// BRDF table cache and the kernel program cache. (Readers stay with their formats: each checks
// bounds and reports errors its own way.)
#include <string>
#include <type_traits>
#include <vector>

namespace rc {

template <typename T>
void put(std::string& out, const T& v) {
  static_assert(std::is_trivially_copyable_v<T>, "put writes the object's bytes");
  out.append(reinterpret_cast<const char*>(&v), sizeof(T));
}

inline void putFloats(std::string& out, const std::vector<float>& v) {
  out.append(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(float));
}

}  // namespace rc
