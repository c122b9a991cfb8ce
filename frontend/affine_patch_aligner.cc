#include "frontend/affine_patch_aligner.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Eigenvalues>

namespace vigil::frontend {
namespace {

// A patch whose Hessian's eigenvalues span more than this ratio cannot fix all six parameters (an edge, a
// blank wall).
constexpr double kMinEigenvalueRatio = 1e-6;

bool Inside(const cv::Mat& image, float x, float y) {
  return x >= 0.0f && y >= 0.0f && x < static_cast<float>(image.cols - 1) && y < static_cast<float>(image.rows - 1);
}

// Bilinear intensity at (x, y); the caller checks Inside.
float Sample(const cv::Mat& image, float x, float y) {
  const int x0 = static_cast<int>(x), y0 = static_cast<int>(y);
  const float fx = x - static_cast<float>(x0), fy = y - static_cast<float>(y0);
  const uchar* row0 = image.ptr<uchar>(y0) + x0;
  const uchar* row1 = image.ptr<uchar>(y0 + 1) + x0;
  const float top = static_cast<float>(row0[0]) + fx * static_cast<float>(row0[1] - row0[0]);
  const float bottom = static_cast<float>(row1[0]) + fx * static_cast<float>(row1[1] - row1[0]);
  return top + fy * (bottom - top);
}

}  // namespace

std::optional<AffinePatch> MakeAffinePatch(const cv::Mat& image, const cv::Point2f& centre_px, int half) {
  const float reach = static_cast<float>(half + 1);
  if (!Inside(image, centre_px.x - reach, centre_px.y - reach) ||
      !Inside(image, centre_px.x + reach, centre_px.y + reach))
    return std::nullopt;
  // Intensities on the patch grid with a one-pixel rim, for central-difference gradients.
  const int side = 2 * half + 3;
  std::vector<float> grid(static_cast<std::size_t>(side * side));
  for (int r = 0; r < side; ++r)
    for (int k = 0; k < side; ++k)
      grid[static_cast<std::size_t>(r * side + k)] = Sample(image, centre_px.x + static_cast<float>(k - half - 1),
                                                            centre_px.y + static_cast<float>(r - half - 1));
  AffinePatch patch;
  patch.half = half;
  const int n = 2 * half + 1;
  patch.intensity.reserve(static_cast<std::size_t>(n * n));
  patch.steepest.reserve(static_cast<std::size_t>(n * n));
  Eigen::Matrix<double, 6, 6> hessian = Eigen::Matrix<double, 6, 6>::Zero();
  for (int v = -half; v <= half; ++v) {
    for (int u = -half; u <= half; ++u) {
      const auto at = [&](int du, int dv) {
        return grid[static_cast<std::size_t>((v + half + 1 + dv) * side + (u + half + 1 + du))];
      };
      const float gx = 0.5f * (at(1, 0) - at(-1, 0)), gy = 0.5f * (at(0, 1) - at(0, -1));
      const float fu = static_cast<float>(u), fv = static_cast<float>(v);
      Eigen::Matrix<float, 6, 1> sd;
      sd << gx, gy, gx * fu, gx * fv, gy * fu, gy * fv;
      patch.intensity.push_back(at(0, 0));
      patch.steepest.push_back(sd);
      hessian += sd.cast<double>() * sd.cast<double>().transpose();
    }
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, 6, 6>> eigen(hessian);
  const Eigen::Matrix<double, 6, 1>& values = eigen.eigenvalues();  // ascending
  if (!(values(5) > 0.0) || values(0) < kMinEigenvalueRatio * values(5)) return std::nullopt;
  patch.hessian_inverse = eigen.eigenvectors() * values.cwiseInverse().asDiagonal() * eigen.eigenvectors().transpose();
  return patch;
}

std::optional<AffineWarp> AlignAffinePatch(const AffinePatch& patch, const cv::Mat& image, const AffineWarp& start,
                                           const AffineAlignOptions& options) {
  const int half = patch.half;
  const float h = static_cast<float>(half);
  const cv::Point2f corners[] = {{-h, -h}, {h, -h}, {-h, h}, {h, h}};
  cv::Matx22f A = start.linear;
  cv::Point2f c = start.centre_px;
  for (int iteration = 0; iteration < options.max_iterations; ++iteration) {
    // The warped patch lies inside the image when its four corners do (an affine image of a square).
    for (const cv::Point2f& corner : corners) {
      const cv::Point2f p = A * corner + c;
      if (!Inside(image, p.x, p.y)) return std::nullopt;
    }
    // Gauss-Newton step of the inverse-compositional problem: dp = H^-1 sum_u sd(u) (I(W(u)) - T(u)).
    Eigen::Matrix<double, 6, 1> b = Eigen::Matrix<double, 6, 1>::Zero();
    std::size_t i = 0;
    for (int v = -half; v <= half; ++v) {
      const float fv = static_cast<float>(v);
      Eigen::Matrix<float, 6, 1> row_sum = Eigen::Matrix<float, 6, 1>::Zero();
      for (int u = -half; u <= half; ++u, ++i) {
        const float fu = static_cast<float>(u);
        const float x = A(0, 0) * fu + A(0, 1) * fv + c.x, y = A(1, 0) * fu + A(1, 1) * fv + c.y;
        row_sum += patch.steepest[i] * (Sample(image, x, y) - patch.intensity[i]);
      }
      b += row_sum.cast<double>();
    }
    const Eigen::Matrix<double, 6, 1> dp = patch.hessian_inverse * b;
    // W <- W o W(dp)^-1, W(dp): u -> (I + D) u + d.
    const cv::Matx22d D(1.0 + dp(2), dp(3), dp(4), 1.0 + dp(5));
    const double det = D(0, 0) * D(1, 1) - D(0, 1) * D(1, 0);
    if (!(std::abs(det) > 1e-6)) return std::nullopt;
    const cv::Matx22d D_inv(D(1, 1) / det, -D(0, 1) / det, -D(1, 0) / det, D(0, 0) / det);
    const cv::Matx22f A_new = A * cv::Matx22f(D_inv);
    const cv::Vec2d shift = cv::Matx22d(A_new) * cv::Vec2d(dp(0), dp(1));
    const cv::Point2f c_new = c - cv::Point2f(static_cast<float>(shift[0]), static_cast<float>(shift[1]));
    // Convergence: the largest motion of a patch corner in this step.
    float moved = 0.0f;
    for (const cv::Point2f& corner : corners)
      moved = std::max(moved, static_cast<float>(cv::norm((A_new - A) * corner + (c_new - c))));
    A = A_new;
    c = c_new;
    if (!std::isfinite(moved)) return std::nullopt;
    if (moved < static_cast<float>(options.epsilon_px)) return AffineWarp{A, c};
  }
  return std::nullopt;
}

}  // namespace vigil::frontend
