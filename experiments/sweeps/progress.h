// A one-line progress bar on a terminal: done/total, resumed, failures, elapsed time and ETA.
//
// Thread-safe: workers report each finished run; the line is redrawn in place ("\r") at most every 100 ms
// and once more, with a newline, by Close(). A null stream makes it silent (not a terminal, or --quiet).
#pragma once

#include <chrono>
#include <cstddef>
#include <cstdio>
#include <mutex>
#include <string>

namespace vigil::experiments {

struct ProgressState {
  std::size_t total = 0;
  std::size_t done = 0;     // finished runs, resumed ones included
  std::size_t resumed = 0;  // finished before this invocation (--resume): they do not count for the ETA
  std::size_t failed = 0;
  double elapsed_s = 0.0;
};

// "3s", "4m05s", "2h03m".
std::string FormatDuration(double seconds);

// "[#######.............]  12/40 runs (3 resumed), 1 failed, 0m42s elapsed, ETA 1m38s". The ETA extrapolates
// the time per run executed so far to the runs left; "ETA --" before the first one.
std::string FormatProgressLine(const ProgressState& state, int bar_width = 24);

class ProgressBar {
 public:
  ProgressBar(std::size_t total, std::FILE* out);
  // One more run finished (resumed: found already done on disk).
  void Finished(bool resumed, bool failed);
  // Draws the final line and ends it with a newline (once; also done by the destructor).
  void Close();
  ~ProgressBar() { Close(); }
  ProgressBar(const ProgressBar&) = delete;
  ProgressBar& operator=(const ProgressBar&) = delete;

  ProgressState state() const;

 private:
  void DrawLocked(bool force);

  std::FILE* out_;
  std::chrono::steady_clock::time_point start_, last_draw_;
  mutable std::mutex mutex_;
  ProgressState state_;
  bool closed_ = false;
};

}  // namespace vigil::experiments
