// Errors that vigil reports to the user.
//
// InputError: bad input (config, CSV, arguments). The message is one line that names the place
// ("file:line: key: reason"); the command line turns it into `vigil: error: ...` and exit status 2.
#pragma once

#include <stdexcept>
#include <string>

namespace vigil {

class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// "file:line: message" (line is 1-based; line <= 0 leaves it out).
std::string Located(const std::string& file, int line, const std::string& message);

}  // namespace vigil
