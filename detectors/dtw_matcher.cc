#include "detectors/dtw_matcher.h"

#include <stdexcept>
#include <string>

#include "detectors/dtw_kernel.h"

namespace vigil::detectors {
namespace {

using internal::DtwKernel;
using internal::Lane8;

struct SelectedKernel {
  DtwKernel kernel;
  const char* name;
};

SelectedKernel Select() {
#ifdef VIGIL_DTW_AVX2_KERNEL
  __builtin_cpu_init();
  if (__builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma"))
    return {internal::Avx2DtwKernel(), "avx2"};
#endif
  return {internal::GenericDtwKernel(), "generic"};
}

const SelectedKernel& Kernel() {
  static const SelectedKernel selected = Select();
  return selected;
}

}  // namespace

DtwMatcher::DtwMatcher(const double* templates, int count, int length, int dims)
    : count_(count), length_(length), dims_(dims), groups_((count + 7) / 8) {
  if (count < 1 || length < 1 || dims < 1 || dims > 6)
    throw std::invalid_argument("DtwMatcher: need count >= 1, length >= 1 and 1 <= dims <= 6 (got " +
                                std::to_string(count) + ", " + std::to_string(length) + ", " +
                                std::to_string(dims) + ")");
  packed_.assign(static_cast<std::size_t>(groups_) * length * dims, Lane8{});
  for (int t = 0; t < count; ++t) {
    const int g = t / 8, lane = t % 8;
    for (int j = 0; j < length; ++j)
      for (int c = 0; c < dims; ++c)
        packed_[(static_cast<std::size_t>(g) * length + j) * dims + c].v[lane] =
            static_cast<float>(templates[(static_cast<std::size_t>(t) * length + j) * dims + c]);
  }
  lanes_.resize(static_cast<std::size_t>(groups_));
}

void DtwMatcher::Compute(const float* slice, int m) {
  const std::size_t need = (static_cast<std::size_t>(m) + 1) * 2;
  if (scratch_.size() < need) scratch_.resize(need);
  const DtwKernel kernel = Kernel().kernel;
  for (int g = 0; g < groups_; g += 2) {
    internal::DtwKernelArgs args;
    args.packed = packed_.data() + static_cast<std::size_t>(g) * length_ * dims_;
    args.groups = groups_ - g >= 2 ? 2 : 1;
    args.length = length_;
    args.dims = dims_;
    args.slice = slice;
    args.m = m;
    args.row = scratch_.data();
    args.out = lanes_.data() + g;
    kernel(args);
  }
}

void DtwMatcher::Distances(const float* slice, int m, float* out) {
  Compute(slice, m);
  for (int t = 0; t < count_; ++t) out[t] = lanes_[t / 8].v[t % 8];
}

DtwMatch DtwMatcher::Best(const float* slice, int m) {
  Compute(slice, m);
  DtwMatch best;
  for (int t = 0; t < count_; ++t) {
    const double d = lanes_[t / 8].v[t % 8];
    if (d < best.distance) {
      best.distance = d;
      best.index = t;
    }
  }
  return best;
}

const char* DtwMatcher::KernelName() { return Kernel().name; }

}  // namespace vigil::detectors
