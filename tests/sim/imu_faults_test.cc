// The low-cost IMU fault models (sim/imu_faults.h): each does what its header says, is recorded with its
// kind, leaves ground truth and the clean stream alone where documented, and is off by default.
#include "sim/imu_faults.h"

#include <cmath>
#include <map>

#include <gtest/gtest.h>

#include "core/dataset.h"
#include "experiments/runs/run_config.h"
#include "sim/scale_misalignment.h"
#include "sim/simulator.h"
#include "tests/core/test_util.h"

namespace vigil::sim {
namespace {
namespace fs = std::filesystem;
using testing::InputErrorOf;
using testing::TempDir;

SimOptions Rescue() {
  SimOptions o;
  o.duration_s = 12.0;
  o.trajectory.type = TrajectoryType::kRescue;
  o.landmarks.layout = LandmarkLayout::kRandom;
  o.landmarks.random_count = 100;
  return o;
}

int CountKind(const std::vector<GlitchRecord>& records, FaultKind kind) {
  int n = 0;
  for (const GlitchRecord& g : records) n += g.kind == kind;
  return n;
}

TEST(ImuFaults, DefaultsChangeNothing) {
  SimOptions o = Rescue();
  o.glitch.enabled = true;
  const Dataset a = Simulate(o, 3);
  SimOptions explicit_off = o;
  explicit_off.faults.saturation.preset = SaturationPreset::kNone;
  explicit_off.faults.timing.drop_rate = 0.0;
  const Dataset b = Simulate(explicit_off, 3);
  EXPECT_EQ(ImuCsv(a.imu), ImuCsv(b.imu));
  EXPECT_EQ(GlitchesCsv(a.glitches), GlitchesCsv(b.glitches));
  for (const GlitchRecord& g : a.glitches) EXPECT_EQ(g.kind, FaultKind::kOffset);
}

// +-4 g clips the N(50, 10) glitches on az that would exceed 39.24 m/s^2; the clean stream and the ground
// truth are those of the unclipped run, and every clipped axis has a saturation record of the exact change.
TEST(ImuFaults, SaturationClipsAndRecords) {
  SimOptions o = Rescue();
  o.glitch.enabled = true;
  o.glitch.mean = 50.0;
  o.glitch.std = 10.0;
  const Dataset unclipped = Simulate(o, 5);
  o.faults.saturation.preset = SaturationPreset::kLowCost4g;
  const Dataset d = Simulate(o, 5);
  const double range = 4.0 * o.gravity_mps2;
  EXPECT_EQ(ImuCsv(d.imu_clean), ImuCsv(unclipped.imu_clean));
  EXPECT_EQ(GroundTruthCsv(d.groundtruth), GroundTruthCsv(unclipped.groundtruth));
  std::map<int64_t, double> change;
  for (const GlitchRecord& g : d.glitches)
    if (g.kind == FaultKind::kSaturation) change[g.t_ns] += g.offset;
  ASSERT_GT(change.size(), 10u);
  EXPECT_EQ(CountKind(d.glitches, FaultKind::kOffset), CountKind(unclipped.glitches, FaultKind::kOffset));
  for (std::size_t k = 0; k < d.imu.size(); ++k) {
    EXPECT_LE(std::abs(d.imu[k].a_B.z()), range);
    const auto it = change.find(d.imu[k].t_ns);
    const double expected = unclipped.imu[k].a_B.z() + (it == change.end() ? 0.0 : it->second);
    EXPECT_NEAR(d.imu[k].a_B.z(), expected, 1e-9);
  }
  // The course's real peaks stay below +-4 g: without glitches nothing is clipped.
  o.glitch.enabled = false;
  EXPECT_EQ(CountKind(Simulate(o, 5).glitches, FaultKind::kSaturation), 0);
}

TEST(ImuFaults, QuantizationRoundsToTheLsb) {
  SimOptions o = Rescue();
  o.faults.quantization.accel_lsb_mps2 = 0.01;
  o.faults.quantization.gyro_lsb_dps = 0.1;
  const Dataset d = Simulate(o, 2);
  const double gyro_lsb = 0.1 * M_PI / 180.0;
  for (const ImuSample& s : d.imu) {
    for (int i = 0; i < 3; ++i) {
      EXPECT_NEAR(s.w_B[i] / gyro_lsb, std::round(s.w_B[i] / gyro_lsb), 1e-6);
      EXPECT_NEAR(s.a_B[i] / 0.01, std::round(s.a_B[i] / 0.01), 1e-6);
    }
  }
  EXPECT_EQ(ImuCsv(d.imu), ImuCsv(d.imu_clean));  // no glitches: both streams are quantized alike
  EXPECT_TRUE(d.glitches.empty());
}

TEST(ImuFaults, ScaleAndMisalignmentMultiplyEverySample) {
  SimOptions o = Rescue();
  const Dataset ideal = Simulate(o, 2);
  o.faults.scale.accel_scale = {0.01, -0.02, 0.03};
  o.faults.scale.gyro_misalignment_deg = {0.5, 0.0, -1.0};
  const Dataset d = Simulate(o, 2);
  const Eigen::Matrix3d M_a = ScaleMisalignmentMatrix(o.faults.scale.accel_scale, {0, 0, 0});
  const Eigen::Matrix3d M_g = ScaleMisalignmentMatrix({0, 0, 0}, o.faults.scale.gyro_misalignment_deg);
  EXPECT_NEAR(M_a(2, 2), 1.03, 1e-15);
  EXPECT_NEAR(M_g(0, 1), -M_PI / 180.0, 1e-15);
  for (std::size_t k = 0; k < d.imu.size(); k += 97) {
    EXPECT_LT((d.imu[k].a_B - M_a * ideal.imu[k].a_B).norm(), 1e-12);
    EXPECT_LT((d.imu[k].w_B - M_g * ideal.imu[k].w_B).norm(), 1e-12);
  }
  EXPECT_EQ(GroundTruthCsv(d.groundtruth), GroundTruthCsv(ideal.groundtruth));
}

// Drops, duplicated and jittered timestamps: recorded per sample, timestamps never go backwards, values are
// untouched, the first and last samples stay, and the dataset reads back through the files.
TEST(ImuFaults, TimingFaultsAreRecordedAndReadBack) {
  SimOptions o = Rescue();
  o.glitch.enabled = true;
  const Dataset ideal = Simulate(o, 4);
  o.faults.timing.drop_rate = 0.01;
  o.faults.timing.duplicate_rate = 0.01;
  o.faults.timing.jitter_std_s = 0.001;
  const Dataset d = Simulate(o, 4);
  const int drops = CountKind(d.glitches, FaultKind::kDrop);
  EXPECT_GT(drops, 5);
  EXPECT_GT(CountKind(d.glitches, FaultKind::kDuplicate), 5);
  EXPECT_GT(CountKind(d.glitches, FaultKind::kJitter), 100);
  EXPECT_EQ(d.imu.size() + static_cast<std::size_t>(drops), ideal.imu.size());
  ASSERT_EQ(d.imu.size(), d.imu_clean.size());
  EXPECT_EQ(d.imu.front().t_ns, ideal.imu.front().t_ns);
  EXPECT_EQ(d.imu.back().t_ns, ideal.imu.back().t_ns);
  const double period_ns = 1e9 / o.imu.rate_hz;
  for (std::size_t k = 1; k < d.imu.size(); ++k) {
    EXPECT_GE(d.imu[k].t_ns, d.imu[k - 1].t_ns);
    EXPECT_EQ(d.imu[k].t_ns, d.imu_clean[k].t_ns);
  }
  for (const GlitchRecord& g : d.glitches) {
    if (g.kind == FaultKind::kJitter) {
      EXPECT_LE(std::abs(g.offset), 0.45 * period_ns + 1);
    }
  }
  EXPECT_EQ(CountKind(d.glitches, FaultKind::kOffset) <= CountKind(ideal.glitches, FaultKind::kOffset), true);
  EXPECT_EQ(d.frames.size(), ideal.frames.size());

  TempDir tmp;
  WriteDataset(tmp.path(), d);
  const Dataset back = ReadDataset(tmp.path());
  EXPECT_EQ(ImuCsv(back.imu), ImuCsv(d.imu));
  EXPECT_EQ(GlitchesCsv(back.glitches), GlitchesCsv(d.glitches));
}

TEST(ImuFaults, GlitchesCsvReadsTheThreeColumnForm) {
  TempDir tmp;
  const std::string old_form = tmp.File("g.csv", "#timestamp [ns],axis,offset\n5,az,50.5\n5,wx,-1\n");
  const std::vector<GlitchRecord> g = ReadGlitchesCsv(old_form);
  ASSERT_EQ(g.size(), 2u);
  EXPECT_EQ(g[0].kind, FaultKind::kOffset);
  EXPECT_EQ(g[1].axis, ImuAxis::kWx);
  const std::string bad = tmp.File("b.csv", "#timestamp [ns],axis,offset,kind\n5,az,1,spike\n");
  EXPECT_EQ(InputErrorOf([&] { ReadGlitchesCsv(bad); }).rfind(bad + ":2: kind: expected one of", 0), 0u);
  const std::string bad_axis = tmp.File("c.csv", "#timestamp [ns],axis,offset,kind\n5,az,0,drop\n");
  EXPECT_EQ(InputErrorOf([&] { ReadGlitchesCsv(bad_axis); }).rfind(bad_axis + ":2: axis: expected 't'", 0),
            0u);
}

TEST(ImuFaults, OutOfRangeParametersAreConfigErrors) {
  const std::string paper = std::string(VIGIL_SOURCE_DIR) + "/configs/paper.yaml";
  const auto error = [&](const std::vector<std::string>& overrides) {
    return InputErrorOf([&] { experiments::LoadRunConfig(paper, overrides); });
  };
  EXPECT_NE(error({"faults.saturation.accel_range_mps2=9"})
                .find("faults.saturation.accel_range_mps2: range 9 m/s^2 must exceed gravity"),
            std::string::npos);
  EXPECT_NE(error({"faults.saturation.accel_range_g=0.5"}).find("faults.saturation.accel_range_g: range"),
            std::string::npos);
  EXPECT_NE(error({"faults.quantization.accel_lsb_mps2=-0.01"}).find("faults.quantization.accel_lsb_mps2"),
            std::string::npos);
  EXPECT_NE(error({"faults.timing.drop_rate=1.5"}).find("faults.timing.drop_rate"), std::string::npos);
  EXPECT_NE(error({"glitch.rate=-0.1"}).find("glitch.rate"), std::string::npos);
  EXPECT_NE(error({"faults.saturation.preset=lowcost_4g", "faults.saturation.gyro_range_dps=250"})
                .find("faults.saturation.preset"),
            std::string::npos);
  EXPECT_NE(error({"faults.scale.accel_scale=[0.1]"}).find("faults.scale.accel_scale: expected 3"),
            std::string::npos);
  EXPECT_EQ(error({"faults.saturation.accel_range_g=16", "faults.saturation.gyro_range_dps=2000"}), "");
  // The scale model's limits are the keys' documented bounds (configs/README.md), not a later check's.
  EXPECT_EQ(error({"faults.scale.accel_scale=[0.6, 0, 0]"}),
            "--set: faults.scale.accel_scale: must be in [-0.5, 0.5]");
  EXPECT_EQ(error({"faults.scale.gyro_misalignment_deg=[0, 10.5, 0]"}),
            "--set: faults.scale.gyro_misalignment_deg: must be in [-10, 10]");
  EXPECT_EQ(
      error({"faults.scale.accel_scale=[0.5, -0.5, 0]", "faults.scale.accel_misalignment_deg=[10, -10, 0]"}),
      "");
}

}  // namespace
}  // namespace vigil::sim
