#pragma once
// Writes a whole file or nothing: data goes to a temporary file beside the target, which is
// renamed over it only after a successful write (rename is atomic within one directory).
// Temporaries are named ".STEM.tmpPID.EXT". While one exists it is registered, so a signal
// handler can remove it before the process dies (removeRegisteredTemporaries); one left by a
// killed process (SIGKILL, power loss) is a hidden file no reader opens, and the next write of
// the same name removes it once its PID no longer runs.
#include <string>

namespace rc {

// Throws rc::Error naming `path` when the directory is not writable or the write fails. The
// data is flushed to disk (fsync) and the temporary's size checked before the rename.
void writeFileAtomically(const std::string& path, const std::string& bytes);
// Temporary name beside `path` for writers that produce the file themselves (image codecs):
// removes stale temporaries of `path` and registers the new one.
std::string beginTemporary(const std::string& path);
// fsync(2) of a finished temporary; throws rc::Error naming `path` (ENOSPC, EIO surface here
// on file systems that report them late).
void syncTemporary(const std::string& tmp, const std::string& path);
// Renames tmp over path (throws rc::Error, removes tmp on failure) and unregisters it.
void commitTemporary(const std::string& tmp, const std::string& path);
// Removes tmp (if it exists) and unregisters it.
void abandonTemporary(const std::string& tmp);
// Async-signal-safe: unlinks every registered temporary (for a handler about to _exit).
void removeRegisteredTemporaries();
// The temporary name beside `path` for process `pid` (what beginTemporary uses with getpid()).
std::string temporaryName(const std::string& path, long pid);

}  // namespace rc
