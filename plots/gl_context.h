// A headless OpenGL context (OSMesa, software rendering) drawing into a multisampled off-screen framebuffer.
//
// One context serves any number of frames of any size: BeginFrame() (re)creates the framebuffer objects for
// the size, EndFrame() resolves the samples (anti-aliasing) and reads the pixels back. The context is current
// on the thread that created it and must only be used there. Everything drawn between BeginFrame and
// EndFrame uses the fixed-function pipeline of the compatibility profile.
#pragma once

#include <vector>

#include "plots/image.h"

struct osmesa_context;

namespace vigil::plots {

class GlContext {
 public:
  // Creates the context; std::runtime_error when OSMesa is unavailable. `samples` is capped to what the
  // implementation supports (llvmpipe: 4).
  explicit GlContext(int samples = 4);
  ~GlContext();
  GlContext(const GlContext&) = delete;
  GlContext& operator=(const GlContext&) = delete;

  // Binds a width x height multisampled framebuffer with depth, clears it to `background`.
  void BeginFrame(int width, int height, const Color& background);
  // Resolves and reads the frame back (top row first).
  Image EndFrame();

  int width() const { return width_; }
  int height() const { return height_; }
  int samples() const { return samples_; }

 private:
  void ReleaseFramebuffers();

  osmesa_context* context_ = nullptr;
  std::vector<unsigned char> buffer_;  // the OSMesa default framebuffer (resolve target)
  int width_ = 0, height_ = 0, samples_ = 0;
  unsigned fbo_ = 0, color_rb_ = 0, depth_rb_ = 0;
  int fb_width_ = 0, fb_height_ = 0;
};

}  // namespace vigil::plots
