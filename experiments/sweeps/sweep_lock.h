// A sweep's hold on its output directory, so that two sweeps never write into one directory at once (one
// would remove or overwrite the other's runs, or die half-way with "cannot open for writing").
//
// The lock is flock(2) on DIR/.vigil-sweep-lock, an empty file vigil creates and leaves in place: a whole
// sweep holds it alone, the shards of one sweep (which may run at once, core/staging.h) share it. The kernel
// releases it when the holder ends, however it ends (kill -9 included), so a stale lock never blocks a
// --resume.
#pragma once

#include <filesystem>

namespace vigil::experiments {

inline constexpr const char* kSweepLockFile = ".vigil-sweep-lock";

class SweepDirectoryLock {
 public:
  // Creates `dir` (and the lock file) when absent and takes the lock, exclusive or shared, without waiting:
  // InputError "DIR: another vigil sweep is writing into this directory ..." when another sweep holds it.
  SweepDirectoryLock(const std::filesystem::path& dir, bool exclusive);
  ~SweepDirectoryLock();
  SweepDirectoryLock(const SweepDirectoryLock&) = delete;
  SweepDirectoryLock& operator=(const SweepDirectoryLock&) = delete;

 private:
  int fd_ = -1;
};

}  // namespace vigil::experiments
