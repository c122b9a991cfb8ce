#include "experiments/sweeps/progress.h"

#include <algorithm>
#include <cmath>

namespace vigil::experiments {

std::string FormatDuration(double seconds) {
  const long s = std::lround(std::max(0.0, seconds));
  char buf[32];
  if (s < 60) {
    std::snprintf(buf, sizeof buf, "%lds", s);
  } else if (s < 3600) {
    std::snprintf(buf, sizeof buf, "%ldm%02lds", s / 60, s % 60);
  } else {
    std::snprintf(buf, sizeof buf, "%ldh%02ldm", s / 3600, (s % 3600) / 60);
  }
  return buf;
}

std::string FormatProgressLine(const ProgressState& st, int bar_width) {
  const double fraction = st.total ? static_cast<double>(st.done) / static_cast<double>(st.total) : 1.0;
  const int filled = static_cast<int>(std::floor(fraction * bar_width));
  std::string line = "[" + std::string(filled, '#') + std::string(bar_width - filled, '.') + "] ";
  line += std::to_string(st.done) + "/" + std::to_string(st.total) + " runs";
  if (st.resumed) line += " (" + std::to_string(st.resumed) + " resumed)";
  line += ", " + std::to_string(st.failed) + " failed, " + FormatDuration(st.elapsed_s) + " elapsed, ETA ";
  const std::size_t executed = st.done - st.resumed;
  if (st.done == st.total) {
    line += "0s";
  } else if (executed == 0) {
    line += "--";
  } else {
    line += FormatDuration(st.elapsed_s / static_cast<double>(executed) *
                           static_cast<double>(st.total - st.done));
  }
  return line;
}

ProgressBar::ProgressBar(std::size_t total, std::FILE* out)
    : out_(out), start_(std::chrono::steady_clock::now()), last_draw_(start_) {
  state_.total = total;
  std::lock_guard<std::mutex> lock(mutex_);
  DrawLocked(true);
}

void ProgressBar::Finished(bool resumed, bool failed) {
  std::lock_guard<std::mutex> lock(mutex_);
  ++state_.done;
  if (resumed) ++state_.resumed;
  if (failed) ++state_.failed;
  DrawLocked(false);
}

void ProgressBar::Close() {
  std::lock_guard<std::mutex> lock(mutex_);
  if (closed_) return;
  DrawLocked(true);
  if (out_) std::fputc('\n', out_);
  closed_ = true;
}

ProgressState ProgressBar::state() const {
  std::lock_guard<std::mutex> lock(mutex_);
  ProgressState s = state_;
  s.elapsed_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  return s;
}

void ProgressBar::DrawLocked(bool force) {
  const auto now = std::chrono::steady_clock::now();
  state_.elapsed_s = std::chrono::duration<double>(now - start_).count();
  if (!out_ || (!force && now - last_draw_ < std::chrono::milliseconds(100))) return;
  last_draw_ = now;
  std::fprintf(out_, "\r%s\x1b[K", FormatProgressLine(state_).c_str());
  std::fflush(out_);
}

}  // namespace vigil::experiments
