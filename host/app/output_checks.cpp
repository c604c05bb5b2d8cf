#include "app/output_checks.h"

#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <utility>
#include <vector>

#include "core/error.h"
#include "image/image_file.h"
#include "image/oiio_module.h"

namespace rc {

std::string parentDirectory(const std::string& path) {
  const size_t slash = path.find_last_of('/');
  if (slash == std::string::npos) return ".";
  return slash == 0 ? "/" : path.substr(0, slash);
}

namespace {

void checkWritableTarget(const std::string& option, const std::string& path) {
  if (path.empty() || path.back() == '/') throw Error(option + " " + path + ": names a directory, not a file");
  struct stat st {};
  if (stat(path.c_str(), &st) == 0) {
    if (S_ISDIR(st.st_mode)) throw Error(option + " " + path + ": is a directory");
    // rename(2) over a device or FIFO would replace it (as root) or fail after the render.
    if (!S_ISREG(st.st_mode)) throw Error(option + " " + path + ": is not a regular file");
  }
  const std::string dir = parentDirectory(path);
  struct stat ds {};
  if (stat(dir.c_str(), &ds) != 0 || !S_ISDIR(ds.st_mode))
    throw Error(option + " " + path + ": directory '" + dir + "' is not writable (it does not exist)");
  if (access(dir.c_str(), W_OK) != 0) throw Error(option + " " + path + ": directory '" + dir + "' is not writable");
}

// Same file for two options: compared after resolving symlinks and "..", so -o a.exr and
// --stats ./a.exr collide as well.
std::string identity(const std::string& path) {
  std::error_code ec;
  const std::filesystem::path p = std::filesystem::weakly_canonical(std::filesystem::absolute(path, ec), ec);
  return ec ? path : p.string();
}

}  // namespace

void checkOutputs(const RenderArgs& args, const std::string& imagePath) {
  const std::string ext = lowerExtension(imagePath);
  if (ext != ".exr" && ext != ".png" && ext != ".hdr")
    throw Error(imagePath + ": unsupported output format (use .exr, .png or .hdr)");
  // PNG and HDR are written through the OpenImageIO module: load it now, so that a missing module
  // is an error before the render instead of after it.
  if (ext != ".exr") oiioModule();
  std::vector<std::pair<std::string, std::string>> targets{{"-o", imagePath}};
  if (!args.statsPath.empty()) targets.emplace_back("--stats", args.statsPath);
  if (!args.cacheSave.empty()) targets.emplace_back("--cache-save", args.cacheSave);
  for (const auto& [option, path] : targets) checkWritableTarget(option, path);
  for (size_t i = 0; i < targets.size(); ++i)
    for (size_t j = i + 1; j < targets.size(); ++j)
      if (identity(targets[i].second) == identity(targets[j].second))
        throw Error(targets[i].first + " and " + targets[j].first + " name the same file '" + targets[j].second +
                    "': one would overwrite the other");
}

}  // namespace rc
