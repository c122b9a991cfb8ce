#include "experiments/sweeps/sweep_engine.h"

#include <unistd.h>

#include <atomic>
#include <chrono>
#include <memory>
#include <thread>
#include <vector>

#include <tbb/parallel_pipeline.h>
#include <tbb/task_arena.h>

#include "core/error.h"
#include "core/output.h"
#include "core/staging.h"
#include "core/thread_handoff.h"
#include "experiments/external/child_process.h"
#include "experiments/sweeps/progress.h"
#include "experiments/sweeps/sweep_lock.h"

namespace vigil::experiments {
namespace fs = std::filesystem;
namespace {

constexpr const char* kMetricsFile = "metrics.json";

// What travels from the parallel stage to the in-order output stage.
struct Finished {
  std::size_t index = 0;
  nlohmann::json
      metrics;  // the committed metrics.json, parsed once (discarded when a resumed file is not JSON)
};

nlohmann::json FailureMetrics(const std::string& reason) {
  nlohmann::json j;
  j["status"] = "failed";
  j["failure_reason"] = reason;
  return j;
}

}  // namespace

bool IsFailed(const nlohmann::json& metrics) {
  const auto it = metrics.find("status");
  if (it == metrics.end() || !it->is_string()) return true;
  const std::string status = it->get<std::string>();
  return status != "ok" && status != "diverged";
}

bool IsDiverged(const nlohmann::json& metrics) {
  const auto it = metrics.find("status");
  return it != metrics.end() && it->is_string() && it->get<std::string>() == "diverged";
}

fs::path RunDirectory(const fs::path& sweep_dir, const std::string& id) { return sweep_dir / "runs" / id; }
fs::path RunMetricsPath(const fs::path& sweep_dir, const std::string& id) {
  return RunDirectory(sweep_dir, id) / kMetricsFile;
}

SweepOutcome ExecuteSweep(const fs::path& sweep_dir, const std::vector<std::string>& run_ids,
                          const RunFunction& run, const ResultFunction& on_result,
                          const SweepEngineOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  const fs::path runs_dir = sweep_dir / "runs";
  fs::create_directories(runs_dir);
  RemoveStaleStaging(runs_dir);  // of dead processes on this host only: other shards may be writing here

  const int threads =
      options.threads > 0 ? options.threads : static_cast<int>(tbb::info::default_concurrency());
  SweepOutcome outcome;
  outcome.total = run_ids.size();
  std::atomic<std::size_t> executed{0}, resumed{0};
  ProgressBar progress(run_ids.size(), options.progress);

  // Items pass as run indices (carried inside the token itself, not in a buffer of libtbb's); a run's result
  // waits in finished[index], handed from `work` to `sink` on its own address; a serial filter's state is
  // handed from one call to the next on one address; `handoff` hands what was written before the pipeline to
  // its bodies (core/thread_handoff.h: what TSan cannot see inside libtbb).
  const int handoff = 0;
  std::vector<std::unique_ptr<Finished>> finished(run_ids.size());
  std::size_t next = 0;
  auto source = [&](tbb::flow_control& fc) -> std::size_t {
    HandOffAcquire(&handoff);
    HandOffAcquire(&next);
    const bool stop = next >= run_ids.size();
    const std::size_t index = stop ? 0 : next++;
    HandOffRelease(&next);  // after the last access to anything the caller owns
    if (stop) fc.stop();
    return index;
  };
  auto work = [&](std::size_t index) -> std::size_t {
    HandOffAcquire(&handoff);
    finished[index] = std::make_unique<Finished>();
    Finished* done = finished[index].get();
    done->index = index;
    const fs::path final_metrics = RunMetricsPath(sweep_dir, run_ids[index]);
    std::error_code ec;
    if (options.resume && fs::is_regular_file(final_metrics, ec)) {
      done->metrics = nlohmann::json::parse(ReadFile(final_metrics), nullptr, false);
      ++resumed;
      progress.Finished(true, IsFailed(done->metrics));
      HandOffRelease(&finished[index]);
      return index;
    }
    StagedDirectory staging(RunDirectory(sweep_dir, run_ids[index]), /*force=*/true);
    try {
      done->metrics = run(index, staging.path());
    } catch (const std::exception& e) {
      done->metrics = FailureMetrics(e.what());
    } catch (const Interrupted&) {
      throw;  // vigil was interrupted: not a failed run; the sweep stops
    } catch (...) {
      done->metrics = FailureMetrics("unknown exception");
    }
    WriteFileAtomic(staging.path() / kMetricsFile, done->metrics.dump(2) + "\n");
    staging.Commit();
    ++executed;
    progress.Finished(false, IsFailed(done->metrics));
    HandOffRelease(&finished[index]);
    return index;
  };
  std::size_t failed = 0;
  auto sink = [&](std::size_t index) {
    HandOffAcquire(&finished[index]);
    HandOffAcquire(&failed);
    const std::unique_ptr<Finished> done = std::move(finished[index]);
    if (done->metrics.is_discarded())
      throw std::runtime_error(RunMetricsPath(sweep_dir, run_ids[done->index]).string() + ": not valid JSON");
    if (IsFailed(done->metrics)) ++failed;
    if (on_result) on_result(done->index, done->metrics);
    HandOffRelease(&failed);
  };

  tbb::task_arena arena(threads);
  HandOffRelease(&handoff);
  arena.execute([&] {
    tbb::parallel_pipeline(static_cast<std::size_t>(4 * threads),
                           tbb::make_filter<void, std::size_t>(tbb::filter_mode::serial_in_order, source) &
                               tbb::make_filter<std::size_t, std::size_t>(tbb::filter_mode::parallel, work) &
                               tbb::make_filter<std::size_t, void>(tbb::filter_mode::serial_in_order, sink));
  });
  HandOffAcquire(&next);  // the last source call
  HandOffAcquire(&failed);
  progress.Close();
  outcome.executed = executed;
  outcome.resumed = resumed;
  outcome.failed = failed;
  outcome.wall_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return outcome;
}

namespace {

// Whether `dir` holds anything besides sweep.yaml being staged: a shard that starts beside another sees the
// other's sweep.yaml staging for an instant before it is linked into place (CommitSweepFile), and that
// directory is still a new sweep, not a user's directory. The sweep's lock file
// (experiments/sweeps/sweep_lock.h) does not count either: it is taken before the directory is prepared.
bool HasEntriesBesidesSweepFileStaging(const fs::path& dir) {
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(dir, ec)) {
    if (entry.path().filename() == kSweepLockFile) continue;
    const auto staging = ParseStagingName(entry.path().filename().string());
    if (!staging || staging->final_name != "sweep.yaml") return true;
  }
  return false;
}

}  // namespace

void CheckSweepDirectory(const fs::path& dir, bool resume, bool force) {
  std::error_code ec;
  if (fs::exists(dir, ec) && !fs::is_directory(dir, ec))
    throw InputError(dir.string() + ": exists and is not a directory");
  const bool non_empty = fs::is_directory(dir, ec) && HasEntriesBesidesSweepFileStaging(dir);
  if (!non_empty) return;
  const bool is_sweep = fs::is_regular_file(dir / "sweep.yaml", ec);
  if (resume && !is_sweep)
    throw InputError(dir.string() +
                     ": not a sweep directory (no sweep.yaml), nothing to resume: refusing to write into it "
                     "(choose an empty or new directory)");
  if (!resume && !force)
    throw InputError(dir.string() +
                     ": output directory is not empty (use --resume to continue the sweep "
                     "in it, or --force to start over)");
  // Refused here, before the sweep takes its lock (a file in `dir`): nothing is written into a user's folder.
  if (force && !resume && !is_sweep)
    throw InputError(
        dir.string() +
        ": no sweep.yaml: not a sweep directory vigil wrote, so --force does not replace it; move it "
        "away or choose another output");
}

void PrepareSweepDirectory(const fs::path& dir, bool resume, bool force) {
  CheckSweepDirectory(dir, resume, force);
  std::error_code ec;
  const bool non_empty = fs::is_directory(dir, ec) && HasEntriesBesidesSweepFileStaging(dir);
  if (non_empty && force && !resume) {
    // Only the sweep's own layout is removed: runs/ and the files a sweep writes at the top level (a
    // directory without sweep.yaml was refused above).
    fs::remove_all(dir / "runs", ec);
    fs::remove_all(dir / "figures", ec);
    for (const char* name : {"sweep.yaml", "results.csv", "timing.csv", "summary.md"})
      fs::remove(dir / name, ec);
    for (const char* table : {"table2", "table3", "table4"})
      for (const char* ext : {".md", ".csv", ".tex"}) fs::remove(dir / (std::string(table) + ext), ec);
  }
  fs::create_directories(dir, ec);
  if (ec) throw InputError(dir.string() + ": cannot create output directory: " + ec.message());
}

}  // namespace vigil::experiments
