// Number formatting shared by every file vigil writes.
//
// Doubles are written in their shortest round-trip form (std::to_chars): reading the text back gives the
// same double bit for bit, and the same value always gives the same bytes on any machine.
#pragma once

#include <string>

namespace vigil {

std::string FormatDouble(double value);
// Fixed-point with `decimals` digits after the point (e.g. seconds with 9 decimals in TUM files).
std::string FormatFixed(double value, int decimals);
// printf into a string (messages and summary lines; files use the two above).
std::string FormatPrintf(const char* format, ...) __attribute__((format(printf, 1, 2)));

// Parses a whole string as a finite double / integer; false on trailing characters, overflow or NaN/Inf.
bool ParseDouble(std::string_view text, double* value);
bool ParseInt64(std::string_view text, int64_t* value);

}  // namespace vigil
