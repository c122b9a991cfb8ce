#include "core/output.h"

#include <sys/stat.h>

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
  {
    StagedDirectory staged(out, false);
    WriteFileAtomic(staged.path() / "old.txt", "vigil's");
    staged.Commit();
  }
  EXPECT_EQ(
      InputErrorOf([&] { StagedDirectory s(out, false); }),
      out.string() + ": output directory is not empty (use --force to replace a directory vigil wrote)");
  {
    StagedDirectory staged(out, /*force=*/true);
    WriteFileAtomic(staged.path() / "new.txt", "x");
    EXPECT_TRUE(fs::exists(out / "old.txt"));  // still there until commit
    staged.Commit();
  }
  EXPECT_FALSE(fs::exists(out / "old.txt"));
  EXPECT_TRUE(fs::exists(out / "new.txt"));
}

TEST(Output, CommittedDirectoryCarriesAManifestOfWhatVigilWrote) {
  TempDir tmp;
  const fs::path out = tmp.path() / "out";
  StagedDirectory staged(out, false);
  WriteFileAtomic(staged.path() / "b.txt", "b");
  WriteFileAtomic(staged.path() / "a.txt", "a");
  staged.Commit();
  EXPECT_EQ(ReadFile(out / kOutputManifest), std::string(kOutputManifestHeader) + "\na.txt\t" +
                                                 EntryFingerprint(out / "a.txt") + "\nb.txt\t" +
                                                 EntryFingerprint(out / "b.txt") + "\n");
  EXPECT_EQ(ReadOutputManifest(out), (std::vector<std::string>{"a.txt", "b.txt"}));
}

TEST(Output, ForceRefusesADirectoryVigilDidNotWrite) {
  TempDir tmp;
  const fs::path out = tmp.path() / "out";
  fs::create_directories(out);
  WriteFileAtomic(out / "mine.txt", "precious");
  const std::string error = InputErrorOf([&] { StagedDirectory s(out, /*force=*/true); });
  EXPECT_NE(error.find("not written by vigil (no .vigil-output)"), std::string::npos) << error;
  EXPECT_EQ(ReadFile(out / "mine.txt"), "precious");
  WriteFileAtomic(out / kOutputManifest, "something else\nmine.txt\n");  // not vigil's manifest
  EXPECT_NE(InputErrorOf([&] { StagedDirectory s(out, true); }).find("not a vigil manifest"),
            std::string::npos);
  EXPECT_EQ(ReadFile(out / "mine.txt"), "precious");
}

TEST(Output, ForceKeepsEntriesAForgedOrStaleManifestLists) {
  TempDir tmp;
  const fs::path out = tmp.path() / "out";
  fs::create_directories(out / "photos");
  WriteFileAtomic(out / "photos" / "a.jpg", "precious");
  WriteFileAtomic(out / "notes.txt", "precious");
  // Names without fingerprints, a wrong fingerprint, a path outside the directory: none is vigil's.
  WriteFileAtomic(
      out / kOutputManifest,
      std::string(kOutputManifestHeader) + "\nphotos\nnotes.txt\tfile 8 0000000000000000\n../x\tfile 1 0\n");
  EXPECT_TRUE(ReadOutputManifest(out).empty());
  {
    StagedDirectory staged(out, true);
    WriteFileAtomic(staged.path() / "result.txt", "new");
    staged.Commit();
  }
  EXPECT_EQ(ReadFile(out / "photos" / "a.jpg"), "precious");
  EXPECT_EQ(ReadFile(out / "notes.txt"), "precious");
  // An entry vigil wrote and that changed since is kept too.
  WriteFileAtomic(out / "result.txt", "edited by hand");
  {
    StagedDirectory staged(out, true);
    WriteFileAtomic(staged.path() / "other.txt", "new");
    staged.Commit();
  }
  EXPECT_EQ(ReadFile(out / "result.txt"), "edited by hand");
}

TEST(Output, ForceKeepsFilesVigilDidNotWrite) {
  TempDir tmp;
  const fs::path out = tmp.path() / "out";
  {
    StagedDirectory staged(out, false);
    WriteFileAtomic(staged.path() / "result.txt", "old");
    staged.Commit();
  }
  WriteFileAtomic(out / "notes.txt", "mine");  // added by the user afterwards
  fs::create_directory(out / "my_dir");
  {
    StagedDirectory staged(out, true);
    WriteFileAtomic(staged.path() / "result.txt", "new");
    staged.Commit();
  }
  EXPECT_EQ(ReadFile(out / "result.txt"), "new");
  EXPECT_EQ(ReadFile(out / "notes.txt"), "mine");
  EXPECT_TRUE(fs::is_directory(out / "my_dir"));
  EXPECT_EQ(ReadOutputManifest(out), std::vector<std::string>{"result.txt"});  // still not vigil's
  EXPECT_EQ(std::distance(fs::directory_iterator(tmp.path()), fs::directory_iterator()), 1);  // no leftovers
}

TEST(Output, ForceRefusesWhenAUserFileHasTheNameOfANewOutput) {
  TempDir tmp;
  const fs::path out = tmp.path() / "out";
  {
    StagedDirectory staged(out, false);
    WriteFileAtomic(staged.path() / "a.txt", "a");
    staged.Commit();
  }
  WriteFileAtomic(out / "b.txt", "mine");
  {
    StagedDirectory staged(out, true);
    WriteFileAtomic(staged.path() / "b.txt", "vigil's");
    EXPECT_NE(InputErrorOf([&] { staged.Commit(); }).find("b.txt: not written by vigil and in the way"),
              std::string::npos);
  }
  EXPECT_EQ(ReadFile(out / "b.txt"), "mine");
  EXPECT_EQ(ReadFile(out / "a.txt"), "a");
  EXPECT_EQ(std::distance(fs::directory_iterator(tmp.path()), fs::directory_iterator()), 1);
}

TEST(Output, OutputThatIsContainsOrLiesInsideAnInputIsRefused) {
  TempDir tmp;
  const fs::path in = tmp.path() / "in";
  fs::create_directories(in / "sub");
  const fs::path file = in / "data.csv";
  WriteFileAtomic(file, "x");
  const auto refused = [&](const fs::path& out, const fs::path& input) {
    return InputErrorOf([&] { RefuseOutputOverInputs(out, {input}); });
  };
  EXPECT_NE(refused(in, in).find("the output is the input"), std::string::npos);
  EXPECT_NE(refused(in / "sub" / "..", in).find("is the input"), std::string::npos);
  EXPECT_NE(refused(in.string() + "/", in).find("is the input"), std::string::npos);
  EXPECT_NE(refused(in / "new", in).find("lies inside the input"), std::string::npos);
  EXPECT_NE(refused(file, file).find("is the input"), std::string::npos);
  EXPECT_NE(refused(tmp.path(), file).find("contains the input"), std::string::npos);
  fs::create_directory_symlink(in, tmp.path() / "link");
  EXPECT_NE(refused(tmp.path() / "link", in).find("is the input"), std::string::npos);
  EXPECT_NE(refused(tmp.path() / "link" / "x", in).find("lies inside"), std::string::npos);
  EXPECT_NE(refused(in, tmp.path() / "link" / "data.csv").find("contains the input"), std::string::npos);
  EXPECT_EQ(refused(tmp.path() / "out", in), "");
  EXPECT_EQ(refused(tmp.path() / "in2", in), "");  // a common prefix is not containment
  EXPECT_EQ(refused(in, tmp.path() / "missing"), "");
  EXPECT_EQ(refused(in, ""), "");
}

TEST(Output, ReplacingAFileRequiresForceAndAFileVigilWrote) {
  TempDir tmp;
  const fs::path out = tmp.path() / "lib.yaml";
  EXPECT_EQ(InputErrorOf([&] { RefuseReplacingFile(out, false, "# vigil"); }), "");
  WriteFileAtomic(out, "# vigil thing\n");
  EXPECT_NE(InputErrorOf([&] { RefuseReplacingFile(out, false, "# vigil"); }).find("use --force"),
            std::string::npos);
  EXPECT_EQ(InputErrorOf([&] { RefuseReplacingFile(out, true, "# vigil"); }), "");
  WriteFileAtomic(out, "user data\n");
  EXPECT_NE(InputErrorOf([&] { RefuseReplacingFile(out, true, "# vigil"); }).find("not a file vigil wrote"),
            std::string::npos);
  EXPECT_NE(
      InputErrorOf([&] { RefuseReplacingFile(tmp.path(), true, "# vigil"); }).find("not a regular file"),
      std::string::npos);
}

TEST(Output, OnlyRegularFilesAreRead) {
  TempDir tmp;
  EXPECT_NE(InputErrorOf([&] { ReadFile(tmp.path()); }).find("is a directory"), std::string::npos);
  const fs::path fifo = tmp.path() / "fifo";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  EXPECT_NE(InputErrorOf([&] { ReadFile(fifo); }).find("not a regular file"), std::string::npos);  // no hang
  EXPECT_NE(InputErrorOf([&] { ReadFile("/dev/zero"); }).find("not a regular file"), std::string::npos);
  EXPECT_NE(InputErrorOf([&] { ReadFile(tmp.path() / "missing"); }).find("no such file"), std::string::npos);
  WriteFileAtomic(tmp.path() / "big", std::string(100, 'x'));
  EXPECT_NE(InputErrorOf([&] { ReadFile(tmp.path() / "big", 99); }).find("larger than the limit of 99 bytes"),
            std::string::npos);
  EXPECT_EQ(ReadFile(tmp.path() / "big", 100).size(), 100u);
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
