#include "core/recording_copy.h"

#include "core/error.h"
#include "core/output.h"

namespace vigil {
namespace fs = std::filesystem;
namespace {

bool IsImageDir(const fs::path& relative) {
  const fs::path parent = relative.parent_path().filename();
  return relative.filename() == "data" && parent.string().rfind("cam", 0) == 0;
}

}  // namespace

RecordingCopyStats CopyRecordingTree(const fs::path& source, const fs::path& dest,
                                     const std::set<std::string>& skip) {
  RecordingCopyStats stats;
  const fs::path root = fs::canonical(source);
  for (auto it = fs::recursive_directory_iterator(root, fs::directory_options::follow_directory_symlink);
       it != fs::recursive_directory_iterator(); ++it) {
    const fs::path relative = it->path().lexically_relative(root);
    const fs::path target = dest / relative;
    if (skip.count(relative.generic_string()) || relative == kOutputManifest) {
      if (it->is_directory()) it.disable_recursion_pending();
      continue;
    }
    if (it->is_directory()) {
      if (IsImageDir(relative)) {
        fs::create_directory_symlink(fs::canonical(it->path()), target);
        ++stats.linked_image_dirs;
        it.disable_recursion_pending();
      } else {
        fs::create_directories(target);
      }
    } else if (it->is_regular_file()) {
      if (it->file_size() > kMaxCopiedFileBytes) {
        fs::create_symlink(fs::canonical(it->path()), target);
        ++stats.linked_files;
      } else {
        fs::copy_file(it->path(), target);
        // A copy is the output's own file: writable by its owner whatever the source's mode.
        fs::permissions(target, fs::perms::owner_write, fs::perm_options::add);
        ++stats.copied_files;
      }
    }
  }
  return stats;
}

}  // namespace vigil
