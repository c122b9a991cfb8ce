// Where `vigil` finds the shipped configs/ (the default sweep of `vigil paper`).
//
// Installed (`cmake --install build --prefix P`): P/share/vigil/configs, found relative to the running binary
// P/bin/vigil (its path from /proc/self/exe), so an installed tree can be moved as a whole. In the build tree
// (the binary cmake built, still in its build directory): the source tree's configs/. Anything else (a binary
// copied on its own) has no configs: `vigil paper --sweep FILE` names the sweep explicitly.
#pragma once

#include <filesystem>
#include <string>

namespace vigil::app {

// The configs directory for the binary at `executable` (see above); empty when there is none.
std::filesystem::path ConfigDirectoryOf(const std::filesystem::path& executable);

// `name` inside the running binary's configs directory; InputError naming what was searched when missing.
std::string ShippedConfig(const std::string& name);

}  // namespace vigil::app
