#pragma once
// A progress bar with ETA on stderr: redrawn at most 10×/s on a terminal, every 10% otherwise
// (so logs stay short), silent when quiet.
#include <chrono>
#include <mutex>
#include <string>

namespace rc {

class ProgressBar {
 public:
  explicit ProgressBar(bool quiet);
  ~ProgressBar();
  // Thread-safe; `phase` starts a new bar when it changes.
  void update(const std::string& phase, double done, double total);
  void finish();

 private:
  bool quiet_, tty_;
  std::mutex mutex_;
  std::string phase_;
  std::chrono::steady_clock::time_point phaseStart_, lastDraw_;
  int lastDecile_ = -1;
  bool open_ = false;
};

}  // namespace rc
