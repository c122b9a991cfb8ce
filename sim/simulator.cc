#include "sim/simulator.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "core/euroc.h"
#include "core/format.h"
#include "core/mesh.h"
#include "core/output.h"
#include "sim/camera_simulator.h"
#include "sim/camera_timing.h"
#include "sim/glitch_injector.h"
#include "sim/image_renderer.h"
#include "sim/imu_faults.h"
#include "sim/imu_synthesizer.h"
#include "sim/landmarks.h"
#include "sim/scale_misalignment.h"
#include "sim/scene.h"
#include "sim/semi_real.h"
#include "sim/trajectory_model.h"

namespace vigil::sim {
namespace {

// Positions along the trajectory (10 Hz) used to lay out landmarks around the path.
std::vector<Eigen::Vector3d> SamplePath(const TrajectoryModel& motion, double duration_s) {
  std::vector<Eigen::Vector3d> path;
  const int n = static_cast<int>(std::ceil(duration_s * 10.0));
  for (int i = 0; i <= n; ++i) path.push_back(motion.StateAt(std::min(duration_s, 0.1 * i)).p_W);
  return path;
}

// The validated motion model of `options`, covering options.duration_s.
std::unique_ptr<TrajectoryModel> CheckedMotion(const SimOptions& options) {
  ValidateSimOptions(options, "simulator options");
  return MakeTrajectoryModel(options.trajectory, options.duration_s);
}

}  // namespace

Scene ScenarioScene(const SimOptions& options, const TrajectoryModel& motion) {
  return MakeScene(options.landmarks, SamplePath(motion, options.duration_s));
}

ImuSynthesis SimulateImu(const SimOptions& options, uint64_t seed) {
  if (options.imu.source == ImuSource::kRecording) {
    ValidateSimOptions(options, "simulator options");
    Dataset d = SimulateSemiReal(options, seed);
    return {std::move(d.imu_clean), std::move(d.groundtruth)};
  }
  const std::unique_ptr<TrajectoryModel> motion = CheckedMotion(options);
  ImuSynthesis out = SynthesizeImu(*motion, options.imu, options.duration_s, options.gravity_mps2, seed);
  ApplyScaleMisalignment(options.faults.scale, &out.imu);
  ImuStream measured = out.imu;  // the faults of imu_clean are applied alongside those of the measured stream
  ApplyMeasurementFaults(options, seed, &measured, &out.imu, nullptr);
  return out;
}

Dataset Simulate(const SimOptions& options, uint64_t seed) {
  if (options.imu.source == ImuSource::kRecording) {
    ValidateSimOptions(options, "simulator options");
    return SimulateSemiReal(options, seed);
  }
  const std::unique_ptr<TrajectoryModel> motion = CheckedMotion(options);
  Dataset d;
  ImuSynthesis imu = SynthesizeImu(*motion, options.imu, options.duration_s, options.gravity_mps2, seed);
  d.imu_clean = std::move(imu.imu);
  d.groundtruth = std::move(imu.groundtruth);
  ApplyScaleMisalignment(options.faults.scale, &d.imu_clean);
  d.imu = d.imu_clean;
  d.glitches = InjectGlitches(options.glitch, seed, &d.imu);
  ApplyMeasurementFaults(options, seed, &d.imu, &d.imu_clean, &d.glitches);
  d.landmarks = MakeLandmarks(options.landmarks, SamplePath(*motion, options.duration_s), seed);
  d.camera = options.camera;
  const std::vector<int64_t> frame_times =
      ApplyCameraTiming(options.faults.camera, options.camera.rate_hz, seed,
                        CameraFrameTimes(options.camera.rate_hz, d.imu.front().t_ns, d.imu.back().t_ns));
  d.frames = SimulateFeatureTracksAt(*motion, options.camera, d.landmarks, frame_times, seed);
  return d;
}

EurocImuSensor ImuSensorOf(const ImuOptions& imu) {
  EurocImuSensor s;
  s.rate_hz = imu.rate_hz;
  if (imu.noise.enabled) {
    s.gyroscope_noise_density = imu.noise.gyro_noise_density;
    s.gyroscope_random_walk = imu.noise.gyro_bias_random_walk;
    s.accelerometer_noise_density = imu.noise.accel_noise_density;
    s.accelerometer_random_walk = imu.noise.accel_bias_random_walk;
  }
  return s;
}

std::uintmax_t WriteImages(const SimOptions& options, uint64_t seed, const Dataset& dataset,
                           const std::filesystem::path& dir) {
  const std::unique_ptr<TrajectoryModel> motion = CheckedMotion(options);
  std::vector<int64_t> times;
  for (const CameraFrame& f : dataset.frames) times.push_back(f.t_ns);
  WriteEuroc(dir, dataset, ImuSensorOf(options.imu), times);
  const Scene scene = ScenarioScene(options, *motion);
  WriteFileAtomic(dir / kSceneObjFile, MeshObj(scene.Mesh()));
  return RenderImageSequence(scene, *motion, options.duration_s, options.camera, options.images, seed, times,
                             EurocImageDir(dir));
}

Dataset SimulateToDirectory(const SimOptions& options, uint64_t seed, const std::string& config_yaml,
                            const std::filesystem::path& dir, bool force) {
  StagedDirectory staged(dir, force);  // refuses a non-empty `dir` before any work
  Dataset d = Simulate(options, seed);
  WriteFileAtomic(staged.path() / dataset_files::kConfig, config_yaml);
  WriteDataset(staged.path(), d, dir);  // errors name the output, not its staging
  if (options.images.enabled) WriteImages(options, seed, d, staged.path());
  staged.Commit();
  return d;
}

}  // namespace vigil::sim
