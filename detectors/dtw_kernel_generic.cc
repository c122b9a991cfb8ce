// The DTW kernel for the baseline instruction set (GCC lowers the 8-float vectors to what the target has).
#include "detectors/dtw_kernel.h"

namespace vigil::detectors::internal {
namespace {
#include "detectors/dtw_kernel_impl.inc"
}  // namespace

DtwKernel GenericDtwKernel() { return &Kernel; }

}  // namespace vigil::detectors::internal
