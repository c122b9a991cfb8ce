#include "estimator/zero_velocity_detector.h"

#include <cmath>

#include "estimator/imu_gating.h"

namespace vigil::estimator {

std::optional<StationarityTest> ImageStationarity(const std::map<int, Eigen::Vector2d>& features_i,
                                                  const std::map<int, Eigen::Vector2d>& features_j, double fx,
                                                  const ZeroVelocityOptions& options) {
  if (options.pixel_std_px <= 0.0) return std::nullopt;
  double sum = 0.0;
  int shared = 0;
  for (const auto& [id, n_j] : features_j) {
    const auto it = features_i.find(id);
    if (it == features_i.end()) continue;
    sum += (fx * (n_j - it->second)).squaredNorm();
    ++shared;
  }
  if (shared < options.min_features) return std::nullopt;
  StationarityTest test;
  test.dof = 2 * shared;
  test.statistic = sum / (2.0 * options.pixel_std_px * options.pixel_std_px);
  test.threshold = ChiSquareQuantile(test.dof, options.probability);
  return test;
}

std::optional<StationarityTest> ImuStationarity(const Preintegration& imu,
                                                const ZeroVelocityOptions& options) {
  if (options.imu_noise_multiplier <= 0.0 || imu.steps().empty()) return std::nullopt;
  const int n = static_cast<int>(imu.steps().size()) + 1;
  Eigen::Vector3d mean_a = imu.first_a_B(), mean_w = imu.first_w_B();
  for (const Preintegration::Step& s : imu.steps()) {
    mean_a += s.a_B;
    mean_w += s.w_B;
  }
  mean_a /= n;
  mean_w /= n;
  const double root_rate = std::sqrt(imu.imu_rate_hz());
  const double sigma_a = options.imu_noise_multiplier * imu.noise().accel_noise_density * root_rate;
  const double sigma_g = options.imu_noise_multiplier * imu.noise().gyro_noise_density * root_rate;
  double sum = (imu.first_a_B() - mean_a).squaredNorm() / (sigma_a * sigma_a) +
               (imu.first_w_B() - mean_w).squaredNorm() / (sigma_g * sigma_g);
  for (const Preintegration::Step& s : imu.steps())
    sum += (s.a_B - mean_a).squaredNorm() / (sigma_a * sigma_a) +
           (s.w_B - mean_w).squaredNorm() / (sigma_g * sigma_g);
  StationarityTest test;
  test.dof = 6 * (n - 1);
  test.statistic = sum;
  test.threshold = ChiSquareQuantile(test.dof, options.probability);
  return test;
}

bool IsStationary(const std::optional<StationarityTest>& image, const std::optional<StationarityTest>& imu) {
  if (!image && !imu) return false;
  return (!image || image->passed()) && (!imu || imu->passed());
}

bool IntervalIsStationary(const std::map<int, Eigen::Vector2d>& features_i,
                          const std::map<int, Eigen::Vector2d>& features_j, const Preintegration& imu,
                          double fx, const ZeroVelocityOptions& options) {
  return IsStationary(ImageStationarity(features_i, features_j, fx, options), ImuStationarity(imu, options));
}

}  // namespace vigil::estimator
