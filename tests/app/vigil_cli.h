// Runs the built `vigil` (VIGIL_BINARY) as a user would, for the command-line tests of tests/app/.
#pragma once

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "core/output.h"
#include "tests/core/test_util.h"

namespace vigil::testing {

struct CliResult {
  int status = -1;  // exit status, or 128 + the signal that ended it
  std::string err;  // what it printed on stderr
};

// Runs `vigil ARGS` (a shell word list) with stdout discarded; stderr goes through a file in `tmp`.
inline CliResult Vigil(const TempDir& tmp, const std::string& args) {
  const std::filesystem::path err = tmp.path() / "stderr.txt";
  const std::string command = std::string(VIGIL_BINARY) + " " + args + " >/dev/null 2>" + err.string();
  const int raw = std::system(command.c_str());
  CliResult r;
  r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : 128 + WTERMSIG(raw);
  r.err = ReadFile(err);
  std::filesystem::remove(err);
  return r;
}

}  // namespace vigil::testing
