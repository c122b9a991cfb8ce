#include "core/staging.h"

#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <climits>
#include <system_error>
#include <vector>

namespace vigil {
namespace fs = std::filesystem;
namespace {
constexpr const char* kMarker = ".tmp-";

bool IsDigits(const std::string& s) {
  return !s.empty() && s.size() <= 18 &&
         std::all_of(s.begin(), s.end(), [](char c) { return c >= '0' && c <= '9'; });
}
}  // namespace

const std::string& StagingHost() {
  static const std::string host = [] {
    char buf[HOST_NAME_MAX + 1] = {};
    std::string h = ::gethostname(buf, sizeof buf - 1) == 0 ? std::string(buf) : std::string();
    for (char& c : h)
      if (!((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '.' ||
            c == '_' || c == '-'))
        c = '_';
    return h.empty() ? std::string("localhost") : h;
  }();
  return host;
}

std::string StagingSuffix() {
  return kMarker + StagingHost() + "-" + std::to_string(static_cast<long>(::getpid()));
}

fs::path StagingPathFor(const fs::path& final_path) {
  fs::path p = final_path;
  p += StagingSuffix();
  return p;
}

std::optional<StagingName> ParseStagingName(const std::string& file_name) {
  const std::size_t marker = file_name.rfind(kMarker);
  if (marker == std::string::npos || marker == 0) return std::nullopt;
  const std::string rest = file_name.substr(marker + std::char_traits<char>::length(kMarker));
  const std::size_t dash = rest.rfind('-');
  if (dash == std::string::npos || dash == 0) return std::nullopt;
  const std::string pid = rest.substr(dash + 1);
  if (!IsDigits(pid)) return std::nullopt;
  StagingName name;
  name.final_name = file_name.substr(0, marker);
  name.host = rest.substr(0, dash);
  name.pid = std::stol(pid);
  return name;
}

bool ProcessExists(long pid) {
  if (pid <= 0 || pid > INT_MAX) return false;
  return ::kill(static_cast<pid_t>(pid), 0) == 0 || errno == EPERM;
}

bool IsStaleStaging(const std::string& file_name) {
  const std::optional<StagingName> name = ParseStagingName(file_name);
  return name && name->host == StagingHost() && !ProcessExists(name->pid);
}

std::size_t RemoveStaleStaging(const fs::path& dir, const std::string& final_name) {
  std::error_code ec;
  std::vector<fs::path> stale;
  for (const auto& entry : fs::directory_iterator(dir, ec)) {
    const std::string file = entry.path().filename().string();
    if (!IsStaleStaging(file)) continue;
    if (!final_name.empty() && ParseStagingName(file)->final_name != final_name) continue;
    stale.push_back(entry.path());
  }
  std::size_t removed = 0;
  for (const auto& p : stale)
    if (fs::remove_all(p, ec) > 0 && !ec) ++removed;
  return removed;
}

}  // namespace vigil
