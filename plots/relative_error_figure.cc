// Figure 4: relative translation and yaw error vs distance travelled, box plots per method.
#include <algorithm>
#include <cmath>

#include "plots/figures.h"
#include "plots/method_colors.h"
#include "plots/style.h"

namespace vigil::plots {

Figure RelativeErrorFigure(const std::vector<RelativeErrorRow>& rows, const std::string& note) {
  const int n = std::max<int>(1, static_cast<int>(rows.size()));
  Figure figure(n, 2, "Relative error vs distance travelled (" + note + ")");
  std::vector<std::string> methods;
  for (const RelativeErrorRow& row : rows)
    for (const RelativeErrorBoxes& boxes : row.methods)
      if (std::find(methods.begin(), methods.end(), boxes.method) == methods.end())
        methods.push_back(boxes.method);
  const MethodColors colors(methods);
  for (int r = 0; r < static_cast<int>(rows.size()); ++r) {
    const RelativeErrorRow& row = rows[r];
    // Boxes of one distance sit side by side inside 70 % of the smallest gap between distances.
    std::vector<double> all_d;
    for (const auto& m : row.methods) all_d.insert(all_d.end(), m.distances_m.begin(), m.distances_m.end());
    std::sort(all_d.begin(), all_d.end());
    all_d.erase(std::unique(all_d.begin(), all_d.end()), all_d.end());
    double gap = 1.0;
    for (std::size_t i = 1; i < all_d.size(); ++i)
      gap = i == 1 ? all_d[1] - all_d[0] : std::min(gap, all_d[i] - all_d[i - 1]);
    if (all_d.size() == 1) gap = std::max(1.0, all_d[0] * 0.5);
    const int k = std::max<int>(1, static_cast<int>(row.methods.size()));
    const double slot = 0.7 * gap / k;
    std::vector<std::pair<double, std::string>> categories;
    for (double d : all_d) {
      char text[32];
      std::snprintf(text, sizeof text, "%g", d);
      categories.emplace_back(d, text);
    }
    for (int col = 0; col < 2; ++col) {
      Axes& axes = figure.AddAxes(r, col);
      axes.title = row.label + (col == 0 ? ": translation" : ": yaw");
      axes.x_label = "distance travelled [m]";
      axes.y_label = col == 0 ? "translation error [m]" : "yaw error [deg]";
      axes.SetXCategories(categories);
      double x_lo = all_d.empty() ? 0.0 : all_d.front() - gap / 2,
             x_hi = all_d.empty() ? 1.0 : all_d.back() + gap / 2;
      axes.SetXLimits(x_lo, x_hi);
      double y_hi = 0.0;
      for (int m = 0; m < static_cast<int>(row.methods.size()); ++m) {
        const RelativeErrorBoxes& boxes = row.methods[m];
        const auto& stats = col == 0 ? boxes.trans_m : boxes.yaw_deg;
        for (std::size_t i = 0; i < boxes.distances_m.size() && i < stats.size(); ++i) {
          const double x = boxes.distances_m[i] + (m - (k - 1) / 2.0) * slot;
          axes.Box(x, stats[i], slot * 0.4, colors.Of(boxes.method), boxes.method);
          y_hi = std::max(y_hi, stats[i].whisker_hi);
        }
      }
      axes.SetYLimits(0.0, y_hi > 0.0 ? y_hi * 1.08 : 1.0);
      axes.legend = r == 0 && col == 0 ? LegendPosition::kUpperLeft : LegendPosition::kNone;
    }
  }
  return figure;
}

}  // namespace vigil::plots
