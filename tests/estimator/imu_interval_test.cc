// Which IMU samples an interval between two camera frames holds.
#include "estimator/imu_interval.h"

#include <gtest/gtest.h>

namespace vigil::estimator {
namespace {

TEST(ImuInterval, AFlaggedSampleIsFoundInItsInterval) {
  ImuStream imu(10);
  for (std::size_t k = 0; k < imu.size(); ++k) imu[k].t_ns = static_cast<int64_t>(k) * 5'000'000;  // 200 Hz
  std::vector<uint8_t> flagged(imu.size(), 0);
  flagged[4] = 1;                                                       // at 20 ms
  EXPECT_TRUE(AnyFlaggedSample(imu, flagged, 10'000'000, 20'000'000));  // (after, until]
  EXPECT_TRUE(AnyFlaggedSample(imu, flagged, 19'999'999, 45'000'000));
  EXPECT_FALSE(AnyFlaggedSample(imu, flagged, 20'000'000, 45'000'000));
  EXPECT_FALSE(AnyFlaggedSample(imu, flagged, 0, 19'999'999));
  EXPECT_FALSE(AnyFlaggedSample(imu, {}, 0, 45'000'000));  // no flags: none is flagged
}

}  // namespace
}  // namespace vigil::estimator
