// The published numbers of tables 2-4 of Long et al., IFAC 2020 (docs/references.md), shown beside
// the regenerated ones in summary.md. They are the paper's results, used for comparison only.
#pragma once

#include "report/result_table.h"

namespace vigil::report {

ResultTable
PaperTable2();  // ATE RMSE [m]: rows trunc, dtw, original; columns noise_0_1, noise_1_10, noise_50_10
ResultTable
PaperTable3();  // relative translation error [m]: rows "7 m".."35 m"; columns trunc, dtw, original
ResultTable PaperTable4();  // relative yaw error [deg], same layout

// The slice length M of the paper's DTW detector in its simulation (samples).
inline constexpr int kPaperSliceLength = 40;

}  // namespace vigil::report
