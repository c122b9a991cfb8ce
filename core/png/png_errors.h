// libpng's error callbacks for vigil's PNG writer (png_encode.h) and the figures' reader (plots/image.cc).
// libpng reports an error by calling the error callback, which must not return: it records the message and
// longjmps back to the setjmp of the calling function, which then throws (exceptions must not cross libpng's
// C code).
#pragma once

#include <png.h>

#include <string>

namespace vigil::png_errors {

// Records `message` as this thread's last libpng error and longjmps to the caller's setjmp.
[[noreturn]] void RecordAndJump(png_structp png, png_const_charp message);
// Warnings are dropped: libpng never prints on stderr.
void Ignore(png_structp png, png_const_charp message);
// The message RecordAndJump recorded last on this thread.
const std::string& Last();

}  // namespace vigil::png_errors
