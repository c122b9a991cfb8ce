#include "frontend/affine_patch_aligner.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include "tests/frontend/synthetic_images.h"

namespace vigil::frontend {
namespace {

using testing::Apply;
using testing::MakeTexture;
using testing::Warp;

// A known affine map M (anchor image pixel -> target image pixel): 6 deg of rotation, 7 % of zoom, some
// shear.
cv::Matx33d KnownAffine() {
  const double a = 6.0 * M_PI / 180.0, s = 1.07;
  return cv::Matx33d(s * std::cos(a), -s * std::sin(a) + 0.03, 12.6, s * std::sin(a), s * std::cos(a), -7.3,
                     0, 0, 1);
}

TEST(AffinePatchAligner, RecoversAKnownAffineWarp) {
  const cv::Mat texture = MakeTexture(640, 480, 5);
  const cv::Matx33d M = KnownAffine();
  const cv::Mat target = Warp(texture, M, texture.size());
  const cv::Matx22f true_linear(static_cast<float>(M(0, 0)), static_cast<float>(M(0, 1)),
                                static_cast<float>(M(1, 0)), static_cast<float>(M(1, 1)));
  std::vector<double> errors_px;
  for (int k = 0; k < 40; ++k) {
    const cv::Point2f anchor(150.0f + 9.37f * static_cast<float>(k),
                             120.0f + 5.21f * static_cast<float>(k % 7));
    const std::optional<AffinePatch> patch = MakeAffinePatch(texture, anchor, 10);
    if (!patch) continue;  // too little texture
    const cv::Point2d truth = Apply(M, anchor);
    // Started 1.5 px away under the identity, as after a frame-to-frame step that ignored the deformation.
    AffineWarp start;
    start.centre_px = cv::Point2f(static_cast<float>(truth.x) + 1.2f, static_cast<float>(truth.y) - 0.9f);
    const std::optional<AffineWarp> warp = AlignAffinePatch(*patch, target, start, AffineAlignOptions{});
    ASSERT_TRUE(warp) << "patch " << k;
    errors_px.push_back(std::hypot(warp->centre_px.x - truth.x, warp->centre_px.y - truth.y));
    EXPECT_LT(errors_px.back(), 0.3) << "patch " << k;
    for (int i = 0; i < 2; ++i)
      for (int j = 0; j < 2; ++j) EXPECT_NEAR(warp->linear(i, j), true_linear(i, j), 0.1) << "patch " << k;
  }
  ASSERT_GE(errors_px.size(), 30u);
  std::sort(errors_px.begin(), errors_px.end());
  // Most patches land within 0.05 px; a few, dominated by one edge, up to 0.2 px (the target is the texture
  // resampled once more, so its interpolation blur differs from the patch's).
  EXPECT_LT(errors_px[errors_px.size() / 2], 0.05);
}

// The steepest-descent images are the derivatives of the warped patch: T(W(u; dp)) - T(u) = sd(u) . dp to
// first order, checked against the image itself sampled at the perturbed warp.
TEST(AffinePatchAligner, SteepestDescentMatchesNumericalDerivatives) {
  // A smooth pattern of strong gradients (30 gray levels per pixel at most), so that neither the 8-bit
  // quantization nor the bilinear interpolation between pixels dominates the derivatives.
  cv::Mat texture(200, 200, CV_8UC1);
  for (int r = 0; r < texture.rows; ++r)
    for (int k = 0; k < texture.cols; ++k)
      texture.at<uchar>(r, k) = cv::saturate_cast<uchar>(128.0 + 70.0 * std::sin(0.21 * k + 0.05 * r) +
                                                         50.0 * std::cos(0.17 * r - 0.08 * k));
  const cv::Point2f centre(100.3f, 99.6f);
  const int half = 6;
  const std::optional<AffinePatch> patch = MakeAffinePatch(texture, centre, half);
  ASSERT_TRUE(patch);
  cv::Mat image;
  texture.convertTo(image, CV_32F);
  const auto sample = [&](double x, double y) {
    cv::Mat out;
    cv::getRectSubPix(image, cv::Size(1, 1), cv::Point2f(static_cast<float>(x), static_cast<float>(y)), out);
    return static_cast<double>(out.at<float>(0, 0));
  };
  // Per parameter, the numerical derivatives over the patch against the steepest-descent column: the
  // difference is the central-difference gradient's error (8-bit quantization), about 5 %; a wrong column
  // (a swapped or missing term) is off by 100 %.
  const double delta = 1e-2;
  for (int p = 0; p < 6; ++p) {
    double difference2 = 0.0, numeric2 = 0.0;
    std::size_t i = 0;
    for (int v = -half; v <= half; ++v) {
      for (int u = -half; u <= half; ++u, ++i) {
        double dp[6] = {0, 0, 0, 0, 0, 0};
        dp[p] = delta;
        // W(u; +-dp) = (I +- D) u +- d around the patch centre.
        const double dx = dp[0] + dp[2] * u + dp[3] * v, dy = dp[1] + dp[4] * u + dp[5] * v;
        const double numeric =
            (sample(centre.x + u + dx, centre.y + v + dy) - sample(centre.x + u - dx, centre.y + v - dy)) /
            (2.0 * delta);
        difference2 += std::pow(numeric - patch->steepest[i](p), 2);
        numeric2 += numeric * numeric;
      }
    }
    EXPECT_LT(std::sqrt(difference2 / numeric2), 0.08) << "parameter " << p;
  }
}

TEST(AffinePatchAligner, RefusesPatchesOutsideTheImageOrWithoutTexture) {
  const cv::Mat texture = MakeTexture(200, 200, 3);
  EXPECT_FALSE(MakeAffinePatch(texture, cv::Point2f(5.0f, 100.0f), 10));
  EXPECT_FALSE(MakeAffinePatch(texture, cv::Point2f(100.0f, 190.5f), 10));
  const cv::Mat blank(200, 200, CV_8UC1, cv::Scalar(90));
  EXPECT_FALSE(MakeAffinePatch(blank, cv::Point2f(100.0f, 100.0f), 10));
  cv::Mat edge = blank.clone();
  edge.colRange(100, 200).setTo(cv::Scalar(200));  // a vertical edge: nothing fixes the vertical position
  EXPECT_FALSE(MakeAffinePatch(edge, cv::Point2f(100.0f, 100.0f), 10));
  // A warp that carries the patch out of the image fails instead of reading outside it.
  const std::optional<AffinePatch> patch = MakeAffinePatch(texture, cv::Point2f(100.0f, 100.0f), 10);
  ASSERT_TRUE(patch);
  AffineWarp start;
  start.centre_px = cv::Point2f(195.0f, 100.0f);
  EXPECT_FALSE(AlignAffinePatch(*patch, texture, start, AffineAlignOptions{}));
}

}  // namespace
}  // namespace vigil::frontend
