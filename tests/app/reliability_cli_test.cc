// Inputs a careless or hostile user gives the built `vigil`: each is refused with one line
// "vigil: error: ..." (exit 2, or 1 where an external program failed) and nothing written, or handled by a
// documented rule (docs/safety.md).
#include <sys/stat.h>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "core/output.h"
#include "tests/app/vigil_cli.h"
#include "tests/core/test_util.h"

namespace vigil {
namespace {
namespace fs = std::filesystem;
using testing::CliResult;
using testing::TempDir;
using testing::Vigil;

class ReliabilityCli : public ::testing::Test {
 protected:
  // Exit `status`, one line on stderr containing `reason`.
  CliResult Expect(const std::string& args, int status, const std::string& reason) {
    const CliResult r = Vigil(tmp_, args);
    EXPECT_EQ(r.status, status) << args << ": " << r.err;
    EXPECT_NE(r.err.find(reason), std::string::npos) << args << ": " << r.err;
    EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << "one line: " << r.err;
    EXPECT_EQ(r.err.rfind("vigil: error: ", 0), 0u) << r.err;
    return r;
  }
  // `command` through sh with stderr captured: for commands that need their own environment.
  CliResult Shell(const std::string& command) {
    const std::string err = Path("shell_stderr.txt");
    const int raw = std::system((command + " >/dev/null 2>" + err).c_str());
    CliResult r;
    r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : 128 + WTERMSIG(raw);
    r.err = ReadFile(err);
    fs::remove(err);
    return r;
  }
  std::string Path(const std::string& name) const { return (tmp_.path() / name).string(); }
  // A tiny sweep file (one method, one seed, 2 s): tmp/tiny.yaml.
  std::string TinySweepFile() {
    tmp_.File("base.yaml", "duration_s: 2\nglitch:\n  enabled: true\n");
    return tmp_.File("tiny.yaml", "base: base.yaml\nmethods: {original: none}\nseeds: [1]\n");
  }
  // The tiny sweep run into tmp/s; returns its directory.
  std::string TinySweep() {
    const std::string sweep = TinySweepFile();
    EXPECT_EQ(Vigil(tmp_, "sweep " + sweep + " -o " + Path("s") + " --quiet -j 1").status, 0);
    return Path("s");
  }

  TempDir tmp_;
};

TEST_F(ReliabilityCli, JobsBeyondTheMaximumAreRefusedBeforeAnythingIsWritten) {
  const std::string configs = std::string(VIGIL_SOURCE_DIR) + "/configs/";
  for (const std::string& command :
       {"sweep " + configs + "ci_sweep.yaml", "map " + configs + "glitch_map.yaml",
        "roc " + configs + "roc_paper.yaml", std::string("paper")}) {
    Expect(command + " -o " + Path("out") + " -j 100000", 2, "--jobs");
    EXPECT_FALSE(fs::exists(Path("out"))) << command;
  }
}

TEST_F(ReliabilityCli, CleanRefusesABrokenImuSensorYaml) {
  std::string rows =
      "#timestamp [ns],w_RS_S_x [rad s^-1],w_RS_S_y [rad s^-1],w_RS_S_z [rad s^-1],a_RS_S_x [m s^-2],"
      "a_RS_S_y [m s^-2],a_RS_S_z [m s^-2]\n";
  for (int k = 0; k < 400; ++k) rows += std::to_string(1000000000 + k * 5000000LL) + ",0,0,0,0,0,9.81\n";
  fs::create_directories(tmp_.path() / "rec/mav0/imu0");
  tmp_.File("rec/mav0/imu0/data.csv", rows);
  tmp_.File(
      "rec/mav0/imu0/sensor.yaml",
      "%YAML:1.0\nsensor_type: imu\nT_BS:\n  cols: 4\n  rows: 4\n  data: [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, "
      "0, 0, 0, 0, 1]\nrate_hz: .nan\ngyroscope_noise_density: 1.6968e-04\n");
  Expect("clean " + Path("rec") + " -o " + Path("out") + " --detector hampel", 2,
         "rec/mav0/imu0/sensor.yaml:7: rate_hz: expected a finite number");
  EXPECT_FALSE(fs::exists(Path("out")));
}

TEST_F(ReliabilityCli, RecursiveYamlAliasesAreRefusedByEveryReader) {
  const std::string sa = tmp_.File("sa.yaml", "a: &a [*a]\n");
  Expect("config " + sa, 2, "sa.yaml:1: a recursive alias");
  Expect("simulate " + sa + " -o " + Path("ds"), 2, "sa.yaml:1: a recursive alias");
  EXPECT_FALSE(fs::exists(Path("ds")));
  const std::string sweep = tmp_.File("sw.yaml", "base: sa.yaml\nmethods: &m {original: *m}\nseeds: [1]\n");
  Expect("sweep " + sweep + " -o " + Path("s"), 2, "sw.yaml:2: a recursive alias");
  EXPECT_FALSE(fs::exists(Path("s")));
  Expect("config " + tmp_.File("deep.yaml", "a: " + std::string(40, '[') + std::string(40, ']') + "\n"), 2,
         "deep.yaml:1: nested deeper than 32 levels");
}

TEST_F(ReliabilityCli, ANullKeyNamesItsLine) {
  Expect("config " + tmp_.File("n.yaml", "duration_s: 2\n~: 2\n"), 2, "n.yaml:2: ~: unknown key");
}

TEST_F(ReliabilityCli, WriteBaselineNeverOverwritesItsInputsOrAFileThatIsNotABaseline) {
  const std::string dir = TinySweep();
  const std::string base = Path("b.json");
  ASSERT_EQ(Vigil(tmp_, "regress " + dir + " --write-baseline " + base).status, 0);
  const std::string text = ReadFile(base);
  Expect("regress " + dir + " --baseline " + base + " --write-baseline " + base + " --force", 2,
         "the output is the input");
  EXPECT_EQ(ReadFile(base), text);
  const std::string notes = tmp_.File("notes.txt", "my notes\n");
  Expect("regress " + dir + " --write-baseline " + notes + " --force", 2, "not a vigil baseline");
  EXPECT_EQ(ReadFile(notes), "my notes\n");
  // A baseline vigil wrote is replaced with --force.
  EXPECT_EQ(Vigil(tmp_, "regress " + dir + " --write-baseline " + base + " --force").status, 0);
}

TEST_F(ReliabilityCli, ABaselineThatComparesNothingFailsTheGate) {
  const std::string dir = TinySweep();
  const std::string empty = tmp_.File(
      "e.json",
      "{\"format\": \"vigil-regress-baseline-1\", \"tolerance\": {\"relative\": 0.25, \"absolute\": {}},\n"
      " \"cells\": []}\n");
  Expect("regress " + dir + " --baseline " + empty, 2, "e.json:2: cells: no cells");
  const std::string broken = tmp_.File("x.json", "{\n\"format\": \n");
  const CliResult r = Expect("regress " + dir + " --baseline " + broken, 2, "x.json:3: not valid JSON");
  EXPECT_EQ(r.err.find("json.exception"), std::string::npos) << r.err;
}

TEST_F(ReliabilityCli, TablesRefusesCorruptForeignOrMisplacedRunData) {
  const std::string dir = TinySweep();
  ASSERT_EQ(Vigil(tmp_, "tables " + dir).status, 0);
  fs::path run;
  for (const auto& e : fs::directory_iterator(fs::path(dir) / "runs")) run = e.path();
  const std::string metrics = ReadFile(run / "metrics.json");
  auto spoil = [&](const std::string& from, const std::string& to) {
    std::string t = metrics;
    const std::size_t at = t.find(from);
    ASSERT_NE(at, std::string::npos) << from;
    t.replace(at, from.size(), to);
    WriteFileAtomic(run / "metrics.json", t);
  };
  spoil("\"seed\": 1", "\"seed\": 2");
  Expect("tables " + dir, 2, "seed: 2 is not this run's seed (1)");
  spoil("\"rmse\": ", "\"rmse\": -1, \"x\": ");
  Expect("tables " + dir, 2, ".rmse: must be in [0, 1e+09], got -1");
  WriteFileAtomic(run / "metrics.json", metrics);
  ASSERT_EQ(Vigil(tmp_, "tables " + dir).status, 0);
  // results.csv a directory: one line, nothing else written.
  fs::remove(fs::path(dir) / "results.csv");
  fs::create_directory(fs::path(dir) / "results.csv");
  Expect("tables " + dir, 2, "results.csv: exists and is not a regular file");
  fs::remove(fs::path(dir) / "results.csv");
  // sweep.yaml swapped for another sweep's (same run ids, another base): refused.
  tmp_.File("base.yaml", "duration_s: 3\nglitch:\n  enabled: true\n");
  const std::string other = Path("other");
  ASSERT_EQ(Vigil(tmp_, "sweep " + Path("tiny.yaml") + " -o " + other + " --quiet -j 1").status, 0);
  fs::copy_file(fs::path(other) / "sweep.yaml", fs::path(dir) / "sweep.yaml",
                fs::copy_options::overwrite_existing);
  Expect("tables " + dir, 2, "not the configuration the sweep's plan gives this run");
}

// A run of an earlier vigil, whose config.yaml lacks the keys added since (here the inconclusive verdict's),
// is not tabulated or resumed with this vigil's runs: one line names the keys it lacks.
TEST_F(ReliabilityCli, ARunOfAnEarlierVigilIsNamedWithTheKeysItLacks) {
  const std::string dir = TinySweep();
  fs::path run;
  for (const auto& e : fs::directory_iterator(fs::path(dir) / "runs")) run = e.path();
  const std::string config = ReadFile(run / "config.yaml");
  std::string old;
  for (std::size_t begin = 0, end; begin < config.size(); begin = end + 1) {
    end = config.find('\n', begin);
    const std::string line = config.substr(begin, end - begin);
    if (line.find("min_coverage:") == std::string::npos &&
        line.find("min_alignment_extent_m:") == std::string::npos)
      old += line + "\n";
  }
  ASSERT_LT(old.size(), config.size());
  WriteFileAtomic(run / "config.yaml", old);
  const std::string reason =
      "config.yaml: written by an earlier vigil, without evaluation.min_coverage, "
      "evaluation.min_alignment_extent_m (its verdict was given without them)";
  Expect("tables " + dir, 2, reason);
  Expect("sweep " + Path("tiny.yaml") + " -o " + dir + " --resume --quiet -j 1", 2, reason);
  WriteFileAtomic(run / "config.yaml", config);
  EXPECT_EQ(Vigil(tmp_, "tables " + dir).status, 0);
}

TEST_F(ReliabilityCli, SlurmSubmitNeverRunsWhatSbatchPrints) {
  const std::string sweep = TinySweepFile();
  fs::create_directories(tmp_.path() / "bin");
  const std::string pwned = Path("pwned");
  auto fake_sbatch = [&](const std::string& prints) {
    const std::string sbatch = tmp_.File("bin/sbatch", "#!/bin/sh\necho '" + prints + "'\n");
    ::chmod(sbatch.c_str(), 0755);
  };
  const std::string env = "env PATH=" + Path("bin") + ":/usr/bin:/bin ";
  const std::string slurm = env + VIGIL_BINARY + " slurm " + sweep + " --tasks 2 --submit -o ";
  fake_sbatch("1$(touch " + pwned + ")");
  CliResult r = Shell(slurm + Path("s1"));
  EXPECT_EQ(r.status, 1) << r.err;
  // The scripts are written (one progress line), then the failure is one line of its own.
  EXPECT_NE(r.err.find("\nvigil: error: sbatch printed '1$(touch "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("not a job id"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(pwned));
  fake_sbatch("");
  r = Shell(slurm + Path("s2"));
  EXPECT_EQ(r.status, 1) << r.err;
  EXPECT_NE(r.err.find("sbatch printed '', not a job id"), std::string::npos) << r.err;
  // submit.sh checks each id the same way before using it.
  ASSERT_EQ(Vigil(tmp_, "slurm " + sweep + " -o " + Path("s3") + " --tasks 2").status, 0);
  fake_sbatch("1$(touch " + pwned + ")");
  EXPECT_NE(Shell(env + "bash " + Path("s3") + "/slurm/submit.sh").status, 0);
  EXPECT_FALSE(fs::exists(pwned));
}

TEST_F(ReliabilityCli, SlurmTaskCountsAndTimesAreBounded) {
  const std::string sweep = TinySweepFile();
  Expect("slurm " + sweep + " -o " + Path("s") + " --tasks 1000000", 2, "--tasks 1000000: must be in");
  Expect("slurm " + sweep + " -o " + Path("s") + " --tasks 2 --time abc", 2, "not a Slurm time limit");
  EXPECT_FALSE(fs::exists(Path("s")));
}

TEST_F(ReliabilityCli, WhatSimulateAcceptsRunAccepts) {
  const std::string config = tmp_.File("c.yaml", "duration_s: 2\nglitch:\n  enabled: true\n");
  for (const char* text : {"glitch.mean=1e308", "faults.timing.drop_rate=1", "duration_s=1e-320",
                           "faults.quantization.accel_lsb_mps2=1e-320"}) {
    const std::string set = text;
    // Named as every --set error is: "--set: KEY: reason" (a bound) or "--set KEY=VALUE: KEY: reason".
    const CliResult r = Expect("simulate " + config + " -o " + Path("ds") + " --set " + set, 2,
                               set.substr(0, set.find('=')) + ": ");
    EXPECT_EQ(r.err.rfind("vigil: error: --set", 0), 0u) << r.err;
    EXPECT_FALSE(fs::exists(Path("ds"))) << set;
  }
  // At the bounds, the dataset simulate writes is one run reads (the estimator may still fail: exit 1).
  for (const char* text : {"faults.timing.drop_rate=0.5", "duration_s=0.5", "glitch.mean=1e4"}) {
    const std::string set = text;
    const std::string ds = Path("ds_" + std::to_string(set.size()));
    ASSERT_EQ(Vigil(tmp_, "simulate " + config + " -o " + ds + " --set " + set).status, 0) << set;
    const CliResult r = Vigil(tmp_, "run " + config + " --dataset " + ds + " -o " + ds + "_run --set " + set);
    EXPECT_NE(r.status, 2) << set << ": " << r.err;
  }
}

// A value found wrong only once the run reads its recording (duration_s past its end, a spline too fine for
// it) is located as a config error is: the --set that gave it, else its line in the file.
TEST_F(ReliabilityCli, ProblemsFoundInTheRecordingNameTheSetOrTheLine) {
  tmp_.File("gt.txt", "0 0 0 0 0 0 0 1\n1 1 0 0 0 0 0 1\n");
  const std::string config =
      tmp_.File("c.yaml", "seed: 1\nduration_s: 5\ntrajectory:\n  type: recording\n  recording: gt.txt\n");
  for (const char* command : {"run", "simulate"}) {
    const std::string out = " -o " + Path(std::string(command) + "_out");
    Expect(std::string(command) + " " + config + out, 2,
           config + ":2: duration_s: 5 s exceeds the end of the trajectory (1 s)");
    Expect(std::string(command) + " " + config + " --set duration_s=4" + out, 2,
           "--set duration_s=4: duration_s: 4 s exceeds the end of the trajectory (1 s)");
    Expect(std::string(command) + " " + config +
               " --set duration_s=1 --set trajectory.spline.knot_spacing_s=1e-9" + out,
           2, "--set trajectory.spline.knot_spacing_s=1e-9: trajectory.spline.knot_spacing_s: 1e-09 s over");
    // duration_s: 0 runs to the end of a recording shorter than a run: said as such, at the line.
    tmp_.File("short.txt", "0 0 0 0 0 0 0 1\n0.3 1 0 0 0 0 0 1\n");
    Expect(std::string(command) + " " + config + " --set trajectory.recording=" + Path("short.txt") +
               " --set duration_s=0" + out,
           2,
           "--set duration_s=0: duration_s: 0 runs to the end of trajectory.recording, which is 0.300 s "
           "long: a run needs at least 0.5 s");
    EXPECT_FALSE(fs::exists(Path(std::string(command) + "_out")));
  }
  // In a sweep, the line of the sweep file that set it, and the cell.
  tmp_.File("short_base.yaml",
            "seed: 1\nduration_s: 1\ntrajectory:\n  type: recording\n  recording: short.txt\n");
  const std::string sweep = tmp_.File(
      "s.yaml", "base: short_base.yaml\nset:\n  duration_s: 0\nmethods: {original: none}\nseeds: [1]\n");
  const CliResult r =
      Expect("sweep " + sweep + " -o " + Path("sweep_out"), 2,
             sweep + ":3: duration_s: 0 runs to the end of trajectory.recording, which is 0.300 s");
  EXPECT_NE(r.err.find("(cell "), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(Path("sweep_out")));
}

TEST_F(ReliabilityCli, PlotRunRefusesADatasetDirectory) {
  const std::string config = tmp_.File("c.yaml", "duration_s: 1\n");
  ASSERT_EQ(Vigil(tmp_, "simulate " + config + " -o " + Path("ds")).status, 0);
  Expect("plot run " + Path("ds"), 2,
         "not a run directory (no metrics.json); for a dataset: vigil plot dataset");
  EXPECT_FALSE(fs::exists(Path("ds") + "/figures"));
}

TEST_F(ReliabilityCli, MapAndRocRefuseNonsenseBeforeAnyRun) {
  Expect(
      "map " + std::string(VIGIL_SOURCE_DIR) + "/configs/glitch_map.yaml -o " + Path("m") + " --target nan",
      2, "--target");
  tmp_.File("base.yaml", "duration_s: 2\nglitch:\n  enabled: true\n");
  const std::string map = tmp_.File(
      "map.yaml",
      "base: base.yaml\naxes:\n  glitch:\n    big: {mean: 50, std: 1}\n    none: {mean: 0, std: 0}\n"
      "  glitch.rate: [0.01, 0.02]\nmethods: {original: none}\nseeds: [1]\n");
  Expect("map " + map + " -o " + Path("m"), 2, "the first axis must start at the glitch-free reference");
  EXPECT_FALSE(fs::exists(Path("m")));
  for (const char* text : {"hampel_nan", "foo", "hampel_3x"}) {
    const std::string label = text;
    const std::string roc = tmp_.File("roc.yaml", "base: base.yaml\nmethods:\n  " + label +
                                                      ": {type: hampel, hampel.n_sigma: 3}\nseeds: [1]\n");
    Expect("roc " + roc + " -o " + Path("r"), 2, "roc.yaml:3: methods: " + label + ": ");
  }
  const std::string wrong = tmp_.File("w.yaml", "base: base.yaml\nmethods:\n  hampel_3: none\nseeds: [1]\n");
  Expect("roc " + wrong + " -o " + Path("r"), 2, "runs the none detector");
  EXPECT_FALSE(fs::exists(Path("r")));
}

}  // namespace
}  // namespace vigil
