#include "detectors/template_library.h"

#include <algorithm>

#include <gtest/gtest.h>

#include "detectors/dtw_distance.h"
#include "synthetic_imu.h"
#include "tests/core/test_util.h"

namespace vigil::detectors {
namespace {

using vigil::testing::InputErrorOf;
using vigil::testing::TempDir;

TEST(TemplateLibrary, BuildsKTemplatesAndACalibratedThreshold) {
  const ImuStream clean = testing::SyntheticImu(1000, 4001);
  DtwOptions options;
  const TemplateLibrary lib = BuildTemplates(clean, options);
  EXPECT_EQ(lib.count(), options.templates);
  EXPECT_EQ(lib.template_length, options.template_length);
  EXPECT_EQ(lib.slice_length, options.slice_length);
  EXPECT_EQ(lib.dims, 6);
  EXPECT_EQ(lib.calibration_slices, 100);
  EXPECT_DOUBLE_EQ(lib.threshold, options.threshold_margin * lib.calibration_quantile_distance);
  // The threshold sits above (almost) every clean slice of the build data, and above most slices of another
  // clean run with the same motion.
  const std::vector<double> same = SliceDistances(lib, clean);
  EXPECT_LE(std::count_if(same.begin(), same.end(), [&](double d) { return d > lib.threshold; }), 1);
  const std::vector<double> other = SliceDistances(lib, testing::SyntheticImu(7, 4001));
  EXPECT_LE(std::count_if(other.begin(), other.end(), [&](double d) { return d > lib.threshold; }), 2);
  // Deterministic.
  EXPECT_EQ(BuildTemplates(clean, options).values, lib.values);
}

TEST(TemplateLibrary, KMedoidsBeatsEvenlySpacedTemplates) {
  // The selected templates cover the clean slices better than k slices picked at regular intervals.
  const ImuStream clean = testing::SyntheticImu(1000, 4001);
  DtwOptions options;
  options.swap_passes = 0;
  const TemplateLibrary greedy = BuildTemplates(clean, options);
  options.swap_passes = 10;
  const TemplateLibrary swapped = BuildTemplates(clean, options);
  TemplateLibrary spaced = swapped;
  spaced.values.clear();
  {
    DtwOptions all = options;
    all.templates = 99;
    all.swap_passes = 0;
    const TemplateLibrary many = BuildTemplates(clean, all);  // 99 candidates in greedy order; spread pick
    for (int t = 0; t < 10; ++t)
      spaced.values.insert(spaced.values.end(), many.Template(t * 9), many.Template(t * 9) + 10 * 6);
  }
  auto total = [&](const TemplateLibrary& lib) {
    double sum = 0.0;
    for (double d : SliceDistances(lib, clean)) sum += d;
    return sum;
  };
  EXPECT_LE(total(swapped), total(greedy) + 1e-9);
  EXPECT_LT(total(swapped), total(spaced));
}

TEST(TemplateLibrary, YamlRoundTripIsExact) {
  TempDir dir;
  TemplateLibrary lib = BuildTemplates(testing::SyntheticImu(1000, 2000), {});
  lib.source = "sim seed 1000: \"clean\"";
  const std::string path = dir.File("t.yaml", TemplateLibraryYaml(lib));
  const TemplateLibrary back = ReadTemplateLibrary(path);
  EXPECT_EQ(back.values, lib.values);
  EXPECT_EQ(back.threshold, lib.threshold);
  EXPECT_EQ(back.slice_length, lib.slice_length);
  EXPECT_EQ(back.template_length, lib.template_length);
  EXPECT_EQ(back.dims, lib.dims);
  EXPECT_EQ(back.normalization, lib.normalization);
  EXPECT_EQ(back.source, lib.source);
  EXPECT_EQ(back.calibration_quantile_distance, lib.calibration_quantile_distance);
}

TEST(TemplateLibrary, BadFilesNameFileLineAndKey) {
  TempDir dir;
  const std::string good = TemplateLibraryYaml(BuildTemplates(testing::SyntheticImu(1000, 2000), {}));
  auto with = [&](const std::string& from, const std::string& to) {
    std::string text = good;
    text.replace(text.find(from), from.size(), to);
    return dir.File("bad.yaml", text);
  };
  std::string msg = InputErrorOf([&] { ReadTemplateLibrary(with("dims: 6", "dims: 4")); });
  EXPECT_NE(msg.find("dims"), std::string::npos) << msg;
  msg = InputErrorOf([&] { ReadTemplateLibrary(with("threshold: ", "threshold: x")); });
  EXPECT_NE(msg.find("bad.yaml:"), std::string::npos) << msg;
  EXPECT_NE(msg.find("threshold"), std::string::npos) << msg;
  const auto row = good.find("    - [");
  const auto comma = good.find(',', row);
  msg = InputErrorOf([&] { ReadTemplateLibrary(with(good.substr(row, comma - row + 1), "    - [1, nan,")); });
  EXPECT_NE(msg.find("templates[0][0]"), std::string::npos) << msg;
  msg = InputErrorOf([&] { ReadTemplateLibrary(dir.File("other.yaml", "seed: 1\n")); });
  EXPECT_NE(msg.find("format"), std::string::npos) << msg;
  msg = InputErrorOf([&] { ReadTemplateLibrary((dir.path() / "missing.yaml").string()); });
  EXPECT_NE(msg.find("missing.yaml"), std::string::npos) << msg;
}

TEST(TemplateLibrary, RejectsTooLittleDataAndBadGeometry) {
  EXPECT_NE(InputErrorOf([] {
              BuildTemplates(testing::SyntheticImu(1, 400), {});
            }).find("clean slices of 40 samples, the clean data has 10: lower detector.dtw.templates"),
            std::string::npos);
  DtwOptions options;
  options.template_length = 41;
  EXPECT_NE(
      InputErrorOf([&] { BuildTemplates(testing::SyntheticImu(1, 4000), options); }).find("template_length"),
      std::string::npos);
  options = {};
  options.dims = 5;
  EXPECT_NE(InputErrorOf([&] { BuildTemplates(testing::SyntheticImu(1, 4000), options); }).find("dims"),
            std::string::npos);
}

}  // namespace
}  // namespace vigil::detectors
