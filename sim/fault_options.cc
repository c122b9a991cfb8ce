#include "sim/fault_options.h"

#include <cmath>
#include <utility>

#include "core/format.h"

namespace vigil::sim {
namespace {

constexpr double kDegToRad = M_PI / 180.0;

}  // namespace

double AccelRangeMps2(const SaturationOptions& options, double gravity_mps2) {
  switch (options.preset) {
    case SaturationPreset::kLowCost4g:
      return 4.0 * gravity_mps2;
    case SaturationPreset::kLowCost16g:
      return 16.0 * gravity_mps2;
    case SaturationPreset::kNone:
      break;
  }
  return options.accel_range_mps2 > 0.0 ? options.accel_range_mps2 : options.accel_range_g * gravity_mps2;
}

double GyroRangeRadps(const SaturationOptions& options) {
  if (options.preset != SaturationPreset::kNone) return 2000.0 * kDegToRad;
  return options.gyro_range_dps * kDegToRad;
}

std::string ValidateFaultOptions(const FaultOptions& options, double gravity_mps2) {
  const SaturationOptions& s = options.saturation;
  const bool custom = s.accel_range_mps2 > 0.0 || s.accel_range_g > 0.0 || s.gyro_range_dps > 0.0;
  if (s.preset != SaturationPreset::kNone && custom)
    return "saturation.preset: a preset sets the ranges; leave accel_range_mps2, accel_range_g and "
           "gyro_range_dps at 0";
  if (s.accel_range_mps2 > 0.0 && s.accel_range_g > 0.0)
    return "saturation.accel_range_g: set either accel_range_mps2 or accel_range_g, not both";
  const double accel_range = AccelRangeMps2(s, gravity_mps2);
  if (accel_range > 0.0 && accel_range <= gravity_mps2)
    return std::string(s.accel_range_g > 0.0 ? "saturation.accel_range_g" : "saturation.accel_range_mps2") +
           ": range " + FormatDouble(accel_range) + " m/s^2 must exceed gravity (" +
           FormatDouble(gravity_mps2) + " m/s^2): a sensor at rest would read saturated";
  // A resolution below 1e-6 (m/s^2 or deg/s) would only round in the last digits of a double, and far
  // below it the quantized values overflow: 0 (off) or at least that.
  const QuantizationOptions& q = options.quantization;
  if (q.accel_lsb_mps2 > 0.0 && q.accel_lsb_mps2 < kMinQuantizationLsb)
    return "quantization.accel_lsb_mps2: 0 (no quantization) or at least 1e-06 m/s^2";
  if (q.gyro_lsb_dps > 0.0 && q.gyro_lsb_dps < kMinQuantizationLsb)
    return "quantization.gyro_lsb_dps: 0 (no quantization) or at least 1e-06 deg/s";
  const ScaleMisalignmentOptions& m = options.scale;  // each value is bounded with its key
  const std::pair<const char*, const std::vector<double>*> vectors[] = {
      {"accel_scale", &m.accel_scale},
      {"gyro_scale", &m.gyro_scale},
      {"accel_misalignment_deg", &m.accel_misalignment_deg},
      {"gyro_misalignment_deg", &m.gyro_misalignment_deg}};
  for (const auto& [name, values] : vectors)
    if (values->size() != 3) return std::string("scale.") + name + ": expected 3 numbers (x, y, z)";
  return "";
}

}  // namespace vigil::sim
