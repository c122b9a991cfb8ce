// One options struct under its key of a run config ("detector:", "frontend:"), for the commands that take
// only that part of a config: `--set detector.dtw.dims=3` then reads as it does in a run's config, and the
// config.yaml written beside their results can be merged into one.
#pragma once

#include <string>
#include <vector>

#include "core/config.h"

namespace vigil::config {

template <class Options>
struct ConfigSection {
  const char* key;
  const char* description;
  Options options{};

  template <class V>
  void Visit(V& v) {
    v.Section(key, options, description);
  }
};

// Applies `key.path=value` assignments in order (ApplyOverride: InputError naming the first bad one).
template <class Options>
void ApplyOverrides(const std::vector<std::string>& assignments, Options& options) {
  for (const std::string& assignment : assignments) ApplyOverride(assignment, options);
}

}  // namespace vigil::config
