#include "plots/figure_png.h"

#include "gl/gl_context.h"
#include "plots/image.h"
#include "plots/text.h"

namespace vigil::plots {

void WriteFigurePng(Figure figure, const std::filesystem::path& path, const FigureOptions& options) {
  ValidateFigureOptions(options);
  gl::GlContext gl;
  TextRenderer text(options.font_file);
  WritePng(path, figure.Render(&gl, &text, options.width, options.height));
}

}  // namespace vigil::plots
