// Which estimator a run uses: vigil's own (builtin) or an external program (external), and how the external
// program is run and read.
//
// An external estimator is a command run once per run on a recording vigil writes in the EuRoC ASL layout
// (experiments/runs/external_recording.h). Its arguments may hold placeholders that vigil replaces before
// running it (experiments/external/external_command.h):
//   {recording}  the recording's folder (holding mav0/, features.csv and config.yaml)
//   {mav0}       its mav0/ folder
//   {output}     an empty folder for the program's output, also its working directory
//   {config}     the run's resolved configuration (config.yaml in the recording's folder)
//   {seed}       the run seed
//   {vigil}      the path of the running vigil executable
// and "{{" / "}}" for literal braces. The program writes its trajectory to `trajectory`, relative to
// {output}.
#pragma once

#include <string>
#include <vector>

#include "core/config.h"
#include "estimator/estimator_options.h"

namespace vigil::experiments {

enum class EstimatorBackend { kBuiltin, kExternal };
enum class TrajectoryFormat { kTum, kEuroc };
enum class TimeUnit { kSeconds, kNanoseconds };
// What an external estimator reads from its recording: camera images, vigil's feature tracks, or whichever
// the recording has.
enum class ExternalInput { kAny, kImages, kFeatures };

// Largest timeout_s (a week).
inline constexpr double kMaxExternalTimeout_s = 604800.0;

struct ExternalEstimatorOptions {
  std::vector<std::string> command;  // argv; argv[0] an executable file (a path, or a name found in PATH)
  std::string trajectory = "stamped_traj_estimate.txt";  // relative to {output}
  TrajectoryFormat format = TrajectoryFormat::kTum;
  TimeUnit time_unit = TimeUnit::kSeconds;
  double timeout_s = 3600.0;
  ExternalInput input = ExternalInput::kAny;
  bool keep_recording = false;  // the recording in the run directory (external/recording) instead of /tmp

  template <class V>
  void Visit(V& v) {
    using config::Bounds;
    v.Field(
        "command", command,
        "argv of the external estimator, run without a shell; placeholders {recording}, {mav0}, {output}, "
        "{config}, {seed}, {vigil}");
    v.Field("trajectory", trajectory, "the trajectory file the command writes, relative to {output}");
    v.Enum("format", format,
           config::EnumNames<TrajectoryFormat>{{"tum", TrajectoryFormat::kTum},
                                               {"euroc", TrajectoryFormat::kEuroc}},
           "trajectory format: tum (t x y z qx qy qz qw[ ...], spaces) or euroc (t,x,y,z,qw,qx,qy,qz[,...], "
           "commas); further columns are ignored");
    v.Enum("time_unit", time_unit,
           config::EnumNames<TimeUnit>{{"s", TimeUnit::kSeconds}, {"ns", TimeUnit::kNanoseconds}},
           "unit of the trajectory's timestamps: s or ns");
    v.Field("timeout_s", timeout_s,
            "wall-clock limit of the command [s]; its whole process group is killed after it",
            Bounds{0.0, kMaxExternalTimeout_s, true, false});
    v.Enum("input", input,
           config::EnumNames<ExternalInput>{{"any", ExternalInput::kAny},
                                            {"images", ExternalInput::kImages},
                                            {"features", ExternalInput::kFeatures}},
           "what the command reads from the recording: images (camera images needed), features (vigil's "
           "features.csv needed) or any");
    v.Field("keep_recording", keep_recording,
            "write the recording into the run directory (external/recording) and keep it, instead of a "
            "temporary folder deleted after the run");
  }
};

// The `estimator` section of a run configuration: the sliding-window estimator's options, which estimator
// runs, and the external one's settings.
struct RunEstimatorOptions : estimator::EstimatorOptions {
  EstimatorBackend backend = EstimatorBackend::kBuiltin;
  ExternalEstimatorOptions external;

  template <class V>
  void Visit(V& v) {
    estimator::EstimatorOptions::Visit(v);
    v.Enum("backend", backend,
           config::EnumNames<EstimatorBackend>{{"builtin", EstimatorBackend::kBuiltin},
                                               {"external", EstimatorBackend::kExternal}},
           "estimator of the run: builtin (vigil's) or external (estimator.external.command)");
    v.Section("external", external, "external estimator program (backend: external)");
  }
};

}  // namespace vigil::experiments
