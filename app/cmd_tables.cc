// `vigil tables`: (re)writes results.csv, tables 2-4 and summary.md of a sweep directory from its runs.
#include <cstdio>
#include <memory>

#include "app/commands.h"
#include "experiments/tables.h"

namespace vigil::app {

void AddTablesCommand(CLI::App& root) {
  auto* cmd = root.add_subcommand("tables",
                                  "(re)write results.csv, table2-4.{md,csv,tex} and summary.md of a sweep "
                                  "directory from runs/*/metrics.json (also of an unfinished sweep)");
  auto dir = std::make_shared<std::string>();
  cmd->add_option("DIR", *dir, "sweep directory (written by vigil sweep / vigil paper)")->required();
  SetAction(cmd, [dir] {
    const experiments::SweepAggregate agg = experiments::WriteSweepTables(*dir);
    std::size_t failed = 0;
    for (const auto& c : agg.cells) failed += c.failed;
    std::fprintf(
        stderr,
        "vigil tables: %zu runs (%zu failed, %zu missing) -> %s/{results.csv, table2-4, summary.md}\n",
        agg.runs, failed, agg.missing, dir->c_str());
    return 0;
  });
}

}  // namespace vigil::app
