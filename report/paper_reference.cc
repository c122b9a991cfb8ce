#include "report/paper_reference.h"

#include <utility>

namespace vigil::report {
namespace {
const std::vector<std::string> kDistanceRows = {"7 m", "14 m", "21 m", "28 m", "35 m"};
const std::vector<std::string> kMethods = {"trunc", "dtw", "original"};

// Tables 3 and 4: one row per distance, one column per method.
ResultTable PaperDistanceTable(const std::string& title, std::vector<std::vector<double>> values) {
  ResultTable t;
  t.title = title;
  t.corner = "distance";
  t.columns = kMethods;
  t.rows = kDistanceRows;
  t.values = std::move(values);
  return t;
}

}  // namespace

ResultTable PaperTable2() {
  ResultTable t;
  t.title = "Table 2 (paper): RMSE of translation [m] (absolute trajectory error)";
  t.corner = "method";
  t.columns = {"noise_0_1", "noise_1_10", "noise_50_10"};
  t.rows = kMethods;
  t.values = {{0.04, 0.14, 0.32}, {0.06, 0.15, 0.06}, {0.06, 0.15, 18.05}};
  return t;
}

ResultTable PaperTable3() {
  return PaperDistanceTable(
      "Table 3 (paper): overall relative translation error [m]",
      {{0.16, 0.07, 2.50}, {0.26, 0.10, 3.03}, {0.37, 0.14, 3.54}, {0.43, 0.17, 4.02}, {0.51, 0.20, 4.29}});
}

ResultTable PaperTable4() {
  return PaperDistanceTable("Table 4 (paper): overall relative yaw error [deg]", {{0.61, 0.08, 9.47},
                                                                                  {0.49, 0.08, 9.66},
                                                                                  {0.53, 0.09, 10.96},
                                                                                  {0.51, 0.10, 12.81},
                                                                                  {0.55, 0.10, 14.71}});
}

}  // namespace vigil::report
