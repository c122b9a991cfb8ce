// The mean of the last n values pushed into it (a ring buffer of n values and their running sum): the
// reference of the relative threshold and the `mean` replacement of the paper's threshold.
#pragma once

#include <vector>

namespace vigil::detectors {

class RunningMean {
 public:
  explicit RunningMean(int capacity = 1)
      : ring_(static_cast<std::size_t>(capacity < 1 ? 1 : capacity), 0.0) {}

  // Adds `value`, dropping the oldest one when n values are held.
  void Add(double value) {
    if (size_ == static_cast<int>(ring_.size())) {
      sum_ -= ring_[next_];
    } else {
      ++size_;
    }
    ring_[next_] = value;
    sum_ += value;
    next_ = (next_ + 1) % static_cast<int>(ring_.size());
  }

  // Forgets every value.
  void Clear() {
    next_ = 0, size_ = 0;
    sum_ = 0.0;
  }

  int size() const { return size_; }
  bool empty() const { return size_ == 0; }
  // The mean of the values held; only when !empty().
  double Mean() const { return sum_ / size_; }

 private:
  std::vector<double> ring_;
  int next_ = 0, size_ = 0;
  double sum_ = 0.0;
};

}  // namespace vigil::detectors
