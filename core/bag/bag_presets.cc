#include "core/bag/bag_presets.h"

#include <vector>

#include "core/error.h"

namespace vigil::bag {
namespace {

BagPreset Euroc() {
  BagPreset p{"euroc",
              "/imu0",
              "/cam0/image_raw",
              "/vicon/firefly_sbx/firefly_sbx",
              "VI-Sensor IMU (ADIS16448), EuRoC's published noise model",
              {},
              {},
              "VI-Sensor cam0 (MT9M034), EuRoC's published calibration",
              ""};
  p.imu.rate_hz = 200.0;
  p.imu.gyroscope_noise_density = 1.6968e-4;
  p.imu.gyroscope_random_walk = 1.9393e-5;
  p.imu.accelerometer_noise_density = 2.0e-3;
  p.imu.accelerometer_random_walk = 3.0e-3;
  CameraModel c;
  c.rate_hz = 20.0;
  c.width = 752;
  c.height = 480;
  c.fx = 458.654;
  c.fy = 457.296;
  c.cx = 367.215;
  c.cy = 248.375;
  c.distortion = {-0.28340811, 0.07395907, 0.00019359, 1.76187114e-05};
  c.T_BC = {0.0148655429818,
            -0.999880929698,
            0.00414029679422,
            -0.0216401454975,  //
            0.999557249008,
            0.0149672133247,
            0.025715529948,
            -0.064676986768,  //
            -0.0257744366974,
            0.00375618835797,
            0.999660727178,
            0.00981073058949,  //
            0.0,
            0.0,
            0.0,
            1.0};
  p.camera = c;
  return p;
}

BagPreset TumVi() {
  BagPreset p{
      "tumvi",
      "/imu0",
      "/cam0/image_raw",
      "/vrpn_client/raw_transform",
      "BMI160, TUM-VI's published noise model",
      {},
      std::nullopt,
      "",
      "TUM-VI's cameras are fisheye lenses calibrated with the equidistant model, which vigil's pinhole "
      "camera cannot describe"};
  p.imu.rate_hz = 200.0;
  p.imu.gyroscope_noise_density = 0.00016;
  p.imu.gyroscope_random_walk = 0.000022;
  p.imu.accelerometer_noise_density = 0.0028;
  p.imu.accelerometer_random_walk = 0.00086;
  return p;
}

const std::vector<BagPreset>& Presets() {
  static const std::vector<BagPreset> presets = {Euroc(), TumVi()};
  return presets;
}

}  // namespace

std::string BagPresetNames() {
  std::string names;
  for (const BagPreset& p : Presets()) names += (names.empty() ? "" : ", ") + std::string(p.name);
  return names;
}

const BagPreset& FindBagPreset(const std::string& name) {
  for (const BagPreset& p : Presets())
    if (name == p.name) return p;
  throw InputError("--preset: '" + name + "' is not a preset (" + BagPresetNames() + ")");
}

}  // namespace vigil::bag
