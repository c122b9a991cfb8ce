// The DTW kernel compiled for AVX2 + FMA (this file alone gets -mavx2 -mfma, see CMakeLists.txt); only called
// after __builtin_cpu_supports confirms the CPU has both.
#include "detectors/dtw_kernel.h"

namespace vigil::detectors::internal {
namespace {
#include "detectors/dtw_kernel_impl.inc"
}  // namespace

DtwKernel Avx2DtwKernel() { return &Kernel; }

}  // namespace vigil::detectors::internal
