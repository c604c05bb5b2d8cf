// libFuzzer entry point for the scene loader and the mesh readers (issue 7). Not built by default
// and not part of CI; the deterministic suite is tests/scene/fuzz_test.cpp.
//
//   cmake -S . -B build-fuzz -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_C_COMPILER=clang \
//         -DCMAKE_BUILD_TYPE=RelWithDebInfo -DRC_FUZZ=ON -DRC_BUILD_TESTS=OFF -DRC_BUILD_BENCH=OFF
//   cmake --build build-fuzz -j2 --target fuzz_scene
//   mkdir -p fuzz-corpus && build-fuzz/fuzz_scene -max_len=8192 -timeout=5 fuzz-corpus scenes scenes/stress tests/cli/data
//
// The first byte picks the reader (0: scene XML, 1: OBJ, 2: PLY, by value mod 3; 0xFF: a deeply
// nested scene built from the rest, see deeplyNested; 0xFE: a chain of <ref>s, see refChain); the rest is the file. Shipped .xml files work as seeds as they are ('<' mod 3 = 0). Contract: the reader returns
// or throws rc::Error; any other exception escapes and libFuzzer reports it as a crash, as it
// does ASan/UBSan findings and inputs that run past -timeout.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

#include "core/error.h"
#include "scene/obj_loader.h"
#include "scene/ply_loader.h"
#include "scene/scene_loader.h"

namespace {

const std::filesystem::path& workDir() {
  static const std::filesystem::path dir = [] {
    const auto d = std::filesystem::temp_directory_path() / ("rc_fuzz_scene_" + std::to_string(::getpid()));
    std::filesystem::create_directories(d / "meshes");
    // Tiny stand-ins for the meshes the shipped scenes name, so seeds load their shapes.
    const char* obj = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//1 3//1 4//1\n";
    for (const char* name : {"cone.obj", "torus.obj", "uv_sphere.obj"}) std::ofstream(d / "meshes" / name) << obj;
    return d;
  }();
  return dir;
}

// Deep nesting (first byte 0xFF): bytes 1–3 give a depth up to 2^18, byte 4 the element that
// nests, the rest goes inside the innermost one. The loader must refuse what is too deep with a
// message, not overflow its stack in a recursive pass.
std::string deeplyNested(const uint8_t* data, size_t size) {
  static const char* const kOpen[] = {"<bsdf type=\"twosided\">", "<bsdf type=\"blendbsdf\">", "<shape type=\"sphere\">",
                                      "<texture type=\"checkerboard\">", "<transform name=\"to_world\">", "<group>"};
  static const char* const kClose[] = {"</bsdf>", "</bsdf>", "</shape>", "</texture>", "</transform>", "</group>"};
  const size_t depth = size > 3 ? ((size_t(data[1]) << 10) | (size_t(data[2]) << 2) | (data[3] & 3)) : 0;
  const size_t kind = size > 4 ? data[4] % 6 : 0;
  std::string xml = "<scene version=\"3.0.0\">";
  for (size_t i = 0; i < depth; ++i) xml += kOpen[kind];
  if (size > 5) xml.append(reinterpret_cast<const char*>(data) + 5, size - 5);
  for (size_t i = 0; i < depth; ++i) xml += kClose[kind];
  return xml + "</scene>";
}

// <ref> chains (first byte 0xFE): byte 1 the chain's length (×4), byte 2 how many refs each
// blend holds to the previous one (1 or 2: linear depth or exponential visits), the rest goes
// into the last BSDF. The loader must bound both with a message.
std::string refChain(const uint8_t* data, size_t size) {
  const size_t length = size > 1 ? size_t(data[1]) * 4 : 0;
  const bool twice = size > 2 && (data[2] & 1);
  std::string xml = "<scene version=\"3.0.0\"><bsdf type=\"diffuse\" id=\"b0\"/>";
  for (size_t i = 1; i <= length; ++i) {
    const std::string prev = "<ref id=\"b" + std::to_string(i - 1) + "\"/>";
    xml += "<bsdf type=\"blendbsdf\" id=\"b" + std::to_string(i) + "\">" + prev + (twice ? prev : "<bsdf type=\"diffuse\"/>");
    if (i == length && size > 3) xml.append(reinterpret_cast<const char*>(data) + 3, size - 3);
    xml += "</bsdf>";
  }
  return xml + "<shape type=\"sphere\"><ref id=\"b" + std::to_string(length) + "\"/></shape></scene>";
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size == 0) return 0;
  if (data[0] == 0xFF || data[0] == 0xFE) {
    const std::filesystem::path path = workDir() / "deep.xml";
    std::ofstream(path, std::ios::binary | std::ios::trunc) << (data[0] == 0xFF ? deeplyNested(data, size) : refChain(data, size));
    try {
      rc::loadScene(path.string());
    } catch (const rc::Error&) {
    }
    return 0;
  }
  const int kind = data[0] % 3;
  static const char* const kNames[] = {"case.xml", "case.obj", "case.ply"};
  const std::filesystem::path path = workDir() / kNames[kind];
  {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data) + (kind == 0 ? 0 : 1), static_cast<std::streamsize>(size - (kind == 0 ? 0 : 1)));
  }
  try {
    if (kind == 0) rc::loadScene(path.string());
    else if (kind == 1) rc::loadObj(path.string(), true);
    else rc::loadPly(path.string());
  } catch (const rc::Error&) {
    // Rejecting bad input with a message is the correct outcome.
  }
  return 0;
}
