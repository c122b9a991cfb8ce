#include "experiments/sweeps/sweep_lock.h"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "core/error.h"

namespace vigil::experiments {
namespace fs = std::filesystem;

SweepDirectoryLock::SweepDirectoryLock(const fs::path& dir, bool exclusive) {
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) throw InputError(dir.string() + ": cannot create output directory: " + ec.message());
  const fs::path file = dir / kSweepLockFile;
  fd_ = ::open(file.c_str(), O_RDWR | O_CREAT | O_CLOEXEC | O_NOFOLLOW, 0644);
  if (fd_ < 0)
    throw InputError(file.string() + ": cannot open the sweep's lock file: " + std::strerror(errno));
  int rc = 0;
  while ((rc = ::flock(fd_, (exclusive ? LOCK_EX : LOCK_SH) | LOCK_NB)) != 0 && errno == EINTR) {
  }
  if (rc == 0) return;
  const int why = errno;
  ::close(fd_);
  if (why == EWOULDBLOCK)
    throw InputError(dir.string() + ": another vigil sweep is writing into this directory (it holds " +
                     file.string() +
                     "); wait until it ends, or choose another output (only the shards of one sweep may "
                     "share a directory)");
  throw InputError(file.string() + ": cannot lock: " + std::strerror(why));
}

SweepDirectoryLock::~SweepDirectoryLock() { ::close(fd_); }

}  // namespace vigil::experiments
