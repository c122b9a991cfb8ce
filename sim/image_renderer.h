// Rendered camera images of the scene (sim/scene.h) along the trajectory: OSMesa through the shared
// gl::GlContext, the configured pinhole camera (fx, fy, cx, cy, width, height, T_BC), procedural textures
// (sim/texture.h), then optional motion blur, lens distortion and pixel noise (sim/image_options.h).
//
// Pixel convention: pixel (u, v) of the camera model (core/camera.h) is the centre of image column u, row v
// (OpenCV's convention). An image is rendered as follows:
// - each sub-frame is a pinhole rendering at the body pose of its time; without blur one sub-frame at t,
//   with exposure e and N blur samples, N sub-frames at t - e/2 + i e / (N - 1) (clamped to the trajectory),
//   averaged in floating point;
// - with camera.distortion, the pinhole view is rendered wider (same fx, fy; a margin that holds every
//   undistorted image pixel) and remapped: image pixel p takes the pinhole pixel UndistortPixel(p)
//   (bilinear, OpenCV cv::remap);
// - noise N(0, noise_std^2) per pixel from Rng(seed, "image_noise/<frame index>") (frames are independent of
//   each other's order), then rounding to 8 bits.
// Same scene, camera, options and seed: the same bytes.
#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "core/camera.h"
#include "sim/image_options.h"
#include "sim/scene.h"
#include "sim/trajectory_model.h"

namespace vigil::sim {

class ImageRenderer {
 public:
  // `seed` drives the textures (unless options.texture_seed is set) and the pixel noise. Throws
  // std::runtime_error when no OpenGL context can be created.
  ImageRenderer(const Scene& scene, const CameraModel& camera, const ImageOptions& options, uint64_t seed);
  ~ImageRenderer();
  ImageRenderer(const ImageRenderer&) = delete;
  ImageRenderer& operator=(const ImageRenderer&) = delete;

  // The 8-bit image (camera.width x camera.height, top row first) of frame `frame_index` at time t_s of
  // `motion` (blur, distortion and noise as above). Sub-frame times are clamped to [0, end_s].
  std::vector<uint8_t> Render(const TrajectoryModel& motion, double t_s, double end_s, int frame_index);
  // One sharp view at body pose T_WB without noise, as floating-point gray levels (distortion applied).
  std::vector<float> RenderSharp(const Eigen::Isometry3d& T_WB);
  // Depth z_C [m] of the pinhole (undistorted) view at body pose T_WB, camera.width x camera.height, top row
  // first; +infinity where no surface is seen.
  std::vector<float> PinholeDepth(const Eigen::Isometry3d& T_WB);

 private:
  struct Gl;
  std::unique_ptr<Gl> gl_;
  CameraModel camera_;
  ImageOptions options_;
  uint64_t seed_;
};

// PNG bytes of an 8-bit gray image (OpenCV's encoder at `compression`, deterministic).
std::string EncodeGrayPng(const std::vector<uint8_t>& gray, int width, int height, int compression);

// Renders `scene` at every frame time of `times_ns` (times from the start of `motion`, in ns) into
// `image_dir`/<t_ns>.png (core/euroc.h's names). Returns the total PNG bytes written.
std::uintmax_t RenderImageSequence(const Scene& scene, const TrajectoryModel& motion, double end_s,
                                   const CameraModel& camera, const ImageOptions& options, uint64_t seed,
                                   const std::vector<int64_t>& times_ns,
                                   const std::filesystem::path& image_dir);

}  // namespace vigil::sim
