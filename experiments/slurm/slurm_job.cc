#include "experiments/slurm/slurm_job.h"

#include <algorithm>
#include <cctype>
#include <stdexcept>

#include "core/error.h"

namespace vigil::experiments {
namespace fs = std::filesystem;
namespace {

std::string Command(const std::vector<std::string>& words) {
  std::string s;
  for (const auto& w : words) s += (s.empty() ? "" : " ") + ShellQuote(w);
  return s;
}

// A value on an #SBATCH line: sbatch reads it up to the first space, and shell quoting does not apply.
void CheckDirectiveValue(const std::string& key, const std::string& value) {
  const bool plain = std::all_of(value.begin(), value.end(), [](char c) {
    return c > ' ' && c != '"' && c != '\'' && c != '\\' && c != '#' && c < 127;
  });
  if (!plain) throw InputError("--" + key + " " + value + ": may not contain spaces, quotes or '#'");
}

// sbatch --time: MM, MM:SS, HH:MM:SS, D-HH, D-HH:MM, D-HH:MM:SS (1 to 4 digits per field), or no limit.
bool IsSbatchTime(const std::string& t) {
  if (t == "UNLIMITED" || t == "INFINITE" || t == "unlimited" || t == "infinite") return true;
  std::vector<std::string> fields;
  std::string days, rest = t;
  if (const std::size_t dash = t.find('-'); dash != std::string::npos) {
    days = t.substr(0, dash);
    rest = t.substr(dash + 1);
  }
  std::size_t start = 0;
  while (true) {
    const std::size_t colon = rest.find(':', start);
    fields.push_back(rest.substr(start, colon == std::string::npos ? std::string::npos : colon - start));
    if (colon == std::string::npos) break;
    start = colon + 1;
  }
  auto number = [](const std::string& f) {
    return !f.empty() && f.size() <= 4 &&
           std::all_of(f.begin(), f.end(), [](char c) { return c >= '0' && c <= '9'; });
  };
  if (!days.empty() || t.find('-') != std::string::npos) {
    if (!number(days) || fields.size() > 3) return false;
  } else if (fields.size() > 3) {
    return false;
  }
  return std::all_of(fields.begin(), fields.end(), number);
}

}  // namespace

std::string ParseSbatchJobId(const std::string& parsable) {
  std::size_t begin = 0, end = parsable.size();
  while (begin < end && std::isspace(static_cast<unsigned char>(parsable[begin]))) ++begin;
  while (end > begin && std::isspace(static_cast<unsigned char>(parsable[end - 1]))) --end;
  const std::string text = parsable.substr(begin, end - begin);
  const std::size_t semicolon = text.find(';');
  const std::string id = text.substr(0, semicolon);
  const std::string cluster = semicolon == std::string::npos ? "" : text.substr(semicolon + 1);
  const bool id_ok = !id.empty() && id.size() <= 18 &&
                     std::all_of(id.begin(), id.end(), [](char c) { return c >= '0' && c <= '9'; });
  const bool cluster_ok =
      semicolon == std::string::npos ||
      (!cluster.empty() && std::all_of(cluster.begin(), cluster.end(), [](char c) {
        return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == '.';
      }));
  if (id_ok && cluster_ok) return id;
  std::string shown = text.substr(0, 80);
  for (char& c : shown)
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) c = ' ';
  throw std::runtime_error("sbatch printed '" + shown + (text.size() > 80 ? "...'" : "'") +
                           ", not a job id (digits, optionally ;cluster)");
}

std::string ShellQuote(const std::string& word) {
  const bool plain = !word.empty() && std::all_of(word.begin(), word.end(), [](char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
           std::string("/._-=:,+@%").find(c) != std::string::npos;
  });
  if (plain) return word;
  std::string s = "'";
  for (char c : word) s += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return s + "'";
}

fs::path SlurmDirectory(const fs::path& sweep_dir) { return sweep_dir / "slurm"; }

void ValidateSlurmJobOptions(const SlurmJobOptions& o) {
  if (o.tasks < 1 || o.tasks > kMaxSlurmTasks)
    throw InputError("--tasks " + std::to_string(o.tasks) + ": must be in [1, " +
                     std::to_string(kMaxSlurmTasks) + "]");
  if (o.cpus_per_task < 1 || o.cpus_per_task > kMaxSlurmCpusPerTask)
    throw InputError("--cpus-per-task " + std::to_string(o.cpus_per_task) + ": must be in [1, " +
                     std::to_string(kMaxSlurmCpusPerTask) + "]");
  if (!o.partition.empty()) CheckDirectiveValue("partition", o.partition);
  if (!o.time.empty() && !IsSbatchTime(o.time))
    throw InputError(
        "--time " + o.time +
        ": not a Slurm time limit (MM, MM:SS, HH:MM:SS, D-HH, D-HH:MM, D-HH:MM:SS or UNLIMITED)");
  CheckDirectiveValue("job-name", o.job_name);
  const std::string logs = SlurmDirectory(o.dir).string();
  if (logs.find_first_of(" \t\n'\"\\%#") != std::string::npos)
    throw InputError(o.dir.string() +
                     ": the sweep directory's path may not contain spaces, quotes, '%' or '#' (it is written "
                     "into #SBATCH --output lines)");
}

SlurmScripts MakeSlurmScripts(const SlurmJobOptions& o) {
  ValidateSlurmJobOptions(o);
  const std::string logs = SlurmDirectory(o.dir).string();
  const std::string tasks = std::to_string(o.tasks), cpus = std::to_string(o.cpus_per_task);
  auto common = [&](const std::string& name, const std::string& cpu_count) {
    std::string s = "#SBATCH --job-name=" + name + "\n#SBATCH --cpus-per-task=" + cpu_count + "\n";
    if (!o.partition.empty()) s += "#SBATCH --partition=" + o.partition + "\n";
    if (!o.time.empty()) s += "#SBATCH --time=" + o.time + "\n";
    return s;
  };

  SlurmScripts out;
  std::vector<std::string> sweep = {o.vigil.string()};
  sweep.insert(sweep.end(), o.sweep_arguments.begin(), o.sweep_arguments.end());
  sweep.push_back("-o");
  sweep.push_back(o.dir.string());
  out.array =
      "#!/bin/bash\n"
      "# Written by `vigil slurm`: a job array of " +
      tasks +
      " tasks, task I running shard I of the sweep in\n"
      "# " +
      o.dir.string() +
      " (see experiments/slurm/slurm_job.h). Submit with submit.sh beside this file;\n"
      "# resubmit one task with `sbatch --array=I array.sbatch`: it resumes its shard.\n" +
      common(o.job_name, cpus) + "#SBATCH --array=0-" + std::to_string(o.tasks - 1) +
      "\n#SBATCH --output=" + logs +
      "/%A_%a.log\n"
      "#SBATCH --requeue\n"
      "set -euo pipefail\n"
      "# The shard count is part of the plan: written here, not read from SLURM_ARRAY_TASK_COUNT.\n"
      "shards=" +
      tasks +
      "\n"
      "exec " +
      Command(sweep) + " --shard \"${SLURM_ARRAY_TASK_ID}/${shards}\" --resume -j " + cpus + "\n";

  std::vector<std::string> tables = {o.vigil.string(), "tables", o.dir.string()};
  tables.insert(tables.end(), o.tables_arguments.begin(), o.tables_arguments.end());
  out.finalize =
      "#!/bin/bash\n"
      "# Written by `vigil slurm`: merges the shards of the sweep in " +
      o.dir.string() +
      "\n"
      "# (results.csv, timing.csv, tables, summary.md); fails while runs are missing.\n" +
      common(o.job_name + "-finalize", "1") + "#SBATCH --output=" + logs +
      "/finalize_%j.log\n"
      "set -euo pipefail\n"
      "exec " +
      Command(tables) + "\n";

  const std::string array_script = ShellQuote(logs + "/array.sbatch");
  const std::string finalize_script = ShellQuote(logs + "/finalize.sbatch");
  out.submit =
      "#!/bin/bash\n"
      "# Written by `vigil slurm`: submits the job array and its finalize job (afterany), prints\n"
      "# both job ids.\n"
      "set -euo pipefail\n"
      "array=$(sbatch --parsable " +
      array_script +
      ")\n"
      "array=${array%%;*}\n"
      "# Only a job id goes on: sbatch printing anything else is an error, never a command line.\n"
      "[[ \"${array}\" =~ ^[0-9]+$ ]] || { echo \"submit.sh: sbatch printed '${array}', not a job id\" >&2; "
      "exit 1; }\n"
      "finalize=$(sbatch --parsable --dependency=afterany:\"${array}\" " +
      finalize_script +
      ")\n"
      "finalize=${finalize%%;*}\n"
      "[[ \"${finalize}\" =~ ^[0-9]+$ ]] || { echo \"submit.sh: sbatch printed '${finalize}', not a job id\" "
      ">&2; exit 1; }\n"
      "echo \"array job ${array} (" +
      tasks + " tasks), finalize job ${finalize}\"\n";
  return out;
}

}  // namespace vigil::experiments
