// `vigil inject`: the simulator's IMU faults (glitch.*, faults.*) applied to a recording's IMU, written as a
// copy of the recording with labels (sim/recording_faults.h).
#include <cstdio>
#include <map>
#include <memory>
#include <set>

#include "app/commands.h"
#include "core/config.h"
#include "core/dataset.h"
#include "core/error.h"
#include "core/euroc.h"
#include "core/output.h"
#include "core/recording_copy.h"
#include "sim/recording_faults.h"

namespace vigil::app {
namespace {

namespace fs = std::filesystem;

// Where a recording keeps its IMU, relative to its folder: imu.csv (vigil's layout, which may also hold a
// mav0/imu0 copy written by vigil simulate --images) or mav0/imu0/data.csv (EuRoC).
std::vector<std::string> ImuFilesOf(const fs::path& dir, const Recording& recording) {
  const std::string euroc =
      std::string(euroc_files::kMav0) + "/" + euroc_files::kImu + "/" + euroc_files::kData;
  std::error_code ec;
  if (recording.layout == "euroc") return {euroc};
  std::vector<std::string> files = {dataset_files::kImu};
  if (fs::is_regular_file(dir / euroc, ec)) files.push_back(euroc);
  return files;
}

std::string KindCounts(const std::vector<GlitchRecord>& records) {
  std::map<std::string, int> counts;
  for (const GlitchRecord& g : records) ++counts[FaultKindName(g.kind)];
  std::string s;
  for (const auto& [kind, n] : counts) s += (s.empty() ? "" : ", ") + std::to_string(n) + " " + kind;
  return s.empty() ? "none" : s;
}

}  // namespace

void AddInjectCommand(CLI::App& root) {
  auto* cmd = root.add_subcommand(
      "inject",
      "apply the simulator's IMU faults (--set glitch.k=v, --set faults.k=v) to a recording's IMU: writes a "
      "copy of the recording (vigil dataset or EuRoC folder) with the faulty IMU, imu_clean.csv (the "
      "recording's own stream), glitches.csv and injection.yaml; images are linked, not copied");
  struct Args {
    std::string dataset, output, seed;
    std::vector<std::string> overrides;
    bool force = false;
  };
  auto args = std::make_shared<Args>();
  cmd->add_option("DATASET", args->dataset,
                  "recording: a vigil dataset directory or a EuRoC folder (holding mav0/)")
      ->required();
  cmd->add_option("-o,--output", args->output,
                  "directory to write (must not exist or be empty, unless --force)")
      ->required();
  cmd->add_option("--set", args->overrides,
                  "key.path=value (repeatable): glitch.*, faults.*, seed, gravity_mps2 with the simulator's "
                  "meaning (configs/README.md)");
  cmd->add_option("--seed", args->seed, "seed of the fault draws (default 1)");
  cmd->add_flag("--force", args->force,
                "replace an output directory vigil wrote (files it did not write are kept)");
  SetAction(cmd, [args] {
    sim::RecordingFaultOptions options;
    for (const std::string& o : args->overrides) config::ApplyOverride(o, options);
    if (!args->seed.empty()) config::ApplyOverride("seed=" + args->seed, options);
    const std::string why = sim::ValidateRecordingFaultOptions(options);
    if (!why.empty()) throw InputError("--set " + why);

    // Read (and check) everything before writing anything.
    const fs::path dir(args->dataset);
    std::error_code ec;
    if (!fs::is_directory(dir, ec)) throw InputError(args->dataset + ": not a dataset directory");
    const fs::path normal = fs::absolute(dir).lexically_normal();
    if ((normal.has_filename() ? normal.filename() : normal.parent_path().filename()) == euroc_files::kMav0)
      throw InputError(args->dataset + ": give the folder that holds mav0/, not mav0/ itself");
    const Recording recording = ReadRecording(dir);
    const Dataset& d = recording.dataset;
    if (d.imu.size() < 2) throw InputError(args->dataset + ": fewer than two IMU samples");
    if (!d.glitches.empty() && d.imu_clean.empty())
      throw InputError(
          (dir / dataset_files::kGlitches).string() +
          ": the recording already has glitches but no imu_clean.csv to keep; faults on top of it "
          "would lose the glitch-free stream (inject into the recording without glitches)");
    const sim::FaultedRecording faulted = sim::InjectIntoRecording(options, d.imu, d.imu_clean, d.glitches);

    RefuseOutputOverInputs(args->output, {dir});
    StagedDirectory out(args->output, args->force);
    const std::vector<std::string> imu_files = ImuFilesOf(dir, recording);
    std::set<std::string> skip(imu_files.begin(), imu_files.end());
    skip.insert({dataset_files::kImuClean, dataset_files::kGlitches, "injection.yaml"});
    const RecordingCopyStats copied = CopyRecordingTree(dir, out.path(), skip);
    for (const std::string& file : imu_files)
      WriteFileAtomic(out.path() / file, ImuCsv(faulted.imu, (fs::path(args->output) / file).string()));
    WriteFileAtomic(out.path() / dataset_files::kImuClean,
                    ImuCsv(faulted.imu_clean, (fs::path(args->output) / dataset_files::kImuClean).string()));
    WriteFileAtomic(
        out.path() / dataset_files::kGlitches,
        GlitchesCsv(faulted.glitches, (fs::path(args->output) / dataset_files::kGlitches).string()));
    YAML::Node injection;
    injection["source"] = fs::absolute(dir).lexically_normal().string();
    injection["layout"] = recording.layout;
    injection["injection"] = YAML::Load(config::ToYaml(options));
    YAML::Emitter yaml;
    yaml << injection;
    WriteFileAtomic(out.path() / "injection.yaml", std::string(yaml.c_str()) + "\n");
    out.Commit();
    std::fprintf(
        stderr,
        "vigil inject: %zu IMU samples -> %zu, fault records: %s; %d files copied, %d linked, %d image "
        "folders linked -> %s\n",
        d.imu.size(), faulted.imu.size(), KindCounts(faulted.glitches).c_str(), copied.copied_files,
        copied.linked_files, copied.linked_image_dirs, args->output.c_str());
    return 0;
  });
}

}  // namespace vigil::app
