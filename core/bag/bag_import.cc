#include "core/bag/bag_import.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <set>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "core/bag/bag_file.h"
#include "core/bag/bag_presets.h"
#include "core/bag/bag_topics.h"
#include "core/bag/gray_image.h"
#include "core/bag/ros_message.h"
#include "core/dataset.h"
#include "core/error.h"
#include "core/euroc.h"
#include "core/format.h"
#include "core/output.h"
#include "core/png/png_encode.h"
#include "core/pose_checks.h"

namespace vigil::bag {
namespace {

namespace fs = std::filesystem;
constexpr std::uintmax_t kMaxSensorYamlBytes = 1 << 20;

// "BAG: TOPIC: message N: " (N from 1).
std::string Where(const std::string& bag, const std::string& topic, std::size_t index) {
  return bag + ": " + topic + ": message " + std::to_string(index + 1) + ": ";
}

std::string Seconds(int64_t t_ns) { return FormatFixed(NsToS(t_ns), 9) + " s"; }

// The sensor.yaml files written: a given file (checked by vigil's reader, copied as it is) or the preset's.
struct SensorFiles {
  std::string imu_yaml, camera_yaml;  // texts; camera_yaml empty without images
  CameraModel camera;
};

SensorFiles ReadSensorFiles(const BagImportRequest& request, const BagPreset& preset, bool images) {
  SensorFiles files;
  if (request.imu_yaml.empty()) {
    files.imu_yaml = EurocImuSensorYaml(preset.imu, preset.imu_comment);
  } else {
    const TextFile file = ReadTextFile(request.imu_yaml, kMaxSensorYamlBytes);
    ReadEurocImuSensorYaml(file);
    files.imu_yaml = file.text;
  }
  if (!images) return files;
  if (!request.camera_yaml.empty()) {
    const TextFile file = ReadTextFile(request.camera_yaml, kMaxSensorYamlBytes);
    files.camera = ReadEurocCameraSensorYaml(file);
    files.camera_yaml = file.text;
  } else if (preset.camera) {
    files.camera = *preset.camera;
    files.camera_yaml = EurocCameraSensorYaml(*preset.camera, preset.camera_comment);
  } else {
    throw InputError(std::string("--camera-yaml: the ") + preset.name +
                     " preset has no camera calibration (" + preset.no_camera_reason +
                     "); give a pinhole cam0 sensor.yaml, or --image-topic none to import the IMU and the "
                     "ground truth only");
  }
  return files;
}

// Converts the messages one by one into the staged directory: images are written as they come, the IMU and
// the ground truth are kept for the end.
class MessageSink {
 public:
  MessageSink(const std::string& bag, const ImportTopics& topics, const SensorFiles& sensors,
              const fs::path& image_dir)
      : bag_(bag), topics_(topics), camera_(sensors.camera), image_dir_(image_dir) {}

  void Take(const BagMessage& m) {
    try {
      if (m.topic == topics_.imu) TakeImu(m);
      if (m.topic == topics_.image) TakeImage(m);
      if (m.topic == topics_.groundtruth) TakePose(m);
    } catch (const MessageError& e) {
      throw InputError(Where(bag_, m.topic, m.index) + e.what());
    }
  }

  ImuStream imu;
  std::vector<int64_t> image_times;
  std::vector<PoseMessage> poses;
  std::set<std::string> encodings;

 private:
  // Stamps must increase (the IMU's may repeat, as imu.csv's may: a duplicated sample is a fault vigil
  // models).
  void CheckStamp(int64_t t_ns, int64_t previous_ns, bool repeat_ok) const {
    if (t_ns > previous_ns || (repeat_ok && t_ns == previous_ns)) return;
    throw MessageError("header stamp " + Seconds(t_ns) + (t_ns == previous_ns ? " repeats" : " goes back") +
                       " (previous message " + Seconds(previous_ns) + ")");
  }
  static void CheckFinite(const Eigen::Ref<const Eigen::VectorXd>& v, const char* what) {
    if (!v.allFinite()) throw MessageError(std::string(what) + ": not a finite number");
  }

  void TakeImu(const BagMessage& m) {
    const ImuSample s = DecodeImu(m.bytes.data(), m.bytes.size());
    if (!imu.empty()) CheckStamp(s.t_ns, imu.back().t_ns, true);
    CheckFinite(s.w_B, "angular_velocity");
    CheckFinite(s.a_B, "linear_acceleration");
    imu.push_back(s);
  }

  void TakeImage(const BagMessage& m) {
    const ImageMessage image = DecodeImage(m.bytes.data(), m.bytes.size());
    if (!image_times.empty()) CheckStamp(image.t_ns, image_times.back(), false);
    const cv::Mat gray = ToGray8(image);
    if (gray.cols != camera_.width || gray.rows != camera_.height)
      throw MessageError("image is " + std::to_string(gray.cols) + " x " + std::to_string(gray.rows) +
                         ", the camera's sensor.yaml declares " + std::to_string(camera_.width) + " x " +
                         std::to_string(camera_.height));
    // zlib level 1, the level OpenCV's PNG writer takes by default.
    WriteFileAtomic(image_dir_ / EurocImageName(image.t_ns),
                    EncodePng8(gray.ptr(), gray.cols, gray.rows, PngRows::kGray, gray.step, {1}));
    image_times.push_back(image.t_ns);
    encodings.insert(image.encoding);
  }

  void TakePose(const BagMessage& m) {
    const PoseMessage pose = DecodePose(topics_.groundtruth_type, m.bytes.data(), m.bytes.size());
    if (!poses.empty()) CheckStamp(pose.t_ns, poses.back().t_ns, false);
    CheckFinite(pose.p_W, "position");
    CheckFinite(pose.q_WB.coeffs(), "orientation");
    if (pose.v_B) CheckFinite(*pose.v_B, "linear velocity");
    // The rule of every pose reader (core/pose_checks.h).
    if (const std::string problem = QuaternionNormProblem(pose.q_WB); !problem.empty())
      throw MessageError("orientation: " + problem);
    poses.push_back(pose);
  }

  const std::string& bag_;
  const ImportTopics& topics_;
  const CameraModel& camera_;
  fs::path image_dir_;
};

bool InSpan(int64_t t_ns, const ImuStream& imu) {
  return t_ns >= imu.front().t_ns && t_ns <= imu.back().t_ns;
}

// The images inside the IMU's time span; the files of the others are removed.
std::vector<int64_t> KeepImagesInImuSpan(const std::vector<int64_t>& times, const ImuStream& imu,
                                         const fs::path& image_dir) {
  std::vector<int64_t> kept;
  for (int64_t t : times) {
    if (InSpan(t, imu))
      kept.push_back(t);
    else
      fs::remove(image_dir / EurocImageName(t));
  }
  return kept;
}

// The ground truth inside the IMU's time span, with velocities (Odometry's rotated into W, or else central
// differences of the positions) and zero biases.
std::vector<NavState> GroundTruthInImuSpan(const std::vector<PoseMessage>& poses, const ImuStream& imu) {
  std::vector<NavState> states;
  std::vector<const PoseMessage*> kept;
  for (const PoseMessage& p : poses)
    if (InSpan(p.t_ns, imu)) kept.push_back(&p);
  for (std::size_t k = 0; k < kept.size(); ++k) {
    NavState s;
    s.t_ns = kept[k]->t_ns;
    s.p_W = kept[k]->p_W;
    s.q_WB = kept[k]->q_WB;
    if (kept[k]->v_B) {
      s.v_W = s.q_WB.normalized() * *kept[k]->v_B;
    } else if (kept.size() > 1) {
      const PoseMessage& a = *kept[k == 0 ? 0 : k - 1];
      const PoseMessage& b = *kept[k + 1 == kept.size() ? k : k + 1];
      s.v_W = (b.p_W - a.p_W) / NsToS(b.t_ns - a.t_ns);
    }
    states.push_back(s);
  }
  return states;
}

std::string JoinSet(const std::set<std::string>& names) {
  std::string s;
  for (const std::string& n : names) s += (s.empty() ? "" : ", ") + n;
  return s;
}

std::string ImportYaml(const BagImportRequest& request, const ImportTopics& topics,
                       const BagImportResult& result) {
  YAML::Node y;
  y["source"] = fs::absolute(request.bag).lexically_normal().string();
  y["preset"] = request.preset;
  y["imu"]["topic"] = topics.imu;
  y["imu"]["samples"] = result.imu_samples;
  y["imu"]["sensor_yaml"] = request.imu_yaml.empty() ? "preset" : request.imu_yaml;
  if (!topics.image.empty()) {
    y["images"]["topic"] = topics.image;
    y["images"]["encodings"] = result.encodings;
    y["images"]["written"] = result.images;
    y["images"]["outside_imu_span"] = result.images_outside;
    y["images"]["sensor_yaml"] = request.camera_yaml.empty() ? "preset" : request.camera_yaml;
  }
  if (!topics.groundtruth.empty()) {
    y["groundtruth"]["topic"] = topics.groundtruth;
    y["groundtruth"]["type"] = topics.groundtruth_type;
    y["groundtruth"]["written"] = result.poses;
    y["groundtruth"]["outside_imu_span"] = result.poses_outside;
    y["groundtruth"]["velocity"] =
        topics.groundtruth_type == kOdometryType.name ? "odometry" : "central differences";
    y["groundtruth"]["biases"] = "unknown (0)";
  }
  YAML::Emitter out;
  out << y;
  return std::string(out.c_str()) + "\n";
}

// vigil's own reader on the staged folder: what it refuses is refused now, naming the final paths.
void ReadBack(const fs::path& staged, const std::string& output, const std::string& bag) {
  try {
    ReadRecording(staged);
  } catch (const InputError& e) {
    std::string message = e.what();
    const std::string from = staged.string(), to = fs::path(output).string();
    for (std::size_t at = message.find(from); at != std::string::npos;
         at = message.find(from, at + to.size()))
      message.replace(at, from.size(), to);
    throw InputError(bag + ": the imported recording does not read back: " + message);
  }
}

}  // namespace

BagImportResult ImportBag(const BagImportRequest& request, const ImportProgress& progress) {
  using namespace euroc_files;
  // Check everything that needs no conversion before writing anything.
  const BagPreset& preset = FindBagPreset(request.preset);
  std::vector<fs::path> inputs{request.bag};
  for (const std::string& file : {request.imu_yaml, request.camera_yaml})
    if (!file.empty()) inputs.emplace_back(file);
  RefuseOutputOverInputs(request.output, inputs);
  const bool images = request.image_topic != kNoTopic;
  const SensorFiles sensors = ReadSensorFiles(request, preset, images);
  const BagFile bag(request.bag);
  const ImportTopics topics = ResolveTopics(request, preset, bag);

  StagedDirectory out(request.output, request.force);
  const fs::path mav0 = out.path() / kMav0;
  fs::create_directories(mav0 / kImu);
  if (images) fs::create_directories(EurocImageDir(out.path()));
  MessageSink sink(request.bag, topics, sensors, EurocImageDir(out.path()));
  std::vector<std::string> names;
  for (const std::string& name : {topics.imu, topics.image, topics.groundtruth})
    if (!name.empty()) names.push_back(name);
  std::size_t done = 0;
  bag.ForEach(names, [&](const BagMessage& m) {
    sink.Take(m);
    if (progress) progress(++done, topics.messages);
  });

  BagImportResult result;
  result.imu_samples = sink.imu.size();
  if (sink.imu.size() < 2 || sink.imu.front().t_ns == sink.imu.back().t_ns)
    throw InputError(request.bag + ": " + topics.imu + ": " + std::to_string(sink.imu.size()) +
                     " messages; an IMU stream needs at least two distinct stamps");
  WriteFileAtomic(mav0 / kImu / kData,
                  ImuCsv(sink.imu, (fs::path(request.output) / kMav0 / kImu / kData).string()));
  WriteFileAtomic(mav0 / kImu / kSensor, sensors.imu_yaml);
  if (images) {
    const std::vector<int64_t> kept =
        KeepImagesInImuSpan(sink.image_times, sink.imu, EurocImageDir(out.path()));
    result.image_topic = topics.image;
    result.images = kept.size();
    result.images_outside = sink.image_times.size() - kept.size();
    result.encodings = JoinSet(sink.encodings);
    if (kept.empty())
      throw InputError(request.bag + ": " + topics.image + ": no image within the IMU's time span (" +
                       Seconds(sink.imu.front().t_ns) + " to " + Seconds(sink.imu.back().t_ns) + ")");
    WriteFileAtomic(mav0 / kCamera / kData, EurocImageListCsv(kept));
    WriteFileAtomic(mav0 / kCamera / kSensor, sensors.camera_yaml);
  }
  result.groundtruth_note = topics.groundtruth_note;
  if (!topics.groundtruth.empty()) {
    const std::vector<NavState> gt = GroundTruthInImuSpan(sink.poses, sink.imu);
    result.groundtruth_topic = topics.groundtruth;
    result.poses = gt.size();
    result.poses_outside = sink.poses.size() - gt.size();
    if (gt.size() < 2)
      throw InputError(request.bag + ": " + topics.groundtruth + ": " + std::to_string(gt.size()) +
                       " poses within the IMU's time span; a ground truth needs at least two");
    fs::create_directories(mav0 / kGroundTruth);
    WriteFileAtomic(mav0 / kGroundTruth / kData, GroundTruthCsv(gt));
  }
  WriteFileAtomic(out.path() / "import.yaml", ImportYaml(request, topics, result));
  ReadBack(out.path(), request.output, request.bag);
  out.Commit();
  return result;
}

std::string BagImportSummary(const BagImportRequest& request, const BagImportResult& result) {
  std::string s = std::to_string(result.imu_samples) + " IMU samples";
  if (!result.image_topic.empty()) {
    s += ", " + std::to_string(result.images) + " images (" + result.encodings + ")";
    if (result.images_outside > 0)
      s += " (" + std::to_string(result.images_outside) + " outside the IMU's time span left out)";
  }
  if (!result.groundtruth_topic.empty()) {
    s += ", " + std::to_string(result.poses) + " ground-truth poses";
    if (result.poses_outside > 0)
      s += " (" + std::to_string(result.poses_outside) + " outside the IMU's time span left out)";
  } else if (!result.groundtruth_note.empty()) {
    s += ", " + result.groundtruth_note;
  }
  return s + " -> " + request.output;
}

}  // namespace vigil::bag
