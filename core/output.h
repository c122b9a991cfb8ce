// Writing results without ever leaving half-written output or silently replacing what a user has.
//
// StagedDirectory: a command writes its output directory into a temporary sibling and renames it into place
// at the end; on an error (or an exception unwinding past it) the temporary is removed and nothing changes.
// WriteFileAtomic: one file, via a temporary file in the same directory and rename(2).
#pragma once

#include <filesystem>
#include <string>

namespace vigil {

class StagedDirectory {
 public:
  // Refuses (InputError) an existing non-empty `final_dir` unless `force`; an existing file of that name is
  // always refused. Creates the temporary sibling "<final_dir>.tmp-<host>-<pid>" (core/staging.h), after
  // removing the stale staging of `final_dir` that dead processes of this host left.
  StagedDirectory(std::filesystem::path final_dir, bool force);
  ~StagedDirectory();
  StagedDirectory(const StagedDirectory&) = delete;
  StagedDirectory& operator=(const StagedDirectory&) = delete;

  // Where to write now.
  const std::filesystem::path& path() const { return staging_; }
  // Moves the staged directory into place (replacing the old one when forced).
  void Commit();

 private:
  std::filesystem::path final_;
  std::filesystem::path staging_;
  bool committed_ = false;
};

// Refuses (InputError) a non-empty existing directory unless `force`; otherwise creates it if missing.
void PrepareOutputDirectory(const std::filesystem::path& dir, bool force);

// Writes `content` to `path` via "<path>.tmp-<host>-<pid>" + rename, then removes the stale staging of `path`
// (core/staging.h) that a killed earlier write left. Refuses (InputError) to replace anything
// that is not a regular file (a directory, a device such as /dev/null, a FIFO). Throws std::runtime_error on
// I/O failure.
void WriteFileAtomic(const std::filesystem::path& path, const std::string& content);

// Writes `content` to `path` unless a file of that name exists, atomically even against another process
// (on another machine sharing the filesystem) doing the same at once: the file appears complete or not at
// all, written by exactly one of them (link(2)). Returns false, writing nothing, when it already existed.
bool WriteFileIfAbsent(const std::filesystem::path& path, const std::string& content);

// Reads a whole file; InputError "path: cannot open for reading" if it cannot.
std::string ReadFile(const std::filesystem::path& path);

}  // namespace vigil
