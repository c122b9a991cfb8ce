// Runs a program as a child process without a shell: in a process group of its own, with its standard
// output and error going to files, its standard input from /dev/null, and a wall-clock timeout after which
// the whole group is killed.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace vigil::experiments {

struct ChildProcessOptions {
  std::string program;                             // path of the executable (not searched in PATH)
  std::vector<std::string> argv;                   // argv[0] included
  std::filesystem::path working_dir;               // empty: the caller's
  std::filesystem::path stdout_path, stderr_path;  // created or truncated
  double timeout_s = 60.0;
};

struct ChildProcessResult {
  enum class Outcome { kExited, kSignaled, kTimedOut, kNotStarted };
  Outcome outcome = Outcome::kNotStarted;
  int exit_code = -1;   // kExited
  int signal = 0;       // kSignaled
  std::string error;    // kNotStarted: why
  double wall_s = 0.0;  // from the spawn to the end of the wait

  bool succeeded() const { return outcome == Outcome::kExited && exit_code == 0; }
  // "exit status 3", "killed by signal 11 (Segmentation fault)", "timed out after 2 s (process group
  // killed)", "could not start: ...".
  std::string Describe(double timeout_s) const;
};

// Starts `options.program` and waits for it. Never throws for what the child does; when the child ends (or
// times out) every process left in its group is killed, so nothing it started outlives the call.
ChildProcessResult RunChildProcess(const ChildProcessOptions& options);

}  // namespace vigil::experiments
