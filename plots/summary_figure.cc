// Figure 6: sweep summary: ATE per glitch setting for each method, median over seeds with the seeds' spread.
#include <algorithm>
#include <cstdio>

#include "plots/figures.h"
#include "plots/method_colors.h"
#include "plots/style.h"

namespace vigil::plots {

Figure SummaryFigure(const std::vector<std::string>& setting_labels, const std::vector<std::string>& methods,
                     const std::vector<SummaryCell>& cells) {
  int runs = 0, failed = 0;
  for (const SummaryCell& c : cells) {
    runs += static_cast<int>(c.ate_trans_m.size()) + c.failed;
    failed += c.failed;
  }
  char title[160];
  std::snprintf(title, sizeof title, "ATE per glitch setting (%d runs, %d failed): median, quartiles, seeds",
                runs, failed);
  Figure figure(1, 2, title);
  std::vector<std::pair<double, std::string>> categories;
  for (std::size_t i = 0; i < setting_labels.size(); ++i)
    categories.emplace_back(static_cast<double>(i), setting_labels[i]);
  const int k = std::max<int>(1, static_cast<int>(methods.size()));
  const double slot = 0.7 / k;
  const MethodColors colors(methods);
  for (int col = 0; col < 2; ++col) {
    Axes& axes = figure.AddAxes(0, col);
    axes.title = col == 0 ? "ATE translation (RMSE)" : "ATE rotation (RMSE)";
    axes.x_label = "glitch setting (mean μ, std σ)";
    axes.y_label = col == 0 ? "ATE [m]" : "ATE [deg]";
    axes.SetXCategories(categories);
    axes.legend = col == 0 ? LegendPosition::kUpperLeft : LegendPosition::kNone;
    double y_hi = 0.0;
    for (int m = 0; m < static_cast<int>(methods.size()); ++m) {
      const Color color = colors.Of(methods[m]);
      std::vector<double> med_x, med_y;
      for (const SummaryCell& c : cells) {
        if (c.method != methods[m]) continue;
        const std::vector<double>& values = col == 0 ? c.ate_trans_m : c.ate_rot_deg;
        if (values.empty()) continue;
        const double x = c.setting + (m - (k - 1) / 2.0) * slot;
        const BoxStats stats = BoxStatsOf(values);
        axes.Box(x, stats, slot * 0.35, color, methods[m]);
        med_x.push_back(x);
        med_y.push_back(stats.median);
        // Every seed as a dot beside its box.
        axes.Scatter(std::vector<double>(values.size(), x + slot * 0.42), values, color.WithAlpha(0.7f), "",
                     0.6);
        y_hi = std::max(y_hi, *std::max_element(values.begin(), values.end()));
      }
      axes.Line(med_x, med_y, color, "", 0.7);
    }
    axes.SetYLimits(0.0, y_hi > 0.0 ? y_hi * 1.08 : 1.0);
  }
  return figure;
}

}  // namespace vigil::plots
