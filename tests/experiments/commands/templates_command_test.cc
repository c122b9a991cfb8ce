#include "experiments/commands/templates_command.h"

#include <filesystem>

#include <gtest/gtest.h>

#include "core/output.h"
#include "detectors/template_library.h"
#include "tests/core/test_util.h"
#include "tests/experiments/commands/command_test_util.h"

namespace vigil::experiments {
namespace {
namespace fs = std::filesystem;
using vigil::testing::InputErrorOf;
using vigil::testing::TempDir;
using vigil::testing::WriteSimulatedRecording;

TEST(BuildTemplateLibraryFile, BuildsFromTheCleanImuAndReportsTheCalibratedBounds) {
  TempDir tmp;
  WriteSimulatedRecording(tmp.path() / "rec", 6.0, 2, /*glitches=*/true);
  TemplatesRequest request;
  request.dataset = (tmp.path() / "rec").string();
  request.output = (tmp.path() / "templates.yaml").string();
  request.overrides = {"detector.dtw.templates=4"};
  std::string report;
  request.report = [&](const std::string& lines) { report += lines; };
  const TemplatesResult result = BuildTemplateLibraryFile(request);

  EXPECT_FALSE(result.used_imu_csv);  // imu_clean.csv is there: the glitch-free stream
  EXPECT_EQ(result.library.count(), 4);
  EXPECT_EQ(result.library.source, (fs::path(request.dataset) / "imu_clean.csv").string());
  const detectors::TemplateLibrary read = detectors::ReadTemplateLibrary(request.output);
  EXPECT_EQ(read.values, result.library.values);
  EXPECT_EQ(result.threshold_bounds.lower.size(), 6u);
  EXPECT_EQ(result.relative_threshold_bounds.size(), 6u);
  for (std::size_t a = 0; a < 6; ++a)
    EXPECT_LT(result.threshold_bounds.lower[a], result.threshold_bounds.upper[a]);
  // Three lines: the library, then both detectors' bounds as ready --set options.
  EXPECT_EQ(std::count(report.begin(), report.end(), '\n'), 3) << report;
  EXPECT_NE(report.find("vigil templates: 4 templates of "), std::string::npos) << report;
  EXPECT_NE(report.find("--set detector.threshold.calibration=manual"), std::string::npos) << report;
  EXPECT_NE(report.find("--set detector.relative_threshold.bounds=["), std::string::npos) << report;
}

TEST(BuildTemplateLibraryFile, WarnsBeforeTakingImuCsvAsClean) {
  TempDir tmp;
  WriteSimulatedRecording(tmp.path() / "rec", 6.0, 2, /*glitches=*/false);
  fs::remove(tmp.path() / "rec" / "imu_clean.csv");
  TemplatesRequest request;
  request.dataset = (tmp.path() / "rec").string();
  request.output = (tmp.path() / "templates.yaml").string();
  request.overrides = {"detector.dtw.templates=1000"};  // too many for 6 s: fails after the warning
  std::string report;
  request.report = [&](const std::string& lines) { report += lines; };
  const std::string error = InputErrorOf([&] { BuildTemplateLibraryFile(request); });
  EXPECT_NE(error.find("imu.csv: detector.dtw.templates"), std::string::npos) << error;
  EXPECT_NE(error.find("(use a longer clean recording or fewer detector.dtw.templates)"), std::string::npos);
  EXPECT_EQ(report, "vigil templates: " + request.dataset +
                        " has no imu_clean.csv, using imu.csv: it must be "
                        "glitch-free\n");
  EXPECT_FALSE(fs::exists(request.output));
}

TEST(BuildTemplateLibraryFile, NeverReplacesAFileVigilDidNotWriteNorAnInput) {
  TempDir tmp;
  WriteSimulatedRecording(tmp.path() / "rec", 6.0, 2, /*glitches=*/false);
  TemplatesRequest request;
  request.dataset = (tmp.path() / "rec").string();
  request.output = tmp.File("notes.yaml", "mine\n");
  request.force = true;
  EXPECT_NE(InputErrorOf([&] { BuildTemplateLibraryFile(request); }), "");
  EXPECT_EQ(ReadFile(request.output), "mine\n");
  request.output = (tmp.path() / "rec" / "imu_clean.csv").string();
  EXPECT_NE(InputErrorOf([&] { BuildTemplateLibraryFile(request); }).find("-o "), std::string::npos);
  request.output = (tmp.path() / "t.yaml").string();
  request.overrides = {"detector.dtw.nope=3"};
  EXPECT_EQ(InputErrorOf([&] { BuildTemplateLibraryFile(request); }),
            "--set: detector.dtw.nope: unknown key");
  EXPECT_FALSE(fs::exists(request.output));
}

}  // namespace
}  // namespace vigil::experiments
