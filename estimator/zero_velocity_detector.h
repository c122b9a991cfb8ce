// Is the platform standing still between two camera frames? (zero_velocity_options.h states the rule.)
//
// Both tests compare a scatter with the noise that alone would produce it, in chi-square terms:
//   image: features seen in both frames, displacement d = fx (n_j - n_i) [px]; with independent track noise
//          of std s per axis in each frame, |d|^2 / (2 s^2) ~ chi-square(2) per feature when still;
//   imu:   over the interval's N samples, sum |a_k - mean a|^2 / sigma_a^2 + |w_k - mean w|^2 / sigma_g^2 ~
//          chi-square(6 (N - 1)) when still, with sigma = multiplier x the per-sample white noise std
//          (density x sqrt(rate_hz)). It needs no bias or orientation, so it works before initialization.
#pragma once

#include <map>
#include <optional>

#include <Eigen/Core>

#include "estimator/estimator_input.h"
#include "estimator/preintegration.h"
#include "estimator/zero_velocity_options.h"

namespace vigil::estimator {

// One test's statistic against its threshold (statistic <= threshold: consistent with standing still).
struct StationarityTest {
  double statistic = 0.0;
  double threshold = 0.0;
  int dof = 0;
  bool passed() const { return statistic <= threshold; }
};

// The image test on the features of two frames (normalized points); empty when fewer than min_features are
// shared or the test is off.
std::optional<StationarityTest> ImageStationarity(const std::map<int, Eigen::Vector2d>& features_i,
                                                  const std::map<int, Eigen::Vector2d>& features_j, double fx,
                                                  const ZeroVelocityOptions& options);

// The IMU test on the samples of a preintegrated interval (its first sample and steps); empty when the test
// is off or the interval has fewer than two samples.
std::optional<StationarityTest> ImuStationarity(const Preintegration& imu,
                                                const ZeroVelocityOptions& options);

// The rule: every available test passed and there was at least one.
bool IsStationary(const std::optional<StationarityTest>& image, const std::optional<StationarityTest>& imu);

// The rule on an interval: the two frames' features and the IMU between them.
bool IntervalIsStationary(const std::map<int, Eigen::Vector2d>& features_i,
                          const std::map<int, Eigen::Vector2d>& features_j, const Preintegration& imu,
                          double fx, const ZeroVelocityOptions& options);

}  // namespace vigil::estimator
