// The user's data folder: a config path "$VIGIL_DATA/REST" names REST inside the folder that the environment
// variable VIGIL_DATA names (docs/datasets.md), so shipped configs can name a user's recordings without a
// path outside the repository.
#pragma once

#include <filesystem>
#include <string>

namespace vigil {

inline constexpr char kDataDirVariable[] = "VIGIL_DATA";

// Whether `path` is "$VIGIL_DATA" or starts with "$VIGIL_DATA/".
bool NamesDataDir(const std::string& path);

// `path` with "$VIGIL_DATA" replaced by the variable's value, made absolute (a relative value is relative to
// the working directory); unchanged when it names no data folder, or when VIGIL_DATA is unset or empty
// (UnsetDataDirReason then says why it cannot be used).
std::string ExpandDataDir(const std::string& path);

// An input path as a config names it, made usable from anywhere: "$VIGIL_DATA/..." expanded
// (ExpandDataDir), a relative path made absolute against `base_dir` (the config file's directory for a path
// read from a file, the working directory for a --set value). Empty and absolute paths, and a data-folder
// path while VIGIL_DATA is unset, are returned as they are.
std::string ResolveInputPath(const std::filesystem::path& base_dir, const std::string& path);

// "" when `path` can be used; else a one-line reason naming the variable (the caller adds file and key).
std::string UnsetDataDirReason(const std::string& path);

}  // namespace vigil
