// Figure 5: detection on one IMU axis: flagged samples shaded, the mitigated signal over the raw one.
#include <algorithm>
#include <cstdio>

#include "plots/figures.h"
#include "plots/style.h"

namespace vigil::plots {
namespace {

// Shades every run of consecutive flagged samples in [t0, t1] (each sample covers half a period each side).
void ShadeFlagged(Axes* axes, const DetectionTrace& trace, double t0, double t1, const Color& color) {
  const std::size_t n = std::min(trace.t_s.size(), trace.flagged.size());
  const double half = n > 1 ? (trace.t_s[n - 1] - trace.t_s[0]) / (n - 1) / 2.0 : 0.0;
  for (std::size_t i = 0; i < n;) {
    if (!trace.flagged[i]) {
      ++i;
      continue;
    }
    std::size_t j = i;
    while (j + 1 < n && trace.flagged[j + 1]) ++j;
    if (trace.t_s[j] + half >= t0 && trace.t_s[i] - half <= t1) {
      axes->Span(trace.t_s[i] - half, trace.t_s[j] + half, color, "flagged");
    }
    i = j + 1;
  }
}

// The samples with t in [t0, t1].
std::vector<double> Window(const std::vector<double>& t, const std::vector<double>& v, double t0, double t1,
                           std::vector<double>* t_out) {
  std::vector<double> out;
  if (t_out) t_out->clear();
  for (std::size_t i = 0; i < t.size() && i < v.size(); ++i) {
    if (t[i] < t0 || t[i] > t1) continue;
    out.push_back(v[i]);
    if (t_out) t_out->push_back(t[i]);
  }
  return out;
}

}  // namespace

Figure DetectionFigure(const DetectionTrace& trace) {
  std::size_t flagged = 0;
  for (uint8_t f : trace.flagged) flagged += f;
  char title[160];
  std::snprintf(title, sizeof title, "Glitch detection (%s): %zu of %zu samples flagged",
                trace.detector.c_str(), flagged, trace.flagged.size());
  Figure figure(3, 1, title);
  const Color span_color = PaletteColor(4).WithAlpha(0.35f);
  const std::string y_label = trace.axis_name + " [" + trace.unit + "]";

  Axes& whole = figure.AddAxes(0, 0);
  char whole_title[96];
  std::snprintf(whole_title, sizeof whole_title, "whole run (shaded: the excerpt below, %.2f to %.2f s)",
                trace.excerpt_t0_s, trace.excerpt_t1_s);
  whole.title = whole_title;
  whole.y_label = y_label;
  ShadeFlagged(&whole, trace, -1e300, 1e300, span_color);
  whole.Line(trace.t_s, trace.raw, PaletteColor(6), "raw", 0.5);
  whole.Line(trace.t_s, trace.mitigated, PaletteColor(0), "mitigated", 0.6);
  whole.Span(trace.excerpt_t0_s, trace.excerpt_t1_s, Color{0.0f, 0.0f, 0.0f, 0.06f});
  whole.legend = LegendPosition::kNone;

  Axes& excerpt = figure.AddAxes(1, 0, 2, 1);
  excerpt.title = "excerpt";
  excerpt.x_label = "time [s]";
  excerpt.y_label = y_label;
  excerpt.SetXLimits(trace.excerpt_t0_s, trace.excerpt_t1_s);
  ShadeFlagged(&excerpt, trace, trace.excerpt_t0_s, trace.excerpt_t1_s, span_color);
  std::vector<double> t;
  const std::vector<double> raw = Window(trace.t_s, trace.raw, trace.excerpt_t0_s, trace.excerpt_t1_s, &t);
  excerpt.Line(t, raw, PaletteColor(6), "raw (with glitches)", 0.8);
  if (!trace.clean.empty()) {
    excerpt.Line(t, Window(trace.t_s, trace.clean, trace.excerpt_t0_s, trace.excerpt_t1_s, nullptr), kBlack,
                 "without glitches", 0.7, /*dashed=*/true);
  }
  excerpt.Line(t, Window(trace.t_s, trace.mitigated, trace.excerpt_t0_s, trace.excerpt_t1_s, nullptr),
               PaletteColor(0), "mitigated", 1.0);
  excerpt.legend = LegendPosition::kUpperRight;
  return figure;
}

}  // namespace vigil::plots
