// What `vigil` and `vigil-eval` do around a command (docs/cli.md): parse the command line, run the action,
// and turn what went wrong into one line on stderr and an exit status: 0 done (or --help, --version), 1 a run
// failed, 2 bad usage or bad input.
#pragma once

#include <cstdio>
#include <exception>
#include <functional>
#include <optional>

#include <CLI/CLI.hpp>

#include "core/error.h"

namespace vigil::app {

// Parses argv into `app`: the exit status when parsing ends the program (help or version: 0; a parse error:
// 2, said in one line), nothing when a command is to run.
inline std::optional<int> ParseCommandLine(CLI::App& app, int argc, char** argv) {
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::fprintf(stderr, "vigil: error: %s\n", OneLine(e.what()).c_str());
    return 2;
  }
  return std::nullopt;
}

// Runs `action` and returns its status; an InputError is bad input (2), any other exception a failure (1).
inline int RunReportingErrors(const std::function<int()>& action) {
  try {
    return action();
  } catch (const InputError& e) {
    std::fprintf(stderr, "vigil: error: %s\n", e.what());  // already one line
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "vigil: error: %s\n", OneLine(e.what()).c_str());
    return 1;
  }
}

}  // namespace vigil::app
