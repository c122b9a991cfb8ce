// Figure 1: the simulated scenario (trajectory and landmarks) in three projections and a 3-D view.
#include "plots/figures.h"
#include "plots/style.h"

namespace vigil::plots {

Figure ScenarioFigure(const ScenarioData& data) {
  Figure figure(2, 2, data.title.empty() ? "Simulated trajectory and landmarks" : data.title);
  const Color path_color = PaletteColor(0), landmark_color = PaletteColor(1);
  struct View {
    int row, col, a, b;
    const char* title;
    const char* x_label;
    const char* y_label;
  };
  const View views[] = {{0, 0, 0, 1, "X-Y (top)", "x [m]", "y [m]"},
                        {0, 1, 0, 2, "X-Z (side)", "x [m]", "z [m]"},
                        {1, 0, 1, 2, "Y-Z (front)", "y [m]", "z [m]"}};
  for (const View& v : views) {
    Axes& axes = figure.AddAxes(v.row, v.col);
    axes.title = v.title;
    axes.x_label = v.x_label;
    axes.y_label = v.y_label;
    axes.equal_aspect = true;
    std::vector<double> lx, ly, px, py;
    for (const auto& p : data.landmarks_W) {
      lx.push_back(p[v.a]);
      ly.push_back(p[v.b]);
    }
    for (const auto& p : data.path_W) {
      px.push_back(p[v.a]);
      py.push_back(p[v.b]);
    }
    if (!lx.empty()) axes.Scatter(lx, ly, landmark_color, "landmarks", 0.8);  // a recording has none
    axes.Line(px, py, path_color, "trajectory");
    axes.legend = v.row == 0 && v.col == 0 ? LegendPosition::kUpperRight : LegendPosition::kNone;
  }
  Axes3D& view = figure.AddAxes3D(1, 1);
  view.title = "3-D view";
  if (!data.landmarks_W.empty()) view.Points(data.landmarks_W, landmark_color, "landmarks");
  view.Line(data.path_W, path_color, "trajectory");
  view.legend = LegendPosition::kNone;
  return figure;
}

}  // namespace vigil::plots
