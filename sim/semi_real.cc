#include "sim/semi_real.h"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "core/error.h"
#include "core/format.h"
#include "core/interpolation.h"
#include "core/random.h"
#include "sim/camera_simulator.h"
#include "sim/camera_timing.h"
#include "sim/glitch_injector.h"
#include "sim/imu_faults.h"
#include "sim/landmarks.h"
#include "sim/scale_misalignment.h"

namespace vigil::sim {
namespace fs = std::filesystem;
namespace {

// A ground truth "at the camera rate" has a median period within this fraction of the camera's period.
constexpr double kCameraRateTolerance = 0.05;

// CSV line of row `index` (0-based) of a file with one header line.
int RowLine(std::size_t index) { return static_cast<int>(index) + 2; }

std::string Seconds(int64_t t_ns) { return FormatDouble(NsToS(t_ns)); }

// The recording's IMU file, for errors.
std::string ImuFileOf(const fs::path& dir, const Recording& recording) {
  if (recording.layout == "vigil") return (dir / dataset_files::kImu).string();
  return (FindMav0(dir) / euroc_files::kImu / euroc_files::kData).string();
}

int64_t MedianPeriodNs(const std::vector<NavState>& states) {
  std::vector<int64_t> periods;
  for (std::size_t k = 1; k < states.size(); ++k) periods.push_back(states[k].t_ns - states[k - 1].t_ns);
  if (periods.empty()) return 0;
  std::nth_element(periods.begin(), periods.begin() + periods.size() / 2, periods.end());
  return periods[periods.size() / 2];
}

// Camera times listed by the recording itself.
std::vector<int64_t> ListedFrameTimes(const Recording& recording) {
  std::vector<int64_t> times;
  if (!recording.images.empty()) {
    for (const CameraImage& image : recording.images) times.push_back(image.t_ns);
  } else {
    for (const CameraFrame& frame : recording.dataset.frames) times.push_back(frame.t_ns);
  }
  return times;
}

// The recorded IMU samples spanning [t0_ns, t1_ns]; throws when the IMU does not cover it.
ImuStream ImuSpanning(const ImuStream& imu, int64_t t0_ns, int64_t t1_ns, const std::string& imu_file) {
  if (imu.front().t_ns > t0_ns)
    throw InputError(Located(imu_file, RowLine(0),
                             "imu.recording: the IMU starts at " + Seconds(imu.front().t_ns) +
                                 " s, after the start of the semi-real window (ground truth from " +
                                 Seconds(t0_ns) + " s): the IMU must cover the window"));
  if (imu.back().t_ns < t1_ns)
    throw InputError(Located(imu_file, RowLine(imu.size() - 1),
                             "imu.recording: the IMU ends at " + Seconds(imu.back().t_ns) +
                                 " s, before the end of the semi-real window (ground truth until " +
                                 Seconds(t1_ns) + " s): the IMU must cover the window"));
  const auto by_time = [](const ImuSample& s, int64_t t) { return s.t_ns < t; };
  auto first = std::lower_bound(imu.begin(), imu.end(), t0_ns, by_time);
  if (first->t_ns > t0_ns) --first;  // the last sample before the window's start
  while (first != imu.begin() && (first - 1)->t_ns == first->t_ns) --first;  // repeated timestamps
  auto last = std::lower_bound(imu.begin(), imu.end(), t1_ns, by_time);      // the first at or after the end
  while (last + 1 != imu.end() && (last + 1)->t_ns == last->t_ns) ++last;
  return ImuStream(first, last + 1);
}

}  // namespace

std::vector<int64_t> RecordedFrameTimes(const Recording& recording) {
  const std::vector<NavState>& gt = recording.dataset.groundtruth;
  const std::vector<int64_t> listed = ListedFrameTimes(recording);
  const double period_ns = 1e9 / recording.dataset.camera.rate_hz;
  const bool gt_at_camera_rate =
      std::abs(static_cast<double>(MedianPeriodNs(gt)) - period_ns) <= kCameraRateTolerance * period_ns;
  const int64_t gt0 = gt.front().t_ns, gt1 = gt.back().t_ns;
  // Times strictly before `before` or strictly after `after`, within the ground truth: its own rows at the
  // camera rate, else every camera period from the nearest listed frame.
  std::vector<int64_t> head, tail;
  if (gt_at_camera_rate) {
    for (const NavState& s : gt) {
      if (listed.empty() || s.t_ns < listed.front()) head.push_back(s.t_ns);
      if (!listed.empty() && s.t_ns > listed.back()) tail.push_back(s.t_ns);
    }
  } else if (listed.empty()) {
    head = CameraFrameTimes(recording.dataset.camera.rate_hz, gt0, gt1);
  } else {
    for (int64_t k = 1;; ++k) {
      const int64_t t = listed.front() - std::llround(static_cast<double>(k) * period_ns);
      if (t < gt0) break;
      head.insert(head.begin(), t);
    }
    for (int64_t t : CameraFrameTimes(recording.dataset.camera.rate_hz, listed.back(), gt1))
      if (t > listed.back()) tail.push_back(t);
  }
  std::vector<int64_t> times = head;
  for (int64_t t : listed)
    if (t >= gt0 && t <= gt1) times.push_back(t);
  times.insert(times.end(), tail.begin(), tail.end());
  return times;
}

RecordedWindow ReadRecordedWindow(const SimOptions& options) {
  const fs::path dir = options.imu.recording;
  // The camera's calibration and times, never its pixels: the image files need not be there (the committed
  // excerpt, data/euroc_v1_01_excerpt, lists the recorded times without the images).
  Recording recording = ReadRecording(dir, /*check_image_files=*/false);
  if (!recording.has_groundtruth)
    throw InputError("imu.recording: " + dir.string() +
                     ": no ground truth (mav0/state_groundtruth_estimate0/data.csv): a semi-real dataset "
                     "synthesizes its camera along the recorded ground truth");
  if (!recording.has_camera)
    throw InputError("imu.recording: " + dir.string() +
                     ": no camera (mav0/cam0/sensor.yaml or camera.yaml): a semi-real dataset uses the "
                     "recording's camera");
  const std::string imu_file = ImuFileOf(dir, recording);
  const std::vector<NavState>& gt = recording.dataset.groundtruth;
  const int64_t gt0 = gt.front().t_ns, gt1 = gt.back().t_ns;
  const int64_t start_ns = gt0 + SToNs(options.imu.recording_start_s);
  const int64_t end_ns = start_ns + SToNs(options.duration_s);
  if (end_ns > gt1)
    throw InputError("duration_s: the semi-real window (imu.recording_start_s " +
                     FormatDouble(options.imu.recording_start_s) + " s + duration_s " +
                     FormatDouble(options.duration_s) + " s) ends after the recording's ground truth (" +
                     FormatPrintf("%.3f", NsToS(gt1 - gt0)) + " s long, " + dir.string() + ")");
  RecordedWindow w;
  for (const NavState& s : gt)
    if (s.t_ns >= start_ns && s.t_ns <= end_ns) w.groundtruth.push_back(s);
  if (w.groundtruth.size() < 2)
    throw InputError("duration_s: the semi-real window holds " + std::to_string(w.groundtruth.size()) +
                     " ground-truth row(s) of " + dir.string() + ": at least 2 are needed");
  const int64_t w0 = w.groundtruth.front().t_ns, w1 = w.groundtruth.back().t_ns;
  w.imu = ImuSpanning(recording.dataset.imu, w0, w1, imu_file);
  w.camera = recording.dataset.camera;
  w.camera.pixel_noise_px = options.camera.pixel_noise_px;
  for (int64_t t : RecordedFrameTimes(recording))
    if (t >= w0 && t <= w1) w.frame_times_ns.push_back(t);
  return w;
}

Dataset SimulateSemiReal(const SimOptions& options, uint64_t seed) {
  RecordedWindow w = ReadRecordedWindow(options);
  Dataset d;
  d.imu_clean = std::move(w.imu);
  d.groundtruth = std::move(w.groundtruth);
  d.camera = w.camera;
  // The fault stages of Simulate(), in the same order (sim/imu_faults.h), on the recorded stream.
  ApplyScaleMisalignment(options.faults.scale, &d.imu_clean);
  d.imu = d.imu_clean;
  d.glitches = InjectGlitches(options.glitch, seed, &d.imu);
  SimOptions at_recorded_rate = options;
  at_recorded_rate.imu.rate_hz =
      static_cast<double>(d.imu.size() - 1) / NsToS(d.imu.back().t_ns - d.imu.front().t_ns);
  ApplyMeasurementFaults(at_recorded_rate, seed, &d.imu, &d.imu_clean, &d.glitches);
  std::vector<Eigen::Vector3d> path_W;
  for (const NavState& s : d.groundtruth) path_W.push_back(s.p_W);
  d.landmarks = MakeLandmarks(options.landmarks, path_W, seed);
  Rng rng(seed, "pixels");
  for (int64_t t_ns : ApplyCameraTiming(options.faults.camera, d.camera.rate_hz, seed, w.frame_times_ns)) {
    NavState x;
    InterpolateNavState(d.groundtruth, t_ns, &x);  // frame times lie within the ground truth
    d.frames.push_back(ObserveLandmarks(d.camera, x.q_WB, x.p_W, d.landmarks, t_ns, &rng));
  }
  return d;
}

}  // namespace vigil::sim
