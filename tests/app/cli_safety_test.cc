// The data-safety and bad-input promises of every command, checked on the built `vigil`: an output that is,
// contains or lies inside an input is refused with or without --force, --force replaces only what vigil
// wrote, and bad input gets one line "vigil: error: ..." with exit status 2.
#include <sys/stat.h>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <set>
#include <string>

#include <gtest/gtest.h>

#include "core/output.h"
#include "tests/app/vigil_cli.h"
#include "tests/core/test_util.h"

namespace vigil {
namespace {
namespace fs = std::filesystem;
using testing::CliResult;
using testing::TempDir;
using testing::Vigil;

// A short simulated dataset (2 s of the paper scenario) at tmp/ds, with its config at tmp/config.yaml.
class Cli : public ::testing::Test {
 protected:
  void SetUp() override {
    config_ = tmp_.File("config.yaml", "duration_s: 2\nglitch:\n  enabled: true\n");
    ds_ = (tmp_.path() / "ds").string();
    ASSERT_EQ(Vigil(tmp_, "simulate " + config_ + " -o " + ds_).status, 0);
    listing_ = Listing(ds_);
  }
  // Every entry of `dir` with its size: what must not change.
  static std::string Listing(const fs::path& dir) {
    std::string s;
    std::set<std::string> lines;
    for (const auto& e : fs::recursive_directory_iterator(dir))
      lines.insert(e.path().lexically_relative(dir).string() + " " +
                   (e.is_regular_file() ? std::to_string(e.file_size()) : "dir"));
    for (const auto& line : lines) s += line + "\n";
    return s;
  }
  void ExpectRefused(const std::string& args, const std::string& reason) {
    const CliResult r = Vigil(tmp_, args);
    EXPECT_EQ(r.status, 2) << args << ": " << r.err;
    EXPECT_NE(r.err.find(reason), std::string::npos) << args << ": " << r.err;
    EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << "one line: " << r.err;
  }
  void ExpectDatasetIntact() { EXPECT_EQ(Listing(ds_), listing_); }
  // A copy of the dataset at tmp/NAME, to spoil.
  std::string CopyOfDataset(const std::string& name) {
    const fs::path copy = tmp_.path() / name;
    fs::copy(ds_, copy, fs::copy_options::recursive);
    return copy.string();
  }

  TempDir tmp_;
  std::string config_, ds_, listing_;
};

TEST_F(Cli, CleanNeverWritesOverItsDataset) {
  for (const char* force : {"", " --force"}) {
    ExpectRefused("clean " + ds_ + " -o " + ds_ + " --detector hampel" + force, "the output is the input");
    ExpectRefused("clean " + ds_ + "/imu.csv -o " + ds_ + "/../ds/ --detector hampel" + force,
                  "contains the input");
    ExpectRefused("clean " + ds_ + " -o " + ds_ + "/cleaned --detector hampel" + force,
                  "lies inside the input");
    ExpectRefused("clean " + ds_ + " -o " + tmp_.path().string() + " --detector hampel" + force,
                  "contains the input");
  }
  ExpectDatasetIntact();
  EXPECT_EQ(Vigil(tmp_, "clean " + ds_ + " -o " + tmp_.path().string() + "/cleaned --detector hampel").status,
            0);
}

TEST_F(Cli, RunNeverWritesOverItsDatasetOrConfig) {
  for (const char* force : {"", " --force"}) {
    ExpectRefused("run " + config_ + " --dataset " + ds_ + " -o " + ds_ + force, "the output is the input");
    ExpectRefused("run " + config_ + " -o " + tmp_.path().string() + force, "contains the input");
  }
  fs::create_directory_symlink(ds_, tmp_.path() / "link");
  ExpectRefused(
      "run " + config_ + " --dataset " + ds_ + " -o " + (tmp_.path() / "link").string() + " --force",
      "the output is the input");
  ExpectDatasetIntact();
}

TEST_F(Cli, SimulateNeverWritesOverItsConfig) {
  ExpectRefused("simulate " + config_ + " -o " + tmp_.path().string() + " --force", "contains the input");
  ExpectRefused("simulate " + config_ + " -o " + config_ + " --force", "the output is the input");
  EXPECT_TRUE(fs::is_regular_file(config_));
}

TEST_F(Cli, TemplatesNeverOverwritesTheRecording) {
  for (const char* force : {"", " --force"})
    ExpectRefused("templates " + ds_ + " -o " + ds_ + "/imu.csv" + force, "lies inside the input");
  ExpectRefused("templates " + ds_ + "/imu.csv -o " + ds_ + "/imu.csv --force", "the output is the input");
  ExpectDatasetIntact();
  const std::string mine = tmp_.File("mine.yaml", "user: data\n");
  ExpectRefused("templates " + ds_ + " -o " + mine + " --force", "not a file vigil wrote");
  EXPECT_EQ(ReadFile(mine), "user: data\n");
}

TEST_F(Cli, PlotNeverWritesOverItsInput) {
  for (const char* force : {"", " --force"})
    ExpectRefused("plot dataset " + ds_ + " -o " + ds_ + force, "the output is the input");
  ExpectRefused("plot dataset " + ds_ + " -o " + ds_ + "/imu.csv --force", "the output is the input");
  ExpectDatasetIntact();
}

TEST_F(Cli, SweepNeverWritesOverItsSweepFileOrBase) {
  const std::string sweep =
      tmp_.File("sweep.yaml", "base: config.yaml\nmethods: {original: none}\nseeds: [1]\n");
  for (const char* force : {"", " --force"})
    ExpectRefused("sweep " + sweep + " -o " + tmp_.path().string() + force + " --quiet",
                  "contains the input");
  ExpectRefused("sweep " + sweep + " -o " + sweep + " --quiet", "the output is the input");
  EXPECT_TRUE(fs::is_regular_file(sweep));
  ExpectRefused("paper --sweep " + sweep + " -o " + tmp_.path().string() + " --force --quiet",
                "contains the input");
}

TEST_F(Cli, ForceRefusesADirectoryVigilDidNotWrite) {
  const fs::path mine = tmp_.path() / "mine";
  fs::create_directory(mine);
  tmp_.File("mine/thesis.tex", "precious");
  ExpectRefused("simulate " + config_ + " -o " + mine.string() + " --force", "not written by vigil");
  ExpectRefused("clean " + ds_ + " -o " + mine.string() + " --detector none --force", "not written by vigil");
  ExpectRefused("plot dataset " + ds_ + " -o " + mine.string() + " --force", "not written by vigil");
  ExpectRefused("sweep " + tmp_.File("s.yaml", "base: config.yaml\nmethods: {original: none}\nseeds: [1]\n") +
                    " -o " + mine.string() + " --force --quiet",
                "not a sweep directory");
  EXPECT_EQ(ReadFile(mine / "thesis.tex"), "precious");
  EXPECT_EQ(std::distance(fs::directory_iterator(mine), fs::directory_iterator()), 1);
}

TEST_F(Cli, ForceKeepsFilesVigilDidNotWrite) {
  tmp_.File("ds/notes.txt", "mine");
  ASSERT_EQ(Vigil(tmp_, "simulate " + config_ + " -o " + ds_ + " --force --seed 2").status, 0);
  EXPECT_EQ(ReadFile(fs::path(ds_) / "notes.txt"), "mine");
  const std::string figures = (tmp_.path() / "figures").string();
  ASSERT_EQ(Vigil(tmp_, "plot dataset " + ds_ + " -o " + figures + " --width 200 --height 200").status, 0);
  tmp_.File("figures/keep.txt", "mine");
  ASSERT_EQ(
      Vigil(tmp_, "plot dataset " + ds_ + " -o " + figures + " --width 200 --height 200 --force").status, 0);
  EXPECT_EQ(ReadFile(fs::path(figures) / "keep.txt"), "mine");
}

TEST_F(Cli, BadSeedsAreRefusedNotClamped) {
  ExpectRefused("config " + config_ + " --seed 9223372036854775808", "--seed: expected an integer");
  ExpectRefused("config " + config_ + " --seed 18446744073709551616", "--seed: expected an integer");
  ExpectRefused("config " + config_ + " --seed -1", "--seed");
  const CliResult r = Vigil(tmp_, "config " + config_ + " --seed 9223372036854775807");
  EXPECT_EQ(r.status, 0) << r.err;
}

TEST_F(Cli, OnlyRegularFilesAreReadAsConfig) {
  ExpectRefused("config " + tmp_.path().string(), "is a directory");
  ExpectRefused("config /dev/zero", "not a regular file");
  const fs::path fifo = tmp_.path() / "fifo.yaml";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  ExpectRefused("config " + fifo.string(), "not a regular file");  // returns instead of blocking
  ExpectRefused(
      "run " + config_ + " --dataset " + tmp_.path().string() + "/nowhere -o " + tmp_.path().string() + "/r",
      "nowhere");
}

TEST_F(Cli, DuplicateKeysAndBlockScalarsGiveOneLineErrors) {
  ExpectRefused("config " + tmp_.File("dup.yaml", "seed: 1\nduration_s: 2\nseed: 3\n"),
                "dup.yaml:3: seed: duplicate key (first at line 1)");
  ExpectRefused("config " + tmp_.File("block.yaml", "seed: |\n  5\n  6\n"), "block.yaml:1: seed:");
  ExpectRefused("config " + tmp_.File("nul.yaml", std::string("seed: 5\0x\n", 10)), "");
}

TEST_F(Cli, AnImuCleanOfOtherSamplesNamesBothFilesAndWhatToDo) {
  const std::string ds = CopyOfDataset("short_clean");
  const std::string clean = ds + "/imu_clean.csv", text = ReadFile(clean);
  std::size_t end = 0;  // after the header and 10 samples
  for (int line = 0; line < 11; ++line) end = text.find('\n', end) + 1;
  WriteFileAtomic(clean, text.substr(0, end));
  const std::string reason = clean + ": 10 samples, but " + ds + "/imu.csv has ";
  ExpectRefused("run " + config_ + " --dataset " + ds + " -o " + tmp_.path().string() + "/r", reason);
  ExpectRefused("clean " + ds + " -o " + tmp_.path().string() + "/c --detector hampel", reason);
  ExpectRefused("clean " + ds + " -o " + tmp_.path().string() + "/c --detector hampel",
                "regenerate both together or remove imu_clean.csv");
  EXPECT_FALSE(fs::exists(tmp_.path() / "r"));
  EXPECT_FALSE(fs::exists(tmp_.path() / "c"));
}

TEST_F(Cli, ACrossKeyErrorFromASetNamesTheSet) {
  ExpectRefused("simulate " + config_ + " --set imu.rate_hz=10 -o " + tmp_.path().string() + "/s",
                "vigil: error: --set imu.rate_hz=10: imu.rate_hz: must be at least camera.rate_hz");
  ExpectRefused("run " + config_ + " --set camera.rate_hz=500 -o " + tmp_.path().string() + "/r",
                "vigil: error: --set camera.rate_hz=500: imu.rate_hz: must be at least camera.rate_hz");
}

// Refused where the config says it (it used to be caught only as a non-finite value in the written IMU).
TEST_F(Cli, AnOutOfRangeNoiseDensityIsRefusedAtItsConfigLine) {
  const std::string loud =
      tmp_.File("loud.yaml", "duration_s: 2\nimu:\n  noise:\n    accel_noise_density: 1e308\n");
  const std::string out = tmp_.path().string() + "/loud";
  ExpectRefused("simulate " + loud + " -o " + out, loud + ":4: imu.noise.accel_noise_density: must be in");
  EXPECT_FALSE(fs::exists(out));
}

TEST_F(Cli, AFifoOrAHugePixelInTheDatasetIsRefused) {
  const std::string fifo_ds = CopyOfDataset("fifo");
  fs::remove(fifo_ds + "/features.csv");
  ASSERT_EQ(::mkfifo((fifo_ds + "/features.csv").c_str(), 0600), 0);
  ExpectRefused("run " + config_ + " --dataset " + fifo_ds + " -o " + tmp_.path().string() + "/r",
                fifo_ds + "/features.csv: not a regular file");  // returns instead of blocking
  const std::string far = CopyOfDataset("far");
  std::string features = ReadFile(far + "/features.csv");
  const std::size_t row = features.find('\n') + 1, u = features.find(',', features.find(',', row) + 1) + 1;
  features.replace(u, features.find(',', u) - u, "1e308");
  WriteFileAtomic(far + "/features.csv", features);
  ExpectRefused("run " + config_ + " --dataset " + far + " -o " + tmp_.path().string() + "/r",
                far + "/features.csv:2: pixel (1e+308, ");
  EXPECT_FALSE(fs::exists(tmp_.path() / "r"));
}

TEST_F(Cli, AHugeSeedCountIsRefusedBeforeAnyWork) {
  const std::string sweep =
      tmp_.File("many.yaml", "base: config.yaml\nmethods: {original: none}\nseeds: {count: 100000000}\n");
  ExpectRefused("sweep " + sweep + " -o " + tmp_.path().string() + "/s --quiet", "many.yaml:3: seeds");
  EXPECT_FALSE(fs::exists(tmp_.path() / "s"));
}

}  // namespace
}  // namespace vigil

namespace vigil {
namespace {

// A EuRoC folder as published, from `vigil simulate --images` (2 s, 160 x 120: the first window at 10 solved
// frames per second ends at 1.5 s): tmp/eu/mav0 with the
// dataset's features.csv beside it.
class EurocCli : public ::testing::Test {
 protected:
  void SetUp() override {
    config_ =
        tmp_.File("config.yaml",
                  "duration_s: 2\ncamera: {width: 160, height: 120, fx: 115, fy: 115, cx: 79.5, cy: 59.5}\n");
    const std::string ds = (tmp_.path() / "ds").string();
    ASSERT_EQ(Vigil(tmp_, "simulate " + config_ + " -o " + ds + " --images").status, 0);
    fs::create_directories(eu_);
    fs::copy(tmp_.path() / "ds" / "mav0", eu_ / "mav0", fs::copy_options::recursive);
    fs::copy_file(tmp_.path() / "ds" / "features.csv", eu_ / "features.csv");
  }
  // `vigil run` on the folder: exit 2, one line containing `reason`, no output directory.
  void ExpectRunRefused(const std::string& reason) {
    const CliResult r = Vigil(tmp_, "run " + config_ + " --dataset " + eu_.string() + " -o " + out_.string());
    EXPECT_EQ(r.status, 2) << r.err;
    EXPECT_NE(r.err.find(reason), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << "one line: " << r.err;
    EXPECT_FALSE(fs::exists(out_));
  }
  void Edit(const std::string& file, const std::string& from, const std::string& to) {
    std::string text = ReadFile(eu_ / file);
    const std::size_t at = text.find(from);
    ASSERT_NE(at, std::string::npos) << from;
    text.replace(at, from.size(), to);
    WriteFileAtomic(eu_ / file, text);
  }

  TempDir tmp_;
  std::string config_;
  fs::path eu_ = tmp_.path() / "eu", out_ = tmp_.path() / "out";
};

TEST_F(EurocCli, RunsAsPublishedWithAndWithoutGroundTruth) {
  const CliResult with =
      Vigil(tmp_, "run " + config_ + " --dataset " + eu_.string() + " -o " + out_.string());
  ASSERT_EQ(with.status, 0) << with.err;
  EXPECT_NE(ReadFile(out_ / "metrics.json").find("\"ate\""), std::string::npos);
  EXPECT_TRUE(fs::exists(out_ / "stamped_groundtruth.txt"));
  fs::remove_all(eu_ / "mav0" / "state_groundtruth_estimate0");
  const fs::path out2 = tmp_.path() / "out2";
  // Ground-truth initialization (the config's default) cannot work without it: a clear error.
  const std::string mav0 = (eu_ / "mav0").string();
  const CliResult init = Vigil(tmp_, "run " + config_ + " --dataset " + mav0 + " -o " + out2.string());
  EXPECT_EQ(init.status, 2);
  EXPECT_NE(init.err.find("groundtruth initialization needs ground truth"), std::string::npos) << init.err;
  // VINS initialization: the estimate is written, the metrics skipped (status from the estimator alone).
  const CliResult without =
      Vigil(tmp_, "run " + config_ + " --set estimator.init=vins --dataset " + mav0 + " -o " + out2.string());
  EXPECT_TRUE(without.status == 0 || without.status == 1) << without.err;
  EXPECT_NE(without.err.find("skipped: the dataset has no ground truth"), std::string::npos) << without.err;
  const std::string metrics = ReadFile(out2 / "metrics.json");
  EXPECT_NE(metrics.find("\"evaluation\": \"skipped: the dataset has no ground truth\""), std::string::npos);
  EXPECT_NE(metrics.find(without.status == 0 ? "\"status\": \"ok\"" : "\"status\": \"failed\""),
            std::string::npos);
  EXPECT_TRUE(fs::exists(out2 / "stamped_traj_estimate.txt"));
  EXPECT_FALSE(fs::exists(out2 / "stamped_groundtruth.txt"));
}

TEST_F(EurocCli, MissingImageIsRefused) {
  const fs::path data = eu_ / "mav0" / "cam0" / "data";
  fs::remove(*fs::directory_iterator(data));
  ExpectRunRefused("image file is missing");
}

TEST_F(EurocCli, RowWithoutFileNameIsRefused) {
  std::string text = ReadFile(eu_ / "mav0/cam0/data.csv");
  const std::size_t line3 = text.find('\n', text.find('\n') + 1) + 1;
  text.replace(text.find(',', line3), text.find('\n', line3) - text.find(',', line3), ",");
  WriteFileAtomic(eu_ / "mav0/cam0/data.csv", text);
  ExpectRunRefused("mav0/cam0/data.csv:3: filename: missing");
}

TEST_F(EurocCli, SensorYamlWithoutIntrinsicsIsRefused) {
  Edit("mav0/cam0/sensor.yaml", "intrinsics:", "# intrinsics:");
  ExpectRunRefused("mav0/cam0/sensor.yaml: intrinsics: missing");
}

TEST_F(EurocCli, ImuOnlyCleansButDoesNotRun) {
  fs::remove_all(eu_ / "mav0" / "cam0");
  ExpectRunRefused("IMU only");
  const CliResult clean =
      Vigil(tmp_, "clean " + eu_.string() + " -o " + out_.string() + " --detector hampel");
  EXPECT_EQ(clean.status, 0) << clean.err;
  EXPECT_TRUE(fs::exists(out_ / "imu.csv"));
}

// Without features.csv the run tracks the images with the visual front-end itself.
TEST_F(EurocCli, ImagesWithoutFeaturesAreTrackedByTheFrontEnd) {
  fs::remove(eu_ / "features.csv");
  const CliResult r = Vigil(tmp_, "run " + config_ + " --dataset " + eu_.string() + " -o " + out_.string());
  EXPECT_NE(r.status, 2) << r.err;
  EXPECT_NE(ReadFile(out_ / "metrics.json").find("\"frontend\""), std::string::npos);
}

}  // namespace
}  // namespace vigil
