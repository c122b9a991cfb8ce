#include "plots/axes3d.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "plots/ticks.h"

namespace vigil::plots {

Eigen::Matrix4d Perspective(double fov_y_rad, double aspect, double z_near, double z_far) {
  const double f = 1.0 / std::tan(fov_y_rad / 2.0);
  Eigen::Matrix4d m = Eigen::Matrix4d::Zero();
  m(0, 0) = f / aspect;
  m(1, 1) = f;
  m(2, 2) = (z_far + z_near) / (z_near - z_far);
  m(2, 3) = 2.0 * z_far * z_near / (z_near - z_far);
  m(3, 2) = -1.0;
  return m;
}

Eigen::Matrix4d LookAt(const Eigen::Vector3d& eye, const Eigen::Vector3d& target, const Eigen::Vector3d& up) {
  const Eigen::Vector3d f = (target - eye).normalized();
  const Eigen::Vector3d s = f.cross(up).normalized();
  const Eigen::Vector3d u = s.cross(f);
  Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
  m.block<1, 3>(0, 0) = s.transpose();
  m.block<1, 3>(1, 0) = u.transpose();
  m.block<1, 3>(2, 0) = -f.transpose();
  m(0, 3) = -s.dot(eye);
  m(1, 3) = -u.dot(eye);
  m(2, 3) = f.dot(eye);
  return m;
}

void Axes3D::Line(std::vector<Eigen::Vector3d> points, const Color& color, const std::string& label,
                  double width_scale) {
  series_.push_back({std::move(points), color, width_scale, true});
  legend_entries_.push_back({label, color, LegendKind::kLine, false});
}

void Axes3D::Points(std::vector<Eigen::Vector3d> points, const Color& color, const std::string& label,
                    double size_scale) {
  series_.push_back({std::move(points), color, size_scale, false});
  legend_entries_.push_back({label, color, LegendKind::kMarker, false});
}

Eigen::Vector2d Axes3D::ToPixel(const Eigen::Vector3d& p) const {
  const Eigen::Vector4d clip = projection_ * view_ * p.homogeneous();
  const double nx = clip.x() / clip.w(), ny = clip.y() / clip.w();
  return {viewport_.x + (nx + 1.0) / 2.0 * viewport_.w, viewport_.y + (1.0 - ny) / 2.0 * viewport_.h};
}

void Axes3D::Draw(Painter& painter, const Rect& cell, const Style& style) {
  const double pad = style.pad_px();
  const double top = cell.y + pad + (title.empty() ? 0.0 : style.axes_title_px() * 1.5);
  viewport_ = {cell.x + pad, top, std::max(cell.w - 2 * pad, 10.0),
               std::max(cell.bottom() - pad - top, 10.0)};

  constexpr double kInf = std::numeric_limits<double>::infinity();
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(kInf), hi = Eigen::Vector3d::Constant(-kInf);
  for (const Series& s : series_) {
    for (const auto& p : s.points) {
      if (!p.allFinite()) continue;
      lo = lo.cwiseMin(p);
      hi = hi.cwiseMax(p);
    }
  }
  for (int i = 0; i < 3; ++i) PadRange(&lo[i], &hi[i], 0.02);
  const Eigen::Vector3d center = (lo + hi) / 2.0;
  const double radius = (hi - lo).norm() / 2.0;
  const double az = azimuth_deg * M_PI / 180.0, el = elevation_deg * M_PI / 180.0;
  const double fov = fov_y_deg * M_PI / 180.0, aspect = viewport_.w / viewport_.h;
  // Start where the bounding sphere fits the narrower field of view; that is a loose fit for flat scenes, so
  // move closer until the box corners fill about 90 % of the viewport (a few fixed-point steps: the projected
  // size scales about inversely with the distance).
  const double half_fov = std::atan(std::tan(fov / 2.0) * std::min(1.0, aspect));
  const Eigen::Vector3d direction(std::cos(el) * std::cos(az), std::cos(el) * std::sin(az), std::sin(el));
  double distance = radius / std::sin(half_fov) * 1.05;
  for (int iteration = 0; iteration <= 4; ++iteration) {
    view_ = LookAt(center + distance * direction, center, Eigen::Vector3d::UnitZ());
    projection_ = Perspective(fov, aspect, distance * 0.05, distance + 2.0 * radius);
    if (iteration == 4) break;
    double extent = 0.0;
    for (int corner = 0; corner < 8; ++corner) {
      const Eigen::Vector3d p((corner & 1) ? hi.x() : lo.x(), (corner & 2) ? hi.y() : lo.y(),
                              (corner & 4) ? hi.z() : lo.z());
      const Eigen::Vector4d clip = projection_ * view_ * p.homogeneous();
      extent = std::max({extent, std::abs(clip.x() / clip.w()), std::abs(clip.y() / clip.w())});
    }
    distance = std::max(distance * std::clamp(extent / 0.88, 0.5, 2.0), radius * 1.2);
  }

  painter.Begin3D(viewport_, projection_, view_);
  // Bounding box wireframe and a floor grid at the nice ticks of x and y.
  std::vector<Eigen::Vector3d> edges;
  for (int axis = 0; axis < 3; ++axis) {
    const int a = (axis + 1) % 3, b = (axis + 2) % 3;
    for (int k = 0; k < 4; ++k) {
      Eigen::Vector3d p0, p1;
      p0[axis] = lo[axis];
      p1[axis] = hi[axis];
      p0[a] = p1[a] = (k & 1) ? hi[a] : lo[a];
      p0[b] = p1[b] = (k & 2) ? hi[b] : lo[b];
      edges.push_back(p0);
      edges.push_back(p1);
    }
  }
  const Ticks x_ticks = NiceTicks(lo.x(), hi.x(), 5), y_ticks = NiceTicks(lo.y(), hi.y(), 5);
  std::vector<Eigen::Vector3d> grid;
  for (double x : x_ticks.values) {
    grid.emplace_back(x, lo.y(), lo.z());
    grid.emplace_back(x, hi.y(), lo.z());
  }
  for (double y : y_ticks.values) {
    grid.emplace_back(lo.x(), y, lo.z());
    grid.emplace_back(hi.x(), y, lo.z());
  }
  painter.Segments3(grid, kGridColor, std::max(1.0, style.scale));
  painter.Segments3(edges, Color{0.55f, 0.55f, 0.55f, 1.0f}, std::max(1.0, style.scale));
  for (const Series& s : series_) {
    if (s.is_line) {
      painter.Polyline3(s.points, s.color, style.line_px() * s.scale);
    } else {
      painter.Points3(s.points, s.color, 5.0 * style.scale * s.scale);
    }
  }
  painter.End3D();

  // Tick labels along the front floor edges and the axis names.
  const Color label_color = kTextColor;
  for (double x : x_ticks.values) {
    const Eigen::Vector2d px = ToPixel({x, lo.y(), lo.z()});
    if (viewport_.Contains(px.x(), px.y())) {
      painter.Text(FormatTick(x, x_ticks.step), style.tick_px(), px.x(), px.y() + pad / 2, HAlign::kCenter,
                   VAlign::kTop, label_color);
    }
  }
  for (double y : y_ticks.values) {
    const Eigen::Vector2d px = ToPixel({hi.x(), y, lo.z()});
    if (viewport_.Contains(px.x(), px.y())) {
      painter.Text(FormatTick(y, y_ticks.step), style.tick_px(), px.x() + pad / 2, px.y() + pad / 2,
                   HAlign::kLeft, VAlign::kTop, label_color);
    }
  }
  const Eigen::Vector2d xl = ToPixel({center.x(), lo.y(), lo.z()}),
                        yl = ToPixel({hi.x(), center.y(), lo.z()});
  const Eigen::Vector2d zl = ToPixel({lo.x(), lo.y(), center.z()});
  painter.Text(x_label, style.label_px(), xl.x(), xl.y() + style.tick_px() * 1.8, HAlign::kCenter,
               VAlign::kTop, label_color);
  painter.Text(y_label, style.label_px(), yl.x() + style.tick_px() * 3.0, yl.y() + style.tick_px(),
               HAlign::kLeft, VAlign::kTop, label_color);
  painter.Text(z_label, style.label_px(), zl.x() - pad, zl.y(), HAlign::kRight, VAlign::kMiddle, label_color);
  if (!title.empty()) {
    painter.Text(title, style.axes_title_px(), viewport_.x + viewport_.w / 2, viewport_.y - pad,
                 HAlign::kCenter, VAlign::kBottom, kTextColor);
  }
  DrawLegend(painter, legend_entries_, viewport_, legend, style);
}

}  // namespace vigil::plots
