// glog, which Ceres reports through, set up once at the start of a program that solves with Ceres.
//
// Ceres logs its warnings (a Levenberg-Marquardt step whose linear solve failed and is retried with more
// damping) and, unconditionally, an error line when a solve stops on a failed evaluation ("Terminating:
// Residual and Jacobian evaluation failed"), whatever Solver::Options::logging_type says. vigil checks every
// solve's outcome itself and says what it means (a failed run's reason, a gated factor), so both stay quiet
// on every thread: only fatal messages pass unless GLOG_minloglevel in the environment asks for more.
#pragma once

namespace vigil::app {

// Initializes glog (no "Logging before InitGoogleLogging()" line), logging to stderr only (no files in /tmp)
// unless GLOG_log_dir or GLOG_logtostderr is set, at the level above.
void InitSolverLogging(const char* argv0);

}  // namespace vigil::app
