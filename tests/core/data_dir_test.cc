// Config paths under the user's data folder ($VIGIL_DATA/...).
#include "core/data_dir.h"

#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "tests/core/test_util.h"

namespace vigil {
namespace {

using testing::ScopedDataDir;

TEST(DataDir, OnlyALeadingVigilDataIsExpanded) {
  EXPECT_TRUE(NamesDataDir("$VIGIL_DATA/euroc/V1_01_easy"));
  EXPECT_TRUE(NamesDataDir("$VIGIL_DATA"));
  EXPECT_FALSE(NamesDataDir("$VIGIL_DATAX/a"));
  EXPECT_FALSE(NamesDataDir("data/$VIGIL_DATA/a"));
  EXPECT_FALSE(NamesDataDir(""));
  const ScopedDataDir set("/datasets/");
  EXPECT_EQ(ExpandDataDir("$VIGIL_DATA/euroc/V1_01_easy"), "/datasets/euroc/V1_01_easy");
  EXPECT_EQ(ExpandDataDir("$VIGIL_DATA"), "/datasets/");
  EXPECT_EQ(ExpandDataDir("../data/euroc"), "../data/euroc");
  EXPECT_EQ(UnsetDataDirReason("$VIGIL_DATA/euroc"), "");
}

TEST(DataDir, ARelativeVigilDataIsRelativeToTheWorkingDirectory) {
  const ScopedDataDir set("sets");
  EXPECT_EQ(ExpandDataDir("$VIGIL_DATA/a"), (std::filesystem::current_path() / "sets/a").string());
}

TEST(DataDir, AnInputPathIsResolvedAgainstItsBase) {
  const ScopedDataDir set("/datasets");
  EXPECT_EQ(ResolveInputPath("/configs", "../data/gt.csv"), "/data/gt.csv");
  EXPECT_EQ(ResolveInputPath("/configs", "/abs/gt.csv"), "/abs/gt.csv");
  EXPECT_EQ(ResolveInputPath("/configs", ""), "");
  EXPECT_EQ(ResolveInputPath("/configs", "$VIGIL_DATA/euroc"), "/datasets/euroc");
  const ScopedDataDir unset(nullptr);
  EXPECT_EQ(ResolveInputPath("/configs", "$VIGIL_DATA/euroc"), "$VIGIL_DATA/euroc");
}

TEST(DataDir, UnsetOrEmptyItIsRefusedWithTheVariablesName) {
  for (const char* value : {static_cast<const char*>(nullptr), ""}) {
    const ScopedDataDir unset(value);
    EXPECT_EQ(ExpandDataDir("$VIGIL_DATA/euroc"), "$VIGIL_DATA/euroc");
    EXPECT_EQ(
        UnsetDataDirReason("$VIGIL_DATA/euroc"),
        "$VIGIL_DATA/euroc names $VIGIL_DATA, which is not set: export VIGIL_DATA=the folder that holds "
        "your datasets (docs/datasets.md)");
    EXPECT_EQ(UnsetDataDirReason("relative/euroc"), "");
  }
}

}  // namespace
}  // namespace vigil
