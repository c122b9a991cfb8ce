// Pinhole camera model with its body extrinsics, as in camera.yaml (docs/formats.md).
//
// A point p_C in the camera frame (x right, y down, z forward) is seen at
//   (u, v) = (fx x/z + cx, fy y/z + cy)   when z > 0 and the pixel lies inside [0, width) x [0, height).
// T_BC maps camera coordinates into the body frame: p_B = R_BC p_C + p_BC.
//
// Lens distortion (optional, `distortion`: radial-tangential k1, k2, p1, p2, EuRoC's and OpenCV's model)
// applies to the images only: an image pixel is Distort()ed from the pinhole pixel of the formula above.
// Project / Normalize and every feature track (features.csv) are pinhole, i.e. undistorted pixels; a
// front-end tracking raw image pixels maps them to pinhole pixels before writing them (UndistortPixel, or
// frontend/point_undistorter.h: OpenCV's inversion of this same model, as vigil's KLT tracker does).
//   distorted normalized (x_d, y_d) of undistorted (x, y), r^2 = x^2 + y^2:
//   x_d = x (1 + k1 r^2 + k2 r^4) + 2 p1 x y + p2 (r^2 + 2 x^2)
//   y_d = y (1 + k1 r^2 + k2 r^4) + p1 (r^2 + 2 y^2) + 2 p2 x y
#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "core/config.h"

namespace vigil {

struct CameraModel {
  double rate_hz = 30.0;
  int width = 640;
  int height = 640;
  double fx = 460.0;
  double fy = 460.0;
  double cx = 255.0;
  double cy = 255.0;
  double pixel_noise_px = 0.0;  // std of Gaussian pixel noise added by the simulator
  // camera -> body, 4x4 row-major. Default: cam x = -y_B, cam y = +z_B, cam z = -x_B; t_BC = (0.05, 0.04,
  // 0.03).
  std::vector<double> T_BC = {0,  0, -1, 0.05,  //
                              -1, 0, 0,  0.04,  //
                              0,  1, 0,  0.03,  //
                              0,  0, 0,  1};
  std::vector<double> distortion = {0, 0, 0, 0};  // radial-tangential k1, k2, p1, p2 (zeros: none)

  template <class V>
  void Visit(V& v) {
    using config::Bounds;
    v.Field("rate_hz", rate_hz, "camera frame rate [Hz]", Bounds::Positive());
    v.Field("width", width, "image width [px]", Bounds::AtLeast(1));
    v.Field("height", height, "image height [px]", Bounds::AtLeast(1));
    v.Field("fx", fx, "focal length x [px]", Bounds::Positive());
    v.Field("fy", fy, "focal length y [px]", Bounds::Positive());
    v.Field("cx", cx, "principal point x [px]");
    v.Field("cy", cy, "principal point y [px]");
    v.Field("pixel_noise_px", pixel_noise_px, "std of Gaussian pixel noise on feature tracks [px]",
            Bounds::NonNegative());
    v.Field("T_BC", T_BC, "camera -> body transform, 4x4 row-major (16 numbers; rotation must be proper)");
    v.Field("distortion", distortion,
            "radial-tangential lens distortion [k1, k2, p1, p2] of the images (rendered and read); feature "
            "tracks stay undistorted pinhole pixels");
  }

  // Checks T_BC (16 numbers, proper rotation, last row 0 0 0 1) and distortion (4 finite numbers); returns an
  // empty string or the reason.
  std::string Validate() const;

  Eigen::Matrix3d R_BC() const;
  Eigen::Vector3d p_BC() const;
  Eigen::Isometry3d T_BC_iso() const;

  // Pixel of a point in C; false when behind the camera (z <= min_depth) or outside the image.
  bool Project(const Eigen::Vector3d& p_C, Eigen::Vector2d* uv_px, double min_depth = 1e-6) const;
  // Normalized image coordinates (x/z, y/z) of a pixel.
  Eigen::Vector2d Normalize(const Eigen::Vector2d& uv_px) const;
  bool InImage(const Eigen::Vector2d& uv_px) const;

  // True when a distortion coefficient is not zero.
  bool HasDistortion() const;
  // Normalized coordinates: undistorted -> distorted (the formula above), and back by fixed-point
  // iteration (converged to 1e-12, or after 100 iterations; exact inverse within the lens's monotonic range).
  Eigen::Vector2d Distort(const Eigen::Vector2d& xy) const;
  Eigen::Vector2d Undistort(const Eigen::Vector2d& xy_distorted) const;
  // The same in pixels: the image pixel of a pinhole pixel, and the pinhole pixel of an image pixel.
  Eigen::Vector2d DistortPixel(const Eigen::Vector2d& uv_px) const;
  Eigen::Vector2d UndistortPixel(const Eigen::Vector2d& uv_image_px) const;
};

}  // namespace vigil
