#include "sim/image_renderer.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include "core/euroc.h"
#include "core/output.h"
#include "core/png/png_encode.h"
#include "core/random.h"
#include "gl/gl_api.h"
#include "gl/gl_context.h"
#include "sim/texture.h"

namespace vigil::sim {
namespace {

constexpr double kNear_m = 0.05, kFar_m = 1000.0;

Eigen::Isometry3d CameraPose(const Eigen::Isometry3d& T_WB, const CameraModel& camera) {
  return T_WB * camera.T_BC_iso();
}

Eigen::Isometry3d BodyPose(const TrajectoryState& x) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = x.q_WB.toRotationMatrix();
  T.translation() = x.p_W;
  return T;
}

}  // namespace

// The GL side: the context, the textures, the scene's display list, and the pinhole view that is rendered
// (the camera's own, or a wider one to be distorted).
struct ImageRenderer::Gl {
  gl::GlContext context;
  unsigned list = 0;
  std::vector<unsigned> textures;
  int width = 0, height = 0;  // of the pinhole rendering
  double cx = 0.0, cy = 0.0;
  cv::Mat map_x, map_y;  // image pixel -> pinhole rendering pixel (with distortion)

  explicit Gl(int samples) : context(samples) {}
};

ImageRenderer::ImageRenderer(const Scene& scene, const CameraModel& camera, const ImageOptions& options,
                             uint64_t seed)
    : gl_(std::make_unique<Gl>(options.antialias_samples)), camera_(camera), options_(options), seed_(seed) {
  Gl& g = *gl_;
  g.width = camera.width;
  g.height = camera.height;
  g.cx = camera.cx;
  g.cy = camera.cy;
  if (camera.HasDistortion()) {
    // The pinhole pixels of every image pixel: their bounding box (plus 2 px for bilinear reads) is the
    // wider rendering; at most 3 x the image on each axis.
    cv::Mat map_x(camera.height, camera.width, CV_32FC1), map_y(camera.height, camera.width, CV_32FC1);
    double u_lo = 0.0, u_hi = camera.width - 1.0, v_lo = 0.0, v_hi = camera.height - 1.0;
    std::vector<Eigen::Vector2d> pinhole(static_cast<std::size_t>(camera.width) * camera.height);
    for (int v = 0; v < camera.height; ++v)
      for (int u = 0; u < camera.width; ++u) {
        const Eigen::Vector2d p = camera.UndistortPixel(Eigen::Vector2d(u, v));
        pinhole[static_cast<std::size_t>(v) * camera.width + u] = p;
        u_lo = std::min(u_lo, p.x());
        u_hi = std::max(u_hi, p.x());
        v_lo = std::min(v_lo, p.y());
        v_hi = std::max(v_hi, p.y());
      }
    u_lo = std::max(u_lo, -1.0 * camera.width);
    v_lo = std::max(v_lo, -1.0 * camera.height);
    u_hi = std::min(u_hi, 2.0 * camera.width);
    v_hi = std::min(v_hi, 2.0 * camera.height);
    const int left = static_cast<int>(std::ceil(-u_lo)) + 2, top = static_cast<int>(std::ceil(-v_lo)) + 2;
    g.width = left + static_cast<int>(std::ceil(u_hi)) + 3;
    g.height = top + static_cast<int>(std::ceil(v_hi)) + 3;
    g.cx = camera.cx + left;
    g.cy = camera.cy + top;
    for (int v = 0; v < camera.height; ++v)
      for (int u = 0; u < camera.width; ++u) {
        const Eigen::Vector2d& p = pinhole[static_cast<std::size_t>(v) * camera.width + u];
        map_x.at<float>(v, u) = static_cast<float>(p.x() + left);
        map_y.at<float>(v, u) = static_cast<float>(p.y() + top);
      }
    g.map_x = map_x;
    g.map_y = map_y;
  }

  // Textures and the scene's geometry, once.
  g.context.BeginFrame(1, 1, 0.0f, 0.0f, 0.0f);
  const uint64_t texture_seed = options.texture_seed != 0 ? options.texture_seed : seed;
  const std::vector<GrayTexture> textures =
      MakeTextures(scene.num_textures, options.texture_size_px, texture_seed);
  g.textures.resize(textures.size());
  glGenTextures(static_cast<GLsizei>(g.textures.size()), g.textures.data());
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  for (std::size_t i = 0; i < textures.size(); ++i) {
    glBindTexture(GL_TEXTURE_2D, g.textures[i]);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_LUMINANCE8, textures[i].size, textures[i].size, 0, GL_LUMINANCE,
                 GL_UNSIGNED_BYTE, textures[i].gray.data());
    glGenerateMipmap(GL_TEXTURE_2D);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
  }
  g.list = glGenLists(1);
  glNewList(g.list, GL_COMPILE);
  for (const SceneFace& f : scene.faces) {
    glBindTexture(GL_TEXTURE_2D, g.textures[static_cast<std::size_t>(f.texture)]);
    glColor3f(f.shade, f.shade, f.shade);
    glBegin(GL_TRIANGLE_FAN);
    for (const Eigen::Vector3d& c : f.corners_W) {
      const Eigen::Vector3d d = c - f.corners_W[0];
      glTexCoord2d(d.dot(f.u_axis_W) / options.texture_scale_m, d.dot(f.v_axis_W) / options.texture_scale_m);
      glVertex3d(c.x(), c.y(), c.z());
    }
    glEnd();
  }
  glEndList();
  g.context.EndFrame();
}

ImageRenderer::~ImageRenderer() = default;

namespace {

// Draws the scene's display list for a camera at T_WC into the current frame of a w x h pinhole view.
void DrawScene(unsigned list, const Eigen::Isometry3d& T_WC, const CameraModel& camera, int w, int h,
               double cx, double cy) {
  // Clip coordinates straight from camera coordinates (x right, y down, z forward; w_clip = z): pixel (u, v)
  // centre <-> NDC x = 2 (u + 0.5) / w - 1, NDC y = 1 - 2 (v + 0.5) / h (the read-back is top row first).
  Eigen::Matrix4d P = Eigen::Matrix4d::Zero();
  P(0, 0) = 2.0 * camera.fx / w;
  P(0, 2) = 2.0 * (cx + 0.5) / w - 1.0;
  P(1, 1) = -2.0 * camera.fy / h;
  P(1, 2) = 1.0 - 2.0 * (cy + 0.5) / h;
  P(2, 2) = (kFar_m + kNear_m) / (kFar_m - kNear_m);
  P(2, 3) = -2.0 * kFar_m * kNear_m / (kFar_m - kNear_m);
  P(3, 2) = 1.0;
  const Eigen::Matrix4d T_CW = T_WC.inverse().matrix();
  glDisable(GL_BLEND);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
  glMatrixMode(GL_PROJECTION);
  glLoadMatrixd(P.data());  // Eigen is column-major, as OpenGL
  glMatrixMode(GL_MODELVIEW);
  glLoadMatrixd(T_CW.data());
  glCallList(list);
}

}  // namespace

std::vector<float> ImageRenderer::RenderSharp(const Eigen::Isometry3d& T_WB) {
  Gl& g = *gl_;
  const float sky = static_cast<float>(options_.sky_gray / 255.0);
  g.context.BeginFrame(g.width, g.height, sky, sky, sky);
  DrawScene(g.list, CameraPose(T_WB, camera_), camera_, g.width, g.height, g.cx, g.cy);
  const std::vector<uint8_t> rgba = g.context.EndFrame();
  cv::Mat pinhole(g.height, g.width, CV_32FC1);
  for (int i = 0; i < g.width * g.height; ++i) pinhole.at<float>(i) = rgba[static_cast<std::size_t>(i) * 4];
  if (!g.map_x.empty()) {
    cv::Mat image;
    cv::remap(pinhole, image, g.map_x, g.map_y, cv::INTER_LINEAR, cv::BORDER_REPLICATE);
    pinhole = image;
  }
  return std::vector<float>(pinhole.begin<float>(), pinhole.end<float>());
}

std::vector<float> ImageRenderer::PinholeDepth(const Eigen::Isometry3d& T_WB) {
  Gl& g = *gl_;
  g.context.BeginFrame(camera_.width, camera_.height, 0.0f, 0.0f, 0.0f);
  DrawScene(g.list, CameraPose(T_WB, camera_), camera_, camera_.width, camera_.height, camera_.cx,
            camera_.cy);
  std::vector<float> depth = g.context.ReadDepth();
  g.context.EndFrame();
  const double a = (kFar_m + kNear_m) / (kFar_m - kNear_m), b = -2.0 * kFar_m * kNear_m / (kFar_m - kNear_m);
  for (float& d : depth) {
    // window depth d -> NDC z = 2 d - 1 = a + b / z
    d = d >= 1.0f ? std::numeric_limits<float>::infinity() : static_cast<float>(b / ((2.0 * d - 1.0) - a));
  }
  return depth;
}

std::vector<uint8_t> ImageRenderer::Render(const TrajectoryModel& motion, double t_s, double end_s,
                                           int frame_index) {
  const std::size_t n = static_cast<std::size_t>(camera_.width) * camera_.height;
  std::vector<float> sum(n, 0.0f);
  const int sub_frames = options_.exposure_s > 0.0 ? options_.blur_samples : 1;
  for (int i = 0; i < sub_frames; ++i) {
    const double t =
        sub_frames == 1 ? t_s : t_s + options_.exposure_s * (static_cast<double>(i) / (sub_frames - 1) - 0.5);
    const std::vector<float> sharp = RenderSharp(BodyPose(motion.StateAt(std::clamp(t, 0.0, end_s))));
    for (std::size_t k = 0; k < n; ++k) sum[k] += sharp[k];
  }
  std::vector<uint8_t> out(n);
  Rng rng(seed_, "image_noise/" + std::to_string(frame_index));
  const float inv = 1.0f / static_cast<float>(sub_frames);
  for (std::size_t k = 0; k < n; ++k) {
    double v = sum[k] * inv;
    if (options_.noise_std > 0.0) v += options_.noise_std * rng.Normal();
    out[k] = static_cast<uint8_t>(std::clamp(std::lround(v), 0L, 255L));
  }
  return out;
}

std::string EncodeGrayPng(const std::vector<uint8_t>& gray, int width, int height, int compression) {
  return EncodePng8(gray.data(), width, height, PngRows::kGray, static_cast<std::size_t>(width),
                    {compression});
}

std::uintmax_t RenderImageSequence(const Scene& scene, const TrajectoryModel& motion, double end_s,
                                   const CameraModel& camera, const ImageOptions& options, uint64_t seed,
                                   const std::vector<int64_t>& times_ns,
                                   const std::filesystem::path& image_dir) {
  ImageRenderer renderer(scene, camera, options, seed);
  std::uintmax_t bytes = 0;
  for (std::size_t k = 0; k < times_ns.size(); ++k) {
    const std::vector<uint8_t> gray = renderer.Render(motion, NsToS(times_ns[k]), end_s, static_cast<int>(k));
    const std::string png = EncodeGrayPng(gray, camera.width, camera.height, options.png_compression);
    WriteFileAtomic(image_dir / EurocImageName(times_ns[k]), png);
    bytes += png.size();
  }
  return bytes;
}

}  // namespace vigil::sim
