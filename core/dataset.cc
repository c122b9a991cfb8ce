#include "core/dataset.h"
#include "core/ground_truth_gap.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <set>
#include <sstream>

#include <yaml-cpp/yaml.h>

#include "core/config.h"
#include "core/csv.h"
#include "core/error.h"
#include "core/format.h"
#include "core/output.h"
#include "core/pose_checks.h"

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

// Column `c` of the current row, a number of magnitude at most `limit`.
double Bounded(const CsvReader& r, std::size_t c, double limit) {
  const double v = r.Double(c);
  if (std::abs(v) > limit)
    r.Fail(r.header_column(c) + ": " + FormatDouble(v) + " is beyond the limit of +-" + FormatDouble(limit));
  return v;
}

// Column `c`, an id: an integer in 0 .. INT32_MAX.
int Id(const CsvReader& r, std::size_t c) {
  const int64_t id = r.Int(c);
  if (id < 0 || id > std::numeric_limits<int>::max())
    r.Fail(r.header_column(c) + ": " + std::to_string(id) + " is not an id (expected 0 .. 2147483647)");
  return static_cast<int>(id);
}

// A quaternion that is unit to double precision is kept bit for bit (what vigil wrote reads back unchanged,
// so a run on a written dataset equals the run on the simulation); a slightly denormalized one (rounded text)
// is renormalized.
Eigen::Quaterniond AsUnit(const Eigen::Quaterniond& q) {
  return std::abs(q.squaredNorm() - 1.0) <= 8 * std::numeric_limits<double>::epsilon() ? q : q.normalized();
}

Eigen::Quaterniond ReadUnitQuaternion(const CsvReader& r, double w, double x, double y, double z) {
  const Eigen::Quaterniond q(w, x, y, z);
  if (const std::string problem = QuaternionNormProblem(q); !problem.empty()) r.Fail(problem);
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

std::string ImuCsv(const ImuStream& imu, const std::string& file) {
  CsvWriter w(kImuHeader, file);
  for (const auto& s : imu) {
    w << s.t_ns;
    for (int i = 0; i < kNumImuAxes; ++i) w << s.axis(i);
    w.EndRow();
  }
  return w.Str();
}

ImuStream ReadImuCsv(const std::string& path) { return ReadImuCsv(ReadTextFile(path)); }

void CheckCleanImuMatches(const ImuStream& imu, const ImuStream& clean, const std::string& imu_path,
                          const std::string& clean_path) {
  const std::string fix =
      ": imu_clean.csv holds the glitch-free value of every imu.csv sample; regenerate "
      "both together or remove imu_clean.csv";
  if (clean.size() != imu.size())
    throw InputError(clean_path + ": " + std::to_string(clean.size()) + " samples, but " + imu_path +
                     " has " + std::to_string(imu.size()) + fix);
  for (std::size_t t = 0; t < imu.size(); ++t)
    if (clean[t].t_ns != imu[t].t_ns)
      throw InputError(Located(clean_path, static_cast<int>(t) + 2,
                               "timestamp " + std::to_string(clean[t].t_ns) + " differs from " + imu_path +
                                   "'s " + std::to_string(imu[t].t_ns) + fix));
}

ImuStream ReadImuCsv(const TextFile& file) {
  CsvReader r(file, 7, "EuRoC imu0 layout: timestamp [ns], w_x, w_y, w_z, a_x, a_y, a_z");
  ImuStream imu;
  int64_t last = INT64_MIN;
  while (r.Next()) {
    ImuSample s;
    s.t_ns = r.Int(0);
    // Equal timestamps are accepted: consumer IMUs stamp two samples alike now and then (the estimator
    // keeps the first of them); a timestamp going backwards is an error.
    // (unsigned difference: no overflow between far-apart timestamps)
    const uint64_t gap_ns = static_cast<uint64_t>(s.t_ns) - static_cast<uint64_t>(last);
    if (last != INT64_MIN && s.t_ns > last && gap_ns > static_cast<uint64_t>(kMaxImuGap_ns))
      r.Fail("timestamp " + std::to_string(s.t_ns) + ": " + FormatDouble(static_cast<double>(gap_ns) * 1e-9) +
             " s after the previous sample, beyond the limit of " + FormatDouble(NsToS(kMaxImuGap_ns)) +
             " s");
    CheckIncreasing(r, s.t_ns, &last, /*allow_equal=*/true);
    for (int i = 0; i < kNumImuAxes; ++i) s.axis(i) = Bounded(r, 1 + i, kMaxAbsImuValue);
    imu.push_back(s);
  }
  CheckNotEmpty(r, imu.size());
  return imu;
}

std::string GlitchesCsv(const std::vector<GlitchRecord>& glitches, const std::string& file) {
  CsvWriter w("timestamp [ns],axis,offset,kind", file);
  for (const auto& g : glitches) {
    w << g.t_ns << (IsTimingFault(g.kind) ? "t" : ImuAxisName(g.axis)) << g.offset << FaultKindName(g.kind);
    w.EndRow();
  }
  return w.Str();
}

namespace {

// Columns of the header line of `text` (its first line; CsvReader reports a missing or wrong header).
std::size_t HeaderColumns(const std::string& text) {
  const std::string header = text.substr(0, text.find('\n'));
  return static_cast<std::size_t>(std::count(header.begin(), header.end(), ',')) + 1;
}

}  // namespace

std::vector<GlitchRecord> ReadGlitchesCsv(const std::string& path) {
  return ReadGlitchesCsv(ReadTextFile(path));
}

std::vector<GlitchRecord> ReadGlitchesCsv(const TextFile& file) {
  // The three-column form (before fault kinds) holds offsets only.
  const bool with_kind = HeaderColumns(file.text) != 3;
  CsvReader r(file, with_kind ? 4 : 3,
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

std::string GroundTruthCsv(const std::vector<NavState>& states, const std::string& file) {
  CsvWriter w(kGroundTruthHeader, file);
  for (const auto& s : states) {
    w << s.t_ns << s.p_W.x() << s.p_W.y() << s.p_W.z() << s.q_WB.w() << s.q_WB.x() << s.q_WB.y() << s.q_WB.z()
      << s.v_W.x() << s.v_W.y() << s.v_W.z() << s.b_g.x() << s.b_g.y() << s.b_g.z() << s.b_a.x() << s.b_a.y()
      << s.b_a.z();
    w.EndRow();
  }
  return w.Str();
}

std::vector<NavState> ReadGroundTruthCsv(const std::string& path) {
  return ReadGroundTruthCsv(ReadTextFile(path));
}

std::vector<NavState> ReadGroundTruthCsv(const TextFile& file) {
  CsvReader r(file, 17, "EuRoC state_groundtruth_estimate0 layout");
  std::vector<NavState> out;
  int64_t last = INT64_MIN;
  while (r.Next()) {
    NavState s;
    s.t_ns = r.Int(0);
    // A ground truth is one pose per instant: a repeated or decreasing timestamp is an error.
    CheckIncreasing(r, s.t_ns, &last);
    const auto rate = [&](std::size_t c) { return Bounded(r, c, kMaxAbsGroundTruthRate); };
    s.p_W = Eigen::Vector3d(Bounded(r, 1, kMaxAbsCoordinate_m), Bounded(r, 2, kMaxAbsCoordinate_m),
                            Bounded(r, 3, kMaxAbsCoordinate_m));
    s.q_WB = ReadUnitQuaternion(r, r.Double(4), r.Double(5), r.Double(6), r.Double(7));
    s.v_W = Eigen::Vector3d(rate(8), rate(9), rate(10));
    s.b_g = Eigen::Vector3d(rate(11), rate(12), rate(13));
    s.b_a = Eigen::Vector3d(rate(14), rate(15), rate(16));
    if (!out.empty()) {
      const double dt_s = NsToS(s.t_ns - out.back().t_ns);
      if (s.t_ns - out.back().t_ns > kMaxGroundTruthGap_ns) r.Fail(GroundTruthGapReason(dt_s));
      const double step_m = (s.p_W - out.back().p_W).norm();
      if (step_m > kMaxGroundTruthSpeed_mps * dt_s)
        r.Fail("position jumps " + FormatDouble(step_m) + " m in " + FormatDouble(dt_s) + " s (" +
               FormatDouble(step_m / dt_s) + " m/s, beyond " + FormatDouble(kMaxGroundTruthSpeed_mps) +
               " m/s): a teleport no motion explains");
      if (const std::string problem = RotationStepProblem(out.back().q_WB, s.q_WB); !problem.empty())
        r.Fail(problem);
    }
    out.push_back(s);
  }
  CheckNotEmpty(r, out.size());
  if (out.size() < 2) r.Fail("one ground-truth row: at least 2 are needed (a trajectory to evaluate)");
  return out;
}

std::string LandmarksCsv(const std::vector<Landmark>& landmarks, const std::string& file) {
  CsvWriter w("id,x [m],y [m],z [m]", file);
  for (const auto& l : landmarks) {
    w << l.id << l.p_W.x() << l.p_W.y() << l.p_W.z();
    w.EndRow();
  }
  return w.Str();
}

std::vector<Landmark> ReadLandmarksCsv(const std::string& path) {
  return ReadLandmarksCsv(ReadTextFile(path));
}

std::vector<Landmark> ReadLandmarksCsv(const TextFile& file) {
  CsvReader r(file, 4, "id, x [m], y [m], z [m]");
  std::vector<Landmark> out;
  std::set<int> ids;
  while (r.Next()) {
    Landmark l;
    l.id = Id(r, 0);
    if (!ids.insert(l.id).second) r.Fail("id: " + std::to_string(l.id) + " listed twice");
    l.p_W = Eigen::Vector3d(Bounded(r, 1, kMaxAbsCoordinate_m), Bounded(r, 2, kMaxAbsCoordinate_m),
                            Bounded(r, 3, kMaxAbsCoordinate_m));
    out.push_back(l);
  }
  return out;
}

std::string FeaturesCsv(const std::vector<CameraFrame>& frames, const std::string& file) {
  CsvWriter w("timestamp [ns],id,u [px],v [px]", file);
  for (const auto& f : frames) {
    for (const auto& o : f.features) {
      w << f.t_ns << o.id << o.uv_px.x() << o.uv_px.y();
      w.EndRow();
    }
  }
  return w.Str();
}

std::vector<CameraFrame> ReadFeaturesCsv(const std::string& path, const std::vector<int64_t>& frame_times_ns,
                                         const FeatureChecks* checks) {
  return ReadFeaturesCsv(ReadTextFile(path), frame_times_ns, checks);
}

std::vector<CameraFrame> ReadFeaturesCsv(const TextFile& file, const std::vector<int64_t>& frame_times_ns,
                                         const FeatureChecks* checks) {
  CsvReader r(file, 4, "timestamp [ns], id, u [px], v [px]");
  std::set<int> known_ids, frame_ids;
  if (checks && checks->landmarks)
    for (const Landmark& l : *checks->landmarks) known_ids.insert(l.id);
  const CameraModel* camera = checks ? checks->camera : nullptr;
  const bool listed_times = checks && checks->listed_times;
  const double margin_px = camera ? 10.0 * camera->pixel_noise_px + 1.0 : 0.0;
  std::vector<CameraFrame> frames;
  std::size_t next_time = 0;
  auto add_empty_until = [&](int64_t t_ns) {  // frames without observations, before t_ns
    while (next_time < frame_times_ns.size() && frame_times_ns[next_time] < t_ns)
      frames.push_back({frame_times_ns[next_time++], {}});
    if (next_time < frame_times_ns.size() && frame_times_ns[next_time] == t_ns) return true;
    return false;
  };
  int64_t last = INT64_MIN;
  while (r.Next()) {
    const int64_t t_ns = r.Int(0);
    CheckIncreasing(r, t_ns, &last, /*allow_equal=*/true);
    if (!frame_times_ns.empty() && (t_ns < frame_times_ns.front() || t_ns > frame_times_ns.back()))
      r.Fail("timestamp " + std::to_string(t_ns) + " is outside the camera frames (" +
             std::to_string(frame_times_ns.front()) + " .. " + std::to_string(frame_times_ns.back()) + ")");
    if (checks && (t_ns < checks->min_t_ns || t_ns > checks->max_t_ns))
      r.Fail("timestamp " + std::to_string(t_ns) + " is outside the IMU's time span (" +
             std::to_string(checks->min_t_ns) + " .. " + std::to_string(checks->max_t_ns) + ")");
    if (frames.empty() || frames.back().t_ns != t_ns) {
      const bool listed = add_empty_until(t_ns);
      if (listed) ++next_time;
      if (listed_times && !listed)
        r.Fail("timestamp " + std::to_string(t_ns) + " is not the time of a camera frame (" +
               dataset_files::kFrames + ")");
      frames.push_back({t_ns, {}});
      frame_ids.clear();
    }
    FeatureObservation o;
    o.id = Id(r, 1);
    if (!frame_ids.insert(o.id).second)
      r.Fail("id: " + std::to_string(o.id) + " observed twice at timestamp " + std::to_string(t_ns));
    if (checks && checks->landmarks && !known_ids.count(o.id))
      r.Fail("id: " + std::to_string(o.id) + " is not a landmark of landmarks.csv");
    o.uv_px = Eigen::Vector2d(r.Double(2), r.Double(3));
    if (camera) {
      // Tracks are undistorted pixels; with lens distortion, their image position is what must be seen.
      const Eigen::Vector2d seen = camera->HasDistortion() ? camera->DistortPixel(o.uv_px) : o.uv_px;
      const double u = seen.x(), v = seen.y();
      if (!(u >= -margin_px && v >= -margin_px && u <= camera->width + margin_px &&
            v <= camera->height + margin_px))
        r.Fail("pixel (" + FormatDouble(o.uv_px.x()) + ", " + FormatDouble(o.uv_px.y()) +
               ") is outside the " + std::to_string(camera->width) + " x " + std::to_string(camera->height) +
               " image (camera.yaml)" + (camera->HasDistortion() ? " once distorted" : ""));
    }
    frames.back().features.push_back(o);
  }
  add_empty_until(INT64_MAX);
  return frames;
}

std::string FramesCsv(const std::vector<CameraFrame>& frames, const std::string& file) {
  CsvWriter w("timestamp [ns]", file);
  for (const CameraFrame& f : frames) {
    w << f.t_ns;
    w.EndRow();
  }
  return w.Str();
}

std::vector<int64_t> ReadFramesCsv(const std::string& path) { return ReadFramesCsv(ReadTextFile(path)); }

std::vector<int64_t> ReadFramesCsv(const TextFile& file) {
  CsvReader r(file, 1, "timestamp [ns] of each camera frame");
  std::vector<int64_t> times;
  int64_t last = INT64_MIN;
  while (r.Next()) {
    const int64_t t_ns = r.Int(0);
    CheckIncreasing(r, t_ns, &last);
    times.push_back(t_ns);
  }
  return times;
}

std::string CameraYaml(const CameraModel& camera) {
  CameraModel copy = camera;
  return config::ToYaml(copy);
}

CameraModel ReadCameraYaml(const std::string& path) {
  CameraModel camera;
  config::LoadFile(path, camera);
  const std::string why = camera.Validate();
  if (!why.empty()) throw InputError(Located(path, config::KeyLine(config::LoadYamlFile(path), "T_BC"), why));
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

void WriteDataset(const fs::path& dir, const Dataset& d, const fs::path& shown_dir) {
  using namespace dataset_files;
  const auto shown = [&](const char* name) {
    return ((shown_dir.empty() ? dir : shown_dir) / name).string();
  };
  WriteFileAtomic(dir / kImu, ImuCsv(d.imu, shown(kImu)));
  WriteFileAtomic(dir / kImuClean, ImuCsv(d.imu_clean, shown(kImuClean)));
  WriteFileAtomic(dir / kGlitches, GlitchesCsv(d.glitches, shown(kGlitches)));
  WriteFileAtomic(dir / kGroundTruth, GroundTruthCsv(d.groundtruth, shown(kGroundTruth)));
  WriteFileAtomic(dir / kLandmarks, LandmarksCsv(d.landmarks, shown(kLandmarks)));
  WriteFileAtomic(dir / kFeatures, FeaturesCsv(d.frames, shown(kFeatures)));
  WriteFileAtomic(dir / kFrames, FramesCsv(d.frames, shown(kFrames)));
  WriteFileAtomic(dir / kCamera, CameraYaml(d.camera));
}

namespace {

std::string ImuSpan(const ImuStream& imu, const std::string& imu_path) {
  return imu_path + " spans " + std::to_string(imu.front().t_ns) + " .. " + std::to_string(imu.back().t_ns) +
         " ns (tolerance " + FormatDouble(NsToS(kSensorSpanTolerance_ns)) + " s)";
}

}  // namespace

void CheckGroundTruthInImuSpan(const ImuStream& imu, const std::string& imu_path,
                               const std::vector<NavState>& groundtruth,
                               const std::string& groundtruth_path) {
  if (imu.empty() || groundtruth.empty()) return;
  if (groundtruth.front().t_ns < imu.front().t_ns - kSensorSpanTolerance_ns)
    throw InputError(Located(groundtruth_path, 2,
                             "timestamp " + std::to_string(groundtruth.front().t_ns) +
                                 ": the ground truth starts before the IMU; " + ImuSpan(imu, imu_path)));
  if (groundtruth.back().t_ns > imu.back().t_ns + kSensorSpanTolerance_ns)
    throw InputError(Located(groundtruth_path, static_cast<int>(groundtruth.size()) + 1,
                             "timestamp " + std::to_string(groundtruth.back().t_ns) +
                                 ": the ground truth ends after the IMU; " + ImuSpan(imu, imu_path)));
}

void CheckCameraTimeInImuSpan(const ImuStream& imu, const std::string& imu_path, int64_t t_ns,
                              const std::string& file, int line) {
  if (imu.empty()) return;
  if (t_ns < imu.front().t_ns || t_ns > imu.back().t_ns)
    throw InputError(Located(file, line,
                             "timestamp " + std::to_string(t_ns) + " is outside the IMU's time span (" +
                                 std::to_string(imu.front().t_ns) + " .. " + std::to_string(imu.back().t_ns) +
                                 " ns, " + imu_path + "): a camera frame needs IMU samples on both sides"));
}

Dataset ReadDataset(const fs::path& dir) {
  using namespace dataset_files;
  if (!fs::is_directory(dir)) throw InputError(dir.string() + ": not a dataset directory");
  Dataset d;
  d.imu = ReadImuCsv((dir / kImu).string());
  if (fs::exists(dir / kImuClean)) {
    d.imu_clean = ReadImuCsv((dir / kImuClean).string());
    CheckCleanImuMatches(d.imu, d.imu_clean, (dir / kImu).string(), (dir / kImuClean).string());
  }
  if (fs::exists(dir / kGlitches)) d.glitches = ReadGlitchesCsv((dir / kGlitches).string());
  d.groundtruth = ReadGroundTruthCsv((dir / kGroundTruth).string());
  CheckGroundTruthInImuSpan(d.imu, (dir / kImu).string(), d.groundtruth, (dir / kGroundTruth).string());
  d.landmarks = ReadLandmarksCsv((dir / kLandmarks).string());
  d.camera = ReadCameraYaml((dir / kCamera).string());
  // Camera frames at their recorded times: frames.csv (never reconstructed from camera.yaml's rate).
  std::vector<int64_t> frame_times;
  FeatureChecks checks;
  checks.camera = &d.camera;
  checks.landmarks = &d.landmarks;
  checks.min_t_ns = d.imu.front().t_ns;
  checks.max_t_ns = d.imu.back().t_ns;
  if (fs::exists(dir / kFrames)) {
    const TextFile frames = ReadTextFile((dir / kFrames).string());
    frame_times = ReadFramesCsv(frames);
    for (std::size_t k = 0; k < frame_times.size(); ++k)
      CheckCameraTimeInImuSpan(d.imu, kImu, frame_times[k], frames.path, static_cast<int>(k) + 2);
    checks.listed_times = true;
  }
  d.frames = ReadFeaturesCsv((dir / kFeatures).string(), frame_times, &checks);
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

Trajectory ReadTumTrajectory(const std::string& path) { return ReadTumTrajectory(ReadTextFile(path)); }

Trajectory ReadTumTrajectory(const TextFile& file) {
  const std::string& path = file.path;
  std::istringstream in(file.text);
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
    if (std::abs(v[0]) > 9e9)
      throw InputError(Located(path, line, "timestamp: " + FormatDouble(v[0]) + " s is beyond +-9e9 s"));
    for (int i = 1; i <= 3; ++i)
      if (std::abs(v[i]) > kMaxAbsCoordinate_m)
        throw InputError(Located(path, line,
                                 "position: " + FormatDouble(v[i]) + " m is beyond the limit of +-" +
                                     FormatDouble(kMaxAbsCoordinate_m) + " m"));
    StampedPose p;
    p.t_ns = SToNs(v[0]);
    if (last != INT64_MIN && p.t_ns <= last)
      throw InputError(Located(path, line, "timestamp does not increase"));
    last = p.t_ns;
    p.p_W = Eigen::Vector3d(v[1], v[2], v[3]);
    const Eigen::Quaterniond q(v[7], v[4], v[5], v[6]);
    if (const std::string problem = QuaternionNormProblem(q); !problem.empty())
      throw InputError(Located(path, line, problem));
    p.q_WB = AsUnit(q);
    out.push_back(p);
  }
  if (out.empty()) throw InputError(path + ": no poses (expected rows 'timestamp tx ty tz qx qy qz qw')");
  return out;
}

}  // namespace vigil
