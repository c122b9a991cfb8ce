// Text drawn with FreeType: anti-aliased glyphs from a TrueType font, composited onto an Image.
//
// Text is drawn after the OpenGL content of a figure has been read back, so it always sits on top. Strings
// are UTF-8 (degree, Greek letters and the like come from the font). Glyph bitmaps are cached per size.
#pragma once

#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "plots/image.h"

namespace vigil::plots {

// The Debian fonts-dejavu-core sans-serif face.
inline constexpr const char* kDefaultFontFile = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";

// Where a text's reference point sits on the text box.
enum class HAlign { kLeft, kCenter, kRight };
enum class VAlign { kTop, kMiddle, kBaseline, kBottom };

struct TextExtent {
  int width = 0;    // advance width [px]
  int ascent = 0;   // above the baseline [px]
  int descent = 0;  // below the baseline [px], positive
};

class TextRenderer {
 public:
  // Loads the font; InputError "<file>: cannot load font" when it cannot.
  explicit TextRenderer(const std::string& font_file = kDefaultFontFile);
  ~TextRenderer();
  TextRenderer(const TextRenderer&) = delete;
  TextRenderer& operator=(const TextRenderer&) = delete;

  TextExtent Measure(const std::string& text, int size_px);
  // Draws `text` so that its (h, v) anchor lands on (x, y). `vertical`: rotated 90 degrees counter-clockwise
  // (reading bottom to top, as a y-axis label); the anchor then refers to the rotated box.
  void Draw(Image* image, const std::string& text, int size_px, double x, double y, HAlign h, VAlign v,
            const Color& color, bool vertical = false);

 private:
  struct Glyph {
    int width = 0, rows = 0, left = 0, top = 0, advance = 0;
    std::vector<uint8_t> coverage;
  };
  const Glyph& GetGlyph(char32_t code, int size_px);
  void SetSize(int size_px);

  struct Face;
  std::unique_ptr<Face> face_;
  std::map<std::pair<char32_t, int>, Glyph> cache_;
};

// Decodes UTF-8 (invalid bytes become U+FFFD).
std::u32string DecodeUtf8(const std::string& text);

}  // namespace vigil::plots
