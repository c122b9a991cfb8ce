// The sliding-window visual-inertial estimator (VINS-Mono design, written for vigil).
//
// Frame by frame: AddFrame() preintegrates the IMU since the previous frame, adds the feature observations,
// decides whether the second newest frame is a keyframe (parallax / track count), and
//   - before initialization, hands the window to the Initializer until it succeeds;
//   - afterwards, triangulates new tracks, optimizes the window (IMU factors, reprojection factors with
//     Cauchy loss, marginalization prior, and the initial bias prior until its frame leaves the window) with
//     Ceres, removes outliers, checks for failure, and when the window holds size + 1 frames marginalizes the
//     oldest frame (keyframe) or the second newest (not a keyframe).
// The pieces live in their own files: estimator.cc (frame flow, initialization, failure handling),
// estimator_optimize.cc (the Ceres problem), estimator_marginalize.cc (sliding the window).
#pragma once

#include <array>
#include <cstdint>
#include <deque>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <ceres/loss_function.h>
#include <ceres/solver.h>
#include <Eigen/Core>

#include "core/camera.h"
#include "core/types.h"
#include "estimator/bias_prior_factor.h"
#include "estimator/estimator_input.h"
#include "estimator/estimator_options.h"
#include "estimator/feature_manager.h"
#include "estimator/imu_gating.h"
#include "estimator/initializer.h"
#include "estimator/marginalization.h"
#include "estimator/oldest_frame_marginalization.h"
#include "estimator/pose_covariance.h"
#include "estimator/pose_manifold.h"
#include "estimator/preintegration.h"
#include "estimator/reprojection_factor.h"
#include "estimator/reprojection_factor_cache.h"

namespace vigil::estimator {

// What happened to one frame.
enum class FrameStatus {
  kWaitingForInit,  // collected for the initializer; no state yet
  kTracking,        // optimized; newest_state() is valid
  kReset,           // a failure was detected and the window was cleared; re-initialization follows
  kFailed,          // a failure that cannot be recovered (failure_reason() says why); stop feeding frames
};

class Estimator {
 public:
  // Benchmarks time the stages of one frame on a fixed window through it (bench/estimator_stages.h).
  friend class EstimatorStages;

  Estimator(const EstimatorOptions& options, const CameraModel& camera, const ImuNoiseDensities& noise,
            double gravity_mps2, double imu_rate_hz, std::unique_ptr<Initializer> initializer);
  ~Estimator();

  // Processes the camera frame at t_ns with its features (id -> normalized point). `imu` must cover the time
  // from the previous frame to t_ns; `imu_variance_scale` (null or one per sample of `imu`): each sample's
  // white-noise variance scale in preintegration (imu_trust.h).
  FrameStatus AddFrame(int64_t t_ns, const std::map<int, Eigen::Vector2d>& features_n, const ImuStream& imu,
                       const std::vector<double>* imu_variance_scale = nullptr);

  NavState newest_state() const;
  // The newest state carried to t_ns (after the newest frame, covered by `imu`) by the IMU with the newest
  // biases, as the next frame's solve starts from it; valid once initialized (solved_frames.h).
  NavState PredictedState(int64_t t_ns, const ImuStream& imu,
                          const std::vector<double>* imu_variance_scale = nullptr) const;
  // The newest state's pose covariance (pose_covariance.h) after the frame AddFrame returned kTracking for;
  // empty when options.pose_covariance is off or it could not be computed.
  const std::optional<Matrix6d>& newest_pose_covariance() const { return newest_pose_covariance_; }
  bool initialized() const { return initialized_; }
  const std::string& failure_reason() const { return failure_reason_; }
  int resets() const { return resets_; }
  // How often each failure check fired (reset or stop), by name: "accel_bias", "gyro_bias", "speed",
  // "position_jump", "z_jump", "rotation_jump", "lost_tracks", "non_finite", "solver".
  const std::map<std::string, int>& failure_checks() const { return failure_checks_; }
  int keyframes() const { return keyframes_; }
  // Marginalizations that failed (nothing left to keep, or non-finite numbers): the prior was dropped.
  int marginalization_failures() const { return marginalization_failures_; }
  const EstimatorTiming& timing() const { return timing_; }
  const GatingStats& gating() const { return gating_; }
  std::optional<int64_t> initialized_at_ns() const { return initialized_at_ns_; }
  // The initializer's last failure reason (empty when it never ran or never failed).
  const std::string& init_failure_reason() const { return init_failure_reason_; }
  // Frames the initialization window holds (initialization waits until it is full).
  int window_frames() const { return WindowCapacity(); }

 private:
  struct Frame {
    uint64_t id = 0;
    int64_t t_ns = 0;
    double pose[kPoseSize] = {0, 0, 0, 0, 0, 0, 1};
    double speed_bias[kSpeedBiasSize] = {};
    std::optional<Preintegration> imu_from_prev;
    std::map<int, Eigen::Vector2d> features_n;
    // The interval from the previous window frame stands still (zero_velocity_detector.h); computed only
    // when NeedsStationarity().
    bool stationary = false;

    NavState State() const;
    void SetState(const NavState& s);
  };

  bool TryInitialize();
  // The keyframe criterion's mean parallax between two window frames (normalized plane), with the rotation
  // compensated when options_.window.parallax_compensates_rotation and the window has states.
  double KeyframeParallax(const Frame& older, const Frame& newer) const;
  void Predict(Frame* frame) const;
  // `s` carried over the interval `pre` integrates (its end at t_ns).
  NavState Propagate(const NavState& s, const Preintegration& pre, int64_t t_ns) const;
  // Builds and solves the window problem; false with a reason when the solver fails.
  bool Optimize(bool marginalize_oldest_next, std::string* reason);
  // Optimize's steps (estimator_optimize.cc), in the order it takes them.
  struct Elimination;
  struct WindowProblem;
  void RepropagateImuFactors();
  Elimination PlanElimination();
  void AddStateBlocks(const Elimination& elimination, WindowProblem* w);
  void AddPriors(WindowProblem* w);
  void AddImuFactors(WindowProblem* w);
  // Zero-velocity factors on the stationary intervals (zero_velocity_factor.h), when the update is on or a
  // static start is held.
  void AddZeroVelocityFactors(WindowProblem* w);
  // The window's IMU factors and zero-velocity factors over `speed_bias` (frame k's block or a solve's copy
  // of it), in the order a solve adds them; `costs` owns them.
  void AppendImuTerms(const std::vector<double*>& speed_bias,
                      std::vector<std::unique_ptr<ceres::CostFunction>>* costs,
                      std::vector<ImuTerm>* imu_terms);
  void AppendZeroVelocityTerms(const std::vector<double*>& speed_bias,
                               std::vector<std::unique_ptr<ceres::CostFunction>>* costs,
                               std::vector<MarginalizationTerm>* terms);
  // The window's solve by the dense Levenberg-Marquardt of dense_window_solver.h (SolverOptions::backend:
  // dense), with the factors of Optimize; false with a reason when it fails (estimator_optimize_dense.cc).
  bool OptimizeDense(bool marginalize_oldest_next, std::string* reason);
  bool ZeroVelocityActive() const { return options_.zero_velocity.update || holding_still_; }
  // Whether a new frame's interval must be tested for standing still: for the update, and for a static start
  // (the window before initialization, and while it is held still). The flags are read nowhere else.
  bool NeedsStationarity() const { return options_.zero_velocity.update || InStaticStart(); }
  // Whether the estimate lets the interval from `older` to `newer` stand still for the update: both frames
  // at most zero_velocity.max_speed_mps.
  bool SlowEnoughToStand(const Frame& older, const Frame& newer) const;
  // The static start's time: before initialization, and while it holds the window still.
  bool InStaticStart() const {
    return options_.zero_velocity.static_init && (!initialized_ || holding_still_);
  }
  // The zero-velocity terms that involve the oldest frame (for its marginalization); `costs` owns them.
  void AppendOldestZeroVelocityTerms(std::vector<std::unique_ptr<ceres::CostFunction>>* costs,
                                     std::vector<MarginalizationTerm>* terms);
  void AddReprojectionFactors(const Elimination& elimination, WindowProblem* w);
  void AddPointFactors(WindowProblem* w);
  ceres::Solver::Summary SolveAndGate(ceres::Solver::Options solver_options, WindowProblem* w);
  void HoldGauge(const NavState& oldest_before);
  // A failure check that fired: its name (failure_checks()) and what it saw; `check` empty when none did.
  struct Failure {
    std::string check;
    std::string reason;
  };
  // The checks of FailureOptions on the window after a solve; `previous` is the frame before the newest as it
  // was before the solve.
  Failure DetectFailure(const NavState& previous) const;
  // After a tracked frame's solve: the newest pose's covariance when one is due, then the slide (the oldest
  // frame leaves after a keyframe, else the second newest) once the window is full.
  void CovarianceAndSlide(int64_t t_ns, bool keyframe, bool full);
  // The factors that involve the oldest frame (window size >= 2), with the usable tracks anchored in it,
  // whose depths its marginalization eliminates, and those tracks' ids; `costs` owns the factors built for
  // it.
  struct OldestFrameTerms {
    std::vector<std::unique_ptr<ceres::CostFunction>> costs;
    OldestFrame frame;
    std::vector<int> tracks;
  };
  OldestFrameTerms TermsOfOldest();
  // The oldest frame's terms, linearized once at the current estimate: for its marginalization, and for the
  // pose covariance when one is due at the same estimate (its share of the window's information).
  struct LinearizedOldest {
    explicit LinearizedOldest(Estimator& estimator);
    OldestFrameTerms terms;
    OldestFrameMarginalization marginalization;  // over terms.frame
  };
  // Drops the oldest frame; with `linearized` (else without a prior), its terms go into the priors, and the
  // lost points leave with it.
  void MarginalizeOldest(const LinearizedOldest* linearized);
  void MarginalizeSecondNewest(bool with_prior);
  // A marginalization of the window: the prior it leaves from `previous` (may be null), in `form`; false
  // when it fails.
  using PriorUpdate = std::function<bool(const LinearPrior* previous, PriorForm form, LinearPrior* prior)>;
  // prior_ := `update` of prior_ (square-root form); dropped (and counted) when that fails.
  void KeepPrior(const PriorUpdate& update);
  // anchored_prior_ := `update` of it (information form), starting from the gauge on the oldest frame when it
  // is null.
  void KeepAnchoredPrior(const PriorUpdate& update);
  void Reset();
  // window.oldest_tracks points (estimator_points.cc): the long tracks kept as landmark points in W.
  bool PointsOn() const { return options_.window.oldest_tracks == OldestTracks::kPoints; }
  bool IsPoint(int id) const { return points_W_.count(id) > 0; }
  // Whether track `id` enters the window by its inverse depth (usable, and not a point).
  bool IsDepthTrack(int id, const FeatureTrack& track) const {
    return features_.Usable(track) && !IsPoint(id);
  }
  // The points' blocks, in the order of their track ids.
  std::vector<double*> PointBlocks();
  // One PointReprojectionFactor (with the robust loss) per observation of each point in the window frames,
  // or in frame `frame_id` alone when it is given; `costs` owns them.
  void AppendPointTerms(std::vector<std::unique_ptr<ceres::CostFunction>>* costs,
                        std::vector<MarginalizationTerm>* terms, std::optional<uint64_t> frame_id = {});
  // Before the oldest frame's marginalization: the tracks anchored in it that qualify
  // (point_min_observations, point_min_baseline_ratio) become points, at their current depth.
  void MakePointsOfOldest();
  // Each point's track takes the depth of its point in its anchor frame (outlier tests and re-anchoring
  // read it).
  void SyncPointDepths();
  // Whether point `id`'s track ended; the lost points (their blocks). A lost point has no factors: only the
  // priors hold it until it is eliminated.
  bool PointIsLost(int id) const;
  std::vector<const double*> LostPoints() const;
  void ErasePoints(const std::vector<const double*>& points);
  // The lost points that cannot wait for the next keyframe's marginalization (one of the priors lacks them)
  // leave both priors now, and the window.
  void DropLostPoints();
  // The newest pose's covariance from the window's information (estimator_covariance.cc). `oldest` (may be
  // null): the information of the terms over the oldest frame, already linearized at the current estimate
  // (LinearizedOldest), which the covariance then adds instead of linearizing them again.
  std::optional<Matrix6d> NewestPoseCovariance(const WindowInformation* oldest = nullptr);
  // One reprojection factor per observation of track `id` after its anchor, with its parameter blocks
  // (anchor pose, observing pose, `inv_depth`: the track's inverse depth or the solve's copy of it), from
  // reprojection_factors_.
  using ReprojectionTerm = ReprojectionFactorCache::Term;
  void AppendReprojectionTerms(int id, const FeatureTrack& track, double* inv_depth,
                               std::vector<ReprojectionTerm>* terms);
  Eigen::Isometry3d T_WC(const Frame& frame) const;
  // T_WC of every window frame by id, as of this call (std::logic_error for another id).
  CameraPoseLookup CameraPoses() const;
  // The window frame `id` (std::logic_error when it is not in the window).
  Frame& FrameById(uint64_t id);
  int WindowCapacity() const { return options_.window.size + 1; }

  EstimatorOptions options_;
  CameraModel camera_;
  Eigen::Isometry3d T_BC_;
  ImuNoiseDensities noise_;
  Eigen::Vector3d g_W_;
  double imu_rate_hz_;
  std::unique_ptr<Initializer> initializer_;

  std::deque<std::unique_ptr<Frame>> window_;
  FeatureManager features_;
  std::shared_ptr<LinearPrior> prior_;
  // prior_ with the gauge of the run (pose_covariance.h): the first marginalization starts from the
  // information that holds the oldest frame's position and yaw, and every later one carries it on. Only the
  // pose covariance uses it; null before the first marginalization, after a reset, or when pose_covariance
  // is off.
  std::shared_ptr<LinearPrior> anchored_prior_;
  // The initial bias prior (options_.prior) on the oldest frame's speed-bias block, from initialization until
  // that frame is marginalized (its information then moves into prior_). Only MarginalizeOldest and Reset
  // remove the oldest frame, and both drop this prior, so while it exists it belongs to window_.front().
  std::unique_ptr<BiasPriorFactor> bias_prior_;
  // Each track's reprojection factors, kept across frames; pruned to the live tracks by Optimize.
  ReprojectionFactorCache reprojection_factors_;
  ceres::CauchyLoss loss_;
  PoseManifold pose_manifold_;

  bool initialized_ = false;
  // A static start holds the window still (no triangulation) until the first interval that moves.
  bool holding_still_ = false;
  uint64_t next_frame_id_ = 0;
  std::optional<int64_t> initialized_at_ns_;
  std::string failure_reason_;
  std::string init_failure_reason_;
  int resets_ = 0;
  int lost_frames_ = 0;  // consecutive frames with fewer than options_.failure.min_tracked_features tracks
  std::map<std::string, int> failure_checks_;
  int keyframes_ = 0;
  int marginalization_failures_ = 0;
  EstimatorTiming timing_;
  GatingStats gating_;
  std::optional<Matrix6d> newest_pose_covariance_;
  // window.oldest_tracks points: each point p_W by its track's id (stable addresses: a std::map).
  std::map<int, std::array<double, kPointSize>> points_W_;
  // The first frame time whose tracks may become points (point_settle_s after the last initialization).
  std::optional<int64_t> points_from_ns_;
  std::optional<int64_t> last_covariance_ns_;  // the newest frame a covariance was computed at
};

}  // namespace vigil::estimator
