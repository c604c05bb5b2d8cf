// Deterministic mutation fuzzing of the scene loader and the OBJ/PLY readers: bad input gets one message, never a crash or hang.
//
// Every shipped scene (scenes/*.xml, scenes/stress/*.xml, tests/cli/data/*.xml) and a few small
// OBJ/PLY files are mutated with a fixed seed (byte flips, truncation, duplicated/deleted lines,
// numbers replaced by nan/inf/-1/1e308/huge integers, deleted attributes, swapped tag names and
// values) and loaded. The contract: loadScene/loadObj/loadPly either return a well-formed result or
// throw rc::Error — never crash, never throw anything else, never take more than a moment.
// A watchdog aborts the binary (naming the case) if one case runs over kCaseSeconds.
//
// Reproduce one case: RC_FUZZ_CASE=<index> ./test_scene --gtest_filter='SceneFuzz.*' keeps
// that case's input in the temp folder and prints its path. RC_FUZZ_CASES=<n> scales the count.
// For open-ended, coverage-guided fuzzing see fuzz/fuzz_scene.cpp (libFuzzer, -DRC_FUZZ=ON).
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <sstream>
#include <thread>
#include <typeinfo>

#include "scene/obj_loader.h"
#include "scene/ply_loader.h"
#include "scene_test_util.h"

namespace rc::test {
namespace {

namespace fs = std::filesystem;

constexpr double kCaseSeconds = 5.0;

// splitmix64: a fixed, platform-independent stream (std distributions are implementation-defined).
struct Rng {
  uint64_t s;
  uint64_t next() {
    uint64_t z = (s += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
  }
  size_t below(size_t n) { return n == 0 ? 0 : static_cast<size_t>(next() % n); }
  template <class T, size_t N>
  const T& pick(const T (&a)[N]) { return a[below(N)]; }
};

// Aborts the process when the current case runs too long: a hang must fail loudly, not stall CI.
class Watchdog {
 public:
  Watchdog() : thread_([this] { run(); }) {}
  ~Watchdog() {
    {
      std::lock_guard<std::mutex> lock(m_);
      stop_ = true;
    }
    cv_.notify_all();
    thread_.join();
  }
  void start(const std::string& what) {
    std::lock_guard<std::mutex> lock(m_);
    what_ = what;
    started_ = std::chrono::steady_clock::now();
    busy_ = true;
  }
  void done() {
    std::lock_guard<std::mutex> lock(m_);
    busy_ = false;
  }

 private:
  void run() {
    std::unique_lock<std::mutex> lock(m_);
    while (!stop_) {
      cv_.wait_for(lock, std::chrono::milliseconds(200));
      if (busy_ && std::chrono::duration<double>(std::chrono::steady_clock::now() - started_).count() > kCaseSeconds) {
        std::fprintf(stderr, "fuzz case ran over %.0f s (hang?): %s\n", kCaseSeconds, what_.c_str());
        std::fflush(stderr);
        std::abort();
      }
    }
  }
  std::mutex m_;
  std::condition_variable cv_;
  bool stop_ = false, busy_ = false;
  std::string what_;
  std::chrono::steady_clock::time_point started_;
  std::thread thread_;
};

std::string readFile(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> out;
  std::string cur;
  for (char c : text) {
    cur += c;
    if (c == '\n') out.push_back(std::move(cur)), cur.clear();
  }
  if (!cur.empty()) out.push_back(cur);
  return out;
}

std::string join(const std::vector<std::string>& ls) {
  std::string s;
  for (const std::string& l : ls) s += l;
  return s;
}

bool isNumberChar(char c) { return (c >= '0' && c <= '9') || c == '.' || c == '-' || c == '+' || c == 'e' || c == 'E'; }

// Positions of the starts of numeric tokens (a digit not preceded by a number character or letter).
std::vector<size_t> numberStarts(const std::string& s) {
  std::vector<size_t> out;
  for (size_t i = 0; i < s.size(); ++i) {
    const bool digit = s[i] >= '0' && s[i] <= '9';
    const bool prevOk = i == 0 || !(isNumberChar(s[i - 1]) || std::isalpha(static_cast<unsigned char>(s[i - 1])));
    if (digit && prevOk) out.push_back(i);
    else if (s[i] == '-' && i + 1 < s.size() && s[i + 1] >= '0' && s[i + 1] <= '9' && prevOk) out.push_back(i);
  }
  return out;
}

size_t numberEnd(const std::string& s, size_t b) {
  size_t e = b;
  while (e < s.size() && isNumberChar(s[e])) ++e;
  return e;
}

const char* const kNumbers[] = {"nan", "inf", "-inf", "-1", "0", "-0", "1e308", "-1e308", "1e-320", "1e39",
                                "3.5e38", "99999999999999999999", "2147483647", "2147483648", "-2147483649",
                                "4294967296", "1000000000", "16385", "65536", "0x10", "1e", "--1", "", "1,2",
                                "1 2 3 4 5 6 7 8 9 10 11 12 13 14 15 16 17", "18446744073709551616"};
const char* const kTags[] = {"scene", "shape", "bsdf", "emitter", "sensor", "film", "sampler", "rfilter",
                             "integrator", "include", "default", "ref", "transform", "translate", "rotate",
                             "scale", "matrix", "lookat", "float", "integer", "rgb", "point", "vector", "string",
                             "boolean", "spectrum", "texture", "bogus"};
const char* const kSnippets[] = {
    "<include filename=\"case.xml\"/>",           // self-include: a cycle
    "<include filename=\"meshes\"/>",             // a folder
    "<include filename=\"meshes/cone.obj\"/>",    // not XML
    "<default name=\"a\" value=\"$a\"/>",         // self-reference
    "<default name=\"b\" value=\"$\"/>",
    "<ref id=\"nope\"/>",
    "<shape type=\"ply\"><string name=\"filename\" value=\"meshes/mesh.ply\"/></shape>",
    "<shape type=\"obj\"><string name=\"filename\" value=\"meshes\"/></shape>",
    "<shape type=\"obj\"><string name=\"filename\" value=\"/dev/null\"/></shape>",
    "<emitter type=\"envmap\"><string name=\"filename\" value=\"meshes/cone.obj\"/></emitter>",
    "<emitter type=\"envmap\"><string name=\"filename\" value=\"case.xml\"/></emitter>",
    "<transform name=\"to_world\"><matrix value=\"0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0\"/></transform>",
    "<transform name=\"to_world\"><scale value=\"0\"/></transform>",
    "<transform name=\"to_world\"><scale value=\"1e30\"/><scale value=\"1e30\"/></transform>",
    "<transform name=\"to_world\"><lookat origin=\"0,0,0\" target=\"0,1,0\" up=\"0,1,0\"/></transform>",
    "<float name=\"radius\" value=\"1e308\"/>",
    "<integer name=\"width\" value=\"99999999999\"/>",
    "<rgb name=\"reflectance\" value=\"1e39\"/>",
    "<![CDATA[ x ]]>",
    "<!-- -- -->",
    "&amp;&#0;&#xFFFFFF;",
    "\xef\xbb\xbf",
    "\xff\xfe\x00",
};

// Replaces the i-th `<name` tag opening (and, roughly, its matching closing tag) by another name.
std::string swapTag(const std::string& s, Rng& rng) {
  std::vector<size_t> opens;
  for (size_t i = 0; i + 1 < s.size(); ++i)
    if (s[i] == '<' && std::isalpha(static_cast<unsigned char>(s[i + 1]))) opens.push_back(i + 1);
  if (opens.empty()) return s;
  const size_t b = opens[rng.below(opens.size())];
  size_t e = b;
  while (e < s.size() && (std::isalnum(static_cast<unsigned char>(s[e])) || s[e] == '_')) ++e;
  const std::string old = s.substr(b, e - b), repl = rng.pick(kTags);
  std::string out = s.substr(0, b) + repl + s.substr(e);
  if (rng.below(2)) {  // also rename the matching closing tag, so the XML stays well-formed
    const size_t close = out.find("</" + old + ">", b);
    if (close != std::string::npos) out.replace(close + 2, old.size(), repl);
  }
  return out;
}

// Attributes `name="value"`: their [begin, end) ranges (leading space included) and value ranges.
struct Attr {
  size_t begin, end, valueBegin, valueEnd;
};
std::vector<Attr> attributes(const std::string& s) {
  std::vector<Attr> out;
  for (size_t q = s.find("=\""); q != std::string::npos; q = s.find("=\"", q + 2)) {
    size_t b = q;
    while (b > 0 && (std::isalnum(static_cast<unsigned char>(s[b - 1])) || s[b - 1] == '_')) --b;
    if (b == q || b == 0 || s[b - 1] != ' ') continue;
    const size_t ve = s.find('"', q + 2);
    if (ve == std::string::npos) break;
    out.push_back({b - 1, ve + 1, q + 2, ve});
  }
  return out;
}

// One random mutation of `s`. Text mutations suit both XML and OBJ/ASCII PLY; byte flips and
// truncation also exercise binary PLY.
std::string mutate(std::string s, Rng& rng, bool xml) {
  switch (rng.below(xml ? 12 : 8)) {
    case 0: {  // flip one bit
      if (s.empty()) return s;
      s[rng.below(s.size())] ^= static_cast<char>(1u << rng.below(8));
      return s;
    }
    case 1: {  // set a byte to a syntactically interesting one
      static const char kChars[] = "<>\"'/=$&;# \n\r\t\0-.e0123456789";
      if (s.empty()) return s;
      s[rng.below(s.size())] = kChars[rng.below(sizeof(kChars) - 1)];
      return s;
    }
    case 2:  // truncate
      return s.substr(0, rng.below(s.size() + 1));
    case 3: {  // duplicate a line (possibly many times)
      std::vector<std::string> ls = lines(s);
      if (ls.empty()) return s;
      const size_t i = rng.below(ls.size());
      const size_t copies = rng.below(4) == 0 ? 50 : 1;
      ls.insert(ls.begin() + static_cast<std::ptrdiff_t>(i), copies, ls[i]);
      return join(ls);
    }
    case 4: {  // delete a line
      std::vector<std::string> ls = lines(s);
      if (ls.empty()) return s;
      ls.erase(ls.begin() + static_cast<std::ptrdiff_t>(rng.below(ls.size())));
      return join(ls);
    }
    case 5:
    case 6: {  // replace a number by an extreme or malformed one
      const std::vector<size_t> starts = numberStarts(s);
      if (starts.empty()) return s;
      const size_t b = starts[rng.below(starts.size())];
      return s.substr(0, b) + rng.pick(kNumbers) + s.substr(numberEnd(s, b));
    }
    case 7: {  // swap two lines
      std::vector<std::string> ls = lines(s);
      if (ls.size() < 2) return s;
      std::swap(ls[rng.below(ls.size())], ls[rng.below(ls.size())]);
      return join(ls);
    }
    case 8: {  // delete an attribute
      const std::vector<Attr> as = attributes(s);
      if (as.empty()) return s;
      const Attr& a = as[rng.below(as.size())];
      return s.substr(0, a.begin) + s.substr(a.end);
    }
    case 9: {  // copy one attribute value over another (type="diffuse" → type="obj", name swaps, ...)
      const std::vector<Attr> as = attributes(s);
      if (as.empty()) return s;
      const Attr& from = as[rng.below(as.size())];
      const Attr& to = as[rng.below(as.size())];
      const std::string v = s.substr(from.valueBegin, from.valueEnd - from.valueBegin);
      return s.substr(0, to.valueBegin) + v + s.substr(to.valueEnd);
    }
    case 10:
      return swapTag(s, rng);
    default: {  // insert a snippet after some tag
      std::vector<size_t> ends;
      for (size_t i = 0; i < s.size(); ++i)
        if (s[i] == '>') ends.push_back(i + 1);
      const size_t at = ends.empty() ? 0 : ends[rng.below(ends.size())];
      return s.substr(0, at) + rng.pick(kSnippets) + s.substr(at);
    }
  }
}

std::string mutateSome(std::string s, Rng& rng, bool xml) {
  const size_t n = 1 + rng.below(4);
  for (size_t i = 0; i < n; ++i) s = mutate(std::move(s), rng, xml);
  return s;
}

// Small meshes, also written under the mesh names the shipped scenes use, so a mutated scene
// loads a mesh in microseconds rather than reading the 100 kB shipped ones thousands of times.
const std::string kObj =
    "# cube corner\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
    "vn 0 0 1\nvn 0 1 0\nf 1/1/1 2/2/1 3/3/1 4/4/1\nf -5//2 -4//2 -1//2\ng part\nf 1 2 5\n";
const std::string kPlyAscii =
    "ply\nformat ascii 1.0\ncomment tiny\nelement vertex 4\nproperty float x\nproperty float y\n"
    "property float z\nproperty float nx\nproperty float ny\nproperty float nz\nproperty float u\n"
    "property float v\nelement face 2\nproperty list uchar int vertex_indices\nend_header\n"
    "0 0 0 0 0 1 0 0\n1 0 0 0 0 1 1 0\n1 1 0 0 0 1 1 1\n0 1 0 0 0 1 0 1\n3 0 1 2\n4 0 2 3 1\n";

std::string plyBinary() {
  std::string s =
      "ply\nformat binary_little_endian 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
      "property float z\nelement face 2\nproperty list uchar uint vertex_indices\nend_header\n";
  const float v[12] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
  s.append(reinterpret_cast<const char*>(v), sizeof(v));
  const uint32_t f[2][3] = {{0, 1, 2}, {0, 2, 3}};
  for (const auto& t : f) {
    s += char(3);
    s.append(reinterpret_cast<const char*>(t), sizeof(t));
  }
  return s;
}

void writeMeshes(const TempDir& dir) {
  for (const char* name : {"meshes/cone.obj", "meshes/torus.obj", "meshes/uv_sphere.obj", "meshes/mesh.obj"})
    dir.write(name, kObj);
  dir.write("meshes/mesh.ply", kPlyAscii);
}

std::vector<std::string> shippedScenes() {
  std::vector<std::string> out;
  const fs::path root = RC_SOURCE_DIR;
  for (const fs::path folder : {root / "scenes", root / "scenes/stress", root / "tests/cli/data"}) {
    if (!fs::is_directory(folder)) continue;
    std::vector<fs::path> files;
    for (const auto& entry : fs::directory_iterator(folder))
      if (entry.path().extension() == ".xml") files.push_back(entry.path());
    std::sort(files.begin(), files.end());  // directory order is not deterministic
    for (const fs::path& f : files) out.push_back(readFile(f));
  }
  return out;
}

bool finite(const Vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// What a successfully read mesh must satisfy for the renderer to use it safely.
void checkMeshData(const MeshData& m, const std::string& what) {
  ASSERT_TRUE(m.normals.empty() || m.normals.size() == m.positions.size()) << what;
  ASSERT_TRUE(m.uvs.empty() || m.uvs.size() == m.positions.size()) << what;
  for (const glm::uvec3& t : m.triangles)
    ASSERT_TRUE(t.x < m.positions.size() && t.y < m.positions.size() && t.z < m.positions.size()) << what;
}

void checkScene(const Scene& s, const std::string& what) {
  ASSERT_TRUE(s.film.width >= 1 && s.film.width <= 16384 && s.film.height >= 1 && s.film.height <= 16384) << what;
  ASSERT_GE(s.sampler.sampleCount, 1) << what;
  ASSERT_TRUE(s.camera.fovDegrees > 0.0f && s.camera.fovDegrees < 180.0f) << what;
  ASSERT_TRUE(std::isfinite(s.camera.nearClip) && std::isfinite(s.camera.farClip)) << what;
  for (int c = 0; c < 4; ++c) ASSERT_TRUE(finite(Vec3(s.camera.toWorld[c]))) << what;
  for (const Mesh& m : s.meshes) {
    ASSERT_TRUE(m.normals.empty() || m.normals.size() == m.positions.size()) << what << " " << m.name;
    ASSERT_TRUE(m.uvs.empty() || m.uvs.size() == m.positions.size()) << what << " " << m.name;
    ASSERT_TRUE(m.bsdf >= 0 && m.bsdf < static_cast<int>(s.bsdfs.size())) << what << " " << m.name;
    for (const glm::uvec3& t : m.triangles) {
      ASSERT_TRUE(t.x < m.positions.size() && t.y < m.positions.size() && t.z < m.positions.size()) << what;
      ASSERT_TRUE(finite(m.positions[t.x]) && finite(m.positions[t.y]) && finite(m.positions[t.z])) << what << " " << m.name;
    }
  }
  for (const Sphere& sp : s.spheres) {
    ASSERT_TRUE(finite(sp.center) && std::isfinite(sp.radius) && sp.radius > 0.0f) << what << " " << sp.name;
    ASSERT_TRUE(sp.bsdf >= 0 && sp.bsdf < static_cast<int>(s.bsdfs.size())) << what << " " << sp.name;
  }
  for (const Emitter& e : s.emitters) {
    ASSERT_TRUE(finite(e.radiance) && finite(e.intensity) && finite(e.irradiance) && finite(e.position) &&
                finite(e.direction) && std::isfinite(e.scale))
        << what;
    ASSERT_EQ(e.envPixels.size(), size_t(e.envWidth) * size_t(e.envHeight)) << what;
  }
}

// Runs `load` on one input; fails the test on anything but success or rc::Error.
template <class F>
void runCase(Watchdog& dog, const std::string& what, F&& load) {
  dog.start(what);
  try {
    load();
  } catch (const Error&) {
    // The expected outcome for most mutations.
  } catch (const std::exception& e) {
    ADD_FAILURE() << what << ": threw " << typeid(e).name() << " (not rc::Error): " << e.what();
  } catch (...) {
    ADD_FAILURE() << what << ": threw a non-std exception";
  }
  dog.done();
}

int caseCount(int fallback) {
  const char* n = std::getenv("RC_FUZZ_CASES");
  return n ? std::max(1, std::atoi(n)) : fallback;
}
int onlyCase() {
  const char* n = std::getenv("RC_FUZZ_CASE");
  return n ? std::atoi(n) : -1;
}

TEST(SceneFuzz, MutatedShippedScenesLoadOrThrowRcError) {
  const std::vector<std::string> seeds = shippedScenes();
  ASSERT_GE(seeds.size(), 10u) << "shipped scenes not found under " << RC_SOURCE_DIR;
  TempDir dir;
  writeMeshes(dir);
  Watchdog dog;
  const int n = caseCount(3000), only = onlyCase();
  int loaded = 0;
  for (int i = 0; i < n; ++i) {
    if (only >= 0 && i != only) continue;
    Rng rng{0x5ce4e0000ull + static_cast<uint64_t>(i)};
    const std::string xml = mutateSome(seeds[rng.below(seeds.size())], rng, true);
    const std::string path = dir.write("case.xml", xml);
    if (only >= 0) std::printf("case %d input: %s\n", i, dir.write("kept_case.xml", xml).c_str());
    const std::string what = "scene case " + std::to_string(i) + " (RC_FUZZ_CASE=" + std::to_string(i) + ")";
    runCase(dog, what, [&] {
      LoadOptions options;
      options.lenient = (i % 4) == 3;  // lenient mode takes other paths (skipped plugins)
      std::vector<std::string> warnings;
      const Scene s = loadScene(path, options, &warnings);
      ++loaded;
      checkScene(s, what);
    });
    if (HasFatalFailure()) return;
  }
  // Sanity: the mutations are not so destructive that nothing ever loads.
  if (only < 0 && n >= 1000) EXPECT_GT(loaded, n / 20);
}

TEST(SceneFuzz, MutatedMeshFilesReadOrThrowRcError) {
  TempDir dir;
  Watchdog dog;
  const std::string seeds[] = {kObj, kPlyAscii, plyBinary()};
  const int n = caseCount(1500), only = onlyCase();
  for (int i = 0; i < n; ++i) {
    if (only >= 0 && i != only) continue;
    Rng rng{0x6e54000ull + static_cast<uint64_t>(i)};
    const size_t kind = static_cast<size_t>(i) % 3;
    const std::string text = mutateSome(seeds[kind], rng, false);
    const std::string path = dir.write(kind == 0 ? "case.obj" : "case.ply", text);
    if (only >= 0) std::printf("case %d input: %s\n", i, dir.write(kind == 0 ? "kept.obj" : "kept.ply", text).c_str());
    const std::string what = "mesh case " + std::to_string(i) + " (RC_FUZZ_CASE=" + std::to_string(i) + ")";
    runCase(dog, what, [&] {
      const MeshData m = kind == 0 ? loadObj(path, (i & 4) != 0) : loadPly(path);
      checkMeshData(m, what);
    });
    if (HasFatalFailure()) return;
  }
}

}  // namespace
}  // namespace rc::test

// Regressions for what the fuzzing found; each failed (crash, hang, foreign exception or a
// malformed Scene) before its fix.
namespace rc::test {
namespace {

TEST(SceneFuzzRegression, HugeVersionNumberIsNotStdOutOfRange) {
  TempDir dir;
  // std::stoi threw std::out_of_range (escaping every rc::Error handler).
  EXPECT_NO_THROW(loadText(dir, "<scene version=\"99999999999.0.0\"><sensor type=\"perspective\"/></scene>"));
  expectError([&] { loadText(dir, "<scene version=\"0001.0.0\"><sensor type=\"perspective\"/></scene>"); },
              {"scene.xml:1:", "Mitsuba 0.6 syntax"});
}

TEST(SceneFuzzRegression, IntegerBeyondIntRangeIsAnError) {
  TempDir dir;
  // static_cast<int>(99999999999.0) is undefined; it gave INT_MIN and a confusing "got -2147483648".
  const std::string film = "<sensor type=\"perspective\"><film type=\"hdrfilm\">\n"
                           "<integer name=\"width\" value=\"99999999999\"/></film></sensor>";
  expectError([&] { loadText(dir, sceneXml("", film)); }, {"scene.xml:2:", "'width' (line 3)", "out of range for a 32-bit integer"});
}

TEST(SceneFuzzRegression, FloatBeyondFloatRangeIsAnError) {
  TempDir dir;
  // 1e308 is a finite double but became an infinite sphere radius / colour / point.
  expectError([&] { loadText(dir, sceneXml("<shape type=\"sphere\">\n<float name=\"radius\" value=\"1e308\"/></shape>")); },
              {"scene.xml:4:", "1e+308 is out of range for a 32-bit float"});
  expectError([&] { loadText(dir, sceneXml("<bsdf type=\"diffuse\">\n<rgb name=\"reflectance\" value=\"0.5, 1e39, 0.5\"/></bsdf>")); },
              {"scene.xml:4:", "out of range for a 32-bit float"});
  expectError([&] { loadText(dir, sceneXml("<shape type=\"sphere\">\n<point name=\"center\" x=\"0\" y=\"-4e38\"/></shape>")); },
              {"scene.xml:4:", "out of range for a 32-bit float"});
}

TEST(SceneFuzzRegression, PlyVertexElementDeclaredTwiceIsAnError) {
  TempDir dir;
  // The second element appended vertices without normals: normals.size() != positions.size().
  const std::string ply =
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
      "property float nx\nproperty float ny\nproperty float nz\nelement vertex 1\nproperty float x\n"
      "property float y\nproperty float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
      "0 0 0 0 0 1\n1 0 0 0 0 1\n0 1 0 0 0 1\n5 5 5\n3 0 1 3\n";
  expectError([&] { loadPly(dir.write("twice.ply", ply)); }, {"twice.ply:10:", "element 'vertex' is declared twice"});
}

TEST(SceneFuzzRegression, PlyEmptyElementWithHugeCountIsFast) {
  TempDir dir;
  // An element without properties looped 2^62 times reading nothing.
  const std::string ply =
      "ply\nformat ascii 1.0\nelement junk 4611686018427387904\nelement vertex 3\nproperty float x\n"
      "property float y\nproperty float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
      "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
  const auto t0 = std::chrono::steady_clock::now();
  const MeshData m = loadPly(dir.write("junk.ply", ply));
  EXPECT_EQ(m.triangles.size(), 1u);
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), 1.0);
}

TEST(SceneFuzzRegression, PlyListLengthBeyondFileIsAnError) {
  TempDir dir;
  // static_cast<size_t>(1e300) is undefined (UBSan: float-cast-overflow).
  const std::string ply =
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
      "element face 1\nproperty list uint int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n1e300 0 1 2\n";
  expectError([&] { loadPly(dir.write("list.ply", ply)); }, {"list.ply:", "list length exceeds the file size"});
}

}  // namespace
}  // namespace rc::test
