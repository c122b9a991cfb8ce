// Deterministic, platform-independent random numbers.
//
// Every random draw in vigil comes from an Rng built from (run seed, purpose): each purpose ("imu_noise",
// "glitch", "pixels", ...) gets its own independent stream, so changing how one stream is used never changes
// another. The generator (xoshiro256**) and the distributions are implemented here, not taken from <random>,
// whose distributions differ between standard libraries: the same seed gives the same numbers everywhere.
#pragma once

#include <array>
#include <cstdint>
#include <string_view>

#include <Eigen/Core>

namespace vigil {

class Rng {
 public:
  Rng(uint64_t seed, std::string_view purpose);

  uint64_t NextU64();
  // Uniform in [0, 1).
  double Uniform();
  // Uniform in [lo, hi).
  double Uniform(double lo, double hi) { return lo + (hi - lo) * Uniform(); }
  // Uniform integer in [0, n).
  uint64_t UniformIndex(uint64_t n);
  // Standard normal N(0, 1) (Marsaglia polar method).
  double Normal();
  double Normal(double mean, double std) { return mean + std * Normal(); }
  // Three standard normal draws as (x, y, z), drawn in that order. Use this rather than
  // Vector3d(Normal(), Normal(), Normal()): the order of evaluation of function arguments is unspecified, so
  // that expression would make the stream depend on the compiler.
  Eigen::Vector3d NormalVector3() {
    const double x = Normal(), y = Normal(), z = Normal();
    return Eigen::Vector3d(x, y, z);
  }
  // True with probability p.
  bool Bernoulli(double p) { return Uniform() < p; }

 private:
  std::array<uint64_t, 4> s_{};
  bool has_spare_ = false;
  double spare_ = 0.0;
};

// A 64-bit hash of (seed, purpose) used to derive sub-seeds (e.g. a run seed from a sweep cell).
uint64_t DeriveSeed(uint64_t seed, std::string_view purpose);

}  // namespace vigil
