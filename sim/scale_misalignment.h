// Constant scale-factor and axis-misalignment errors (fault_options.h: ScaleMisalignmentOptions).
//
// Every sample's gyro and accelerometer vectors are multiplied by the constant matrix (I + diag(scale)) (I +
// N) of their sensor: the error acts on what the sensor senses, bias and white noise included. Deterministic
// (no random stream); a zero configuration leaves the samples untouched.
#pragma once

#include <Eigen/Core>

#include "core/types.h"
#include "sim/fault_options.h"

namespace vigil::sim {

// (I + diag(scale)) (I + N(misalignment_deg)) for 3 scale errors and 3 non-orthogonality angles.
Eigen::Matrix3d ScaleMisalignmentMatrix(const std::vector<double>& scale,
                                        const std::vector<double>& misalignment_deg);

// Whether `options` is the identity (nothing to apply).
bool IsIdentity(const ScaleMisalignmentOptions& options);

// Applies the two matrices to every sample in place.
void ApplyScaleMisalignment(const ScaleMisalignmentOptions& options, ImuStream* imu);

}  // namespace vigil::sim
