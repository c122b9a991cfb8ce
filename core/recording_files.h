// What a recording is on disk: the entries vigil knows by name (docs/recordings.md, "What a recording
// holds"). Nothing else in a recording's folder is part of it: `vigil inject` copies these entries only, and
// no output may be, contain or lie inside one of them once symbolic links are resolved (an image folder that
// links elsewhere makes that elsewhere an input).
//
// Entries are looked up by name, never found by walking a directory: a link inside the recording to another
// tree (/usr/share/doc, /, or back into the recording) is never entered.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace vigil {

struct RecordingEntry {
  enum class Kind { kFile, kDirectory, kImageFolder };
  std::string path;  // relative to the recording's folder, generic form ("mav0/cam0/data.csv")
  Kind kind = Kind::kFile;
};

// The known entries of the recording in `dir` that exist with the right type (links followed to find it):
// - vigil's files in `dir` (imu.csv, groundtruth.csv, ..., frames.csv, scene.obj, injection.yaml,
//   README.md);
// - mav0/ (`dir` itself when `dir` holds imu0/ directly), its body.yaml, and of each EuRoC sensor folder
//   (imu0, cam0, cam1, state_groundtruth_estimate0, leica0, vicon0) data.csv and sensor.yaml; the cameras'
//   image folders data/ as kImageFolder, never listed.
// Directories come before what they hold. Empty when `dir` is not a directory.
std::vector<RecordingEntry> RecordingEntries(const std::filesystem::path& dir);

// `dir` and `dir / entry` for every entry: the paths an output must stay clear of (RefuseOutputOverInputs
// resolves each, so a linked image folder stands for its target).
std::vector<std::filesystem::path> RecordingInputPaths(const std::filesystem::path& dir);

// What lies directly in `dir`, in mav0/ and in its sensor folders but is not a known entry (generic relative
// paths, sorted): what a copy of the recording leaves out. Lists one level per folder; enters nothing else.
std::vector<std::string> EntriesOutsideRecording(const std::filesystem::path& dir);

}  // namespace vigil
