// `vigil regress`: the accuracy regression gate of a sweep against a committed baseline.
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "app/commands.h"
#include "core/error.h"
#include "core/output.h"
#include "experiments/sweeps/regression.h"
#include "experiments/sweeps/sweep_aggregate.h"

namespace vigil::app {
namespace {
struct Args {
  std::string dir, baseline, write_baseline;
  bool force = false;
};

// --write-baseline may not be (or lie inside) an input: the sweep directory or the --baseline it is compared
// with. An existing file is replaced only with --force, and only when it is a baseline vigil wrote.
void RefuseBaselineOutput(const Args& args) {
  std::vector<std::filesystem::path> inputs{args.dir};
  if (!args.baseline.empty()) inputs.emplace_back(args.baseline);
  RefuseOutputOverInputs(args.write_baseline, inputs, "--write-baseline");
  std::error_code ec;
  const auto status = std::filesystem::symlink_status(args.write_baseline, ec);
  if (!std::filesystem::exists(status)) return;
  if (!std::filesystem::is_regular_file(std::filesystem::status(args.write_baseline, ec)))
    throw InputError(args.write_baseline + ": --write-baseline: exists and is not a regular file");
  if (!args.force) throw InputError(args.write_baseline + ": exists (use --force to replace it)");
  if (!experiments::IsBaselineFile(args.write_baseline))
    throw InputError(
        args.write_baseline +
        ": --write-baseline: not a vigil baseline (no \"format\": \"vigil-regress-baseline-1\"); "
        "--force replaces only a baseline");
}

// Compares `current` with the baseline file, prints the report (stdout) and its summary (stderr); returns the
// exit status (1 on a regression, or when no cell was compared). `tolerance`: the baseline's.
int CompareWithBaselineFile(const std::string& baseline_file,
                            const std::vector<experiments::RegressionCell>& current,
                            experiments::RegressionTolerance* tolerance) {
  std::vector<experiments::RegressionCell> baseline;
  experiments::ReadBaseline(baseline_file, &baseline, tolerance);
  const experiments::RegressionReport report =
      experiments::CompareWithBaseline(current, baseline, *tolerance);
  std::fputs(report.text.c_str(), stdout);
  std::fprintf(stderr, "vigil regress: %zu cells compared with %s: %zu regressed, %zu improved%s\n",
               report.compared, baseline_file.c_str(), report.regressions, report.improvements,
               report.improvements && !report.regressions ? " (consider recording a new baseline)" : "");
  if (report.compared == 0) {  // unreachable with a valid baseline (it has cells), kept as the last word
    std::fprintf(stderr, "vigil: error: %s: no cell compared: the gate checked nothing\n",
                 baseline_file.c_str());
    return 1;
  }
  return report.regressions ? 1 : 0;
}
}  // namespace

void AddRegressCommand(CLI::App& root) {
  auto* cmd = root.add_subcommand(
      "regress",
      "compare a sweep's per-cell means with a baseline (exit 1 on a regression beyond tolerance), or record "
      "one with --write-baseline");
  auto args = std::make_shared<Args>();
  cmd->add_option("DIR", args->dir, "sweep directory")->required();
  cmd->add_option("--baseline", args->baseline,
                  "baseline JSON to compare with (experiments/baselines/*.json)");
  cmd->add_option(
      "--write-baseline", args->write_baseline,
      "write the sweep's cells as a baseline (tolerances of --baseline when given, else defaults)");
  cmd->add_flag("--force", args->force, "replace an existing --write-baseline file");
  SetAction(cmd, [args] {
    namespace ex = experiments;
    if (args->baseline.empty() && args->write_baseline.empty())
      throw InputError("regress: give --baseline FILE and/or --write-baseline FILE");
    if (!args->write_baseline.empty()) RefuseBaselineOutput(*args);
    const ex::SweepSpec spec = ex::LoadSweepSpec((std::filesystem::path(args->dir) / "sweep.yaml").string());
    const ex::SweepAggregate agg = ex::AggregateSweep(args->dir, spec, ex::SweepDistances(spec));
    const std::vector<ex::RegressionCell> current = ex::RegressionCells(agg);
    ex::RegressionTolerance tolerance;
    const int status =
        args->baseline.empty() ? 0 : CompareWithBaselineFile(args->baseline, current, &tolerance);
    if (!args->write_baseline.empty()) {
      // Checked again here for a --baseline-less call; the same check ran before any work above.
      RefuseBaselineOutput(*args);
      WriteFileAtomic(args->write_baseline, ex::BaselineJson(current, tolerance, spec.path).dump(2) + "\n");
      std::fprintf(stderr, "vigil regress: baseline of %zu cells -> %s\n", current.size(),
                   args->write_baseline.c_str());
    }
    return status;
  });
}

}  // namespace vigil::app
