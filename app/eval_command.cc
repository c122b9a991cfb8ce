#include "app/eval_command.h"

#include <cstdio>

#include "core/config.h"
#include "core/dataset.h"
#include "core/error.h"
#include "core/format.h"
#include "evaluation/evaluate_trajectory.h"

namespace vigil::app {

const char* const kEvalDescription =
    "rpg-compatible evaluation of an estimated trajectory: association within 0.02 s, alignment, ATE and "
    "relative errors per sub-trajectory length (files: '# timestamp tx ty tz qx qy qz qw', seconds)";

void AddEvalOptions(CLI::App* cmd, EvalArgs* args) {
  cmd->add_option("GT", args->gt, "ground-truth trajectory (e.g. stamped_groundtruth.txt)")->required();
  cmd->add_option("EST", args->est, "estimated trajectory (e.g. stamped_traj_estimate.txt)")->required();
  cmd->add_option("--align", args->align,
                  "alignment: " + config::EnumChoices(evaluation::AlignmentNames()) + " (default posyaw)");
  cmd->add_option(
         "--distances", args->distances,
         "sub-trajectory lengths of the relative errors [m], comma separated (default 7,14,21,28,35)")
      ->delimiter(',');
  cmd->add_flag("--json", args->json, "print JSON (the ate/relative/coverage part of metrics.json)");
}

int RunEval(const EvalArgs& args) {
  evaluation::EvaluationOptions options;
  const auto align = config::EnumFromName(args.align, evaluation::AlignmentNames());
  if (!align) throw InputError("--align: unknown alignment '" + args.align + "'");
  options.align = *align;
  if (!args.distances.empty()) {
    for (double d : args.distances)
      if (!(d > 0.0)) throw InputError("--distances: every length must be > 0, got " + FormatDouble(d));
    options.distances_m = args.distances;
  }
  const Trajectory gt = ReadTumTrajectory(args.gt);
  const Trajectory est = ReadTumTrajectory(args.est);
  const evaluation::TrajectoryEvaluation ev = evaluation::EvaluateTrajectory(gt, est, options);
  if (ev.matched_poses == 0) throw InputError(args.est + ": no pose within 0.02 s of a pose of " + args.gt);
  if (args.json)
    std::printf("%s\n", evaluation::EvaluationJson(ev).dump(2).c_str());
  else
    std::printf("%s", evaluation::EvaluationTable(ev).c_str());
  return 0;
}

}  // namespace vigil::app
