// Options of the simulator's rendered camera images (`vigil simulate --images`, section `images`).
#pragma once

#include <cstdint>

#include "core/config.h"

namespace vigil::sim {

struct ImageOptions {
  bool enabled = false;          // render images into mav0/cam0/ (vigil simulate)
  double noise_std = 2.0;        // Gaussian pixel noise [gray levels], stream "image_noise"
  double exposure_s = 0.0;       // motion blur: sub-frame renders across [t - e/2, t + e/2], averaged
  int blur_samples = 5;          // sub-frames of a blurred frame (exposure_s > 0)
  uint64_t texture_seed = 0;     // seed of the procedural textures (0: the scenario's seed)
  int texture_size_px = 512;     // side of each square texture
  double texture_scale_m = 4.0;  // metres covered by one texture repeat on a surface
  int antialias_samples = 4;     // multisampling of the rendering (0: none)
  double sky_gray = 190.0;       // background gray level where no surface is seen
  int png_compression = 1;       // zlib level of the PNG files (0-9; 1: fastest, 2 % larger than 6)

  template <class V>
  void Visit(V& v) {
    using config::Bounds;
    v.Field("enabled", enabled,
            "render 8-bit grayscale camera images of a textured scene (vigil simulate writes mav0/ and "
            "scene.obj; --images sets it)");
    v.Field("noise_std", noise_std, "std of Gaussian pixel noise [gray levels] (stream image_noise)",
            Bounds::NonNegative());
    v.Field("exposure_s", exposure_s,
            "exposure time [s]: motion blur averages sub-frames at poses across [t - e/2, t + e/2] (0: none)",
            Bounds::Closed(0.0, 1.0));
    v.Field("blur_samples", blur_samples, "sub-frames rendered per blurred image", Bounds::Closed(2, 64));
    v.Field("texture_seed", texture_seed,
            "seed of the procedural textures (stream texture; 0: the run seed)");
    v.Field("texture_size_px", texture_size_px, "side of each square procedural texture [px]",
            Bounds::Closed(16, 4096));
    v.Field("texture_scale_m", texture_scale_m, "metres covered by one repeat of a texture on a surface",
            Bounds::Positive());
    v.Field("antialias_samples", antialias_samples, "multisampling of the rendering (0: none; at most 4)",
            Bounds::Closed(0, 16));
    v.Field("sky_gray", sky_gray, "gray level of the background where no surface is seen",
            Bounds::Closed(0.0, 255.0));
    v.Field("png_compression", png_compression, "zlib level of the PNG images (0-9)", Bounds::Closed(0, 9));
  }
};

}  // namespace vigil::sim
