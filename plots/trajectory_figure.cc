// Figure 3: ground truth and each method's aligned estimate, top (x-y) and side (x-z) view per glitch
// setting.
#include <algorithm>

#include "plots/figures.h"
#include "plots/method_colors.h"
#include "plots/style.h"

namespace vigil::plots {
namespace {

void Project(const std::vector<Eigen::Vector3d>& points, int a, int b, std::vector<double>* x,
             std::vector<double>* y) {
  for (const auto& p : points) {
    x->push_back(p[a]);
    y->push_back(p[b]);
  }
}

}  // namespace

Figure TrajectoryFigure(const std::vector<TrajectoryPanel>& rows) {
  const int n = std::max<int>(1, static_cast<int>(rows.size()));
  Figure figure(n, 2, "Trajectories: ground truth and aligned estimates");
  std::vector<std::string> methods;
  for (const TrajectoryPanel& row : rows)
    for (const MethodTrajectory& m : row.estimates)
      if (std::find(methods.begin(), methods.end(), m.method) == methods.end()) methods.push_back(m.method);
  const MethodColors colors(methods);
  for (int r = 0; r < static_cast<int>(rows.size()); ++r) {
    const TrajectoryPanel& row = rows[r];
    for (int view = 0; view < 2; ++view) {
      Axes& axes = figure.AddAxes(r, view);
      axes.title = row.label + (view == 0 ? ": top view" : ": side view");
      axes.x_label = "x [m]";
      axes.y_label = view == 0 ? "y [m]" : "z [m]";
      axes.equal_aspect = view == 0;
      const int b = view == 0 ? 1 : 2;
      std::vector<double> x, y;
      Project(row.groundtruth_W, 0, b, &x, &y);
      axes.Line(x, y, kBlack, "ground truth", 1.0, /*dashed=*/true);
      for (const MethodTrajectory& m : row.estimates) {
        std::vector<double> ex, ey;
        Project(m.p_W, 0, b, &ex, &ey);
        axes.Line(ex, ey, colors.Of(m.method), m.method, 0.9);
      }
      axes.legend = r == 0 && view == 1 ? LegendPosition::kOutsideRight : LegendPosition::kNone;
    }
  }
  return figure;
}

}  // namespace vigil::plots
