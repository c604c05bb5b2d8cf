#pragma once
// Writes a whole file or nothing: data goes to a temporary file beside the target, which is
// renamed over it only after a successful write (rename is atomic within one directory).
#include <string>

namespace rc {

// Throws rc::Error naming `path` when the directory is not writable or the write fails.
void writeFileAtomically(const std::string& path, const std::string& bytes);
// Temporary name beside `path` used by writers that produce the file themselves (OIIO).
std::string temporarySibling(const std::string& path);
// Renames tmp over path (throws rc::Error, removes tmp on failure).
void commitTemporary(const std::string& tmp, const std::string& path);

}  // namespace rc
