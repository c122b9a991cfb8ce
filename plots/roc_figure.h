// The detector ROC figure: true-positive rate vs false-positive rate per sample, one curve per detector
// (experiments/sweeps/detection_roc.h), its threshold points marked; drawn from what the runs recorded.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "experiments/sweeps/detection_roc.h"
#include "plots/figure.h"
#include "plots/render.h"

namespace vigil::plots {

Figure RocFigure(const std::vector<experiments::RocCurve>& curves, const std::string& title);

void WriteRocFigure(const std::vector<experiments::RocCurve>& curves, const std::string& title,
                    const std::filesystem::path& path, const FigureOptions& options);

}  // namespace vigil::plots
