// A copy of a recording that a command then edits (`vigil inject` replaces its IMU): the recording's known
// entries only (core/recording_files.h); image folders are linked, never copied; small files are copied;
// large ones are linked.
#pragma once

#include <cstdint>
#include <filesystem>
#include <set>
#include <string>
#include <vector>

namespace vigil {

// Files above this size are linked instead of copied.
inline constexpr std::uintmax_t kMaxCopiedFileBytes = 16u << 20;  // 16 MiB

struct RecordingCopyStats {
  int copied_files = 0, linked_files = 0, linked_image_dirs = 0;
  std::vector<std::string> left_out;  // EntriesOutsideRecording(source): not part of the recording
};

// Copies the recording in `source` into the existing directory `dest`, entry by entry of
// RecordingEntries(source): directories are created, an image folder becomes a symbolic link to its
// canonical path (not entered), files are copied (or linked above kMaxCopiedFileBytes; a link is followed
// to the file it names). Entries whose relative path is in `skip` (generic form, e.g. "mav0/imu0/data.csv")
// are left out. Nothing else of `source` is read: no directory is walked.
RecordingCopyStats CopyRecordingTree(const std::filesystem::path& source, const std::filesystem::path& dest,
                                     const std::set<std::string>& skip);

}  // namespace vigil
