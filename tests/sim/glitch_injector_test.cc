#include "sim/glitch_injector.h"

#include <map>

#include <gtest/gtest.h>

#include "sim/simulator.h"

namespace vigil::sim {
namespace {

SimOptions Glitchy() {
  SimOptions o;
  o.glitch.enabled = true;
  o.glitch.mean = 50.0;
  o.glitch.std = 10.0;
  o.glitch.rate = 0.02;
  o.glitch.axes = {ImuAxis::kAz, ImuAxis::kWx};
  return o;
}

// imu - imu_clean is non-zero exactly at the (sample, axis) pairs of the glitch records, by their offsets.
TEST(GlitchInjector, BookkeepingMatchesTheStreams) {
  const Dataset d = Simulate(Glitchy(), 11);
  ASSERT_EQ(d.imu.size(), d.imu_clean.size());
  std::map<std::pair<int64_t, int>, double> offsets;
  for (const GlitchRecord& g : d.glitches) {
    EXPECT_TRUE(offsets.emplace(std::pair{g.t_ns, static_cast<int>(g.axis)}, g.offset).second) << "duplicate";
  }
  ASSERT_GT(offsets.size(), 50u);
  std::size_t nonzero = 0;
  for (std::size_t k = 0; k < d.imu.size(); ++k) {
    ASSERT_EQ(d.imu[k].t_ns, d.imu_clean[k].t_ns);
    for (int axis = 0; axis < kNumImuAxes; ++axis) {
      const double diff = d.imu[k].axis(axis) - d.imu_clean[k].axis(axis);
      const auto it = offsets.find({d.imu[k].t_ns, axis});
      if (it == offsets.end()) {
        EXPECT_EQ(diff, 0.0) << "sample " << k << " axis " << axis;
      } else {
        ++nonzero;
        // (clean + offset) - clean differs from offset only by the rounding of the addition.
        EXPECT_NEAR(diff, it->second, 1e-12 * (std::abs(it->second) + std::abs(d.imu_clean[k].axis(axis))));
        EXPECT_NE(diff, 0.0);
      }
    }
  }
  EXPECT_EQ(nonzero, offsets.size());
}

TEST(GlitchInjector, OnsetRateAndOffsetDistribution) {
  SimOptions o = Glitchy();
  o.duration_s = 200.0;  // 40001 samples
  o.glitch.axes = {ImuAxis::kAz};
  const Dataset d = Simulate(o, 5);
  const double n = static_cast<double>(d.imu.size());
  // Binomial count: mean 800, std 28: 5 std.
  EXPECT_NEAR(static_cast<double>(d.glitches.size()), o.glitch.rate * n, 5 * std::sqrt(o.glitch.rate * n));
  double mean = 0, sq = 0;
  for (const auto& g : d.glitches) mean += g.offset;
  mean /= static_cast<double>(d.glitches.size());
  for (const auto& g : d.glitches) sq += (g.offset - mean) * (g.offset - mean);
  const double std = std::sqrt(sq / static_cast<double>(d.glitches.size() - 1));
  EXPECT_NEAR(mean, 50.0, 1.5);  // standard error 10 / sqrt(800) = 0.35
  EXPECT_NEAR(std, 10.0, 1.0);   // standard error about 0.25
}

TEST(GlitchInjector, BurstsCoverConsecutiveSamples) {
  ImuStream imu(1000);
  for (std::size_t k = 0; k < imu.size(); ++k) imu[k].t_ns = static_cast<int64_t>(k) * 5'000'000;
  GlitchOptions o;
  o.enabled = true;
  o.rate = 0.01;
  o.burst_length = 4;
  o.axes = {ImuAxis::kAx};
  const auto glitches = InjectGlitches(o, 3, &imu);
  ASSERT_FALSE(glitches.empty());
  // Every run of consecutive glitched samples is at least burst_length long (unless cut by the stream's end).
  std::vector<int> glitched(imu.size(), 0);
  for (const auto& g : glitches) glitched[static_cast<std::size_t>(g.t_ns / 5'000'000)] = 1;
  for (std::size_t k = 0; k < imu.size();) {
    if (!glitched[k]) {
      ++k;
      continue;
    }
    std::size_t end = k;
    while (end < imu.size() && glitched[end]) ++end;
    if (end < imu.size()) {
      EXPECT_GE(end - k, 4u) << "run at sample " << k;
    }
    k = end;
  }
  // Same seed, burst length 1: the onsets are the same samples.
  ImuStream imu1(1000);
  for (std::size_t k = 0; k < imu1.size(); ++k) imu1[k].t_ns = static_cast<int64_t>(k) * 5'000'000;
  o.burst_length = 1;
  for (const auto& g : InjectGlitches(o, 3, &imu1))
    EXPECT_TRUE(glitched[static_cast<std::size_t>(g.t_ns / 5'000'000)]);
}

// Glitch settings never change the clean stream (their random streams are separate), and the glitch positions
// do not depend on the offsets' distribution.
TEST(GlitchInjector, SettingsLeaveTheCleanStreamAlone) {
  SimOptions a = Glitchy(), b = Glitchy(), off;
  b.glitch.mean = 1.0;
  b.glitch.std = 0.5;
  b.glitch.axes = {ImuAxis::kAz};
  const Dataset da = Simulate(a, 21), db = Simulate(b, 21), doff = Simulate(off, 21);
  EXPECT_EQ(ImuCsv(da.imu_clean), ImuCsv(doff.imu_clean));
  EXPECT_EQ(ImuCsv(db.imu_clean), ImuCsv(doff.imu_clean));
  EXPECT_EQ(ImuCsv(doff.imu), ImuCsv(doff.imu_clean));
  EXPECT_TRUE(doff.glitches.empty());
  std::vector<int64_t> ta, tb;
  for (const auto& g : da.glitches)
    if (g.axis == ImuAxis::kAz) ta.push_back(g.t_ns);
  for (const auto& g : db.glitches) tb.push_back(g.t_ns);
  EXPECT_EQ(ta, tb);
}

}  // namespace
}  // namespace vigil::sim
