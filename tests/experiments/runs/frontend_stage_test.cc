#include "experiments/runs/frontend_stage.h"

#include <cmath>

#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>

#include "experiments/runs/frontend_metrics.h"
#include "tests/core/test_util.h"
#include "tests/frontend/synthetic_images.h"

namespace vigil::experiments {
namespace {

using vigil::testing::InputErrorOf;
using vigil::testing::TempDir;

CameraModel Camera(int width, int height) {
  CameraModel camera;
  camera.width = width;
  camera.height = height;
  camera.fx = camera.fy = 300.0;
  camera.cx = width / 2.0;
  camera.cy = height / 2.0;
  return camera;
}

// Writes `count` shifted views of a texture as PNG files and lists them.
std::vector<CameraImage> WriteImages(const TempDir& dir, int count, cv::Size size) {
  const cv::Mat texture = frontend::testing::MakeTexture(size.width + 10 * count, size.height, 4);
  std::vector<CameraImage> files;
  for (int k = 0; k < count; ++k) {
    CameraImage f;
    f.t_ns = 1'000'000'000LL + k * 50'000'000LL;
    f.path = (dir.path() / (std::to_string(f.t_ns) + ".png")).string();
    f.list_path = (dir.path() / "data.csv").string();
    f.list_line = k + 2;
    cv::imwrite(f.path, texture(cv::Rect(10 * (count - k), 0, size.width, size.height)));
    files.push_back(f);
  }
  return files;
}

TEST(FrontendStage, TracksImageFiles) {
  const TempDir dir;
  const std::vector<CameraImage> files = WriteImages(dir, 5, {320, 240});
  const TrackedFeatures tracked = TrackImageFiles(files, Camera(320, 240), frontend::FeatureTrackerOptions{});
  ASSERT_EQ(tracked.frames.size(), 5u);
  EXPECT_EQ(tracked.frames[3].t_ns, files[3].t_ns);
  EXPECT_GT(tracked.frames[4].features.size(), 30u);
  EXPECT_EQ(tracked.stats.images, 5);
}

TEST(FrontendStage, BadImagesNameTheFileAndLine) {
  const TempDir dir;
  std::vector<CameraImage> files = WriteImages(dir, 3, {320, 240});
  const CameraModel camera = Camera(320, 240);
  const frontend::FeatureTrackerOptions options;

  std::vector<CameraImage> missing = files;
  missing[1].path = (dir.path() / "nope.png").string();
  EXPECT_EQ(InputErrorOf([&] { TrackImageFiles(missing, camera, options); }),
            files[1].list_path + ":3: " + missing[1].path + ": no such image file");

  std::vector<CameraImage> garbage = files;
  garbage[2].path = dir.File("bad.png", "not a png");
  EXPECT_EQ(InputErrorOf([&] { TrackImageFiles(garbage, camera, options); }),
            files[2].list_path + ":4: " + garbage[2].path +
                ": not a PNG file (cam0 images must be 8-bit grayscale PNG)");

  EXPECT_EQ(InputErrorOf([&] { TrackImageFiles(files, Camera(640, 240), options); }),
            files[0].list_path + ":2: " + files[0].path +
                ": image is 320 x 240, the camera's sensor.yaml declares 640 x 240");
}

// A camera 4 m above the ground plane z = 0 looking down and moving along x: the tracker's tracks are
// evaluated against the plane's ray-cast; with ideal images they are within a pixel.
TEST(FrontendStage, EvaluatesTracksAgainstTheScene) {
  CameraModel camera = Camera(320, 240);
  camera.T_BC = {1, 0, 0, 0, 0, -1, 0, 0, 0, 0, -1, 0, 0, 0, 0, 1};  // looking down -z_B, body level
  const double height_m = 4.0, speed_mps = 1.0, texture_px_per_m = 100.0;
  const cv::Mat texture = frontend::testing::MakeTexture(1200, 800, 6);
  std::vector<NavState> groundtruth;
  for (int i = 0; i <= 100; ++i) {
    NavState s;
    s.t_ns = i * 10'000'000LL;
    s.p_W = Eigen::Vector3d(speed_mps * NsToS(s.t_ns), 0.0, height_m);
    groundtruth.push_back(s);
  }
  // The image of the textured ground: a camera pixel sees ground point p_W; the texture maps W (x, y) to
  // texture pixels (600 + 100 x, 400 - 100 y) (the camera's y axis is -y_W).
  const auto image_at = [&](std::size_t k) -> std::pair<int64_t, cv::Mat> {
    const int64_t t_ns = static_cast<int64_t>(k) * 50'000'000LL;
    const double x_m = speed_mps * NsToS(t_ns);
    const double s = texture_px_per_m * height_m / camera.fx;  // texture px per image px
    const cv::Matx23d image_to_texture(s, 0, 600 + texture_px_per_m * x_m - s * camera.cx,  //
                                       0, s, 400 - s * camera.cy);
    cv::Mat image;
    cv::warpAffine(texture, image, cv::Mat(image_to_texture), cv::Size(camera.width, camera.height),
                   cv::INTER_LINEAR | cv::WARP_INVERSE_MAP);
    return {t_ns, image};
  };
  const TrackedFeatures tracked =
      TrackImages(10, image_at, [](std::size_t) { return std::string("img"); }, camera, {});
  const auto ground = [](const Eigen::Vector3d& o, const Eigen::Vector3d& d) -> std::optional<double> {
    if (d.z() >= 0) return std::nullopt;
    return -o.z() / d.z();
  };
  const frontend::ReprojectionEvaluation e = EvaluateTracks(tracked.frames, groundtruth, camera, ground, 1.0);
  ASSERT_GT(e.errors_px.size(), 200u);
  EXPECT_EQ(e.without_truth, 0);
  EXPECT_EQ(e.outliers, 0);

  const nlohmann::json j = FrontendMetricsJson(tracked.frames, tracked.stats, {}, e);
  EXPECT_EQ(j["images"], 10);
  EXPECT_EQ(j["published_frames"], 10);
  EXPECT_EQ(j["reprojection"]["evaluated"], static_cast<int64_t>(e.errors_px.size()));
  EXPECT_LT(j["reprojection"]["error_px"]["rmse"].get<double>(), 0.3);
  EXPECT_EQ(j["track_length_frames"]["histogram"].back()["to"], nullptr);
  EXPECT_EQ(j["track_length_frames"]["max"], 10);
  // The errors by age partition the evaluated observations over the default bins (1, 2, 3-4, 5-9, 10-19,
  // ...): tracks of 10 frames have ages 1 to 9, so the bins from 10 on are empty.
  const nlohmann::json& by_age = j["reprojection"]["error_by_age_px"];
  ASSERT_EQ(by_age.size(), 8u);
  int64_t binned = 0;
  for (const nlohmann::json& bin : by_age) binned += bin["error_px"]["n"].get<int64_t>();
  EXPECT_EQ(binned, static_cast<int64_t>(e.errors_px.size()));
  EXPECT_EQ(by_age[0]["from"], 1);
  EXPECT_EQ(by_age[2]["to"], 4);
  EXPECT_GT(by_age[3]["error_px"]["n"].get<int64_t>(), 0);
  EXPECT_EQ(by_age[4]["error_px"]["n"], 0);
  EXPECT_EQ(by_age.back()["to"], nullptr);
  EXPECT_FALSE(FrontendMetricsJson(tracked.frames, tracked.stats, {}, std::nullopt).contains("reprojection"));
}

}  // namespace
}  // namespace vigil::experiments
