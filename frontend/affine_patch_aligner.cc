#include "frontend/affine_patch_aligner.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include <Eigen/Eigenvalues>

namespace vigil::frontend {
namespace {

// A patch whose Hessian's eigenvalues span more than this ratio cannot fix all six parameters (an edge, a
// blank wall).
constexpr double kMinEigenvalueRatio = 1e-6;

bool Inside(const cv::Mat& image, float x, float y) {
  return x >= 0.0f && y >= 0.0f && x < static_cast<float>(image.cols - 1) &&
         y < static_cast<float>(image.rows - 1);
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

// I(W(u)) - T(u) at every patch pixel, into `residual`: Sample's arithmetic, in loops over the whole patch
// that the compiler vectorizes but for the loads of each pixel's four neighbours. Scratch: `work` holds 2
// floats per pixel, `neighbours` 5 integers. The caller checks that the warped patch lies inside the image.
void Residuals(const AffinePatch& patch, const cv::Mat& image, const cv::Matx22f& A, const cv::Point2f& c,
               float* __restrict work, int32_t* __restrict neighbours, float* __restrict residual) {
  const std::size_t n = patch.intensity.size();
  const float* __restrict u = patch.offset_u.data();
  const float* __restrict v = patch.offset_v.data();
  const float* __restrict intensity = patch.intensity.data();
  float* __restrict fx = work;
  float* __restrict fy = work + n;
  int32_t* __restrict offset = neighbours;
  int32_t* __restrict top_left = neighbours + n;
  int32_t* __restrict top_right = neighbours + 2 * n;
  int32_t* __restrict bottom_left = neighbours + 3 * n;
  int32_t* __restrict bottom_right = neighbours + 4 * n;
  const float a00 = A(0, 0), a01 = A(0, 1), a10 = A(1, 0), a11 = A(1, 1), cx = c.x, cy = c.y;
  const int32_t step = static_cast<int32_t>(image.step[0]);
  for (std::size_t i = 0; i < n; ++i) {
    const float x = a00 * u[i] + a01 * v[i] + cx;
    const float y = a10 * u[i] + a11 * v[i] + cy;
    const int32_t x0 = static_cast<int32_t>(x), y0 = static_cast<int32_t>(y);
    fx[i] = x - static_cast<float>(x0);
    fy[i] = y - static_cast<float>(y0);
    offset[i] = y0 * step + x0;
  }
  for (std::size_t i = 0; i < n; ++i) {
    const uchar* p = image.data + offset[i];
    top_left[i] = p[0];
    top_right[i] = p[1];
    bottom_left[i] = p[step];
    bottom_right[i] = p[step + 1];
  }
  for (std::size_t i = 0; i < n; ++i) {
    const float top =
        static_cast<float>(top_left[i]) + fx[i] * static_cast<float>(top_right[i] - top_left[i]);
    const float bottom =
        static_cast<float>(bottom_left[i]) + fx[i] * static_cast<float>(bottom_right[i] - bottom_left[i]);
    residual[i] = top + fy[i] * (bottom - top) - intensity[i];
  }
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
      grid[static_cast<std::size_t>(r * side + k)] =
          Sample(image, centre_px.x + static_cast<float>(k - half - 1),
                 centre_px.y + static_cast<float>(r - half - 1));
  AffinePatch patch;
  patch.half = half;
  const int n = 2 * half + 1;
  patch.intensity.reserve(static_cast<std::size_t>(n * n));
  patch.offset_u.reserve(static_cast<std::size_t>(n * n));
  patch.offset_v.reserve(static_cast<std::size_t>(n * n));
  patch.steepest.reserve(static_cast<std::size_t>(n * n));
  Eigen::Matrix<double, 6, 6> hessian = Eigen::Matrix<double, 6, 6>::Zero();
  for (int v = -half; v <= half; ++v) {
    for (int u = -half; u <= half; ++u) {
      const auto at = [&](int du, int dv) {
        return grid[static_cast<std::size_t>((v + half + 1 + dv) * side + (u + half + 1 + du))];
      };
      const float gx = 0.5f * (at(1, 0) - at(-1, 0)), gy = 0.5f * (at(0, 1) - at(0, -1));
      const float fu = static_cast<float>(u), fv = static_cast<float>(v);
      Eigen::Matrix<float, 8, 1> sd;
      sd << gx, gy, gx * fu, gx * fv, gy * fu, gy * fv, 0.0f, 0.0f;
      patch.intensity.push_back(at(0, 0));
      patch.offset_u.push_back(fu);
      patch.offset_v.push_back(fv);
      patch.steepest.push_back(sd);
      hessian += sd.head<6>().cast<double>() * sd.head<6>().cast<double>().transpose();
    }
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, 6, 6>> eigen(hessian);
  const Eigen::Matrix<double, 6, 1>& values = eigen.eigenvalues();  // ascending
  if (!(values(5) > 0.0) || values(0) < kMinEigenvalueRatio * values(5)) return std::nullopt;
  patch.hessian_inverse =
      eigen.eigenvectors() * values.cwiseInverse().asDiagonal() * eigen.eigenvectors().transpose();
  return patch;
}

std::optional<AffineWarp> AlignAffinePatch(const AffinePatch& patch, const cv::Mat& image,
                                           const AffineWarp& start, const AffineAlignOptions& options) {
  const int half = patch.half;
  const float h = static_cast<float>(half);
  const cv::Point2f corners[] = {{-h, -h}, {h, -h}, {-h, h}, {h, h}};
  cv::Matx22f A = start.linear;
  cv::Point2f c = start.centre_px;
  const std::size_t side = static_cast<std::size_t>(2 * half + 1);
  std::vector<float> work(2 * side * side), residual(side * side);
  std::vector<int32_t> neighbours(5 * side * side);
  for (int iteration = 0; iteration < options.max_iterations; ++iteration) {
    // The warped patch lies inside the image when its four corners do (an affine image of a square).
    for (const cv::Point2f& corner : corners) {
      const cv::Point2f p = A * corner + c;
      if (!Inside(image, p.x, p.y)) return std::nullopt;
    }
    // Gauss-Newton step of the inverse-compositional problem: dp = H^-1 sum_u sd(u) (I(W(u)) - T(u)).
    Residuals(patch, image, A, c, work.data(), neighbours.data(), residual.data());
    Eigen::Matrix<double, 6, 1> b = Eigen::Matrix<double, 6, 1>::Zero();
    for (std::size_t row = 0, i = 0; row < side; ++row) {
      Eigen::Matrix<float, 8, 1> row_sum = Eigen::Matrix<float, 8, 1>::Zero();
      for (std::size_t k = 0; k < side; ++k, ++i) row_sum += patch.steepest[i] * residual[i];
      b += row_sum.head<6>().cast<double>();
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
