#include "app/solver_logging.h"

#include <cstdlib>

#include <glog/logging.h>

namespace vigil::app {

void InitSolverLogging(const char* argv0) {
  if (std::getenv("GLOG_log_dir") == nullptr && std::getenv("GLOG_logtostderr") == nullptr)
    FLAGS_logtostderr = true;
  google::InitGoogleLogging(argv0);
  // The level is a process-wide flag: it holds for the solves of every worker thread too.
  if (std::getenv("GLOG_minloglevel") == nullptr) FLAGS_minloglevel = google::GLOG_FATAL;
}

}  // namespace vigil::app
