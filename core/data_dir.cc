#include "core/data_dir.h"

#include <cstdlib>
#include <filesystem>
#include <string_view>

namespace vigil {
namespace {

constexpr std::string_view kPrefix = "$VIGIL_DATA";

// The variable's value, or "" when it is unset.
std::string DataDir() {
  const char* value = std::getenv(kDataDirVariable);
  return value == nullptr ? "" : value;
}

}  // namespace

bool NamesDataDir(const std::string& path) {
  return path.compare(0, kPrefix.size(), kPrefix) == 0 &&
         (path.size() == kPrefix.size() || path[kPrefix.size()] == '/');
}

std::string ExpandDataDir(const std::string& path) {
  const std::string dir = DataDir();
  if (!NamesDataDir(path) || dir.empty()) return path;
  // A relative VIGIL_DATA is relative to the working directory, as the shell that set it meant.
  const std::string rest = path.size() > kPrefix.size() ? path.substr(kPrefix.size() + 1) : "";
  return (std::filesystem::absolute(dir) / rest).lexically_normal().string();
}

std::string ResolveInputPath(const std::filesystem::path& base_dir, const std::string& path) {
  const std::string expanded = ExpandDataDir(path);
  if (expanded.empty() || NamesDataDir(expanded) || std::filesystem::path(expanded).is_absolute())
    return expanded;
  return std::filesystem::absolute(base_dir / expanded).lexically_normal().string();
}

std::string UnsetDataDirReason(const std::string& path) {
  if (!NamesDataDir(path) || !DataDir().empty()) return "";
  return path +
         " names $VIGIL_DATA, which is not set: export VIGIL_DATA=the folder that holds your datasets "
         "(docs/datasets.md)";
}

}  // namespace vigil
