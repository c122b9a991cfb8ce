// The glitch-sweep map figure: one heat map per method of the ATE relative to the glitch-free ATE of the same
// seeds (experiments/sweeps/glitch_map.h), cell values printed; green at or below 1, red from 3 up (log
// scale). Drawn from what the runs recorded (metrics.json through ReadGlitchMap), never by re-running
// anything.
#pragma once

#include <filesystem>

#include "experiments/sweeps/glitch_map.h"
#include "plots/figure.h"
#include "plots/render.h"

namespace vigil::plots {

Figure GlitchMapFigure(const experiments::GlitchMap& map, const std::string& title);

// Renders GlitchMapFigure into `path` (PNG, options' size and font).
void WriteGlitchMapFigure(const experiments::GlitchMap& map, const std::string& title,
                          const std::filesystem::path& path, const FigureOptions& options);

}  // namespace vigil::plots
