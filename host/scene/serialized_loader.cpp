#include "scene/serialized_loader.h"
#include "core/regular_file.h"

#include <zlib.h>

#include <cstdint>
#include <cstring>
#include <vector>

#include "core/error.h"

namespace rc {

namespace {

constexpr uint16_t kMagic = 0x041C;
constexpr uint32_t kHasNormals = 0x0001, kHasUvs = 0x0002, kHasColors = 0x0008, kDouble = 0x2000;

template <class T>
T readLittle(const unsigned char* p) {
  T v{};
  for (size_t i = 0; i < sizeof(T); ++i) v = static_cast<T>(v | (static_cast<T>(p[i]) << (8 * i)));
  return v;
}

// Inflates the zlib stream starting at `offset` on demand, so a header claiming 10^12 vertices
// fails when the data runs out instead of allocating for it.
class Inflater {
 public:
  Inflater(const std::string& path, const std::string& file, size_t offset) : path_(path) {
    std::memset(&z_, 0, sizeof(z_));
    if (inflateInit(&z_) != Z_OK) fail("cannot initialise zlib");
    z_.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(file.data() + offset));
    z_.avail_in = static_cast<uInt>(file.size() - offset);
  }
  ~Inflater() { inflateEnd(&z_); }
  Inflater(const Inflater&) = delete;
  Inflater& operator=(const Inflater&) = delete;

  void read(void* out, size_t bytes, const char* what) {
    unsigned char* dst = static_cast<unsigned char*>(out);
    while (bytes > 0) {
      const size_t chunk = std::min<size_t>(bytes, 1u << 30);
      z_.next_out = dst;
      z_.avail_out = static_cast<uInt>(chunk);
      while (z_.avail_out > 0) {
        const int rc = inflate(&z_, Z_NO_FLUSH);
        if (rc == Z_STREAM_END && z_.avail_out > 0) fail(std::string("the data ends inside the ") + what);
        if (rc != Z_OK && rc != Z_STREAM_END)
          fail(std::string("corrupt compressed data in the ") + what + (z_.msg ? std::string(" (") + z_.msg + ")" : ""));
      }
      dst += chunk;
      bytes -= chunk;
    }
  }
  template <class T>
  T value(const char* what) {
    unsigned char b[sizeof(T)];
    read(b, sizeof(T), what);
    return readLittle<T>(b);
  }
  // Reads n·dim reals (float or double) and appends them to `out` as they arrive (null: read past
  // them), so memory grows with the data actually present, not with the counts a header claims.
  void reals(size_t n, int dim, bool doubles, std::vector<float>* out, const char* what) {
    const size_t width = doubles ? 8 : 4;
    std::vector<unsigned char> chunk;
    for (size_t done = 0; done < n * dim;) {
      const size_t count = std::min<size_t>(n * dim - done, 1u << 16);
      chunk.resize(count * width);
      read(chunk.data(), chunk.size(), what);
      for (size_t i = 0; out && i < count; ++i) {
        float f;
        if (doubles) {
          const uint64_t bits = readLittle<uint64_t>(&chunk[i * 8]);
          double d;
          std::memcpy(&d, &bits, 8);
          f = static_cast<float>(d);
        } else {
          const uint32_t bits = readLittle<uint32_t>(&chunk[i * 4]);
          std::memcpy(&f, &bits, 4);
        }
        out->push_back(f);
      }
      done += count;
    }
  }
  [[noreturn]] void fail(const std::string& what) const { throw Error(path_ + ": " + what); }

 private:
  std::string path_;
  z_stream z_;
};

}  // namespace

MeshData loadSerialized(const std::string& path, int shapeIndex) {
  const std::string file = readRegularFile(path, "mesh file");
  auto fail = [&](const std::string& what) -> void { throw Error(path + ": " + what); };
  const auto* bytes = reinterpret_cast<const unsigned char*>(file.data());
  if (file.size() < 4 || readLittle<uint16_t>(bytes) != kMagic) fail("not a Mitsuba serialized mesh (bad magic number)");
  const uint16_t version = readLittle<uint16_t>(bytes + 2);
  if (version != 3 && version != 4)
    fail("serialized version " + std::to_string(version) + " is not supported (versions 3 and 4 are)");
  if (shapeIndex < 0) fail("'shape_index' must be non-negative");

  size_t offset = 0;
  if (shapeIndex > 0) {
    if (file.size() < 8) fail("the file has no shape table");
    const uint32_t count = readLittle<uint32_t>(bytes + file.size() - 4);
    if (static_cast<uint32_t>(shapeIndex) >= count)
      fail("shape_index " + std::to_string(shapeIndex) + " is out of range (the file has " + std::to_string(count) + " shapes)");
    const size_t entry = version == 4 ? 8 : 4;
    const size_t back = entry * (count - static_cast<size_t>(shapeIndex)) + 4;
    if (back > file.size()) fail("the shape table is larger than the file");
    const unsigned char* at = bytes + file.size() - back;
    const uint64_t o = version == 4 ? readLittle<uint64_t>(at) : readLittle<uint32_t>(at);
    if (o + 4 > file.size()) fail("shape " + std::to_string(shapeIndex) + " starts beyond the end of the file");
    if (readLittle<uint16_t>(bytes + o) != kMagic || readLittle<uint16_t>(bytes + o + 2) != version)
      fail("shape " + std::to_string(shapeIndex) + " has no valid header");
    offset = static_cast<size_t>(o);
  }

  Inflater z(path, file, offset + 4);
  const uint32_t flags = z.value<uint32_t>("flags");
  if (version == 4) {
    for (size_t n = 0; z.value<char>("shape name") != 0; ++n)
      if (n > (1u << 20)) fail("the shape name is not terminated");
  }
  const uint64_t vertices = z.value<uint64_t>("vertex count");
  const uint64_t triangles = z.value<uint64_t>("triangle count");
  // zlib expands at most ~1032:1, so counts beyond that bound cannot be in this file.
  const double bound = 1100.0 * static_cast<double>(file.size());
  if (double(vertices) * 12.0 > bound || double(triangles) * 12.0 > bound)
    fail("vertex/triangle counts (" + std::to_string(vertices) + ", " + std::to_string(triangles) +
         ") exceed what the file can hold");
  const bool doubles = flags & kDouble;
  std::vector<float> positions, normals, uvs;
  z.reals(vertices, 3, doubles, &positions, "positions");
  if (flags & kHasNormals) z.reals(vertices, 3, doubles, &normals, "normals");
  if (flags & kHasUvs) z.reals(vertices, 2, doubles, &uvs, "texture coordinates");
  if (flags & kHasColors) z.reals(vertices, 3, doubles, nullptr, "vertex colours");
  MeshData mesh;
  for (size_t i = 0; i < vertices; ++i) {
    mesh.positions.emplace_back(positions[3 * i], positions[3 * i + 1], positions[3 * i + 2]);
    if (!normals.empty()) mesh.normals.emplace_back(normals[3 * i], normals[3 * i + 1], normals[3 * i + 2]);
    if (!uvs.empty()) mesh.uvs.emplace_back(uvs[2 * i], uvs[2 * i + 1]);
  }
  unsigned char raw[12];
  for (uint64_t t = 0; t < triangles; ++t) {
    z.read(raw, 12, "triangle indices");
    const glm::uvec3 tri(readLittle<uint32_t>(&raw[0]), readLittle<uint32_t>(&raw[4]), readLittle<uint32_t>(&raw[8]));
    if (tri.x >= vertices || tri.y >= vertices || tri.z >= vertices)
      fail("triangle " + std::to_string(t) + " has a vertex index out of range (" + std::to_string(vertices) + " vertices)");
    mesh.triangles.push_back(tri);
  }
  return mesh;
}

}  // namespace rc
