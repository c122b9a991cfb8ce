#include "core/png/png_errors.h"

namespace vigil::png_errors {
namespace {
thread_local std::string g_last;
}  // namespace

void RecordAndJump(png_structp png, png_const_charp message) {
  g_last = message;
  png_longjmp(png, 1);
}

void Ignore(png_structp, png_const_charp) {}

const std::string& Last() { return g_last; }

}  // namespace vigil::png_errors
