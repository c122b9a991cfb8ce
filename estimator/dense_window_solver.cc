#include "estimator/dense_window_solver.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>

#include "estimator/pose_manifold.h"
#include "estimator/window_factorization.h"

namespace vigil::estimator {
namespace {

// Levenberg-Marquardt's trust region as Ceres runs it: the damping is diag(H) / radius (the diagonal
// clamped to [1e-6, 1e32]), the radius grows after a good step and shrinks, ever faster, after a bad one.
// The window's position and yaw are unobservable (the estimator holds them after the solve), so H is
// singular along them and the damping decides how far a step moves the window there. The initial damping
// of 1e-8 diag(H) is the regularization of the Gauss-Newton step in Ceres' dogleg, which the Ceres solve
// takes: with it the two solves give the same trajectories (paper seeds 1-10, 4 decimals of the ATE). Ceres'
// Levenberg-Marquardt default, 1e-4, damps the gauge enough to change them (ATE 0.0317 -> 0.0453 m on seed
// 1); an undamped step (1e-12) moves the window's position freely (position NEES 2.3 -> 8.5).
constexpr double kInitialRadius = 1e8;
constexpr double kMaxRadius = 1e16;
constexpr double kMinDiagonal = 1e-6;
constexpr double kMaxDiagonal = 1e32;
constexpr double kMinRelativeDecrease = 1e-3;  // a step's actual decrease over its model's, to accept it

double LossOf(const ceres::LossFunction* loss, double s) {
  if (loss == nullptr) return s;
  double rho[3];
  loss->Evaluate(s, rho);
  return rho[0];
}

// The window's states, points and depths, to undo a rejected step.
class Snapshot {
 public:
  explicit Snapshot(const DenseWindowProblem& p) : p_(p) {}
  void Save() {
    values_.clear();
    for (const double* pose : p_.poses) values_.insert(values_.end(), pose, pose + kPoseSize);
    for (const double* sb : p_.speed_biases) values_.insert(values_.end(), sb, sb + kSpeedBiasSize);
    for (const double* point : p_.points) values_.insert(values_.end(), point, point + kPointSize);
    for (const auto& track : p_.tracks) values_.push_back(*track.inv_depth);
  }
  void Restore() const {
    const double* v = values_.data();
    for (double* pose : p_.poses) {
      std::copy_n(v, kPoseSize, pose);
      v += kPoseSize;
    }
    for (double* sb : p_.speed_biases) {
      std::copy_n(v, kSpeedBiasSize, sb);
      v += kSpeedBiasSize;
    }
    for (double* point : p_.points) {
      std::copy_n(v, kPointSize, point);
      v += kPointSize;
    }
    for (const auto& track : p_.tracks) *track.inv_depth = *v++;
  }

 private:
  const DenseWindowProblem& p_;
  std::vector<double> values_;
};

// The normal equations at the current values, with each depth's eliminated row.
struct Linearization {
  Eigen::MatrixXd H;
  Eigen::VectorXd g;
  std::vector<WindowInformation::EliminatedDepth> depths;
  // The depths' elimination (WindowInformation::depth_fill_H/g: fill_H over the poses alone), which H and
  // g hold subtracted.
  Eigen::MatrixXd fill_H;
  Eigen::VectorXd fill_g;
  Eigen::VectorXd diagonal;  // of the states' information before the depths' elimination: the damping's
  int residuals = 0;
};

bool Linearize(const DenseWindowProblem& p, Linearization* out) {
  WindowInformation info(p.poses, p.speed_biases, p.points);
  out->residuals = 0;
  for (const MarginalizationTerm& f : p.factors) {
    if (!info.AddTerm(f)) return false;
    out->residuals += f.cost->num_residuals();
  }
  info.SeparateDepthFill();
  out->depths.resize(p.tracks.size());
  for (std::size_t i = 0; i < p.tracks.size(); ++i) {
    const auto& reps = p.tracks[i].reprojections;
    if (!info.AddTrack(reps.data(), reps.data() + reps.size(), p.reprojection_loss, p.eigen_threshold,
                       &out->depths[i]))
      return false;
    out->residuals += 2 * static_cast<int>(reps.size());
  }
  if (p.prior) {
    if (!info.AddPrior(*p.prior)) return false;
    out->residuals += static_cast<int>(p.prior->r.size());
  }
  out->fill_H = info.depth_fill_H();
  out->fill_g = info.depth_fill_g();
  out->H = std::move(info.mutable_H());
  WindowInformation::AddPoseBlocks(out->fill_H, -1.0, &out->H);
  out->g = info.g() - out->fill_g;
  if (p.hold_oldest_pose) {
    out->H.topRows<kPoseTangentSize>().setZero();
    out->H.leftCols<kPoseTangentSize>().setZero();
    out->H.topLeftCorner<kPoseTangentSize, kPoseTangentSize>().setIdentity();
    out->g.head<kPoseTangentSize>().setZero();
    // A held pose has no step: the depths' couplings to it drop out too.
    out->fill_H.topRows<kPoseTangentSize>().setZero();
    out->fill_H.leftCols<kPoseTangentSize>().setZero();
    out->fill_g.head<kPoseTangentSize>().setZero();
    for (WindowInformation::EliminatedDepth& d : out->depths)
      d.w.erase(std::remove_if(d.w.begin(), d.w.end(),
                               [](const auto& column_w) { return column_w.first < kPoseTangentSize; }),
                d.w.end());
  }
  out->diagonal = out->H.diagonal();
  for (int k = 0; k < static_cast<int>(p.poses.size()); ++k)
    out->diagonal.segment<kPoseTangentSize>(WindowInformation::PoseColumn(k)) +=
        out->fill_H.diagonal().segment<kPoseTangentSize>(WindowInformation::FillColumn(k));
  return out->H.allFinite() && out->g.allFinite();
}

// The damping of each depth, as Ceres damps every block: its pivot (clamped) / radius.
double DepthDamping(const WindowInformation::EliminatedDepth& d, double radius) {
  return std::clamp(d.h_dd, kMinDiagonal, kMaxDiagonal) / radius;
}

// The damped system over the states: the depths are eliminated with their damped pivots h_dd + lambda_d, so
// the Schur complement the linearization holds (undamped pivots) gains c_d = 1/h_dd - 1/(h_dd + lambda_d)
// times each track's w w^T and w b_d. With lambda_d = h_dd / radius (a pivot within the clamp), c_d h_dd =
// 1 / (radius + 1) for every track: the linearization's whole fill, scaled once. Only a pivot below the
// clamp is corrected on its own.
void DampedSystem(const Linearization& lin, double radius, Eigen::MatrixXd* A, Eigen::VectorXd* b) {
  const double scale = 1.0 / (radius + 1.0);
  *A = lin.H;
  WindowInformation::AddPoseBlocks(lin.fill_H, scale, A);
  A->diagonal() += lin.diagonal.cwiseMax(kMinDiagonal).cwiseMin(kMaxDiagonal) / radius;
  *b = -lin.g - scale * lin.fill_g;
  for (const WindowInformation::EliminatedDepth& d : lin.depths) {
    if (d.h_dd == 0.0 || d.h_dd >= kMinDiagonal) continue;
    const double c = 1.0 / d.h_dd - 1.0 / (d.h_dd + DepthDamping(d, radius)) - scale / d.h_dd;
    for (const auto& [p, w_p] : d.w) {
      b->segment<kPoseTangentSize>(p) -= c * d.b_d * w_p;
      for (const auto& [q, w_q] : d.w)
        A->block<kPoseTangentSize, kPoseTangentSize>(p, q) += c * w_p * w_q.transpose();
    }
  }
}

// The damped depth steps for the states' step dx, and the decrease the undamped Gauss-Newton model of the
// whole problem (states and depths) predicts for the step.
double DepthStepsAndModelDecrease(const Linearization& lin, const Eigen::VectorXd& dx, double radius,
                                  std::vector<double>* depth_steps) {
  // The model over states and depths is the states' Schur model (H, g) plus, per depth,
  // (coupling + h_dd dd)^2 / (2 h_dd) - b_d^2 / (2 h_dd).
  double model = lin.g.dot(dx) + 0.5 * dx.dot(lin.H * dx);
  depth_steps->assign(lin.depths.size(), 0.0);
  for (std::size_t i = 0; i < lin.depths.size(); ++i) {
    const WindowInformation::EliminatedDepth& d = lin.depths[i];
    if (d.h_dd == 0.0) continue;
    const double coupling = d.Coupling(dx);
    const double dd = -coupling / (d.h_dd + DepthDamping(d, radius));
    (*depth_steps)[i] = dd;
    model += ((coupling + d.h_dd * dd) * (coupling + d.h_dd * dd) - d.b_d * d.b_d) / (2.0 * d.h_dd);
  }
  return -model;
}

// Moves the states and points by dx and the depths by their steps.
bool ApplyStep(const DenseWindowProblem& p, const Eigen::VectorXd& dx, const std::vector<double>& depth_steps,
               const ceres::Manifold& pose_manifold) {
  double moved[kPoseSize];
  for (std::size_t k = 0; k < p.poses.size(); ++k) {
    if (!pose_manifold.Plus(p.poses[k], dx.data() + WindowInformation::PoseColumn(static_cast<int>(k)),
                            moved))
      return false;
    std::copy_n(moved, kPoseSize, p.poses[k]);
    Eigen::Map<Eigen::Matrix<double, kSpeedBiasSize, 1>>(p.speed_biases[k]) +=
        dx.segment<kSpeedBiasSize>(WindowInformation::SpeedBiasColumn(static_cast<int>(k)));
  }
  const int frames = static_cast<int>(p.poses.size());
  for (std::size_t j = 0; j < p.points.size(); ++j)
    Eigen::Map<Eigen::Matrix<double, kPointSize, 1>>(p.points[j]) +=
        dx.segment<kPointSize>(WindowInformation::PointColumn(frames, static_cast<int>(j)));
  for (std::size_t i = 0; i < p.tracks.size(); ++i) *p.tracks[i].inv_depth += depth_steps[i];
  return true;
}

}  // namespace

bool DenseWindowCost(const DenseWindowProblem& p, double* cost) {
  double total = 0.0;
  std::vector<double> r;
  for (const MarginalizationTerm& f : p.factors) {
    r.resize(f.cost->num_residuals());
    if (!f.cost->Evaluate(f.blocks.data(), r.data(), nullptr)) return false;
    total += LossOf(f.loss, Eigen::Map<const Eigen::VectorXd>(r.data(), r.size()).squaredNorm());
  }
  for (const auto& track : p.tracks)
    for (const auto& rep : track.reprojections) {
      Eigen::Vector2d r2;
      if (!rep.factor->Evaluate(rep.blocks.data(), r2.data(), nullptr)) return false;
      total += LossOf(p.reprojection_loss, r2.squaredNorm());
    }
  if (p.prior) {
    // A non-owning handle: the factor evaluates the caller's prior.
    const MarginalizationFactor factor(
        std::shared_ptr<const LinearPrior>(std::shared_ptr<const LinearPrior>(), p.prior));
    const std::vector<double*> blocks = factor.parameter_blocks();
    r.resize(p.prior->r.size());
    if (!factor.Evaluate(blocks.data(), r.data(), nullptr)) return false;
    total += Eigen::Map<const Eigen::VectorXd>(r.data(), r.size()).squaredNorm();
  }
  *cost = 0.5 * total;
  return std::isfinite(*cost);
}

DenseSolveSummary SolveDenseWindow(const DenseWindowProblem& p, const DenseSolveOptions& options,
                                   const ceres::Manifold& pose_manifold) {
  DenseSolveSummary summary;
  double cost = 0.0;
  if (!DenseWindowCost(p, &cost)) {
    summary.message = "the initial cost is not finite";
    return summary;
  }
  summary.initial_cost = summary.final_cost = cost;
  summary.usable = true;
  Snapshot snapshot(p);
  Linearization lin;
  Eigen::MatrixXd A;
  Eigen::VectorXd b;
  WindowFactorization factorization;
  std::vector<double> depth_steps;
  bool relinearize = true;
  double radius = kInitialRadius, decrease_factor = 2.0;
  const auto start = std::chrono::steady_clock::now();
  const auto out_of_time = [&] {
    return options.max_time_s > 0.0 &&
           std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() >
               options.max_time_s;
  };
  for (int iteration = 0; iteration < options.max_iterations && !out_of_time(); ++iteration) {
    if (relinearize) {
      if (!Linearize(p, &lin)) {
        summary.message = "a factor failed or gave non-finite numbers";
        return summary;
      }
      relinearize = false;
    }
    DampedSystem(lin, radius, &A, &b);
    bool accepted = false;
    double new_cost = cost;
    if (factorization.Compute(A, static_cast<int>(p.points.size()))) {
      const Eigen::VectorXd dx = factorization.Solve(b);
      const double model_decrease = DepthStepsAndModelDecrease(lin, dx, radius, &depth_steps);
      snapshot.Save();
      if (dx.allFinite() && model_decrease > 0.0 && ApplyStep(p, dx, depth_steps, pose_manifold) &&
          DenseWindowCost(p, &new_cost)) {
        const double rho = (cost - new_cost) / model_decrease;
        if (rho > kMinRelativeDecrease) {
          accepted = true;
          radius = std::min(kMaxRadius, radius / std::max(1.0 / 3.0, 1.0 - std::pow(2.0 * rho - 1.0, 3)));
          decrease_factor = 2.0;
        }
      }
      if (!accepted) snapshot.Restore();
    }
    if (!accepted) {
      ++summary.unsuccessful_steps;
      radius /= decrease_factor;
      decrease_factor *= 2.0;
      continue;
    }
    ++summary.successful_steps;
    const double change = cost - new_cost;
    cost = new_cost;
    summary.final_cost = cost;
    relinearize = true;
    if (change <= options.function_tolerance * (cost + change)) break;
    if (options.accepted_steps > 0 && summary.successful_steps >= options.accepted_steps &&
        cost <= 0.5 * lin.residuals)
      break;
  }
  return summary;
}

}  // namespace vigil::estimator
