#include "core/output.h"

#include <gtest/gtest.h>

#include "tests/core/test_util.h"

namespace vigil {
namespace {
namespace fs = std::filesystem;
using testing::InputErrorOf;
using testing::TempDir;

TEST(Output, StagedDirectoryAppearsOnlyOnCommit) {
  TempDir tmp;
  const fs::path out = tmp.path() / "out";
  {
    StagedDirectory staged(out, /*force=*/false);
    WriteFileAtomic(staged.path() / "a.txt", "hello");
    EXPECT_FALSE(fs::exists(out));
    staged.Commit();
  }
  EXPECT_EQ(ReadFile(out / "a.txt"), "hello");
  EXPECT_EQ(std::distance(fs::directory_iterator(tmp.path()), fs::directory_iterator()), 1);
}

TEST(Output, AbandonedStagingLeavesNothingBehind) {
  TempDir tmp;
  const fs::path out = tmp.path() / "out";
  {
    StagedDirectory staged(out, false);
    WriteFileAtomic(staged.path() / "a.txt", "partial");
  }  // no Commit: e.g. an exception unwound
  EXPECT_FALSE(fs::exists(out));
  EXPECT_TRUE(fs::is_empty(tmp.path()));
}

TEST(Output, NonEmptyDirectoryIsRefusedUnlessForced) {
  TempDir tmp;
  const fs::path out = tmp.path() / "out";
  fs::create_directories(out);
  WriteFileAtomic(out / "mine.txt", "precious");
  EXPECT_EQ(InputErrorOf([&] { StagedDirectory s(out, false); }),
            out.string() + ": output directory is not empty (use --force to replace it)");
  EXPECT_EQ(ReadFile(out / "mine.txt"), "precious");
  {
    StagedDirectory staged(out, /*force=*/true);
    WriteFileAtomic(staged.path() / "new.txt", "x");
    EXPECT_TRUE(fs::exists(out / "mine.txt"));  // still there until commit
    staged.Commit();
  }
  EXPECT_FALSE(fs::exists(out / "mine.txt"));
  EXPECT_TRUE(fs::exists(out / "new.txt"));
}

TEST(Output, AFileInTheWayIsRefusedEvenWhenForced) {
  TempDir tmp;
  const fs::path out = tmp.path() / "file";
  WriteFileAtomic(out, "x");
  EXPECT_EQ(InputErrorOf([&] { StagedDirectory s(out, true); }),
            out.string() + ": exists and is not a directory");
}

TEST(Output, WriteFileAtomicNeverReplacesANonRegularFile) {
  TempDir tmp;
  const fs::path dir = tmp.path() / "a_directory";
  fs::create_directory(dir);
  EXPECT_EQ(InputErrorOf([&] { WriteFileAtomic(dir, "x"); }),
            dir.string() + ": exists and is not a regular file; refusing to replace it");
  EXPECT_TRUE(fs::is_directory(dir));
  EXPECT_FALSE(InputErrorOf([&] { WriteFileAtomic("/dev/null", "x"); }).empty());
  EXPECT_TRUE(fs::is_character_file("/dev/null"));
}

}  // namespace
}  // namespace vigil
