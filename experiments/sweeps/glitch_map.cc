#include "experiments/sweeps/glitch_map.h"

#include <cmath>
#include <limits>
#include <map>

#include "core/error.h"
#include "core/format.h"
#include "evaluation/metrics_access.h"
#include "experiments/sweeps/sweep_aggregate.h"
#include "experiments/sweeps/sweep_engine.h"

namespace vigil::experiments {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// ATE RMSE per (cell index, seed) of successful runs; failures and missing runs per cell.
struct RunTable {
  std::map<std::pair<std::size_t, uint64_t>, double> ate_m;
  std::map<std::size_t, int> failed, missing;
};

RunTable ReadRuns(const std::filesystem::path& dir, const SweepSpec& spec) {
  RunTable table;
  AggregateSweep(dir, spec, {}, [&](const SweepRunRef& run, const SweepCell&, const nlohmann::json* m) {
    if (m == nullptr) {
      ++table.missing[run.cell];
      return;
    }
    const double ate = evaluation::MetricNumber(*m, {"ate", "trans_m", "rmse"});
    if (IsFailed(*m) || !std::isfinite(ate)) {
      ++table.failed[run.cell];
      return;
    }
    table.ate_m[{run.cell, run.seed}] = ate;
  });
  return table;
}

std::string RatioText(const MapCell& c) {
  std::string s = std::isfinite(c.ratio) ? FormatFixed(c.ratio, 2) : "-";
  if (c.failed > 0) s += " (" + std::to_string(c.failed) + " F)";
  if (c.missing > 0) s += " (" + std::to_string(c.missing) + " missing)";
  return s;
}

std::string TableHeader(const GlitchMap& map) {
  std::string s = "| " + map.row_axis + " \\ " + map.column_axis + " |";
  for (const std::string& c : map.columns) s += " " + c + " |";
  s += "\n|---|";
  for (std::size_t i = 0; i < map.columns.size(); ++i) s += "---|";
  return s + "\n";
}

}  // namespace

int GlitchMap::BestMethod(std::size_t row, std::size_t column) const {
  int best = -1;
  for (std::size_t m = 0; m < methods.size(); ++m) {
    const double r = Cell(m, row, column).ratio;
    if (std::isfinite(r) && (best < 0 || r < Cell(static_cast<std::size_t>(best), row, column).ratio))
      best = static_cast<int>(m);
  }
  return best;
}

void CheckGlitchMapSpec(const SweepSpec& spec) {
  if (spec.axes.size() != 2 || spec.axes[0].settings.size() < 2)
    throw InputError(spec.path +
                     ": axes: a map needs exactly two axes, the first with the glitch-free "
                     "reference setting first and at least one more");
  // The reference row is what every ratio divides by: it must be glitch-free in every column.
  const std::vector<SweepCell> cells = EnumerateCells(spec);
  const std::size_t per_row = spec.axes[1].settings.size() * spec.methods.size();
  for (std::size_t c = 0; c < per_row && c < cells.size(); ++c) {
    const sim::GlitchOptions& g = ResolveCellConfig(spec, cells[c]).sim.glitch;
    if (g.enabled && !(g.mean == 0.0 && g.std == 0.0))
      throw InputError(spec.path +
                       ": axes: the first axis must start at the glitch-free reference (glitches "
                       "off, or mean 0 and std 0); its first setting '" +
                       spec.axes[0].settings[0].label + "' gives N(" + FormatDouble(g.mean) + ", " +
                       FormatDouble(g.std) + ") glitches");
  }
}

GlitchMap ReadGlitchMap(const std::filesystem::path& dir, const SweepSpec& spec) {
  CheckGlitchMapSpec(spec);
  GlitchMap map;
  map.row_axis = spec.axes[0].key;
  map.column_axis = spec.axes[1].key;
  map.reference = spec.axes[0].settings[0].label;
  for (std::size_t r = 1; r < spec.axes[0].settings.size(); ++r)
    map.rows.push_back(spec.axes[0].settings[r].label);
  for (const SweepSetting& s : spec.axes[1].settings) map.columns.push_back(s.label);
  for (const SweepSetting& m : spec.methods) map.methods.push_back(m.label);

  const RunTable runs = ReadRuns(dir, spec);
  // Cell index in EnumerateCells order: the first axis slowest, the method fastest.
  const std::size_t n_methods = map.methods.size(), n_columns = map.columns.size();
  const auto cell_index = [&](std::size_t row_setting, std::size_t column, std::size_t method) {
    return (row_setting * n_columns + column) * n_methods + method;
  };
  for (std::size_t m = 0; m < n_methods; ++m) {
    for (std::size_t r = 0; r < map.rows.size(); ++r) {
      for (std::size_t c = 0; c < n_columns; ++c) {
        const std::size_t cell = cell_index(r + 1, c, m), reference = cell_index(0, c, m);
        MapCell out;
        double sum = 0.0, sum_ref = 0.0;
        for (const uint64_t seed : spec.seeds) {
          const auto a = runs.ate_m.find({cell, seed}), b = runs.ate_m.find({reference, seed});
          if (a == runs.ate_m.end() || b == runs.ate_m.end()) continue;
          sum += a->second;
          sum_ref += b->second;
          ++out.seeds;
        }
        const auto count = [](const std::map<std::size_t, int>& counts, std::size_t key) {
          const auto it = counts.find(key);
          return it == counts.end() ? 0 : it->second;
        };
        out.failed = count(runs.failed, cell);
        out.missing = count(runs.missing, cell);
        out.ate_m = out.seeds ? sum / out.seeds : kNaN;
        out.reference_m = out.seeds ? sum_ref / out.seeds : kNaN;
        out.ratio = out.seeds && out.failed == 0 ? out.ate_m / out.reference_m : kNaN;
        map.cells.push_back(out);
      }
    }
  }
  return map;
}

std::string GlitchMapMarkdown(const GlitchMap& map, double target_ratio) {
  std::string s = "# Glitch map: ATE relative to the glitch-free ATE of the same method and seeds\n\n";
  s +=
      "Rows: " + map.row_axis + " (reference: `" + map.reference + "`), columns: " + map.column_axis +
      ". A cell is mean ATE RMSE over the seeds / the same for the reference; `F`: failed runs (no ratio).\n";
  for (std::size_t m = 0; m < map.methods.size(); ++m) {
    s += "\n## " + map.methods[m] + "\n\n" + TableHeader(map);
    for (std::size_t r = 0; r < map.rows.size(); ++r) {
      s += "| " + map.rows[r] + " |";
      for (std::size_t c = 0; c < map.columns.size(); ++c) s += " " + RatioText(map.Cell(m, r, c)) + " |";
      s += "\n";
    }
    s += "\nglitch-free ATE [m] per column:";
    for (std::size_t c = 0; c < map.columns.size(); ++c)
      s += " " + (std::isfinite(map.Cell(m, 0, c).reference_m) ? FormatFixed(map.Cell(m, 0, c).reference_m, 4)
                                                               : std::string("-"));
    s += "\n";
  }
  s += "\n## best method per cell\n\n" + TableHeader(map);
  int within = 0, total = 0;
  for (std::size_t r = 0; r < map.rows.size(); ++r) {
    s += "| " + map.rows[r] + " |";
    for (std::size_t c = 0; c < map.columns.size(); ++c) {
      const int best = map.BestMethod(r, c);
      ++total;
      if (best < 0) {
        s += " - |";
        continue;
      }
      const double ratio = map.Cell(static_cast<std::size_t>(best), r, c).ratio;
      within += ratio <= target_ratio;
      s += " " + map.methods[static_cast<std::size_t>(best)] + " " + FormatFixed(ratio, 2) + " |";
    }
    s += "\n";
  }
  s += "\nBest method within " + FormatFixed(target_ratio, 2) + "x the glitch-free ATE in " +
       std::to_string(within) + " of " + std::to_string(total) + " cells.\n";
  return s;
}

}  // namespace vigil::experiments
