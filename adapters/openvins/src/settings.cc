#include "settings.h"

#include <fstream>
#include <iomanip>
#include <sstream>

namespace vigil_openvins {
namespace fs = std::filesystem;
namespace {

std::string Rows(const Eigen::Matrix4d& T, const char* indent) {
  std::ostringstream out;
  out << std::setprecision(17);
  for (int r = 0; r < 4; ++r)
    out << indent << "- [" << T(r, 0) << ", " << T(r, 1) << ", " << T(r, 2) << ", " << T(r, 3) << "]\n";
  return out.str();
}

void WriteText(const fs::path& path, const std::string& text) {
  std::ofstream out(path);
  out << text;
  if (!out.flush()) throw std::runtime_error(path.string() + ": cannot write");
}

// The estimator's settings: one monocular camera whose calibration is known (nothing calibrated online),
// single-threaded and without wall-clock limits, so that a run repeats exactly.
std::string EstimatorConfig(const Settings& s) {
  std::ostringstream y;
  y << std::setprecision(17);
  y << "%YAML:1.0\n"
    << "# Written by vigil's OpenVINS adapter (adapters/openvins/src/settings.cc).\n"
    << "use_fej: true\nintegration: \"rk4\"\nuse_stereo: false\nmax_cameras: 1\n"
    << "calib_cam_extrinsics: false\ncalib_cam_intrinsics: false\ncalib_cam_timeoffset: false\n"
    << "calib_imu_intrinsics: false\ncalib_imu_g_sensitivity: false\n"
    << "max_clones: " << s.max_clones << "\nmax_slam: " << s.max_slam << "\n"
    << "max_slam_in_update: 25\nmax_msckf_in_update: 40\nnum_aruco: " << kArucoTags << "\ndt_slam_delay: 1\n"
    << "gravity_mag: " << s.gravity_mps2 << "\n"
    << "feat_rep_msckf: \"GLOBAL_3D\"\nfeat_rep_slam: \"GLOBAL_3D\"\n"
    << "feat_rep_aruco: \"GLOBAL_3D\"\n"
    << "try_zupt: false\nzupt_chi2_multipler: 0\nzupt_max_velocity: 0.1\nzupt_noise_multiplier: 10\n"
    << "zupt_max_disparity: 0.5\nzupt_only_at_beginning: false\n"
    << "init_window_time: " << s.init_window_s << "\n"
    << "init_imu_thresh: 1.0\ninit_max_disparity: 1.5\n"
    << "init_max_features: " << s.init_max_features << "\n"
    << "init_dyn_use: true\ninit_dyn_mle_opt_calib: false\ninit_dyn_mle_max_iter: 50\n"
    << "init_dyn_mle_max_time: 60\ninit_dyn_mle_max_threads: 1\ninit_dyn_num_pose: 6\ninit_dyn_min_deg: "
       "10.0\n"
    << "init_dyn_inflation_ori: 10\ninit_dyn_inflation_vel: 100\ninit_dyn_inflation_bg: 10\n"
    << "init_dyn_inflation_ba: 100\ninit_dyn_min_rec_cond: 1e-15\n"
    << "init_dyn_bias_g: [0.0, 0.0, 0.0]\ninit_dyn_bias_a: [0.0, 0.0, 0.0]\n"
    << "record_timing_information: false\nrecord_timing_filepath: \"timing.txt\"\n"
    << "use_klt: true\nnum_pts: 200\nfast_threshold: 20\ngrid_x: 5\ngrid_y: 5\nmin_px_dist: 10\n"
    << "knn_ratio: 0.70\ntrack_frequency: 1000.0\ndownsample_cameras: false\nnum_opencv_threads: 1\n"
    << "multi_threading_pubs: false\nmulti_threading_subs: false\n"
    << "histogram_method: \"HISTOGRAM\"\nuse_aruco: false\ndownsize_aruco: true\n"
    << "up_msckf_sigma_px: " << s.pixel_sigma_px << "\nup_msckf_chi2_multipler: 1\n"
    << "up_slam_sigma_px: " << s.pixel_sigma_px << "\nup_slam_chi2_multipler: 1\n"
    << "up_aruco_sigma_px: 1\nup_aruco_chi2_multipler: 1\n"
    << "use_mask: false\n"
    << "relative_config_imu: \"kalibr_imu_chain.yaml\"\nrelative_config_imucam: "
       "\"kalibr_imucam_chain.yaml\"\n";
  return y.str();
}

// imu0: the noise densities and rate of imu0/sensor.yaml; an ideal (calibrated) IMU otherwise.
std::string ImuChain(const ImuNoise& n) {
  std::ostringstream y;
  y << std::setprecision(17);
  const char* identity3 = "    - [1.0, 0.0, 0.0]\n    - [0.0, 1.0, 0.0]\n    - [0.0, 0.0, 1.0]\n";
  y << "%YAML:1.0\nimu0:\n"
    << "  accelerometer_noise_density: " << n.accel_noise_density << "\n"
    << "  accelerometer_random_walk: " << n.accel_random_walk << "\n"
    << "  gyroscope_noise_density: " << n.gyro_noise_density << "\n"
    << "  gyroscope_random_walk: " << n.gyro_random_walk << "\n"
    << "  update_rate: " << n.rate_hz << "\n  time_offset: 0.0\n  model: \"kalibr\"\n"
    << "  Tw:\n"
    << identity3 << "  Ta:\n"
    << identity3 << "  R_IMUtoGYRO:\n"
    << identity3 << "  R_IMUtoACC:\n"
    << identity3 << "  Tg:\n    - [0.0, 0.0, 0.0]\n    - [0.0, 0.0, 0.0]\n    - [0.0, 0.0, 0.0]\n";
  return y.str();
}

// cam0: the camera in the IMU frame. The tracks are undistorted pinhole pixels, so no distortion is given.
std::string ImuCamChain(const Recording& r) {
  const Camera& c = r.camera;
  const Eigen::Matrix4d T_IC = r.noise.T_BI.inverse() * c.T_BC;  // camera -> IMU
  std::ostringstream y;
  y << std::setprecision(17);
  y << "%YAML:1.0\ncam0:\n  T_imu_cam:\n"
    << Rows(T_IC, "    ") << "  camera_model: pinhole\n"
    << "  distortion_coeffs: [0.0, 0.0, 0.0, 0.0]\n  distortion_model: radtan\n"
    << "  intrinsics: [" << c.fx << ", " << c.fy << ", " << c.cx << ", " << c.cy << "]\n"
    << "  resolution: [" << c.width << ", " << c.height << "]\n  timeshift_cam_imu: 0.0\n";
  return y.str();
}

}  // namespace

fs::path WriteOpenvinsConfig(const fs::path& dir, const Settings& settings, const Recording& recording) {
  fs::create_directories(dir);
  WriteText(dir / "kalibr_imu_chain.yaml", ImuChain(recording.noise));
  WriteText(dir / "kalibr_imucam_chain.yaml", ImuCamChain(recording));
  WriteText(dir / "estimator_config.yaml", EstimatorConfig(settings));
  return dir / "estimator_config.yaml";
}

}  // namespace vigil_openvins
