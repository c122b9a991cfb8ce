#include "sim/landmarks.h"

#include <algorithm>
#include <array>

#include "core/random.h"

namespace vigil::sim {

std::vector<Landmark> HouseLandmarks() {
  // 18 distinct vertices of a 10 m cube house inside the ellipse: body, roof ridge, door, window.
  // clang-format off
  static const std::array<Eigen::Vector3d, 18> kVertices = {{
      {0, 0, 0},  {10, 0, 0},  {10, 10, 0},  {0, 10, 0},   // floor corners
      {0, 0, 10}, {10, 0, 10}, {10, 10, 10}, {0, 10, 10},  // eaves corners
      {5, 0, 14}, {5, 10, 14},                             // roof ridge (gable ends on y = 0 and y = 10)
      {10, 4, 0}, {10, 6, 0},  {10, 6, 4},   {10, 4, 4},   // door on the x = 10 face
      {3, 10, 5}, {7, 10, 5},  {7, 10, 8},   {3, 10, 8},   // window on the y = 10 face
  }};
  // clang-format on
  const Eigen::Vector3d shift(0.5, 0.5, -0.5);
  std::vector<Landmark> out;
  out.reserve(2 * kVertices.size());
  for (const auto& p : kVertices) out.push_back({static_cast<int>(out.size()), p});
  for (const auto& p : kVertices) out.push_back({static_cast<int>(out.size()), p + shift});
  return out;
}

WallRoom RoomAround(const std::vector<Eigen::Vector3d>& path_W, double margin_m, double height_m) {
  Eigen::Vector3d lo = path_W.front(), hi = path_W.front();
  for (const auto& p : path_W) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  return {lo.x() - margin_m, hi.x() + margin_m,       lo.y() - margin_m,
          hi.y() + margin_m, lo.z() - 0.5 * height_m, hi.z() + 0.5 * height_m};
}

std::vector<Landmark> RandomWallLandmarks(int count, const std::vector<Eigen::Vector3d>& path_W,
                                          double margin_m, double height_m, uint64_t seed, int first_id) {
  std::vector<Landmark> out;
  if (count <= 0 || path_W.empty()) return out;
  const WallRoom room = RoomAround(path_W, margin_m, height_m);
  const double x0 = room.x0, x1 = room.x1, y0 = room.y0, y1 = room.y1, z0 = room.z0, z1 = room.z1;
  const double wx = x1 - x0, wy = y1 - y0;
  Rng rng(seed, "landmarks");
  out.reserve(static_cast<std::size_t>(count));
  for (int i = 0; i < count; ++i) {
    // Arc position along the room's perimeter, counter-clockwise from (x0, y0).
    double s = rng.Uniform(0.0, 2.0 * (wx + wy));
    const double z = rng.Uniform(z0, z1);
    Eigen::Vector3d p;
    if (s < wx) {
      p = {x0 + s, y0, z};
    } else if ((s -= wx) < wy) {
      p = {x1, y0 + s, z};
    } else if ((s -= wy) < wx) {
      p = {x1 - s, y1, z};
    } else {
      s -= wx;
      p = {x0, y1 - std::min(s, wy), z};
    }
    out.push_back({first_id + i, p});
  }
  return out;
}

std::vector<Landmark> MakeLandmarks(const LandmarkOptions& options,
                                    const std::vector<Eigen::Vector3d>& path_W, uint64_t seed) {
  std::vector<Landmark> out;
  if (options.layout != LandmarkLayout::kRandom) out = HouseLandmarks();
  if (options.layout != LandmarkLayout::kHouse) {
    const auto random = RandomWallLandmarks(options.random_count, path_W, options.random_margin_m,
                                            options.random_height_m, seed, static_cast<int>(out.size()));
    out.insert(out.end(), random.begin(), random.end());
  }
  return out;
}

}  // namespace vigil::sim
