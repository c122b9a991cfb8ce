#include "experiments/runs/run_config.h"

#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "tests/core/test_util.h"

namespace vigil::experiments {
namespace {
using testing::InputErrorOf;
using testing::TempDir;

TEST(RunConfig, SpecKeysExistWithTheirTypes) {
  // The keys that docs/cli.md promises to scripts and tests.
  const RunConfig c = LoadRunConfig(
      "", {"seed=5", "imu.rate_hz=400", "imu.noise.enabled=false", "camera.rate_hz=20",
           "camera.pixel_noise_px=0.5", "glitch.enabled=true", "glitch.mean=50", "glitch.std=10",
           "glitch.rate=0.02", "glitch.axes=[ax, az]", "detector.type=none", "estimator.init=groundtruth",
           "evaluation.align=se3", "evaluation.distances_m=[7, 14]"});
  EXPECT_EQ(c.seed, 5u);
  EXPECT_EQ(c.sim.imu.rate_hz, 400.0);
  EXPECT_FALSE(c.sim.imu.noise.enabled);
  EXPECT_EQ(c.sim.camera.pixel_noise_px, 0.5);
  EXPECT_EQ(c.sim.glitch.axes, (std::vector<ImuAxis>{ImuAxis::kAx, ImuAxis::kAz}));
  EXPECT_EQ(c.evaluation.align, evaluation::Alignment::kSe3);
  EXPECT_EQ(c.evaluation.distances_m, (std::vector<double>{7.0, 14.0}));
}

TEST(RunConfig, BadKeysAreNamed) {
  EXPECT_EQ(InputErrorOf([] { LoadRunConfig("", {"glitch.axes=[az, q]"}); }),
            "--set: glitch.axes: must be one of: wx, wy, wz, ax, ay, az");
  EXPECT_EQ(InputErrorOf([] { LoadRunConfig("", {"imu.noise.loud=true"}); }),
            "--set: imu.noise.loud: unknown key");
  EXPECT_EQ(InputErrorOf([] { LoadRunConfig("", {"glitch.rate=2"}); }),
            "--set: glitch.rate: must be in [0, 1]");
  EXPECT_EQ(InputErrorOf([] {
              LoadRunConfig("", {"glitch.enabled=true", "glitch.axes=[]"});
            }),
            "--set glitch.axes=[]: glitch.axes: must name at least one axis when glitch.enabled is true");
}

TEST(RunConfig, ShippedConfigsLoadAndEveryKeyIsDocumented) {
  for (const char* name : {"paper.yaml"}) {
    const std::string path = std::string(VIGIL_SOURCE_DIR) + "/configs/" + name;
    EXPECT_EQ(InputErrorOf([&] { LoadRunConfig(path); }), "") << path;
  }
  std::ifstream in(std::string(VIGIL_SOURCE_DIR) + "/configs/README.md");
  const std::string readme((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  RunConfig c;
  EXPECT_NE(readme.find(config::KeysMarkdownTable(config::DescribeKeys(c))), std::string::npos)
      << "configs/README.md's key table is out of date: run scripts/update-config-docs";
}

TEST(RunConfig, CrossKeyChecksNameTheLineOrTheSet) {
  TempDir dir;
  const std::string path = dir.File("c.yaml", "seed: 1\nimu:\n  rate_hz: 20\ncamera:\n  rate_hz: 30\n");
  EXPECT_EQ(InputErrorOf([&] { LoadRunConfig(path); }),
            path + ":3: imu.rate_hz: must be at least camera.rate_hz");
  EXPECT_EQ(InputErrorOf([&] { LoadRunConfig(path, {"imu.rate_hz=25"}); }),
            "--set imu.rate_hz=25: imu.rate_hz: must be at least camera.rate_hz");
  // The key at fault is not in the file: the line of the other key its reason names.
  const std::string fast = dir.File("f.yaml", "seed: 1\ncamera:\n  rate_hz: 1e12\n");
  EXPECT_EQ(InputErrorOf([&] { LoadRunConfig(fast); }),
            fast + ":3: imu.rate_hz: must be at least camera.rate_hz");
  const std::string tbc = dir.File("t.yaml", "camera:\n  T_BC: [1, 2]\n");
  EXPECT_EQ(InputErrorOf([&] { LoadRunConfig(tbc); }).rfind(tbc + ":2: camera.T_BC: ", 0), 0u);
  const std::string axes = dir.File("a.yaml", "glitch:\n  enabled: true\n  axes: [az, az]\n");
  EXPECT_EQ(InputErrorOf([&] { LoadRunConfig(axes); }), axes + ":3: glitch.axes: axis az listed twice");
}

// A path under $VIGIL_DATA is read inside the folder the variable names; unset, the line or --set that used
// it is named with the variable.
TEST(RunConfig, VigilDataPathsNeedTheVariable) {
  TempDir dir;
  const std::string path =
      dir.File("c.yaml", "seed: 1\nimu:\n  source: recording\n  recording: $VIGIL_DATA/euroc/V1_01_easy\n");
  const std::string reason =
      "names $VIGIL_DATA, which is not set: export VIGIL_DATA=the folder that holds your datasets "
      "(docs/datasets.md)";
  {
    const vigil::testing::ScopedDataDir unset(nullptr);
    EXPECT_EQ(InputErrorOf([&] { LoadRunConfig(path); }),
              path + ":4: imu.recording: $VIGIL_DATA/euroc/V1_01_easy " + reason);
    EXPECT_EQ(InputErrorOf([&] {
                LoadRunConfig("", {"imu.source=recording", "imu.recording=$VIGIL_DATA/x"});
              }),
              "--set imu.recording=$VIGIL_DATA/x: imu.recording: $VIGIL_DATA/x " + reason);
    const std::string trajectory = dir.File(
        "t.yaml", "duration_s: 0\ntrajectory:\n  type: recording\n  recording: $VIGIL_DATA/gt.txt\n");
    EXPECT_EQ(InputErrorOf([&] { LoadRunConfig(trajectory); }),
              trajectory + ":4: trajectory.recording: $VIGIL_DATA/gt.txt " + reason);
  }
  const vigil::testing::ScopedDataDir set("/datasets");
  EXPECT_EQ(LoadRunConfig(path).sim.imu.recording, "/datasets/euroc/V1_01_easy");
}

TEST(RunConfig, EveryInputPathIsRelativeToTheConfigFile) {
  // The detector's files as the simulator's: relative to the config file, --set values to the working
  // directory, "$VIGIL_DATA/..." in the data folder.
  TempDir dir;
  std::filesystem::create_directories(dir.path() / "sub");
  const std::string path = dir.File(
      "sub/c.yaml", "detector:\n  calibration_dataset: ../clean\n  dtw:\n    templates_file: t.yaml\n");
  const RunConfig from_file = LoadRunConfig(path);
  EXPECT_EQ(from_file.detector.calibration_dataset, (dir.path() / "clean").string());
  EXPECT_EQ(from_file.detector.dtw.templates_file, (dir.path() / "sub/t.yaml").string());
  const RunConfig from_set = LoadRunConfig(path, {"detector.dtw.templates_file=lib.yaml"});
  EXPECT_EQ(from_set.detector.dtw.templates_file, (std::filesystem::current_path() / "lib.yaml").string());
  const vigil::testing::ScopedDataDir unset(nullptr);
  EXPECT_EQ(InputErrorOf([&] { LoadRunConfig(path, {"detector.calibration_dataset=$VIGIL_DATA/c"}); }),
            "--set detector.calibration_dataset=$VIGIL_DATA/c: detector.calibration_dataset: $VIGIL_DATA/c "
            "names $VIGIL_DATA, which is not set: export VIGIL_DATA=the folder that holds your datasets "
            "(docs/datasets.md)");
}

TEST(RunConfig, CrossKeyErrorOfASetKeyNotInTheFileNamesTheSet) {
  TempDir dir;
  const std::string path = dir.File("c.yaml", "seed: 1\ncamera:\n  rate_hz: 20\n");
  // The key at fault was set on the command line: no line of the file is to blame.
  EXPECT_EQ(InputErrorOf([&] { LoadRunConfig(path, {"imu.rate_hz=10"}); }),
            "--set imu.rate_hz=10: imu.rate_hz: must be at least camera.rate_hz");
  // The other key of the check was set on the command line: that --set, not the file's default.
  EXPECT_EQ(InputErrorOf([&] { LoadRunConfig(path, {"camera.rate_hz=500"}); }),
            "--set camera.rate_hz=500: imu.rate_hz: must be at least camera.rate_hz");
  // The last --set of a key is the one in effect.
  EXPECT_EQ(InputErrorOf([&] {
              LoadRunConfig(path, {"imu.rate_hz=300", "imu.rate_hz=5"});
            }),
            "--set imu.rate_hz=5: imu.rate_hz: must be at least camera.rate_hz");
  // Without a file.
  EXPECT_EQ(InputErrorOf([&] { LoadRunConfig("", {"camera.rate_hz=500"}); }),
            "--set camera.rate_hz=500: imu.rate_hz: must be at least camera.rate_hz");
}

// Every key that feeds the IMU is bounded when the config is read, naming the key: 1e308 would write IMU
// values that no reader accepts, or overflow to inf.
TEST(RunConfig, KeysThatFeedTheImuAreBounded) {
  for (const char* key :
       {"imu.noise.switch_on_accel_bias_std", "imu.noise.switch_on_gyro_bias_std",
        "imu.noise.gyro_noise_density", "imu.noise.accel_noise_density", "imu.noise.gyro_bias_random_walk",
        "imu.noise.accel_bias_random_walk", "imu.vibration.frequency_hz", "imu.vibration.bandwidth_hz",
        "imu.vibration.accel_rms_mps2", "imu.vibration.gyro_rms_radps", "imu.rate_hz", "gravity_mps2",
        "faults.saturation.accel_range_mps2", "faults.saturation.accel_range_g",
        "faults.saturation.gyro_range_dps", "faults.quantization.accel_lsb_mps2",
        "faults.quantization.gyro_lsb_dps", "faults.timing.jitter_std_s"}) {
    const std::string error = InputErrorOf([&] { LoadRunConfig("", {std::string(key) + "=1e308"}); });
    EXPECT_EQ(error.rfind("--set: " + std::string(key) + ": must be ", 0), 0u) << error;
  }
  for (const char* key : {"imu.noise.initial_accel_bias", "imu.noise.initial_gyro_bias",
                          "faults.scale.accel_scale", "faults.scale.gyro_scale",
                          "faults.scale.accel_misalignment_deg", "faults.scale.gyro_misalignment_deg"}) {
    const std::string error = InputErrorOf([&] { LoadRunConfig("", {std::string(key) + "=[0, 0, 1e308]"}); });
    EXPECT_EQ(error.rfind("--set: " + std::string(key) + ": must be ", 0), 0u) << error;
  }
  // Values of real sensors, and far beyond, still pass.
  EXPECT_EQ(InputErrorOf([] {
              LoadRunConfig("", {"imu.noise.switch_on_accel_bias_std=0.5", "imu.vibration.frequency_hz=150",
                                 "imu.vibration.accel_rms_mps2=20", "imu.rate_hz=4000"});
            }),
            "");
}

// Sizes that a config value drives are bounded before anything is allocated: 2e9 random landmarks or a
// detector window of 2e9 samples ended in std::bad_alloc (exit 1) instead of an error naming the key.
TEST(RunConfig, SizesThatDriveAllocationsAreBounded) {
  for (const char* key :
       {"landmarks.random_count", "detector.threshold.mean_samples",
        "detector.relative_threshold.reference_samples", "detector.hampel.half_window",
        "detector.dtw.templates", "detector.dtw.slice_length", "detector.dtw.max_build_slices"}) {
    const std::string error = InputErrorOf([&] { LoadRunConfig("", {std::string(key) + "=2000000000"}); });
    EXPECT_EQ(error.rfind("--set: " + std::string(key) + ": must be in [", 0), 0u) << error;
  }
  EXPECT_EQ(InputErrorOf([] {
              LoadRunConfig("", {"landmarks.layout=random", "landmarks.random_count=100000",
                                 "detector.hampel.half_window=100000"});
            }),
            "");
}

// A problem found after loading is located like a cross-key check: at the --set that set its key, or the
// file's line, never with an empty location.
TEST(RunConfig, LaterProblemsNameTheSetOrTheLine) {
  EXPECT_EQ(std::string(LocatedConfigError("", {"estimator.external.input=images"},
                                           "estimator.external.input: images: no images")
                            .what()),
            "--set estimator.external.input=images: estimator.external.input: images: no images");
  EXPECT_EQ(std::string(LocatedConfigError("", {}, "estimator.external.input: images: no images").what()),
            "--set: estimator.external.input: images: no images");
  TempDir dir;
  const std::string path = dir.File("c.yaml", "seed: 1\nimu:\n  source: recording\n  recording: gone\n");
  EXPECT_EQ(
      std::string(LocatedConfigError(path, {}, "imu.recording: gone: no such file or directory").what()),
      path + ":4: imu.recording: gone: no such file or directory");
  RunConfig config;
  config.sim.imu.recording = (dir.path() / "gone").string();
  EXPECT_EQ(MissingInputProblem(config),
            "imu.recording: " + config.sim.imu.recording + ": no such file or directory");
  config.sim.imu.recording = dir.path().string();
  EXPECT_EQ(MissingInputProblem(config), "");
}

}  // namespace
}  // namespace vigil::experiments
