#include "experiments/commands/inject_command.h"

#include <filesystem>
#include <map>
#include <set>

#include <yaml-cpp/yaml.h>

#include "core/config.h"
#include "core/config_section.h"
#include "core/dataset.h"
#include "core/error.h"
#include "core/euroc.h"
#include "core/format.h"
#include "core/output.h"
#include "core/recording_files.h"
#include "sim/recording_faults.h"

namespace vigil::experiments {
namespace {

namespace fs = std::filesystem;

sim::RecordingFaultOptions ResolveInjectOptions(const InjectRequest& request) {
  sim::RecordingFaultOptions options;
  config::ApplyOverrides(request.overrides, options);
  if (!request.seed.empty()) options.seed = config::ParseSeedArgument(request.seed);
  const std::string why = sim::ValidateRecordingFaultOptions(options);
  if (!why.empty()) throw InputError("--set " + why);
  return options;
}

// The recording, refused when faults cannot be injected into it.
Recording ReadInjectSource(const std::string& dataset) {
  const fs::path dir(dataset);
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) throw InputError(dataset + ": not a dataset directory");
  const fs::path normal = fs::absolute(dir).lexically_normal();
  if ((normal.has_filename() ? normal.filename() : normal.parent_path().filename()) == euroc_files::kMav0)
    throw InputError(dataset + ": give the folder that holds mav0/, not mav0/ itself");
  Recording recording = ReadRecording(dir);
  const Dataset& d = recording.dataset;
  if (d.imu.size() < 2) throw InputError(dataset + ": fewer than two IMU samples");
  if (!d.glitches.empty() && d.imu_clean.empty())
    throw InputError((dir / dataset_files::kGlitches).string() +
                     ": the recording already has glitches but no imu_clean.csv to keep; faults on top of it "
                     "would lose the glitch-free stream (inject into the recording without glitches)");
  return recording;
}

// Where a recording keeps its IMU, relative to its folder: imu.csv (vigil's layout, which may also hold a
// mav0/imu0 copy written by vigil simulate --images) or mav0/imu0/data.csv (EuRoC; imu0/data.csv when the
// folder holds imu0/ itself).
std::vector<std::string> ImuFilesOf(const fs::path& dir, const Recording& recording) {
  const fs::path mav0 = FindMav0(dir);
  const std::string imu = std::string(euroc_files::kImu) + "/" + euroc_files::kData,
                    euroc = mav0 == dir ? imu : std::string(euroc_files::kMav0) + "/" + imu;
  std::error_code ec;
  if (recording.layout == "euroc") return {euroc};
  std::vector<std::string> files = {dataset_files::kImu};
  if (!mav0.empty() && fs::is_regular_file(dir / euroc, ec)) files.push_back(euroc);
  return files;
}

std::string InjectionYaml(const fs::path& dir, const Recording& recording,
                          sim::RecordingFaultOptions& options) {
  YAML::Node injection;
  injection["source"] = fs::absolute(dir).lexically_normal().string();
  injection["layout"] = recording.layout;
  injection["injection"] = YAML::Load(config::ToYaml(options));
  YAML::Emitter yaml;
  yaml << injection;
  return std::string(yaml.c_str()) + "\n";
}

std::string KindCounts(const std::vector<GlitchRecord>& records) {
  std::map<std::string, int> counts;
  for (const GlitchRecord& g : records) ++counts[FaultKindName(g.kind)];
  std::string s;
  for (const auto& [kind, n] : counts) s += (s.empty() ? "" : ", ") + std::to_string(n) + " " + kind;
  return s.empty() ? "none" : s;
}

}  // namespace

InjectResult InjectRecording(const InjectRequest& request) {
  sim::RecordingFaultOptions options = ResolveInjectOptions(request);
  // Read (and check) everything before writing anything.
  const fs::path dir(request.dataset);
  const Recording recording = ReadInjectSource(request.dataset);
  const Dataset& d = recording.dataset;
  const sim::FaultedRecording faulted = sim::InjectIntoRecording(options, d.imu, d.imu_clean, d.glitches);

  RefuseOutputOverInputs(request.output, RecordingInputPaths(dir));
  StagedDirectory out(request.output, request.force);
  const std::vector<std::string> imu_files = ImuFilesOf(dir, recording);
  std::set<std::string> skip(imu_files.begin(), imu_files.end());
  skip.insert({dataset_files::kImuClean, dataset_files::kGlitches, "injection.yaml"});
  InjectResult result{d.imu.size(), faulted.imu.size(), faulted.glitches,
                      CopyRecordingTree(dir, out.path(), skip)};
  const fs::path shown(request.output);  // the paths CSV errors would name
  for (const std::string& file : imu_files)
    WriteFileAtomic(out.path() / file, ImuCsv(faulted.imu, (shown / file).string()));
  WriteFileAtomic(out.path() / dataset_files::kImuClean,
                  ImuCsv(faulted.imu_clean, (shown / dataset_files::kImuClean).string()));
  WriteFileAtomic(out.path() / dataset_files::kGlitches,
                  GlitchesCsv(faulted.glitches, (shown / dataset_files::kGlitches).string()));
  WriteFileAtomic(out.path() / "injection.yaml", InjectionYaml(dir, recording, options));
  out.Commit();
  return result;
}

std::string InjectSummary(const InjectRequest& request, const InjectResult& result) {
  std::string summary = FormatPrintf(
      "%zu IMU samples -> %zu, fault records: %s; %d files copied, %d linked, %d image folders linked",
      result.imu_samples_in, result.imu_samples_out, KindCounts(result.glitches).c_str(),
      result.copied.copied_files, result.copied.linked_files, result.copied.linked_image_dirs);
  const std::vector<std::string>& left_out = result.copied.left_out;
  if (!left_out.empty()) {
    summary += FormatPrintf("; %zu entries that are not part of a recording left out (", left_out.size());
    for (std::size_t i = 0; i < left_out.size() && i < 3; ++i) summary += (i ? ", " : "") + left_out[i];
    summary += left_out.size() > 3 ? ", ...)" : ")";
  }
  return summary + " -> " + request.output;
}

}  // namespace vigil::experiments
