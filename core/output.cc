#include "core/output.h"

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>
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

void RefuseExisting(const fs::path& dir, bool force) {
  std::error_code ec;
  if (fs::exists(dir, ec) && !fs::is_directory(dir, ec))
    throw InputError(dir.string() + ": exists and is not a directory");
  if (!force && IsNonEmptyDirectory(dir))
    throw InputError(dir.string() + ": output directory is not empty (use --force to replace it)");
}
}  // namespace

StagedDirectory::StagedDirectory(fs::path final_dir, bool force) : final_(std::move(final_dir)) {
  if (final_.has_filename() == false) final_ = final_.parent_path();  // "out/" -> "out"
  RefuseExisting(final_, force);
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
  std::error_code ec;
  if (fs::exists(final_, ec)) {
    // Only reached when forced, or when the directory is empty: move the old one aside first, so that a
    // failure below leaves it in place.
    fs::path old = final_;
    old += ".old" + StagingSuffix();
    fs::rename(final_, old);
    fs::rename(staging_, final_);
    fs::remove_all(old, ec);
  } else {
    fs::rename(staging_, final_);
  }
  committed_ = true;
}

void PrepareOutputDirectory(const fs::path& dir, bool force) {
  RefuseExisting(dir, force);
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) throw InputError(dir.string() + ": cannot create output directory: " + ec.message());
}

void WriteFileAtomic(const fs::path& path, const std::string& content) {
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if (fs::exists(status) && !fs::is_regular_file(status))
    throw InputError(path.string() + ": exists and is not a regular file; refusing to replace it");
  const fs::path tmp = StagingPathFor(path);
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) throw std::runtime_error(tmp.string() + ": cannot open for writing");
    out.write(content.data(), static_cast<std::streamsize>(content.size()));
    out.flush();
    if (!out) throw std::runtime_error(tmp.string() + ": write failed");
  }
  fs::rename(tmp, path);
  // A killed earlier write of the same file left its staging: removed now (dead processes of this host only).
  RemoveStaleStaging(path.has_parent_path() ? path.parent_path() : fs::path("."), path.filename().string());
}

bool WriteFileIfAbsent(const fs::path& path, const std::string& content) {
  std::error_code ec;
  if (fs::exists(path, ec)) return false;
  const fs::path tmp = StagingPathFor(path);
  WriteFileAtomic(tmp, content);
  const int linked = ::link(tmp.c_str(), path.c_str());
  const int link_errno = errno;
  fs::remove(tmp, ec);
  if (linked == 0) return true;
  if (link_errno == EEXIST) return false;
  throw std::runtime_error(path.string() + ": cannot create: " + std::strerror(link_errno));
}

std::string ReadFile(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path.string() + ": cannot open for reading");
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace vigil
