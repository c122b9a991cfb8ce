#include "gl/gl_context.h"

#include <algorithm>
#include <cstring>
#include <stdexcept>
#include <string>

#include "gl/gl_api.h"

namespace vigil::gl {

GlContext::GlContext(int samples) {
  const int attribs[] = {
      OSMESA_FORMAT, OSMESA_RGBA, OSMESA_DEPTH_BITS, 24, OSMESA_PROFILE, OSMESA_COMPAT_PROFILE, 0};
  context_ = OSMesaCreateContextAttribs(attribs, nullptr);
  if (context_ == nullptr) throw std::runtime_error("gl: cannot create an OSMesa context");
  // A 1 x 1 buffer makes the context current so that its limits can be queried.
  buffer_.assign(4, 0);
  if (!OSMesaMakeCurrent(context_, buffer_.data(), GL_UNSIGNED_BYTE, 1, 1)) {
    OSMesaDestroyContext(context_);
    throw std::runtime_error("gl: cannot make the OSMesa context current");
  }
  GLint max_samples = 0;
  glGetIntegerv(GL_MAX_SAMPLES, &max_samples);
  samples_ = std::clamp(samples, 0, static_cast<int>(max_samples));
}

GlContext::~GlContext() {
  ReleaseFramebuffers();
  OSMesaDestroyContext(context_);
}

void GlContext::ReleaseFramebuffers() {
  if (fbo_ != 0) glDeleteFramebuffers(1, &fbo_);
  if (color_rb_ != 0) glDeleteRenderbuffers(1, &color_rb_);
  if (depth_rb_ != 0) glDeleteRenderbuffers(1, &depth_rb_);
  fbo_ = color_rb_ = depth_rb_ = 0;
  fb_width_ = fb_height_ = 0;
}

void GlContext::BeginFrame(int width, int height, float r, float g, float b) {
  if (width <= 0 || height <= 0) throw std::runtime_error("gl: frame size must be positive");
  width_ = width;
  height_ = height;
  buffer_.assign(static_cast<std::size_t>(width) * height * 4, 0);
  if (!OSMesaMakeCurrent(context_, buffer_.data(), GL_UNSIGNED_BYTE, width, height)) {
    throw std::runtime_error("gl: cannot bind a " + std::to_string(width) + "x" + std::to_string(height) +
                             " OSMesa buffer");
  }
  if (fb_width_ != width || fb_height_ != height) {
    ReleaseFramebuffers();
    glGenFramebuffers(1, &fbo_);
    glGenRenderbuffers(1, &color_rb_);
    glGenRenderbuffers(1, &depth_rb_);
    glBindRenderbuffer(GL_RENDERBUFFER, color_rb_);
    glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples_, GL_RGBA8, width, height);
    glBindRenderbuffer(GL_RENDERBUFFER, depth_rb_);
    glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples_, GL_DEPTH_COMPONENT24, width, height);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, color_rb_);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_rb_);
    if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
      ReleaseFramebuffers();
      throw std::runtime_error("gl: incomplete framebuffer");
    }
    fb_width_ = width;
    fb_height_ = height;
  }
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
  glViewport(0, 0, width, height);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_SCISSOR_TEST);
  glDisable(GL_CULL_FACE);
  glEnable(GL_MULTISAMPLE);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glClearColor(r, g, b, 1.0f);
  glClearDepth(1.0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
}

void GlContext::Resolve(unsigned mask) {
  glDisable(GL_SCISSOR_TEST);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo_);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
  glBlitFramebuffer(0, 0, width_, height_, 0, 0, width_, height_, mask, GL_NEAREST);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

std::vector<uint8_t> GlContext::EndFrame() {
  Resolve(GL_COLOR_BUFFER_BIT);
  glFinish();
  // OSMesa's buffer has its first row at the bottom.
  std::vector<uint8_t> rgba(buffer_.size());
  const std::size_t row_bytes = static_cast<std::size_t>(width_) * 4;
  for (int y = 0; y < height_; ++y) {
    std::memcpy(rgba.data() + y * row_bytes, buffer_.data() + (height_ - 1 - y) * row_bytes, row_bytes);
  }
  for (std::size_t i = 3; i < rgba.size(); i += 4) rgba[i] = 255;
  return rgba;
}

std::vector<float> GlContext::ReadDepth() {
  // A multisampled depth buffer cannot be read directly: copy it (one sample per pixel) to the default
  // framebuffer's depth buffer, read that, then go on drawing into the off-screen framebuffer.
  Resolve(GL_DEPTH_BUFFER_BIT);
  std::vector<float> bottom_first(static_cast<std::size_t>(width_) * height_);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width_, height_, GL_DEPTH_COMPONENT, GL_FLOAT, bottom_first.data());
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
  std::vector<float> depth(bottom_first.size());
  for (int y = 0; y < height_; ++y) {
    std::memcpy(depth.data() + static_cast<std::size_t>(y) * width_,
                bottom_first.data() + static_cast<std::size_t>(height_ - 1 - y) * width_,
                sizeof(float) * width_);
  }
  return depth;
}

}  // namespace vigil::gl
