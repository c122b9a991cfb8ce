#include "sim/image_renderer.h"

#include <cmath>

#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "core/euroc.h"
#include "core/mesh.h"
#include "core/output.h"
#include "experiments/runs/run_config.h"
#include "sim/scene.h"
#include "sim/simulator.h"
#include "sim/trajectory_model.h"
#include "tests/core/test_util.h"

namespace vigil::sim {
namespace {
namespace fs = std::filesystem;

CameraModel SmallCamera() {
  CameraModel cam;
  cam.width = 320;
  cam.height = 240;
  cam.fx = cam.fy = 230.0;
  cam.cx = 159.5;
  cam.cy = 119.5;
  return cam;
}

ImageOptions Sharp() {
  ImageOptions o;
  o.enabled = true;
  o.noise_std = 0.0;
  o.antialias_samples = 0;
  return o;
}

// Body pose whose camera stands at (5, -18, 7) looking along +y at the house's y = 0 wall, slightly turned.
Eigen::Isometry3d BodyFacingTheHouse(const CameraModel& cam) {
  Eigen::Isometry3d T_WC = Eigen::Isometry3d::Identity();
  Eigen::Matrix3d R;  // columns: camera x, y, z in W (x right = +x_W, y down = -z_W, z forward = +y_W)
  R << 1, 0, 0, 0, 0, 1, 0, -1, 0;
  T_WC.linear() = Eigen::AngleAxisd(0.15, Eigen::Vector3d::UnitZ()) * R;
  T_WC.translation() = Eigen::Vector3d(5, -18, 7);
  return T_WC * cam.T_BC_iso().inverse();
}

TEST(ImageRenderer, DepthBufferMatchesTheSceneGeometryWithinOnePercent) {
  const CameraModel cam = SmallCamera();
  ImageRenderer renderer(MakeHouseScene(), cam, Sharp(), 1);
  const Eigen::Isometry3d T_WB = BodyFacingTheHouse(cam);
  const Eigen::Isometry3d T_WC = T_WB * cam.T_BC_iso();
  const std::vector<float> depth = renderer.PinholeDepth(T_WB);
  const TriangleMesh mesh = MakeHouseScene().Mesh();
  int checked = 0;
  for (int v = 10; v < cam.height; v += 37) {
    for (int u = 7; u < cam.width; u += 41) {
      const std::optional<Eigen::Vector3d> hit = PixelRayHit(mesh, cam, T_WC, Eigen::Vector2d(u, v));
      const float d = depth[static_cast<std::size_t>(v) * cam.width + u];
      if (!hit) {
        EXPECT_TRUE(std::isinf(d)) << u << " " << v;
        continue;
      }
      const double z_C = (T_WC.inverse() * *hit).z();
      EXPECT_NEAR(d, z_C, 0.01 * z_C) << "pixel " << u << ", " << v;
      ++checked;
    }
  }
  EXPECT_GT(checked, 30);
}

TEST(ImageRenderer, HouseVertexProjectsOntoTheWallItBelongsTo) {
  const CameraModel cam = SmallCamera();
  ImageRenderer renderer(MakeHouseScene(), cam, Sharp(), 1);
  const Eigen::Isometry3d T_WB = BodyFacingTheHouse(cam);
  const Eigen::Isometry3d T_CW = (T_WB * cam.T_BC_iso()).inverse();
  const std::vector<float> depth = renderer.PinholeDepth(T_WB);
  // Points on the y = 0 wall and gable: the house's corner (10, 0, 10) pulled 0.3 m inside the wall, the
  // door's corner and a point below the ridge.
  for (const Eigen::Vector3d& p_W :
       {Eigen::Vector3d(9.7, 0, 9.7), Eigen::Vector3d(6.0, 0, 4.0), Eigen::Vector3d(5.0, 0, 13.0)}) {
    Eigen::Vector2d uv;
    ASSERT_TRUE(cam.Project(T_CW * p_W, &uv));
    const int u = static_cast<int>(std::lround(uv.x())), v = static_cast<int>(std::lround(uv.y()));
    const double z_C = (T_CW * p_W).z();
    EXPECT_NEAR(depth[static_cast<std::size_t>(v) * cam.width + u], z_C, 0.01 * z_C) << p_W.transpose();
  }
}

std::vector<uint8_t> RenderFrame(const ImageOptions& options, uint64_t seed, const CameraModel& cam,
                                 double t_s = 2.0) {
  const std::unique_ptr<TrajectoryModel> motion = MakeTrajectoryModel(TrajectoryOptions{});
  ImageRenderer renderer(MakeHouseScene(), cam, options, seed);
  return renderer.Render(*motion, t_s, 20.0, 3);
}

TEST(ImageRenderer, SameSeedSameBytesOtherSeedOtherTextures) {
  ImageOptions o;  // noise and multisampling on
  CameraModel cam = SmallCamera();
  const std::string a = EncodeGrayPng(RenderFrame(o, 7, cam), cam.width, cam.height, 3);
  const std::string b = EncodeGrayPng(RenderFrame(o, 7, cam), cam.width, cam.height, 3);
  EXPECT_EQ(a, b);
  EXPECT_NE(a, EncodeGrayPng(RenderFrame(o, 8, cam), cam.width, cam.height, 3));
  o.texture_seed = 7;  // textures pinned: seed 8 changes only the noise
  const std::vector<uint8_t> x = RenderFrame(o, 7, cam), y = RenderFrame(o, 8, cam);
  double diff = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) diff += std::abs(int(x[i]) - int(y[i]));
  EXPECT_LT(diff / x.size(), 4.0);  // two N(0, 2^2) draws differ by 2.26 on average
  EXPECT_GT(diff / x.size(), 1.0);
}

TEST(ImageRenderer, PaperViewIsRichInCorners) {
  experiments::RunConfig config =
      experiments::LoadRunConfig(std::string(VIGIL_SOURCE_DIR) + "/configs/paper_images.yaml", {});
  const CameraModel& cam = config.sim.camera;
  for (double t : {0.5, 5.0, 12.0}) {
    const std::vector<uint8_t> gray = RenderFrame(config.sim.images, 1, cam, t);
    cv::Mat image(cam.height, cam.width, CV_8UC1, const_cast<uint8_t*>(gray.data()));
    std::vector<cv::Point2f> corners;
    cv::goodFeaturesToTrack(image, corners, 300, 0.01, 10);
    EXPECT_GE(corners.size(), 150u) << "t = " << t;
  }
}

double GradientEnergy(const std::vector<uint8_t>& g, int w, int h) {
  double e = 0.0;
  for (int y = 0; y < h; ++y)
    for (int x = 1; x < w; ++x) e += std::abs(int(g[y * w + x]) - int(g[y * w + x - 1]));
  return e;
}

TEST(ImageRenderer, MotionBlurSmoothsTheImage) {
  const CameraModel cam = SmallCamera();
  ImageOptions blurred = Sharp();
  blurred.exposure_s = 0.2;  // the camera turns by about 4 degrees meanwhile
  const std::vector<uint8_t> sharp = RenderFrame(Sharp(), 1, cam), blur = RenderFrame(blurred, 1, cam);
  EXPECT_LT(GradientEnergy(blur, cam.width, cam.height), 0.8 * GradientEnergy(sharp, cam.width, cam.height));
}

float Bilinear(const std::vector<float>& img, int w, const Eigen::Vector2d& p) {
  const int x = static_cast<int>(std::floor(p.x())), y = static_cast<int>(std::floor(p.y()));
  const float a = static_cast<float>(p.x() - x), b = static_cast<float>(p.y() - y);
  const auto at = [&](int xx, int yy) { return img[static_cast<std::size_t>(yy) * w + xx]; };
  return (1 - a) * (1 - b) * at(x, y) + a * (1 - b) * at(x + 1, y) + (1 - a) * b * at(x, y + 1) +
         a * b * at(x + 1, y + 1);
}

TEST(ImageRenderer, DistortionMovesPixelsAsTheCameraModelSays) {
  CameraModel pinhole = SmallCamera();
  CameraModel distorted = pinhole;
  distorted.distortion = {-0.28, 0.07, 0.0002, 0.00002};
  ImageRenderer a(MakeHouseScene(), pinhole, Sharp(), 1), b(MakeHouseScene(), distorted, Sharp(), 1);
  const Eigen::Isometry3d T_WB = BodyFacingTheHouse(pinhole);
  const std::vector<float> ideal = a.RenderSharp(T_WB), image = b.RenderSharp(T_WB);
  double matched = 0.0, unmatched = 0.0;
  int n = 0;
  for (int v = 20; v < pinhole.height - 20; v += 9)
    for (int u = 20; u < pinhole.width - 20; u += 11) {
      const Eigen::Vector2d p(u, v);
      const Eigen::Vector2d q = distorted.UndistortPixel(p);  // where the image pixel looks on the pinhole
      if (q.x() < 0 || q.y() < 0 || q.x() > pinhole.width - 2 || q.y() > pinhole.height - 2) continue;
      const float value = image[static_cast<std::size_t>(v) * pinhole.width + u];
      matched += std::abs(value - Bilinear(ideal, pinhole.width, q));
      unmatched += std::abs(value - Bilinear(ideal, pinhole.width, p));
      ++n;
    }
  ASSERT_GT(n, 200);
  EXPECT_LT(matched / n, 0.3 * unmatched / n);
  EXPECT_LT(matched / n, 6.0);
}

TEST(ImageRenderer, SimulateWritesTheEurocLayoutAndTheScene) {
  vigil::testing::TempDir tmp;
  experiments::RunConfig c = experiments::LoadRunConfig(
      std::string(VIGIL_SOURCE_DIR) + "/configs/paper.yaml",
      {"duration_s=0.5", "images.enabled=true", "camera.width=160", "camera.height=120", "camera.cx=79.5",
       "camera.cy=59.5", "camera.fx=115", "camera.fy=115", "camera.distortion=[-0.1, 0.01, 0, 0]"});
  const Dataset d = SimulateToDirectory(c.sim, c.seed, config::ToYaml(c), tmp.path() / "ds", false);
  const fs::path ds = tmp.path() / "ds";
  for (const char* f :
       {"imu.csv", "features.csv", "scene.obj", "mav0/imu0/data.csv", "mav0/imu0/sensor.yaml",
        "mav0/cam0/data.csv", "mav0/cam0/sensor.yaml", "mav0/state_groundtruth_estimate0/data.csv"})
    EXPECT_TRUE(fs::is_regular_file(ds / f)) << f;
  EXPECT_EQ(ReadFile(ds / "mav0/imu0/data.csv"), ReadFile(ds / "imu.csv"));
  const TriangleMesh mesh = ReadMeshObj((ds / "scene.obj").string());
  EXPECT_EQ(mesh.triangles.size(), MakeHouseScene().Mesh().triangles.size());

  // The mav0/ folder alone reads as a EuRoC recording with one image per feature frame.
  const Recording rec = ReadRecording(ds / "mav0");
  EXPECT_EQ(rec.layout, "euroc");
  ASSERT_EQ(rec.images.size(), d.frames.size());
  EXPECT_EQ(rec.dataset.camera.distortion, c.sim.camera.distortion);
  EXPECT_EQ(rec.imu_sensor.gyroscope_noise_density, c.sim.imu.noise.gyro_noise_density);
  for (std::size_t k = 0; k < rec.images.size(); ++k) {
    EXPECT_EQ(rec.images[k].t_ns, d.frames[k].t_ns);
    const cv::Mat image = cv::imread(rec.images[k].path, cv::IMREAD_UNCHANGED);
    ASSERT_EQ(image.type(), CV_8UC1);
    CheckImageSize(rec.images[k], image.cols, image.rows, rec.dataset.camera);
  }
  // The whole directory still reads as vigil's dataset, with its images listed.
  EXPECT_EQ(ReadRecording(ds).images.size(), d.frames.size());
}

}  // namespace
}  // namespace vigil::sim
