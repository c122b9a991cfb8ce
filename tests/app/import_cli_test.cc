// `vigil import` on the built binary: ROS 1 bags written by tests/core/bag/write_bag.py (Debian's
// python3-rosbag) from a EuRoC folder that `vigil simulate --images` rendered. The round trip (folder -> bag
// -> imported folder) gives back what vigil reads, and `vigil run --dataset` on the imported folder gives the
// same trajectory as on the original; each bad input is one line, exit 2, nothing written. One bag of the
// whole flight is shared by the tests; the others are the first second of it (write_bag.py --seconds 1),
// enough for what each checks: writing a bag takes seconds, an import of a short one a fraction.
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include "core/dataset.h"
#include "core/euroc.h"
#include "core/output.h"
#include "tests/app/vigil_cli.h"
#include "tests/core/test_util.h"

namespace vigil {
namespace {
namespace fs = std::filesystem;
using testing::CliResult;
using testing::RunShell;
using testing::TempDir;
using testing::Vigil;

// A short flight along the paper's ellipse, rendered at 320 x 240: long enough for the estimator to
// initialize on the tracked images.
constexpr const char* kScenario =
    "duration_s: 6\ncamera: {width: 320, height: 240, fx: 230, fy: 230, cx: 159.5, cy: 119.5}\n"
    "frontend: {features: tracked}\nestimator: {init: vins}\n";

class ImportCli : public ::testing::Test {
 protected:
  // The recording, simulated once for the suite (every test only reads it).
  static fs::path& Shared() {
    static fs::path dir;
    return dir;
  }
  static void SetUpTestSuite() {
    Shared() = fs::temp_directory_path() / ("vigil_test_ImportCli_" + std::to_string(::getpid()));
    fs::remove_all(Shared());
    fs::create_directories(Shared());
    std::ofstream(Shared() / "config.yaml") << kScenario;
    const fs::path sim = Shared() / "sim", source = Shared() / "source";
    ASSERT_EQ(RunShell(std::string(VIGIL_BINARY) + " simulate " + (Shared() / "config.yaml").string() +
                       " -o " + sim.string() + " --images 2>&1")
                  .status,
              0);
    // The source recording as a EuRoC folder (mav0/ alone), and PGM copies of its images for the script.
    fs::create_directories(source);
    fs::copy(sim / "mav0", source / "mav0", fs::copy_options::recursive);
    for (const fs::directory_entry& e : fs::directory_iterator(EurocImageDir(sim))) {
      const cv::Mat gray = cv::imread(e.path().string(), cv::IMREAD_UNCHANGED);
      ASSERT_TRUE(cv::imwrite((EurocImageDir(sim) / (e.path().stem().string() + ".pgm")).string(), gray));
    }
    const testing::ShellOutput flight = WriteBag(FlightBag(), "");
    ASSERT_EQ(flight.status, 0) << flight.out;
  }
  static void TearDownTestSuite() { fs::remove_all(Shared()); }

  static testing::ShellOutput WriteBag(const std::string& bag, const std::string& options) {
    return RunShell(std::string(VIGIL_ROSBAG_PYTHON) + " " + VIGIL_SOURCE_DIR +
                    "/tests/core/bag/write_bag.py " + (Shared() / "sim" / "mav0").string() + " " + bag + " " +
                    options + " 2>&1");
  }
  // The bag of the whole flight with write_bag.py's defaults (EuRoC's topics), written once. Only read.
  static std::string FlightBag() { return (Shared() / "flight.bag").string(); }
  // A bag of the first second of the source recording written with write_bag.py OPTIONS.
  std::string ShortBag(const std::string& name, const std::string& options = "") {
    const std::string bag = (tmp_.path() / (name + ".bag")).string();
    const testing::ShellOutput r = WriteBag(bag, "--seconds 1 " + options);
    EXPECT_EQ(r.status, 0) << r.out;
    return bag;
  }
  // The sensor files of the simulated recording (its camera is not EuRoC's).
  std::string SensorFiles() const {
    return " --imu-yaml " + (sim_ / "mav0/imu0/sensor.yaml").string() + " --camera-yaml " +
           (sim_ / "mav0/cam0/sensor.yaml").string();
  }
  CliResult Import(const std::string& bag, const fs::path& out, const std::string& options = "") {
    return Vigil(tmp_, "import " + bag + " -o " + out.string() + " " + options);
  }
  // Exit 2, one line naming `reason`, and nothing written: no output, no staging left beside it.
  void ExpectRefused(const std::string& bag, const std::string& options, const std::string& reason) {
    const CliResult r = Import(bag, out_, options);
    EXPECT_EQ(r.status, 2) << r.err;
    EXPECT_NE(r.err.find(reason), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << "one line: " << r.err;
    EXPECT_FALSE(fs::exists(out_));
    for (const fs::directory_entry& e : fs::directory_iterator(tmp_.path()))
      EXPECT_EQ(e.path().filename().string().find("out.tmp-"), std::string::npos) << e.path();
  }
  // The images of a EuRoC folder, decoded.
  static std::vector<cv::Mat> Images(const fs::path& dir) {
    std::vector<cv::Mat> images;
    for (const CameraImage& image :
         ReadEurocImageList(ReadTextFile((dir / "mav0/cam0/data.csv").string()), EurocImageDir(dir)))
      images.push_back(cv::imread(image.path, cv::IMREAD_UNCHANGED));
    return images;
  }
  // The images of `b` are the first ones of `a` (all of them when the bag held the whole flight).
  static void ExpectSameImages(const fs::path& a, const fs::path& b) {
    const std::vector<cv::Mat> x = Images(a), y = Images(b);
    ASSERT_FALSE(y.empty());
    ASSERT_LE(y.size(), x.size());
    for (std::size_t k = 0; k < y.size(); ++k) {
      ASSERT_EQ(y[k].type(), CV_8UC1);
      EXPECT_EQ(cv::norm(x[k], y[k], cv::NORM_INF), 0.0) << "image " << k;
    }
  }

  TempDir tmp_;
  const std::string config_ = (Shared() / "config.yaml").string();
  const fs::path sim_ = Shared() / "sim", source_ = Shared() / "source";
  const fs::path out_ = tmp_.path() / "out";
};

TEST_F(ImportCli, RoundTripRunsLikeTheRecording) {
  const std::string bag = FlightBag();
  const CliResult r = Import(bag, out_, SensorFiles());
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << "one summary line: " << r.err;
  EXPECT_NE(r.err.find("vigil import: 1201 IMU samples, 181 images (mono8), 1201 ground-truth poses -> "),
            std::string::npos)
      << r.err;
  // What vigil reads comes back as written: the IMU and the image list byte for byte, the images pixel for
  // pixel, the ground truth's poses exactly.
  for (const char* file :
       {"mav0/imu0/data.csv", "mav0/imu0/sensor.yaml", "mav0/cam0/data.csv", "mav0/cam0/sensor.yaml"})
    EXPECT_EQ(ReadFile(out_ / file), ReadFile(source_ / file)) << file;
  ExpectSameImages(source_, out_);  // as many: data.csv is the same
  const std::vector<NavState> gt =
      ReadGroundTruthCsv((out_ / "mav0/state_groundtruth_estimate0/data.csv").string());
  const std::vector<NavState> truth =
      ReadGroundTruthCsv((source_ / "mav0/state_groundtruth_estimate0/data.csv").string());
  ASSERT_EQ(gt.size(), truth.size());
  for (std::size_t k = 0; k < gt.size(); ++k) {
    EXPECT_EQ(gt[k].t_ns, truth[k].t_ns);
    EXPECT_EQ(gt[k].p_W, truth[k].p_W);
    EXPECT_EQ(gt[k].q_WB.coeffs(), truth[k].q_WB.coeffs());
    EXPECT_LT((gt[k].v_W - truth[k].v_W).norm(), 0.05) << "central differences, row " << k;
  }
  EXPECT_NE(ReadFile(out_ / "import.yaml").find("topic: /vicon/firefly_sbx/firefly_sbx"), std::string::npos);

  // End to end: `vigil run --dataset` tracks, estimates and evaluates the imported folder as the original.
  const fs::path run_source = tmp_.path() / "run_source", run_imported = tmp_.path() / "run_imported";
  const CliResult a =
      Vigil(tmp_, "run " + config_ + " --dataset " + source_.string() + " -o " + run_source.string());
  const CliResult b =
      Vigil(tmp_, "run " + config_ + " --dataset " + out_.string() + " -o " + run_imported.string());
  ASSERT_EQ(a.status, 0) << a.err;
  ASSERT_EQ(b.status, 0) << b.err;
  for (const char* file : {"stamped_traj_estimate.txt", "stamped_groundtruth.txt"})
    EXPECT_EQ(ReadFile(run_imported / file), ReadFile(run_source / file)) << file;
}

// Colour and 16-bit images are converted to the same 8-bit gray (equal channels, v16 = 257 v8); compressed
// bags read as uncompressed ones; the ground truth may be a PoseStamped or an Odometry (whose velocity,
// in the body frame, is rotated back into the world frame).
TEST_F(ImportCli, EncodingsCompressionAndGroundTruthTypes) {
  struct Case {
    const char* name;
    const char* bag_options;
    const char* import_options;
    const char* encoding;
  };
  for (const Case& c :
       {Case{"rgb", "--encoding rgb8 --groundtruth pose --groundtruth-topic /pose",
             "--groundtruth-topic /pose", "rgb8"},
        Case{"bgr", "--encoding bgr8 --compression lz4", "", "bgr8"},
        Case{"mono16", "--encoding mono16 --groundtruth odometry --groundtruth-topic /odom --compression bz2",
             "--groundtruth-topic /odom", "mono16"}}) {
    SCOPED_TRACE(c.name);
    const fs::path out = tmp_.path() / c.name;
    const CliResult r = Import(ShortBag(c.name, c.bag_options), out, SensorFiles() + " " + c.import_options);
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.err.find(std::string("vigil import: 200 IMU samples, 30 images (") + c.encoding +
                         "), 200 ground-truth poses -> "),
              std::string::npos)
        << r.err;
    ExpectSameImages(source_, out);
    const std::vector<NavState> got =
        ReadGroundTruthCsv((out / "mav0/state_groundtruth_estimate0/data.csv").string());
    const std::vector<NavState> truth =
        ReadGroundTruthCsv((source_ / "mav0/state_groundtruth_estimate0/data.csv").string());
    ASSERT_EQ(got.size(), 200u);
    for (std::size_t k = 0; k < got.size(); ++k) {
      EXPECT_EQ(got[k].t_ns, truth[k].t_ns);
      EXPECT_EQ(got[k].p_W, truth[k].p_W);
      if (std::string(c.name) == "mono16") {
        EXPECT_LT((got[k].v_W - truth[k].v_W).norm(), 1e-9) << k;
      }
    }
  }
}

// The preset's ground-truth topic is optional (EuRoC's Machine Hall bags have none), a named one is not.
TEST_F(ImportCli, ThePresetsGroundTruthIsOptional) {
  const std::string bag = ShortBag("no_gt", "--groundtruth none");
  const CliResult r = Import(bag, out_, SensorFiles());
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("no ground truth (the bag has no /vicon/firefly_sbx/firefly_sbx"), std::string::npos)
      << r.err;
  EXPECT_FALSE(fs::exists(out_ / "mav0/state_groundtruth_estimate0"));
  // IMU and ground truth only: what the semi-real study reads.
  const fs::path imu_only = tmp_.path() / "imu_only";
  const CliResult i = Import(FlightBag(), imu_only, "--image-topic none");
  ASSERT_EQ(i.status, 0) << i.err;
  EXPECT_FALSE(fs::exists(imu_only / "mav0/cam0"));
  EXPECT_TRUE(fs::exists(imu_only / "mav0/state_groundtruth_estimate0/data.csv"));
}

TEST_F(ImportCli, BadInputIsOneLineAndWritesNothing) {
  const std::string bag = FlightBag();
  // A truncated bag (its index, at the end, is gone) and a corrupt one.
  const std::string bytes = ReadFile(bag);
  const std::string truncated = tmp_.File("truncated.bag", bytes.substr(0, bytes.size() / 2));
  ExpectRefused(truncated, SensorFiles(), truncated + ": not a readable ROS bag: ");
  std::string damaged = bytes;
  damaged.replace(0, 13, "#ROSBAG V9.9\n");
  const std::string corrupt = tmp_.File("corrupt.bag", damaged);
  ExpectRefused(corrupt, SensorFiles(), corrupt + ": not a readable ROS bag: ");
  const std::string text = tmp_.File("text.bag", "hello\n");
  ExpectRefused(text, SensorFiles(), text + ": not a readable ROS bag: ");
  // A missing topic, and one of another type or definition.
  ExpectRefused(bag, SensorFiles() + " --imu-topic /imu1",
                bag +
                    ": /imu1: no such topic (--imu-topic; the bag's "
                    "topics: /cam0/image_raw (sensor_msgs/Image)");
  ExpectRefused(bag, SensorFiles() + " --groundtruth-topic /nope", bag + ": /nope: no such topic");
  ExpectRefused(bag, SensorFiles() + " --imu-topic /cam0/image_raw",
                bag + ": /cam0/image_raw: sensor_msgs/Image messages, --imu-topic needs sensor_msgs/Imu");
  const std::string other = ShortBag("other", "--imu-other-definition");
  ExpectRefused(other, SensorFiles(), other + ": /imu0: sensor_msgs/Imu of another definition (MD5 ");
  const std::string point = ShortBag("point", "--groundtruth point");
  ExpectRefused(point, SensorFiles(),
                point +
                    ": /vicon/firefly_sbx/firefly_sbx: geometry_msgs/PointStamped messages, a ground truth "
                    "needs a pose with its orientation");
  // A ground truth whose quaternions are 3x unit length (the rule of every pose reader, core/pose_checks.h).
  const std::string scaled = ShortBag("scaled", "--quaternion-scale 3");
  ExpectRefused(
      scaled, SensorFiles(),
      scaled + ": /vicon/firefly_sbx/firefly_sbx: message 1: orientation: quaternion is not unit (norm 3)");
  // An unsupported encoding, stamps that go back, an image of another size than the camera's.
  const std::string yuv = ShortBag("yuv", "--encoding yuv422");
  ExpectRefused(yuv, SensorFiles(),
                yuv +
                    ": /cam0/image_raw: message 1: encoding 'yuv422' is not supported (mono8, mono16, rgb8, "
                    "bgr8, rgba8, bgra8)");
  const std::string swapped = ShortBag("swapped", "--swap-imu 6");
  ExpectRefused(swapped, SensorFiles(),
                swapped +
                    ": /imu0: message 8: header stamp 0.030000000 s goes back "
                    "(previous message 0.035000000 s)");
  ExpectRefused(
      bag, "--imu-yaml " + (sim_ / "mav0/imu0/sensor.yaml").string(),
      bag + ": /cam0/image_raw: message 1: image is 320 x 240, the camera's sensor.yaml declares 752 x 480");
  // No camera calibration (TUM-VI's fisheye), an unknown preset.
  ExpectRefused(bag, "--preset tumvi", "--camera-yaml: the tumvi preset has no camera calibration");
  ExpectRefused(bag, "--preset kitti", "--preset: 'kitti' is not a preset (euroc, tumvi)");
}

// The data-safety rules of every command: no output over an input, --force replaces only vigil's output.
TEST_F(ImportCli, OutputsNeverReplaceInputs) {
  const std::string bag = FlightBag();
  const CliResult over = Import(bag, bag, SensorFiles());
  EXPECT_EQ(over.status, 2) << over.err;
  EXPECT_TRUE(fs::is_regular_file(bag));
  fs::create_directories(out_);
  const std::string mine = tmp_.File("out/mine.txt", "a user's file\n");
  EXPECT_EQ(Import(bag, out_, SensorFiles() + " --force").status, 2);
  EXPECT_EQ(ReadFile(mine), "a user's file\n");
  fs::remove_all(out_);
  ASSERT_EQ(Import(bag, out_, SensorFiles()).status, 0);
  EXPECT_EQ(Import(bag, out_, SensorFiles()).status, 2);  // not empty: needs --force
  const CliResult again = Import(bag, out_, SensorFiles() + " --force");
  EXPECT_EQ(again.status, 0) << again.err;
}

}  // namespace
}  // namespace vigil
