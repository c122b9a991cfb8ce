// Options of the sliding-window visual-inertial estimator.
//
// Defaults are the reference values of VINS-Mono (docs/references.md, "VINS-Mono's estimator"), except
// PriorOptions (VINS-Mono has no initial bias prior; see there) and the window length and keyframe parallax
// (WindowOptions).
#pragma once

#include "core/config.h"
#include "estimator/imu_noise_model.h"
#include "estimator/init/vins_init_options.h"
#include "estimator/mitigation_options.h"
#include "estimator/zero_velocity_options.h"

namespace vigil::estimator {

enum class InitMode { kGroundTruth, kVins };

// `init: groundtruth`: the first window's states from ground truth, optionally perturbed (seeded from the run
// seed).
struct GroundTruthInitOptions {
  double position_std_m = 0.0;
  double rotation_std_deg = 0.0;
  double velocity_std_mps = 0.0;

  template <class V>
  void Visit(V& v) {
    using config::Bounds;
    v.Field("position_std_m", position_std_m, "std of the Gaussian perturbation of each initial position [m]",
            Bounds::NonNegative());
    v.Field("rotation_std_deg", rotation_std_deg,
            "std of the Gaussian perturbation (rotation vector, per axis) of each initial orientation [deg]",
            Bounds::NonNegative());
    v.Field("velocity_std_mps", velocity_std_mps,
            "std of the Gaussian perturbation of each initial velocity [m/s]", Bounds::NonNegative());
  }
};

// What becomes of the tracks anchored in the oldest frame when it leaves the window. Their factors all
// involve that frame's pose, so all of them go into the marginalization prior. VINS-Mono then keeps the
// track, re-anchored in its next observation, and uses the observations the prior already holds once more:
// the window claims more information than it has (the orientation NEES on the IMU simulated along V1_01
// is 4.5). Restarting the track uses each observation once (NEES 1.8), but loses what ties a long track's
// past to the window: ATE +74 % there, and one of five semi-real runs diverges
// (docs/results/2026-12-estimator.md, "What the marginalization prior holds"). So VINS-Mono's rule stays the
// default. vigil's `points` keeps each long track with a baseline as a landmark point in W, a state of the
// window and of its prior (OKVIS's design): each observation enters once, and the track ties the window to
// its past for as long as it is seen (docs/estimator.md, "Long tracks as landmark points").
enum class OldestTracks {
  kReanchor,  // VINS-Mono: marginalized into the prior, then kept, re-anchored in their next observation
  kRestart,   // marginalized into the prior, then erased: a later observation starts a new track
  kPoints,    // vigil: the long tracks with a baseline become points in W kept in the prior; others reanchor
};

// Window length and keyframe policy. VINS-Mono keeps 10 keyframes and makes one at 10 px of parallax; at a
// 20-30 Hz camera and a slow flight that makes every second frame a keyframe (EuRoC V1_01: 1,402 of 2,895
// frames), so the window spans about a second and its yaw and scale drift with the IMU's errors. vigil keeps
// 15 keyframes and makes one at 20 px, which spans about three times as long
// (docs/results/2026-12-estimator.md, "Accuracy ablations": ATE -45 to -50 % on the real IMU, -50 % on the
// IMU simulated along V1_01, -6 % on the paper scenario, -28 % on the rescue course).
struct WindowOptions {
  int size = 15;                  // keyframes kept besides the newest frame
  double min_parallax_px = 20.0;  // keyframe when the mean parallax to the previous frame reaches this
  int min_tracked_features = 20;  // keyframe when fewer features are tracked into the newest frame
  // Measure the keyframe parallax after rotating the older frame's observations by the frames' estimated
  // relative rotation, so that turning on the spot makes no keyframe (VINS-Mono's paper describes this
  // compensation; its code and vigil's default measure the raw displacement). Off by default: the paper
  // scenario's gate was recorded without it. The rescue course uses it (configs/rescue_accuracy.yaml).
  bool parallax_compensates_rotation = false;
  double repropagate_accel_bias = 0.10;  // re-integrate an IMU factor when b_a moved this far [m/s^2]
  double repropagate_gyro_bias = 0.01;   // ... or b_g moved this far [rad/s]
  double marginalization_eigen_threshold =
      1e-8;  // information at or below this counts as none (marginalization.h)
  OldestTracks oldest_tracks = OldestTracks::kReanchor;
  // With oldest_tracks `points`: which tracks anchored in the leaving frame become points.
  int point_min_observations = 10;        // observations in the window, the anchor's included
  double point_min_baseline_ratio = 0.3;  // distance of the anchor's camera to the last one, over the depth
  double point_settle_s = 6.0;            // no points from frames earlier than this after an initialization
  int point_max = 0;                      // live points at most (the first made are kept); 0: no cap

  template <class V>
  void Visit(V& v) {
    using config::Bounds;
    v.Field("size", size, "sliding-window keyframes (plus the newest frame)", Bounds::AtLeast(2));
    v.Field(
        "min_parallax_px", min_parallax_px,
        "keyframe when the mean parallax of the features tracked from the previous frame reaches this [px]",
        Bounds::Positive());
    v.Field("parallax_compensates_rotation", parallax_compensates_rotation,
            "measure the keyframe parallax after removing the frames' estimated relative rotation (the "
            "parallax of translation alone; false: the raw image displacement)");
    v.Field("min_tracked_features", min_tracked_features,
            "keyframe when fewer already-known features are seen in the newest frame", Bounds::NonNegative());
    v.Field("repropagate_accel_bias", repropagate_accel_bias,
            "re-integrate an IMU factor when its b_a estimate moved this far from the linearization point "
            "[m/s^2]",
            Bounds::Positive());
    v.Field("repropagate_gyro_bias", repropagate_gyro_bias,
            "re-integrate an IMU factor when its b_g estimate moved this far from the linearization point "
            "[rad/s]",
            Bounds::Positive());
    v.Field("marginalization_eigen_threshold", marginalization_eigen_threshold,
            "marginalization: eigenvalues and pivots of the normal equations at or below this count as zero, "
            "and the kept prior gets this ridge",
            Bounds::Positive());
    v.Enum("oldest_tracks", oldest_tracks,
           config::EnumNames<OldestTracks>{{"reanchor", OldestTracks::kReanchor},
                                           {"restart", OldestTracks::kRestart},
                                           {"points", OldestTracks::kPoints}},
           "the tracks anchored in the oldest frame when it leaves: reanchor (VINS-Mono: marginalized, then "
           "re-anchored and used again), restart (marginalized, then erased), points (vigil: the long tracks "
           "with a baseline become landmark points in W, kept in the window and its prior; the others "
           "reanchor)");
    v.Field("point_min_observations", point_min_observations,
            "with oldest_tracks points: a track becomes a point with at least this many observations in the "
            "window",
            Bounds::AtLeast(2));
    v.Field("point_min_baseline_ratio", point_min_baseline_ratio,
            "with oldest_tracks points: ... and when its anchor's camera and its last one are apart by at "
            "least this fraction of its depth",
            Bounds::NonNegative());
    v.Field(
        "point_settle_s", point_settle_s,
        "with oldest_tracks points: no track anchored in a frame earlier than this after an initialization "
        "becomes a point (the first windows carry the initialization's errors, and points would hold them) "
        "[s]",
        Bounds::NonNegative());
    v.Field("point_max", point_max,
            "with oldest_tracks points: at most this many live points, 0 for no cap; a track qualifies only "
            "while fewer are live (each point adds 3 dimensions to the dense blocks the window factorizes)",
            Bounds::NonNegative());
  }
};

// Prior knowledge of the IMU biases at initialization (not part of VINS-Mono, which starts its biases free;
// OKVIS- and OpenVINS-style estimators carry an initial bias uncertainty like this one). The initializer's
// bias estimate (groundtruth: the true biases; vins: the gyroscope bias from its least squares and a zero
// accelerometer bias) enters as a Gaussian prior on the first window's oldest frame and is carried into the
// marginalization prior when that frame leaves the window; it never fixes the gauge (position, yaw).
// Why: over the first windows (about a second, little rotation) a roll/pitch error d_theta and an
// accelerometer bias g * d_theta explain the IMU data equally well, so with free biases the noise tilts the
// early windows by a few tenths of a degree, the tilted window drifts in z, and the marginalization prior
// freezes that in. The prior keeps the bias near what is known before any motion. The defaults describe a
// low-cost MEMS IMU calibrated once but not at start-up (turn-on biases of ~0.1 m/s^2 and ~0.03 rad/s = 1.7
// deg/s; the bias priors OKVIS ships with); 0 switches a prior off. A true bias several std away from the
// prior's centre is still found, only more slowly.
struct PriorOptions {
  double accel_bias_std = 0.1;  // [m/s^2]
  double gyro_bias_std = 0.03;  // [rad/s]

  template <class V>
  void Visit(V& v) {
    using config::Bounds;
    v.Field("accel_bias_std", accel_bias_std,
            "std of the Gaussian prior on the initial accelerometer bias (around the initializer's estimate) "
            "[m/s^2]; 0: no prior",
            Bounds::NonNegative());
    v.Field("gyro_bias_std", gyro_bias_std,
            "std of the Gaussian prior on the initial gyroscope bias (around the initializer's estimate) "
            "[rad/s]; 0: no prior",
            Bounds::NonNegative());
  }
};

struct FeatureOptions {
  int min_observations = 2;      // a feature enters the optimization once seen this often in the window
  double pixel_std_px = 1.5;     // reprojection noise std: sqrt information = focal length / pixel_std_px
  double cauchy_scale = 1.0;     // Cauchy loss scale on the whitened residual
  double min_depth_m = 0.1;      // triangulated depths below this are rejected
  double max_depth_m = 200.0;    // ... and above this
  double default_depth_m = 5.0;  // initial depth when triangulation is not possible
  double outlier_threshold_px =
      3.0;  // after a solve, features with a larger mean reprojection error are removed

  template <class V>
  void Visit(V& v) {
    using config::Bounds;
    v.Field("min_observations", min_observations, "observations in the window before a feature is optimized",
            Bounds::AtLeast(2));
    v.Field("pixel_std_px", pixel_std_px,
            "feature reprojection noise std (sqrt information = fx / this) [px]", Bounds::Positive());
    v.Field("cauchy_scale", cauchy_scale, "Cauchy loss scale of the whitened reprojection residual",
            Bounds::Positive());
    v.Field("min_depth_m", min_depth_m, "smallest accepted feature depth in its first observing frame [m]",
            Bounds::Positive());
    v.Field("max_depth_m", max_depth_m, "largest accepted feature depth in its first observing frame [m]",
            Bounds::Positive());
    v.Field("default_depth_m", default_depth_m, "initial depth of a feature that cannot be triangulated [m]",
            Bounds::Positive());
    v.Field("outlier_threshold_px", outlier_threshold_px,
            "features whose mean reprojection error exceeds this after a solve are removed [px]",
            Bounds::Positive());
  }
};

// The window's solver: Ceres (DENSE_SCHUR, DOGLEG: VINS-Mono's) or vigil's dense Levenberg-Marquardt over the
// window with the depths eliminated (dense_window_solver.h), with the same factors and stopping rules.
enum class SolverBackend { kCeres, kDense };

struct SolverOptions {
  SolverBackend backend = SolverBackend::kDense;
  int max_iterations = 8;  // trust-region iterations per solve (VINS-Mono's value)
  // A solve ends after this many accepted trust-region steps (0: only max_iterations, the function tolerance
  // and the time limit end it). The window is re-solved at every camera frame and a keyframe stays in it for
  // about 40 frames, so its states are relinearized and stepped in every frame anyway; a second accepted step
  // in the same frame mostly confirms convergence (the function tolerance stopped 82 % of solves right after
  // it) at the price of another Schur elimination and Jacobian evaluation. A rejected step does not count
  // (the solve shrinks the trust region and tries again), and the solve goes on to max_iterations while the
  // window's cost exceeds its expectation under the noise model (half the number of residuals: a glitch burst
  // in the IMU factors, a re-initialization on bad data), so hard frames still converge. Measured when it was
  // introduced (before the initial bias prior), configs/paper.yaml, seeds 1-5 (groundtruth init): ATE
  // 0.0443 / 0.0596 / 0.0283 / 0.0420 / 0.0343 m with 1 against 0.0469 / 0.0611 / 0.0292 / 0.0422 / 0.0360 m
  // with 0; optimization time -40 %; N(50,10) glitches without a detector degrade it the same way (mean
  // 0.483 m against 0.480 m).
  int accepted_steps = 1;
  // A solve stops when an iteration changes the cost by less than this fraction. Every frame's solve starts
  // from the previous solution, so after the first one or two steps the remaining ones change the cost by
  // far less than the noise; Ceres' default 1e-6 runs most solves to max_iterations for nothing (measured
  // with accepted_steps 0: 5.2 -> 2.2 iterations per solve, ATE unchanged or better over 5 seeds).
  double function_tolerance = 1e-3;
  // Per solve; 0 = no limit. VINS-Mono caps a solve at 0.04 s, but a wall-clock cap that binds makes the
  // result depend on the machine's load; vigil's default keeps runs bit-for-bit reproducible (set 0.04 for
  // the reference).
  double max_time_s = 0.0;
  double marginalize_old_time_factor = 0.8;  // time limit scale when the oldest frame is marginalized

  template <class V>
  void Visit(V& v) {
    using config::Bounds;
    v.Enum(
        "backend", backend,
        config::EnumNames<SolverBackend>{{"ceres", SolverBackend::kCeres}, {"dense", SolverBackend::kDense}},
        "the window's solver: ceres (DENSE_SCHUR, DOGLEG) or dense (vigil's Levenberg-Marquardt over the "
        "window with the depths eliminated)");
    v.Field("max_iterations", max_iterations, "Ceres iterations per solve (DENSE_SCHUR, DOGLEG)",
            Bounds::AtLeast(1));
    v.Field("accepted_steps", accepted_steps,
            "a solve ends after this many accepted trust-region steps once its cost is within the noise "
            "model's expectation (0: no such limit; rejected steps do not count)",
            Bounds::NonNegative());
    v.Field("function_tolerance", function_tolerance,
            "a solve stops when an iteration changes the cost by less than this fraction (Ceres "
            "function_tolerance)",
            Bounds::Closed(0.0, 1.0));
    v.Field(
        "max_time_s", max_time_s,
        "wall-clock limit per solve [s] (0: none, the default, for reproducible runs; VINS-Mono uses 0.04)",
        Bounds::NonNegative());
    v.Field("marginalize_old_time_factor", marginalize_old_time_factor,
            "scale of the time limit when the oldest frame will be marginalized", Bounds::Closed(0.01, 1.0));
  }
};

// The estimator's checks of its own state after every solve (VINS-Mono's failure detection: bias norms and
// position jumps; vigil adds the speed, the rotation jump and lost tracks, which VINS-Mono's code carries
// disabled). A check that fires resets the window for re-initialization when the initializer can do that
// (init: vins) and otherwise stops the run; EstimatorResult counts both, and which check fired.
struct FailureOptions {
  double max_accel_bias = 2.5;          // |b_a| [m/s^2]
  double max_gyro_bias = 1.0;           // |b_g| [rad/s]
  double max_position_jump_m = 5.0;     // newest position change between two frames [m]
  double max_z_jump_m = 1.0;            // newest z change between two frames [m]
  double max_speed_mps = 30.0;          // |v_W| of the newest frame [m/s]
  double max_rotation_jump_deg = 50.0;  // newest orientation change between two frames [deg]
  int min_tracked_features = 2;         // fewer tracked features than this ...
  int max_lost_frames = 20;             // ... in this many consecutive frames

  template <class V>
  void Visit(V& v) {
    using config::Bounds;
    v.Field("max_accel_bias", max_accel_bias, "failure when the norm of b_a exceeds this [m/s^2]",
            Bounds::Positive());
    v.Field("max_gyro_bias", max_gyro_bias, "failure when the norm of b_g exceeds this [rad/s]",
            Bounds::Positive());
    v.Field("max_position_jump_m", max_position_jump_m,
            "failure when the newest position moves more than this between two frames [m]",
            Bounds::Positive());
    v.Field("max_z_jump_m", max_z_jump_m,
            "failure when the newest z moves more than this between two frames [m]", Bounds::Positive());
    v.Field("max_speed_mps", max_speed_mps, "failure when the newest frame's speed exceeds this [m/s]",
            Bounds::Positive());
    v.Field("max_rotation_jump_deg", max_rotation_jump_deg,
            "failure when the newest orientation turns more than this between two frames [deg]",
            Bounds::Closed(1.0, 180.0));
    v.Field("min_tracked_features", min_tracked_features,
            "failure when fewer already-known features than this are tracked into max_lost_frames "
            "consecutive frames (0: off)",
            Bounds::NonNegative());
    v.Field("max_lost_frames", max_lost_frames,
            "consecutive frames with fewer than min_tracked_features tracked features before a failure",
            Bounds::AtLeast(1));
  }
};

struct EstimatorOptions {
  InitMode init = InitMode::kGroundTruth;
  GroundTruthInitOptions groundtruth_init;
  VinsInitOptions vins;
  WindowOptions window;
  PriorOptions prior;
  FeatureOptions features;
  SolverOptions solver;
  FailureOptions failure;
  ImuNoiseModelOptions imu_noise;
  MitigationOptions mitigation;
  ZeroVelocityOptions zero_velocity;
  bool pose_covariance = true;  // compute each output pose's covariance (pose_covariance.h; NEES)
  // With pose_covariance, compute the covariance at most this many times per second of solved frames (0:
  // at every solved frame; solved_frames.h's rule); the poses between have no covariance and do not enter
  // the NEES. The estimate is the same at any rate: the covariance is an output only. At every frame it
  // took a third of the estimator's time in a paper run; at 10 Hz (every third frame of a 30 Hz camera) the
  // NEES of paper seeds 1-10 is 3.59 / 1.56 against 3.56 / 1.56 (docs/results/2026-12-estimator-speed.md,
  // "Seventh round").
  double covariance_rate_hz = 10.0;
  // The estimator solves at most this many camera frames per second, from the first frame on (0: every
  // frame). A frame is solved when at least 0.9 of the period has passed since the last one the cap let
  // through (solved_frames.h); the others are left out. VINS-Mono's EuRoC configuration feeds its estimator
  // 10 frames per second of the camera's 20 (`freq: 10`), and 10 is the default: on every set without
  // glitches or with them removed a better or equal mean ATE at under half the CPU of every frame, but
  // unremoved large glitches cost more (docs/results/2026-12-estimator-speed.md, "Sixth round" and "Ninth
  // round").
  double max_frame_rate_hz = 10.0;
  // Under max_frame_rate_hz, output each frame left out as the IMU's prediction from the newest solved
  // state, without a covariance, so the trajectory keeps the camera's rate. Off (the default), the
  // trajectory has the solved frames only, as VINS-Mono's: the predictions carry the gyroscope's noise
  // between solves (0.2 deg over 67 ms for the paper's IMU), which the relative yaw errors show.
  bool predict_between_solves = false;
  // Under max_frame_rate_hz, also solve each frame whose interval since the last solved frame holds a sample
  // a detector flagged (vigil's rule; solved_frames.h). A capped IMU factor spans three camera intervals, and
  // where its data is wrong (a DTW replacement, an unremoved glitch) a third of the vision holds it: on the
  // CI gate's N(50,10) cell the paper's dtw went from 1.26 to 1.69 m capped, 1.20 m with this rule
  // (docs/results/2026-12-estimator-speed.md, "Eighth round").
  bool solve_flagged_frames = true;

  template <class V>
  void Visit(V& v) {
    v.Enum("init", init,
           config::EnumNames<InitMode>{{"groundtruth", InitMode::kGroundTruth}, {"vins", InitMode::kVins}},
           "initialization: groundtruth (first window from ground truth) or vins (visual-inertial, no ground "
           "truth)");
    v.Section("groundtruth_init", groundtruth_init, "perturbation of the ground-truth initialization");
    v.Section("vins", vins, "visual-inertial initialization (init: vins)");
    v.Section("window", window, "sliding window and keyframe decision");
    v.Section("prior", prior, "initial IMU bias prior (from the initializer's estimate)");
    v.Section("features", features, "feature tracks: triangulation, reprojection noise, outliers");
    v.Section("solver", solver, "Ceres solve per frame");
    v.Section("failure", failure,
              "failure detection (groundtruth init: the run fails; vins: reset and re-init)");
    v.Section("imu_noise", imu_noise,
              "IMU noise model of the IMU factors (matched = the sensor's own densities, or set / mis-set)");
    v.Section("mitigation", mitigation, "in-estimator mitigation of bad IMU samples and factors");
    v.Section("zero_velocity", zero_velocity,
              "zero-velocity detection, update and static initialization (docs/estimator.md)");
    v.Field("pose_covariance", pose_covariance,
            "compute each output pose's covariance (the marginal of the newest frame of the window, relative "
            "to the position and yaw of the run's first frame) for the NEES");
    v.Field(
        "covariance_rate_hz", covariance_rate_hz,
        "with pose_covariance, compute the covariance at most this many times per second of solved frames "
        "(0: every solved frame); the poses between have none and do not enter the NEES [Hz]",
        config::Bounds::NonNegative());
    v.Field("max_frame_rate_hz", max_frame_rate_hz,
            "solve at most this many camera frames per second, from the first frame (0: every frame); the "
            "trajectory has the solved frames, unless predict_between_solves [Hz]",
            config::Bounds::NonNegative());
    v.Field("predict_between_solves", predict_between_solves,
            "under max_frame_rate_hz, output each frame left out as the IMU's prediction from the newest "
            "solved state, without a covariance, so the trajectory keeps the camera's rate");
    v.Field("solve_flagged_frames", solve_flagged_frames,
            "under max_frame_rate_hz, also solve each frame whose interval since the last solved frame holds "
            "a sample a detector flagged");
  }
};

}  // namespace vigil::estimator
