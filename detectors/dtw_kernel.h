// Internal to dtw_matcher.cc: the SIMD DTW kernel, compiled once per instruction set (dtw_kernel_*.cc).
#pragma once

#include "detectors/dtw_matcher.h"

namespace vigil::detectors::internal {

// One call computes the DTW distances of a slice to the templates of one or two lane groups.
struct DtwKernelArgs {
  const Lane8* packed;  // [group][row][dim], starting at the first group to process
  int groups;           // 1 or 2
  int length;           // template rows N
  int dims;             // 1..6
  const float* slice;   // m rows x dims
  int m;
  Lane8* row;  // scratch: (m + 1) x groups
  Lane8* out;  // one Lane8 per group
};
using DtwKernel = void (*)(const DtwKernelArgs& args);

DtwKernel GenericDtwKernel();
#ifdef VIGIL_DTW_AVX2_KERNEL
DtwKernel Avx2DtwKernel();  // only on x86-64 builds (dtw_kernel_avx2.cc)
#endif

}  // namespace vigil::detectors::internal
