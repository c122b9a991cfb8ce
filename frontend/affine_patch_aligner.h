// Affine alignment of one image patch: where, and under which local affine warp, a patch of an earlier image
// (the anchor) appears in a later one. The tracker's anchor refinement (frontend/feature_tracker.h) uses it
// to realign each tracked point with the view its track began in, so that frame-to-frame errors do not add
// up.
//
// Inverse-compositional Lucas-Kanade (Baker and Matthews, "Lucas-Kanade 20 years on", 2004) with the six
// parameters of an affine warp: the patch's intensities T(u) at offsets u from the anchor pixel, u in
// [-half, half]^2, are matched to the image at W(u) = A u + c, c the patch centre's pixel in the image. The
// steepest-descent images and the Gauss-Newton Hessian depend on the patch only and are computed once, when
// the patch is made; each iteration then costs one bilinear sample of the image per patch pixel.
// cv::findTransformECC solves the same problem but costs about 1.5 ms per 21 x 21 patch in OpenCV 4.6 (its
// per-call overhead on small images): 210 ms per 150-feature frame, 40x the front-end's 5 ms budget.
#pragma once

#include <optional>
#include <vector>

#include <Eigen/Core>
#include <opencv2/core.hpp>

namespace vigil::frontend {

struct AffinePatch {
  int half = 0;                  // the patch is (2 half + 1)^2 pixels
  std::vector<float> intensity;  // T(u), row-major
  // u, row-major: the same for every patch of this half, kept with it (a patch is made once and aligned at
  // every image of its track) so that an iteration computes its sample coordinates in one vectorized loop
  std::vector<float> offset_u, offset_v;
  // dT/dp of each pixel (p: dc_x, dc_y, dA00, dA01, dA10, dA11), padded with two zeros to two SIMD packets
  std::vector<Eigen::Matrix<float, 8, 1>> steepest;
  Eigen::Matrix<double, 6, 6> hessian_inverse;
};

// The patch of `image` (8-bit, one channel) around `centre_px`, sampled bilinearly at centre_px + u, or
// nothing when it does not lie inside the image (with one pixel to spare for the gradients) or has too little
// texture for all six parameters (a singular Hessian).
std::optional<AffinePatch> MakeAffinePatch(const cv::Mat& image, const cv::Point2f& centre_px, int half);

struct AffineAlignOptions {
  int max_iterations = 30;
  double epsilon_px = 0.01;  // stop when no patch corner moves more than this in an iteration
};

struct AffineWarp {
  cv::Matx22f linear = cv::Matx22f::eye();  // A
  cv::Point2f centre_px;                    // c
};

// Aligns `patch` with `image` from `start`; the converged warp, or nothing when the warped patch leaves the
// image or the iterations do not converge.
std::optional<AffineWarp> AlignAffinePatch(const AffinePatch& patch, const cv::Mat& image,
                                           const AffineWarp& start, const AffineAlignOptions& options);

}  // namespace vigil::frontend
