// The command line of an external estimator: its placeholders, and the checks made before any run.
#pragma once

#include <string>
#include <vector>

#include "experiments/external/external_estimator_options.h"

namespace vigil::experiments {

// What the placeholders of external_estimator_options.h stand for in one run.
struct CommandPlaceholders {
  std::string recording, mav0, output, config, seed, vigil;
};

// `arg` with every placeholder replaced ("{{" -> "{", "}}" -> "}"). Throws InputError("reason") for an
// unknown placeholder or an unmatched brace.
std::string ExpandPlaceholders(const std::string& arg, const CommandPlaceholders& values);

// The absolute path of the running executable (/proc/self/exe); empty when it cannot be read.
std::string CurrentExecutablePath();

// The file `name` stands for: itself when it holds a '/' (relative to the working directory), else the
// first match in PATH. Empty (with `why`) unless it is an executable regular file.
std::string ResolveExecutable(const std::string& name, std::string* why);

// "key: reason" for options that cannot run (no command, an unknown placeholder, a command that is not an
// executable file, a trajectory path outside {output}); empty when they are fine. Keys are relative to
// `estimator.external`.
std::string ValidateExternalOptions(const ExternalEstimatorOptions& options);

}  // namespace vigil::experiments
