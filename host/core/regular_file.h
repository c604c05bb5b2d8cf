#pragma once
// Inputs are read whole, so only regular files qualify: /dev/zero, /dev/urandom or a FIFO given
// as a scene, mesh, image or cache would be read forever (or block), and a directory would fail
// with a misleading message later ("bad magic", "parse error").
#include <string>

namespace rc {

// Throws rc::Error("<path>: cannot open <what> ...") when path is missing, a directory or
// anything but a regular file. `what` names the role: "scene file", "mesh file", ...
void requireRegularFile(const std::string& path, const std::string& what);

// The whole of a regular file (requireRegularFile's checks first). Throws rc::Error("cannot open
// <what> '<path>' ...") when it cannot be opened or read.
std::string readRegularFile(const std::string& path, const std::string& what);

// What keeps `path` from being read: "" for a regular file, else "not found", "it is a directory"
// or "not a regular file", for callers that word their own message.
std::string irregularFileReason(const std::string& path);

}  // namespace rc
