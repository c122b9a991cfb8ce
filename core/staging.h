// Names of staging entries (a directory or file being written, renamed into place when complete) and the
// rule for removing the ones a killed process left behind.
//
// A staging name is "<name>.tmp-<host>-<pid>": the final name, the host that writes it and that process' id.
// Several processes, on one machine or on several machines sharing a filesystem (sweep shards), may write
// into one directory at the same time: the host and pid keep their names apart, and tell which leftovers are
// stale. An entry is stale only when it was written on THIS host by a process that no longer exists; the
// staging of a live process, or of any process on another host (whose liveness cannot be seen from here), is
// never stale. Names without a host (older versions: "<name>.tmp-<pid>") are never stale either.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

namespace vigil {

struct StagingName {
  std::string final_name;  // "<name>"
  std::string host;
  long pid = 0;
};

// This host's name as used in staging names (characters other than [A-Za-z0-9._-] replaced by '_').
const std::string& StagingHost();

// ".tmp-<host>-<pid>" of this process.
std::string StagingSuffix();

// "<final>.tmp-<host>-<pid>" of this process, beside `final_path`.
std::filesystem::path StagingPathFor(const std::filesystem::path& final_path);

// Parses a file name; nullopt when it is not a staging name with a host.
std::optional<StagingName> ParseStagingName(const std::string& file_name);

// Whether a process with this id exists on this host (a zombie counts as existing).
bool ProcessExists(long pid);

// True when `file_name` is a staging name of a dead process on this host.
bool IsStaleStaging(const std::string& file_name);

// Removes the stale staging entries (files or directories) directly inside `dir`; with `final_name`
// non-empty, only those staging that name. Returns how many were removed. Errors are ignored (nothing to
// clean is not a failure).
std::size_t RemoveStaleStaging(const std::filesystem::path& dir, const std::string& final_name = "");

}  // namespace vigil
