// `vigil run` without the process: configuration errors first, then the run into a staged directory.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "experiments/runs/run.h"

namespace vigil::experiments {

// Loads `config_path` with `overrides` and validates it (detector options included): every InputError is
// thrown before anything is written. Then refuses a `dir` that is, contains or lies inside one of the
// run's inputs (config file, dataset, waypoints, templates), a non-empty `dir` unless `force`, runs into a
// temporary sibling and renames it into place; an exception during the run leaves nothing behind. Returns
// metrics.json.
nlohmann::json RunToDirectory(const std::string& config_path, const std::vector<std::string>& overrides,
                              const RunOptions& options, const std::filesystem::path& dir, bool force);

}  // namespace vigil::experiments
