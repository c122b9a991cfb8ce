// A stand-in external estimator for the tests of the external path: `fake_estimator MODE OUTPUT RECORDING`
// reads the recording vigil wrote (its ground truth and camera frame times) and misbehaves as MODE says:
//   good       the ground truth at every camera frame, TUM, seconds
//   partial    the same for the first half of the frames only
//   two        the same for the first two frames only
//   scaled_q   the ground truth with every quaternion 3 times unit length
//   euroc_ns   the ground truth at every frame, EuRoC csv, nanoseconds
//   exit3      exits with status 3
//   signal     kills itself with SIGKILL
//   sleep      starts a grandchild in its process group (pid written to OUTPUT/grandchild.pid), then both
//   sleep garbage    writes text that is no trajectory ns         nanoseconds where seconds are expected
//   unsorted   rows in reverse time order
//   nan        a row with nan
//   empty      an empty file
//   none       writes nothing and exits 0
//   setsid     starts a grandchild that leaves the process group and the session (setsid) and sleeps 60 s;
//              exits 0 once the grandchild is in its own session (its pid in OUTPUT/grandchild.pid)
//   announce   starts a grandchild in its group, writes "PID GRANDCHILD_PID\n" into the FIFO that the
//              environment's VIGIL_TEST_ANNOUNCE names, then waits for a signal (both keep the defaults)
//   link_out   the good trajectory in OUTPUT/../outside.txt, OUTPUT's trajectory a symbolic link to it
//   link_in    the good trajectory in OUTPUT/real.txt, OUTPUT's trajectory a symbolic link to it
// It writes OUTPUT/stamped_traj_estimate.txt (OUTPUT/traj.csv for euroc_ns).
#include <signal.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include "core/csv.h"
#include "core/dataset.h"
#include "core/interpolation.h"

namespace fs = std::filesystem;
using namespace vigil;

namespace {

std::vector<StampedPose> GroundTruthAtFrames(const fs::path& recording) {
  const std::vector<NavState> gt =
      ReadGroundTruthCsv((recording / "mav0/state_groundtruth_estimate0/data.csv").string());
  CsvReader frames((recording / "mav0/cam0/data.csv").string(), 2, "cam0 list");
  std::vector<StampedPose> out;
  while (frames.Next()) {
    NavState s;
    if (InterpolateNavState(gt, frames.Int(0), &s)) out.push_back({s.t_ns, s.p_W, s.q_WB});
  }
  return out;
}

void WriteTum(const fs::path& path, const std::vector<StampedPose>& poses, bool in_ns) {
  std::ofstream f(path);
  f << "# timestamp tx ty tz qx qy qz qw\n";
  char line[512];
  for (const StampedPose& p : poses) {
    if (in_ns)
      std::snprintf(line, sizeof(line), "%lld", static_cast<long long>(p.t_ns));
    else
      std::snprintf(line, sizeof(line), "%.9f", NsToS(p.t_ns));
    f << line;
    std::snprintf(line, sizeof(line), " %.17g %.17g %.17g %.17g %.17g %.17g %.17g\n", p.p_W.x(), p.p_W.y(),
                  p.p_W.z(), p.q_WB.x(), p.q_WB.y(), p.q_WB.z(), p.q_WB.w());
    f << line;
  }
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 4) {
    std::fprintf(stderr, "usage: fake_estimator MODE OUTPUT RECORDING\n");
    return 2;
  }
  const std::string mode = argv[1];
  const fs::path output = argv[2];
  const fs::path recording = argv[3];
  const fs::path trajectory = output / "stamped_traj_estimate.txt";
  std::printf("fake estimator: %s\n", mode.c_str());
  if (mode == "exit3") return 3;
  if (mode == "signal") ::kill(::getpid(), SIGKILL);
  if (mode == "sleep") {
    const pid_t child = ::fork();
    if (child == 0) {
      std::this_thread::sleep_for(std::chrono::seconds(60));
      return 0;
    }
    std::ofstream(output / "grandchild.pid") << child << "\n";
    std::this_thread::sleep_for(std::chrono::seconds(60));
    return 0;
  }
  if (mode == "setsid") {
    int ready[2];
    if (::pipe(ready) != 0) return 1;
    const pid_t child = ::fork();
    if (child == 0) {
      ::setsid();
      const pid_t self = ::getpid();
      [[maybe_unused]] const ssize_t n = ::write(ready[1], &self, sizeof self);
      std::this_thread::sleep_for(std::chrono::seconds(60));
      return 0;
    }
    pid_t escaped = 0;
    if (::read(ready[0], &escaped, sizeof escaped) != sizeof escaped) return 1;
    std::ofstream(output / "grandchild.pid") << escaped << "\n";
    return 0;
  }
  if (mode == "announce") {
    const pid_t child = ::fork();
    if (child == 0) {
      ::pause();
      return 0;
    }
    const char* fifo = std::getenv("VIGIL_TEST_ANNOUNCE");
    if (fifo == nullptr) return 1;
    std::ofstream(fifo) << ::getpid() << " " << child << "\n";
    ::pause();
    return 0;
  }
  if (mode == "none") return 0;
  if (mode == "empty") {
    std::ofstream{trajectory};
    return 0;
  }
  if (mode == "garbage") {
    std::ofstream(trajectory) << "hello estimator\n\x01\x02 not a trajectory at all\n";
    return 0;
  }
  std::vector<StampedPose> poses = GroundTruthAtFrames(recording);
  if (mode == "good")
    WriteTum(trajectory, poses, false);
  else if (mode == "ns")
    WriteTum(trajectory, poses, true);
  else if (mode == "link_out" || mode == "link_in") {
    const fs::path real = mode == "link_out" ? output.parent_path() / "outside.txt" : output / "real.txt";
    WriteTum(real, poses, false);
    fs::create_symlink(fs::absolute(real), trajectory);
  } else if (mode == "partial") {
    poses.resize(poses.size() / 2);
    WriteTum(trajectory, poses, false);
  } else if (mode == "two") {
    poses.resize(2);
    WriteTum(trajectory, poses, false);
  } else if (mode == "scaled_q") {
    for (StampedPose& p : poses) p.q_WB.coeffs() *= 3.0;
    WriteTum(trajectory, poses, false);
  } else if (mode == "unsorted") {
    std::vector<StampedPose> reversed(poses.rbegin(), poses.rend());
    WriteTum(trajectory, reversed, false);
  } else if (mode == "nan") {
    WriteTum(trajectory, poses, false);
    std::ofstream(trajectory, std::ios::app) << "99.0 nan 0 0 0 0 0 1\n";
  } else if (mode == "euroc_ns") {
    std::ofstream f(output / "traj.csv");
    f << "#timestamp,p_x,p_y,p_z,q_w,q_x,q_y,q_z\n";
    for (const StampedPose& p : poses) {
      char line[512];
      std::snprintf(line, sizeof(line), "%lld,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g\n",
                    static_cast<long long>(p.t_ns), p.p_W.x(), p.p_W.y(), p.p_W.z(), p.q_WB.w(), p.q_WB.x(),
                    p.q_WB.y(), p.q_WB.z());
      f << line;
    }
  } else {
    std::fprintf(stderr, "fake_estimator: unknown mode %s\n", mode.c_str());
    return 2;
  }
  return 0;
}
