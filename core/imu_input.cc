#include "core/imu_input.h"

#include "core/error.h"
#include "core/euroc.h"

namespace vigil {

ImuInput ResolveImuInput(const std::string& dataset, const std::string& file_in_dir) {
  namespace fs = std::filesystem;
  const fs::path path(dataset);
  std::error_code ec;
  if (fs::is_directory(path, ec)) {
    const fs::path file = path / file_in_dir;
    if (fs::exists(file, ec)) return {file, path};
    // A EuRoC folder (the one holding mav0/, or mav0/ itself): its imu0/data.csv.
    const fs::path mav0 = FindMav0(path);
    const fs::path euroc_imu = mav0 / euroc_files::kImu / euroc_files::kData;
    // imu_clean.csv and glitches.csv sit beside mav0/ (where vigil inject writes them, core/euroc.h).
    if (!mav0.empty() && fs::exists(euroc_imu, ec)) {
      const fs::path m = fs::absolute(mav0).lexically_normal();
      return {euroc_imu, (m.has_filename() ? m : m.parent_path()).parent_path()};
    }
    throw InputError(file.string() +
                     ": not found (expected a dataset directory: vigil's, or a EuRoC folder with "
                     "mav0/imu0/data.csv)");
  }
  if (!fs::exists(path, ec)) throw InputError(dataset + ": no such file or directory");
  return {path, path.parent_path().empty() ? fs::path(".") : path.parent_path()};
}

}  // namespace vigil
