#include "experiments/slurm_job.h"

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
  EXPECT_NE(InputErrorOf([&] { MakeSlurmScripts(o); }).find("--tasks 0: must be at least 1"),
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

TEST(SlurmJob, ShellQuoteKeepsEveryWordOneWord) {
  EXPECT_EQ(ShellQuote("/a/b-c_d.yaml"), "/a/b-c_d.yaml");
  EXPECT_EQ(ShellQuote("a b"), "'a b'");
  EXPECT_EQ(ShellQuote("it's"), "'it'\\''s'");
  EXPECT_EQ(ShellQuote("$HOME"), "'$HOME'");
  EXPECT_EQ(ShellQuote(""), "''");
}

}  // namespace
}  // namespace vigil::experiments
