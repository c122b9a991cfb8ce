// vigil-openvins: OpenVINS's MSCKF (ov_msckf) on a recording vigil writes for an external estimator, fed
// with the recording's feature tracks and IMU through OpenVINS's C++ API; writes the IMU trajectory as TUM.
//
//   vigil-openvins RECORDING TRAJECTORY [--init openvins|groundtruth] [--gravity M_S2] [--pixel-sigma PX]
//                  [--verbosity LEVEL]
//
// Exit status: 0 a trajectory was written, 1 OpenVINS never initialized (no trajectory), 2 bad arguments or
// input (one line naming the file), 3 an internal error.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>

#include "core/VioManagerOptions.h"
#include "recording.h"
#include "settings.h"
#include "track_fed_vio.h"
#include "utils/opencv_yaml_parse.h"
#include "utils/print.h"
#include "utils/quat_ops.h"
#include "utils/sensor_data.h"

namespace vigil_openvins {
namespace fs = std::filesystem;
namespace {

constexpr const char* kUsage =
    "usage: vigil-openvins RECORDING TRAJECTORY [--init openvins|groundtruth] [--gravity M_S2] "
    "[--pixel-sigma PX] [--verbosity ALL|DEBUG|INFO|WARNING|ERROR|SILENT]";

struct Arguments {
  fs::path recording, trajectory;
  Settings settings;
};

double PositiveNumber(const std::string& flag, const std::string& text) {
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if (text.empty() || *end != '\0' || !std::isfinite(value) || value <= 0.0)
    throw InputError(flag + ": '" + text + "' is not a positive number");
  return value;
}

Arguments ParseArguments(int argc, char** argv) {
  Arguments a;
  std::vector<std::string> positional;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg.rfind("--", 0) != 0) {
      positional.push_back(arg);
      continue;
    }
    if (i + 1 >= argc) throw InputError(arg + ": needs a value\n" + kUsage);
    const std::string value = argv[++i];
    if (arg == "--init") {
      if (value == "openvins")
        a.settings.init = InitMode::kOpenvins;
      else if (value == "groundtruth")
        a.settings.init = InitMode::kGroundtruth;
      else
        throw InputError("--init: '" + value + "' is not one of openvins, groundtruth");
    } else if (arg == "--gravity") {
      a.settings.gravity_mps2 = PositiveNumber(arg, value);
    } else if (arg == "--pixel-sigma") {
      a.settings.pixel_sigma_px = PositiveNumber(arg, value);
    } else if (arg == "--verbosity") {
      a.settings.verbosity = value;
    } else {
      throw InputError(arg + ": unknown option\n" + kUsage);
    }
  }
  if (positional.size() != 2) throw InputError(kUsage);
  a.recording = positional[0];
  a.trajectory = positional[1];
  return a;
}

// "S.NNNNNNNNN" from integer nanoseconds, exactly.
std::string Seconds(int64_t t_ns) {
  char text[40];
  const char* sign = t_ns < 0 ? "-" : "";
  const int64_t magnitude = t_ns < 0 ? -t_ns : t_ns;
  std::snprintf(text, sizeof text, "%s%lld.%09lld", sign, static_cast<long long>(magnitude / 1000000000),
                static_cast<long long>(magnitude % 1000000000));
  return text;
}

// The ground-truth row a ground-truth start takes: the last one before the first frame with tracks.
const GroundTruth* StartRow(const Recording& r) {
  const GroundTruth* start = nullptr;
  for (const FrameTracks& frame : r.tracks) {
    for (const GroundTruth& g : r.groundtruth)
      if (g.t_ns < frame.t_ns) start = &g;
    if (start) return start;
  }
  return nullptr;
}

int Run(const Arguments& a) {
  const Recording r = ReadRecording(a.recording);
  if (fs::exists(a.trajectory)) throw InputError(a.trajectory.string() + ": exists (refusing to overwrite)");
  const fs::path out_dir = a.trajectory.parent_path().empty() ? fs::path(".") : a.trajectory.parent_path();
  const fs::path config_dir = out_dir / "openvins_config";
  if (fs::exists(config_dir)) throw InputError(config_dir.string() + ": exists (refusing to overwrite)");
  const GroundTruth* start = nullptr;
  if (a.settings.init == InitMode::kGroundtruth) {
    start = StartRow(r);
    if (!start)
      throw InputError(
          a.recording.string() +
          ": --init groundtruth needs mav0/state_groundtruth_estimate0/data.csv with a row before "
          "the first frame with tracks");
  }

  ov_core::Printer::setPrintLevel(a.settings.verbosity);
  const fs::path config = WriteOpenvinsConfig(config_dir, a.settings, r);
  auto parser = std::make_shared<ov_core::YamlParser>(config.string());
  ov_msckf::VioManagerOptions options;
  options.print_and_load(parser);
  if (!parser->successful())
    throw std::runtime_error(config.string() + ": OpenVINS did not read every setting");
  TrackFedVio vio(options);

  // OpenVINS works in seconds as doubles: times are fed relative to the first IMU sample (exact to the
  // nanosecond over any recording length) and written back as the recording's integer nanoseconds.
  const int64_t t0_ns = r.imu.front().t_ns;
  const auto seconds = [t0_ns](int64_t t_ns) { return static_cast<double>(t_ns - t0_ns) * 1e-9; };
  size_t next_imu = 0;
  const auto feed_imu_until = [&](int64_t t_ns) {  // every sample up to t, and one past it
    while (next_imu < r.imu.size() && r.imu[next_imu].t_ns <= t_ns) {
      const ImuSample& s = r.imu[next_imu++];
      vio.feed_measurement_imu({seconds(s.t_ns), s.w_B, s.a_B});
    }
    if (next_imu < r.imu.size()) {
      const ImuSample& s = r.imu[next_imu++];
      vio.feed_measurement_imu({seconds(s.t_ns), s.w_B, s.a_B});
    }
  };

  if (start) {
    // OpenVINS's IMU state: [t, q_GtoI (JPL, x y z w), p_IinG, v_IinG, b_gyro, b_accel].
    Eigen::Matrix<double, 17, 1> imu_state;
    imu_state(0) = seconds(start->t_ns);
    imu_state.segment<4>(1) = ov_core::rot_2_quat(start->q_WB.toRotationMatrix().transpose());
    imu_state.segment<3>(5) = start->p_WB;
    imu_state.segment<3>(8) = start->v_WB;
    imu_state.segment<3>(11) = start->b_gyro;
    imu_state.segment<3>(14) = start->b_accel;
    feed_imu_until(start->t_ns);
    vio.initialize_with_gt(imu_state);
  }

  std::ostringstream rows;
  rows << "# vigil-openvins: OpenVINS (ov_msckf) on " << a.recording.string() << ", init "
       << (start ? "groundtruth" : "openvins") << "\n# timestamp [s] x y z qx qy qz qw\n";
  rows.precision(9);
  rows << std::fixed;
  size_t written = 0;
  int64_t last_ns = 0;
  for (const FrameTracks& frame : r.tracks) {
    if (start && frame.t_ns <= start->t_ns) continue;
    feed_imu_until(frame.t_ns);
    std::vector<std::pair<size_t, Eigen::VectorXf>> uv;
    uv.reserve(frame.uv.size());
    for (const auto& [id, px] : frame.uv) uv.emplace_back(OpenvinsFeatureId(id), px.cast<float>());
    vio.FeedTracks(seconds(frame.t_ns), uv);
    if (!vio.initialized()) continue;
    const int64_t t_ns = t0_ns + std::llround(vio.state_time_s() * 1e9);
    if (written > 0 && t_ns <= last_ns) continue;  // no update at this frame: the state did not move on
    const Eigen::Vector3d p = vio.p_WB();
    const Eigen::Quaterniond q = vio.q_WB();
    if (!p.allFinite() || !q.coeffs().allFinite()) {
      std::cerr << "vigil-openvins: the state became non-finite at t = " << Seconds(t_ns)
                << " s; the trajectory stops there\n";
      break;
    }
    rows << Seconds(t_ns) << ' ' << p.x() << ' ' << p.y() << ' ' << p.z() << ' ' << q.x() << ' ' << q.y()
         << ' ' << q.z() << ' ' << q.w() << '\n';
    last_ns = t_ns;
    ++written;
  }
  if (written == 0) {
    std::cerr << "vigil-openvins: OpenVINS did not initialize over the " << r.tracks.size()
              << " frames with tracks (no trajectory written)\n";
    return 1;
  }
  // Written beside the trajectory and renamed onto it: never half a file.
  const fs::path partial = a.trajectory.string() + ".partial";
  {
    std::ofstream out(partial);
    out << rows.str();
    if (!out.flush()) throw std::runtime_error(partial.string() + ": cannot write");
  }
  fs::rename(partial, a.trajectory);
  std::cerr << "vigil-openvins: " << written << " poses of " << r.tracks.size() << " frames written to "
            << a.trajectory.string() << "\n";
  return 0;
}

}  // namespace
}  // namespace vigil_openvins

int main(int argc, char** argv) {
  using namespace vigil_openvins;
  try {
    return Run(ParseArguments(argc, argv));
  } catch (const InputError& e) {
    std::cerr << "vigil-openvins: error: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "vigil-openvins: internal error: " << e.what() << "\n";
    return 3;
  }
}
