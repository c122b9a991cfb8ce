#include "plots/run_data.h"

#include <gtest/gtest.h>

#include "core/output.h"
#include "experiments/sweeps/sweep_spec.h"
#include "plots/figure_data.h"
#include "plots/trajectory_alignment.h"
#include "sim/simulator.h"
#include "tests/core/test_util.h"
#include "tests/plots/synthetic_runs.h"

namespace vigil::plots {
namespace {

TEST(RunData, SweepRunsAreGroupedByTheirOwnConfig) {
  vigil::testing::TempDir tmp;
  testing::WriteSyntheticSweep(tmp.path(), {{true, 4.0, 2.0}, {true, 1.0, 0.5}}, 2, 2.0);
  const SweepData sweep = LoadSweepDirectory(tmp.path());
  ASSERT_EQ(sweep.runs.size(), 12u);
  EXPECT_EQ(sweep.methods, (std::vector<std::string>{"original", "trunc", "dtw"}));
  ASSERT_EQ(sweep.settings.size(), 2u);
  EXPECT_EQ(sweep.settings[0].mean, 1.0);  // sorted, whatever the run ids say
  EXPECT_EQ(sweep.settings[1].Label(), "μ = 4, σ = 2");
  int failed = 0;
  for (const RunData& r : sweep.runs) failed += !r.ok();
  EXPECT_EQ(failed, 1);
  const std::vector<SummaryCell> cells = SummaryCellsOf(sweep);
  ASSERT_EQ(cells.size(), 6u);
  int total_failed = 0;
  for (const SummaryCell& c : cells) {
    EXPECT_EQ(c.ate_trans_m.size() + c.failed, 2u);
    total_failed += c.failed;
  }
  EXPECT_EQ(total_failed, 1);
}

// Two methods with the same detector (vigil's trunc and another estimator's trunc): in a sweep directory
// whose sweep.yaml loads, each run keeps the sweep's label, and the methods follow its table_methods.
TEST(RunData, SweepLabelsKeepMethodsWithTheSameDetectorApart) {
  vigil::testing::TempDir tmp;
  WriteFileAtomic(tmp.path() / "sweep.yaml",
                  "base: " + std::string(VIGIL_SOURCE_DIR) +
                      "/configs/paper.yaml\n"
                      "methods:\n  trunc: threshold\n  other_trunc: {type: threshold, "
                      "estimator.mitigation.gating.enabled: true}\n"
                      "seeds: {count: 2, first: 1}\ntable_methods: [other_trunc, trunc]\n");
  const experiments::SweepSpec spec = experiments::LoadSweepSpec((tmp.path() / "sweep.yaml").string());
  const std::vector<experiments::SweepCell> cells = experiments::EnumerateCells(spec);
  const testing::SyntheticSetting setting;
  const experiments::RunConfig base =
      testing::SyntheticConfig(setting, detectors::DetectorType::kThreshold, 1, 2.0);
  const Dataset data = sim::Simulate(base.sim, base.seed);
  for (const experiments::SweepRunRef& run : experiments::EnumerateRuns(spec, cells))
    testing::WriteSyntheticRun(
        tmp.path() / "runs" / run.id,
        testing::SyntheticConfig(setting, detectors::DetectorType::kThreshold, run.seed, 2.0), data);
  const SweepData sweep = LoadSweepDirectory(tmp.path());
  ASSERT_EQ(sweep.runs.size(), 4u);
  EXPECT_EQ(sweep.methods, (std::vector<std::string>{"other_trunc", "trunc"}));
  for (const RunData& r : sweep.runs)
    EXPECT_EQ(r.method, r.id.find("other_trunc") != std::string::npos ? "other_trunc" : "trunc") << r.id;
  ASSERT_EQ(SummaryCellsOf(sweep).size(), 2u);
}

TEST(RunData, MethodNamesFollowThePaper) {
  EXPECT_EQ(MethodName(detectors::DetectorType::kThreshold), "trunc");
  EXPECT_EQ(MethodName(detectors::DetectorType::kDtw), "dtw");
  EXPECT_EQ(MethodName(detectors::DetectorType::kNone), "original");
  EXPECT_EQ(MethodName(detectors::DetectorType::kHampel), "hampel");
  EXPECT_EQ(MethodName(detectors::DetectorType::kRelativeThreshold), "relative_threshold");
  detectors::DetectorOptions dtw;
  dtw.type = detectors::DetectorType::kDtw;
  EXPECT_EQ(MethodName(dtw), "dtw");
  dtw.dtw.normalization = detectors::SliceNormalization::kLinear;
  EXPECT_EQ(MethodName(dtw), "normalized_dtw");
  EXPECT_TRUE(MethodBefore("original", "dtw"));
  EXPECT_TRUE(MethodBefore("dtw", "hampel"));
}

TEST(RunData, DetectionsCsvIsValidated) {
  vigil::testing::TempDir tmp;
  std::vector<int64_t> t;
  std::vector<uint8_t> f;
  ReadDetectionsCsv(tmp.File("ok.csv", "#timestamp [ns],flagged\n10,0\n20,1\n"), &t, &f);
  EXPECT_EQ(t, (std::vector<int64_t>{10, 20}));
  EXPECT_EQ(f, (std::vector<uint8_t>{0, 1}));
  EXPECT_NE(vigil::testing::InputErrorOf([&] {
              ReadDetectionsCsv(tmp.File("bad.csv", "#timestamp [ns],flagged\n10,0\n20,2\n"), &t, &f);
            }).find("bad.csv:3"),
            std::string::npos);
}

TEST(TrajectoryAlignment, PosYawUndoesAYawAndATranslation) {
  Trajectory gt, est;
  const Eigen::AngleAxisd yaw(0.7, Eigen::Vector3d::UnitZ());
  for (int i = 0; i < 50; ++i) {
    const double t = i * 0.1;
    const Eigen::Vector3d p(std::cos(t) * 5, std::sin(2 * t) * 3, 0.2 * t);
    gt.push_back({i * 100'000'000LL, p, Eigen::Quaterniond::Identity()});
    if (i >= 5)
      est.push_back({i * 100'000'000LL + 1000, yaw * p + Eigen::Vector3d(1, 2, 3), Eigen::Quaterniond(yaw)});
  }
  const Trajectory aligned = AlignForDisplay(est, gt, evaluation::Alignment::kPosYaw);
  ASSERT_EQ(aligned.size(), 45u);
  for (std::size_t i = 0; i < aligned.size(); ++i) {
    EXPECT_NEAR((aligned[i].p_W - gt[i + 5].p_W).norm(), 0.0, 1e-9);
    EXPECT_NEAR(aligned[i].q_WB.angularDistance(Eigen::Quaterniond::Identity()), 0.0, 1e-9);
  }
  const Trajectory se3 = AlignForDisplay(est, gt, evaluation::Alignment::kSe3);
  EXPECT_NEAR((se3.back().p_W - gt.back().p_W).norm(), 0.0, 1e-6);
  const Trajectory none = AlignForDisplay(est, gt, evaluation::Alignment::kNone);
  EXPECT_NEAR((none.back().p_W - est.back().p_W).norm(), 0.0, 1e-12);
}

}  // namespace
}  // namespace vigil::plots
