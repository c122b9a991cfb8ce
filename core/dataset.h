// The dataset directory of docs/formats.md, in memory and on disk.
//
// `vigil simulate` writes it, `vigil clean` and `vigil run --dataset` read it. Every reader validates what it
// reads (column count, finite numbers, strictly increasing timestamps) and reports "file:line: reason".
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "core/camera.h"
#include "core/output.h"
#include "core/types.h"

namespace vigil {

struct Dataset {
  ImuStream imu;                       // measured (glitches included)
  ImuStream imu_clean;                 // the same samples without the injected glitches
  std::vector<GlitchRecord> glitches;  // injected faults (one row per sample and axis, or per sample)
  std::vector<NavState> groundtruth;   // at IMU rate
  std::vector<Landmark> landmarks;
  std::vector<CameraFrame> frames;  // feature tracks per camera frame (frames without features included)
  CameraModel camera;
};

// File names inside a dataset directory.
namespace dataset_files {
inline constexpr const char* kConfig = "config.yaml";
inline constexpr const char* kImu = "imu.csv";
inline constexpr const char* kImuClean = "imu_clean.csv";
inline constexpr const char* kGlitches = "glitches.csv";
inline constexpr const char* kGroundTruth = "groundtruth.csv";
inline constexpr const char* kLandmarks = "landmarks.csv";
inline constexpr const char* kFeatures = "features.csv";
inline constexpr const char* kCamera = "camera.yaml";
inline constexpr const char* kFrames = "frames.csv";  // every camera frame's time, features or not
}  // namespace dataset_files

// The records of kind offset (the glitches a detector is scored on: the paper's fault); saturation and timing
// records describe other faults.
std::vector<GlitchRecord> OffsetGlitches(const std::vector<GlitchRecord>& records);

// Limits every reader checks (besides finite numbers and increasing timestamps), so that a corrupt file is an
// error naming its line instead of a NaN or an allocation that never ends.
inline constexpr double kMaxAbsCoordinate_m = 1e6;     // positions (ground truth, landmarks)
inline constexpr double kMaxAbsImuValue = 1e6;         // any gyroscope [rad/s] or accelerometer [m/s^2] axis
inline constexpr int64_t kMaxImuGap_ns = 1000000000;   // between consecutive IMU samples (1 s)
inline constexpr double kMaxAbsGroundTruthRate = 1e6;  // velocity [m/s] and bias components
// A ground truth whose position jumps faster than this between consecutive rows is rejected (a teleport: a
// glued or mis-stamped file; the fastest platforms vigil models fly at tens of m/s).
inline constexpr double kMaxGroundTruthSpeed_mps = 100.0;
// How far the ground truth may reach beyond the IMU's time span (a recording's sensors
// start and stop a little apart; beyond this the recording is cut or its clocks disagree).
inline constexpr int64_t kSensorSpanTolerance_ns = 100'000'000;  // 0.1 s

// InputError "FILE:LINE: ..." unless the IMU covers the ground truth's span within kSensorSpanTolerance_ns
// (`groundtruth` may be empty; its row k is line k + 2 of its file).
void CheckGroundTruthInImuSpan(const ImuStream& imu, const std::string& imu_path,
                               const std::vector<NavState>& groundtruth, const std::string& groundtruth_path);
// InputError "FILE:LINE: ..." unless the camera time `t_ns`, read at `file`:`line`, lies inside the IMU's
// time span (no tolerance: a frame needs IMU samples on both sides to be tied to the motion).
void CheckCameraTimeInImuSpan(const ImuStream& imu, const std::string& imu_path, int64_t t_ns,
                              const std::string& file, int line);

// What a features.csv is checked against when its dataset is known (ReadDataset): ids of landmarks.csv,
// pixels inside the image (with a margin of 10 x the pixel noise + 1 px; for a camera with lens distortion,
// the pixel's distorted image position), one observation per id and frame, times within the camera frames
// (with `listed_times`: each time one of the frames listed).
struct FeatureChecks {
  const CameraModel* camera = nullptr;
  const std::vector<Landmark>* landmarks = nullptr;
  bool listed_times = false;
  int64_t min_t_ns = INT64_MIN;  // the IMU's time span: every feature time lies within it
  int64_t max_t_ns = INT64_MAX;
};

// Serialization of each file (the text is what is written; reading parses a path). `file` names the file in
// the error for a value that cannot be written (inf or nan).
std::string ImuCsv(const ImuStream& imu, const std::string& file = dataset_files::kImu);
std::string GlitchesCsv(const std::vector<GlitchRecord>& glitches,
                        const std::string& file = dataset_files::kGlitches);
std::string GroundTruthCsv(const std::vector<NavState>& states,
                           const std::string& file = dataset_files::kGroundTruth);
std::string LandmarksCsv(const std::vector<Landmark>& landmarks,
                         const std::string& file = dataset_files::kLandmarks);
// One row per observation; `frames` must be in time order.
std::string FeaturesCsv(const std::vector<CameraFrame>& frames,
                        const std::string& file = dataset_files::kFeatures);
std::string CameraYaml(const CameraModel& camera);
// frames.csv: "#timestamp [ns]", one row per camera frame (frames without features included), so that a
// reader gets the recording's frames at their own times, never reconstructed from a rate.
std::string FramesCsv(const std::vector<CameraFrame>& frames,
                      const std::string& file = dataset_files::kFrames);
std::vector<int64_t> ReadFramesCsv(const std::string& path);
std::vector<int64_t> ReadFramesCsv(const TextFile& file);

// Every reader takes a path (a regular file, core/output.h) or a file already in memory (the fuzz targets).
ImuStream ReadImuCsv(const std::string& path);
ImuStream ReadImuCsv(const TextFile& file);
std::vector<GlitchRecord> ReadGlitchesCsv(const std::string& path);
std::vector<GlitchRecord> ReadGlitchesCsv(const TextFile& file);
std::vector<NavState> ReadGroundTruthCsv(const std::string& path);
std::vector<NavState> ReadGroundTruthCsv(const TextFile& file);
std::vector<Landmark> ReadLandmarksCsv(const std::string& path);
std::vector<Landmark> ReadLandmarksCsv(const TextFile& file);
// imu_clean.csv must hold the glitch-free value of every imu.csv sample: the same number of rows with the
// same timestamps (else InputError naming both files, and the row where they part, and what to do).
void CheckCleanImuMatches(const ImuStream& imu, const ImuStream& clean, const std::string& imu_path,
                          const std::string& clean_path);
// Groups rows by timestamp. Camera frames with no visible feature do not appear in the file; pass the
// recording's frame times in `frame_times_ns` (frames.csv, a EuRoC cam0/data.csv) to get them back as empty
// frames (or leave it empty: the frames are the file's timestamps).
// Ids must be >= 0 and distinct per frame; with `checks`, also the checks of FeatureChecks.
std::vector<CameraFrame> ReadFeaturesCsv(const std::string& path,
                                         const std::vector<int64_t>& frame_times_ns = {},
                                         const FeatureChecks* checks = nullptr);
std::vector<CameraFrame> ReadFeaturesCsv(const TextFile& file,
                                         const std::vector<int64_t>& frame_times_ns = {},
                                         const FeatureChecks* checks = nullptr);
CameraModel ReadCameraYaml(const std::string& path);

// Camera frame times on a grid: t_k = t_first_ns + round(k * 1e9 / rate_hz) for k = 0, 1, ... while
// t_k <= t_last_ns. The simulator takes its frames at these times (before camera timing faults); readers
// never reconstruct frames from a rate (frames.csv lists them).
std::vector<int64_t> CameraFrameTimes(double rate_hz, int64_t t_first_ns, int64_t t_last_ns);

// Writes every file except config.yaml into `dir` (which must exist); errors name the files as inside
// `shown_dir` when given (the final output directory, when `dir` is its staging).
void WriteDataset(const std::filesystem::path& dir, const Dataset& dataset,
                  const std::filesystem::path& shown_dir = {});
// Reads a dataset directory; imu_clean.csv and glitches.csv are optional (left empty when absent). Ground
// truth needs at least 2 rows. The camera frames are those of frames.csv at their own times (features.csv
// timestamps must be among them; frames without features come back empty); without frames.csv (datasets
// written before it), the timestamps of features.csv. Frame times must lie within the IMU's time span.
Dataset ReadDataset(const std::filesystem::path& dir);

// rpg / TUM trajectory text: "# timestamp tx ty tz qx qy qz qw", seconds with 9 decimals.
std::string TumTrajectory(const Trajectory& trajectory);
Trajectory ReadTumTrajectory(const std::string& path);
Trajectory ReadTumTrajectory(const TextFile& file);

}  // namespace vigil
