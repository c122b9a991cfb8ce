#include "experiments/external/external_trajectory.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string_view>
#include <system_error>
#include <vector>

#include "core/dataset.h"
#include "core/error.h"
#include "core/format.h"
#include "core/output.h"
#include "core/pose_checks.h"

namespace vigil::experiments {
namespace fs = std::filesystem;
namespace {

// Largest |time| accepted in seconds (far beyond any recording, short of int64 nanoseconds' range).
constexpr double kMaxAbsTime_s = 9e9;
// Closest two poses may be: no estimator runs at a megahertz, so rows closer than this were read in the
// wrong unit.
constexpr int64_t kMinExternalPoseStep_ns = 1000;

std::vector<std::string_view> SplitFields(std::string_view line, TrajectoryFormat format) {
  std::vector<std::string_view> fields;
  if (format == TrajectoryFormat::kEuroc) {
    for (std::size_t begin = 0;;) {
      const std::size_t end = line.find(',', begin);
      fields.push_back(
          line.substr(begin, end == std::string_view::npos ? std::string_view::npos : end - begin));
      if (end == std::string_view::npos) break;
      begin = end + 1;
    }
    return fields;
  }
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
    std::size_t j = i;
    while (j < line.size() && line[j] != ' ' && line[j] != '\t') ++j;
    if (j > i) fields.push_back(line.substr(i, j - i));
    i = j;
  }
  return fields;
}

// Seconds as decimal text, to the nanosecond without going through a double ("12.3456789015" rounds the
// tenth digit); text with an exponent is read as a double. False when it is not a finite time.
bool ParseSeconds(std::string_view text, int64_t* t_ns) {
  double value = 0.0;
  if (!ParseDouble(text, &value) || std::abs(value) > kMaxAbsTime_s) return false;
  const bool plain = text.find_first_of("eE") == std::string_view::npos;
  if (!plain) {
    *t_ns = SToNs(value);
    return true;
  }
  while (!text.empty() && (text.front() == ' ' || text.front() == '+')) text.remove_prefix(1);
  const bool negative = !text.empty() && text.front() == '-';
  if (negative) text.remove_prefix(1);
  const std::size_t dot = text.find('.');
  int64_t whole = 0;
  const std::string_view int_part = text.substr(0, dot);
  if (!int_part.empty() && !ParseInt64(int_part, &whole)) return false;
  int64_t frac_ns = 0;
  if (dot != std::string_view::npos) {
    std::string_view frac = text.substr(dot + 1);
    while (!frac.empty() && (frac.back() == ' ' || frac.back() == '\r')) frac.remove_suffix(1);
    int64_t scale = 100000000;
    for (std::size_t k = 0; k < frac.size(); ++k) {
      if (frac[k] < '0' || frac[k] > '9') return false;
      if (k < 9) {
        frac_ns += (frac[k] - '0') * scale;
        scale /= 10;
      } else if (k == 9 && frac[k] >= '5') {
        ++frac_ns;  // round half up at the tenth digit
      }
    }
  }
  const int64_t t = whole * 1000000000 + frac_ns;
  *t_ns = negative ? -t : t;
  return true;
}

bool ParseNanoseconds(std::string_view text, int64_t* t_ns) {
  if (ParseInt64(text, t_ns)) return true;
  double value = 0.0;  // 1.4e18 and the like
  if (!ParseDouble(text, &value) || std::abs(value) > 9e18) return false;
  *t_ns = static_cast<int64_t>(std::llround(value));
  return true;
}

}  // namespace

std::string TrajectoryOutsideOutput(const fs::path& path, const fs::path& output_dir) {
  std::error_code ec;
  if (!fs::exists(fs::symlink_status(path, ec))) return {};
  const std::string name = path.filename().string();
  const fs::path root = fs::canonical(output_dir, ec);
  if (ec) return name + ": the {output} folder cannot be resolved: " + ec.message();
  const fs::path real = fs::canonical(path, ec);
  if (ec) return name + ": cannot be resolved (" + ec.message() + "); not read";
  const fs::path inside = real.lexically_relative(root);
  if (!inside.empty() && *inside.begin() != "..") return {};
  return name + ": resolves to " + real.string() +
         ", outside the estimator's {output} folder: not read (the trajectory must be a file the estimator "
         "wrote there, not a link out of it)";
}

ExternalTrajectory ReadExternalTrajectory(const fs::path& path, TrajectoryFormat format, TimeUnit unit,
                                          int64_t t_first_ns, int64_t t_last_ns) {
  ExternalTrajectory out;
  const std::string name = path.filename().string();
  const auto fail = [&](int line, const std::string& why) {
    out.trajectory.clear();
    // One printable line, whatever bytes of the file `why` quotes (the run's reason, metrics.json, logs).
    out.failure = OneLine(line > 0 ? name + ":" + std::to_string(line) + ": " + why : name + ": " + why);
    return out;
  };
  std::error_code ec;
  if (!fs::exists(path, ec)) return fail(0, "the estimator wrote no trajectory");
  if (!fs::is_regular_file(path, ec)) return fail(0, "not a regular file");
  const std::uintmax_t bytes = fs::file_size(path, ec);
  if (ec) return fail(0, "cannot read its size: " + ec.message());
  if (bytes > kMaxExternalTrajectoryBytes)
    return fail(0, std::to_string(bytes) + " bytes, beyond the limit of " +
                       std::to_string(kMaxExternalTrajectoryBytes) + " bytes");
  std::string text;
  try {
    text = ReadFile(path, kMaxExternalTrajectoryBytes);
  } catch (const std::exception& e) {
    return fail(0, e.what());
  }
  const std::size_t min_columns = 8;
  const std::string layout =
      format == TrajectoryFormat::kTum ? "TUM 't x y z qx qy qz qw'" : "EuRoC 't,x,y,z,qw,qx,qy,qz'";
  int line_number = 0;
  double previous_written = -std::numeric_limits<double>::infinity();
  for (std::size_t begin = 0; begin < text.size();) {
    std::size_t end = text.find('\n', begin);
    if (end == std::string::npos) end = text.size();
    std::string_view line(text.data() + begin, end - begin);
    begin = end + 1;
    ++line_number;
    while (!line.empty() && (line.back() == '\r' || line.back() == ' ' || line.back() == '\t'))
      line.remove_suffix(1);
    std::size_t lead = 0;
    while (lead < line.size() && (line[lead] == ' ' || line[lead] == '\t')) ++lead;
    line.remove_prefix(lead);
    if (line.empty() || line.front() == '#') continue;
    const std::vector<std::string_view> f = SplitFields(line, format);
    if (f.size() < min_columns)
      return fail(line_number, std::to_string(f.size()) + " columns, expected the " + layout + " layout");
    StampedPose pose;
    const bool time_ok =
        unit == TimeUnit::kSeconds ? ParseSeconds(f[0], &pose.t_ns) : ParseNanoseconds(f[0], &pose.t_ns);
    if (!time_ok) return fail(line_number, "timestamp '" + std::string(f[0]) + "' is not a finite number");
    double v[7];
    for (int k = 0; k < 7; ++k)
      if (!ParseDouble(f[static_cast<std::size_t>(k) + 1], &v[k]))
        return fail(line_number, "column " + std::to_string(k + 2) + ": '" +
                                     std::string(f[static_cast<std::size_t>(k) + 1]) +
                                     "' is not a finite number");
    for (int k = 0; k < 3; ++k)
      if (std::abs(v[k]) > kMaxAbsCoordinate_m)
        return fail(line_number, "position " + FormatDouble(v[k]) + " m is beyond the limit of +-" +
                                     FormatDouble(kMaxAbsCoordinate_m) + " m");
    pose.p_W = Eigen::Vector3d(v[0], v[1], v[2]);
    pose.q_WB = format == TrajectoryFormat::kTum ? Eigen::Quaterniond(v[6], v[3], v[4], v[5])
                                                 : Eigen::Quaterniond(v[3], v[4], v[5], v[6]);
    if (const std::string problem = QuaternionNormProblem(pose.q_WB); !problem.empty())
      return fail(line_number, problem);
    if (std::abs(pose.q_WB.squaredNorm() - 1.0) > 8 * std::numeric_limits<double>::epsilon())
      pose.q_WB.normalize();
    // Times that increase as written but not once read in the unit (seconds read as nanoseconds collapse
    // onto a few ns) are a unit mix-up, whatever the recording's start.
    double written = 0.0;
    ParseDouble(f[0], &written);
    const std::string unit_hint = std::string(": a unit mix-up? (estimator.external.time_unit ") +
                                  (unit == TimeUnit::kSeconds ? "s" : "ns") + " reads them as " +
                                  (unit == TimeUnit::kSeconds ? "seconds" : "nanoseconds") + ")";
    if (!out.trajectory.empty() && pose.t_ns < out.trajectory.back().t_ns + kMinExternalPoseStep_ns) {
      if (written > previous_written && pose.t_ns >= out.trajectory.back().t_ns)
        return fail(line_number, "timestamp " + std::string(f[0]) + " lies " +
                                     std::to_string(pose.t_ns - out.trajectory.back().t_ns) +
                                     " ns after the previous row's, less than 1 us" + unit_hint);
      return fail(line_number, "timestamps are not strictly increasing (" + std::string(f[0]) + " after " +
                                   std::to_string(out.trajectory.back().t_ns) + " ns)");
    }
    previous_written = written;
    if (pose.t_ns < t_first_ns - kExternalTimeSlack_ns || pose.t_ns > t_last_ns + kExternalTimeSlack_ns)
      return fail(line_number, "timestamp " + std::string(f[0]) +
                                   (unit == TimeUnit::kSeconds ? " s" : " ns") +
                                   " lies outside the recording (" + FormatFixed(NsToS(t_first_ns), 3) +
                                   " .. " + FormatFixed(NsToS(t_last_ns), 3) +
                                   " s): a unit mix-up? (estimator.external.time_unit)");
    out.trajectory.push_back(pose);
  }
  if (out.trajectory.empty()) return fail(0, "the trajectory is empty (no rows)");
  return out;
}

}  // namespace vigil::experiments
