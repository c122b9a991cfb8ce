// vigil's estimator through the external path equals the built-in method, byte for byte: a small sweep with
// both, `vigil estimate` as the external command, compared run by run.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "core/output.h"
#include "tests/app/vigil_cli.h"

namespace vigil {
namespace {
namespace fs = std::filesystem;
using testing::TempDir;
using testing::Vigil;

TEST(ExternalIdentity, VigilEstimateAsAnExternalCommandEqualsTheBuiltInMethod) {
  TempDir tmp;
  const std::string sweep =
      tmp.File("compare.yaml",
               "base: " + std::string(VIGIL_SOURCE_DIR) +
                   "/configs/paper.yaml\n"
                   "set: {duration_s: 4, glitch.enabled: true, estimator.solver.max_time_s: 0}\n"
                   "axes:\n  glitch:\n    noise_50_10: {mean: 50, std: 10}\n"
                   "methods:\n"
                   "  builtin_trunc: threshold\n"
                   "  builtin_original: none\n"
                   "  ext_trunc:\n    type: threshold\n    estimator.backend: external\n"
                   "    estimator.external: &e\n"
                   "      command: [\"{vigil}\", estimate, \"{recording}\", -o, \"{output}\", --config, "
                   "\"{config}\"]\n"
                   "  ext_original: {type: none, estimator.backend: external, estimator.external: *e}\n"
                   // In-estimator mitigation reads the detector's flags: the recording carries them.
                   "  builtin_inflate: {type: threshold, estimator.mitigation.inflate.enabled: true}\n"
                   "  ext_inflate: {type: threshold, estimator.mitigation.inflate.enabled: true,\n"
                   "                estimator.backend: external, estimator.external: *e}\n"
                   "seeds: [1]\nwrite_figure_data: false\n"
                   "table_methods: [builtin_trunc, ext_trunc, builtin_original, ext_original]\n");
  const fs::path out = tmp.path() / "sweep";
  const testing::CliResult r = Vigil(tmp, "sweep " + sweep + " -o " + out.string() + " -j 1 --quiet");
  ASSERT_EQ(r.status, 0) << r.err;
  for (const char* method : {"trunc", "original", "inflate"}) {
    const fs::path builtin = out / "runs" / ("noise_50_10-builtin_" + std::string(method) + "-s001");
    const fs::path external = out / "runs" / ("noise_50_10-ext_" + std::string(method) + "-s001");
    const std::string a = ReadFile(builtin / "stamped_traj_estimate.txt");
    const std::string b = ReadFile(external / "stamped_traj_estimate.txt");
    EXPECT_GT(a.size(), 1000u) << method;
    EXPECT_EQ(a, b) << method;  // byte for byte
    const nlohmann::json ma = nlohmann::json::parse(ReadFile(builtin / "metrics.json"));
    const nlohmann::json mb = nlohmann::json::parse(ReadFile(external / "metrics.json"));
    EXPECT_EQ(ma["status"], "ok") << method;
    EXPECT_EQ(mb["status"], "ok") << method << ": " << mb["failure_reason"];
    EXPECT_EQ(ma["ate"], mb["ate"]) << method;
    EXPECT_EQ(ma["relative"], mb["relative"]) << method;
    EXPECT_FALSE(ma.contains("external"));
    EXPECT_EQ(mb["external"]["outcome"], "exited");
  }
  // One table row per estimator and method.
  const std::string table = ReadFile(out / "table2.md");
  for (const char* row : {"builtin_trunc", "ext_trunc", "builtin_original", "ext_original"})
    EXPECT_NE(table.find(row), std::string::npos) << row;
}

TEST(ExternalIdentity, EstimateRefusesBadInputAndWritesNothing) {
  TempDir tmp;
  const fs::path out = tmp.path() / "out";
  testing::CliResult r = Vigil(tmp, "estimate " + (tmp.path() / "absent").string() + " -o " + out.string());
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find("vigil: error: "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("not a dataset directory"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out));
  fs::create_directories(tmp.path() / "rec");
  r = Vigil(tmp, "estimate " + (tmp.path() / "rec").string() + " -o " + out.string() +
                     " --set estimator.solver.max_iterations=0");
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find("estimator.solver.max_iterations"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out));
}

}  // namespace
}  // namespace vigil
