// A copy of a recording's directory tree that a command then edits (`vigil inject` replaces its IMU):
// image folders are linked, never copied; small files are copied; large ones are linked.
#pragma once

#include <cstdint>
#include <filesystem>
#include <set>
#include <string>

namespace vigil {

// Files above this size are linked instead of copied.
inline constexpr std::uintmax_t kMaxCopiedFileBytes = 16u << 20;  // 16 MiB

struct RecordingCopyStats {
  int copied_files = 0, linked_files = 0, linked_image_dirs = 0;
};

// Mirrors `source` into the existing directory `dest`: every directory is created, except an image folder
// (a `data/` directory inside a `cam*` directory of the EuRoC layout), which becomes a symbolic link to the
// source's absolute path; regular files are copied (or linked above kMaxCopiedFileBytes). Entries whose path
// relative to `source` is in `skip` (generic form, e.g. "mav0/imu0/data.csv") are left out, as is vigil's
// output manifest. Symbolic links in `source` are followed.
RecordingCopyStats CopyRecordingTree(const std::filesystem::path& source, const std::filesystem::path& dest,
                                     const std::set<std::string>& skip);

}  // namespace vigil
