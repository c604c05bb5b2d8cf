#include "core/atomic_file.h"

#include <dirent.h>
#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <thread>

#include "core/error.h"

namespace rc {

namespace {

// Registered temporaries: fixed slots of fixed-size names so the signal handler reads them
// without locks or allocation. A slot is claimed by writing its name, then publishing `used`.
constexpr int kSlots = 8;
constexpr size_t kNameMax = 4096;
struct Slot {
  std::atomic<bool> used{false};
  char name[kNameMax];
};
Slot gSlots[kSlots];

void registerTemporary(const std::string& tmp) {
  if (tmp.size() >= kNameMax) return;
  for (Slot& s : gSlots) {
    if (s.used.load()) continue;
    std::memcpy(s.name, tmp.c_str(), tmp.size() + 1);
    s.used.store(true);
    return;
  }
}

void unregisterTemporary(const std::string& tmp) {
  for (Slot& s : gSlots)
    if (s.used.load() && tmp == s.name) s.used.store(false);
}

struct NameParts {
  std::string dir, stem, ext;  // dir ends with '/' or is empty
};

NameParts splitName(const std::string& path) {
  const size_t slash = path.find_last_of('/');
  NameParts n;
  n.dir = slash == std::string::npos ? "" : path.substr(0, slash + 1);
  const std::string base = slash == std::string::npos ? path : path.substr(slash + 1);
  // Keep the extension last: image writers choose the format from it.
  const size_t dot = base.find_last_of('.');
  n.stem = dot == std::string::npos ? base : base.substr(0, dot);
  n.ext = dot == std::string::npos ? "" : base.substr(dot);
  return n;
}

bool processRuns(long pid) { return pid > 0 && (kill(static_cast<pid_t>(pid), 0) == 0 || errno == EPERM); }

// Removes ".STEM.tmpPID.EXT" beside path whose PID no longer runs (left by a killed process).
void removeStaleTemporaries(const std::string& path) {
  const NameParts n = splitName(path);
  const std::string prefix = "." + n.stem + ".tmp";
  DIR* dir = opendir(n.dir.empty() ? "." : n.dir.c_str());
  if (!dir) return;
  while (const dirent* e = readdir(dir)) {
    const std::string name = e->d_name;
    if (name.size() <= prefix.size() + n.ext.size() || name.compare(0, prefix.size(), prefix) != 0 ||
        name.compare(name.size() - n.ext.size(), n.ext.size(), n.ext) != 0)
      continue;
    const std::string digits = name.substr(prefix.size(), name.size() - prefix.size() - n.ext.size());
    if (digits.empty() || digits.find_first_not_of("0123456789") != std::string::npos || digits.size() > 18) continue;
    const long pid = std::strtol(digits.c_str(), nullptr, 10);
    if (pid == static_cast<long>(getpid()) || processRuns(pid)) continue;
    std::remove((n.dir + name).c_str());
  }
  closedir(dir);
}

// RC_TEST_COMMIT_DELAY_MS (tests only, tests/cli/hostile_tests.sh): waits this long before each
// rename, so a test can deliver a signal while a finished temporary awaits its commit.
void testCommitDelay() {
  const char* v = std::getenv("RC_TEST_COMMIT_DELAY_MS");
  if (!v || !*v) return;
  const long ms = std::strtol(v, nullptr, 10);
  if (ms > 0 && ms <= 60000) std::this_thread::sleep_for(std::chrono::milliseconds(ms));
}

std::string errnoText() { return std::strerror(errno); }

}  // namespace

std::string temporaryName(const std::string& path, long pid) {
  const NameParts n = splitName(path);
  return n.dir + "." + n.stem + ".tmp" + std::to_string(pid) + n.ext;
}

std::string beginTemporary(const std::string& path) {
  removeStaleTemporaries(path);
  const std::string tmp = temporaryName(path, static_cast<long>(getpid()));
  registerTemporary(tmp);
  return tmp;
}

void syncTemporary(const std::string& tmp, const std::string& path) {
  const int fd = open(tmp.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) throw Error(path + ": cannot write (" + errnoText() + ")");
  const bool ok = fsync(fd) == 0 || errno == EINVAL || errno == EROFS;  // EINVAL: no sync on this file system
  const std::string why = ok ? "" : errnoText();
  close(fd);
  if (!ok) throw Error(path + ": cannot write (" + why + ")");
}

void abandonTemporary(const std::string& tmp) {
  std::remove(tmp.c_str());
  unregisterTemporary(tmp);
}

void commitTemporary(const std::string& tmp, const std::string& path) {
  testCommitDelay();
  if (std::rename(tmp.c_str(), path.c_str()) != 0) {
    const std::string why = errnoText();
    abandonTemporary(tmp);
    throw Error(path + ": cannot write (" + why + ")");
  }
  unregisterTemporary(tmp);
}

void removeRegisteredTemporaries() {
  for (Slot& s : gSlots)
    if (s.used.load()) unlink(s.name);
}

void writeFileAtomically(const std::string& path, const std::string& bytes) {
  const std::string tmp = beginTemporary(path);
  const int fd = open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) {
    const std::string why = errnoText();
    unregisterTemporary(tmp);
    throw Error(path + ": cannot write (" + why + ")");
  }
  // Every error of write, fsync and close counts: a full disk may show at any of them.
  size_t done = 0;
  std::string why;
  while (done < bytes.size()) {
    const ssize_t n = write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      why = n < 0 ? errnoText() : "no progress";
      break;
    }
    done += static_cast<size_t>(n);
  }
  if (why.empty() && fsync(fd) != 0 && errno != EINVAL && errno != EROFS) why = errnoText();
  if (close(fd) != 0 && why.empty()) why = errnoText();
  struct stat st {};
  if (why.empty() && (stat(tmp.c_str(), &st) != 0 || static_cast<size_t>(st.st_size) != bytes.size()))
    why = "the written file has the wrong size";
  if (!why.empty()) {
    abandonTemporary(tmp);
    throw Error(path + ": cannot write (" + why + ")");
  }
  commitTemporary(tmp, path);
}

}  // namespace rc
