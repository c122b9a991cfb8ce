// Corner-rich procedural textures for the rendered scene: square, tileable 8-bit gray images.
//
// A texture is a mid-gray canvas covered by random axis-aligned rectangles of random gray levels (in
// [20, 235]), drawn with wrap-around so that the texture tiles without seams, then a few rectangles' worth of
// checkerboard patches. Every corner of a rectangle is a good feature to track. Stream: Rng(seed, "texture")
// shared by the textures in order, so texture i depends only on the seed and on the textures before it.
#pragma once

#include <cstdint>
#include <vector>

namespace vigil::sim {

struct GrayTexture {
  int size = 0;
  std::vector<uint8_t> gray;  // size * size, row-major
};

// `count` textures of `size` x `size` pixels.
std::vector<GrayTexture> MakeTextures(int count, int size, uint64_t seed);

}  // namespace vigil::sim
