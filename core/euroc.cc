#include "core/euroc.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include <yaml-cpp/yaml.h>

#include "core/config.h"
#include "core/csv.h"
#include "core/error.h"
#include "core/format.h"

namespace vigil {
namespace fs = std::filesystem;
namespace {

constexpr std::uintmax_t kMaxSensorYamlBytes = 1 << 20;  // a sensor.yaml is a few hundred bytes

// OpenCV writes "%YAML:1.0" as its first line, which yaml-cpp rejects: it becomes a comment (lines keep
// their numbers).
TextFile WithoutOpenCvDirective(TextFile file) {
  if (file.text.rfind("%YAML", 0) == 0) file.text[0] = '#';
  return file;
}

std::string RateRule() {
  return "must be in [" + FormatDouble(kMinSensorRateHz) + ", " + FormatDouble(kMaxSensorRateHz) + "] Hz";
}

// A parsed sensor.yaml and the errors it gives.
class SensorYaml {
 public:
  explicit SensorYaml(const TextFile& file)
      : path_(file.path), root_(config::LoadYamlText(WithoutOpenCvDirective(file))) {
    if (!root_.IsMap()) throw InputError(Located(path_, 1, "expected a mapping of keys (EuRoC sensor.yaml)"));
  }

  bool Has(const std::string& key) const { return static_cast<bool>(root_[key]); }

  [[noreturn]] void Fail(const std::string& key, const std::string& reason) const {
    throw InputError(Located(path_, config::KeyLine(root_, key), key + ": " + reason));
  }

  YAML::Node Required(const std::string& key, const std::string& what) const {
    const YAML::Node node = root_[key];
    if (!node) Fail(key, "missing (" + what + ")");
    return node;
  }

  double Number(const std::string& key, const YAML::Node& node) const {
    double v = 0.0;
    if (!node.IsScalar() || !ParseDouble(node.Scalar(), &v)) Fail(key, "expected a finite number");
    return v;
  }

  double Number(const std::string& key, const std::string& what) const {
    return Number(key, Required(key, what));
  }

  std::vector<double> Numbers(const std::string& key, const YAML::Node& node, std::size_t n) const {
    if (!node.IsSequence() || node.size() != n)
      Fail(key, "expected a list of " + std::to_string(n) + " numbers");
    std::vector<double> v;
    for (const YAML::Node& e : node) v.push_back(Number(key, e));
    return v;
  }

  std::string Text(const std::string& key) const {
    const YAML::Node node = root_[key];
    if (!node) return "";
    if (!node.IsScalar()) Fail(key, "expected a text");
    return node.Scalar();
  }

  // T_BS: {cols: 4, rows: 4, data: [16 numbers]}, a rigid transform.
  Eigen::Isometry3d Transform(const std::string& key) const {
    const YAML::Node node =
        Required(key, "the sensor's pose in the body frame, {cols: 4, rows: 4, data: [16]}");
    if (!node.IsMap() || !node["data"]) Fail(key, "expected {cols: 4, rows: 4, data: [16 numbers]}");
    if (node["rows"] && Number(key, node["rows"]) != 4) Fail(key, "rows: expected 4");
    if (node["cols"] && Number(key, node["cols"]) != 4) Fail(key, "cols: expected 4");
    CameraModel check;
    check.T_BC = Numbers(key, node["data"], 16);
    const std::string why = check.Validate();
    if (!why.empty()) Fail(key, why.substr(why.find(':') + 2));
    if (check.p_BC().norm() > kMaxSensorOffsetM)
      Fail(key, "translation of " + FormatDouble(check.p_BC().norm()) +
                    " m: a sensor on the body lies within " + FormatDouble(kMaxSensorOffsetM) + " m of it");
    return check.T_BC_iso();
  }

 private:
  std::string path_;
  YAML::Node root_;
};

std::string MatrixYaml(const Eigen::Isometry3d& T) {
  std::string s = "T_BS:\n  cols: 4\n  rows: 4\n  data: [";
  const Eigen::Matrix4d m = T.matrix();
  for (int r = 0; r < 4; ++r) {
    for (int c = 0; c < 4; ++c) {
      s += FormatDouble(m(r, c));
      if (r < 3 || c < 3) s += ", ";
    }
    if (r < 3) s += "\n         ";
  }
  return s + "]\n";
}

std::string ListYaml(const std::vector<double>& v) {
  std::string s = "[";
  for (std::size_t i = 0; i < v.size(); ++i) s += (i ? ", " : "") + FormatDouble(v[i]);
  return s + "]";
}

// The 1-based line of the first row of a CSV text (after its '#' header and blank lines).
int FirstDataLine(const std::string& text) {
  int line = 1;
  for (std::size_t at = 0; at < text.size(); ++line) {
    const std::size_t end = std::min(text.find('\n', at), text.size());
    const std::size_t first = text.find_first_not_of(" \t\r", at);
    if (first < end && text[first] != '#') return line;
    at = end + 1;
  }
  return 0;
}

// Whether an optional file is there; a symbolic link to nothing is an error, never "absent" (a dangling
// ground-truth link would otherwise silently mean "no ground truth").
bool IsFile(const fs::path& path) {
  std::error_code ec;
  if (fs::exists(path, ec)) return true;
  if (fs::is_symlink(fs::symlink_status(path, ec)))
    throw InputError(path.string() + ": a symbolic link to nothing (" + fs::read_symlink(path, ec).string() +
                     "); fix it or remove it");
  return false;
}

}  // namespace

std::string EurocImuSensorYaml(const EurocImuSensor& s, const std::string& comment) {
  return "%YAML:1.0\n"
         "# Default imu sensor yaml file (EuRoC layout, written by vigil)\n"
         "sensor_type: imu\n"
         "comment: " +
         comment +
         "\n\n"
         "# Sensor extrinsics wrt. the body-frame.\n" +
         MatrixYaml(s.T_BS) + "rate_hz: " + FormatDouble(s.rate_hz) +
         "\n\n# inertial sensor noise model parameters (static)\n"
         "gyroscope_noise_density: " +
         FormatDouble(s.gyroscope_noise_density) +
         "     # [ rad / s / sqrt(Hz) ]   ( gyro \"white noise\" )\n"
         "gyroscope_random_walk: " +
         FormatDouble(s.gyroscope_random_walk) +
         "       # [ rad / s^2 / sqrt(Hz) ] ( gyro bias diffusion )\n"
         "accelerometer_noise_density: " +
         FormatDouble(s.accelerometer_noise_density) +
         "  # [ m / s^2 / sqrt(Hz) ]   ( accel \"white noise\" )\n"
         "accelerometer_random_walk: " +
         FormatDouble(s.accelerometer_random_walk) +
         "    # [ m / s^3 / sqrt(Hz) ]   ( accel bias diffusion )\n";
}

std::string EurocCameraSensorYaml(const CameraModel& c, const std::string& comment) {
  return "%YAML:1.0\n"
         "# General sensor definitions.\n"
         "sensor_type: camera\n"
         "comment: " +
         comment +
         "\n\n"
         "# Sensor extrinsics wrt. the body-frame.\n" +
         MatrixYaml(c.T_BC_iso()) +
         "\n# Camera specific definitions.\n"
         "rate_hz: " +
         FormatDouble(c.rate_hz) + "\nresolution: [" + std::to_string(c.width) + ", " +
         std::to_string(c.height) +
         "]\ncamera_model: pinhole\nintrinsics: " + ListYaml({c.fx, c.fy, c.cx, c.cy}) +
         " #fu, fv, cu, cv\ndistortion_model: radial-tangential\n" +
         "distortion_coefficients: " + ListYaml(c.distortion) + "\n";
}

std::string EurocImageName(int64_t t_ns) { return std::to_string(t_ns) + ".png"; }

std::string EurocImageListCsv(const std::vector<int64_t>& times_ns) {
  CsvWriter w("timestamp [ns],filename", "mav0/cam0/data.csv");
  for (int64_t t : times_ns) {
    w << t << EurocImageName(t);
    w.EndRow();
  }
  return w.Str();
}

EurocImuSensor ReadEurocImuSensorYaml(const TextFile& file) {
  const SensorYaml y(file);
  EurocImuSensor s;
  s.T_BS = y.Transform("T_BS");
  s.rate_hz = y.Number("rate_hz", "the IMU rate [Hz]");
  if (!(s.rate_hz >= kMinSensorRateHz && s.rate_hz <= kMaxSensorRateHz)) y.Fail("rate_hz", RateRule());
  const auto density = [&](const char* key) {
    const double v = y.Number(key, "IMU noise model");
    if (v < 0.0) y.Fail(key, "must not be negative");
    return v;
  };
  s.gyroscope_noise_density = density("gyroscope_noise_density");
  s.gyroscope_random_walk = density("gyroscope_random_walk");
  s.accelerometer_noise_density = density("accelerometer_noise_density");
  s.accelerometer_random_walk = density("accelerometer_random_walk");
  return s;
}

CameraModel ReadEurocCameraSensorYaml(const TextFile& file) {
  const SensorYaml y(file);
  CameraModel c;
  const Eigen::Isometry3d T_BS = y.Transform("T_BS");
  c.T_BC.assign(16, 0.0);
  for (int r = 0; r < 4; ++r)
    for (int col = 0; col < 4; ++col) c.T_BC[4 * r + col] = T_BS.matrix()(r, col);
  c.rate_hz = y.Number("rate_hz", "the camera rate [Hz]");
  if (!(c.rate_hz >= kMinSensorRateHz && c.rate_hz <= kMaxSensorRateHz)) y.Fail("rate_hz", RateRule());
  const std::vector<double> res = y.Numbers("resolution", y.Required("resolution", "[width, height]"), 2);
  for (double v : res)
    if (v < 1.0 || v > 100000.0 || v != std::floor(v))
      y.Fail("resolution", "expected two integers in 1 .. 100000 [px]");
  c.width = static_cast<int>(res[0]);
  c.height = static_cast<int>(res[1]);
  const std::string model = y.Text("camera_model");
  if (!model.empty() && model != "pinhole")
    y.Fail("camera_model", "'" + model + "' is not supported (vigil reads pinhole cameras)");
  const std::vector<double> k =
      y.Numbers("intrinsics", y.Required("intrinsics", "a pinhole camera needs [fu, fv, cu, cv]"), 4);
  if (!(k[0] >= 1.0 && k[0] <= kMaxFocalLengthPx) || !(k[1] >= 1.0 && k[1] <= kMaxFocalLengthPx))
    y.Fail("intrinsics", "focal lengths fu, fv must be in [1, " + FormatDouble(kMaxFocalLengthPx) + "] px");
  if (!(k[2] >= 0.0 && k[2] <= c.width) || !(k[3] >= 0.0 && k[3] <= c.height))
    y.Fail("intrinsics", "principal point cu, cv must lie in the image (0 .. width, 0 .. height px)");
  c.fx = k[0];
  c.fy = k[1];
  c.cx = k[2];
  c.cy = k[3];
  const std::string distortion = y.Text("distortion_model");
  if (!distortion.empty() && distortion != "radial-tangential" && distortion != "radtan" &&
      distortion != "none")
    y.Fail("distortion_model", "'" + distortion + "' is not supported (radial-tangential or none)");
  if (y.Has("distortion_coefficients") && distortion != "none")
    c.distortion = y.Numbers("distortion_coefficients", y.Required("distortion_coefficients", ""), 4);
  for (double coefficient : c.distortion)
    if (!(std::abs(coefficient) <= kMaxDistortionCoefficient))
      y.Fail("distortion_coefficients", "k1, k2, p1, p2 must be within +-" +
                                            FormatDouble(kMaxDistortionCoefficient) + " (got " +
                                            FormatDouble(coefficient) + ")");
  return c;
}

std::vector<CameraImage> ReadEurocImageList(const TextFile& file, const fs::path& image_dir,
                                            bool check_files) {
  CsvReader r(file, 2, "EuRoC cam0 layout: timestamp [ns], filename");
  std::vector<CameraImage> images;
  int64_t last = INT64_MIN;
  while (r.Next()) {
    CameraImage image;
    image.t_ns = r.Int(0);
    if (last != INT64_MIN && image.t_ns <= last)
      r.Fail("timestamp " + std::to_string(image.t_ns) + " does not increase (previous " +
             std::to_string(last) + ")");
    last = image.t_ns;
    const std::string name(r.Text(1));
    if (name.empty())
      r.Fail("filename: missing (expected the image file name, e.g. " + EurocImageName(image.t_ns) + ")");
    image.path = fs::absolute(image_dir / name).lexically_normal().string();
    image.list_path = r.path();
    image.list_line = r.line();
    if (check_files) {
      std::error_code ec;
      if (!fs::is_regular_file(image.path, ec)) r.Fail(image.path + ": image file is missing");
    }
    images.push_back(std::move(image));
  }
  if (images.empty()) r.Fail("no data rows (no images)");
  return images;
}

void CheckImageSize(const CameraImage& image, int width, int height, const CameraModel& camera) {
  if (width == camera.width && height == camera.height) return;
  throw InputError(Located(image.list_path, image.list_line,
                           image.path + ": image is " + std::to_string(width) + " x " +
                               std::to_string(height) + ", the camera's sensor.yaml declares " +
                               std::to_string(camera.width) + " x " + std::to_string(camera.height)));
}

fs::path FindMav0(const fs::path& dir) {
  std::error_code ec;
  const fs::path clean = fs::absolute(dir).lexically_normal();
  const fs::path name = clean.has_filename() ? clean.filename() : clean.parent_path().filename();
  if (name == euroc_files::kMav0 || fs::is_directory(dir / euroc_files::kImu, ec)) return dir;
  if (fs::is_directory(dir / euroc_files::kMav0, ec)) return dir / euroc_files::kMav0;
  return {};
}

fs::path EurocImageDir(const fs::path& dir) {
  return dir / euroc_files::kMav0 / euroc_files::kCamera / euroc_files::kImages;
}

Recording ReadRecording(const fs::path& dir, bool check_image_files) {
  using namespace euroc_files;
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) throw InputError(dir.string() + ": not a dataset directory");
  Recording rec;
  if (IsFile(dir / dataset_files::kImu)) {
    rec.layout = "vigil";
    rec.dataset = ReadDataset(dir);
    rec.has_camera = rec.has_features = rec.has_groundtruth = true;
    const fs::path list = dir / kMav0 / kCamera / kData;
    if (IsFile(list))
      rec.images =
          ReadEurocImageList(ReadTextFile(list.string()), list.parent_path() / kImages, check_image_files);
    for (const CameraImage& image : rec.images)
      CheckCameraTimeInImuSpan(rec.dataset.imu, (dir / dataset_files::kImu).string(), image.t_ns,
                               image.list_path, image.list_line);
    return rec;
  }
  const fs::path mav0 = FindMav0(dir);
  if (mav0.empty())
    throw InputError(
        dir.string() +
        ": not a dataset directory (expected imu.csv of vigil's layout, or a EuRoC mav0/ folder)");
  rec.layout = "euroc";
  Dataset& d = rec.dataset;
  const fs::path imu_dir = mav0 / kImu;
  const TextFile imu_file = ReadTextFile((imu_dir / kData).string());
  d.imu = ReadImuCsv(imu_file);
  // Timestamps never decrease (ReadImuCsv): the stream spans no time when the last equals the first.
  if (d.imu.back().t_ns == d.imu.front().t_ns)
    throw InputError(Located(
        imu_file.path, FirstDataLine(imu_file.text),
        std::to_string(d.imu.size()) + (d.imu.size() == 1 ? " sample" : " samples, all") + " at timestamp " +
            std::to_string(d.imu.front().t_ns) + ": an IMU stream needs at least two distinct timestamps"));
  if (IsFile(imu_dir / kSensor))
    rec.imu_sensor = ReadEurocImuSensorYaml(ReadTextFile((imu_dir / kSensor).string(), kMaxSensorYamlBytes));
  const fs::path cam_dir = mav0 / kCamera;
  if (fs::is_directory(cam_dir, ec)) {
    d.camera = ReadEurocCameraSensorYaml(ReadTextFile((cam_dir / kSensor).string(), kMaxSensorYamlBytes));
    // vigil's body is the IMU: T_BC = T_BS(imu0)^-1 T_BS(cam0).
    const Eigen::Isometry3d T_IC = rec.imu_sensor.T_BS.inverse() * d.camera.T_BC_iso();
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 4; ++c) d.camera.T_BC[4 * r + c] = T_IC.matrix()(r, c);
    rec.images =
        ReadEurocImageList(ReadTextFile((cam_dir / kData).string()), cam_dir / kImages, check_image_files);
    rec.has_camera = true;
  }
  const fs::path gt = mav0 / kGroundTruth / kData;
  if (IsFile(gt)) {
    d.groundtruth = ReadGroundTruthCsv(gt.string());
    rec.has_groundtruth = true;
  }
  CheckGroundTruthInImuSpan(d.imu, (imu_dir / kData).string(), d.groundtruth, gt.string());
  for (const CameraImage& image : rec.images)
    CheckCameraTimeInImuSpan(d.imu, (imu_dir / kData).string(), image.t_ns, image.list_path, image.list_line);
  // Feature tracks beside mav0/ (e.g. written there by `vigil track`), at the image times.
  const fs::path root = mav0 == dir && fs::absolute(dir).lexically_normal().filename() == kMav0
                            ? fs::absolute(dir).lexically_normal().parent_path()
                            : dir;
  // Faults injected into the recording (vigil inject): the glitch-free stream and the records beside mav0/.
  const fs::path clean = root / dataset_files::kImuClean, glitches = root / dataset_files::kGlitches;
  if (IsFile(clean)) {
    d.imu_clean = ReadImuCsv(clean.string());
    CheckCleanImuMatches(d.imu, d.imu_clean, (imu_dir / kData).string(), clean.string());
  }
  if (IsFile(glitches)) d.glitches = ReadGlitchesCsv(glitches.string());
  std::vector<int64_t> frame_times;
  for (const CameraImage& image : rec.images) frame_times.push_back(image.t_ns);
  const fs::path features = root / dataset_files::kFeatures;
  if (rec.has_camera && IsFile(features)) {
    // Tracks are undistorted pixels: with lens distortion they may lie outside the image, so the image bounds
    // are only checked for a pinhole camera.
    FeatureChecks checks;
    checks.camera = d.camera.HasDistortion() ? nullptr : &d.camera;
    d.frames = ReadFeaturesCsv(features.string(), frame_times, &checks);
    rec.has_features = true;
  } else {
    for (int64_t t : frame_times) d.frames.push_back({t, {}});
  }
  return rec;
}

void WriteEuroc(const fs::path& dir, const Dataset& dataset, const EurocImuSensor& imu_sensor,
                const std::vector<int64_t>& image_times_ns) {
  using namespace euroc_files;
  const fs::path mav0 = dir / kMav0;
  fs::create_directories(mav0 / kImu);
  fs::create_directories(EurocImageDir(dir));
  WriteFileAtomic(mav0 / kImu / kData, ImuCsv(dataset.imu));
  WriteFileAtomic(mav0 / kImu / kSensor, EurocImuSensorYaml(imu_sensor));
  WriteFileAtomic(mav0 / kCamera / kData, EurocImageListCsv(image_times_ns));
  WriteFileAtomic(mav0 / kCamera / kSensor, EurocCameraSensorYaml(dataset.camera));
  if (!dataset.groundtruth.empty()) {
    fs::create_directories(mav0 / kGroundTruth);
    WriteFileAtomic(mav0 / kGroundTruth / kData, GroundTruthCsv(dataset.groundtruth));
  }
}

}  // namespace vigil
