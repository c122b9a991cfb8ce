// Writing results without ever leaving half-written output or silently replacing what a user has.
//
// StagedDirectory: a command writes its output directory into a temporary sibling and renames it into place
// at the end; on an error (or an exception unwinding past it) the temporary is removed and nothing changes.
// WriteFileAtomic: one file, via a temporary file in the same directory and rename(2).
//
// Every output directory vigil creates holds a manifest, ".vigil-output": the line "vigil output directory"
// followed by one line per entry vigil wrote into it, "NAME<TAB>FINGERPRINT" (EntryFingerprint). `--force`
// replaces only a directory with a manifest, and only the entries it lists whose fingerprint still matches:
// whatever else is in it (files a user added, entries changed since, names a copied or hand-written manifest
// lists without the right fingerprint) is kept.
// RefuseOutputOverInputs: an output that is, contains or lies inside an input is refused, with or without
// --force (paths compared after resolving symbolic links, "..", and ".").
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace vigil {

// The manifest's file name and first line.
inline constexpr const char* kOutputManifest = ".vigil-output";
inline constexpr const char* kOutputManifestHeader = "vigil output directory";

// The entry names listed by `dir`'s manifest whose fingerprints still match; InputError when `dir` has none
// (or not a valid one): it was not written by vigil.
std::vector<std::string> ReadOutputManifest(const std::filesystem::path& dir);
// "KIND SIZE HASH" of one entry: a file's size and FNV-1a hash of its content, a directory's count and hash
// of its recursive listing (paths, types, file sizes), a symbolic link's target.
std::string EntryFingerprint(const std::filesystem::path& entry);
// Writes the manifest of `dir` listing its current top-level entries.
void WriteOutputManifest(const std::filesystem::path& dir);

// Refuses (InputError) `output` when it is empty, is one of `inputs`, contains one, or lies inside one (a
// directory). Missing inputs are ignored; `option` names the output in the message (e.g. "-o").
void RefuseOutputOverInputs(const std::filesystem::path& output,
                            const std::vector<std::filesystem::path>& inputs,
                            const std::string& option = "-o");

class StagedDirectory {
 public:
  // Refuses (InputError) an existing non-empty `final_dir` unless `force`, and even when forced one without a
  // manifest (not written by vigil); an existing file of that name is always refused. Creates the temporary
  // sibling "<final_dir>.tmp-<host>-<pid>" (core/staging.h), after removing the stale staging of `final_dir`
  // that dead processes of this host left.
  StagedDirectory(std::filesystem::path final_dir, bool force);
  ~StagedDirectory();
  StagedDirectory(const StagedDirectory&) = delete;
  StagedDirectory& operator=(const StagedDirectory&) = delete;

  // Where to write now.
  const std::filesystem::path& path() const { return staging_; }
  // Writes the manifest and moves the staged directory into place. When forced, the entries the old
  // directory's manifest listed are replaced and the others moved into the new directory (InputError, before
  // anything changes, when one of them has the name of a new entry).
  void Commit();

 private:
  std::filesystem::path final_;
  std::filesystem::path staging_;
  std::vector<std::string> foreign_;  // entries of the old directory vigil did not write
  bool committed_ = false;
};

// Writes `content` to `path` via "<path>.tmp-<host>-<pid>" + rename, then removes the stale staging of `path`
// (core/staging.h) that a killed earlier write left. Refuses (InputError) to replace anything
// that is not a regular file (a directory, a device such as /dev/null, a FIFO). Throws std::runtime_error on
// I/O failure.
void WriteFileAtomic(const std::filesystem::path& path, const std::string& content);

// Writes `content` to `path` unless a file of that name exists, atomically even against another process
// (on another machine sharing the filesystem) doing the same at once: the file appears complete or not at
// all, written by exactly one of them (link(2)). Returns false, writing nothing, when it already existed.
bool WriteFileIfAbsent(const std::filesystem::path& path, const std::string& content);

// Refuses (InputError) to replace an existing output file: always when it is not a regular file, and unless
// `force` and its content starts with `vigil_header` (a file vigil wrote) otherwise.
void RefuseReplacingFile(const std::filesystem::path& path, bool force, const std::string& vigil_header);

// Reads a whole regular file (a FIFO or device is refused, never waited on); InputError "path: cannot open
// for reading" if it cannot, "path: larger than N bytes" beyond `max_bytes`.
inline constexpr std::uintmax_t kMaxInputFileBytes = std::uintmax_t{1} << 30;  // 1 GiB
std::string ReadFile(const std::filesystem::path& path, std::uintmax_t max_bytes = kMaxInputFileBytes);
// A file's content and the name errors give it (its path, or e.g. "<fuzz input>" for text made in memory).
struct TextFile {
  std::string path;
  std::string text;
};
// ReadFile(path) with its path.
TextFile ReadTextFile(const std::string& path, std::uintmax_t max_bytes = kMaxInputFileBytes);

// InputError unless `path` is an existing regular file (after following symbolic links) of at most
// `max_bytes`: what every reader checks before opening a file.
void RequireRegularFile(const std::filesystem::path& path, std::uintmax_t max_bytes = kMaxInputFileBytes);

}  // namespace vigil
