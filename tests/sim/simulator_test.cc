#include "sim/simulator.h"

#include <algorithm>
#include <cstdio>

#include <gtest/gtest.h>

#include "core/output.h"
#include "experiments/runs/run_config.h"
#include "tests/core/test_util.h"

namespace vigil::sim {
namespace {
namespace fs = std::filesystem;
using testing::InputErrorOf;
using testing::TempDir;

const char* const kFiles[] = {"config.yaml",     "imu.csv",       "imu_clean.csv", "glitches.csv",
                              "groundtruth.csv", "landmarks.csv", "features.csv",  "camera.yaml"};

// `vigil simulate CONFIG -o DIR [--set ...]` without the process: what cmd_simulate.cc does.
void SimulateCommand(const std::string& config, const std::vector<std::string>& overrides,
                     const fs::path& dir, bool force = false) {
  experiments::RunConfig c = experiments::LoadRunConfig(config, overrides);
  SimulateToDirectory(c.sim, c.seed, config::ToYaml(c), dir, force);
}

const std::string kPaper = std::string(VIGIL_SOURCE_DIR) + "/configs/paper.yaml";
const std::vector<std::string> kGlitchy = {"glitch.enabled=true", "camera.pixel_noise_px=0.7",
                                           "landmarks.layout=house+random", "landmarks.random_count=50"};

TEST(Simulator, SameSeedGivesIdenticalBytesAndTheConfigReproducesThem) {
  TempDir tmp;
  SimulateCommand(kPaper, kGlitchy, tmp.path() / "a");
  SimulateCommand(kPaper, kGlitchy, tmp.path() / "b");
  // The written config.yaml alone reproduces the dataset.
  SimulateCommand((tmp.path() / "a" / "config.yaml").string(), {}, tmp.path() / "c");
  for (const char* f : kFiles) {
    const std::string a = ReadFile(tmp.path() / "a" / f);
    EXPECT_FALSE(a.empty()) << f;
    EXPECT_EQ(a, ReadFile(tmp.path() / "b" / f)) << f;
    EXPECT_EQ(a, ReadFile(tmp.path() / "c" / f)) << f;
  }
  // Another seed changes every random stream.
  auto other = kGlitchy;
  other.push_back("seed=2");
  SimulateCommand(kPaper, other, tmp.path() / "d");
  for (const char* f : {"imu.csv", "imu_clean.csv", "glitches.csv", "landmarks.csv", "features.csv"})
    EXPECT_NE(ReadFile(tmp.path() / "a" / f), ReadFile(tmp.path() / "d" / f)) << f;
  EXPECT_EQ(ReadFile(tmp.path() / "a" / "camera.yaml"), ReadFile(tmp.path() / "d" / "camera.yaml"));
}

TEST(Simulator, DatasetRoundTripsThroughTheFiles) {
  TempDir tmp;
  experiments::RunConfig c = experiments::LoadRunConfig(kPaper, kGlitchy);
  const Dataset d = SimulateToDirectory(c.sim, c.seed, config::ToYaml(c), tmp.path() / "ds", false);
  const Dataset back = ReadDataset(tmp.path() / "ds");
  ASSERT_EQ(back.frames.size(), d.frames.size());
  for (std::size_t i = 0; i < d.frames.size(); ++i) {
    ASSERT_EQ(back.frames[i].t_ns, d.frames[i].t_ns);
    ASSERT_EQ(back.frames[i].features.size(), d.frames[i].features.size());
  }
  EXPECT_EQ(back.imu.size(), 4001u);
  EXPECT_EQ(back.glitches.size(), d.glitches.size());
  EXPECT_EQ(back.imu[100].a_B, d.imu[100].a_B);  // shortest round-trip text: exact
  EXPECT_EQ(back.groundtruth[4000].q_WB.coeffs(), d.groundtruth[4000].q_WB.coeffs());
}

// A non-empty output is refused; --force replaces only a directory vigil wrote, and keeps the files in it
// that vigil did not write.
TEST(Simulator, RefusesNonEmptyOutputAndForceKeepsWhatVigilDidNotWrite) {
  TempDir tmp;
  const fs::path out = tmp.path() / "out";
  fs::create_directories(out);
  tmp.File("out/keep.txt", "precious");
  EXPECT_NE(InputErrorOf([&] { SimulateCommand(kPaper, {}, out); }), "");
  EXPECT_NE(
      InputErrorOf([&] { SimulateCommand(kPaper, {}, out, /*force=*/true); }).find("not written by vigil"),
      std::string::npos);
  EXPECT_EQ(ReadFile(out / "keep.txt"), "precious");
  EXPECT_FALSE(fs::exists(out / "features.csv"));

  const fs::path mine = tmp.path() / "mine";
  SimulateCommand(kPaper, {"duration_s=2"}, mine);
  tmp.File("mine/notes.txt", "the user's own");
  SimulateCommand(kPaper, {"duration_s=2"}, mine, /*force=*/true);
  EXPECT_EQ(ReadFile(mine / "notes.txt"), "the user's own");
  EXPECT_TRUE(fs::exists(mine / "features.csv"));
}

TEST(Simulator, BadConfigsAreRejectedWithTheKeyAndWriteNothing) {
  TempDir tmp;
  const fs::path out = tmp.path() / "out";
  const auto error = [&](const std::vector<std::string>& overrides) {
    return InputErrorOf([&] { SimulateCommand(kPaper, overrides, out); });
  };
  EXPECT_NE(error({"imu.rate_hz=-1"}).find("imu.rate_hz"), std::string::npos);
  EXPECT_NE(error({"imu.rate_hz=20"}).find("imu.rate_hz: must be at least camera.rate_hz"),
            std::string::npos);
  EXPECT_NE(error({"glitch.axes=[az, up]"}).find("glitch.axes"), std::string::npos);
  EXPECT_NE(error({"glitch.axes=[az, ax, az]"}).find("glitch.axes: axis az listed twice"), std::string::npos);
  EXPECT_NE(error({"duration_s=1e9"}).find("duration_s: "), std::string::npos);
  EXPECT_NE(error({"imu.noise.initial_accel_bias=[1, 2]"}).find("imu.noise.initial_accel_bias: expected 3"),
            std::string::npos);
  EXPECT_NE(error({"camera.T_BC=[1, 2, 3]"}).find("camera.T_BC"), std::string::npos);
  EXPECT_NE(error({"landmarks.layout=random"}).find("landmarks.random_count"), std::string::npos);
  EXPECT_NE(error({"trajectory.type=waypoints"}).find("trajectory.waypoints_file"), std::string::npos);
  EXPECT_NE(error({"trajectory.kind=ellipse"}).find("trajectory.kind: unknown key"), std::string::npos);
  const std::string bad = tmp.File("bad.yaml", "seed: 1\nimu:\n  rate_hz: fast\n");
  EXPECT_EQ(InputErrorOf([&] { SimulateCommand(bad, {}, out); }).rfind(bad + ":3: imu.rate_hz", 0), 0u);
  EXPECT_FALSE(fs::exists(out));
}

// Every shipped scenario simulates and keeps enough landmarks in view for VIO (VINS-Mono wants about 20
// tracked features per frame). The waypoints file is found relative to the config file, whatever the cwd.
TEST(Simulator, ShippedScenariosKeepLandmarksInView) {
  for (const char* name : {"paper.yaml", "rescue.yaml", "waypoints.yaml"}) {
    const experiments::RunConfig c =
        experiments::LoadRunConfig(std::string(VIGIL_SOURCE_DIR) + "/configs/" + name);
    const Dataset d = Simulate(c.sim, c.seed);
    std::size_t lo = 1 << 30, sum = 0;
    for (const CameraFrame& f : d.frames) {
      lo = std::min(lo, f.features.size());
      sum += f.features.size();
    }
    std::printf("%s: %zu frames, features per frame min %zu mean %.1f\n", name, d.frames.size(), lo,
                static_cast<double>(sum) / static_cast<double>(d.frames.size()));
    EXPECT_GE(lo, 20u) << name;
  }
}

TEST(Simulator, DurationBeyondTheWaypointsIsRejected) {
  const std::string config = std::string(VIGIL_SOURCE_DIR) + "/configs/waypoints.yaml";
  const experiments::RunConfig c = experiments::LoadRunConfig(config, {"duration_s=25"});
  EXPECT_EQ(InputErrorOf([&] { Simulate(c.sim, c.seed); }).rfind("duration_s: ", 0), 0u);
}

}  // namespace
}  // namespace vigil::sim
