// `vigil tables`: (re)writes results.csv, timing.csv, tables 2-4 and summary.md of a sweep directory from
// its runs: the finalization of a sweep run in shards (`vigil sweep --shard`, `vigil slurm`).
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "app/commands.h"
#include "core/error.h"
#include "plots/render.h"
#include "report/tables.h"

namespace vigil::app {
namespace {

// "a, b, c and 7 more".
std::string IdList(const std::vector<std::string>& ids, std::size_t shown = 10) {
  std::string s;
  for (std::size_t i = 0; i < ids.size() && i < shown; ++i) s += (i ? ", " : "") + ids[i];
  if (ids.size() > shown) s += " and " + std::to_string(ids.size() - shown) + " more";
  return s;
}

// What is replaced must be a file: a directory (or FIFO...) of that name is refused before any work.
void RefuseNonFileOutputs(const std::string& dir) {
  for (const char* name : {"results.csv", "timing.csv", "summary.md"}) {
    const std::filesystem::path path = std::filesystem::path(dir) / name;
    std::error_code ec;
    if (std::filesystem::exists(std::filesystem::symlink_status(path, ec)) &&
        !std::filesystem::is_regular_file(std::filesystem::status(path, ec)))
      throw InputError(path.string() + ": exists and is not a regular file; move it away");
  }
}

// The failed and the missing runs, when there are any.
void ReportUnfinishedRuns(const experiments::SweepAggregate& agg) {
  if (!agg.failed_ids.empty())
    std::fprintf(stderr, "vigil tables: failed runs (reasons in summary.md): %s\n",
                 IdList(agg.failed_ids).c_str());
  if (!agg.missing_ids.empty())
    std::fprintf(
        stderr,
        "vigil tables: missing runs (not finished: resume the sweep or its shard with --resume): %s\n",
        IdList(agg.missing_ids).c_str());
}

}  // namespace

void AddTablesCommand(CLI::App& root) {
  auto* cmd =
      root.add_subcommand("tables",
                          "(re)write results.csv, timing.csv, table2-4.{md,csv,tex} and summary.md of "
                          "a sweep directory from runs/*/metrics.json; reports missing and failed "
                          "runs; exit 1 while runs are missing, unless --allow-incomplete");
  struct Args {
    std::string dir;
    bool allow_incomplete = false, figures = false;
  };
  auto args = std::make_shared<Args>();
  cmd->add_option("DIR", args->dir, "sweep directory (written by vigil sweep / vigil paper)")->required();
  cmd->add_flag("--allow-incomplete", args->allow_incomplete,
                "exit 0 even when runs are missing (tables of the runs finished so far)");
  cmd->add_flag("--figures", args->figures, "also render figures/*.png, as vigil paper does");
  SetAction(cmd, [args] {
    RefuseNonFileOutputs(args->dir);
    const experiments::SweepAggregate agg = report::WriteSweepTables(args->dir);
    std::fprintf(stderr,
                 "vigil tables: %zu runs (%zu failed, %zu missing) -> %s/{results.csv, timing.csv, table2-4, "
                 "summary.md}\n",
                 agg.runs, agg.failed_ids.size(), agg.missing, args->dir.c_str());
    ReportUnfinishedRuns(agg);
    if (args->figures) {
      const auto figures = plots::RenderSweepFigures(args->dir, plots::FigureOptions{});
      std::fprintf(stderr, "vigil tables: %zu figures -> %s\n", figures.size(),
                   (std::filesystem::path(args->dir) / "figures").string().c_str());
    }
    if (agg.missing > 0 && !args->allow_incomplete) {
      std::fprintf(stderr, "vigil tables: the sweep is incomplete (%zu of %zu runs missing)\n", agg.missing,
                   agg.runs);
      return 1;
    }
    return 0;
  });
}

}  // namespace vigil::app
