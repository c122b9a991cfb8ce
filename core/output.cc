#include "core/output.h"

#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <set>
#include <sstream>
#include <system_error>

#include "core/error.h"
#include "core/staging.h"

namespace vigil {
namespace fs = std::filesystem;
namespace {
bool IsNonEmptyDirectory(const fs::path& dir) {
  std::error_code ec;
  return fs::is_directory(dir, ec) && !fs::is_empty(dir, ec);
}

// `path` with symbolic links, "." and ".." resolved (as far as it exists), absolute.
fs::path Resolved(const fs::path& path) {
  std::error_code ec;
  fs::path p = fs::weakly_canonical(fs::absolute(path, ec), ec);
  if (ec) p = fs::absolute(path, ec).lexically_normal();
  if (!p.has_filename()) p = p.parent_path();  // "out/" -> "out"
  return p;
}

// Whether `inner` is `outer` or lies inside it (both resolved).
bool IsWithin(const fs::path& inner, const fs::path& outer) {
  auto o = outer.begin(), i = inner.begin();
  for (; o != outer.end(); ++o, ++i)
    if (i == inner.end() || *i != *o) return false;
  return true;
}

std::vector<std::string> EntryNames(const fs::path& dir) {
  std::vector<std::string> names;
  for (const fs::directory_entry& e : fs::directory_iterator(dir))
    names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

void RefuseExisting(const fs::path& dir, bool force) {
  std::error_code ec;
  if (fs::exists(dir, ec) && !fs::is_directory(dir, ec))
    throw InputError(dir.string() + ": exists and is not a directory");
  if (!force && IsNonEmptyDirectory(dir))
    throw InputError(dir.string() +
                     ": output directory is not empty (use --force to replace a directory vigil wrote)");
}
}  // namespace

std::string EntryFingerprint(const fs::path& entry) {
  // FNV-1a, 64 bits: not a defence against a forger (who can compute any hash), a check that an entry is
  // still the one vigil wrote (docs/safety.md, "The output manifest").
  uint64_t hash = 14695981039346656037ull;
  auto mix = [&](const char* data, std::size_t n) {
    for (std::size_t i = 0; i < n; ++i)
      hash = (hash ^ static_cast<unsigned char>(data[i])) * 1099511628211ull;
  };
  std::error_code ec;
  const fs::file_status status = fs::symlink_status(entry, ec);
  std::string kind;
  uintmax_t size = 0;
  if (fs::is_symlink(status)) {
    kind = "link";
    const std::string target = fs::read_symlink(entry, ec).string();
    mix(target.data(), target.size());
    size = target.size();
  } else if (fs::is_regular_file(status)) {
    kind = "file";
    std::ifstream in(entry, std::ios::binary);
    char buf[1 << 16];
    while (in.read(buf, sizeof buf) || in.gcount() > 0) {
      mix(buf, static_cast<std::size_t>(in.gcount()));
      size += static_cast<uintmax_t>(in.gcount());
    }
  } else if (fs::is_directory(status)) {
    // A directory's fingerprint is its listing (every path below it, its type and file size), not the
    // content: enough to see a directory swapped or changed, without reading a dataset's images again.
    kind = "dir";
    std::vector<std::string> lines;
    for (auto it = fs::recursive_directory_iterator(entry, ec);
         !ec && it != fs::recursive_directory_iterator(); it.increment(ec)) {
      const fs::file_status s = it->symlink_status(ec);
      std::string line = it->path().lexically_relative(entry).string();
      line += fs::is_regular_file(s) ? " f " + std::to_string(it->file_size(ec))
              : fs::is_directory(s)  ? " d"
                                     : " o";
      lines.push_back(std::move(line));
    }
    std::sort(lines.begin(), lines.end());
    for (const std::string& line : lines) mix(line.c_str(), line.size() + 1);
    size = lines.size();
  } else {
    return "other";
  }
  char text[64];
  std::snprintf(text, sizeof text, "%s %ju %016jx", kind.c_str(), size, static_cast<uintmax_t>(hash));
  return text;
}

std::vector<std::string> ReadOutputManifest(const fs::path& dir) {
  const fs::path manifest = dir / kOutputManifest;
  std::error_code ec;
  if (!fs::is_regular_file(manifest, ec))
    throw InputError(dir.string() + ": not written by vigil (no " + kOutputManifest +
                     "), so --force does not replace it; move it away or choose another output");
  std::istringstream in(ReadFile(manifest, 1 << 20));
  std::string line;
  if (!std::getline(in, line) || line != kOutputManifestHeader)
    throw InputError(Located(manifest.string(), 1,
                             std::string("expected '") + kOutputManifestHeader +
                                 "': not a vigil manifest, so --force does not replace " + dir.string()));
  // "NAME<TAB>FINGERPRINT": only a plain entry name of `dir` whose fingerprint still matches counts as
  // vigil's; any other line (no fingerprint, a path, a changed entry) leaves its entry to the user.
  std::vector<std::string> names;
  while (std::getline(in, line)) {
    const std::size_t tab = line.find('\t');
    if (tab == std::string::npos || tab == 0) continue;
    const std::string name = line.substr(0, tab);
    if (name == "." || name == ".." || name == kOutputManifest || name.find('/') != std::string::npos)
      continue;
    if (EntryFingerprint(dir / name) == line.substr(tab + 1)) names.push_back(name);
  }
  return names;
}

void WriteOutputManifest(const fs::path& dir) {
  std::string text = std::string(kOutputManifestHeader) + "\n";
  for (const std::string& name : EntryNames(dir))
    if (name != kOutputManifest && name.find_first_of("\t\n") == std::string::npos)
      text += name + "\t" + EntryFingerprint(dir / name) + "\n";
  WriteFileAtomic(dir / kOutputManifest, text);
}

void RefuseOutputOverInputs(const fs::path& output, const std::vector<fs::path>& inputs,
                            const std::string& option) {
  if (output.empty()) throw InputError(option + ": the output path is empty (name a directory to write)");
  const fs::path out = Resolved(output);
  std::error_code ec;
  for (const fs::path& input : inputs) {
    if (input.empty() || !fs::exists(input, ec)) continue;
    const fs::path in = Resolved(input);
    std::string relation;
    if (in == out)
      relation = "is the input ";
    else if (IsWithin(in, out))
      relation = "contains the input ";
    else if (IsWithin(out, in))
      relation = "lies inside the input ";
    else
      continue;
    // An input reached through a link (a recording's image folder linked elsewhere) is named with its target.
    fs::path plain = fs::absolute(input, ec).lexically_normal();
    if (!plain.has_filename()) plain = plain.parent_path();
    const std::string target = in == plain ? "" : " (" + in.string() + ")";
    throw InputError(option + " " + output.string() + ": the output " + relation + input.string() + target +
                     ", which it would overwrite; choose an output outside every input");
  }
}

StagedDirectory::StagedDirectory(fs::path final_dir, bool force) : final_(std::move(final_dir)) {
  if (final_.empty()) throw InputError("-o: the output path is empty (name a directory to write)");
  if (final_.has_filename() == false) final_ = final_.parent_path();  // "out/" -> "out"
  RefuseExisting(final_, force);
  if (IsNonEmptyDirectory(final_)) {
    const std::vector<std::string> listed = ReadOutputManifest(final_);
    const std::set<std::string> mine(listed.begin(), listed.end());
    for (const std::string& name : EntryNames(final_))
      if (name != kOutputManifest && !mine.count(name)) foreign_.push_back(name);
  }
  staging_ = StagingPathFor(final_);
  std::error_code ec;
  fs::remove_all(staging_, ec);
  if (!final_.parent_path().empty()) fs::create_directories(final_.parent_path(), ec);
  RemoveStaleStaging(final_.parent_path().empty() ? fs::path(".") : final_.parent_path(),
                     final_.filename().string());
  if (!fs::create_directory(staging_, ec) || ec)
    throw InputError(staging_.string() + ": cannot create output directory: " + ec.message());
}

StagedDirectory::~StagedDirectory() {
  if (!committed_) {
    std::error_code ec;
    fs::remove_all(staging_, ec);
  }
}

void StagedDirectory::Commit() {
  WriteOutputManifest(staging_);
  std::error_code ec;
  for (const std::string& name : foreign_)
    if (fs::exists(staging_ / name, ec) || fs::is_symlink(staging_ / name, ec))
      throw InputError((final_ / name).string() +
                       ": not written by vigil and in the way of the new output; move it away and run again");
  if (fs::exists(final_, ec)) {
    // Only reached when forced, or when the directory is empty: move the old one aside first, so that a
    // failure below leaves it in place; then the user's own entries move into the new directory.
    fs::path old = final_;
    old += ".old" + StagingSuffix();
    fs::rename(final_, old);
    fs::rename(staging_, final_);
    committed_ = true;
    for (const std::string& name : foreign_) {
      fs::rename(old / name, final_ / name, ec);
      if (ec)
        throw std::runtime_error((old / name).string() + ": cannot move back into " + final_.string() + ": " +
                                 ec.message() + " (the old directory is kept at " + old.string() + ")");
    }
    fs::remove_all(old, ec);
  } else {
    fs::rename(staging_, final_);
  }
  committed_ = true;
}

void RefuseReplacingFile(const fs::path& path, bool force, const std::string& vigil_header) {
  std::error_code ec;
  const fs::file_status status = fs::symlink_status(path, ec);
  if (!fs::exists(status)) return;
  if (!fs::is_regular_file(fs::status(path, ec)))
    throw InputError(path.string() + ": exists and is not a regular file; refusing to replace it");
  if (!force) throw InputError(path.string() + ": exists (use --force to replace a file vigil wrote)");
  std::ifstream in(path, std::ios::binary);
  std::string head(vigil_header.size(), '\0');
  in.read(head.data(), static_cast<std::streamsize>(head.size()));
  if (!in || head != vigil_header)
    throw InputError(path.string() + ": not a file vigil wrote (it does not start with '" + vigil_header +
                     "'), so --force does not replace it; move it away or choose another output");
}

namespace {

// Writes `content` into a new file at `path` (truncating a leftover of the same name).
void WriteWholeFile(const fs::path& path, const std::string& content) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  if (!out) throw std::runtime_error(path.string() + ": cannot open for writing");
  out.write(content.data(), static_cast<std::streamsize>(content.size()));
  out.flush();
  if (!out) throw std::runtime_error(path.string() + ": write failed");
}

}  // namespace

void WriteFileAtomic(const fs::path& path, const std::string& content) {
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if (fs::exists(status) && !fs::is_regular_file(status))
    throw InputError(path.string() + ": exists and is not a regular file; refusing to replace it");
  const fs::path tmp = StagingPathFor(path);
  WriteWholeFile(tmp, content);
  fs::rename(tmp, path);
  // A killed earlier write of the same file left its staging: removed now (dead processes of this host only).
  RemoveStaleStaging(path.has_parent_path() ? path.parent_path() : fs::path("."), path.filename().string());
}

bool WriteFileIfAbsent(const fs::path& path, const std::string& content) {
  std::error_code ec;
  if (fs::exists(path, ec)) return false;
  // Staged once, under this process' staging name, then linked into place: link(2) fails when the name
  // exists, so of several processes creating the file at once exactly one succeeds.
  const fs::path tmp = StagingPathFor(path);
  WriteWholeFile(tmp, content);
  const int linked = ::link(tmp.c_str(), path.c_str());
  const int link_errno = errno;
  fs::remove(tmp, ec);
  if (linked == 0) return true;
  if (link_errno == EEXIST) return false;
  throw std::runtime_error(path.string() + ": cannot create: " + std::strerror(link_errno));
}

void RequireRegularFile(const fs::path& path, std::uintmax_t max_bytes) {
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if (!fs::exists(status)) throw InputError(path.string() + ": cannot open for reading: no such file");
  if (fs::is_directory(status)) throw InputError(path.string() + ": is a directory; expected a file");
  if (!fs::is_regular_file(status))
    throw InputError(path.string() + ": not a regular file (a FIFO, socket or device); expected a file");
  const std::uintmax_t size = fs::file_size(path, ec);
  if (!ec && size > max_bytes)
    throw InputError(path.string() + ": " + std::to_string(size) + " bytes, larger than the limit of " +
                     std::to_string(max_bytes) + " bytes for an input file");
}

std::string ReadFile(const fs::path& path, std::uintmax_t max_bytes) {
  RequireRegularFile(path, max_bytes);
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path.string() + ": cannot open for reading");
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

TextFile ReadTextFile(const std::string& path, std::uintmax_t max_bytes) {
  return {path, ReadFile(path, max_bytes)};
}

}  // namespace vigil
