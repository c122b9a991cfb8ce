#include "experiments/sweeps/sweep_spec.h"

#include <algorithm>
#include <filesystem>

#include <gtest/gtest.h>

#include "experiments/sweeps/sweep_runner.h"
#include "tests/core/test_util.h"
#include "tests/experiments/sweeps/sweep_test_util.h"

namespace vigil::experiments {
namespace {
using testing::WriteSmallSweep;
using vigil::testing::InputErrorOf;
using vigil::testing::TempDir;
namespace fs = std::filesystem;

TEST(SweepSpec, GridIdsAndOverridesInOrder) {
  TempDir dir;
  const SweepSpec spec =
      LoadSweepSpec(WriteSmallSweep(dir, "  trunc: threshold\n  original: {type: none}\n"));
  ASSERT_EQ(spec.axes.size(), 1u);
  EXPECT_EQ(spec.axes[0].key, "glitch");
  EXPECT_EQ(spec.seeds, (std::vector<uint64_t>{1, 2, 3}));
  EXPECT_EQ(spec.cell_count(), 4u);
  EXPECT_EQ(spec.run_count(), 12u);
  EXPECT_EQ(spec.table_methods, (std::vector<std::string>{"trunc", "original"}));
  const auto cells = EnumerateCells(spec);
  const auto runs = EnumerateRuns(spec, cells);
  ASSERT_EQ(runs.size(), 12u);
  EXPECT_EQ(runs[0].id, "noise_0_1-trunc-s001");
  EXPECT_EQ(runs[5].id, "noise_0_1-original-s003");
  EXPECT_EQ(runs[11].id, "noise_50_10-original-s003");
  EXPECT_EQ(CellGroupLabel(spec, cells[3]), "noise_50_10");

  const RunConfig c = ResolveCellConfig(spec, cells[2]);  // noise_50_10, trunc
  EXPECT_EQ(c.sim.duration_s, 4.0);                       // base
  EXPECT_EQ(c.sim.camera.pixel_noise_px, 0.5);            // set
  EXPECT_EQ(c.sim.glitch.mean, 50.0);                     // axis setting, several keys
  EXPECT_EQ(c.sim.glitch.std, 10.0);
  EXPECT_EQ(c.sim.glitch.rate, 0.02);  // base key the setting leaves alone
  EXPECT_EQ(c.detector.type, detectors::DetectorType::kThreshold);
}

TEST(SweepSpec, ListAxesAndSeedLists) {
  TempDir dir;
  dir.File("base.yaml", "duration_s: 3\n");
  const std::string path =
      dir.File("s.yaml",
               "base: base.yaml\naxes:\n  camera.pixel_noise_px: [0, 1.5]\n  glitch.axes: [[az], [ax, az]]\n"
               "methods: {hampel: hampel}\nseeds: [4, 9]\n");
  const SweepSpec spec = LoadSweepSpec(path);
  const auto cells = EnumerateCells(spec);
  ASSERT_EQ(cells.size(), 4u);
  EXPECT_EQ(RunId(spec, cells[3], 9), "pixel_noise_px_1.5-axes_ax_az-hampel-s009");
  EXPECT_EQ(ResolveCellConfig(spec, cells[3]).sim.glitch.axes,
            (std::vector<ImuAxis>{ImuAxis::kAx, ImuAxis::kAz}));
  EXPECT_EQ(ResolveCellConfig(spec, cells[1]).sim.camera.pixel_noise_px, 0.0);
}

TEST(SweepSpec, ResolvedYamlReadsBackToTheSamePlan) {
  TempDir dir;
  const SweepSpec spec = LoadSweepSpec(WriteSmallSweep(dir, "  dtw: {type: dtw, dtw: {templates: 4}}\n"));
  const std::string text = ResolvedSweepYaml(spec);
  std::filesystem::create_directories(dir.path() / "resolved");
  const std::string p = dir.File("resolved/sweep.yaml", text);
  const SweepSpec again = LoadSweepSpec(p);
  EXPECT_EQ(ResolvedSweepYaml(again), text);
  const auto cells = EnumerateCells(again);
  EXPECT_EQ(RunId(again, cells[1], 2), "noise_50_10-dtw-s002");
  EXPECT_EQ(ResolveCellConfig(again, cells[1]).detector.dtw.templates, 4);
  EXPECT_EQ(ResolveCellConfig(again, cells[1]).sim.glitch.mean, 50.0);
}

TEST(SweepSpec, ErrorsNameFileLineAndKey) {
  TempDir dir;
  dir.File("base.yaml", "duration_s: 3\n");
  auto error = [&](const std::string& body) {
    const std::string p = dir.File("bad.yaml", "base: base.yaml\n" + body);
    return InputErrorOf([&] { LoadSweepSpec(p); });
  };
  const std::string f = (dir.path() / "bad.yaml").string();
  EXPECT_EQ(error("methods: {a: none}\nseeds: [1]\nsurprise: 1\n"), f + ":4: surprise: unknown key");
  EXPECT_EQ(error("methods: {a: nonsense}\nseeds: [1]\n"),
            f + ":2: detector.type: must be one of: none, threshold, relative_threshold, dtw, hampel");
  EXPECT_EQ(error("axes:\n  glitch:\n    big: {mean: 5, loudness: 3}\nmethods: {a: none}\nseeds: [1]\n"),
            f + ":4: glitch.loudness: unknown key");
  EXPECT_EQ(error("methods: {a: none}\nseeds: [1, 1]\n"), f + ":3: seeds: seeds must be distinct");
  // A complex key (found by fuzz_sweep_spec) is an input error, not a yaml-cpp conversion failure.
  EXPECT_EQ(error("? {x: 1}: 0\nmethods: {a: none}\nseeds: [1]\n"),
            f + ":2: (top level): a key must be a plain name, not a sequence or mapping");
  EXPECT_EQ(error("methods: {? [a, b]: none}\nseeds: [1]\n"),
            f + ":2: methods: a key must be a plain name, not a sequence or mapping");
  EXPECT_EQ(
      error("methods: {a: none}\nseeds: [1000]\n"),
      f + ":3: template_seed: must differ from every run seed (templates come from data the runs never see)");
  EXPECT_EQ(error("methods: {a-b: none}\nseeds: [1]\n"),
            f + ":2: methods.a-b: method names may use only letters, digits, '_' and '.'");
  EXPECT_EQ(error("methods: {a: none}\nseeds: [1]\ntable_methods: [b]\n"),
            f + ":4: table_methods: 'b' is not one of the methods");
  EXPECT_EQ(error("axes: {camera.pixel_noise_px: [1, 1]}\nmethods: {a: none}\nseeds: [1]\n"),
            f + ":2: axes.camera.pixel_noise_px: two settings have the label 'pixel_noise_px_1' (use named "
                "settings)");
  EXPECT_EQ(error("set: {glitch.rate: 3}\nmethods: {a: none}\nseeds: [1]\n"),
            f + ":2: glitch.rate: must be in [0, 1]");
  // Labels become run ids and directory names: a 300-character one is refused at its line.
  const std::string long_label(300, 'x');
  EXPECT_EQ(error("axes:\n  glitch:\n    " + long_label + ": {mean: 5}\nmethods: {a: none}\nseeds: [1]\n"),
            f + ":4: axes.glitch." + long_label +
                ": label of 300 characters (at most 64: labels become parts of run ids and directory names)");
  const std::string label60(60, 'y');
  EXPECT_NE(error("axes:\n  glitch: {" + label60 + ": {mean: 1}}\n  camera: {" + label60 +
                  ": {pixel_noise_px: 1}}\nmethods: {" + label60 + ": none}\nseeds: [1]\n")
                .find("the longest run id would have 187 characters (at most 160)"),
            std::string::npos);
  EXPECT_EQ(InputErrorOf([&] {
              LoadSweepSpec(dir.File("nobase.yaml", "base: missing.yaml\nmethods: {a: none}\nseeds: [1]\n"));
            }).rfind((dir.path() / "nobase.yaml").string() + ":1: base: ", 0),
            0u);
}

TEST(SweepSpec, SizesAreCheckedBeforeAnythingIsAllocated) {
  TempDir dir;
  dir.File("base.yaml", "duration_s: 3\n");
  auto error = [&](const std::string& body) {
    const std::string p = dir.File("bad.yaml", "base: base.yaml\n" + body);
    return InputErrorOf([&] { LoadSweepSpec(p); });
  };
  const std::string f = (dir.path() / "bad.yaml").string();
  EXPECT_EQ(error("methods: {a: none}\nseeds: {count: 100000000}\n"),
            f + ":3: seeds.count: must be at most 100000");
  EXPECT_NE(error("axes: {duration_s: [1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11]}\nmethods: {a: none}\n"
                  "seeds: {count: 100000, first: 2000}\n")
                .find("more than 1000000 runs"),
            std::string::npos);
  EXPECT_EQ(error("methods: {a: none}\nseeds: [1]\nseeds: [2]\n"),
            f + ":4: seeds: duplicate key (first at line 3); keep one");
}

TEST(SweepSpec, ACellsCrossKeyErrorNamesTheSweepLineThatSetTheKey) {
  TempDir dir;
  dir.File("base.yaml", "duration_s: 3\ncamera:\n  rate_hz: 20\n");
  const auto error = [&](const std::string& body) {
    const std::string p = dir.File("cell.yaml", "base: base.yaml\n" + body);
    return InputErrorOf([&] {
      const SweepSpec spec = LoadSweepSpec(p);
      ResolveCellConfig(spec, EnumerateCells(spec).front());
    });
  };
  const std::string f = (dir.path() / "cell.yaml").string();
  EXPECT_EQ(error("set:\n  imu.rate_hz: 10\nmethods: {original: none}\nseeds: [1]\n"),
            f + ":3: imu.rate_hz: must be at least camera.rate_hz (cell all-original)");
  EXPECT_EQ(error("methods: {original: none}\naxes:\n  camera.rate_hz: [500]\nseeds: [1]\n"),
            f + ":4: imu.rate_hz: must be at least camera.rate_hz (cell rate_hz_500-original)");
}

// The semi-real gate reads the committed excerpt, on every clone; the whole-flight sweep reads the sequence
// under $VIGIL_DATA, and says so when the variable is unset.
TEST(SweepSpec, ShippedSemiRealSweepsNameNoPathOutsideTheRepository) {
  const fs::path source = fs::path(VIGIL_SOURCE_DIR).lexically_normal();
  const SweepSpec gate = LoadSweepSpec((source / "configs/ci_semireal_sweep.yaml").string());
  const RunConfig cell = ResolveCellConfig(gate, EnumerateCells(gate).front());
  EXPECT_EQ(cell.sim.imu.recording, (source / "data/euroc_v1_01_excerpt").string());
  EXPECT_TRUE(fs::is_regular_file(source / "data/euroc_v1_01_excerpt/mav0/imu0/data.csv"));
  EXPECT_EQ(cell.sim.duration_s, 30.0);

  const std::string path = (source / "configs/euroc_paper_sweep.yaml").string();
  const SweepSpec whole = LoadSweepSpec(path);
  const SweepCell first = EnumerateCells(whole).front();
  {
    const vigil::testing::ScopedDataDir unset(nullptr);
    const std::string error = InputErrorOf([&] { ResolveCellConfig(whole, first); });
    EXPECT_EQ(error.rfind(path + ":", 0), 0u) << error;
    EXPECT_NE(error.find(": imu.recording: $VIGIL_DATA/euroc/V1_01_easy names $VIGIL_DATA, which is not set"),
              std::string::npos)
        << error;
  }
  const vigil::testing::ScopedDataDir set("/datasets");
  EXPECT_EQ(ResolveCellConfig(whole, first).sim.imu.recording, "/datasets/euroc/V1_01_easy");
}

// A sweep whose recording is absent would run every cell as failed: it is refused before any run, at the
// line that names the file (the base's, or the sweep's set).
TEST(SweepSpec, AnAbsentInputFileIsRefusedBeforeAnyRun) {
  TempDir dir;
  dir.File("base.yaml", "duration_s: 3\ntrajectory:\n  type: recording\n  recording: absent_gt.csv\n");
  const std::string p = dir.File("s.yaml", "base: base.yaml\nmethods: {original: none}\nseeds: [1]\n");
  const std::string absent = (dir.path() / "absent_gt.csv").string();
  EXPECT_EQ(InputErrorOf([&] { ResolveSweepPlan(LoadSweepSpec(p)); }),
            (dir.path() / "base.yaml").string() + ":4: trajectory.recording: " + absent +
                ": no such file or directory (cell all-original)");
  dir.File("plain.yaml", "duration_s: 3\n");
  const std::string q =
      dir.File("t.yaml",
               "base: plain.yaml\nset:\n  imu.source: recording\n  imu.recording: no_such_dir\n"
               "methods: {original: none}\nseeds: [1]\n");
  EXPECT_NE(InputErrorOf([&] { ResolveSweepPlan(LoadSweepSpec(q)); }).find("t.yaml:4: imu.recording: "),
            std::string::npos);
}

TEST(SweepSpec, ShippedSweepsLoadAndResolve) {
  const SweepSpec paper = LoadSweepSpec(std::string(VIGIL_SOURCE_DIR) + "/configs/paper_sweep.yaml");
  EXPECT_EQ(paper.run_count(), 3u * 6u * 10u);
  EXPECT_EQ(paper.table_methods, (std::vector<std::string>{"trunc", "dtw", "original"}));
  const auto cells = EnumerateCells(paper);
  const auto runs = EnumerateRuns(paper, cells);
  EXPECT_TRUE(
      std::any_of(runs.begin(), runs.end(), [](const auto& r) { return r.id == "noise_50_10-dtw-s003"; }));
  for (const auto& cell : cells) {
    const RunConfig c = ResolveCellConfig(paper, cell);
    EXPECT_TRUE(c.sim.glitch.enabled);
    EXPECT_EQ(c.sim.duration_s, 20.0);
  }
  const RunConfig big = ResolveCellConfig(paper, cells[12]);  // noise_50_10 x trunc
  EXPECT_EQ(big.sim.glitch.mean, 50.0);
  EXPECT_EQ(big.detector.type, detectors::DetectorType::kThreshold);
  // The paper's dtw compares raw slices; vigil's normalized_dtw removes a line.
  EXPECT_EQ(ResolveCellConfig(paper, cells[13]).detector.dtw.normalization,
            detectors::SliceNormalization::kNone);
  EXPECT_EQ(ResolveCellConfig(paper, cells[16]).detector.dtw.normalization,
            detectors::SliceNormalization::kLinear);
  EXPECT_EQ(ResolveCellConfig(paper, cells[15]).detector.type, detectors::DetectorType::kRelativeThreshold);

  const SweepSpec noise = LoadSweepSpec(std::string(VIGIL_SOURCE_DIR) + "/configs/paper_noise_sweep.yaml");
  const auto noise_cells = EnumerateCells(noise);
  ASSERT_EQ(noise_cells.size(), 3u * 2u * 3u);
  EXPECT_EQ(CellGroupLabel(noise, noise_cells[0]), "noise_0_1-densities_as_per_sample");
  EXPECT_EQ(ResolveCellConfig(noise, noise_cells[3]).estimator.imu_noise.model,
            estimator::ImuNoiseModel::kVinsEuroc);
  SweepSpec ten = paper;
  SetSeedCount(&ten, 3);
  EXPECT_EQ(ten.seeds, (std::vector<uint64_t>{1, 2, 3}));
  EXPECT_NE(InputErrorOf([&] { SetSeedCount(&ten, 1000); }).find("template seed 1000"), std::string::npos);

  const SweepSpec ci = LoadSweepSpec(std::string(VIGIL_SOURCE_DIR) + "/configs/ci_sweep.yaml");
  EXPECT_EQ(ci.run_count(), 30u);
  EXPECT_FALSE(ci.write_trajectories);
  EXPECT_FALSE(ci.write_figure_data);    // the accuracy gate keeps its runs small
  EXPECT_TRUE(paper.write_figure_data);  // the paper's figures draw what its runs recorded
  EXPECT_NE(ResolvedSweepYaml(ci).find("write_figure_data: false"), std::string::npos);
  // The default is left out, so that a paper sweep started before the key existed still resumes.
  EXPECT_EQ(ResolvedSweepYaml(paper).find("write_figure_data"), std::string::npos);
}

}  // namespace
}  // namespace vigil::experiments
