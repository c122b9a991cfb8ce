// Synthetic camera images with known motion, for the front-end's tests and benchmark.
//
// A texture is a seeded, corner-rich random pattern (overlapping rectangles of random gray levels, slightly
// blurred so that sub-pixel interpolation is meaningful). A frame is the texture seen through a homography H
// (texture pixel -> image pixel): a point at image pixel p of frame a is at H_b H_a^-1 p in frame b.
#pragma once

#include <cstdint>
#include <vector>

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include "core/random.h"

namespace vigil::frontend::testing {

inline cv::Mat MakeTexture(int width, int height, uint64_t seed) {
  Rng rng(seed, "texture");
  cv::Mat texture(height, width, CV_8UC1, cv::Scalar(128));
  const int count = width * height / 300;
  for (int i = 0; i < count; ++i) {
    const int w = 6 + static_cast<int>(rng.UniformIndex(35));
    const int h = 6 + static_cast<int>(rng.UniformIndex(35));
    const int x = static_cast<int>(rng.UniformIndex(static_cast<uint64_t>(width)));
    const int y = static_cast<int>(rng.UniformIndex(static_cast<uint64_t>(height)));
    const int gray = static_cast<int>(rng.UniformIndex(256));
    cv::rectangle(texture, cv::Rect(x, y, w, h), cv::Scalar(gray), cv::FILLED);
  }
  cv::GaussianBlur(texture, texture, cv::Size(0, 0), 1.2);
  return texture;
}

// The image of `texture` through H (texture pixel -> image pixel), bilinear.
inline cv::Mat Warp(const cv::Mat& texture, const cv::Matx33d& H, cv::Size size) {
  cv::Mat image;
  cv::warpPerspective(texture, image, cv::Mat(H), size, cv::INTER_LINEAR, cv::BORDER_REFLECT);
  return image;
}

inline cv::Point2d Apply(const cv::Matx33d& H, const cv::Point2d& p) {
  const cv::Vec3d q = H * cv::Vec3d(p.x, p.y, 1.0);
  return {q[0] / q[2], q[1] / q[2]};
}

// A camera moving over a textured plane: frame k sees the texture through
//   H_k = T(c + offset + k t) R(k angle) S(1 + k scale) T(-c - offset0),
// c the image centre; `offset0` places the image over the texture's middle.
struct PlaneMotion {
  cv::Point2d offset0{300.0, 250.0};
  cv::Point2d translation_px{1.7, -0.9};  // per frame
  double angle_rad = 0.005;               // per frame
  double scale = 0.004;                   // per frame
  cv::Size size{640, 480};

  cv::Matx33d H(int k) const {
    const cv::Point2d c(size.width / 2.0, size.height / 2.0);
    const double a = angle_rad * k, s = 1.0 + scale * k;
    const cv::Matx33d to_origin(1, 0, -c.x - offset0.x, 0, 1, -c.y - offset0.y, 0, 0, 1);
    const cv::Matx33d rs(s * std::cos(a), -s * std::sin(a), 0, s * std::sin(a), s * std::cos(a), 0, 0, 0, 1);
    const cv::Matx33d back(1, 0, c.x + translation_px.x * k, 0, 1, c.y + translation_px.y * k, 0, 0, 1);
    return back * rs * to_origin;
  }

  // Frames 0 .. count - 1 of `texture` seen through this motion.
  std::vector<cv::Mat> Frames(const cv::Mat& texture, int count) const {
    std::vector<cv::Mat> out;
    for (int k = 0; k < count; ++k) out.push_back(Warp(texture, H(k), size));
    return out;
  }
};

}  // namespace vigil::frontend::testing
