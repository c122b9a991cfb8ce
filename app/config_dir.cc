#include "app/config_dir.h"

#include <system_error>

#include "core/error.h"

namespace vigil::app {
namespace fs = std::filesystem;

namespace {

bool SameDirectory(const fs::path& a, const fs::path& b) {
  std::error_code ec;
  return fs::equivalent(a, b, ec);
}

}  // namespace

fs::path ConfigDirectoryOf(const fs::path& executable) {
  const fs::path bin = executable.parent_path();
  std::error_code ec;
  const fs::path installed = (bin / VIGIL_INSTALLED_CONFIG_DIR_FROM_BIN).lexically_normal();
  if (fs::is_directory(installed, ec)) return installed;
  if (SameDirectory(bin, VIGIL_BUILD_DIR) && fs::is_directory(VIGIL_SOURCE_CONFIG_DIR, ec))
    return VIGIL_SOURCE_CONFIG_DIR;
  return {};
}

std::string ShippedConfig(const std::string& name) {
  std::error_code ec;
  const fs::path executable = fs::read_symlink("/proc/self/exe", ec);
  const fs::path dir = ec ? fs::path() : ConfigDirectoryOf(executable);
  if (dir.empty() || !fs::is_regular_file(dir / name, ec))
    throw InputError(
        name + ": not found beside the binary (" +
        (executable.parent_path() / VIGIL_INSTALLED_CONFIG_DIR_FROM_BIN).lexically_normal().string() +
        "; install vigil with cmake --install, or name the file with --sweep FILE)");
  return (dir / name).string();
}

}  // namespace vigil::app
