// `estimator.init: vins`: visual-inertial initialization from the window alone (no ground truth).
//
// TryInitialize runs, once the window is full: the vision-only SfM (window_sfm.h: reference frame by
// correspondences and parallax, relative pose, triangulation, PnP, bundle adjustment), the gyro bias by least
// squares, vigil's check that it explains every pair's rotation (VinsInitOptions::max_gyro_residual_deg), the
// preintegrations re-propagated with it, the linear alignment of velocities, gravity and scale,
// the gravity refinement on the sphere (visual_inertial_alignment.h), and finally rotates the world so
// gravity is -z, with the yaw of W set to the first frame's body yaw and the first body position at the
// origin. A failed attempt leaves nothing behind; the estimator retries on later windows, and after a failure
// reset.
#pragma once

#include "core/camera.h"
#include "estimator/init/vins_init_options.h"
#include "estimator/init/visual_inertial_alignment.h"
#include "estimator/init/window_sfm.h"
#include "estimator/initializer.h"

namespace vigil::estimator {

class VinsInitializer : public Initializer {
 public:
  // `window_frames`: the full window (keyframes + newest); smaller windows are refused, as in the reference.
  VinsInitializer(const VinsInitOptions& options, const CameraModel& camera, double gravity_mps2,
                  int window_frames);

  bool TryInitialize(const std::vector<InitFrame>& window, InitResult* result) override;
  bool CanReinitialize() const override { return true; }

  // The SfM settings derived from the options (pixel thresholds over the camera's fx).
  WindowSfmOptions SfmOptions() const;

 private:
  // False, with the reason in `result`, when a pair's rotations disagree beyond max_gyro_residual_deg.
  bool GyroAgreesWithVision(const std::vector<AlignmentFrame>& frames, const Eigen::Vector3d& b_g,
                            InitResult* result) const;

  VinsInitOptions options_;
  Eigen::Matrix3d R_BC_;
  Eigen::Vector3d p_BC_;
  double fx_;
  double gravity_mps2_;
  std::size_t window_frames_;
};

}  // namespace vigil::estimator
