#include "plots/roc_figure.h"

#include <algorithm>
#include <cmath>

#include "plots/figure_png.h"
#include "plots/figures.h"
#include "plots/method_colors.h"

namespace vigil::plots {

Figure RocFigure(const std::vector<experiments::RocCurve>& curves, const std::string& title) {
  Figure figure(1, 1, title);
  Axes& axes = figure.AddAxes(0, 0);
  axes.title = "TPR vs FPR per sample (each point one threshold)";
  axes.x_label = "false-positive rate [%]";
  axes.y_label = "true-positive rate";
  axes.legend = LegendPosition::kLowerRight;
  double x_hi = 0.0;
  std::vector<std::string> detectors;
  for (const experiments::RocCurve& curve : curves) detectors.push_back(curve.detector);
  const MethodColors colors(detectors);
  for (std::size_t i = 0; i < curves.size(); ++i) {
    std::vector<double> x, y;
    for (const experiments::RocPoint& p : curves[i].points) {
      if (!std::isfinite(p.fpr) || !std::isfinite(p.tpr)) continue;
      x.push_back(100.0 * p.fpr);
      y.push_back(p.tpr);
    }
    if (x.empty()) continue;
    x_hi = std::max(x_hi, *std::max_element(x.begin(), x.end()));
    const Color color = colors.Of(curves[i].detector);
    axes.Line(x, y, color, curves[i].detector);
    axes.Scatter(x, y, color, "", 1.2);
  }
  axes.SetXLimits(0.0, x_hi > 0.0 ? 1.05 * x_hi : 1.0);
  axes.SetYLimits(0.0, 1.02);
  return figure;
}

void WriteRocFigure(const std::vector<experiments::RocCurve>& curves, const std::string& title,
                    const std::filesystem::path& path, const FigureOptions& options) {
  WriteFigurePng(RocFigure(curves, title), path, options);
}

}  // namespace vigil::plots
