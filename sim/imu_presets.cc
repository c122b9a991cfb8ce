#include "sim/imu_presets.h"

namespace vigil::sim {
namespace {

constexpr double kPresetDegToRad = 3.14159265358979323846 / 180.0;
constexpr double kPresetG = 9.80665;  // standard gravity, for datasheet figures in g [m/s^2]

struct PresetFigures {
  double gyro_noise_density;        // [rad/s/sqrt(Hz)]
  double accel_noise_density;       // [m/s^2/sqrt(Hz)]
  double gyro_bias_random_walk;     // [rad/s^2/sqrt(Hz)]
  double accel_bias_random_walk;    // [m/s^3/sqrt(Hz)]
  double switch_on_gyro_bias_std;   // [rad/s]
  double switch_on_accel_bias_std;  // [m/s^2]
};

// Datasheets give no bias random walk for the consumer parts: vigil's defaults (1e-5, 1e-4) are kept there.
PresetFigures FiguresOf(ImuPreset preset) {
  switch (preset) {
    case ImuPreset::kAdis16448:  // EuRoC imu0/sensor.yaml; switch-on spread from V1_01's ground-truth biases
      return {1.6968e-4, 2.0e-3, 1.9393e-5, 3.0e-3, 0.05, 0.05};
    case ImuPreset::kBmi088:  // Bosch BMI088 datasheet: 0.014 deg/s/sqrt(Hz), 175 ug/sqrt(Hz), +-1 deg/s,
                              // +-20 mg
      return {0.014 * kPresetDegToRad, 175e-6 * kPresetG, 1e-5, 1e-4,
              1.0 * kPresetDegToRad,   20e-3 * kPresetG};
    case ImuPreset::kMpu6050:  // InvenSense PS-MPU-6000A-00: 0.005 deg/s/sqrt(Hz), 400 ug/sqrt(Hz), +-20
                               // deg/s,
                               // +-50 mg (x, y; z +-80 mg)
      return {0.005 * kPresetDegToRad, 400e-6 * kPresetG, 1e-5, 1e-4,
              20.0 * kPresetDegToRad,  50e-3 * kPresetG};
    case ImuPreset::kNone:
      break;
  }
  return {};
}

}  // namespace

void ApplyImuPreset(ImuPreset preset, ImuOptions* imu) {
  if (preset == ImuPreset::kNone) return;
  const PresetFigures f = FiguresOf(preset);
  ImuNoiseOptions& n = imu->noise;
  n.enabled = true;
  n.gyro_noise_density = f.gyro_noise_density;
  n.accel_noise_density = f.accel_noise_density;
  n.gyro_bias_random_walk = f.gyro_bias_random_walk;
  n.accel_bias_random_walk = f.accel_bias_random_walk;
  n.switch_on_gyro_bias_std = f.switch_on_gyro_bias_std;
  n.switch_on_accel_bias_std = f.switch_on_accel_bias_std;
}

}  // namespace vigil::sim
