#include "core/reference_imu.h"

#include "core/dataset.h"
#include "core/error.h"
#include "core/euroc.h"

namespace vigil {

ReferenceImu ReadReferenceImu(const std::filesystem::path& path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  fs::path file;
  if (fs::is_directory(path, ec)) {
    const fs::path mav0 = FindMav0(path);
    for (const fs::path& candidate :
         {path / dataset_files::kImuClean, path / dataset_files::kImu,
          mav0.empty() ? fs::path() : mav0 / euroc_files::kImu / euroc_files::kData})
      if (!candidate.empty() && fs::is_regular_file(candidate, ec)) {
        file = candidate;
        break;
      }
    if (file.empty())
      throw InputError(
          path.string() +
          ": no IMU to calibrate on (expected imu_clean.csv or imu.csv of a vigil dataset, or a EuRoC "
          "folder with mav0/imu0/data.csv)");
  } else if (fs::exists(path, ec)) {
    file = path;
  } else {
    throw InputError(path.string() + ": no such file or directory");
  }
  return {ReadImuCsv(file.string()), file};
}

}  // namespace vigil
