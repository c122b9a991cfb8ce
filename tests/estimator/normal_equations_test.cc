// NormalEquations: the split sparse/dense accumulation equals the dense J^T J, J^T r of the same terms, and
// eliminating the scalars gives the dense Schur complement.
#include "estimator/normal_equations.h"

#include <cstdlib>
#include <vector>

#include <gtest/gtest.h>
#include <Eigen/Dense>

#include "estimator/pose_manifold.h"

namespace vigil::estimator {
namespace {

// Blocks: two scalars (0, 1: dropped, uncoupled), a dropped 3-vector (2), a kept pose (3) and a kept 9-vector
// (4). Dense columns: block 2 at 0, block 3 at 3, block 4 at 9 (18 in all).
std::vector<Column> Columns() {
  std::vector<Column> c(5);
  c[0] = {nullptr, 1, 1, true, false, 0, -1};
  c[1] = {nullptr, 1, 1, true, false, 1, -1};
  c[2] = {nullptr, 3, 3, true, false, -1, 0};
  c[3] = {nullptr, kPoseSize, kPoseTangentSize, false, false, -1, 3};
  c[4] = {nullptr, 9, 9, false, false, -1, 9};
  return c;
}

// The position of block k in the full (scalars first) ordering: 2 scalars, then the dense columns.
int FullColumn(const Column& c) { return c.scalar >= 0 ? c.scalar : 2 + c.column; }

struct Term {
  std::vector<int> indices;
  Eigen::MatrixXd J;
  Eigen::VectorXd r;
};

std::vector<Term> Terms(const std::vector<Column>& columns) {
  std::srand(7);
  std::vector<Term> terms;
  for (const std::vector<int>& indices :
       std::vector<std::vector<int>>{{0, 3, 4}, {1, 2, 3}, {2, 3, 4}, {3, 4}, {0, 4}, {1, 3}}) {
    int width = 0;
    for (const int i : indices) width += columns[i].tangent;
    terms.push_back({indices, Eigen::MatrixXd::Random(width + 2, width), Eigen::VectorXd::Random(width + 2)});
  }
  return terms;
}

// The dense normal equations of all terms over the full ordering.
void Dense(const std::vector<Column>& columns, const std::vector<Term>& terms, Eigen::MatrixXd* H,
           Eigen::VectorXd* b) {
  *H = Eigen::MatrixXd::Zero(20, 20);
  *b = Eigen::VectorXd::Zero(20);
  for (const Term& t : terms) {
    Eigen::MatrixXd J = Eigen::MatrixXd::Zero(t.J.rows(), 20);
    for (std::size_t k = 0, c = 0; k < t.indices.size(); ++k) {
      const Column& col = columns[t.indices[k]];
      J.middleCols(FullColumn(col), col.tangent) = t.J.middleCols(c, col.tangent);
      c += col.tangent;
    }
    *H += J.transpose() * J;
    *b += J.transpose() * t.r;
  }
}

NormalEquations Accumulate(const std::vector<Column>& columns, const std::vector<Term>& terms) {
  NormalEquations eq;
  eq.Resize(2, 18, 3);
  for (const Term& t : terms)
    eq.AddTerm(columns, {t.indices.data(), static_cast<int>(t.indices.size())}, t.J.transpose() * t.J,
               t.J.transpose() * t.r);
  return eq;
}

TEST(NormalEquationsTest, AccumulatesTheDenseNormalEquations) {
  const std::vector<Column> columns = Columns();
  const std::vector<Term> terms = Terms(columns);
  Eigen::MatrixXd H;
  Eigen::VectorXd b;
  Dense(columns, terms, &H, &b);
  const NormalEquations eq = Accumulate(columns, terms);
  const Eigen::MatrixXd dense_upper = eq.H.triangularView<Eigen::Upper>();
  const Eigen::MatrixXd expected_upper = H.bottomRightCorner(18, 18).triangularView<Eigen::Upper>();
  EXPECT_LT((dense_upper - expected_upper).norm(), 1e-12 * H.norm());
  EXPECT_LT((eq.b - b.tail(18)).norm(), 1e-12 * b.norm());
  for (int s = 0; s < 2; ++s) {
    EXPECT_NEAR(eq.h[s], H(s, s), 1e-12 * H.norm());
    EXPECT_NEAR(eq.bs[s], b[s], 1e-12 * b.norm());
    // The row's reached blocks hold the information; the expected row is zero everywhere else.
    Eigen::VectorXd row = Eigen::VectorXd::Zero(18);
    for (const int i : eq.ReachOf(s))
      row.segment(columns[i].column, columns[i].tangent) =
          eq.Hs.row(s).segment(columns[i].column, columns[i].tangent).transpose();
    EXPECT_LT((row.transpose() - H.row(s).tail(18)).norm(), 1e-12 * H.norm());
  }
  EXPECT_EQ(H(0, 1), 0.0);  // the scalars share no term
  // Scalar 0 reaches the pose and the 9-vector, scalar 1 the 3-vector and the pose.
  auto reach = [&](int scalar) {
    return std::vector<int>(eq.ReachOf(scalar).begin(), eq.ReachOf(scalar).end());
  };
  EXPECT_EQ(reach(0), (std::vector<int>{3, 4}));
  EXPECT_EQ(reach(1), (std::vector<int>{2, 3}));
}

TEST(NormalEquationsTest, EliminatingTheScalarsGivesTheSchurComplement) {
  const std::vector<Column> columns = Columns();
  const std::vector<Term> terms = Terms(columns);
  Eigen::MatrixXd H;
  Eigen::VectorXd b;
  Dense(columns, terms, &H, &b);
  const Eigen::MatrixXd Hss = H.topLeftCorner(2, 2), Hsd = H.topRightCorner(2, 18);
  const Eigen::MatrixXd S = H.bottomRightCorner(18, 18) - Hsd.transpose() * Hss.inverse() * Hsd;
  const Eigen::VectorXd bS = b.tail(18) - Hsd.transpose() * Hss.inverse() * b.head(2);

  NormalEquations eq = Accumulate(columns, terms);
  eq.EliminateScalars(columns, 1e-8);
  const Eigen::MatrixXd upper = eq.H.triangularView<Eigen::Upper>();
  const Eigen::MatrixXd expected = S.triangularView<Eigen::Upper>();
  EXPECT_LT((upper - expected).norm(), 1e-10 * S.norm());
  EXPECT_LT((eq.b - bS).norm(), 1e-10 * bS.norm());

  // A pivot at or below the threshold counts as zero: nothing is eliminated.
  NormalEquations kept = Accumulate(columns, terms);
  const Eigen::MatrixXd before = kept.H;
  kept.EliminateScalars(columns, 1e9);
  EXPECT_EQ(kept.H, before);
}

}  // namespace
}  // namespace vigil::estimator
