// IMU samples between two camera frames: the stream is cut at the frame times, with a sample linearly
// interpolated at each end when a frame falls between two IMU samples.
#pragma once

#include <cstdint>
#include <vector>

#include "core/types.h"
#include "estimator/preintegration.h"

namespace vigil::estimator {

// Whether `imu` (time-ordered) covers t_ns.
bool ImuCovers(const ImuStream& imu, int64_t t_ns);
// The measurement at t_ns, linearly interpolated between its neighbours; `imu` must cover t_ns.
ImuSample InterpolateImu(const ImuStream& imu, int64_t t_ns);
// Preintegrates [t0_ns, t1_ns] (t0 < t1, both covered) from the bias linearization point (b_a, b_g).
// `variance_scale` (null, or one per sample of `imu`): each sample's white-noise variance scale; a sample
// interpolated at an end takes the larger scale of its two neighbours.
Preintegration PreintegrateInterval(const ImuStream& imu, int64_t t0_ns, int64_t t1_ns,
                                    const Eigen::Vector3d& b_a, const Eigen::Vector3d& b_g,
                                    const ImuNoiseDensities& noise, double imu_rate_hz,
                                    const std::vector<double>* variance_scale = nullptr);
// Whether a sample of `imu` (time-ordered) with a time in (after_ns, until_ns] is flagged; `flagged` is empty
// (none is) or holds one flag per sample of `imu`.
bool AnyFlaggedSample(const ImuStream& imu, const std::vector<uint8_t>& flagged, int64_t after_ns,
                      int64_t until_ns);

}  // namespace vigil::estimator
