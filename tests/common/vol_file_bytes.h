#pragma once
// Mitsuba's `.vol` grid files written byte by byte (after src/render/volumegrid.cpp), for the
// tests of the grid reader and of the shapes and media that read such files.
#include <cstdint>
#include <cstring>
#include <functional>
#include <string>

namespace rc::test {

struct VolBytes {
  std::string s = "VOL\x03";
  void i32(int32_t v) { for (int i = 0; i < 4; ++i) s.push_back(static_cast<char>((static_cast<uint32_t>(v) >> (8 * i)) & 0xff)); }
  void f32(float f) { int32_t b; std::memcpy(&b, &f, 4); i32(b); }
};

// Encoding 1 (float32), the resolution and channel count, bounds (−1,−2,−3)…(1,2,3).
inline VolBytes volHeader(int x, int y, int z, int channels) {
  VolBytes b;
  b.i32(1);
  b.i32(x); b.i32(y); b.i32(z);
  b.i32(channels);
  for (float f : {-1.f, -2.f, -3.f, 1.f, 2.f, 3.f}) b.f32(f);
  return b;
}

// A single-channel grid of nx·ny·nz samples, value(i, j, k) at each, x fastest.
inline std::string volGrid(int nx, int ny, int nz, const std::function<float(int, int, int)>& value) {
  VolBytes b = volHeader(nx, ny, nz, 1);
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) b.f32(value(i, j, k));
  return b.s;
}

}  // namespace rc::test
