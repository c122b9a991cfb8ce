#include "core/recording_files.h"

#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "core/error.h"
#include "core/output.h"
#include "tests/core/test_util.h"

namespace vigil {
namespace {
namespace fs = std::filesystem;
using testing::InputErrorOf;
using testing::TempDir;

void Touch(const fs::path& file) {
  fs::create_directories(file.parent_path());
  std::ofstream(file) << "x\n";
}

// A EuRoC folder whose image folder is a link to `images`, with links out of the recording and loops beside
// its own files.
fs::path LinkedRecording(const TempDir& tmp, const fs::path& images) {
  const fs::path rec = tmp.path() / "rec";
  Touch(rec / "mav0" / "imu0" / "data.csv");
  Touch(rec / "mav0" / "cam0" / "data.csv");
  Touch(rec / "mav0" / "cam0" / "sensor.yaml");
  Touch(rec / "features.csv");
  Touch(rec / "notes.txt");
  fs::create_directories(images);
  Touch(images / "1.png");
  fs::create_directory_symlink(images, rec / "mav0" / "cam0" / "data");
  fs::create_directory_symlink("/usr", rec / "mav0" / "usr_link");
  fs::create_directory_symlink("..", rec / "mav0" / "loop");
  fs::create_directory_symlink(".", rec / "loop");
  fs::create_symlink("self", rec / "mav0" / "imu0" / "self");
  return rec;
}

TEST(RecordingFiles, KnownEntriesAreLookedUpByNameAndNothingElseIsEntered) {
  TempDir tmp;
  const fs::path rec = LinkedRecording(tmp, tmp.path() / "images");
  std::vector<std::string> paths;
  for (const RecordingEntry& e : RecordingEntries(rec)) paths.push_back(e.path);
  EXPECT_EQ(paths,
            (std::vector<std::string>{"features.csv", "mav0", "mav0/imu0", "mav0/imu0/data.csv", "mav0/cam0",
                                      "mav0/cam0/data.csv", "mav0/cam0/sensor.yaml", "mav0/cam0/data"}));
  EXPECT_EQ(RecordingEntries(rec).back().kind, RecordingEntry::Kind::kImageFolder);
  EXPECT_EQ(EntriesOutsideRecording(rec),
            (std::vector<std::string>{"loop", "mav0/imu0/self", "mav0/loop", "mav0/usr_link", "notes.txt"}));
}

TEST(RecordingFiles, AnOutputInsideALinkedImageFolderIsRefused) {
  TempDir tmp;
  const fs::path images = tmp.path() / "images";
  const fs::path rec = LinkedRecording(tmp, images);
  const std::string why =
      InputErrorOf([&] { RefuseOutputOverInputs(images / "sub", RecordingInputPaths(rec)); });
  EXPECT_NE(why.find("the output lies inside the input " + (rec / "mav0" / "cam0" / "data").string() + " (" +
                     fs::canonical(images).string() + ")"),
            std::string::npos)
      << why;
  // An output beside the recording is fine.
  EXPECT_EQ(InputErrorOf([&] { RefuseOutputOverInputs(tmp.path() / "out", RecordingInputPaths(rec)); }), "");
}

}  // namespace
}  // namespace vigil
