#include "estimator/estimator.h"

#include <chrono>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

#include "core/format.h"
#include "estimator/imu_interval.h"
#include "estimator/solved_frames.h"
#include "estimator/zero_velocity_detector.h"

namespace vigil::estimator {
namespace {

double SecondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

bool AllFinite(const NavState& s) {
  return s.p_W.allFinite() && s.q_WB.coeffs().allFinite() && s.v_W.allFinite() && s.b_a.allFinite() &&
         s.b_g.allFinite();
}

}  // namespace

NavState Estimator::Frame::State() const {
  NavState s;
  s.t_ns = t_ns;
  s.p_W = PoseP(pose);
  s.q_WB = PoseQ(pose).normalized();
  s.v_W = Eigen::Map<const Eigen::Vector3d>(speed_bias);
  s.b_a = Eigen::Map<const Eigen::Vector3d>(speed_bias + 3);
  s.b_g = Eigen::Map<const Eigen::Vector3d>(speed_bias + 6);
  return s;
}

void Estimator::Frame::SetState(const NavState& s) {
  Eigen::Map<Eigen::Vector3d> p(pose), v(speed_bias), b_a(speed_bias + 3), b_g(speed_bias + 6);
  Eigen::Map<Eigen::Quaterniond> q(pose + 3);
  p = s.p_W;
  q = s.q_WB.normalized();
  v = s.v_W;
  b_a = s.b_a;
  b_g = s.b_g;
}

Estimator::Estimator(const EstimatorOptions& options, const CameraModel& camera,
                     const ImuNoiseDensities& noise, double gravity_mps2, double imu_rate_hz,
                     std::unique_ptr<Initializer> initializer)
    : options_(options),
      camera_(camera),
      T_BC_(camera.T_BC_iso()),
      noise_(noise),
      g_W_(0.0, 0.0, -gravity_mps2),
      imu_rate_hz_(imu_rate_hz),
      initializer_(std::move(initializer)),
      features_(options.features),
      reprojection_factors_(T_BC_, camera.fx / options.features.pixel_std_px),
      loss_(options.features.cauchy_scale) {}

Estimator::~Estimator() = default;

NavState Estimator::newest_state() const { return window_.back()->State(); }

Estimator::Frame& Estimator::FrameById(uint64_t id) {
  for (const auto& f : window_)
    if (f->id == id) return *f;
  throw std::logic_error("Estimator::FrameById: frame " + std::to_string(id) + " is not in the window");
}

Eigen::Isometry3d Estimator::T_WC(const Frame& f) const {
  Eigen::Isometry3d T_WB = Eigen::Isometry3d::Identity();
  T_WB.linear() = PoseQ(f.pose).normalized().toRotationMatrix();
  T_WB.translation() = PoseP(f.pose);
  return T_WB * T_BC_;
}

void Estimator::AppendReprojectionTerms(int id, const FeatureTrack& track, double* inv_depth,
                                        std::vector<ReprojectionTerm>* terms) {
  reprojection_factors_.AppendTerms(
      id, track, [this](uint64_t frame_id) { return FrameById(frame_id).pose; }, inv_depth, terms);
}

CameraPoseLookup Estimator::CameraPoses() const {
  // Computed once per call: feature bookkeeping looks poses up several times per observation.
  std::vector<std::pair<uint64_t, Eigen::Isometry3d>> poses;
  for (const auto& f : window_) poses.emplace_back(f->id, T_WC(*f));
  return [poses = std::move(poses)](uint64_t id) {
    for (const auto& [frame_id, T] : poses)
      if (frame_id == id) return T;
    throw std::logic_error("Estimator::CameraPoses: frame " + std::to_string(id) + " is not in the window");
  };
}

NavState Estimator::Propagate(const NavState& s, const Preintegration& pre, int64_t t_ns) const {
  const double T = pre.sum_dt_s();
  NavState next = s;
  next.t_ns = t_ns;
  next.p_W = s.p_W + s.v_W * T + 0.5 * g_W_ * T * T + s.q_WB * pre.delta_p();
  next.v_W = s.v_W + g_W_ * T + s.q_WB * pre.delta_v();
  next.q_WB = (s.q_WB * pre.delta_q()).normalized();
  return next;
}

void Estimator::Predict(Frame* frame) const {
  frame->SetState(Propagate(window_.back()->State(), *frame->imu_from_prev, frame->t_ns));
}

NavState Estimator::PredictedState(int64_t t_ns, const ImuStream& imu,
                                   const std::vector<double>* imu_variance_scale) const {
  const NavState s = newest_state();
  if (t_ns <= s.t_ns) return s;
  return Propagate(
      s, PreintegrateInterval(imu, s.t_ns, t_ns, s.b_a, s.b_g, noise_, imu_rate_hz_, imu_variance_scale),
      t_ns);
}

FrameStatus Estimator::AddFrame(int64_t t_ns, const std::map<int, Eigen::Vector2d>& features_n,
                                const ImuStream& imu, const std::vector<double>* imu_variance_scale) {
  auto frame = std::make_unique<Frame>();
  frame->id = next_frame_id_++;
  frame->t_ns = t_ns;
  frame->features_n = features_n;
  if (!window_.empty()) {
    const NavState prev = window_.back()->State();
    frame->imu_from_prev = PreintegrateInterval(imu, window_.back()->t_ns, t_ns, prev.b_a, prev.b_g, noise_,
                                                imu_rate_hz_, imu_variance_scale);
    if (initialized_) Predict(frame.get());
    if (NeedsStationarity()) {
      // The static start's tests in its time; the update's after, for what the estimate sees slow.
      const bool static_start = InStaticStart();
      frame->stationary = IntervalIsStationary(
          window_.back()->features_n, features_n, *frame->imu_from_prev, camera_.fx,
          static_start ? StaticStartTests(options_.zero_velocity) : options_.zero_velocity);
      if (frame->stationary && initialized_ && !static_start)
        frame->stationary = SlowEnoughToStand(*window_.back(), *frame);
    }
  }
  holding_still_ = holding_still_ && frame->stationary;
  const int tracked = features_.AddFrame(frame->id, features_n);
  lost_frames_ = tracked < options_.failure.min_tracked_features ? lost_frames_ + 1 : 0;
  window_.push_back(std::move(frame));

  // Is the second newest frame a keyframe? (then the oldest frame leaves the window, else the second newest)
  const std::size_t n = window_.size();
  const bool keyframe =
      n < 3 || tracked < options_.window.min_tracked_features ||
      KeyframeParallax(*window_[n - 3], *window_[n - 2]) >= options_.window.min_parallax_px / camera_.fx;
  const bool full = static_cast<int>(n) >= WindowCapacity();

  if (!initialized_) {
    // Initialization works on a full window (the Initializer contract).
    if (!full) return FrameStatus::kWaitingForInit;
    const auto start = std::chrono::steady_clock::now();
    const bool ok = TryInitialize();
    timing_.initialize_s += SecondsSince(start);
    if (!ok) {
      // A still platform makes no keyframes, so a window that held motion before the rest would keep that
      // motion's frames as long as the rest lasts, and the static start would never see a still window.
      // While the newest interval is still, the oldest frame leaves instead.
      const bool still_now = options_.zero_velocity.static_init && window_.back()->stationary;
      // No prior before initialization: the frame is dropped.
      if (keyframe || still_now)
        MarginalizeOldest(/*linearized=*/nullptr);
      else
        MarginalizeSecondNewest(/*with_prior=*/false);
      return FrameStatus::kWaitingForInit;
    }
  }

  const NavState previous = n >= 2 ? window_[n - 2]->State() : window_.back()->State();
  if (!holding_still_) features_.Triangulate(CameraPoses());
  Failure failure;
  const auto start = std::chrono::steady_clock::now();
  const bool solved = options_.solver.backend == SolverBackend::kDense
                          ? OptimizeDense(keyframe && full, &failure.reason)
                          : Optimize(keyframe && full, &failure.reason);
  timing_.optimize_s += SecondsSince(start);
  ++timing_.optimizations;
  if (solved) {
    SyncPointDepths();
    features_.RemoveOutliers(CameraPoses(), camera_.fx);
    DropLostPoints();
    failure = DetectFailure(previous);
  } else {
    failure.check = "solver";
  }
  if (!failure.check.empty()) {
    ++failure_checks_[failure.check];
    const std::string& reason = failure.reason;
    if (initializer_->CanReinitialize()) {
      Reset();
      ++resets_;
      return FrameStatus::kReset;
    }
    failure_reason_ = "at t = " + FormatFixed(NsToS(t_ns), 3) + " s: " + reason;
    return FrameStatus::kFailed;
  }
  CovarianceAndSlide(t_ns, keyframe, full);
  return FrameStatus::kTracking;
}

void Estimator::CovarianceAndSlide(int64_t t_ns, bool keyframe, bool full) {
  // After a keyframe the oldest frame leaves: its terms, linearized once at the solved estimate, serve its
  // marginalization and the covariance.
  std::optional<LinearizedOldest> oldest;
  const auto marg_start = std::chrono::steady_clock::now();
  if (full && keyframe) {
    if (PointsOn()) MakePointsOfOldest();
    oldest.emplace(*this);
  }
  timing_.marginalize_s += SecondsSince(marg_start);
  newest_pose_covariance_.reset();
  if (options_.pose_covariance &&
      (!last_covariance_ns_ || RateAllows(*last_covariance_ns_, t_ns, options_.covariance_rate_hz))) {
    last_covariance_ns_ = t_ns;
    const auto covariance_start = std::chrono::steady_clock::now();
    newest_pose_covariance_ = NewestPoseCovariance(oldest ? oldest->marginalization.information() : nullptr);
    timing_.covariance_s += SecondsSince(covariance_start);
  }
  if (full) {
    const auto slide_start = std::chrono::steady_clock::now();
    if (oldest)
      MarginalizeOldest(&*oldest);
    else
      MarginalizeSecondNewest(/*with_prior=*/true);
    DropLostPoints();
    timing_.marginalize_s += SecondsSince(slide_start);
    ++timing_.marginalizations;
  }
  if (keyframe && full) ++keyframes_;
}

double Estimator::KeyframeParallax(const Frame& older, const Frame& newer) const {
  // Before initialization the frames have no states: the raw displacement.
  if (!options_.window.parallax_compensates_rotation || !initialized_)
    return features_.MeanParallax(older.id, newer.id);
  const Eigen::Matrix3d R_CnewerColder = T_WC(newer).linear().transpose() * T_WC(older).linear();
  return features_.MeanParallax(older.id, newer.id, R_CnewerColder);
}

bool Estimator::TryInitialize() {
  std::vector<InitFrame> init_window;
  for (const auto& f : window_) init_window.push_back(InitFrame{f->t_ns, f->features_n, f->imu_from_prev});
  InitResult result;
  if (!initializer_->TryInitialize(init_window, &result)) {
    init_failure_reason_ = result.failure_reason;
    return false;
  }
  if (result.states.size() != window_.size()) {
    init_failure_reason_ = "the initializer returned " + std::to_string(result.states.size()) +
                           " states for a window of " + std::to_string(window_.size()) + " frames";
    return false;
  }
  for (std::size_t i = 0; i < window_.size(); ++i) {
    if (!AllFinite(result.states[i])) {
      init_failure_reason_ = "non-finite initial state";
      return false;
    }
    window_[i]->SetState(result.states[i]);
  }
  // Re-integrate the IMU from the initialized biases.
  for (std::size_t i = 1; i < window_.size(); ++i)
    window_[i]->imu_from_prev->Repropagate(result.states[i - 1].b_a, result.states[i - 1].b_g);
  for (const auto& [id, p_W] : result.landmarks_W) features_.SetPoint(id, p_W, CameraPoses());
  // The initializer's biases as a prior on the oldest frame (the bias factors carry it through the window).
  const PriorOptions& prior = options_.prior;
  if (prior.accel_bias_std > 0.0 || prior.gyro_bias_std > 0.0) {
    bias_prior_ = std::make_unique<BiasPriorFactor>(result.states.front().b_a, result.states.front().b_g,
                                                    prior.accel_bias_std, prior.gyro_bias_std);
  }
  // The update's intervals flagged before the window had velocities (a static start's are still).
  if (options_.zero_velocity.update && !result.stationary)
    for (std::size_t i = 1; i < window_.size(); ++i)
      window_[i]->stationary = window_[i]->stationary && SlowEnoughToStand(*window_[i - 1], *window_[i]);
  initialized_ = true;
  holding_still_ = result.stationary;
  if (!initialized_at_ns_) initialized_at_ns_ = window_.back()->t_ns;
  points_from_ns_ = window_.back()->t_ns + SToNs(options_.window.point_settle_s);
  return true;
}

bool Estimator::SlowEnoughToStand(const Frame& older, const Frame& newer) const {
  const double max_speed_mps = options_.zero_velocity.max_speed_mps;
  return older.State().v_W.norm() <= max_speed_mps && newer.State().v_W.norm() <= max_speed_mps;
}

Estimator::Failure Estimator::DetectFailure(const NavState& previous) const {
  for (const auto& f : window_) {
    const NavState s = f->State();
    if (!AllFinite(s)) return {"non_finite", "non-finite state"};
  }
  const NavState s = window_.back()->State();
  const FailureOptions& o = options_.failure;
  if (s.b_a.norm() > o.max_accel_bias)
    return {"accel_bias", "accelerometer bias norm " + FormatFixed(s.b_a.norm(), 3) + " m/s^2"};
  if (s.b_g.norm() > o.max_gyro_bias)
    return {"gyro_bias", "gyro bias norm " + FormatFixed(s.b_g.norm(), 3) + " rad/s"};
  if (s.v_W.norm() > o.max_speed_mps) return {"speed", "speed " + FormatFixed(s.v_W.norm(), 3) + " m/s"};
  const double jump_m = (s.p_W - previous.p_W).norm();
  if (jump_m > o.max_position_jump_m)
    return {"position_jump", "position jump " + FormatFixed(jump_m, 3) + " m"};
  const double z_jump_m = std::abs(s.p_W.z() - previous.p_W.z());
  if (z_jump_m > o.max_z_jump_m) return {"z_jump", "z jump " + FormatFixed(z_jump_m, 3) + " m"};
  const double turn_deg = s.q_WB.angularDistance(previous.q_WB) * 180.0 / M_PI;
  if (turn_deg > o.max_rotation_jump_deg)
    return {"rotation_jump", "rotation jump " + FormatFixed(turn_deg, 1) + " deg"};
  if (lost_frames_ >= o.max_lost_frames)
    return {"lost_tracks", "fewer than " + std::to_string(o.min_tracked_features) + " tracked features in " +
                               std::to_string(lost_frames_) + " frames"};
  return {};
}

void Estimator::Reset() {
  window_.clear();
  features_.Clear();
  reprojection_factors_.Clear();
  prior_.reset();
  anchored_prior_.reset();
  bias_prior_.reset();
  points_W_.clear();
  points_from_ns_.reset();
  initialized_ = false;
  holding_still_ = false;
  lost_frames_ = 0;
}

}  // namespace vigil::estimator
