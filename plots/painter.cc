#include "plots/painter.h"

#include <algorithm>
#include <cmath>

#include "gl/gl_api.h"

namespace vigil::plots {
namespace {

void SetColor(const Color& c) { glColor4f(c.r, c.g, c.b, c.a); }

// Sets a 2-D pixel projection (y down) for the whole frame.
void PixelProjection(int width, int height) {
  glViewport(0, 0, width, height);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0.0, width, height, 0.0, -1.0, 1.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
}

// A segment as a quad of the given width (wide GL lines have no consistent joins or ends).
void EmitThickSegment(const Eigen::Vector2d& a, const Eigen::Vector2d& b, double half_width) {
  Eigen::Vector2d d = b - a;
  const double length = d.norm();
  if (length < 1e-12) return;
  d /= length;
  const Eigen::Vector2d n(-d.y() * half_width, d.x() * half_width);
  glVertex2d(a.x() + n.x(), a.y() + n.y());
  glVertex2d(b.x() + n.x(), b.y() + n.y());
  glVertex2d(b.x() - n.x(), b.y() - n.y());
  glVertex2d(a.x() + n.x(), a.y() + n.y());
  glVertex2d(b.x() - n.x(), b.y() - n.y());
  glVertex2d(a.x() - n.x(), a.y() - n.y());
}

// Round joins: a small disc at every interior vertex of a solid line.
void EmitDisc(const Eigen::Vector2d& c, double radius) {
  constexpr int kSides = 12;
  for (int i = 0; i < kSides; ++i) {
    const double a0 = 2.0 * M_PI * i / kSides, a1 = 2.0 * M_PI * (i + 1) / kSides;
    glVertex2d(c.x(), c.y());
    glVertex2d(c.x() + radius * std::cos(a0), c.y() + radius * std::sin(a0));
    glVertex2d(c.x() + radius * std::cos(a1), c.y() + radius * std::sin(a1));
  }
}

}  // namespace

Painter::Painter(gl::GlContext* gl, TextRenderer* text, int width, int height)
    : gl_(gl), text_(text), width_(width), height_(height) {
  gl_->BeginFrame(width, height, 1.0f, 1.0f, 1.0f);
  PixelProjection(width, height);
}

void Painter::SetClip(const Rect& clip) {
  glEnable(GL_SCISSOR_TEST);
  const int x0 = static_cast<int>(std::floor(clip.x)), x1 = static_cast<int>(std::ceil(clip.right()));
  const int y1 = static_cast<int>(std::ceil(clip.bottom())), y0 = static_cast<int>(std::floor(clip.y));
  glScissor(x0, height_ - y1, x1 - x0, y1 - y0);
}

void Painter::ClearClip() { glDisable(GL_SCISSOR_TEST); }

void Painter::Polyline(const std::vector<Eigen::Vector2d>& points, const Color& color, double width_px,
                       double dash_px) {
  if (points.size() < 2) return;
  // Opaque lines are quads with round joins. Translucent ones are one GL line strip instead, because
  // overlapping join geometry would blend twice and darken the joins.
  const double half = std::max(width_px, 0.5) / 2.0;
  SetColor(color);
  if (color.a < 1.0f) {
    glLineWidth(static_cast<float>(std::max(width_px, 1.0)));
    glBegin(GL_LINE_STRIP);
    for (const auto& p : points) glVertex2d(p.x(), p.y());
    glEnd();
    return;
  }
  glBegin(GL_TRIANGLES);
  if (dash_px > 0.0) {
    // Walk the polyline, drawing `dash_px` on and `dash_px` off.
    double phase = 0.0;
    bool on = true;
    for (std::size_t i = 1; i < points.size(); ++i) {
      Eigen::Vector2d a = points[i - 1];
      const Eigen::Vector2d b = points[i];
      double remaining = (b - a).norm();
      if (remaining < 1e-12) continue;
      const Eigen::Vector2d dir = (b - a) / remaining;
      while (remaining > 0.0) {
        const double step = std::min(remaining, dash_px - phase);
        const Eigen::Vector2d next = a + dir * step;
        if (on) EmitThickSegment(a, next, half);
        phase += step;
        remaining -= step;
        a = next;
        if (phase >= dash_px - 1e-9) {
          phase = 0.0;
          on = !on;
        }
      }
    }
  } else {
    for (std::size_t i = 1; i < points.size(); ++i) EmitThickSegment(points[i - 1], points[i], half);
    if (half > 0.75) {
      for (std::size_t i = 1; i + 1 < points.size(); ++i) EmitDisc(points[i], half);
    }
  }
  glEnd();
}

void Painter::FillRect(const Rect& rect, const Color& color) {
  SetColor(color);
  glBegin(GL_TRIANGLES);
  glVertex2d(rect.x, rect.y);
  glVertex2d(rect.right(), rect.y);
  glVertex2d(rect.right(), rect.bottom());
  glVertex2d(rect.x, rect.y);
  glVertex2d(rect.right(), rect.bottom());
  glVertex2d(rect.x, rect.bottom());
  glEnd();
}

void Painter::StrokeRect(const Rect& rect, const Color& color, double width_px) {
  const double x0 = rect.x, y0 = rect.y, x1 = rect.right(), y1 = rect.bottom(), w = width_px;
  FillRect({x0 - w / 2, y0 - w / 2, x1 - x0 + w, w}, color);
  FillRect({x0 - w / 2, y1 - w / 2, x1 - x0 + w, w}, color);
  FillRect({x0 - w / 2, y0 + w / 2, w, y1 - y0 - w}, color);
  FillRect({x1 - w / 2, y0 + w / 2, w, y1 - y0 - w}, color);
}

void Painter::Discs(const std::vector<Eigen::Vector2d>& centers, double radius_px, const Color& color) {
  SetColor(color);
  glBegin(GL_TRIANGLES);
  for (const auto& c : centers) EmitDisc(c, radius_px);
  glEnd();
}

void Painter::Text(const std::string& text, int size_px, double x, double y, HAlign h, VAlign v,
                   const Color& color, bool vertical) {
  texts_.push_back({text, size_px, x, y, h, v, color, vertical});
}

void Painter::Begin3D(const Rect& viewport, const Eigen::Matrix4d& projection, const Eigen::Matrix4d& view) {
  const int x0 = static_cast<int>(std::lround(viewport.x)),
            y1 = static_cast<int>(std::lround(viewport.bottom()));
  const int w = static_cast<int>(std::lround(viewport.w)), h = static_cast<int>(std::lround(viewport.h));
  glViewport(x0, height_ - y1, w, h);
  SetClip(viewport);
  glMatrixMode(GL_PROJECTION);
  glLoadMatrixd(projection.data());
  glMatrixMode(GL_MODELVIEW);
  glLoadMatrixd(view.data());
  glClear(GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LEQUAL);
}

void Painter::Polyline3(const std::vector<Eigen::Vector3d>& points, const Color& color, double width_px) {
  SetColor(color);
  glLineWidth(static_cast<float>(width_px));
  glBegin(GL_LINE_STRIP);
  for (const auto& p : points) glVertex3d(p.x(), p.y(), p.z());
  glEnd();
}

void Painter::Segments3(const std::vector<Eigen::Vector3d>& endpoints, const Color& color, double width_px) {
  SetColor(color);
  glLineWidth(static_cast<float>(width_px));
  glBegin(GL_LINES);
  for (const auto& p : endpoints) glVertex3d(p.x(), p.y(), p.z());
  glEnd();
}

void Painter::Points3(const std::vector<Eigen::Vector3d>& points, const Color& color, double size_px) {
  SetColor(color);
  glPointSize(static_cast<float>(size_px));
  glEnable(GL_POINT_SMOOTH);
  glBegin(GL_POINTS);
  for (const auto& p : points) glVertex3d(p.x(), p.y(), p.z());
  glEnd();
  glDisable(GL_POINT_SMOOTH);
}

void Painter::End3D() {
  glDisable(GL_DEPTH_TEST);
  ClearClip();
  PixelProjection(width_, height_);
}

Image Painter::Finish() {
  Image image(width_, height_);
  image.rgba = gl_->EndFrame();
  for (const QueuedText& t : texts_) {
    text_->Draw(&image, t.text, t.size_px, t.x, t.y, t.h, t.v, t.color, t.vertical);
  }
  texts_.clear();
  return image;
}

}  // namespace vigil::plots
