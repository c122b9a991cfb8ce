#include "plots/gl_context.h"

#define GL_GLEXT_PROTOTYPES 1
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>

#include <algorithm>
#include <cstring>
#include <stdexcept>
#include <string>

namespace vigil::plots {

GlContext::GlContext(int samples) {
  const int attribs[] = {
      OSMESA_FORMAT, OSMESA_RGBA, OSMESA_DEPTH_BITS, 24, OSMESA_PROFILE, OSMESA_COMPAT_PROFILE, 0};
  context_ = OSMesaCreateContextAttribs(attribs, nullptr);
  if (context_ == nullptr) throw std::runtime_error("plots: cannot create an OSMesa context");
  // A 1 x 1 buffer makes the context current so that its limits can be queried.
  buffer_.assign(4, 0);
  if (!OSMesaMakeCurrent(context_, buffer_.data(), GL_UNSIGNED_BYTE, 1, 1)) {
    OSMesaDestroyContext(context_);
    throw std::runtime_error("plots: cannot make the OSMesa context current");
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

void GlContext::BeginFrame(int width, int height, const Color& background) {
  if (width <= 0 || height <= 0) throw std::runtime_error("plots: frame size must be positive");
  width_ = width;
  height_ = height;
  buffer_.assign(static_cast<std::size_t>(width) * height * 4, 0);
  if (!OSMesaMakeCurrent(context_, buffer_.data(), GL_UNSIGNED_BYTE, width, height)) {
    throw std::runtime_error("plots: cannot bind a " + std::to_string(width) + "x" + std::to_string(height) +
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
      throw std::runtime_error("plots: incomplete multisampled framebuffer");
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
  glClearColor(background.r, background.g, background.b, 1.0f);
  glClearDepth(1.0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
}

namespace {

// Copies the OSMesa buffer (bottom row first) into an opaque image (top row first).
Image ReadBack(const std::vector<unsigned char>& buffer, int width, int height) {
  Image image(width, height);
  const std::size_t row_bytes = static_cast<std::size_t>(width) * 4;
  for (int y = 0; y < height; ++y) {
    // OSMesa's buffer has its first row at the bottom.
    std::memcpy(image.Pixel(0, y), buffer.data() + (height - 1 - y) * row_bytes, row_bytes);
  }
  for (std::size_t i = 3; i < image.rgba.size(); i += 4) image.rgba[i] = 255;
  return image;
}

}  // namespace

Image GlContext::EndFrame() {
  glDisable(GL_SCISSOR_TEST);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo_);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
  glBlitFramebuffer(0, 0, width_, height_, 0, 0, width_, height_, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glFinish();
  return ReadBack(buffer_, width_, height_);
}

}  // namespace vigil::plots
