// `vigil-eval` is `vigil eval` linked against the evaluation library and core/ only: its dynamic
// dependencies hold no OpenCV, oneTBB, Ceres, OSMesa or glog, it holds no code of the libraries further down
// the data flow, and it prints what `vigil eval` prints.
#include <regex>
#include <set>
#include <string>

#include <gtest/gtest.h>

#include "tests/app/vigil_cli.h"

namespace vigil::testing {
namespace {

// The shared libraries `binary` names directly (readelf -d: NEEDED), e.g. "libyaml-cpp.so.0.7".
std::set<std::string> NeededLibraries(const std::string& binary) {
  const ShellOutput r = RunShell("readelf -d " + binary);
  EXPECT_EQ(r.status, 0) << "readelf failed on " << binary;
  std::set<std::string> needed;
  const std::regex entry(R"(\(NEEDED\)\s+Shared library: \[([^\]]+)\])");
  for (std::sregex_iterator it(r.out.begin(), r.out.end(), entry), end; it != end; ++it)
    needed.insert((*it)[1]);
  return needed;
}

const std::string kData = std::string(VIGIL_SOURCE_DIR) + "/tests/evaluation/data/";

TEST(VigilEval, NeedsOnlyTheLibrariesOfCore) {
  const std::set<std::string> eval = NeededLibraries(VIGIL_EVAL_BINARY);
  ASSERT_FALSE(eval.empty());
  // core/ links yaml-cpp; Eigen, CLI11 and nlohmann-json are header-only.
  const std::regex allowed(R"(lib(yaml-cpp|stdc\+\+|m|gcc_s|c)\.so.*|ld-linux.*)");
  for (const std::string& lib : eval) EXPECT_TRUE(std::regex_match(lib, allowed)) << lib;
  // The check can fail: vigil itself needs what vigil-eval must not.
  const std::set<std::string> vigil = NeededLibraries(VIGIL_BINARY);
  const std::regex heavy(R"(lib(opencv|tbb|ceres|OSMesa|glog).*)");
  std::size_t heavy_in_vigil = 0;
  for (const std::string& lib : vigil) heavy_in_vigil += std::regex_match(lib, heavy);
  EXPECT_GT(heavy_in_vigil, 0u);
}

TEST(VigilEval, HoldsNoCodeOfTheLibrariesDownTheDataFlow) {
  const ShellOutput symbols = RunShell("nm -C --defined-only " + std::string(VIGIL_EVAL_BINARY));
  ASSERT_EQ(symbols.status, 0);
  EXPECT_NE(symbols.out.find("vigil::evaluation::EvaluateTrajectory"), std::string::npos);
  for (const char* ns : {"vigil::sim::", "vigil::frontend::", "vigil::detectors::", "vigil::estimator::",
                         "vigil::experiments::", "vigil::report::", "vigil::plots::"})
    EXPECT_EQ(symbols.out.find(ns), std::string::npos) << ns;
}

TEST(VigilEval, PrintsWhatVigilEvalPrints) {
  const std::string files = " " + kData + "rpg_pair_gt.txt " + kData + "rpg_pair_est.txt";
  for (const std::string flags : {"", " --json", " --align se3 --distances 2,4"}) {
    const ShellOutput alone = RunShell(std::string(VIGIL_EVAL_BINARY) + files + flags + " 2>/dev/null");
    const ShellOutput sub = RunShell(std::string(VIGIL_BINARY) + " eval" + files + flags + " 2>/dev/null");
    EXPECT_EQ(alone.status, 0) << flags;
    EXPECT_EQ(sub.status, 0) << flags;
    EXPECT_FALSE(alone.out.empty()) << flags;
    EXPECT_EQ(alone.out, sub.out) << flags;
  }
  // Bad input: the same one-line message and exit status 2.
  const std::string bad = files + " --align bogus 2>&1";
  const ShellOutput alone = RunShell(std::string(VIGIL_EVAL_BINARY) + bad);
  const ShellOutput sub = RunShell(std::string(VIGIL_BINARY) + " eval" + bad);
  EXPECT_EQ(alone.status, 2);
  EXPECT_EQ(sub.status, 2);
  EXPECT_EQ(alone.out, "vigil: error: --align: unknown alignment 'bogus'\n");
  EXPECT_EQ(alone.out, sub.out);
}

}  // namespace
}  // namespace vigil::testing
