#include "core/euroc.h"

#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "core/output.h"
#include "tests/core/test_util.h"

namespace vigil {
namespace {

namespace fs = std::filesystem;
using vigil::testing::InputErrorOf;
using vigil::testing::TempDir;

const fs::path kFixtures = fs::path(VIGIL_SOURCE_DIR) / "tests/core/data/euroc";

TEST(EurocSensorYaml, ReadsThePublishedCam0File) {
  const CameraModel cam = ReadEurocCameraSensorYaml(ReadTextFile((kFixtures / "cam0_sensor.yaml").string()));
  EXPECT_EQ(cam.width, 752);
  EXPECT_EQ(cam.height, 480);
  EXPECT_EQ(cam.rate_hz, 20.0);
  EXPECT_EQ(cam.fx, 458.654);
  EXPECT_EQ(cam.fy, 457.296);
  EXPECT_EQ(cam.cx, 367.215);
  EXPECT_EQ(cam.cy, 248.375);
  EXPECT_EQ(cam.distortion, (std::vector<double>{-0.28340811, 0.07395907, 0.00019359, 1.76187114e-05}));
  // T_BS (sensor -> body) is vigil's T_BC: the camera looks along the body's z axis, offset -6.5 cm in y.
  EXPECT_EQ(cam.T_BC[3], -0.0216401454975);
  EXPECT_EQ(cam.T_BC[7], -0.064676986768);
  EXPECT_GT((cam.R_BC() * Eigen::Vector3d::UnitZ()).z(), 0.99);
  EXPECT_EQ(cam.Validate(), "");
}

TEST(EurocSensorYaml, ReadsThePublishedImu0File) {
  const EurocImuSensor imu = ReadEurocImuSensorYaml(ReadTextFile((kFixtures / "imu0_sensor.yaml").string()));
  EXPECT_EQ(imu.rate_hz, 200.0);
  EXPECT_EQ(imu.gyroscope_noise_density, 1.6968e-04);
  EXPECT_EQ(imu.gyroscope_random_walk, 1.9393e-05);
  EXPECT_EQ(imu.accelerometer_noise_density, 2.0e-3);
  EXPECT_EQ(imu.accelerometer_random_walk, 3.0e-3);
  EXPECT_TRUE(imu.T_BS.isApprox(Eigen::Isometry3d::Identity()));
}

TEST(EurocSensorYaml, WrittenFilesLookLikeEurocAndReadBack) {
  CameraModel cam = ReadEurocCameraSensorYaml(ReadTextFile((kFixtures / "cam0_sensor.yaml").string()));
  const std::string text = EurocCameraSensorYaml(cam);
  EXPECT_EQ(text.rfind("%YAML:1.0\n", 0), 0u);
  for (const char* key : {"T_BS:", "rate_hz: 20", "resolution: [752, 480]", "camera_model: pinhole",
                          "intrinsics: [458.654, 457.296, 367.215, 248.375]",
                          "distortion_model: radial-tangential", "distortion_coefficients: ["})
    EXPECT_NE(text.find(key), std::string::npos) << key;
  const CameraModel back = ReadEurocCameraSensorYaml({"cam0/sensor.yaml", text});
  EXPECT_EQ(back.T_BC, cam.T_BC);
  EXPECT_EQ(back.distortion, cam.distortion);
  EXPECT_EQ(back.fx, cam.fx);

  EurocImuSensor imu;
  imu.rate_hz = 400;
  imu.gyroscope_noise_density = 1e-3;
  imu.accelerometer_random_walk = 4e-4;
  const EurocImuSensor imu_back = ReadEurocImuSensorYaml({"imu0/sensor.yaml", EurocImuSensorYaml(imu)});
  EXPECT_EQ(imu_back.rate_hz, 400.0);
  EXPECT_EQ(imu_back.gyroscope_noise_density, 1e-3);
  EXPECT_EQ(imu_back.accelerometer_random_walk, 4e-4);
}

TEST(EurocSensorYaml, MissingIntrinsicsIsAnErrorNamingTheFile) {
  TextFile file = ReadTextFile((kFixtures / "cam0_sensor.yaml").string());
  file.path = "mav0/cam0/sensor.yaml";
  const std::size_t at = file.text.find("intrinsics:");
  file.text.erase(at, file.text.find('\n', at) - at);
  const std::string error = InputErrorOf([&] { ReadEurocCameraSensorYaml(file); });
  EXPECT_EQ(error.rfind("mav0/cam0/sensor.yaml: intrinsics: missing", 0), 0u) << error;
  EXPECT_EQ(error.find('\n'), std::string::npos);
}

TEST(EurocSensorYaml, BadValuesNameTheLine) {
  TextFile file = ReadTextFile((kFixtures / "cam0_sensor.yaml").string());
  file.path = "sensor.yaml";
  const std::size_t at = file.text.find("resolution: [752, 480]");
  file.text.replace(at, 22, "resolution: [752]");
  EXPECT_EQ(InputErrorOf([&] { ReadEurocCameraSensorYaml(file); }),
            "sensor.yaml:17: resolution: expected a list of 2 numbers");
  EXPECT_NE(InputErrorOf([&] {
              ReadEurocCameraSensorYaml({"s.yaml", "%YAML:1.0\nrate_hz: [\n"});
            }).find("s.yaml:"),
            std::string::npos);
}

TEST(EurocSensorYaml, ValuesBeyondPhysicalBoundsAreRefusedWithTheirLine) {
  const TextFile published = ReadTextFile((kFixtures / "cam0_sensor.yaml").string());
  auto error = [&](const std::string& from, const std::string& to) {
    TextFile file = published;
    file.path = "sensor.yaml";
    const std::size_t at = file.text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    file.text.replace(at, from.size(), to);
    return InputErrorOf([&] { ReadEurocCameraSensorYaml(file); });
  };
  EXPECT_EQ(error("458.654,", "4.9e-324,"),
            "sensor.yaml:19: intrinsics: focal lengths fu, fv must be in [1, 1e+05] px");
  EXPECT_EQ(error("367.215", "1e9"),
            "sensor.yaml:19: intrinsics: principal point cu, cv must lie in the image (0 .. width, 0 .. "
            "height px)");
  EXPECT_EQ(error("[-0.28340811,", "[1e300,"),
            "sensor.yaml:21: distortion_coefficients: k1, k2, p1, p2 must be within +-10 (got 1e+300)");
  EXPECT_NE(error("-0.0216401454975", "1e300").find("sensor.yaml:7: T_BS: translation of"),
            std::string::npos);
  EXPECT_EQ(error("rate_hz: 20", "rate_hz: 1e-300"), "sensor.yaml:16: rate_hz: must be in [0.1, 1e+05] Hz");
  EXPECT_EQ(error("rate_hz: 20", "rate_hz: 20"), "");
}

TEST(EurocImageList, ReadsRowsAndChecksTheFiles) {
  TempDir tmp;
  fs::create_directories(tmp.path() / "data");
  std::ofstream(tmp.path() / "data" / "100.png") << "x";
  std::ofstream(tmp.path() / "data" / "200.png") << "x";
  const TextFile list{"cam0/data.csv", "#timestamp [ns],filename\n100,100.png\n200,200.png\n"};
  const std::vector<CameraImage> images = ReadEurocImageList(list, tmp.path() / "data");
  ASSERT_EQ(images.size(), 2u);
  EXPECT_EQ(images[1].t_ns, 200);
  EXPECT_EQ(fs::path(images[1].path), fs::absolute(tmp.path() / "data" / "200.png"));
  EXPECT_EQ(images[1].list_line, 3);

  const std::string missing = InputErrorOf([&] {
    ReadEurocImageList({"cam0/data.csv", "#timestamp [ns],filename\n100,100.png\n300,300.png\n"},
                       tmp.path() / "data");
  });
  EXPECT_EQ(missing.rfind("cam0/data.csv:3: ", 0), 0u) << missing;
  EXPECT_NE(missing.find("300.png: image file is missing"), std::string::npos) << missing;

  EXPECT_EQ(InputErrorOf([&] {
              ReadEurocImageList({"cam0/data.csv", "#timestamp [ns],filename\n100,\n"}, tmp.path() / "data");
            }).rfind("cam0/data.csv:2: filename: missing", 0),
            0u);
  EXPECT_EQ(InputErrorOf([&] {
              ReadEurocImageList({"cam0/data.csv", "#timestamp [ns],filename\n100\n"}, tmp.path() / "data");
            }),
            "cam0/data.csv:2: expected 2 columns, found 1");
}

TEST(EurocImageList, ImageOfTheWrongSizeNamesTheRow) {
  CameraImage image;
  image.path = "/d/mav0/cam0/data/5.png";
  image.list_path = "/d/mav0/cam0/data.csv";
  image.list_line = 7;
  CameraModel cam;
  cam.width = 752;
  cam.height = 480;
  EXPECT_EQ(InputErrorOf([&] { CheckImageSize(image, 752, 480, cam); }), "");
  EXPECT_EQ(InputErrorOf([&] { CheckImageSize(image, 640, 480, cam); }),
            "/d/mav0/cam0/data.csv:7: /d/mav0/cam0/data/5.png: image is 640 x 480, the camera's sensor.yaml "
            "declares 752 x 480");
}

// A small recording: 1 s of IMU at 100 Hz, ground truth, a camera at 10 Hz.
Dataset OneSecondDataset() {
  Dataset d;
  for (int i = 0; i <= 100; ++i) {
    ImuSample s;
    s.t_ns = 1000000000LL + i * 10000000LL;
    s.a_B = Eigen::Vector3d(0.1 * i, 0, 9.81);
    s.w_B = Eigen::Vector3d(0, 0.01 * i, 0);
    d.imu.push_back(s);
    NavState n;
    n.t_ns = s.t_ns;
    n.p_W = Eigen::Vector3d(0.01 * i, 0, 1);
    d.groundtruth.push_back(n);
  }
  d.camera.rate_hz = 10;
  d.camera.distortion = {-0.2, 0.05, 0.001, -0.001};
  return d;
}

std::vector<int64_t> ImageTimes(const Dataset& d) {
  return CameraFrameTimes(d.camera.rate_hz, d.imu.front().t_ns, d.imu.back().t_ns);
}

void WriteImages(const fs::path& dir, const std::vector<int64_t>& times) {
  for (int64_t t : times) std::ofstream(EurocImageDir(dir) / EurocImageName(t)) << "png";
}

TEST(EurocRecording, WrittenLayoutReadsBackAsPublishedEuroc) {
  TempDir tmp;
  const Dataset d = OneSecondDataset();
  const std::vector<int64_t> times = ImageTimes(d);
  WriteEuroc(tmp.path(), d, EurocImuSensor{}, times);
  WriteImages(tmp.path(), times);
  for (const char* f : {"mav0/imu0/data.csv", "mav0/imu0/sensor.yaml", "mav0/cam0/data.csv",
                        "mav0/cam0/sensor.yaml", "mav0/state_groundtruth_estimate0/data.csv"})
    EXPECT_TRUE(fs::is_regular_file(tmp.path() / f)) << f;

  // Given as the folder holding mav0/ and as mav0/ itself.
  for (const fs::path& dir : {tmp.path(), tmp.path() / "mav0"}) {
    const Recording rec = ReadRecording(dir);
    EXPECT_EQ(rec.layout, "euroc");
    EXPECT_TRUE(rec.has_camera);
    EXPECT_TRUE(rec.has_groundtruth);
    EXPECT_FALSE(rec.has_features);
    ASSERT_EQ(rec.dataset.imu.size(), d.imu.size());
    EXPECT_EQ(rec.dataset.imu[50].a_B, d.imu[50].a_B);
    EXPECT_EQ(rec.dataset.groundtruth.size(), d.groundtruth.size());
    EXPECT_EQ(rec.dataset.camera.T_BC, d.camera.T_BC);
    EXPECT_EQ(rec.dataset.camera.distortion, d.camera.distortion);
    ASSERT_EQ(rec.images.size(), times.size());
    EXPECT_EQ(rec.images[3].t_ns, times[3]);
    EXPECT_EQ(fs::path(rec.images[3].path),
              fs::absolute(EurocImageDir(tmp.path()) / EurocImageName(times[3])));
    ASSERT_EQ(rec.dataset.frames.size(), times.size());  // empty frames at the image times
  }
}

TEST(EurocRecording, AnImageAfterTheLastImuSampleIsRefused) {
  TempDir tmp;
  const Dataset d = OneSecondDataset();
  std::vector<int64_t> times = ImageTimes(d);
  times.push_back(d.imu.back().t_ns + 1000000);
  WriteEuroc(tmp.path(), d, EurocImuSensor{}, times);
  WriteImages(tmp.path(), times);
  const std::string error = InputErrorOf([&] { ReadRecording(tmp.path()); });
  EXPECT_NE(error.find("data.csv:" + std::to_string(times.size() + 1) + ": timestamp " +
                       std::to_string(times.back()) + " is outside the IMU's time span"),
            std::string::npos)
      << error;
}

TEST(EurocRecording, ADanglingGroundTruthLinkIsAnErrorNotAbsentGroundTruth) {
  TempDir tmp;
  const Dataset d = OneSecondDataset();
  WriteEuroc(tmp.path(), d, EurocImuSensor{}, ImageTimes(d));
  WriteImages(tmp.path(), ImageTimes(d));
  const fs::path gt = tmp.path() / "mav0" / "state_groundtruth_estimate0" / "data.csv";
  fs::remove(gt);
  fs::create_symlink(tmp.path() / "nowhere.csv", gt);
  const std::string error = InputErrorOf([&] { ReadRecording(tmp.path()); });
  EXPECT_NE(error.find("data.csv: a symbolic link to nothing"), std::string::npos) << error;
}

TEST(EurocRecording, AnImuWithAllTimestampsEqualNamesTheFileAndLine) {
  TempDir tmp;
  Dataset d = OneSecondDataset();
  for (ImuSample& s : d.imu) s.t_ns = d.imu.front().t_ns;
  WriteEuroc(tmp.path(), d, EurocImuSensor{}, {});
  fs::remove_all(tmp.path() / "mav0" / "cam0");
  const std::string error = InputErrorOf([&] { ReadRecording(tmp.path()); });
  EXPECT_NE(error.find("imu0/data.csv:2: " + std::to_string(d.imu.size()) + " samples, all at timestamp " +
                       std::to_string(d.imu.front().t_ns) +
                       ": an IMU stream needs at least two distinct timestamps"),
            std::string::npos)
      << error;
}

TEST(EurocRecording, GroundTruthAndCameraAreOptional) {
  TempDir tmp;
  Dataset d = OneSecondDataset();
  d.groundtruth.clear();
  WriteEuroc(tmp.path(), d, EurocImuSensor{}, ImageTimes(d));
  WriteImages(tmp.path(), ImageTimes(d));
  fs::remove_all(tmp.path() / "mav0" / "cam0");
  const Recording rec = ReadRecording(tmp.path());
  EXPECT_FALSE(rec.has_groundtruth);
  EXPECT_FALSE(rec.has_camera);
  EXPECT_TRUE(rec.images.empty());
  EXPECT_EQ(rec.dataset.imu.size(), d.imu.size());
}

TEST(EurocRecording, FeaturesBesideMav0AreReadAtTheImageTimes) {
  TempDir tmp;
  const Dataset d = OneSecondDataset();
  const std::vector<int64_t> times = ImageTimes(d);
  WriteEuroc(tmp.path(), d, EurocImuSensor{}, times);
  WriteImages(tmp.path(), times);
  std::ofstream(tmp.path() / "features.csv") << "#timestamp [ns],id,u [px],v [px]\n"
                                             << times[2] << ",7,100,120\n";
  const Recording rec = ReadRecording(tmp.path() / "mav0");
  EXPECT_TRUE(rec.has_features);
  ASSERT_EQ(rec.dataset.frames.size(), times.size());
  EXPECT_EQ(rec.dataset.frames[2].features.size(), 1u);
  EXPECT_TRUE(rec.dataset.frames[1].features.empty());
  // Undistorted pixels of a distorted camera may lie outside the image (barrel distortion).
  std::ofstream(tmp.path() / "features.csv") << "#timestamp [ns],id,u [px],v [px]\n"
                                             << times[2] << ",7,-40.5,120\n";
  EXPECT_EQ(ReadRecording(tmp.path()).dataset.frames[2].features[0].uv_px.x(), -40.5);
}

TEST(EurocRecording, BadInputNamesTheFile) {
  TempDir tmp;
  const Dataset d = OneSecondDataset();
  const std::vector<int64_t> times = ImageTimes(d);
  WriteEuroc(tmp.path(), d, EurocImuSensor{}, times);
  WriteImages(tmp.path(), times);
  fs::remove(EurocImageDir(tmp.path()) / EurocImageName(times[4]));
  const std::string missing = InputErrorOf([&] { ReadRecording(tmp.path()); });
  EXPECT_NE(missing.find("cam0/data.csv:6: "), std::string::npos) << missing;
  EXPECT_NE(missing.find("image file is missing"), std::string::npos) << missing;

  const std::string neither = InputErrorOf([&] { ReadRecording(tmp.path() / "mav0" / "cam0"); });
  EXPECT_NE(neither.find("not a dataset directory"), std::string::npos) << neither;
}

TEST(EurocRecording, VigilDatasetWithMav0KeepsItsFilesAndListsTheImages) {
  TempDir tmp;
  Dataset d = OneSecondDataset();
  Landmark l;
  l.id = 7;
  l.p_W = Eigen::Vector3d(1, 2, 3);
  d.landmarks.push_back(l);
  const std::vector<int64_t> times = ImageTimes(d);
  for (int64_t t : times) d.frames.push_back({t, {}});
  d.frames[1].features.push_back({7, Eigen::Vector2d(10, 20)});
  d.imu_clean = d.imu;
  WriteDataset(tmp.path(), d);
  WriteEuroc(tmp.path(), d, EurocImuSensor{}, times);
  WriteImages(tmp.path(), times);
  const Recording rec = ReadRecording(tmp.path());
  EXPECT_EQ(rec.layout, "vigil");
  EXPECT_TRUE(rec.has_features);
  EXPECT_EQ(rec.dataset.landmarks.size(), 1u);
  EXPECT_EQ(rec.dataset.frames[1].features.size(), 1u);
  EXPECT_EQ(rec.images.size(), times.size());
  EXPECT_EQ(rec.dataset.camera.distortion, d.camera.distortion);
}

}  // namespace
}  // namespace vigil
