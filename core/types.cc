#include "core/types.h"

#include <cmath>

namespace vigil {
namespace {
constexpr std::array<const char*, kNumImuAxes> kAxisNames = {"wx", "wy", "wz", "ax", "ay", "az"};
}  // namespace

int64_t SToNs(double t_s) { return static_cast<int64_t>(std::llround(t_s * 1e9)); }

const char* ImuAxisName(ImuAxis axis) { return kAxisNames[static_cast<int>(axis)]; }

bool ParseImuAxis(const std::string& name, ImuAxis* axis) {
  for (int i = 0; i < kNumImuAxes; ++i) {
    if (name == kAxisNames[i]) {
      *axis = static_cast<ImuAxis>(i);
      return true;
    }
  }
  return false;
}

namespace {
constexpr const char* kFaultKindNames[] = {"offset", "saturation", "drop", "duplicate", "jitter"};
}  // namespace

const char* FaultKindName(FaultKind kind) { return kFaultKindNames[static_cast<int>(kind)]; }

bool ParseFaultKind(const std::string& name, FaultKind* kind) {
  for (int i = 0; i < 5; ++i) {
    if (name == kFaultKindNames[i]) {
      *kind = static_cast<FaultKind>(i);
      return true;
    }
  }
  return false;
}

}  // namespace vigil
