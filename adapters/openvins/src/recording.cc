#include "recording.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <map>
#include <opencv2/core.hpp>
#include <sstream>

namespace vigil_openvins {
namespace fs = std::filesystem;
namespace {

// Rows of a CSV file (comment lines starting with '#' and blank lines skipped), each cell checked as a
// number.
class CsvRows {
 public:
  CsvRows(const fs::path& path, size_t min_columns) : path_(path), in_(path), min_columns_(min_columns) {
    if (!in_) throw InputError(path.string() + ": cannot open");
  }
  // The next row's cells, false at the end.
  bool Next() {
    std::string line;
    while (std::getline(in_, line)) {
      ++line_;
      if (!line.empty() && line.back() == '\r') line.pop_back();
      if (line.empty() || line[0] == '#') continue;
      cells_.clear();
      std::stringstream stream(line);
      for (std::string cell; std::getline(stream, cell, ',');) cells_.push_back(cell);
      if (cells_.size() < min_columns_)
        Fail(std::to_string(cells_.size()) + " columns, expected " + std::to_string(min_columns_));
      return true;
    }
    return false;
  }
  int64_t Int(size_t column) const {
    const std::string& text = cells_[column];
    char* end = nullptr;
    errno = 0;
    const long long value = std::strtoll(text.c_str(), &end, 10);
    if (text.empty() || *end != '\0' || errno != 0)
      Fail("column " + std::to_string(column + 1) + ": '" + text + "' is not an integer");
    return value;
  }
  double Double(size_t column) const {
    const std::string& text = cells_[column];
    char* end = nullptr;
    const double value = std::strtod(text.c_str(), &end);
    if (text.empty() || *end != '\0' || !std::isfinite(value))
      Fail("column " + std::to_string(column + 1) + ": '" + text + "' is not a finite number");
    return value;
  }
  [[noreturn]] void Fail(const std::string& why) const {
    throw InputError(path_.string() + ":" + std::to_string(line_) + ": " + why);
  }

 private:
  fs::path path_;
  std::ifstream in_;
  size_t min_columns_;
  int line_ = 0;
  std::vector<std::string> cells_;
};

// A sensor.yaml in OpenCV's YAML dialect (its "%YAML:1.0" line), as EuRoC publishes and vigil writes it.
class SensorYaml {
 public:
  explicit SensorYaml(const fs::path& path) : path_(path) {
    if (!fs::is_regular_file(path)) throw InputError(path.string() + ": not found");
    try {
      file_.open(path.string(), cv::FileStorage::READ);
    } catch (const cv::Exception& e) {
      throw InputError(path.string() + ": not readable as YAML: " + e.what());
    }
    if (!file_.isOpened()) throw InputError(path.string() + ": not readable as YAML");
  }
  double Number(const std::string& key) const {
    const cv::FileNode node = file_[key];
    if (node.empty() || (!node.isReal() && !node.isInt())) Fail(key, "missing or not a number");
    return static_cast<double>(node);
  }
  std::vector<double> Numbers(const std::string& key, size_t count,
                              const cv::FileNode* parent = nullptr) const {
    const cv::FileNode node = parent ? (*parent)[key] : file_[key];
    std::vector<double> values;
    if (node.isSeq())
      for (const cv::FileNode& item : node)
        if (item.isReal() || item.isInt()) values.push_back(static_cast<double>(item));
    if (values.size() != count || !node.isSeq())
      Fail(key, "expected a list of " + std::to_string(count) + " numbers");
    return values;
  }
  // T_BS {cols: 4, rows: 4, data: [16 numbers, row-major]}.
  Eigen::Matrix4d Transform(const std::string& key) const {
    const cv::FileNode node = file_[key];
    if (!node.isMap()) Fail(key, "missing (expected cols, rows and data)");
    const std::vector<double> data = Numbers("data", 16, &node);
    Eigen::Matrix4d T;
    for (int r = 0; r < 4; ++r)
      for (int c = 0; c < 4; ++c) T(r, c) = data[4 * r + c];
    const Eigen::Matrix3d R = T.topLeftCorner<3, 3>();
    if ((R.transpose() * R - Eigen::Matrix3d::Identity()).norm() > 1e-6 || R.determinant() < 0.0)
      Fail(key, "not a proper rotation");
    return T;
  }
  [[noreturn]] void Fail(const std::string& key, const std::string& why) const {
    throw InputError(path_.string() + ": " + key + ": " + why);
  }
  const cv::FileStorage& file() const { return file_; }

 private:
  fs::path path_;
  cv::FileStorage file_;
};

std::vector<ImuSample> ReadImu(const fs::path& path) {
  std::vector<ImuSample> imu;
  CsvRows rows(path, 7);
  while (rows.Next()) {
    ImuSample s;
    s.t_ns = rows.Int(0);
    s.w_B = {rows.Double(1), rows.Double(2), rows.Double(3)};
    s.a_B = {rows.Double(4), rows.Double(5), rows.Double(6)};
    if (!imu.empty() && s.t_ns < imu.back().t_ns) rows.Fail("timestamp goes backwards");
    if (!imu.empty() && s.t_ns == imu.back().t_ns) continue;  // a repeated sample (a timing fault): kept once
    imu.push_back(s);
  }
  if (imu.size() < 2) throw InputError(path.string() + ": fewer than 2 IMU samples");
  return imu;
}

ImuNoise ReadImuNoise(const fs::path& path) {
  const SensorYaml yaml(path);
  ImuNoise noise;
  noise.rate_hz = yaml.Number("rate_hz");
  noise.gyro_noise_density = yaml.Number("gyroscope_noise_density");
  noise.gyro_random_walk = yaml.Number("gyroscope_random_walk");
  noise.accel_noise_density = yaml.Number("accelerometer_noise_density");
  noise.accel_random_walk = yaml.Number("accelerometer_random_walk");
  for (const char* key : {"gyroscope_noise_density", "gyroscope_random_walk", "accelerometer_noise_density",
                          "accelerometer_random_walk", "rate_hz"})
    if (!(yaml.Number(key) > 0.0)) yaml.Fail(key, "must be > 0");
  if (!yaml.file()["T_BS"].empty()) noise.T_BI = yaml.Transform("T_BS");
  return noise;
}

Camera ReadCamera(const fs::path& path) {
  const SensorYaml yaml(path);
  Camera camera;
  camera.T_BC = yaml.Transform("T_BS");
  const std::vector<double> resolution = yaml.Numbers("resolution", 2);
  camera.width = static_cast<int>(resolution[0]);
  camera.height = static_cast<int>(resolution[1]);
  if (camera.width < 1 || camera.height < 1) yaml.Fail("resolution", "must be positive");
  const std::vector<double> k = yaml.Numbers("intrinsics", 4);
  camera.fx = k[0], camera.fy = k[1], camera.cx = k[2], camera.cy = k[3];
  if (!(camera.fx > 0.0 && camera.fy > 0.0)) yaml.Fail("intrinsics", "focal lengths must be > 0");
  camera.distortion = yaml.file()["distortion_coefficients"].empty()
                          ? std::vector<double>(4, 0.0)
                          : yaml.Numbers("distortion_coefficients", 4);
  const cv::FileNode model = yaml.file()["camera_model"];
  if (!model.empty() && static_cast<std::string>(model) != "pinhole")
    yaml.Fail("camera_model", "only pinhole is read");
  return camera;
}

std::vector<int64_t> ReadFrameTimes(const fs::path& path) {
  std::vector<int64_t> times;
  CsvRows rows(path, 1);
  while (rows.Next()) {
    times.push_back(rows.Int(0));
    if (times.size() > 1 && times.back() <= times[times.size() - 2]) rows.Fail("timestamps must increase");
  }
  return times;
}

std::vector<FrameTracks> ReadTracks(const fs::path& path) {
  std::vector<FrameTracks> frames;
  CsvRows rows(path, 4);
  while (rows.Next()) {
    const int64_t t_ns = rows.Int(0);
    const int64_t id = rows.Int(1);
    if (id < 0) rows.Fail("id: must be >= 0");
    if (!frames.empty() && t_ns < frames.back().t_ns) rows.Fail("timestamp goes backwards");
    if (frames.empty() || t_ns != frames.back().t_ns) frames.push_back({t_ns, {}});
    frames.back().uv.emplace_back(static_cast<size_t>(id), Eigen::Vector2d(rows.Double(2), rows.Double(3)));
  }
  return frames;
}

std::vector<GroundTruth> ReadGroundTruth(const fs::path& path) {
  std::vector<GroundTruth> rows_out;
  CsvRows rows(path, 17);
  while (rows.Next()) {
    GroundTruth g;
    g.t_ns = rows.Int(0);
    g.p_WB = {rows.Double(1), rows.Double(2), rows.Double(3)};
    g.q_WB = Eigen::Quaterniond(rows.Double(4), rows.Double(5), rows.Double(6), rows.Double(7));
    if (g.q_WB.norm() < 1e-6) rows.Fail("zero quaternion");
    g.q_WB.normalize();
    g.v_WB = {rows.Double(8), rows.Double(9), rows.Double(10)};
    g.b_gyro = {rows.Double(11), rows.Double(12), rows.Double(13)};
    g.b_accel = {rows.Double(14), rows.Double(15), rows.Double(16)};
    if (!rows_out.empty() && g.t_ns < rows_out.back().t_ns) rows.Fail("timestamp goes backwards");
    rows_out.push_back(g);
  }
  return rows_out;
}

}  // namespace

Recording ReadRecording(const fs::path& dir) {
  const fs::path mav0 = dir / "mav0";
  if (!fs::is_directory(mav0)) throw InputError(dir.string() + ": no mav0/ folder (not a vigil recording)");
  Recording recording;
  recording.imu = ReadImu(mav0 / "imu0" / "data.csv");
  recording.noise = ReadImuNoise(mav0 / "imu0" / "sensor.yaml");
  recording.camera = ReadCamera(mav0 / "cam0" / "sensor.yaml");
  recording.frame_times_ns = ReadFrameTimes(mav0 / "cam0" / "data.csv");
  const fs::path features = dir / "features.csv";
  if (!fs::is_regular_file(features))
    throw InputError(features.string() + ": not found (this adapter feeds OpenVINS vigil's feature tracks)");
  recording.tracks = ReadTracks(features);
  const fs::path groundtruth = mav0 / "state_groundtruth_estimate0" / "data.csv";
  if (fs::is_regular_file(groundtruth)) recording.groundtruth = ReadGroundTruth(groundtruth);
  return recording;
}

}  // namespace vigil_openvins
