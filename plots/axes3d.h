// A 3-D perspective view: lines and points drawn with OpenGL depth testing inside the panel, over the
// wireframe of the data's bounding box with ticks on its floor edges. Axes have equal scale (metres).
#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "plots/legend.h"
#include "plots/panel.h"

namespace vigil::plots {

class Axes3D : public Panel {
 public:
  std::string title;
  std::string x_label = "x [m]", y_label = "y [m]", z_label = "z [m]";
  double azimuth_deg = -55.0;   // camera direction around z, from the +x axis
  double elevation_deg = 28.0;  // camera height angle above the x-y plane
  double fov_y_deg = 30.0;
  LegendPosition legend = LegendPosition::kUpperRight;

  void Line(std::vector<Eigen::Vector3d> points, const Color& color, const std::string& label = "",
            double width_scale = 1.0);
  void Points(std::vector<Eigen::Vector3d> points, const Color& color, const std::string& label = "",
              double size_scale = 1.0);

  void Draw(Painter& painter, const Rect& cell, const Style& style) override;

  // Projection and view matrices of the last Draw() and its viewport (for tests and labels).
  Eigen::Matrix4d projection() const { return projection_; }
  Eigen::Matrix4d view() const { return view_; }
  // Pixel position of a world point in the last Draw()'s viewport.
  Eigen::Vector2d ToPixel(const Eigen::Vector3d& p) const;

 private:
  struct Series {
    std::vector<Eigen::Vector3d> points;
    Color color;
    double scale;
    bool is_line;
  };
  std::vector<Series> series_;
  std::vector<LegendEntry> legend_entries_;
  Eigen::Matrix4d projection_ = Eigen::Matrix4d::Identity(), view_ = Eigen::Matrix4d::Identity();
  Rect viewport_;
};

// OpenGL-style matrices (column vectors, camera looking down -z).
Eigen::Matrix4d Perspective(double fov_y_rad, double aspect, double z_near, double z_far);
Eigen::Matrix4d LookAt(const Eigen::Vector3d& eye, const Eigen::Vector3d& target, const Eigen::Vector3d& up);

}  // namespace vigil::plots
