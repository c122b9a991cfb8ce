#include "plots/text.h"

#include <ft2build.h>
#include FT_FREETYPE_H

#include <algorithm>
#include <cmath>

#include "core/error.h"

namespace vigil::plots {

struct TextRenderer::Face {
  FT_Library library = nullptr;
  FT_Face face = nullptr;
  int size_px = 0;
};

std::u32string DecodeUtf8(const std::string& text) {
  std::u32string out;
  for (std::size_t i = 0; i < text.size();) {
    const auto c = static_cast<unsigned char>(text[i]);
    int extra = c < 0x80 ? 0 : (c >> 5) == 0x6 ? 1 : (c >> 4) == 0xe ? 2 : (c >> 3) == 0x1e ? 3 : -1;
    if (extra < 0 || i + extra >= text.size() + (extra == 0 ? 1 : 0)) {
      out.push_back(0xfffd);
      ++i;
      continue;
    }
    char32_t code = extra == 0 ? c : c & (0x3f >> extra);
    bool ok = true;
    for (int k = 1; k <= extra; ++k) {
      const auto cc = static_cast<unsigned char>(text[i + k]);
      if ((cc >> 6) != 0x2) ok = false;
      code = (code << 6) | (cc & 0x3f);
    }
    out.push_back(ok ? code : 0xfffd);
    i += ok ? extra + 1 : 1;
  }
  return out;
}

TextRenderer::TextRenderer(const std::string& font_file) : face_(std::make_unique<Face>()) {
  if (FT_Init_FreeType(&face_->library) != 0) throw InputError("freetype: cannot initialize");
  if (FT_New_Face(face_->library, font_file.c_str(), 0, &face_->face) != 0) {
    FT_Done_FreeType(face_->library);
    throw InputError(font_file + ": cannot load font (install fonts-dejavu-core)");
  }
}

TextRenderer::~TextRenderer() {
  FT_Done_Face(face_->face);
  FT_Done_FreeType(face_->library);
}

void TextRenderer::SetSize(int size_px) {
  if (face_->size_px == size_px) return;
  FT_Set_Pixel_Sizes(face_->face, 0, static_cast<FT_UInt>(size_px));
  face_->size_px = size_px;
}

const TextRenderer::Glyph& TextRenderer::GetGlyph(char32_t code, int size_px) {
  const auto key = std::make_pair(code, size_px);
  auto it = cache_.find(key);
  if (it != cache_.end()) return it->second;
  Glyph glyph;
  SetSize(size_px);
  if (FT_Load_Char(face_->face, code, FT_LOAD_RENDER | FT_LOAD_TARGET_NORMAL) == 0) {
    const FT_GlyphSlot slot = face_->face->glyph;
    const FT_Bitmap& bitmap = slot->bitmap;
    glyph.width = static_cast<int>(bitmap.width);
    glyph.rows = static_cast<int>(bitmap.rows);
    glyph.left = slot->bitmap_left;
    glyph.top = slot->bitmap_top;
    glyph.advance = static_cast<int>((slot->advance.x + 32) >> 6);
    glyph.coverage.resize(static_cast<std::size_t>(glyph.width) * glyph.rows);
    for (int r = 0; r < glyph.rows; ++r) {
      std::copy_n(bitmap.buffer + r * bitmap.pitch, glyph.width, glyph.coverage.data() + r * glyph.width);
    }
  }
  return cache_.emplace(key, std::move(glyph)).first->second;
}

TextExtent TextRenderer::Measure(const std::string& text, int size_px) {
  TextExtent extent;
  // Ascent and descent of the face at this size, so that labels of one size share a baseline.
  SetSize(size_px);
  extent.ascent = static_cast<int>(std::lround(face_->face->size->metrics.ascender / 64.0));
  extent.descent = static_cast<int>(std::lround(-face_->face->size->metrics.descender / 64.0));
  for (char32_t c : DecodeUtf8(text)) extent.width += GetGlyph(c, size_px).advance;
  return extent;
}

void TextRenderer::Draw(Image* image, const std::string& text, int size_px, double x, double y, HAlign h,
                        VAlign v, const Color& color, bool vertical) {
  const TextExtent extent = Measure(text, size_px);
  // Layout in text space: pen starts at (0, ascent) in a box of width x (ascent + descent).
  double dx = h == HAlign::kLeft ? 0.0 : h == HAlign::kCenter ? -extent.width / 2.0 : -extent.width;
  const int box_h = extent.ascent + extent.descent;
  double dy = v == VAlign::kTop        ? 0.0
              : v == VAlign::kMiddle   ? -box_h / 2.0
              : v == VAlign::kBaseline ? -extent.ascent
                                       : -box_h;
  const int ox = static_cast<int>(std::lround(x)), oy = static_cast<int>(std::lround(y));
  const int ddx = static_cast<int>(std::lround(dx)), ddy = static_cast<int>(std::lround(dy));
  int pen = 0;
  for (char32_t c : DecodeUtf8(text)) {
    const Glyph& g = GetGlyph(c, size_px);
    for (int r = 0; r < g.rows; ++r) {
      for (int col = 0; col < g.width; ++col) {
        const uint8_t cov = g.coverage[static_cast<std::size_t>(r) * g.width + col];
        if (cov == 0) continue;
        // Text-space pixel (tx, ty) relative to the box's top-left corner.
        const int tx = pen + g.left + col + ddx;
        const int ty = extent.ascent - g.top + r + ddy;
        if (vertical) {
          // Rotate 90 degrees counter-clockwise about the anchor: text x runs up, text y runs right.
          image->Blend(ox + ty, oy - tx, color, cov / 255.0f);
        } else {
          image->Blend(ox + tx, oy + ty, color, cov / 255.0f);
        }
      }
    }
    pen += g.advance;
  }
}

}  // namespace vigil::plots
