#include "sim/semi_real.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include <gtest/gtest.h>

#include "core/dataset.h"
#include "core/euroc.h"
#include "core/output.h"
#include "estimator/run_estimator.h"
#include "evaluation/evaluate_trajectory.h"
#include "experiments/runs/run_config.h"
#include "experiments/runs/run_inputs.h"
#include "sim/camera_simulator.h"
#include "sim/simulator.h"
#include "tests/core/test_util.h"

namespace vigil::sim {
namespace {
namespace fs = std::filesystem;
using testing::InputErrorOf;
using testing::TempDir;

// Three seconds of EuRoC V1_01 (real IMU, ground truth and camera times; README.md beside it).
const fs::path kSemiRealExcerpt = fs::path(VIGIL_SOURCE_DIR) / "tests/sim/data/v1_01_excerpt";
// The committed first 30 s of V1_01 (README.md and LICENSE beside it), which the semi-real configs and the
// CI gate read.
const fs::path kV101Excerpt = fs::path(VIGIL_SOURCE_DIR) / "data/euroc_v1_01_excerpt";
// The whole V1_01 flight, beside the repository where the development machine has it (absent: skipped).
const fs::path kV101 = fs::path(VIGIL_SOURCE_DIR) / "../shared/data/euroc_v1_01";

SimOptions SemiReal(const fs::path& recording, double duration_s) {
  SimOptions o;
  o.duration_s = duration_s;
  o.imu.source = ImuSource::kRecording;
  o.imu.recording = recording.string();
  o.landmarks.layout = LandmarkLayout::kRandom;
  o.landmarks.random_count = 300;
  o.landmarks.random_margin_m = 2.0;
  o.landmarks.random_height_m = 3.0;
  return o;
}

void ExpectSameImu(const ImuStream& a, const ImuStream& b) {
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t k = 0; k < a.size(); ++k) {
    ASSERT_EQ(a[k].t_ns, b[k].t_ns) << k;
    ASSERT_EQ(a[k].w_B, b[k].w_B) << k;
    ASSERT_EQ(a[k].a_B, b[k].a_B) << k;
  }
}

std::vector<int64_t> TimesOf(const std::vector<CameraFrame>& frames) {
  std::vector<int64_t> t;
  for (const CameraFrame& f : frames) t.push_back(f.t_ns);
  return t;
}

// Every observation is the landmark's projection from the ground-truth pose at the frame's time.
void ExpectTracksFollowGroundTruth(const Dataset& d) {
  int checked = 0;
  for (const CameraFrame& f : d.frames) {
    const auto gt = std::find_if(d.groundtruth.begin(), d.groundtruth.end(),
                                 [&](const NavState& s) { return s.t_ns == f.t_ns; });
    ASSERT_NE(gt, d.groundtruth.end()) << f.t_ns;
    for (const FeatureObservation& o : f.features) {
      Eigen::Vector2d uv;
      ASSERT_TRUE(
          d.camera.Project(LandmarkInCamera(d.camera, gt->q_WB, gt->p_W, d.landmarks[o.id].p_W), &uv));
      EXPECT_LT((uv - o.uv_px).norm(), 1e-9);
      ++checked;
    }
  }
  EXPECT_GT(checked, 20 * static_cast<int>(d.frames.size()));
}

TEST(SemiReal, KeepsTheRecordedImuAndGroundTruthAndTheRecordedFrameTimes) {
  const Dataset recorded = ReadDataset(kSemiRealExcerpt);
  const Dataset d = Simulate(SemiReal(kSemiRealExcerpt, 3.0), 1);
  ExpectSameImu(d.imu_clean, recorded.imu);
  ExpectSameImu(d.imu, recorded.imu);
  ASSERT_EQ(d.groundtruth.size(), recorded.groundtruth.size());
  for (std::size_t k = 0; k < d.groundtruth.size(); ++k)
    EXPECT_EQ(d.groundtruth[k].p_W, recorded.groundtruth[k].p_W);
  // The frames are frames.csv's: real times (50 ms +- 128 ns apart), one of them dropped, none added.
  const std::vector<int64_t> listed = ReadFramesCsv((kSemiRealExcerpt / dataset_files::kFrames).string());
  EXPECT_EQ(TimesOf(d.frames), listed);
  EXPECT_EQ(listed.size(), 60u);
  int off_grid = 0;
  for (std::size_t k = 1; k < listed.size(); ++k) off_grid += (listed[k] - listed[k - 1]) % 50'000'000 != 0;
  EXPECT_GT(off_grid, 50);
  EXPECT_EQ(d.camera.width, 752);
  EXPECT_TRUE(d.camera.HasDistortion());
  ExpectTracksFollowGroundTruth(d);
}

TEST(SemiReal, ReadingTheDatasetKeepsItsFramesWithoutPadding) {
  const Dataset recorded = ReadDataset(kSemiRealExcerpt);
  EXPECT_EQ(TimesOf(recorded.frames), ReadFramesCsv((kSemiRealExcerpt / dataset_files::kFrames).string()));
  for (const CameraFrame& f : recorded.frames) EXPECT_TRUE(f.features.empty());
  TempDir tmp;
  SimOptions o = SemiReal(kSemiRealExcerpt, 3.0);
  o.camera.pixel_noise_px = 0.5;
  const Dataset d = Simulate(o, 2);
  WriteDataset(tmp.path(), d);
  const Dataset back = ReadDataset(tmp.path());
  ASSERT_EQ(TimesOf(back.frames), TimesOf(d.frames));
  for (std::size_t k = 0; k < d.frames.size(); ++k)
    ASSERT_EQ(back.frames[k].features.size(), d.frames[k].features.size());
  // The evaluation's ground truth sits at exactly these frames.
  EXPECT_EQ(experiments::GroundTruthAtFrames(back.groundtruth, back.frames).size(), d.frames.size());
}

TEST(SemiReal, GlitchesAndFaultsActOnTheRecordedImuWithLabels) {
  SimOptions o = SemiReal(kSemiRealExcerpt, 3.0);
  o.glitch.enabled = true;
  o.glitch.rate = 0.05;
  o.glitch.mean = 5.0;
  o.glitch.axes = {ImuAxis::kAz, ImuAxis::kWx};
  const Dataset d = Simulate(o, 3);
  ExpectSameImu(d.imu_clean, ReadDataset(kSemiRealExcerpt).imu);
  ASSERT_GT(d.glitches.size(), 20u);
  std::size_t k = 0;
  for (const GlitchRecord& g : d.glitches) {
    EXPECT_EQ(g.kind, FaultKind::kOffset);
    while (d.imu[k].t_ns < g.t_ns) ++k;
    const int axis = static_cast<int>(g.axis);
    EXPECT_NEAR(d.imu[k].axis(axis) - d.imu_clean[k].axis(axis), g.offset, 1e-9);
  }
  // The same keys as in the simulator: dropped samples leave both streams alike.
  o.faults.timing.drop_rate = 0.1;
  const Dataset dropped = Simulate(o, 3);
  EXPECT_LT(dropped.imu.size(), d.imu.size());
  EXPECT_EQ(dropped.imu.size(), dropped.imu_clean.size());
}

TEST(SemiReal, RecordingsThatDoNotCoverTheWindowAreRefusedWithFileAndLine) {
  TempDir tmp;
  const fs::path dir = tmp.path() / "rec";
  fs::create_directories(dir);
  for (const char* f : {"groundtruth.csv", "camera.yaml", "frames.csv", "features.csv", "landmarks.csv"})
    fs::copy_file(kSemiRealExcerpt / f, dir / f);
  ImuStream imu = ReadDataset(kSemiRealExcerpt).imu;
  imu.resize(imu.size() - 5);  // ends 25 ms before the ground truth
  const std::vector<int64_t> frames = ReadFramesCsv((kSemiRealExcerpt / dataset_files::kFrames).string());
  // frames.csv's last time is now outside the IMU: the dataset itself is refused.
  WriteFileAtomic(dir / "imu.csv", ImuCsv(imu));
  EXPECT_NE(InputErrorOf([&] {
              Simulate(SemiReal(dir, 3.0), 1);
            }).find((dir / "frames.csv").string() + ":61: timestamp"),
            std::string::npos);
  std::vector<CameraFrame> kept;
  for (int64_t t : frames)
    if (t <= imu.back().t_ns) kept.push_back({t, {}});
  WriteFileAtomic(dir / "frames.csv", FramesCsv(kept));
  const std::string error = InputErrorOf([&] { Simulate(SemiReal(dir, 3.0), 1); });
  EXPECT_EQ(error.rfind((dir / "imu.csv").string() + ":" + std::to_string(imu.size() + 1) +
                            ": imu.recording: the IMU ends at ",
                        0),
            0u)
      << error;
  // A window beyond the ground truth.
  EXPECT_EQ(InputErrorOf([&] {
              Simulate(SemiReal(kSemiRealExcerpt, 3.5), 1);
            }).rfind("duration_s: the semi-real window", 0),
            0u);
}

// A EuRoC folder (mav0/) of the excerpt, with cam0/data.csv listing `image_times` (empty image files).
fs::path WriteEurocExcerpt(const fs::path& dir, const std::vector<int64_t>& image_times,
                           const std::vector<NavState>& groundtruth) {
  Dataset d = ReadDataset(kSemiRealExcerpt);
  d.groundtruth = groundtruth;
  WriteEuroc(dir, d, EurocImuSensor{}, image_times);
  for (int64_t t : image_times) WriteFileAtomic(EurocImageDir(dir) / EurocImageName(t), "");
  return dir;
}

TEST(SemiReal, CameraTimesOutsideTheImuAreRefusedWithFileAndLine) {
  TempDir tmp;
  const Dataset excerpt = ReadDataset(kSemiRealExcerpt);
  const int64_t after = excerpt.imu.back().t_ns + 1'000'000;
  const fs::path dir =
      WriteEurocExcerpt(tmp.path() / "rec", {excerpt.groundtruth[0].t_ns, after}, excerpt.groundtruth);
  const std::string error = InputErrorOf([&] { Simulate(SemiReal(dir, 3.0), 1); });
  EXPECT_NE(
      error.find("cam0/data.csv:3: timestamp " + std::to_string(after) + " is outside the IMU's time span"),
      std::string::npos)
      << error;
}

TEST(SemiReal, FrameTimesAreTheRecordedOnesThenTheGroundTruthsOrTheCameraRate) {
  TempDir tmp;
  const Dataset excerpt = ReadDataset(kSemiRealExcerpt);
  std::vector<int64_t> listed;
  for (int k = 0; k < 10; ++k) listed.push_back(excerpt.groundtruth[static_cast<std::size_t>(k)].t_ns);
  // Ground truth at the camera times: the listed frames, then the ground truth's own times.
  Recording rec = ReadRecording(WriteEurocExcerpt(tmp.path() / "a", listed, excerpt.groundtruth));
  std::vector<int64_t> expected;
  for (const NavState& s : excerpt.groundtruth) expected.push_back(s.t_ns);
  EXPECT_EQ(RecordedFrameTimes(rec), expected);
  // Ground truth at the IMU rate: the listed frames, then every 50 ms from the last of them.
  std::vector<NavState> dense;
  for (const ImuSample& s : excerpt.imu) {
    NavState x = excerpt.groundtruth.front();
    x.t_ns = s.t_ns;
    dense.push_back(x);
  }
  rec = ReadRecording(WriteEurocExcerpt(tmp.path() / "b", listed, dense));
  const std::vector<int64_t> times = RecordedFrameTimes(rec);
  ASSERT_GT(times.size(), 10u);
  EXPECT_TRUE(std::equal(listed.begin(), listed.end(), times.begin()));
  for (std::size_t k = 10; k < times.size(); ++k)
    EXPECT_EQ(times[k] - listed.back(), 50'000'000 * static_cast<int64_t>(k - 9));
  EXPECT_LE(times.back(), dense.back().t_ns);
}

// The estimator on the excerpt's real times (a dropped frame included), seeded from ground truth.
TEST(SemiReal, TheEstimatorRunsOnRecordedTimes) {
  experiments::RunConfig config;
  config.sim = SemiReal(kSemiRealExcerpt, 3.0);
  config.sim.camera.pixel_noise_px = 0.5;
  config.estimator.init = estimator::InitMode::kGroundTruth;
  // The excerpt's first 3 s barely move, too little to fit a yaw; the estimate starts at the ground truth.
  config.evaluation.align = evaluation::Alignment::kNone;
  const Dataset d = Simulate(config.sim, 1);
  const estimator::EstimatorResult r =
      estimator::RunEstimator(config.estimator, experiments::MakeEstimatorInput(config, d, d.imu));
  ASSERT_TRUE(r.ok) << r.failure_reason;
  const std::vector<int64_t> frames = TimesOf(d.frames);
  for (const StampedPose& p : r.trajectory)
    EXPECT_TRUE(std::binary_search(frames.begin(), frames.end(), p.t_ns)) << p.t_ns;
  const evaluation::TrajectoryEvaluation e = evaluation::EvaluateTrajectory(
      experiments::GroundTruthAtFrames(d.groundtruth, d.frames), r.trajectory, config.evaluation);
  EXPECT_LT(e.ate_trans_m.rmse, 0.1);
}

// configs/euroc_v1_01_semireal.yaml's dataset on a V1_01 folder: frames at cam0/data.csv's times then the
// ground truth's, the recorded IMU unchanged, features in every frame. The folder's images are not read.
void ExpectV101SemiReal(const experiments::RunConfig& c, const fs::path& recording, std::size_t frames) {
  const Dataset d = Simulate(c.sim, c.seed);
  const Recording rec = ReadRecording(recording, /*check_image_files=*/false);
  ASSERT_EQ(d.frames.size(), frames);
  ASSERT_EQ(d.frames.size(), rec.dataset.groundtruth.size());  // nothing padded
  // cam0/data.csv's 95 times, then the ground truth's (the redistributed ground truth's times are the camera
  // times rounded: up to 256 ns away from cam0/data.csv's).
  ASSERT_EQ(rec.images.size(), 95u);
  for (std::size_t k = 0; k < d.frames.size(); ++k) {
    ASSERT_EQ(d.frames[k].t_ns, k < rec.images.size() ? rec.images[k].t_ns : rec.dataset.groundtruth[k].t_ns);
    ASSERT_LE(std::abs(d.frames[k].t_ns - rec.dataset.groundtruth[k].t_ns), 256);
  }
  EXPECT_EQ(d.imu_clean.front().t_ns, rec.dataset.imu.front().t_ns);
  EXPECT_GE(d.imu_clean.back().t_ns, rec.dataset.groundtruth.back().t_ns);
  const auto first = std::find_if(rec.dataset.imu.begin(), rec.dataset.imu.end(),
                                  [&](const ImuSample& s) { return s.t_ns == d.imu_clean.front().t_ns; });
  ImuStream window(first, first + static_cast<std::ptrdiff_t>(d.imu_clean.size()));
  ExpectSameImu(d.imu_clean, window);
  std::size_t fewest = 1000;
  for (const CameraFrame& f : d.frames) fewest = std::min(fewest, f.features.size());
  std::printf("V1_01 semi-real: %zu frames, %zu IMU samples, features per frame min %zu\n", d.frames.size(),
              d.imu.size(), fewest);
  EXPECT_GE(fewest, 10u);
}

const std::string kV101Config = std::string(VIGIL_SOURCE_DIR) + "/configs/euroc_v1_01_semireal.yaml";

// The shipped config reads the committed excerpt, whole: on every clone, without its images.
TEST(SemiReal, V101ExcerptIsTheShippedConfigsRecording) {
  const experiments::RunConfig c = experiments::LoadRunConfig(kV101Config);
  EXPECT_EQ(c.sim.imu.recording, kV101Excerpt.lexically_normal().string());
  ASSERT_FALSE(fs::exists(kV101Excerpt / "mav0/cam0/data"));
  EXPECT_EQ(ReadRecording(kV101Excerpt, /*check_image_files=*/false).dataset.imu.size(), 6001u);
  ExpectV101SemiReal(c, kV101Excerpt, 601);  // 30 s at 20 Hz
}

TEST(SemiReal, V101WholeFlightUsesItsRecordedTimes) {
  if (!fs::exists(kV101 / "mav0")) GTEST_SKIP() << "SKIPPED: " << kV101.string() << " is absent";
  ExpectV101SemiReal(
      experiments::LoadRunConfig(kV101Config, {"imu.recording=" + kV101.string(), "duration_s=144.7"}), kV101,
      2895);
}

}  // namespace
}  // namespace vigil::sim
