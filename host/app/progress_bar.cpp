#include "app/progress_bar.h"

#include <unistd.h>

#include <cmath>
#include <cstdio>

namespace rc {

ProgressBar::ProgressBar(bool quiet) : quiet_(quiet), tty_(isatty(STDERR_FILENO) == 1) {}

ProgressBar::~ProgressBar() { finish(); }

static std::string formatSeconds(double s) {
  char buf[32];
  if (!std::isfinite(s) || s < 0) return "--";
  if (s < 60) std::snprintf(buf, sizeof buf, "%.1fs", s);
  else if (s < 3600) std::snprintf(buf, sizeof buf, "%dm%02ds", int(s) / 60, int(s) % 60);
  else std::snprintf(buf, sizeof buf, "%dh%02dm", int(s) / 3600, (int(s) / 60) % 60);
  return buf;
}

void ProgressBar::update(const std::string& phase, double done, double total) {
  if (quiet_) return;
  std::lock_guard<std::mutex> lock(mutex_);
  const auto now = std::chrono::steady_clock::now();
  if (phase != phase_) {
    if (open_) std::fputc('\n', stderr);
    open_ = false;
    phase_ = phase;
    phaseStart_ = now;
    lastDecile_ = -1;
    lastDraw_ = now - std::chrono::seconds(1);
  }
  const double frac = total > 0 ? std::fmin(1.0, std::fmax(0.0, done / total)) : 0.0;
  const int decile = static_cast<int>(frac * 10);
  if (tty_) {
    if (frac < 1.0 && now - lastDraw_ < std::chrono::milliseconds(100)) return;
  } else if (decile == lastDecile_) {
    return;
  }
  lastDraw_ = now;
  lastDecile_ = decile;
  const double elapsed = std::chrono::duration<double>(now - phaseStart_).count();
  const double eta = frac > 0 ? elapsed * (1.0 - frac) / frac : NAN;
  const int width = 30, filled = static_cast<int>(frac * width + 0.5);
  std::string bar(filled, '#');
  bar += std::string(width - filled, '.');
  std::fprintf(stderr, "%s%-14s [%s] %5.1f%%  elapsed %s  ETA %s%s", tty_ ? "\r" : "", phase.c_str(), bar.c_str(),
               frac * 100.0, formatSeconds(elapsed).c_str(), formatSeconds(eta).c_str(), tty_ ? "   " : "\n");
  open_ = tty_;
  std::fflush(stderr);
}

void ProgressBar::finish() {
  if (quiet_) return;
  std::lock_guard<std::mutex> lock(mutex_);
  if (open_) std::fputc('\n', stderr);
  open_ = false;
}

}  // namespace rc
