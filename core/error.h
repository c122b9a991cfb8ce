// Errors that vigil reports to the user.
//
// InputError: bad input (config, CSV, arguments). The message is one line that names the place
// ("file:line: key: reason"); the command line turns it into `vigil: error: ...` and exit status 2.
#pragma once

#include <stdexcept>
#include <string>
#include <string_view>

namespace vigil {

// `text` on one printable line: control characters (newline, tab, NUL, ...), DEL and bytes that are not
// valid UTF-8 become C-style escapes ("\n", "\t", "\x00", "\xff"), so that an error quoting a user's bytes
// never breaks the one-line format nor writes raw binary to a terminal.
std::string OneLine(std::string_view text);

class InputError : public std::runtime_error {
 public:
  explicit InputError(const std::string& message) : std::runtime_error(OneLine(message)) {}
};

// "file:line: message" (line is 1-based; line <= 0 leaves it out).
std::string Located(const std::string& file, int line, const std::string& message);

}  // namespace vigil
