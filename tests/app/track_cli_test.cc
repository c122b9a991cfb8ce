// `vigil track` on the built binary: a EuRoC folder of synthetic images in, features.csv + frontend.json +
// config.yaml out; bad images are one-line errors naming the file and line, with nothing written.
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>

#include "core/dataset.h"
#include "core/euroc.h"
#include "core/output.h"
#include "tests/app/vigil_cli.h"
#include "tests/core/test_util.h"
#include "tests/frontend/synthetic_images.h"

namespace vigil {
namespace {
namespace fs = std::filesystem;
using testing::CliResult;
using testing::TempDir;
using testing::Vigil;

constexpr int kImages = 8;
constexpr int64_t kStart_ns = 1'403'636'579'763'555'584LL;  // EuRoC-like absolute timestamps
constexpr int64_t kPeriod_ns = 50'000'000;

// tmp/euroc/mav0 with imu0 (1 s at 200 Hz), cam0 (sensor.yaml + 8 images of a texture sliding 6 px per
// frame) and no ground truth.
class TrackCli : public ::testing::Test {
 protected:
  void SetUp() override {
    dataset_ = tmp_.path() / "euroc";
    fs::create_directories(dataset_);
    Dataset d;
    d.camera.width = 320;
    d.camera.height = 240;
    d.camera.rate_hz = 20.0;
    d.camera.cx = 160.0;
    d.camera.cy = 120.0;
    for (int i = 0; i < 200; ++i) {
      ImuSample s;
      s.t_ns = kStart_ns - 10'000'000 + i * 5'000'000LL;
      s.a_B.z() = 9.81;
      d.imu.push_back(s);
    }
    std::vector<int64_t> times;
    for (int k = 0; k < kImages; ++k) times.push_back(kStart_ns + k * kPeriod_ns);
    WriteEuroc(dataset_, d, EurocImuSensor{}, times);
    const cv::Mat texture = frontend::testing::MakeTexture(320 + 6 * kImages, 240, 3);
    for (int k = 0; k < kImages; ++k)
      cv::imwrite((EurocImageDir(dataset_) / EurocImageName(times[k])).string(),
                  texture(cv::Rect(6 * (kImages - k), 0, 320, 240)));
    times_ = times;
  }
  fs::path Image(int k) const { return EurocImageDir(dataset_) / EurocImageName(times_[k]); }

  TempDir tmp_;
  fs::path dataset_;
  std::vector<int64_t> times_;
};

TEST_F(TrackCli, WritesTracksStatisticsAndConfig) {
  const fs::path out = tmp_.path() / "tracks";
  const CliResult r = Vigil(tmp_, "track " + dataset_.string() + " -o " + out.string() +
                                      " --set frontend.max_features=60 --set frontend.backward_check=true");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("vigil track: 8 images, 8 frames"), std::string::npos) << r.err;
  const std::vector<CameraFrame> frames = ReadFeaturesCsv((out / "features.csv").string(), {}, nullptr);
  ASSERT_EQ(frames.size(), static_cast<std::size_t>(kImages));
  EXPECT_EQ(frames[2].t_ns, times_[2]);
  EXPECT_LE(frames[0].features.size(), 60u);
  EXPECT_GT(frames[kImages - 1].features.size(), 30u);
  const nlohmann::json j = nlohmann::json::parse(ReadFile(out / "frontend.json"));
  EXPECT_EQ(j["images"], kImages);
  EXPECT_FALSE(j.contains("reprojection"));  // no ground truth, no scene
  const std::string config = ReadFile(out / "config.yaml");
  EXPECT_NE(config.find("max_features: 60"), std::string::npos) << config;
  EXPECT_NE(config.find("backward_check: true"), std::string::npos) << config;
  EXPECT_TRUE(fs::exists(out / kOutputManifest));

  // Again: refused without --force, replaced with it; never over its input.
  EXPECT_EQ(Vigil(tmp_, "track " + dataset_.string() + " -o " + out.string()).status, 2);
  EXPECT_EQ(Vigil(tmp_, "track " + dataset_.string() + " -o " + out.string() + " --force").status, 0);
  const CliResult inside = Vigil(tmp_, "track " + dataset_.string() + " -o " + (dataset_ / "t").string());
  EXPECT_EQ(inside.status, 2);
  EXPECT_NE(inside.err.find("lies inside the input"), std::string::npos) << inside.err;
}

TEST_F(TrackCli, BadImagesAreOneLineErrorsAndNothingIsWritten) {
  const fs::path out = tmp_.path() / "tracks";
  const std::string list = (dataset_ / "mav0" / "cam0" / "data.csv").string();
  struct Case {
    std::string what;
    std::function<void()> damage;
    std::string expected;
  };
  const std::vector<Case> cases = {
      {"missing", [&] { fs::remove(Image(3)); }, ":5: "},
      {"unreadable", [&] { std::ofstream(Image(3)) << "not a png"; },
       ":5: " + Image(3).string() + ": not a PNG file"},
      // Only 8-bit grayscale is read (docs/safety.md): colour and 16-bit images are refused, not converted.
      {"rgb", [&] { cv::imwrite(Image(3).string(), cv::Mat(240, 320, CV_8UC3, cv::Scalar(9, 9, 9))); },
       ":5: " + Image(3).string() + ": RGB PNG: cam0 images must be 8-bit grayscale"},
      {"16-bit", [&] { cv::imwrite(Image(3).string(), cv::Mat(240, 320, CV_16UC1, cv::Scalar(900))); },
       ":5: " + Image(3).string() + ": 16-bit grayscale PNG: cam0 images must be 8-bit grayscale"},
      {"wrong size", [&] { cv::imwrite(Image(4).string(), cv::Mat(240, 200, CV_8UC1, cv::Scalar(9))); },
       ":6: " + Image(4).string() + ": image is 200 x 240, the camera's sensor.yaml declares 320 x 240"},
  };
  for (const Case& c : cases) {
    SetUp();  // a fresh dataset
    c.damage();
    const CliResult r = Vigil(tmp_, "track " + dataset_.string() + " -o " + out.string());
    EXPECT_EQ(r.status, 2) << c.what << ": " << r.err;
    EXPECT_NE(r.err.find(list + c.expected), std::string::npos) << c.what << ": " << r.err;
    EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << "one line: " << r.err;
    EXPECT_FALSE(fs::exists(out)) << c.what;
    fs::remove_all(dataset_);
  }
}

}  // namespace
}  // namespace vigil
