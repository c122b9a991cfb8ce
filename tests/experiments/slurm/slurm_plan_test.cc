#include "experiments/slurm/slurm_plan.h"

#include <sys/stat.h>

#include <cstdlib>
#include <filesystem>

#include <gtest/gtest.h>

#include "core/output.h"
#include "tests/core/test_util.h"
#include "tests/experiments/sweeps/sweep_test_util.h"

namespace vigil::experiments {
namespace {
namespace fs = std::filesystem;
using vigil::testing::InputErrorOf;
using vigil::testing::TempDir;

// PATH set to one directory for the life of the object (the planner looks sbatch up there).
class ScopedPath {
 public:
  explicit ScopedPath(const fs::path& dir) : saved_(std::getenv("PATH") ? std::getenv("PATH") : "") {
    ::setenv("PATH", dir.c_str(), 1);
  }
  ~ScopedPath() { ::setenv("PATH", saved_.c_str(), 1); }

 private:
  std::string saved_;
};

SlurmRequest SlurmRequestIn(const TempDir& tmp) {
  SlurmRequest request;
  request.sweep = testing::WriteSmallSweep(tmp, "  original: none\n", "{count: 2, first: 1}");
  request.output = (tmp.path() / "out").string();
  request.tasks = 3;
  request.cpus_per_task = 2;
  request.vigil = "/opt/vigil/bin/vigil";
  return request;
}

TEST(PlanSlurmJob, PlansWithoutWritingThenWritesTheSweepFileAndScripts) {
  TempDir tmp;
  const fs::path no_sbatch = tmp.path() / "bin";
  fs::create_directories(no_sbatch);
  ScopedPath path(no_sbatch);
  const SlurmRequest request = SlurmRequestIn(tmp);
  const SlurmJobPlan plan = PlanSlurmJob(request);
  EXPECT_FALSE(fs::exists(request.output));  // planning writes nothing
  EXPECT_TRUE(plan.sbatch.empty());
  EXPECT_EQ(plan.runs, 2u * 2u);  // 2 glitch settings x 1 method x 2 seeds
  EXPECT_EQ(plan.job.dir, fs::absolute(request.output).lexically_normal());
  EXPECT_EQ(plan.job.job_name, "vigil-out");
  EXPECT_EQ(plan.job.sweep_arguments,
            (std::vector<std::string>{"sweep", fs::absolute(request.sweep).string()}));
  EXPECT_NE(plan.scripts.array.find("shards=3\n"), std::string::npos);

  WriteSlurmJob(plan);
  const fs::path slurm = fs::path(request.output) / "slurm";
  EXPECT_EQ(ReadFile(fs::path(request.output) / "sweep.yaml"), plan.resolved_sweep);
  for (const char* name : {"array.sbatch", "finalize.sbatch", "submit.sh"}) {
    struct stat st {};
    ASSERT_EQ(::stat((slurm / name).c_str(), &st), 0) << name;
    EXPECT_TRUE(st.st_mode & S_IXUSR) << name;
  }
  EXPECT_EQ(ReadFile(slurm / "array.sbatch"), plan.scripts.array);
  // Planned again over the directory of the same sweep: fine (the tasks resume it).
  EXPECT_EQ(PlanSlurmJob(request).runs, plan.runs);
}

TEST(PlanSlurmJob, RefusesBeforeAnythingIsWritten) {
  TempDir tmp;
  const fs::path no_sbatch = tmp.path() / "bin";
  fs::create_directories(no_sbatch);
  ScopedPath path(no_sbatch);
  SlurmRequest request = SlurmRequestIn(tmp);
  request.submit = true;
  EXPECT_NE(InputErrorOf([&] { PlanSlurmJob(request); }).find("--submit: sbatch is not on the PATH"),
            std::string::npos);
  request = SlurmRequestIn(tmp);
  request.paper = true;
  EXPECT_EQ(InputErrorOf([&] { PlanSlurmJob(request); }),
            "SWEEP: not with --paper (use --sweep to change the paper's sweep file)");
  request.sweep.clear();
  request.paper = false;
  EXPECT_EQ(InputErrorOf([&] { PlanSlurmJob(request); }), "SWEEP: required (a sweep file), or --paper");
  request = SlurmRequestIn(tmp);
  request.tasks = 0;
  EXPECT_NE(InputErrorOf([&] { PlanSlurmJob(request); }).find("--tasks 0"), std::string::npos);
  request = SlurmRequestIn(tmp);
  request.sweep = tmp.File("broken.yaml", "base: base.yaml\nnope: 1\n");
  EXPECT_NE(InputErrorOf([&] { PlanSlurmJob(request); }).find("broken.yaml:2"), std::string::npos);
  EXPECT_FALSE(fs::exists(request.output));
}

TEST(PlanSlurmJob, ThePaperTakesItsShippedSweepWithTheSeedCount) {
  TempDir tmp;
  ScopedPath path(tmp.path());
  SlurmRequest request = SlurmRequestIn(tmp);
  const std::string sweep = request.sweep;
  request.sweep.clear();
  request.paper = true;
  request.seeds = 1;
  request.shipped_paper_sweep = [&] { return sweep; };
  const SlurmJobPlan plan = PlanSlurmJob(request);
  EXPECT_EQ(plan.runs, 2u);  // one seed per cell
  EXPECT_EQ(plan.job.sweep_arguments,
            (std::vector<std::string>{"paper", "--sweep", fs::absolute(sweep).string(), "--seeds", "1"}));
  EXPECT_EQ(plan.job.tables_arguments, std::vector<std::string>{"--figures"});
}

TEST(SubmitSlurmJob, SubmitsTheArrayThenTheFinalizeJobDependingOnIt) {
  TempDir tmp;
  const fs::path bin = tmp.path() / "bin";
  fs::create_directories(bin);
  // A stand-in sbatch (shell builtins only: PATH holds nothing else): logs its arguments and prints a job id
  // as `sbatch --parsable` does, 101 for the first call, 102 for the second.
  const fs::path log = tmp.path() / "sbatch.log";
  const std::string sbatch = tmp.File("bin/sbatch", "#!/bin/sh\necho \"$@\" >> " + log.string() +
                                                        "\nn=0\nwhile read -r _; do n=$((n + 1)); done < " +
                                                        log.string() + "\necho \"$((100 + n));cluster\"\n");
  ::chmod(sbatch.c_str(), 0755);
  ScopedPath path(bin);
  SlurmRequest request = SlurmRequestIn(tmp);
  request.submit = true;
  const SlurmJobPlan plan = PlanSlurmJob(request);
  EXPECT_EQ(plan.sbatch, fs::path(sbatch));
  WriteSlurmJob(plan);
  const SlurmJobIds ids = SubmitSlurmJob(plan);
  EXPECT_EQ(ids.array, "101");
  EXPECT_EQ(ids.finalize, "102");
  const fs::path slurm = plan.job.dir / "slurm";
  EXPECT_EQ(ReadFile(log), "--parsable " + (slurm / "array.sbatch").string() + "\n--parsable " +
                               "--dependency=afterany:101 " + (slurm / "finalize.sbatch").string() + "\n");

  // An sbatch that fails: the error names the command and its exit status.
  tmp.File("bin/sbatch", "#!/bin/sh\nexit 3\n");
  try {
    SubmitSlurmJob(plan);
    ADD_FAILURE() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("failed (exit status 3)"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace vigil::experiments
