// `--set key.path=value` on the command line (repeatable): the overrides a command hands to the library,
// which applies them in order to its options (config::ApplyOverrides, core/config_section.h).
#pragma once

#include <string>
#include <vector>

#include <CLI/CLI.hpp>

namespace vigil::app {

// Adds --set to `cmd`, collecting into `overrides`. `take_all`: the words after --set up to the next option
// are all overrides.
inline CLI::Option* AddSetOption(CLI::App* cmd, std::vector<std::string>& overrides, const std::string& help,
                                 bool take_all = true) {
  CLI::Option* option = cmd->add_option("--set", overrides, help);
  return take_all ? option->take_all() : option;
}

}  // namespace vigil::app
