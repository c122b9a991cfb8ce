// Runs the built `vigil` (VIGIL_BINARY), or any command, as a user would, for the command-line tests of
// tests/app/.
#pragma once

#include <sys/wait.h>

#include <cstdio>
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

struct ShellOutput {
  int status = -1;  // exit status, or 128 + the signal that ended it
  std::string out;  // what it printed on stdout
};

// Runs `command` through /bin/sh; its stdout and exit status.
inline ShellOutput RunShell(const std::string& command) {
  ShellOutput r;
  FILE* pipe = popen(command.c_str(), "r");
  if (pipe == nullptr) return r;
  char buf[4096];
  for (std::size_t n; (n = std::fread(buf, 1, sizeof(buf), pipe)) > 0;) r.out.append(buf, n);
  const int raw = pclose(pipe);
  r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : 128 + WTERMSIG(raw);
  return r;
}

}  // namespace vigil::testing
