#include "experiments/external/external_command.h"

#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <system_error>

#include "core/error.h"

namespace vigil::experiments {
namespace fs = std::filesystem;
namespace {

// The value of placeholder `name`, or null when vigil does not know it.
const std::string* PlaceholderValue(const std::string& name, const CommandPlaceholders& v) {
  if (name == "recording") return &v.recording;
  if (name == "mav0") return &v.mav0;
  if (name == "output") return &v.output;
  if (name == "config") return &v.config;
  if (name == "seed") return &v.seed;
  if (name == "vigil") return &v.vigil;
  return nullptr;
}

bool IsExecutableFile(const fs::path& path) {
  std::error_code ec;
  return fs::is_regular_file(path, ec) && ::access(path.c_str(), X_OK) == 0;
}

}  // namespace

std::string ExpandPlaceholders(const std::string& arg, const CommandPlaceholders& values) {
  std::string out;
  for (std::size_t i = 0; i < arg.size(); ++i) {
    const char c = arg[i];
    if ((c == '{' || c == '}') && i + 1 < arg.size() && arg[i + 1] == c) {
      out += c;
      ++i;
      continue;
    }
    if (c == '}') throw InputError("'" + arg + "': unmatched '}' (write '}}' for a literal brace)");
    if (c != '{') {
      out += c;
      continue;
    }
    const std::size_t close = arg.find('}', i + 1);
    if (close == std::string::npos)
      throw InputError("'" + arg + "': unmatched '{' (write '{{' for a literal brace)");
    const std::string name = arg.substr(i + 1, close - i - 1);
    const std::string* value = PlaceholderValue(name, values);
    if (!value)
      throw InputError("'" + arg + "': unknown placeholder {" + name +
                       "} (known: {recording}, {mav0}, {output}, {config}, {seed}, {vigil})");
    out += *value;
    i = close;
  }
  return out;
}

std::string CurrentExecutablePath() {
  std::error_code ec;
  const fs::path self = fs::read_symlink("/proc/self/exe", ec);
  return ec ? std::string() : self.string();
}

std::string ResolveExecutable(const std::string& name, std::string* why) {
  if (name.empty()) {
    *why = "the program is an empty string";
    return {};
  }
  if (name.find('/') != std::string::npos) {
    if (IsExecutableFile(name)) return fs::absolute(name).lexically_normal().string();
    *why = "'" + name + "' is not an executable file";
    return {};
  }
  const char* path = std::getenv("PATH");
  const std::string dirs = path ? path : "/usr/local/bin:/usr/bin:/bin";
  for (std::size_t begin = 0; begin <= dirs.size();) {
    std::size_t end = dirs.find(':', begin);
    if (end == std::string::npos) end = dirs.size();
    const fs::path candidate = fs::path(end > begin ? dirs.substr(begin, end - begin) : ".") / name;
    if (IsExecutableFile(candidate)) return fs::absolute(candidate).lexically_normal().string();
    begin = end + 1;
  }
  *why = "'" + name + "' is not an executable file in PATH";
  return {};
}

std::string ValidateExternalOptions(const ExternalEstimatorOptions& options) {
  if (options.command.empty())
    return "command: backend external needs a command, e.g. [\"{vigil}\", estimate, \"{recording}\", -o, "
           "\"{output}\", --config, \"{config}\"]";
  // Every argument is expanded with stand-in values, so that an unknown placeholder is found before a run.
  CommandPlaceholders stand_in{"recording", "mav0", "output", "config", "1", CurrentExecutablePath()};
  std::vector<std::string> argv;
  for (std::size_t i = 0; i < options.command.size(); ++i) {
    try {
      argv.push_back(ExpandPlaceholders(options.command[i], stand_in));
    } catch (const InputError& e) {
      return "command: element " + std::to_string(i) + ": " + e.what();
    }
  }
  std::string why;
  if (ResolveExecutable(argv.front(), &why).empty()) return "command: " + why;
  const fs::path trajectory(options.trajectory);
  if (options.trajectory.empty() || trajectory.is_absolute())
    return "trajectory: expected a file name relative to the command's {output} folder";
  for (const fs::path& part : trajectory)
    if (part == "..") return "trajectory: '" + options.trajectory + "' leaves the {output} folder";
  // A file name, not a folder: "traj.txt/" and "." name no file the estimator could write.
  if (!trajectory.has_filename() || trajectory.filename() == ".")
    return "trajectory: '" + options.trajectory + "' names a folder, not a file (expected e.g. traj.txt)";
  return {};
}

}  // namespace vigil::experiments
