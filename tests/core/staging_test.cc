#include "core/staging.h"

#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include "core/output.h"
#include "tests/core/test_util.h"

namespace vigil {
namespace {
namespace fs = std::filesystem;
using testing::TempDir;

// The id of a process that has exited and been reaped: certainly dead (until the id is reused).
long DeadPid() {
  const pid_t child = ::fork();
  if (child == 0) ::_exit(0);
  int status = 0;
  ::waitpid(child, &status, 0);
  return child;
}

std::string Name(const std::string& final_name, const std::string& host, long pid) {
  return final_name + ".tmp-" + host + "-" + std::to_string(pid);
}

TEST(Staging, NamesCarryTheHostAndThePidAndParseBack) {
  const std::string mine = StagingPathFor("runs/a-dtw-s001").filename().string();
  EXPECT_EQ(mine, "a-dtw-s001" + StagingSuffix());
  const auto parsed = ParseStagingName(mine);
  ASSERT_TRUE(parsed);
  EXPECT_EQ(parsed->final_name, "a-dtw-s001");
  EXPECT_EQ(parsed->host, StagingHost());
  EXPECT_EQ(parsed->pid, static_cast<long>(::getpid()));
  // Host names may contain '-', run ids '-' and '.': the pid is after the last '-', the host before it.
  const auto dashed = ParseStagingName("noise_0.5-dtw-s003.tmp-node-07.lab-4242");
  ASSERT_TRUE(dashed);
  EXPECT_EQ(dashed->final_name, "noise_0.5-dtw-s003");
  EXPECT_EQ(dashed->host, "node-07.lab");
  EXPECT_EQ(dashed->pid, 4242);
}

TEST(Staging, OtherNamesAreNotStaging) {
  for (const char* name : {"results.csv", "x.tmp-dtw-s001", "run5.tmp-99999", ".tmp-host-1", "a.tmp--12",
                           "a.tmp-host-", "a.tmp-host-12x"})
    EXPECT_FALSE(ParseStagingName(name)) << name;
}

TEST(Staging, OnlyTheStagingOfADeadProcessOnThisHostIsStale) {
  const long dead = DeadPid();
  EXPECT_TRUE(IsStaleStaging(Name("results.csv", StagingHost(), dead)));
  EXPECT_FALSE(IsStaleStaging(Name("results.csv", StagingHost(), ::getpid())));  // alive: this process
  EXPECT_FALSE(IsStaleStaging(Name("results.csv", StagingHost(), 1)));           // alive: init
  EXPECT_FALSE(IsStaleStaging(Name("results.csv", StagingHost() + "x", dead)));  // another host
  EXPECT_FALSE(IsStaleStaging("run5.tmp-" + std::to_string(dead)));              // no host: unknown
}

TEST(Staging, RemoveStaleStagingKeepsLiveOtherHostAndFinishedEntries) {
  TempDir tmp;
  const long dead = DeadPid();
  const fs::path dead_run = tmp.path() / Name("run1", StagingHost(), dead);
  const fs::path dead_csv = tmp.path() / Name("results.csv", StagingHost(), dead);
  const fs::path live = tmp.path() / Name("run2", StagingHost(), ::getpid());
  const fs::path remote = tmp.path() / Name("run3", "elsewhere", dead);
  fs::create_directories(dead_run / "sub");
  tmp.File(dead_csv.filename().string(), "partial");
  fs::create_directories(live);
  fs::create_directories(remote);
  fs::create_directories(tmp.path() / "run0");
  EXPECT_EQ(RemoveStaleStaging(tmp.path(), "run1"), 1u);  // only the staging of that name
  EXPECT_FALSE(fs::exists(dead_run));
  EXPECT_TRUE(fs::exists(dead_csv));
  EXPECT_EQ(RemoveStaleStaging(tmp.path()), 1u);
  EXPECT_FALSE(fs::exists(dead_csv));
  EXPECT_TRUE(fs::exists(live));
  EXPECT_TRUE(fs::exists(remote));
  EXPECT_TRUE(fs::exists(tmp.path() / "run0"));
}

TEST(Staging, StagedDirectoryRemovesTheStaleStagingOfItsOutput) {
  TempDir tmp;
  const long dead = DeadPid();
  const fs::path stale = tmp.path() / Name("out", StagingHost(), dead);
  const fs::path other = tmp.path() / Name("other", StagingHost(), dead);
  fs::create_directories(stale);
  fs::create_directories(other);
  StagedDirectory staged(tmp.path() / "out", false);
  EXPECT_FALSE(fs::exists(stale));
  EXPECT_TRUE(fs::exists(other));  // another output's leftovers: not this command's business
  staged.Commit();
}

TEST(Staging, WriteFileAtomicRemovesTheStaleStagingOfItsFile) {
  TempDir tmp;
  const long dead = DeadPid();
  const std::string stale = Name("templates.yaml", StagingHost(), dead);
  const std::string live = Name("templates.yaml", StagingHost(), 1);
  tmp.File(stale, "half");
  tmp.File(live, "being written");
  WriteFileAtomic(tmp.path() / "templates.yaml", "whole\n");
  EXPECT_EQ(ReadFile(tmp.path() / "templates.yaml"), "whole\n");
  EXPECT_FALSE(fs::exists(tmp.path() / stale));
  EXPECT_TRUE(fs::exists(tmp.path() / live));
}

}  // namespace
}  // namespace vigil
