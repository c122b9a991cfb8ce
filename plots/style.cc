#include "plots/style.h"

namespace vigil::plots {

Color PaletteColor(int index) {
  static constexpr Color kPalette[] = {
      {0.000f, 0.447f, 0.698f, 1.0f},  // blue
      {0.835f, 0.369f, 0.000f, 1.0f},  // vermillion
      {0.000f, 0.620f, 0.451f, 1.0f},  // bluish green
      {0.800f, 0.475f, 0.655f, 1.0f},  // reddish purple
      {0.902f, 0.624f, 0.000f, 1.0f},  // orange
      {0.337f, 0.706f, 0.914f, 1.0f},  // sky blue
      {0.600f, 0.600f, 0.600f, 1.0f},  // grey
      {0.941f, 0.894f, 0.259f, 1.0f},  // yellow
  };
  constexpr int kCount = sizeof(kPalette) / sizeof(kPalette[0]);
  return kPalette[((index % kCount) + kCount) % kCount];
}

}  // namespace vigil::plots
