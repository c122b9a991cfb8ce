// A headless OpenGL context (OSMesa, software rendering) drawing into an off-screen framebuffer, optionally
// multisampled.
//
// One context serves any number of frames of any size: BeginFrame() (re)creates the framebuffer objects for
// the size, EndFrame() resolves the samples (anti-aliasing) and reads the pixels back; ReadDepth() reads the
// depth buffer of the frame. The context is current on the thread that created it and must only be used
// there. Everything drawn between BeginFrame and EndFrame uses the fixed-function pipeline of the
// compatibility profile. Used by the figures (plots/) and by the simulator's camera images (sim/).
#pragma once

#include <cstdint>
#include <vector>

struct osmesa_context;

namespace vigil::gl {

class GlContext {
 public:
  // Creates the context; std::runtime_error when OSMesa is unavailable. `samples` is capped to what the
  // implementation supports (llvmpipe: 4); 0 renders without multisampling.
  explicit GlContext(int samples = 4);
  ~GlContext();
  GlContext(const GlContext&) = delete;
  GlContext& operator=(const GlContext&) = delete;

  // Binds a width x height framebuffer with a 24-bit depth buffer and clears it to the colour (r, g, b) in
  // [0, 1] and depth 1. Leaves blending on (source alpha), depth test, scissor and culling off.
  void BeginFrame(int width, int height, float r, float g, float b);
  // Resolves and reads the frame back: width * height * 4 bytes (r, g, b, a = 255), top row first.
  std::vector<uint8_t> EndFrame();
  // The depth buffer of the current frame in [0, 1] (window depth), top row first; call before EndFrame.
  std::vector<float> ReadDepth();

  int width() const { return width_; }
  int height() const { return height_; }
  int samples() const { return samples_; }

 private:
  void ReleaseFramebuffers();
  void Resolve(unsigned mask);

  osmesa_context* context_ = nullptr;
  std::vector<unsigned char> buffer_;  // the OSMesa default framebuffer (resolve target)
  int width_ = 0, height_ = 0, samples_ = 0;
  unsigned fbo_ = 0, color_rb_ = 0, depth_rb_ = 0;
  int fb_width_ = 0, fb_height_ = 0;
};

}  // namespace vigil::gl
