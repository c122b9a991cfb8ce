// One figure written as a PNG file, in a headless GL context and with a font of its own: what each
// single-figure command (`vigil map`, `vigil roc`) does after building its figure.
#pragma once

#include <filesystem>

#include "plots/figure.h"
#include "plots/render.h"

namespace vigil::plots {

// Checks `options` (InputError as ValidateFigureOptions), renders `figure` at the options' size and font,
// and writes it into `path`.
void WriteFigurePng(Figure figure, const std::filesystem::path& path, const FigureOptions& options);

}  // namespace vigil::plots
