#pragma once
// Inputs are read whole, so only regular files qualify: /dev/zero, /dev/urandom or a FIFO given
// as a scene, mesh, image or cache would be read forever (or block), and a directory would fail
// with a misleading message later ("bad magic", "parse error").
#include <string>

namespace rc {

// Throws rc::Error("<path>: cannot open <what> ...") when path is missing, a directory or
// anything but a regular file. `what` names the role: "scene file", "mesh file", ...
void requireRegularFile(const std::string& path, const std::string& what);

}  // namespace rc
