#include "estimator/rest_noise.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "core/format.h"
#include "estimator/zero_velocity_detector.h"

namespace vigil::estimator {
namespace {

// The median of chi-square with one degree of freedom: median(d^2) = this x var(d) for Gaussian d.
constexpr double kChiSquare1Median = 0.454936423119572;
// Differences beyond this many robust standard deviations are glitches, left out of the variance. Vibration
// has heavy tails (on EuRoC V1_01 3 % of the differences lie beyond 5, none beyond 9); a glitch of the
// paper's N(50, 10) m/s^2 lies hundreds out.
constexpr double kOutlierSigmas = 10.0;
// Fewest pooled differences (8 cluster pairs on each of 3 axes) for a measurement.
constexpr int kMinDifferences = 24;

double MedianCameraPeriodS(const std::vector<CameraFrame>& frames, int64_t t0_ns, int64_t t1_ns) {
  std::vector<int64_t> periods;
  for (std::size_t k = 1; k < frames.size(); ++k)
    if (frames[k - 1].t_ns >= t0_ns && frames[k].t_ns <= t1_ns)
      periods.push_back(frames[k].t_ns - frames[k - 1].t_ns);
  if (periods.empty()) return 0.0;
  std::nth_element(periods.begin(), periods.begin() + periods.size() / 2, periods.end());
  return NsToS(periods[periods.size() / 2]);
}

bool Includes(RestNoiseSensors set, RestNoiseSensors sensor) {
  return set == RestNoiseSensors::kBoth || set == sensor;
}

struct Applied {
  bool white_noise = false;
  bool bias_walk = false;
};

// The rule for one sensor: where `measured` is at least min_ratio times the model's white noise, the bias
// walk (when `walk`) is multiplied by measured / model, and the white noise (when `white`) becomes
// `measured`.
Applied Apply(const std::optional<double>& measured, double min_ratio, bool white, bool walk,
              double* white_noise, double* bias_walk) {
  if (!measured || *measured < min_ratio * *white_noise) return {};
  if (walk) *bias_walk *= *measured / *white_noise;  // before the white noise changes
  if (white) *white_noise = *measured;
  return {white, walk};
}

}  // namespace

std::optional<RestSpan> FindFirstRest(const std::vector<CameraFrame>& frames, const CameraModel& camera,
                                      const ZeroVelocityOptions& image_test, double min_rest_s) {
  if (frames.empty()) return std::nullopt;
  const auto still = [&](const std::map<int, Eigen::Vector2d>& older,
                         const std::map<int, Eigen::Vector2d>& newer) {
    const std::optional<StationarityTest> test = ImageStationarity(older, newer, camera.fx, image_test);
    return test && test->passed();
  };
  RestSpan run{frames.front().t_ns, frames.front().t_ns};
  std::size_t first_k = 0;  // the run's first frame
  std::map<int, Eigen::Vector2d> first = NormalizedFeatures(frames.front(), camera);
  std::map<int, Eigen::Vector2d> previous = first;
  for (std::size_t k = 1; k < frames.size(); ++k) {
    std::map<int, Eigen::Vector2d> current = NormalizedFeatures(frames[k], camera);
    // Still since the previous frame, and since the rest began: a slow motion passes the first test at
    // every interval, but its displacement grows until the second one fails (the same test while the run
    // began at the previous frame).
    const bool interval_still = still(previous, current);
    const bool rest_goes_on = interval_still && (first_k + 1 == k || still(first, current));
    if (rest_goes_on) run.t1_ns = frames[k].t_ns;
    if (!rest_goes_on || k + 1 == frames.size()) {
      if (NsToS(run.t1_ns - run.t0_ns) >= min_rest_s) return run;
      // A new run from the previous frame when this interval is still, else from this frame.
      first_k = interval_still ? k - 1 : k;
      run = {frames[first_k].t_ns, frames[k].t_ns};
      first = interval_still ? previous : current;
    }
    previous = std::move(current);
  }
  return std::nullopt;
}

std::optional<double> AllanWhiteNoiseDensity(const ImuStream& imu, int64_t t0_ns, int64_t t1_ns, double tau_s,
                                             bool accel, int* differences) {
  *differences = 0;
  const auto begin = std::lower_bound(imu.begin(), imu.end(), t0_ns,
                                      [](const ImuSample& s, int64_t t) { return s.t_ns < t; });
  const auto end = std::upper_bound(imu.begin(), imu.end(), t1_ns,
                                    [](int64_t t, const ImuSample& s) { return t < s.t_ns; });
  const long count = std::distance(begin, end);
  if (count < 2 || tau_s <= 0.0) return std::nullopt;
  const double rate_hz = static_cast<double>(count - 1) / NsToS(std::prev(end)->t_ns - begin->t_ns);
  const long per_cluster = std::max(1L, std::lround(tau_s * rate_hz));
  const long clusters = count / per_cluster;
  std::vector<Eigen::Vector3d> means;
  for (long c = 0; c < clusters; ++c) {
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    for (auto s = begin + c * per_cluster; s != begin + (c + 1) * per_cluster; ++s)
      sum += accel ? s->a_B : s->w_B;
    means.push_back(sum / static_cast<double>(per_cluster));
  }
  std::vector<double> squared;
  for (std::size_t c = 1; c < means.size(); ++c)
    for (int axis = 0; axis < 3; ++axis) squared.push_back(std::pow(means[c][axis] - means[c - 1][axis], 2));
  *differences = static_cast<int>(squared.size());
  if (*differences < kMinDifferences) return std::nullopt;
  // Glitches: a difference beyond kOutlierSigmas robust standard deviations (from the median) is no noise.
  std::vector<double> sorted = squared;
  std::nth_element(sorted.begin(), sorted.begin() + sorted.size() / 2, sorted.end());
  const double robust_variance = sorted[sorted.size() / 2] / kChiSquare1Median;
  double sum = 0.0;
  int kept = 0;
  for (const double d2 : squared) {
    if (d2 > kOutlierSigmas * kOutlierSigmas * robust_variance) continue;
    sum += d2;
    ++kept;
  }
  const double variance = sum / kept;  // var(d) = 2 N^2 / tau
  const double tau_actual_s = static_cast<double>(per_cluster) / rate_hz;
  return std::sqrt(variance * tau_actual_s / 2.0);
}

RestNoise MeasureRestNoise(const ImuStream& imu, const std::vector<CameraFrame>& frames,
                           const CameraModel& camera, const ZeroVelocityOptions& zero_velocity,
                           const RestNoiseOptions& options, ImuNoiseDensities* model) {
  RestNoise out;
  if (options.sensors == RestNoiseSensors::kNone && options.bias_walk == RestNoiseSensors::kNone) return out;
  // The static start's test: the rest measured is the stand the static start stands on.
  ZeroVelocityOptions image_test = StaticStartTests(zero_velocity);
  image_test.probability = options.probability;
  const std::optional<RestSpan> rest = FindFirstRest(frames, camera, image_test, options.min_rest_s);
  if (!rest) return out;
  out.start_s = NsToS(rest->t0_ns - frames.front().t_ns);
  out.rest_s = NsToS(rest->t1_ns - rest->t0_ns);
  out.tau_s = MedianCameraPeriodS(frames, rest->t0_ns, rest->t1_ns);
  out.gyro_noise_density =
      AllanWhiteNoiseDensity(imu, rest->t0_ns, rest->t1_ns, out.tau_s, false, &out.differences);
  out.accel_noise_density =
      AllanWhiteNoiseDensity(imu, rest->t0_ns, rest->t1_ns, out.tau_s, true, &out.differences);
  const RestNoiseSensors gyro = RestNoiseSensors::kGyroscope, accel = RestNoiseSensors::kAccelerometer;
  const Applied g =
      Apply(out.gyro_noise_density, options.min_ratio, Includes(options.sensors, gyro),
            Includes(options.bias_walk, gyro), &model->gyro_noise_density, &model->gyro_bias_random_walk);
  const Applied a =
      Apply(out.accel_noise_density, options.min_ratio, Includes(options.sensors, accel),
            Includes(options.bias_walk, accel), &model->accel_noise_density, &model->accel_bias_random_walk);
  out.gyro_applied = g.white_noise;
  out.gyro_bias_walk_applied = g.bias_walk;
  out.accel_applied = a.white_noise;
  out.accel_bias_walk_applied = a.bias_walk;
  return out;
}

}  // namespace vigil::estimator
