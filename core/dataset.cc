#include "core/dataset.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>

#include <yaml-cpp/yaml.h>

#include "core/config.h"
#include "core/csv.h"
#include "core/error.h"
#include "core/format.h"
#include "core/output.h"

namespace vigil {
namespace fs = std::filesystem;
namespace {

constexpr const char* kImuHeader =
    "timestamp [ns],w_RS_S_x [rad s^-1],w_RS_S_y [rad s^-1],w_RS_S_z [rad s^-1],a_RS_S_x [m s^-2],"
    "a_RS_S_y [m s^-2],a_RS_S_z [m s^-2]";
constexpr const char* kGroundTruthHeader =
    "timestamp [ns],p_RS_R_x [m],p_RS_R_y [m],p_RS_R_z [m],q_RS_w [],q_RS_x [],q_RS_y [],q_RS_z [],"
    "v_RS_R_x [m s^-1],v_RS_R_y [m s^-1],v_RS_R_z [m s^-1],b_w_RS_S_x [rad s^-1],b_w_RS_S_y [rad s^-1],"
    "b_w_RS_S_z [rad s^-1],b_a_RS_S_x [m s^-2],b_a_RS_S_y [m s^-2],b_a_RS_S_z [m s^-2]";

// Enforces strictly increasing timestamps while reading.
void CheckIncreasing(const CsvReader& r, int64_t t_ns, int64_t* last, bool allow_equal = false) {
  if (*last != INT64_MIN && (allow_equal ? t_ns < *last : t_ns <= *last))
    r.Fail("timestamp " + std::to_string(t_ns) + " does not increase (previous " + std::to_string(*last) +
           ")");
  *last = t_ns;
}

void CheckNotEmpty(const CsvReader& r, std::size_t n) {
  if (n == 0) r.Fail("no data rows");
}

// A quaternion that is unit to double precision is kept bit for bit (what vigil wrote reads back unchanged,
// so a run on a written dataset equals the run on the simulation); a slightly denormalized one (rounded text)
// is renormalized.
Eigen::Quaterniond AsUnit(const Eigen::Quaterniond& q) {
  return std::abs(q.squaredNorm() - 1.0) <= 8 * std::numeric_limits<double>::epsilon() ? q : q.normalized();
}

Eigen::Quaterniond ReadUnitQuaternion(const CsvReader& r, double w, double x, double y, double z) {
  const Eigen::Quaterniond q(w, x, y, z);
  if (std::abs(q.norm() - 1.0) > 1e-3) r.Fail("quaternion is not unit (norm " + FormatDouble(q.norm()) + ")");
  return AsUnit(q);
}

}  // namespace

std::vector<GlitchRecord> OffsetGlitches(const std::vector<GlitchRecord>& records) {
  std::vector<GlitchRecord> out;
  out.reserve(records.size());
  for (const GlitchRecord& g : records)
    if (g.kind == FaultKind::kOffset) out.push_back(g);
  return out;
}

std::string ImuCsv(const ImuStream& imu) {
  CsvWriter w(kImuHeader);
  for (const auto& s : imu) {
    w << s.t_ns;
    for (int i = 0; i < kNumImuAxes; ++i) w << s.axis(i);
    w.EndRow();
  }
  return w.Str();
}

ImuStream ReadImuCsv(const std::string& path) {
  CsvReader r(path, 7, "EuRoC imu0 layout: timestamp [ns], w_x, w_y, w_z, a_x, a_y, a_z");
  ImuStream imu;
  int64_t last = INT64_MIN;
  while (r.Next()) {
    ImuSample s;
    s.t_ns = r.Int(0);
    // Equal timestamps are accepted: consumer IMUs stamp two samples alike now and then (the estimator
    // keeps the first of them); a timestamp going backwards is an error.
    CheckIncreasing(r, s.t_ns, &last, /*allow_equal=*/true);
    for (int i = 0; i < kNumImuAxes; ++i) s.axis(i) = r.Double(1 + i);
    imu.push_back(s);
  }
  CheckNotEmpty(r, imu.size());
  return imu;
}

std::string GlitchesCsv(const std::vector<GlitchRecord>& glitches) {
  CsvWriter w("timestamp [ns],axis,offset,kind");
  for (const auto& g : glitches) {
    w << g.t_ns << (IsTimingFault(g.kind) ? "t" : ImuAxisName(g.axis)) << g.offset << FaultKindName(g.kind);
    w.EndRow();
  }
  return w.Str();
}

namespace {

// Columns of the header line of `path` (0 when it cannot be read: CsvReader then reports the problem).
std::size_t HeaderColumns(const std::string& path) {
  std::ifstream in(path);
  std::string header;
  if (!std::getline(in, header)) return 0;
  return static_cast<std::size_t>(std::count(header.begin(), header.end(), ',')) + 1;
}

}  // namespace

std::vector<GlitchRecord> ReadGlitchesCsv(const std::string& path) {
  // The three-column form (before fault kinds) holds offsets only.
  const bool with_kind = HeaderColumns(path) != 3;
  CsvReader r(path, with_kind ? 4 : 3,
              with_kind ? "timestamp [ns], axis, offset, kind" : "timestamp [ns], axis, offset");
  std::vector<GlitchRecord> out;
  int64_t last = INT64_MIN;
  while (r.Next()) {
    GlitchRecord g;
    g.t_ns = r.Int(0);
    if (with_kind && !ParseFaultKind(std::string(r.Text(3)), &g.kind))
      r.Fail("kind: expected one of offset, saturation, drop, duplicate, jitter, got '" +
             std::string(r.Text(3)) + "'");
    CheckIncreasing(r, g.t_ns, &last, /*allow_equal=*/true);
    if (IsTimingFault(g.kind)) {
      if (r.Text(1) != "t") r.Fail("axis: expected 't' for the timing fault kind " + std::string(r.Text(3)));
    } else if (!ParseImuAxis(std::string(r.Text(1)), &g.axis)) {
      r.Fail("axis: expected one of wx, wy, wz, ax, ay, az, got '" + std::string(r.Text(1)) + "'");
    }
    g.offset = r.Double(2);
    out.push_back(g);
  }
  return out;
}

std::string GroundTruthCsv(const std::vector<NavState>& states) {
  CsvWriter w(kGroundTruthHeader);
  for (const auto& s : states) {
    w << s.t_ns << s.p_W.x() << s.p_W.y() << s.p_W.z() << s.q_WB.w() << s.q_WB.x() << s.q_WB.y() << s.q_WB.z()
      << s.v_W.x() << s.v_W.y() << s.v_W.z() << s.b_g.x() << s.b_g.y() << s.b_g.z() << s.b_a.x() << s.b_a.y()
      << s.b_a.z();
    w.EndRow();
  }
  return w.Str();
}

std::vector<NavState> ReadGroundTruthCsv(const std::string& path) {
  CsvReader r(path, 17, "EuRoC state_groundtruth_estimate0 layout");
  std::vector<NavState> out;
  int64_t last = INT64_MIN;
  while (r.Next()) {
    NavState s;
    s.t_ns = r.Int(0);
    // Equal timestamps are accepted: consumer IMUs stamp two samples alike now and then (the estimator
    // keeps the first of them); a timestamp going backwards is an error.
    CheckIncreasing(r, s.t_ns, &last, /*allow_equal=*/true);
    s.p_W = Eigen::Vector3d(r.Double(1), r.Double(2), r.Double(3));
    s.q_WB = ReadUnitQuaternion(r, r.Double(4), r.Double(5), r.Double(6), r.Double(7));
    s.v_W = Eigen::Vector3d(r.Double(8), r.Double(9), r.Double(10));
    s.b_g = Eigen::Vector3d(r.Double(11), r.Double(12), r.Double(13));
    s.b_a = Eigen::Vector3d(r.Double(14), r.Double(15), r.Double(16));
    out.push_back(s);
  }
  CheckNotEmpty(r, out.size());
  return out;
}

std::string LandmarksCsv(const std::vector<Landmark>& landmarks) {
  CsvWriter w("id,x [m],y [m],z [m]");
  for (const auto& l : landmarks) {
    w << l.id << l.p_W.x() << l.p_W.y() << l.p_W.z();
    w.EndRow();
  }
  return w.Str();
}

std::vector<Landmark> ReadLandmarksCsv(const std::string& path) {
  CsvReader r(path, 4, "id, x [m], y [m], z [m]");
  std::vector<Landmark> out;
  while (r.Next()) {
    Landmark l;
    l.id = static_cast<int>(r.Int(0));
    l.p_W = Eigen::Vector3d(r.Double(1), r.Double(2), r.Double(3));
    out.push_back(l);
  }
  return out;
}

std::string FeaturesCsv(const std::vector<CameraFrame>& frames) {
  CsvWriter w("timestamp [ns],id,u [px],v [px]");
  for (const auto& f : frames) {
    for (const auto& o : f.features) {
      w << f.t_ns << o.id << o.uv_px.x() << o.uv_px.y();
      w.EndRow();
    }
  }
  return w.Str();
}

std::vector<CameraFrame> ReadFeaturesCsv(const std::string& path,
                                         const std::vector<int64_t>& frame_times_ns) {
  CsvReader r(path, 4, "timestamp [ns], id, u [px], v [px]");
  std::vector<CameraFrame> frames;
  std::size_t next_time = 0;
  auto add_empty_until = [&](int64_t t_ns) {  // frames without observations, before t_ns
    while (next_time < frame_times_ns.size() && frame_times_ns[next_time] < t_ns)
      frames.push_back({frame_times_ns[next_time++], {}});
    if (next_time < frame_times_ns.size() && frame_times_ns[next_time] == t_ns) ++next_time;
  };
  int64_t last = INT64_MIN;
  while (r.Next()) {
    const int64_t t_ns = r.Int(0);
    CheckIncreasing(r, t_ns, &last, /*allow_equal=*/true);
    if (frames.empty() || frames.back().t_ns != t_ns) {
      add_empty_until(t_ns);
      frames.push_back({t_ns, {}});
    }
    FeatureObservation o;
    o.id = static_cast<int>(r.Int(1));
    o.uv_px = Eigen::Vector2d(r.Double(2), r.Double(3));
    frames.back().features.push_back(o);
  }
  add_empty_until(INT64_MAX);
  return frames;
}

std::string CameraYaml(const CameraModel& camera) {
  CameraModel copy = camera;
  return config::ToYaml(copy);
}

CameraModel ReadCameraYaml(const std::string& path) {
  CameraModel camera;
  config::LoadFile(path, camera);
  const std::string why = camera.Validate();
  if (!why.empty()) throw InputError(path + ": " + why);
  return camera;
}

std::vector<int64_t> CameraFrameTimes(double rate_hz, int64_t t_first_ns, int64_t t_last_ns) {
  std::vector<int64_t> times;
  const double period_ns = 1e9 / rate_hz;
  for (int64_t k = 0;; ++k) {
    const int64_t t = t_first_ns + static_cast<int64_t>(std::llround(static_cast<double>(k) * period_ns));
    if (t > t_last_ns) break;
    times.push_back(t);
  }
  return times;
}

void WriteDataset(const fs::path& dir, const Dataset& d) {
  using namespace dataset_files;
  WriteFileAtomic(dir / kImu, ImuCsv(d.imu));
  WriteFileAtomic(dir / kImuClean, ImuCsv(d.imu_clean));
  WriteFileAtomic(dir / kGlitches, GlitchesCsv(d.glitches));
  WriteFileAtomic(dir / kGroundTruth, GroundTruthCsv(d.groundtruth));
  WriteFileAtomic(dir / kLandmarks, LandmarksCsv(d.landmarks));
  WriteFileAtomic(dir / kFeatures, FeaturesCsv(d.frames));
  WriteFileAtomic(dir / kCamera, CameraYaml(d.camera));
}

Dataset ReadDataset(const fs::path& dir) {
  using namespace dataset_files;
  if (!fs::is_directory(dir)) throw InputError(dir.string() + ": not a dataset directory");
  Dataset d;
  d.imu = ReadImuCsv((dir / kImu).string());
  if (fs::exists(dir / kImuClean)) d.imu_clean = ReadImuCsv((dir / kImuClean).string());
  if (fs::exists(dir / kGlitches)) d.glitches = ReadGlitchesCsv((dir / kGlitches).string());
  d.groundtruth = ReadGroundTruthCsv((dir / kGroundTruth).string());
  d.landmarks = ReadLandmarksCsv((dir / kLandmarks).string());
  d.camera = ReadCameraYaml((dir / kCamera).string());
  // Camera frame times: every 1/rate_hz from the first IMU sample, within the IMU time span.
  const std::vector<int64_t> frame_times =
      CameraFrameTimes(d.camera.rate_hz, d.imu.front().t_ns, d.imu.back().t_ns);
  d.frames = ReadFeaturesCsv((dir / kFeatures).string(), frame_times);
  return d;
}

std::string TumTrajectory(const Trajectory& trajectory) {
  std::string s = "# timestamp tx ty tz qx qy qz qw\n";
  for (const auto& p : trajectory) {
    // Seconds with 9 decimals, from integer nanoseconds so no rounding happens.
    const int64_t sec = p.t_ns / 1000000000, ns = p.t_ns % 1000000000;
    char t[40];
    std::snprintf(t, sizeof(t), "%lld.%09lld", static_cast<long long>(sec), static_cast<long long>(ns));
    s += t;
    for (double v : {p.p_W.x(), p.p_W.y(), p.p_W.z(), p.q_WB.x(), p.q_WB.y(), p.q_WB.z(), p.q_WB.w()})
      s += " " + FormatDouble(v);
    s += "\n";
  }
  return s;
}

Trajectory ReadTumTrajectory(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError(path + ": cannot open for reading");
  Trajectory out;
  std::string row;
  int line = 0;
  int64_t last = INT64_MIN;
  while (std::getline(in, row)) {
    ++line;
    if (!row.empty() && row.back() == '\r') row.pop_back();
    const auto first = row.find_first_not_of(" \t");
    if (first == std::string::npos || row[first] == '#') continue;
    std::istringstream fields(row);
    std::vector<double> v;
    std::string tok;
    while (fields >> tok) {
      double x = 0.0;
      if (!ParseDouble(tok, &x))
        throw InputError(Located(path, line, "expected a finite number, got '" + tok + "'"));
      v.push_back(x);
    }
    if (v.size() != 8)
      throw InputError(
          Located(path, line,
                  "expected 8 columns (timestamp tx ty tz qx qy qz qw), found " + std::to_string(v.size())));
    StampedPose p;
    p.t_ns = SToNs(v[0]);
    if (last != INT64_MIN && p.t_ns <= last)
      throw InputError(Located(path, line, "timestamp does not increase"));
    last = p.t_ns;
    p.p_W = Eigen::Vector3d(v[1], v[2], v[3]);
    const Eigen::Quaterniond q(v[7], v[4], v[5], v[6]);
    if (std::abs(q.norm() - 1.0) > 1e-3) throw InputError(Located(path, line, "quaternion is not unit"));
    p.q_WB = AsUnit(q);
    out.push_back(p);
  }
  if (out.empty()) throw InputError(path + ": no poses");
  return out;
}

}  // namespace vigil
