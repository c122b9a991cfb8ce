// Per-sample trust of the IMU stream for in-estimator mitigation (mitigation_options.h): the variance scale
// each sample enters preintegration with.
//   - inflate:    samples a detector flagged (EstimatorInput::imu_flagged) get inflate.variance_factor;
//   - saturation: samples with an axis at |x| >= range (1 - tolerance_fraction) get
//   saturation.variance_factor;
// a sample both flagged and clipped takes the larger factor.
#pragma once

#include <cstdint>
#include <vector>

#include "core/types.h"
#include "estimator/mitigation_options.h"

namespace vigil::estimator {

struct ImuTrust {
  std::vector<double> variance_scale;  // empty when every sample is trusted (scale 1)
  int inflated_samples = 0;            // flagged samples inflated
  int clipped_samples = 0;             // samples found at the full-scale range (inflated)
};

// `flagged`: empty, or one flag per sample of `imu`.
ImuTrust ComputeImuTrust(const MitigationOptions& options, const ImuStream& imu,
                         const std::vector<uint8_t>& flagged);

// Whether any axis of `s` sits at the full-scale range of `options` (ranges of 0 are unknown: never).
bool IsClipped(const SaturationAwareOptions& options, const ImuSample& s);

}  // namespace vigil::estimator
