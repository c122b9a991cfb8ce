// Marginalize(): the prior it builds against the Schur complement of the full normal equations, and the
// previous prior's information form against the same prior entering as a residual block.
#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <set>
#include <vector>

#include <ceres/loss_function.h>
#include <ceres/sized_cost_function.h>
#include <gtest/gtest.h>
#include <Eigen/QR>

#include "core/so3.h"
#include "estimator/marginalization.h"
#include "estimator/pose_manifold.h"
#include "estimator/reprojection_factor.h"
#include "tests/estimator/synthetic_window.h"

namespace vigil::estimator {
namespace {

using RowMajorMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

std::vector<double> Pose(const Eigen::Vector3d& p, const Eigen::Quaterniond& q) {
  return {p.x(), p.y(), p.z(), q.x(), q.y(), q.z(), q.w()};
}

// r = A [x_1; ...; x_k] + c over vector blocks: a residual block whose normal equations are known exactly.
class LinearCost : public ceres::CostFunction {
 public:
  LinearCost(const std::vector<int>& sizes, Eigen::MatrixXd A, Eigen::VectorXd c)
      : A_(std::move(A)), c_(std::move(c)) {
    set_num_residuals(static_cast<int>(A_.rows()));
    for (const int s : sizes) mutable_parameter_block_sizes()->push_back(s);
  }
  bool Evaluate(double const* const* parameters, double* residuals, double** jacobians) const override {
    Eigen::VectorXd x(A_.cols());
    for (std::size_t k = 0, c = 0; k < parameter_block_sizes().size(); ++k)
      for (int i = 0; i < parameter_block_sizes()[k]; ++i) x[static_cast<int>(c++)] = parameters[k][i];
    Eigen::Map<Eigen::VectorXd>(residuals, num_residuals()) = A_ * x + c_;
    if (jacobians == nullptr) return true;
    for (std::size_t k = 0, c = 0; k < parameter_block_sizes().size(); ++k) {
      const int size = parameter_block_sizes()[k];
      if (jacobians[k] != nullptr)
        Eigen::Map<RowMajorMatrix>(jacobians[k], num_residuals(), size) = A_.middleCols(c, size);
      c += size;
    }
    return true;
  }

 private:
  Eigen::MatrixXd A_;
  Eigen::VectorXd c_;
};

// Residuals and Jacobians (rows x ambient size per block) of `cost` at `blocks`.
void EvaluateCost(const ceres::CostFunction& cost, const std::vector<const double*>& blocks,
                  Eigen::VectorXd* r, std::vector<RowMajorMatrix>* jac) {
  const int rows = cost.num_residuals();
  std::vector<double*> jac_ptr;
  jac->clear();
  for (const int32_t size : cost.parameter_block_sizes()) jac->emplace_back(rows, size);
  for (RowMajorMatrix& j : *jac) jac_ptr.push_back(j.data());
  r->resize(rows);
  ASSERT_TRUE(cost.Evaluate(blocks.data(), r->data(), jac_ptr.data()));
}

// The Schur complement (S, b_S) of `dropped` in the normal equations of `terms` (no loss functions), columns
// in the order of `kept`; the dropped part through a pseudo-inverse.
void DirectSchur(const std::vector<MarginalizationTerm>& terms, const std::vector<double*>& dropped,
                 const std::vector<double*>& kept, Eigen::MatrixXd* S, Eigen::VectorXd* b_S) {
  std::map<const double*, int> column;
  int m = 0, n = 0;
  std::map<const double*, int> size_of;
  for (const MarginalizationTerm& t : terms)
    for (std::size_t k = 0; k < t.blocks.size(); ++k)
      size_of[t.blocks[k]] = t.cost->parameter_block_sizes()[k];
  for (double* b : dropped) {
    column[b] = m;
    m += TangentSizeOf(size_of.at(b));
  }
  for (double* b : kept) {
    column[b] = m + n;
    n += TangentSizeOf(size_of.at(b));
  }
  Eigen::MatrixXd H = Eigen::MatrixXd::Zero(m + n, m + n);
  Eigen::VectorXd g = Eigen::VectorXd::Zero(m + n);
  for (const MarginalizationTerm& t : terms) {
    const int rows = t.cost->num_residuals();
    const std::vector<int32_t>& sizes = t.cost->parameter_block_sizes();
    Eigen::VectorXd r;
    std::vector<RowMajorMatrix> jac;
    EvaluateCost(*t.cost, {t.blocks.begin(), t.blocks.end()}, &r, &jac);
    Eigen::MatrixXd J = Eigen::MatrixXd::Zero(rows, m + n);
    for (std::size_t k = 0; k < t.blocks.size(); ++k)
      J.middleCols(column.at(t.blocks[k]), TangentSizeOf(sizes[k])) +=
          jac[k].leftCols(TangentSizeOf(sizes[k]));
    H += J.transpose() * J;
    g += J.transpose() * r;
  }
  const Eigen::MatrixXd pinv = H.topLeftCorner(m, m).completeOrthogonalDecomposition().pseudoInverse();
  *S = H.bottomRightCorner(n, n) - H.bottomLeftCorner(n, m) * pinv * H.topRightCorner(m, n);
  *b_S = g.tail(n) - H.bottomLeftCorner(n, m) * pinv * g.head(m);
}

// Two dropped scalars in one residual block cannot be eliminated as independent pivots; with an uncoupled
// scalar and a dropped vector block beside them, the prior is still the Schur complement.
TEST(MarginalizationTest, CoupledScalarsGiveTheDirectSchurComplement) {
  std::vector<double> s1 = {0.3}, s2 = {-0.2}, s3 = {0.7}, v = {0.1, -0.4}, k = {0.5, 0.2, -0.1};
  const LinearCost t12({1, 1, 3}, Eigen::MatrixXd::Random(5, 5), Eigen::VectorXd::Random(5));
  const LinearCost t1v({1, 2, 3}, Eigen::MatrixXd::Random(4, 6), Eigen::VectorXd::Random(4));
  const LinearCost t3({1, 3}, Eigen::MatrixXd::Random(3, 4), Eigen::VectorXd::Random(3));
  const LinearCost tk({3}, Eigen::MatrixXd::Random(3, 3), Eigen::VectorXd::Random(3));
  const std::vector<MarginalizationTerm> terms = {{&t12, nullptr, {s1.data(), s2.data(), k.data()}},
                                                  {&t1v, nullptr, {s1.data(), v.data(), k.data()}},
                                                  {&t3, nullptr, {s3.data(), k.data()}},
                                                  {&tk, nullptr, {k.data()}}};
  LinearPrior prior;
  ASSERT_TRUE(Marginalize(nullptr, terms, {s1.data(), s2.data(), s3.data(), v.data()}, 1e-8, &prior));
  ASSERT_EQ(prior.blocks.size(), 1u);
  EXPECT_EQ(prior.blocks[0].address, k.data());
  Eigen::MatrixXd S;
  Eigen::VectorXd b_S;
  DirectSchur(terms, {s1.data(), s2.data(), s3.data(), v.data()}, {k.data()}, &S, &b_S);
  EXPECT_LT((prior.J.transpose() * prior.J - S).norm(), 1e-6 * S.norm());
  EXPECT_LT((prior.J.transpose() * prior.r - b_S).norm(), 1e-6 * (1.0 + b_S.norm()));
  // The information form is the same quadratic.
  EXPECT_LT((prior.H - prior.J.transpose() * prior.J).norm(), 1e-10 * S.norm());
  EXPECT_LT((prior.g - prior.J.transpose() * prior.r).norm(), 1e-10 * (1.0 + b_S.norm()));
}

// r = weight [p - p0; Log(q0^-1 q)]: an absolute pose measurement, so that a window of reprojections has no
// free gauge and its Schur complements are well conditioned.
class PoseAnchor : public ceres::SizedCostFunction<6, kPoseSize> {
 public:
  PoseAnchor(std::vector<double> pose0, double weight) : pose0_(std::move(pose0)), weight_(weight) {}
  bool Evaluate(double const* const* parameters, double* residuals, double** jacobians) const override {
    const Eigen::Vector3d phi = LogQ(PoseQ(pose0_.data()).conjugate() * PoseQ(parameters[0]));
    Eigen::Map<Eigen::Matrix<double, 6, 1>> r(residuals);
    r.head<3>() = weight_ * (PoseP(parameters[0]) - PoseP(pose0_.data()));
    r.tail<3>() = weight_ * phi;
    if (jacobians != nullptr && jacobians[0] != nullptr) {
      Eigen::Map<Eigen::Matrix<double, 6, 7, Eigen::RowMajor>> jac(jacobians[0]);
      jac.setZero();
      jac.block<3, 3>(0, 0) = weight_ * Eigen::Matrix3d::Identity();
      jac.block<3, 3>(3, 3) = weight_ * RightJacobianInverse(phi);
    }
    return true;
  }

 private:
  std::vector<double> pose0_;
  double weight_;
};

// Normalized observation of landmark l_W from a camera at `pose` (camera frame = body frame).
Eigen::Vector2d Observe(const std::vector<double>& pose, const Eigen::Vector3d& l_W) {
  const Eigen::Vector3d p_C = PoseQ(pose.data()).conjugate() * (l_W - PoseP(pose.data()));
  return p_C.head<2>() / p_C.z();
}

// The previous prior enters Marginalize through its information form, relinearized at the blocks' current
// values; that must equal passing it as a MarginalizationFactor residual block, rotations included.
TEST(MarginalizationTest, PreviousPriorEntersAsItsFactorWould) {
  const Eigen::Isometry3d T_BC = Eigen::Isometry3d::Identity();
  std::vector<double> pose_a = Pose(Eigen::Vector3d(0, 0, 0), ExpQ(Eigen::Vector3d(0.01, 0.02, 0.1)));
  std::vector<double> pose_b = Pose(Eigen::Vector3d(0.3, 0.1, -0.05), ExpQ(Eigen::Vector3d(0.0, 0.05, 0.2)));
  std::vector<double> pose_c = Pose(Eigen::Vector3d(0.6, -0.2, 0.05), ExpQ(Eigen::Vector3d(0.05, 0.0, 0.3)));
  const ceres::CauchyLoss loss(1.0);
  const PoseAnchor anchor(pose_a, 100.0);
  // Features anchored in a (observed in b and c) and in b (observed in c), with measurement noise so that
  // the residuals and gradients are not zero.
  std::vector<std::unique_ptr<ReprojectionFactor>> factors;
  std::vector<std::vector<double>> depths_a, depths_b;
  std::vector<MarginalizationTerm> terms_a, terms_b;
  const double noise = 0.002;
  // Inverse depth of l_W in `pose`, off by 1 % per feature index.
  auto inverse_depth = [](const std::vector<double>& pose, const Eigen::Vector3d& l_W, int i) {
    const Eigen::Vector3d p_C = PoseQ(pose.data()).conjugate() * (l_W - PoseP(pose.data()));
    return std::vector<double>{(1.0 + 0.01 * i) / p_C.z()};
  };
  std::vector<Eigen::Vector3d> landmarks;
  for (int i = 0; i < 8; ++i) {
    landmarks.emplace_back(-1.0 + 0.3 * i, 0.5 * std::sin(i), 3.0 + 0.4 * i);
    depths_a.push_back(inverse_depth(pose_a, landmarks[i], i));
    depths_b.push_back(inverse_depth(pose_b, landmarks[i], i));
  }
  for (int i = 0; i < 8; ++i) {  // after the depths: their addresses are final
    const Eigen::Vector3d& l_W = landmarks[i];
    const Eigen::Vector2d e(noise * std::cos(3.0 * i), noise * std::sin(5.0 * i));
    const ceres::LossFunction* l = i % 2 == 0 ? &loss : nullptr;
    for (std::vector<double>* seen : {&pose_b, &pose_c}) {
      factors.push_back(
          std::make_unique<ReprojectionFactor>(Observe(pose_a, l_W), Observe(*seen, l_W) + e, T_BC, 300.0));
      terms_a.push_back({factors.back().get(), l, {pose_a.data(), seen->data(), depths_a[i].data()}});
    }
    factors.push_back(
        std::make_unique<ReprojectionFactor>(Observe(pose_b, l_W), Observe(pose_c, l_W) - e, T_BC, 300.0));
    terms_b.push_back({factors.back().get(), l, {pose_b.data(), pose_c.data(), depths_b[i].data()}});
  }
  terms_a.push_back({&anchor, nullptr, {pose_a.data()}});
  DroppedBlocks dropped_a = {pose_a.data()}, dropped_b = {pose_b.data()};
  for (int i = 0; i < 8; ++i) {
    dropped_a.push_back(depths_a[i].data());
    dropped_b.push_back(depths_b[i].data());
  }
  auto first = std::make_shared<LinearPrior>();
  ASSERT_TRUE(Marginalize(nullptr, terms_a, dropped_a, 1e-8, first.get()));
  ASSERT_EQ(first->blocks.size(), 2u);  // pose_b, pose_c

  // Move the kept blocks away from the prior's linearization point, rotations included.
  PoseManifold manifold;
  std::vector<double> moved(kPoseSize);
  const Eigen::Matrix<double, 6, 1> db =
      (Eigen::Matrix<double, 6, 1>() << 0.02, -0.01, 0.03, 0.05, -0.04, 0.1).finished();
  manifold.Plus(pose_b.data(), db.data(), moved.data());
  pose_b = moved;
  const Eigen::Matrix<double, 6, 1> dc =
      (Eigen::Matrix<double, 6, 1>() << -0.03, 0.02, 0.01, -0.08, 0.03, 0.06).finished();
  manifold.Plus(pose_c.data(), dc.data(), moved.data());
  pose_c = moved;

  LinearPrior from_information;
  ASSERT_TRUE(Marginalize(first.get(), terms_b, dropped_b, 1e-8, &from_information));
  // In information form only: the same H and g, bit for bit (the Cholesky succeeds here), and no J or r.
  LinearPrior information_only;
  ASSERT_TRUE(MarginalizeInformation(first.get(), terms_b, dropped_b, 1e-8, &information_only));
  EXPECT_EQ(information_only.H, from_information.H);
  EXPECT_EQ(information_only.g, from_information.g);
  EXPECT_EQ(information_only.J.size(), 0);
  EXPECT_EQ(information_only.r.size(), 0);
  ASSERT_EQ(information_only.blocks.size(), from_information.blocks.size());
  for (std::size_t k = 0; k < information_only.blocks.size(); ++k) {
    EXPECT_EQ(information_only.blocks[k].address, from_information.blocks[k].address);
    EXPECT_EQ(information_only.blocks[k].x0, from_information.blocks[k].x0);
  }
  const MarginalizationFactor factor(first);
  const std::vector<double*> factor_blocks = factor.parameter_blocks();
  std::vector<MarginalizationTerm> with_factor = {
      {&factor, nullptr, {factor_blocks.begin(), factor_blocks.end()}}};
  with_factor.insert(with_factor.end(), terms_b.begin(), terms_b.end());
  LinearPrior from_factor;
  ASSERT_TRUE(Marginalize(nullptr, with_factor, dropped_b, 1e-8, &from_factor));

  ASSERT_EQ(from_information.blocks.size(), 1u);
  ASSERT_EQ(from_factor.blocks.size(), 1u);
  EXPECT_EQ(from_information.blocks[0].address, pose_c.data());
  const Eigen::MatrixXd H = from_factor.J.transpose() * from_factor.J;
  const Eigen::VectorXd g = from_factor.J.transpose() * from_factor.r;
  EXPECT_GT(H.diagonal().minCoeff(), 1.0);  // the anchor reaches c: a well-conditioned prior
  EXPECT_GT(g.norm(), 1e-2);                // the move made a gradient to compare
  EXPECT_LT((from_information.J.transpose() * from_information.J - H).norm(), 1e-9 * H.norm());
  EXPECT_LT((from_information.J.transpose() * from_information.r - g).norm(), 1e-9 * g.norm());
}

// A prior alone (a frame dropped between keyframes) is eliminated from its information at the current values:
// the same as the general elimination of the prior entered as its factor.
TEST(MarginalizationTest, APriorAloneGivesWhatItsFactorGives) {
  testing::SyntheticWindow w(11);  // a prior on frame 1's pose and frame 2's states, away from its x0
  const auto prior = std::make_shared<LinearPrior>(w.prior);
  const DroppedBlocks dropped = {w.pose_blocks[2]};
  SchurComplement alone;
  ASSERT_TRUE(EliminateDropped(prior.get(), {}, dropped, 1e-8, &alone));
  const MarginalizationFactor factor(prior);
  const std::vector<double*> factor_blocks = factor.parameter_blocks();
  SchurComplement from_factor;
  ASSERT_TRUE(EliminateDropped(nullptr, {{&factor, nullptr, {factor_blocks.begin(), factor_blocks.end()}}},
                               dropped, 1e-8, &from_factor));
  ASSERT_EQ(alone.blocks.size(), 2u);
  ASSERT_EQ(from_factor.blocks.size(), 2u);
  for (std::size_t k = 0; k < 2; ++k) {
    EXPECT_EQ(alone.blocks[k].address, from_factor.blocks[k].address);
    EXPECT_EQ(alone.blocks[k].x0, from_factor.blocks[k].x0);
  }
  EXPECT_EQ(alone.blocks[0].address, w.pose_blocks[1]);
  EXPECT_EQ(alone.blocks[1].address, w.speed_bias_blocks[2]);
  EXPECT_GT(from_factor.g.norm(), 1e-2);  // away from x0: a gradient to compare
  EXPECT_LT((alone.H - from_factor.H).norm(), 1e-10 * from_factor.H.norm());
  EXPECT_LT((alone.g - from_factor.g).norm(), 1e-10 * from_factor.g.norm());
}

// The rows of J below its diagonal are zero: what PriorFactors() relies on.
void ExpectUpperTrapezoidal(const Eigen::MatrixXd& J) {
  ASSERT_LE(J.rows(), J.cols());
  EXPECT_EQ(Eigen::MatrixXd(J.triangularView<Eigen::StrictlyLower>()).norm(), 0.0);
}

// The values of blocks first, first + 1, ... as a factor's parameters.
std::vector<const double*> From(const std::vector<std::vector<double>>& values, std::size_t first) {
  std::vector<const double*> out;
  for (std::size_t k = first; k < values.size(); ++k) out.push_back(values[k].data());
  return out;
}

// PriorFactors() cut the prior into pieces by its triangle: stacked, they are the whole factor, and the whole
// factor's Jacobian is zero where a piece has no block.
TEST(MarginalizationTest, PriorFactorsStackToTheWholePrior) {
  std::vector<double> pose_a = Pose(Eigen::Vector3d(0.1, 0.2, 0.3), ExpQ(Eigen::Vector3d(0.01, 0.02, 0.1)));
  std::vector<double> v = {0.3, -0.1, 0.2};
  std::vector<double> pose_b = Pose(Eigen::Vector3d(0.6, -0.2, 0.05), ExpQ(Eigen::Vector3d(0.05, 0.0, 0.3)));
  auto prior = std::make_shared<LinearPrior>();
  for (std::vector<double>* b : {&pose_a, &v, &pose_b}) {
    const int size = static_cast<int>(b->size());
    prior->blocks.push_back({b->data(), size, TangentSizeOf(size), *b});
  }
  // Fewer rows than columns (a prior with a dropped direction): the last block gets only part of its rows.
  prior->J = Eigen::MatrixXd(Eigen::MatrixXd::Random(13, 15).triangularView<Eigen::Upper>());
  prior->r = Eigen::VectorXd::Random(13);
  // Evaluate away from x0, rotations included.
  const PoseManifold manifold;
  std::vector<std::vector<double>> values = {pose_a, {0.35, -0.12, 0.1}, pose_b};
  const Eigen::Matrix<double, 6, 1> d =
      (Eigen::Matrix<double, 6, 1>() << 0.02, -0.01, 0.03, 0.2, -0.1, 0.1).finished();
  manifold.Plus(pose_a.data(), d.data(), values[0].data());
  manifold.Plus(pose_b.data(), (-d).eval().data(), values[2].data());

  const MarginalizationFactor whole(prior);
  Eigen::VectorXd r_whole;
  std::vector<RowMajorMatrix> jac_whole;
  EvaluateCost(whole, From(values, 0), &r_whole, &jac_whole);
  EXPECT_GT(r_whole.norm(), 0.1);

  const auto pieces = PriorFactors(prior);
  ASSERT_EQ(pieces.size(), 3u);
  int row = 0;
  for (std::size_t p = 0; p < pieces.size(); ++p) {
    const std::size_t first = prior->blocks.size() - pieces[p]->parameter_block_sizes().size();
    EXPECT_EQ(first, p);
    EXPECT_EQ(pieces[p]->parameter_blocks().front(), prior->blocks[first].address);
    Eigen::VectorXd r;
    std::vector<RowMajorMatrix> jac;
    EvaluateCost(*pieces[p], From(values, first), &r, &jac);
    const int rows = pieces[p]->num_residuals();
    EXPECT_LT((r - r_whole.segment(row, rows)).norm(), 1e-12 * r_whole.norm());
    for (std::size_t k = 0; k < values.size(); ++k) {
      const RowMajorMatrix whole_rows = jac_whole[k].middleRows(row, rows);
      if (k < first)
        EXPECT_EQ(whole_rows.norm(), 0.0) << "piece " << p << " block " << k;
      else
        EXPECT_LT((jac[k - first] - whole_rows).norm(), 1e-12 * (1.0 + whole_rows.norm()));
    }
    row += rows;
  }
  EXPECT_EQ(row, 13);
}

// Marginalize() leaves J upper trapezoidal, from the Cholesky factor and from the eigen-decomposition that
// replaces it when the Schur complement is not positive definite (here: a previous prior with a negative
// eigenvalue, which the eigen-decomposition drops).
TEST(MarginalizationTest, PriorIsUpperTrapezoidal) {
  std::vector<double> s = {0.3}, k1 = {0.5, 0.2, -0.1}, k2 = {0.1, -0.4, 0.3};
  const LinearCost t1({1, 3, 3}, Eigen::MatrixXd::Random(5, 7), Eigen::VectorXd::Random(5));
  const LinearCost t2({3, 3}, Eigen::MatrixXd::Random(6, 6), Eigen::VectorXd::Random(6));
  LinearPrior regular;
  ASSERT_TRUE(Marginalize(
      nullptr, {{&t1, nullptr, {s.data(), k1.data(), k2.data()}}, {&t2, nullptr, {k1.data(), k2.data()}}},
      {s.data()}, 1e-8, &regular));
  ASSERT_EQ(regular.J.rows(), 6);
  ExpectUpperTrapezoidal(regular.J);

  LinearPrior indefinite;
  indefinite.blocks = {{k1.data(), 3, 3, k1}, {k2.data(), 3, 3, k2}};
  const Eigen::Matrix<double, 6, 6> V =
      Eigen::HouseholderQR<Eigen::Matrix<double, 6, 6>>(Eigen::Matrix<double, 6, 6>::Random()).householderQ();
  Eigen::Matrix<double, 6, 1> eigenvalues;
  eigenvalues << 4.0, 3.0, 2.0, 1.0, 5.0, -0.5;
  indefinite.H = V * eigenvalues.asDiagonal() * V.transpose();
  indefinite.g = Eigen::VectorXd::Random(6);
  const LinearCost ts({1}, Eigen::MatrixXd::Ones(1, 1), Eigen::VectorXd::Zero(1));
  LinearPrior fallback;
  ASSERT_TRUE(Marginalize(&indefinite, {{&ts, nullptr, {s.data()}}}, {s.data()}, 1e-8, &fallback));
  ASSERT_EQ(fallback.J.rows(), 5);  // the negative eigenvalue is dropped
  ExpectUpperTrapezoidal(fallback.J);
  eigenvalues[5] = 0.0;
  const Eigen::MatrixXd psd_part = V * eigenvalues.asDiagonal() * V.transpose();
  EXPECT_LT((fallback.J.transpose() * fallback.J - psd_part).norm(), 1e-9);
  EXPECT_LT((fallback.H - psd_part).norm(), 1e-9);
  // The gradient keeps its part in the kept directions.
  EXPECT_LT((fallback.J.transpose() * fallback.r -
             psd_part * psd_part.completeOrthogonalDecomposition().pseudoInverse() * indefinite.g)
                .norm(),
            1e-9);
}

// A term that evaluates to a value that is not finite makes the marginalization fail, even where the
// elimination would skip it (a dropped depth whose only information is that term).
TEST(MarginalizationTest, ANonFiniteTermFails) {
  std::vector<double> s = {0.3}, k = {0.5, 0.2, -0.1};
  const LinearCost kept({3}, Eigen::MatrixXd::Identity(3, 3), Eigen::VectorXd::Zero(3));
  Eigen::MatrixXd A = Eigen::MatrixXd::Random(2, 4);
  A(0, 0) = A(1, 0) = std::nan("");
  const LinearCost bad_jacobian({1, 3}, A, Eigen::VectorXd::Zero(2));
  const LinearCost bad_residual({1, 3}, Eigen::MatrixXd::Random(2, 4),
                                Eigen::Vector2d(std::numeric_limits<double>::infinity(), 0.0));
  for (const LinearCost* bad : {&bad_jacobian, &bad_residual}) {
    LinearPrior prior;
    EXPECT_FALSE(Marginalize(nullptr, {{&kept, nullptr, {k.data()}}, {bad, nullptr, {s.data(), k.data()}}},
                             {s.data()}, 1e-8, &prior));
    SchurComplement schur;
    EXPECT_FALSE(EliminateDropped(nullptr,
                                  {{&kept, nullptr, {k.data()}}, {bad, nullptr, {s.data(), k.data()}}},
                                  {s.data()}, 1e-8, &schur));
  }
  LinearPrior prior;
  EXPECT_TRUE(Marginalize(nullptr, {{&kept, nullptr, {k.data()}}}, {}, 1e-8, &prior));
}

TEST(TermBlocksTest, HoldsUpToItsCapacityInOrder) {
  double x[7];
  const TermBlocks blocks = {&x[0], &x[1], &x[2]};
  ASSERT_EQ(blocks.size(), 3u);
  EXPECT_EQ(std::vector<double*>(blocks.begin(), blocks.end()), (std::vector<double*>{&x[0], &x[1], &x[2]}));
  TermBlocks full;
  for (std::size_t k = 0; k < TermBlocks::kCapacity; ++k) full.push_back(&x[k]);
  EXPECT_EQ(full[TermBlocks::kCapacity - 1], &x[TermBlocks::kCapacity - 1]);
  EXPECT_THROW(full.push_back(&x[6]), std::length_error);
}

}  // namespace
}  // namespace vigil::estimator
