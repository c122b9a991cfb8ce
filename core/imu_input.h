// Where an IMU stream given on the command line is (`vigil templates` / `vigil clean` DATASET): a dataset
// directory (vigil's, or a EuRoC folder) or the path of an EuRoC imu0 CSV file.
#pragma once

#include <filesystem>
#include <string>

namespace vigil {

struct ImuInput {
  std::filesystem::path imu;  // the CSV to read
  std::filesystem::path dir;  // where imu_clean.csv and glitches.csv may sit beside it
};

// For a directory: `file_in_dir` inside it, else a EuRoC folder's mav0/imu0/data.csv (InputError if neither).
// For a file: the file itself.
ImuInput ResolveImuInput(const std::string& dataset, const std::string& file_in_dir);

}  // namespace vigil
