#include "estimator/imu_interval.h"

#include <algorithm>

namespace vigil::estimator {
namespace {

ImuStream::const_iterator FirstNotBefore(const ImuStream& imu, int64_t t_ns) {
  return std::lower_bound(imu.begin(), imu.end(), t_ns,
                          [](const ImuSample& s, int64_t t) { return s.t_ns < t; });
}

ImuStream::const_iterator FirstAfter(const ImuStream& imu, int64_t t_ns) {
  return std::upper_bound(imu.begin(), imu.end(), t_ns,
                          [](int64_t t, const ImuSample& s) { return t < s.t_ns; });
}

// The variance scale of the measurement at t_ns (see PreintegrateInterval).
double VarianceScaleAt(const ImuStream& imu, const std::vector<double>& scale, int64_t t_ns) {
  const auto hi = FirstNotBefore(imu, t_ns);
  const std::size_t k = static_cast<std::size_t>(hi - imu.begin());
  if (hi->t_ns == t_ns || hi == imu.begin()) return scale[k];
  return std::max(scale[k - 1], scale[k]);
}

}  // namespace

bool ImuCovers(const ImuStream& imu, int64_t t_ns) {
  return !imu.empty() && t_ns >= imu.front().t_ns && t_ns <= imu.back().t_ns;
}

ImuSample InterpolateImu(const ImuStream& imu, int64_t t_ns) {
  const auto hi = FirstNotBefore(imu, t_ns);
  if (hi->t_ns == t_ns || hi == imu.begin()) {
    ImuSample s = *hi;
    s.t_ns = t_ns;
    return s;
  }
  const ImuSample& a = *(hi - 1);
  const ImuSample& b = *hi;
  const double s = static_cast<double>(t_ns - a.t_ns) / static_cast<double>(b.t_ns - a.t_ns);
  ImuSample out;
  out.t_ns = t_ns;
  out.w_B = (1.0 - s) * a.w_B + s * b.w_B;
  out.a_B = (1.0 - s) * a.a_B + s * b.a_B;
  return out;
}

Preintegration PreintegrateInterval(const ImuStream& imu, int64_t t0_ns, int64_t t1_ns,
                                    const Eigen::Vector3d& b_a, const Eigen::Vector3d& b_g,
                                    const ImuNoiseDensities& noise, double imu_rate_hz,
                                    const std::vector<double>* variance_scale) {
  const ImuSample first = InterpolateImu(imu, t0_ns);
  const bool scaled = variance_scale != nullptr && !variance_scale->empty();
  Preintegration pre(first.a_B, first.w_B, b_a, b_g, noise, imu_rate_hz,
                     scaled ? VarianceScaleAt(imu, *variance_scale, t0_ns) : 1.0);
  int64_t t_last = t0_ns;
  for (auto it = FirstAfter(imu, t0_ns); it != imu.end() && it->t_ns < t1_ns; ++it) {
    pre.Push(NsToS(it->t_ns - t_last), it->a_B, it->w_B,
             scaled ? (*variance_scale)[static_cast<std::size_t>(it - imu.begin())] : 1.0);
    t_last = it->t_ns;
  }
  const ImuSample last = InterpolateImu(imu, t1_ns);
  pre.Push(NsToS(t1_ns - t_last), last.a_B, last.w_B,
           scaled ? VarianceScaleAt(imu, *variance_scale, t1_ns) : 1.0);
  return pre;
}

bool AnyFlaggedSample(const ImuStream& imu, const std::vector<uint8_t>& flagged, int64_t after_ns,
                      int64_t until_ns) {
  if (flagged.empty()) return false;
  for (auto it = FirstAfter(imu, after_ns); it != imu.end() && it->t_ns <= until_ns; ++it)
    if (flagged[static_cast<std::size_t>(it - imu.begin())]) return true;
  return false;
}

}  // namespace vigil::estimator
