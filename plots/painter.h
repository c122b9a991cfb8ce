// Drawing primitives of a figure in pixel coordinates (origin at the top-left corner, y down).
//
// Shapes go to OpenGL (anti-aliased by the multisampled framebuffer of gl::GlContext); text is queued and
// drawn with FreeType over the read-back image by Finish(), so text is always on top. A clip rectangle
// (scissor) limits shapes to a plot area. Begin3D/End3D switch to a perspective view with depth testing
// inside a rectangle.
#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>

#include "gl/gl_context.h"
#include "plots/image.h"
#include "plots/text.h"

namespace vigil::plots {

// An axis-aligned rectangle in pixels.
struct Rect {
  double x = 0.0, y = 0.0, w = 0.0, h = 0.0;
  double right() const { return x + w; }
  double bottom() const { return y + h; }
  bool Contains(double px, double py) const { return px >= x && px <= right() && py >= y && py <= bottom(); }
};

class Painter {
 public:
  // Starts a width x height frame on `gl` cleared to white.
  Painter(gl::GlContext* gl, TextRenderer* text, int width, int height);

  int width() const { return width_; }
  int height() const { return height_; }
  TextRenderer& text_renderer() { return *text_; }

  // Limits shapes (not text) to `clip`; ClearClip() lifts the limit.
  void SetClip(const Rect& clip);
  void ClearClip();

  // A connected line through `points` (pixels). `dash_px` > 0 draws it dashed.
  void Polyline(const std::vector<Eigen::Vector2d>& points, const Color& color, double width_px,
                double dash_px = 0.0);
  void FillRect(const Rect& rect, const Color& color);
  void StrokeRect(const Rect& rect, const Color& color, double width_px);
  // Filled discs of radius `radius_px` at `centers`.
  void Discs(const std::vector<Eigen::Vector2d>& centers, double radius_px, const Color& color);

  // Queues text (see TextRenderer::Draw).
  void Text(const std::string& text, int size_px, double x, double y, HAlign h, VAlign v, const Color& color,
            bool vertical = false);
  TextExtent MeasureText(const std::string& text, int size_px) { return text_->Measure(text, size_px); }

  // 3-D drawing inside `viewport` with `projection` * `view` (OpenGL conventions, column vectors).
  void Begin3D(const Rect& viewport, const Eigen::Matrix4d& projection, const Eigen::Matrix4d& view);
  void Polyline3(const std::vector<Eigen::Vector3d>& points, const Color& color, double width_px);
  void Segments3(const std::vector<Eigen::Vector3d>& endpoints, const Color& color, double width_px);
  void Points3(const std::vector<Eigen::Vector3d>& points, const Color& color, double size_px);
  void End3D();

  // Ends the frame: reads the shapes back and draws the queued text.
  Image Finish();

 private:
  struct QueuedText {
    std::string text;
    int size_px;
    double x, y;
    HAlign h;
    VAlign v;
    Color color;
    bool vertical;
  };

  gl::GlContext* gl_;
  TextRenderer* text_;
  int width_, height_;
  std::vector<QueuedText> texts_;
};

}  // namespace vigil::plots
