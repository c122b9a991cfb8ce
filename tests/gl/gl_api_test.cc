#include "gl/gl_api.h"

#include <dlfcn.h>

#include <cstdint>
#include <cstdlib>
#include <vector>

#include <gtest/gtest.h>

#include "gl/gl_context.h"

namespace vigil::gl {
namespace {

// Whether the process has loaded OSMesa (RTLD_NOLOAD: only a library already loaded is returned).
bool OsMesaLoaded() {
  void* library = dlopen(OsMesaLibrary(), RTLD_NOW | RTLD_NOLOAD);
  if (library == nullptr) return false;
  dlclose(library);  // NOLOAD counted a reference
  return true;
}

// In a freshly started process (the threadsafe death-test style starts the test binary again), so that no
// context another test made, in any order or repetition, has loaded OSMesa already. Exit status 1: loaded
// before any context (linked); 2: still not loaded after the first one.
TEST(GlApi, OsMesaIsLoadedWithTheFirstContextOnly) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  EXPECT_EXIT(
      {
        if (OsMesaLoaded()) std::_Exit(1);
        const GlContext context(/*samples=*/0);
        std::_Exit(OsMesaLoaded() ? 0 : 2);
      },
      ::testing::ExitedWithCode(0), "")
      << "1: " << OsMesaLibrary()
      << " is loaded before any context (it is linked); 2: not after the first one";
}

TEST(GlApi, TheLoadedFunctionsDraw) {
  GlContext context(/*samples=*/0);
  context.BeginFrame(4, 2, 0.0f, 0.0f, 0.0f);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0.0, 4.0, 2.0, 0.0, -1.0, 1.0);  // pixels, y down
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glColor3f(1.0f, 1.0f, 1.0f);
  glBegin(GL_TRIANGLES);  // the left half: columns 0 and 1
  glVertex2d(0.0, 0.0);
  glVertex2d(2.0, 0.0);
  glVertex2d(2.0, 2.0);
  glVertex2d(0.0, 0.0);
  glVertex2d(2.0, 2.0);
  glVertex2d(0.0, 2.0);
  glEnd();
  const std::vector<uint8_t> rgba = context.EndFrame();
  ASSERT_EQ(rgba.size(), 4u * 2u * 4u);
  for (int row = 0; row < 2; ++row)
    for (int column = 0; column < 4; ++column)
      EXPECT_EQ(rgba[(row * 4 + column) * 4], column < 2 ? 255 : 0) << "row " << row << ", column " << column;
}

}  // namespace
}  // namespace vigil::gl
