#include "sim/recorded_poses.h"

#include <cmath>
#include <string>

#include "core/csv.h"
#include "core/dataset.h"
#include "core/error.h"
#include "core/euroc.h"
#include "core/format.h"
#include "core/ground_truth_gap.h"
#include "core/output.h"
#include "core/pose_checks.h"

namespace vigil::sim {
namespace fs = std::filesystem;
namespace {

constexpr std::size_t kEurocColumns = 17;

// The ground-truth file a folder stands for (EuRoC layout), or `path` itself.
fs::path GroundTruthFile(const fs::path& path) {
  std::error_code ec;
  if (!fs::is_directory(path, ec)) return path;
  const fs::path mav0 = FindMav0(path);
  const fs::path in_mav0 = mav0 / euroc_files::kGroundTruth / euroc_files::kData;
  if (!mav0.empty() && fs::is_regular_file(in_mav0, ec)) return in_mav0;
  if (fs::is_regular_file(path / euroc_files::kData, ec)) return path / euroc_files::kData;  // the gt folder
  throw InputError(path.string() + ": no ground truth found (expected mav0/" + euroc_files::kGroundTruth +
                   "/" + euroc_files::kData + ")");
}

// The first line that is neither empty nor a comment.
bool IsCommaSeparated(const std::string& text) {
  std::size_t pos = 0;
  while (pos < text.size()) {
    const std::size_t end = std::min(text.find('\n', pos), text.size());
    const std::string_view line = std::string_view(text).substr(pos, end - pos);
    pos = end + 1;
    const auto first = line.find_first_not_of(" \t\r");
    if (first == std::string_view::npos) continue;
    if (line[first] == '#') {
      if (line.find(',') != std::string_view::npos) return true;  // a EuRoC header
      continue;
    }
    return line.find(',') != std::string_view::npos;
  }
  return false;
}

// Number of comma-separated columns of the first line (the header).
std::size_t HeaderColumns(const std::string& text) {
  const std::string_view header = std::string_view(text).substr(0, text.find('\n'));
  std::size_t n = 1;
  for (char c : header) n += c == ',';
  return n;
}

Eigen::Quaterniond UnitQuaternion(const Eigen::Quaterniond& q, const std::string& file, int line) {
  if (const std::string problem = QuaternionNormProblem(q); !problem.empty())
    throw InputError(Located(file, line, problem));
  return q.normalized();
}

std::vector<TimedPose> ReadEurocGroundTruth(TextFile file, std::vector<int>* lines) {
  const std::size_t columns = HeaderColumns(file.text);
  if (columns < kEurocColumns)
    throw InputError(Located(file.path, 1,
                             "header has " + std::to_string(columns) + " columns, expected " +
                                 std::to_string(kEurocColumns) +
                                 " or more (EuRoC state_groundtruth_estimate0 layout)"));
  CsvReader r(std::move(file), columns, "EuRoC state_groundtruth_estimate0 layout");
  std::vector<TimedPose> out;
  while (r.Next()) {
    TimedPose pose;
    pose.t_ns = r.Int(0);
    pose.p_W = Eigen::Vector3d(r.Double(1), r.Double(2), r.Double(3));
    pose.q_WB = UnitQuaternion(Eigen::Quaterniond(r.Double(4), r.Double(5), r.Double(6), r.Double(7)),
                               r.path(), r.line());
    pose.v_W = Eigen::Vector3d(r.Double(8), r.Double(9), r.Double(10));
    out.push_back(pose);
    lines->push_back(r.line());
  }
  return out;
}

std::vector<TimedPose> ReadTum(const TextFile& file, std::vector<int>* lines) {
  std::vector<TimedPose> out;
  int line = 0;
  std::size_t pos = 0;
  while (pos < file.text.size()) {
    const std::size_t end = std::min(file.text.find('\n', pos), file.text.size());
    const std::string row = file.text.substr(pos, end - pos);
    pos = end + 1;
    ++line;
    const auto first = row.find_first_not_of(" \t\r");
    if (first == std::string::npos || row[first] == '#') continue;
    std::vector<double> v;
    std::size_t i = first;
    while (i < row.size()) {
      const std::size_t stop = std::min(row.find_first_of(" \t\r", i), row.size());
      if (stop > i) {
        double x = 0.0;
        const std::string token = row.substr(i, stop - i);
        if (!ParseDouble(token, &x))
          throw InputError(Located(file.path, line, "expected a finite number, got '" + token + "'"));
        v.push_back(x);
      }
      i = stop + 1;
    }
    if (v.size() != 8)
      throw InputError(
          Located(file.path, line,
                  "expected 8 columns (timestamp tx ty tz qx qy qz qw), found " + std::to_string(v.size())));
    if (std::abs(v[0]) > 9e9)
      throw InputError(Located(file.path, line, "timestamp: " + FormatDouble(v[0]) + " s is beyond +-9e9 s"));
    TimedPose pose;
    pose.t_ns = SToNs(v[0]);
    pose.p_W = Eigen::Vector3d(v[1], v[2], v[3]);
    pose.q_WB = UnitQuaternion(Eigen::Quaterniond(v[7], v[4], v[5], v[6]), file.path, line);
    out.push_back(pose);
    lines->push_back(line);
  }
  return out;
}

// Row checks that need the previous row: order, and no jump.
void CheckSequence(const std::vector<TimedPose>& poses, const std::vector<int>& lines,
                   const std::string& file) {
  for (std::size_t k = 0; k < poses.size(); ++k) {
    const TimedPose& p = poses[k];
    if (p.p_W.cwiseAbs().maxCoeff() > kMaxAbsCoordinate_m)
      throw InputError(
          Located(file, lines[k], "position is beyond +-" + FormatDouble(kMaxAbsCoordinate_m) + " m"));
    if (k == 0) continue;
    const TimedPose& q = poses[k - 1];
    if (p.t_ns <= q.t_ns)
      throw InputError(Located(file, lines[k],
                               "timestamp " + std::to_string(p.t_ns) + " ns does not increase (previous " +
                                   std::to_string(q.t_ns) + " ns)"));
    const double dt_s = NsToS(p.t_ns - q.t_ns);
    if (p.t_ns - q.t_ns > kMaxGroundTruthGap_ns)
      throw InputError(Located(file, lines[k], GroundTruthGapReason(dt_s)));
    const double speed = (p.p_W - q.p_W).norm() / dt_s;
    if (speed > kMaxRecordedSpeed_mps)
      throw InputError(Located(file, lines[k],
                               "position jumps " + FormatDouble((p.p_W - q.p_W).norm()) + " m in " +
                                   FormatDouble(dt_s) + " s since the previous row (faster than " +
                                   FormatDouble(kMaxRecordedSpeed_mps) + " m/s: not a motion)"));
    if (const std::string problem = RotationStepProblem(q.q_WB, p.q_WB); !problem.empty())
      throw InputError(Located(file, lines[k], problem));
  }
}

}  // namespace

std::vector<TimedPose> ReadRecordedPoses(const fs::path& path) {
  const fs::path file_path = GroundTruthFile(path);
  TextFile file = ReadTextFile(file_path.string());
  const std::string name = file.path;
  std::vector<int> lines;
  std::vector<TimedPose> poses =
      IsCommaSeparated(file.text) ? ReadEurocGroundTruth(std::move(file), &lines) : ReadTum(file, &lines);
  if (poses.size() < 2)
    throw InputError(
        Located(name, lines.empty() ? 0 : lines.back(),
                std::to_string(poses.size()) + " pose(s): a recorded trajectory needs at least 2"));
  CheckSequence(poses, lines, name);
  return poses;
}

}  // namespace vigil::sim
