#include "core/recording_files.h"

#include <algorithm>
#include <set>

#include "core/dataset.h"
#include "core/euroc.h"
#include "core/mesh.h"

namespace vigil {
namespace fs = std::filesystem;
namespace {

// Files of vigil's layout (and what vigil writes beside a EuRoC mav0/), in the recording's folder.
constexpr const char* kRootFiles[] = {dataset_files::kConfig,
                                      dataset_files::kImu,
                                      dataset_files::kImuClean,
                                      dataset_files::kGlitches,
                                      dataset_files::kGroundTruth,
                                      dataset_files::kLandmarks,
                                      dataset_files::kFeatures,
                                      dataset_files::kCamera,
                                      dataset_files::kFrames,
                                      kSceneObjFile,
                                      "injection.yaml",
                                      "README.md"};
// The sensor folders of the EuRoC MAV layout, and which of them are cameras with an image folder.
constexpr const char* kSensorDirs[] = {
    euroc_files::kImu, euroc_files::kCamera, "cam1", euroc_files::kGroundTruth, "leica0", "vicon0"};
constexpr const char* kSensorFiles[] = {euroc_files::kData, euroc_files::kSensor};
constexpr const char* kMav0Files[] = {"body.yaml"};

bool IsCamera(const std::string& sensor) { return sensor.rfind("cam", 0) == 0; }

// mav0/'s path relative to `dir`: "" when `dir` is itself mav0 (or holds imu0/), "mav0", or none.
bool FindMav0Prefix(const fs::path& dir, std::string* prefix) {
  const fs::path mav0 = FindMav0(dir);
  if (mav0.empty()) return false;
  *prefix = mav0 == dir ? "" : euroc_files::kMav0;
  return true;
}

std::string Join(const std::string& a, const std::string& b) { return a.empty() ? b : a + "/" + b; }

}  // namespace

std::vector<RecordingEntry> RecordingEntries(const fs::path& dir) {
  std::vector<RecordingEntry> entries;
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) return entries;
  auto add = [&](const std::string& path, RecordingEntry::Kind kind) {
    const fs::file_status status = fs::status(dir / path, ec);
    const bool is_dir = fs::is_directory(status), is_file = fs::is_regular_file(status);
    if (kind == RecordingEntry::Kind::kFile ? is_file : is_dir) entries.push_back({path, kind});
    return kind == RecordingEntry::Kind::kFile ? is_file : is_dir;
  };
  for (const char* file : kRootFiles) add(file, RecordingEntry::Kind::kFile);
  std::string mav0;
  if (!FindMav0Prefix(dir, &mav0)) return entries;
  if (!mav0.empty()) add(mav0, RecordingEntry::Kind::kDirectory);
  for (const char* file : kMav0Files) add(Join(mav0, file), RecordingEntry::Kind::kFile);
  for (const char* sensor : kSensorDirs) {
    const std::string sensor_dir = Join(mav0, sensor);
    if (!add(sensor_dir, RecordingEntry::Kind::kDirectory)) continue;
    for (const char* file : kSensorFiles) add(Join(sensor_dir, file), RecordingEntry::Kind::kFile);
    if (IsCamera(sensor)) add(Join(sensor_dir, euroc_files::kImages), RecordingEntry::Kind::kImageFolder);
  }
  return entries;
}

std::vector<fs::path> RecordingInputPaths(const fs::path& dir) {
  std::vector<fs::path> paths{dir};
  for (const RecordingEntry& entry : RecordingEntries(dir)) paths.push_back(dir / entry.path);
  return paths;
}

std::vector<std::string> EntriesOutsideRecording(const fs::path& dir) {
  const std::vector<RecordingEntry> entries = RecordingEntries(dir);
  std::set<std::string> known;
  std::vector<std::string> folders{""};
  for (const RecordingEntry& e : entries) {
    known.insert(e.path);
    if (e.kind == RecordingEntry::Kind::kDirectory) folders.push_back(e.path);
  }
  std::vector<std::string> outside;
  std::error_code ec;
  for (const std::string& folder : folders)
    for (fs::directory_iterator it(dir / folder, ec), end; !ec && it != end; it.increment(ec)) {
      const std::string path = Join(folder, it->path().filename().string());
      if (!known.count(path) && path != kOutputManifest) outside.push_back(path);
    }
  std::sort(outside.begin(), outside.end());
  return outside;
}

}  // namespace vigil
