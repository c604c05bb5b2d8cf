#include "core/regular_file.h"

#include <sys/stat.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>

#include "core/error.h"

namespace rc {

void requireRegularFile(const std::string& path, const std::string& what) {
  struct stat st {};
  if (stat(path.c_str(), &st) != 0) throw Error("cannot open " + what + " '" + path + "' (" + std::strerror(errno) + ")");
  if (S_ISDIR(st.st_mode)) throw Error("cannot open " + what + " '" + path + "': it is a directory");
  if (!S_ISREG(st.st_mode)) throw Error("cannot open " + what + " '" + path + "': not a regular file");
}

std::string readRegularFile(const std::string& path, const std::string& what) {
  requireRegularFile(path, what);
  std::ifstream in(path, std::ios::binary);
  std::ostringstream contents;
  if (in) contents << in.rdbuf();
  if (!in || in.bad()) throw Error("cannot open " + what + " '" + path + "' (" + std::strerror(errno) + ")");
  return contents.str();
}

std::string irregularFileReason(const std::string& path) {
  struct stat st {};
  if (stat(path.c_str(), &st) != 0) return "not found";
  if (S_ISDIR(st.st_mode)) return "it is a directory";
  return S_ISREG(st.st_mode) ? "" : "not a regular file";
}

}  // namespace rc
