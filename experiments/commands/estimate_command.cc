#include "experiments/commands/estimate_command.h"

#include <chrono>
#include <system_error>
#include <utility>

#include "core/csv.h"
#include "core/dataset.h"
#include "core/error.h"
#include "core/euroc.h"
#include "core/output.h"
#include "core/recording_files.h"
#include "evaluation/metrics_access.h"
#include "experiments/runs/external_recording.h"
#include "experiments/runs/frontend_run.h"
#include "experiments/runs/run.h"
#include "experiments/runs/run_config.h"

namespace vigil::experiments {
namespace fs = std::filesystem;

namespace {

// The recording with its feature tracks (tracked from its images when it has no features.csv).
Recording ReadWithTracks(const RunConfig& config, const fs::path& dataset, bool* tracked) {
  // Image files are needed only when there is no features.csv (a recording vigil wrote for an external
  // estimator may list frames whose images were never rendered).
  Recording recording = ReadRecording(dataset, /*check_image_files=*/false);
  if (!recording.has_camera)
    throw InputError(dataset.string() +
                     ": IMU only (no camera.yaml, no mav0/cam0/): the estimator needs a camera");
  *tracked = !recording.has_features && !recording.images.empty();
  if (*tracked) {
    recording = ReadRecording(dataset);  // the same, with every image file checked
    TrackRecording(config, dataset, &recording);
  }
  if (!recording.has_features && !*tracked)
    throw InputError(dataset.string() +
                     ": no features.csv and no camera images (mav0/cam0/data.csv) to track");
  return recording;
}

// The detector's flags of a recording vigil wrote (detections.csv beside mav0/, one row per IMU sample at
// the same timestamps); empty when there is no such file.
std::vector<uint8_t> ReadRecordingFlags(const fs::path& dataset, const ImuStream& imu) {
  const fs::path mav0 = FindMav0(dataset);
  const fs::path root =
      !mav0.empty() && fs::absolute(mav0).lexically_normal() == fs::absolute(dataset).lexically_normal() &&
              fs::absolute(dataset).lexically_normal().filename() == euroc_files::kMav0
          ? fs::absolute(dataset).lexically_normal().parent_path()
          : dataset;
  const fs::path path = root / kRecordingDetections;
  std::error_code ec;
  if (!fs::is_regular_file(path, ec)) return {};
  CsvReader r(path.string(), 2, "detections: timestamp [ns], flagged (0/1)");
  std::vector<uint8_t> flagged;
  flagged.reserve(imu.size());
  while (r.Next()) {
    if (flagged.size() >= imu.size() || r.Int(0) != imu[flagged.size()].t_ns)
      r.Fail("timestamp " + std::string(r.Text(0)) + " is not that of IMU sample " +
             std::to_string(flagged.size() + 1) + " (one row per sample of mav0/imu0/data.csv)");
    const int64_t flag = r.Int(1);
    if (flag != 0 && flag != 1) r.Fail("flagged: expected 0 or 1");
    flagged.push_back(static_cast<uint8_t>(flag));
  }
  if (flagged.size() != imu.size())
    throw InputError(path.string() + ": " + std::to_string(flagged.size()) + " rows for " +
                     std::to_string(imu.size()) + " IMU samples");
  return flagged;
}

}  // namespace

nlohmann::json EstimateToDirectory(const fs::path& dataset, const std::string& config_path,
                                   const std::vector<std::string>& overrides, const fs::path& dir,
                                   bool force) {
  using Clock = std::chrono::steady_clock;
  const Clock::time_point start = Clock::now();
  RunConfig config = LoadRunConfig(config_path, overrides);
  config.estimator.backend = EstimatorBackend::kBuiltin;
  std::vector<fs::path> inputs = RecordingInputPaths(dataset);
  if (!config_path.empty()) inputs.emplace_back(config_path);
  RefuseOutputOverInputs(dir, inputs);

  bool tracked = false;
  Recording recording = ReadWithTracks(config, dataset, &tracked);
  const fs::path mav0 = FindMav0(dataset);
  std::error_code ec;
  if (!mav0.empty() && fs::is_regular_file(mav0 / euroc_files::kImu / euroc_files::kSensor, ec)) {
    sim::ImuNoiseOptions& noise = config.sim.imu.noise;
    noise.gyro_noise_density = recording.imu_sensor.gyroscope_noise_density;
    noise.gyro_bias_random_walk = recording.imu_sensor.gyroscope_random_walk;
    noise.accel_noise_density = recording.imu_sensor.accelerometer_noise_density;
    noise.accel_bias_random_walk = recording.imu_sensor.accelerometer_random_walk;
  }
  const Clock::time_point estimate_start = Clock::now();
  std::vector<uint8_t> flagged = ReadRecordingFlags(dataset, recording.dataset.imu);
  ImuStream imu = recording.dataset.imu;
  const estimator::EstimatorResult result =
      Estimate(config, recording.dataset, std::move(imu), std::move(flagged));
  const double estimate_s = std::chrono::duration<double>(Clock::now() - estimate_start).count();

  nlohmann::json status;
  status["status"] = result.ok ? "ok" : "failed";
  status["failure_reason"] = result.ok ? "" : result.failure_reason;
  status["frames"] = result.frames;
  status["keyframes"] = result.keyframes;
  status["resets"] = result.resets;
  status["initialized_at_s"] = evaluation::NumberOrNull(result.initialized_at_s);
  status["output_poses"] = result.trajectory.size();
  status["tracked"] = tracked;
  status["dataset"] = fs::absolute(dataset).lexically_normal().string();
  status["wall_time_s"] = {{"estimate", estimate_s},
                           {"total", std::chrono::duration<double>(Clock::now() - start).count()}};
  StagedDirectory out(dir, force);
  WriteFileAtomic(out.path() / "stamped_traj_estimate.txt", TumTrajectory(result.trajectory));
  WriteFileAtomic(out.path() / "status.json", status.dump(2) + "\n");
  out.Commit();
  return status;
}

}  // namespace vigil::experiments
