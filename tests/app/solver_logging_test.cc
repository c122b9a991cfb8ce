// Ceres's own error lines ("E... trust_region_minimizer.cc] Terminating: ...") never reach stderr of a
// program set up as vigil is, from the main thread or a worker; GLOG_minloglevel in the environment still
// shows them.
#include <string>

#include <gtest/gtest.h>

#include "tests/app/vigil_cli.h"

namespace vigil::testing {
namespace {

TEST(SolverLogging, CeresErrorsStayQuietOnEveryThread) {
  const ShellOutput quiet = RunShell("env -u GLOG_minloglevel " HELPER_BINARY " 2>&1");
  EXPECT_EQ(quiet.status, 0);  // both solves failed, as the helper meant them to
  EXPECT_EQ(quiet.out, "");
  const ShellOutput shown = RunShell("GLOG_minloglevel=0 " HELPER_BINARY " 2>&1");
  EXPECT_EQ(shown.status, 0);
  EXPECT_NE(shown.out.find("Terminating"), std::string::npos) << shown.out;
}

}  // namespace
}  // namespace vigil::testing
