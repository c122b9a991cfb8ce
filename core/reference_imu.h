// A glitch-free IMU stream named by the user as a calibration reference (detector bounds, DTW templates) for
// work on a recording, where no simulation of "the same scenario" exists.
#pragma once

#include <filesystem>
#include <string>

#include "core/types.h"

namespace vigil {

struct ReferenceImu {
  ImuStream imu;
  std::filesystem::path file;  // the CSV it was read from
};

// `path` is a dataset directory (its imu_clean.csv when present, else its imu.csv), a EuRoC folder (the one
// holding mav0/, or mav0/ itself: mav0/imu0/data.csv) or an IMU CSV file. InputError naming the path when it
// is none of these, and the readers' "file:line: reason" on a bad file.
ReferenceImu ReadReferenceImu(const std::filesystem::path& path);

}  // namespace vigil
