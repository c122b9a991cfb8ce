#include "core/recording_copy.h"

#include "core/recording_files.h"

namespace vigil {
namespace fs = std::filesystem;

RecordingCopyStats CopyRecordingTree(const fs::path& source, const fs::path& dest,
                                     const std::set<std::string>& skip) {
  RecordingCopyStats stats;
  for (const RecordingEntry& entry : RecordingEntries(source)) {
    if (skip.count(entry.path)) continue;
    const fs::path from = source / entry.path, to = dest / entry.path;
    fs::create_directories(to.parent_path());
    switch (entry.kind) {
      case RecordingEntry::Kind::kDirectory:
        fs::create_directories(to);
        break;
      case RecordingEntry::Kind::kImageFolder:
        fs::create_directory_symlink(fs::canonical(from), to);
        ++stats.linked_image_dirs;
        break;
      case RecordingEntry::Kind::kFile:
        if (fs::file_size(from) > kMaxCopiedFileBytes) {
          fs::create_symlink(fs::canonical(from), to);
          ++stats.linked_files;
        } else {
          fs::copy_file(from, to);
          // A copy is the output's own file: writable by its owner whatever the source's mode.
          fs::permissions(to, fs::perms::owner_write, fs::perm_options::add);
          ++stats.copied_files;
        }
        break;
    }
  }
  stats.left_out = EntriesOutsideRecording(source);
  return stats;
}

}  // namespace vigil
