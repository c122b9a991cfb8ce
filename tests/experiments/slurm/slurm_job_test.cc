#include "experiments/slurm/slurm_job.h"

#include <gtest/gtest.h>

#include "tests/core/test_util.h"

namespace vigil::experiments {
namespace {
using vigil::testing::InputErrorOf;

SlurmJobOptions Job() {
  SlurmJobOptions o;
  o.vigil = "/opt/vigil/bin/vigil";
  o.dir = "/shared/out/ci";
  o.sweep_arguments = {"sweep", "/shared/configs/ci sweep.yaml"};
  o.tasks = 3;
  o.cpus_per_task = 2;
  o.job_name = "vigil-ci";
  return o;
}

TEST(SlurmJob, ArrayScriptRunsOneShardPerTaskWithTheShardCountWrittenIn) {
  SlurmJobOptions o = Job();
  o.partition = "short";
  o.time = "0:30:00";
  const SlurmScripts s = MakeSlurmScripts(o);
  for (const char* line :
       {"#SBATCH --array=0-2\n", "#SBATCH --cpus-per-task=2\n", "#SBATCH --partition=short\n",
        "#SBATCH --time=0:30:00\n", "#SBATCH --output=/shared/out/ci/slurm/%A_%a.log\n",
        "#SBATCH --requeue\n", "shards=3\n"})
    EXPECT_NE(s.array.find(line), std::string::npos) << line;
  EXPECT_NE(s.array.find("exec /opt/vigil/bin/vigil sweep '/shared/configs/ci sweep.yaml' -o /shared/out/ci "
                         "--shard \"${SLURM_ARRAY_TASK_ID}/${shards}\" --resume -j 2\n"),
            std::string::npos)
      << s.array;
  EXPECT_EQ(s.array.find("SLURM_ARRAY_TASK_COUNT}"), std::string::npos);  // never read from the environment
  EXPECT_NE(s.finalize.find("exec /opt/vigil/bin/vigil tables /shared/out/ci\n"), std::string::npos);
  EXPECT_NE(s.finalize.find("#SBATCH --output=/shared/out/ci/slurm/finalize_%j.log\n"), std::string::npos);
  EXPECT_NE(s.submit.find("--dependency=afterany:\"${array}\" /shared/out/ci/slurm/finalize.sbatch"),
            std::string::npos);
  EXPECT_EQ(MakeSlurmScripts(Job()).array.find("--partition"), std::string::npos);  // none given: none set
}

TEST(SlurmJob, BadOptionsAreRefused) {
  SlurmJobOptions o = Job();
  o.tasks = 0;
  EXPECT_NE(InputErrorOf([&] { MakeSlurmScripts(o); }).find("--tasks 0: must be in [1, 100000]"),
            std::string::npos);
  o = Job();
  o.cpus_per_task = 0;
  EXPECT_NE(InputErrorOf([&] { MakeSlurmScripts(o); }).find("--cpus-per-task"), std::string::npos);
  o = Job();
  o.time = "1 day";
  EXPECT_NE(InputErrorOf([&] { MakeSlurmScripts(o); }).find("--time"), std::string::npos);
  o = Job();
  o.dir = "/shared/my out";
  EXPECT_NE(InputErrorOf([&] { MakeSlurmScripts(o); }).find("may not contain spaces"), std::string::npos);
}

TEST(SlurmJob, TaskCountsAndTimesBeyondWhatSlurmTakesAreRefused) {
  SlurmJobOptions o = Job();
  o.tasks = 1000000;
  EXPECT_NE(InputErrorOf([&] { MakeSlurmScripts(o); }).find("--tasks 1000000: must be in [1, 100000]"),
            std::string::npos);
  for (const char* bad : {"abc", "1:2:3:4", "-5", "1-", "10:", "1-2:3:4:5", "12345"}) {
    o = Job();
    o.time = bad;
    EXPECT_NE(InputErrorOf([&] { MakeSlurmScripts(o); }).find("not a Slurm time limit"), std::string::npos)
        << bad;
  }
  for (const char* good : {"30", "30:00", "2:00:00", "1-0", "1-12:30", "1-12:30:00", "UNLIMITED"}) {
    o = Job();
    o.time = good;
    EXPECT_EQ(InputErrorOf([&] { MakeSlurmScripts(o); }), "") << good;
  }
}

TEST(SlurmJob, OnlyADigitJobIdIsTakenFromSbatch) {
  EXPECT_EQ(ParseSbatchJobId("1234\n"), "1234");
  EXPECT_EQ(ParseSbatchJobId("1234;cluster-a\n"), "1234");
  for (const char* bad : {"", "\n", "1$(touch /tmp/pwned)", "12 34", "abc", "1234;", "1234;a b", "1;x;y",
                          "Submitted batch job 1234", "1234\n5678"}) {
    try {
      ParseSbatchJobId(bad);
      ADD_FAILURE() << "accepted '" << bad << "'";
    } catch (const std::runtime_error& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find("not a job id"), std::string::npos) << what;
      EXPECT_EQ(what.find('\n'), std::string::npos) << what;
    }
  }
}

TEST(SlurmJob, SubmitScriptChecksEachJobIdBeforeUsingIt) {
  const SlurmScripts s = MakeSlurmScripts(Job());
  EXPECT_NE(s.submit.find("[[ \"${array}\" =~ ^[0-9]+$ ]] ||"), std::string::npos) << s.submit;
  EXPECT_NE(s.submit.find("[[ \"${finalize}\" =~ ^[0-9]+$ ]] ||"), std::string::npos) << s.submit;
  EXPECT_LT(s.submit.find("=~ ^[0-9]+$"), s.submit.find("--dependency"));
}

TEST(SlurmJob, ShellQuoteKeepsEveryWordOneWord) {
  EXPECT_EQ(ShellQuote("/a/b-c_d.yaml"), "/a/b-c_d.yaml");
  EXPECT_EQ(ShellQuote("a b"), "'a b'");
  EXPECT_EQ(ShellQuote("it's"), "'it'\\''s'");
  EXPECT_EQ(ShellQuote("$HOME"), "'$HOME'");
  EXPECT_EQ(ShellQuote(""), "''");
}

}  // namespace
}  // namespace vigil::experiments
