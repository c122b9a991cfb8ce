#include "experiments/runs/external_estimator.h"

#include <stdlib.h>

#include <cerrno>
#include <chrono>
#include <exception>
#include <memory>
#include <optional>
#include <string>
#include <system_error>
#include <vector>

#include "core/error.h"
#include "core/staging.h"
#include "experiments/external/child_process.h"
#include "experiments/external/external_command.h"
#include "experiments/external/external_trajectory.h"
#include "experiments/runs/external_recording.h"

namespace vigil::experiments {
namespace fs = std::filesystem;
namespace {

using Clock = std::chrono::steady_clock;

double ExternalSecondsSince(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// A folder for the recording: inside the run directory (kept), or a temporary one removed on destruction.
class RecordingDir {
 public:
  RecordingDir(const fs::path& run_dir, bool keep) {
    if (keep) {
      path_ = run_dir / "external" / "recording";
      fs::create_directories(path_);
      return;
    }
    std::string pattern = (fs::temp_directory_path() / "vigil-recording-XXXXXX").string();
    if (!::mkdtemp(pattern.data()))
      throw std::system_error(errno, std::generic_category(), "cannot create a temporary folder " + pattern);
    path_ = pattern;
    temporary_ = true;
  }
  ~RecordingDir() {
    std::error_code ec;
    if (temporary_) fs::remove_all(path_, ec);
  }
  RecordingDir(const RecordingDir&) = delete;
  RecordingDir& operator=(const RecordingDir&) = delete;
  const fs::path& path() const { return path_; }

 private:
  fs::path path_;
  bool temporary_ = false;
};

const char* OutcomeName(ChildProcessResult::Outcome outcome) {
  switch (outcome) {
    case ChildProcessResult::Outcome::kExited:
      return "exited";
    case ChildProcessResult::Outcome::kSignaled:
      return "signaled";
    case ChildProcessResult::Outcome::kTimedOut:
      return "timed_out";
    case ChildProcessResult::Outcome::kNotStarted:
      return "not_started";
  }
  return "?";
}

// The command line as it reads once the run is committed: the run directory's staging name
// ("<id>.tmp-<host>-<pid>", core/staging.h) replaced by its final one, where the files then are.
std::vector<std::string> CommittedCommand(std::vector<std::string> argv, const fs::path& run_dir) {
  const fs::path staged = fs::absolute(run_dir).lexically_normal();
  const std::optional<StagingName> staging = ParseStagingName(staged.filename().string());
  if (!staging) return argv;
  const std::string from = staged.string();
  const std::string to = (staged.parent_path() / staging->final_name).string();
  for (std::string& arg : argv)
    for (std::size_t at = arg.find(from); at != std::string::npos; at = arg.find(from, at + to.size()))
      arg.replace(at, from.size(), to);
  return argv;
}

}  // namespace

ExternalEstimate RunExternalEstimator(const RunConfig& config, const Dataset& dataset, const ImuStream& imu,
                                      const std::vector<uint8_t>& flagged,
                                      const std::vector<CameraImage>& images, const fs::path& run_dir,
                                      const EurocImuSensor* dataset_imu_sensor) {
  const ExternalEstimatorOptions& options = config.estimator.external;
  ExternalEstimate out;
  estimator::EstimatorResult& result = out.result;
  nlohmann::json& json = out.json;
  const auto fail = [&](const std::string& reason) {
    result.ok = false;
    result.failure_reason = "external estimator: " + reason;
    result.trajectory.clear();
    result.frames = 0;
  };
  json["wall_time_s"] = {{"write_recording", 0.0}, {"process", 0.0}, {"read", 0.0}};
  // From here to the return, an interrupt is handed on to the program and then thrown (Interrupted), so
  // that the temporary recording is removed on the way out.
  const InterruptScope interrupts;

  // 1. The recording, the output folder and the command line.
  const fs::path external_dir = run_dir / "external";
  const fs::path output_dir = external_dir / "output";
  Clock::time_point t = Clock::now();
  std::unique_ptr<RecordingDir> recording;
  try {
    fs::create_directories(output_dir);
    recording = std::make_unique<RecordingDir>(run_dir, options.keep_recording);
    WriteExternalRecording(recording->path(), config, dataset, imu, flagged, images, dataset_imu_sensor);
  } catch (const std::exception& e) {
    fail(std::string("cannot write the recording: ") + e.what());
    return out;
  }
  json["wall_time_s"]["write_recording"] = ExternalSecondsSince(t);
  const CommandPlaceholders values{fs::absolute(recording->path()).string(),
                                   fs::absolute(recording->path() / euroc_files::kMav0).string(),
                                   fs::absolute(output_dir).string(),
                                   fs::absolute(recording->path() / dataset_files::kConfig).string(),
                                   std::to_string(config.seed),
                                   CurrentExecutablePath()};
  ChildProcessOptions child;
  for (const std::string& arg : options.command) child.argv.push_back(ExpandPlaceholders(arg, values));
  json["command"] = CommittedCommand(child.argv, run_dir);
  json["recording"] = options.keep_recording
                          ? "external/recording"
                          : "removed after the run (estimator.external.keep_recording: true keeps it in "
                            "external/recording)";
  std::string why;
  child.program = ResolveExecutable(child.argv.front(), &why);
  if (child.program.empty()) {
    fail(why);
    return out;
  }
  child.working_dir = output_dir;
  child.stdout_path = external_dir / "stdout.txt";
  child.stderr_path = external_dir / "stderr.txt";
  child.timeout_s = options.timeout_s;

  // 2. The program.
  const ChildProcessResult run = RunChildProcess(child);
  json["wall_time_s"]["process"] = run.wall_s;
  json["outcome"] = OutcomeName(run.outcome);
  json["exit_code"] = run.exit_code;
  if (run.outcome == ChildProcessResult::Outcome::kSignaled) json["signal"] = run.signal;
  if (!run.succeeded()) {
    fail(run.Describe(options.timeout_s) + " (see external/stderr.txt)");
    return out;
  }

  // 3. Its trajectory.
  t = Clock::now();
  const int64_t t_first = imu.empty() ? 0 : imu.front().t_ns;
  const int64_t t_last = imu.empty() ? 0 : imu.back().t_ns;
  const fs::path trajectory = output_dir / options.trajectory;
  const std::string outside = TrajectoryOutsideOutput(trajectory, output_dir);
  if (!outside.empty()) {
    fail(outside);
    return out;
  }
  ExternalTrajectory read =
      ReadExternalTrajectory(trajectory, options.format, options.time_unit, t_first, t_last);
  json["wall_time_s"]["read"] = ExternalSecondsSince(t);
  json["rows"] = read.trajectory.size();
  if (!read.failure.empty()) {
    fail(read.failure);
    return out;
  }
  result.trajectory = std::move(read.trajectory);
  result.frames = static_cast<int>(result.trajectory.size());
  result.initialized_at_s = NsToS(result.trajectory.front().t_ns);
  return out;
}

std::string ExternalInputProblem(const RunConfig& config, bool has_images, bool has_features) {
  if (config.estimator.backend != EstimatorBackend::kExternal) return {};
  const ExternalInput input = config.estimator.external.input;
  if (input == ExternalInput::kImages && !has_images)
    return "estimator.external.input: images: the recording has no camera images for the external estimator "
           "(simulated runs have feature tracks only; run it on a dataset with mav0/cam0 images)";
  if (input == ExternalInput::kFeatures && !has_features)
    return "estimator.external.input: features: the recording has no feature tracks";
  if (!has_images && !has_features)
    return "estimator.external.input: the recording has neither camera images nor feature tracks for the "
           "external estimator";
  return {};
}

}  // namespace vigil::experiments
