// Shared by the libFuzzer targets: the readers take paths, so each input is written to a file in a private
// temporary directory first; bad input must end in vigil::InputError, anything else (another exception, a
// crash, a leak, a hang) is a finding.
#pragma once

#include <stdlib.h>
#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <string>

#include "core/error.h"

namespace vigil::fuzz {

// A temporary directory for this process, removed at exit.
inline const std::filesystem::path& WorkDir() {
  static const std::filesystem::path dir = [] {
    std::string pattern = (std::filesystem::temp_directory_path() / "vigil_fuzz_XXXXXX").string();
    if (!::mkdtemp(pattern.data())) std::abort();
    static const std::string keep = pattern;
    std::atexit([] {
      std::error_code ec;
      std::filesystem::remove_all(keep, ec);
    });
    return std::filesystem::path(pattern);
  }();
  return dir;
}

// Writes `data` to WorkDir()/name and returns the path.
inline std::string WriteInput(const std::string& name, const uint8_t* data, size_t size) {
  const std::string path = (WorkDir() / name).string();
  std::FILE* f = std::fopen(path.c_str(), "wb");
  if (!f) std::abort();
  if (size && std::fwrite(data, 1, size, f) != size) std::abort();
  std::fclose(f);
  return path;
}

// Runs `read`; InputError is the expected outcome of bad input, any other exception is a finding.
template <class F>
void ExpectOnlyInputErrors(F&& read) {
  try {
    read();
  } catch (const InputError& e) {
    // Every message is one printable line.
    for (const char* c = e.what(); *c; ++c)
      if (*c == '\n' || static_cast<unsigned char>(*c) < 0x20) std::abort();
  } catch (const std::exception& e) {
    std::fprintf(stderr, "not an InputError: %s\n", e.what());
    std::abort();
  }
}

}  // namespace vigil::fuzz
