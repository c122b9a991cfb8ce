// Glitch-sweep maps: a sweep over two axes (e.g. glitch magnitude x rate, or magnitude x burst length) read
// back from its runs' metrics.json and summarized per method as a map of ATE relative to the glitch-free ATE.
//
// The first setting of the first axis is the glitch-free reference (configs/glitch_map.yaml names it `none`:
// offsets of exactly 0, so its runs see the same random streams as the glitched ones and no fault). For a
// cell (method m, row setting r of axis 0, column setting c of axis 1), the ratio is
//   mean over seeds of ATE RMSE(m, r, c, seed) / mean over the same seeds of ATE RMSE(m, none, c, seed),
// over the seeds where both runs succeeded; a cell where some run failed reports the failures. Nothing is
// re-run: only what the runs recorded is read.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "experiments/sweeps/sweep_spec.h"

namespace vigil::experiments {

struct MapCell {
  double ratio = 0.0;        // NaN when no seed succeeded in both the cell and its reference
  double ate_m = 0.0;        // mean ATE RMSE of the cell over those seeds
  double reference_m = 0.0;  // mean ATE RMSE of the reference over those seeds
  int seeds = 0;             // seeds compared
  int failed = 0;            // failed runs of the cell
  int missing = 0;           // runs not on disk
};

struct GlitchMap {
  std::string row_axis, column_axis;       // axis keys
  std::string reference;                   // label of the reference setting
  std::vector<std::string> rows, columns;  // setting labels (rows without the reference)
  std::vector<std::string> methods;
  std::vector<MapCell> cells;  // methods x rows x columns, method-major then row-major

  const MapCell& Cell(std::size_t method, std::size_t row, std::size_t column) const {
    return cells[(method * rows.size() + row) * columns.size() + column];
  }
  // The method with the lowest finite ratio in a cell (-1 when none).
  int BestMethod(std::size_t row, std::size_t column) const;
};

// InputError when the spec cannot give a map: not exactly two axes, fewer than two settings on the first,
// or a first setting (the reference every ratio divides by) that is not glitch-free.
void CheckGlitchMapSpec(const SweepSpec& spec);

// Reads the sweep in `dir` (spec = its sweep.yaml), checked by CheckGlitchMapSpec.
GlitchMap ReadGlitchMap(const std::filesystem::path& dir, const SweepSpec& spec);

// map.md: one table per method (cells: ratio, with "F" for failed runs), the best method per cell, and the
// number of cells where the best method stays within `target_ratio`.
std::string GlitchMapMarkdown(const GlitchMap& map, double target_ratio = 1.2);

}  // namespace vigil::experiments
