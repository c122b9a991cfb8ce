#include "experiments/runs/imu_axis_record.h"

#include <fstream>
#include <stdexcept>

#include "core/csv.h"

namespace vigil::experiments {
namespace {

// The number of comma-separated columns of the first line of `path` (0 when it cannot be read).
std::size_t HeaderColumns(const std::string& path) {
  std::ifstream in(path);
  std::string line;
  if (!std::getline(in, line)) return 0;
  std::size_t columns = 1;
  for (char c : line) columns += c == ',';
  return columns;
}

// "raw az" -> az; false when the header column is not "<what> <axis>".
bool AxisOfColumn(const std::string& column, const std::string& what, ImuAxis* axis) {
  const std::string prefix = what + " ";
  return column.rfind(prefix, 0) == 0 && ParseImuAxis(column.substr(prefix.size()), axis);
}

}  // namespace

ImuAxisRecord MakeImuAxisRecord(ImuAxis axis, const ImuStream& raw, const ImuStream* clean,
                                const ImuStream& mitigated, const std::vector<uint8_t>& flagged) {
  if (mitigated.size() != raw.size() || flagged.size() != raw.size() ||
      (clean != nullptr && clean->size() != raw.size()))
    throw std::invalid_argument("MakeImuAxisRecord: one clean, mitigated and flag value per raw sample");
  ImuAxisRecord record;
  record.axis = axis;
  const int a = static_cast<int>(axis);
  for (std::size_t i = 0; i < raw.size(); ++i) {
    record.t_ns.push_back(raw[i].t_ns);
    record.raw.push_back(raw[i].axis(a));
    if (clean != nullptr) record.clean.push_back((*clean)[i].axis(a));
    record.mitigated.push_back(mitigated[i].axis(a));
    record.flagged.push_back(flagged[i] != 0);
  }
  return record;
}

std::string ImuAxisCsv(const ImuAxisRecord& record) {
  const std::string name = ImuAxisName(record.axis);
  const bool with_clean = !record.clean.empty();
  CsvWriter w(
      "timestamp [ns],raw " + name + (with_clean ? ",clean " + name : "") + ",mitigated " + name + ",flagged",
      "imu_axis.csv");
  for (std::size_t i = 0; i < record.t_ns.size(); ++i) {
    w << record.t_ns[i] << record.raw[i];
    if (with_clean) w << record.clean[i];
    w << record.mitigated[i] << static_cast<int>(record.flagged[i]);
    w.EndRow();
  }
  return w.Str();
}

ImuAxisRecord ReadImuAxisCsv(const std::string& path) {
  const std::size_t columns = HeaderColumns(path) == 4 ? 4 : 5;
  const bool with_clean = columns == 5;
  CsvReader reader(path, columns,
                   with_clean ? "imu_axis layout (#timestamp [ns],raw AX,clean AX,mitigated AX,flagged)"
                              : "imu_axis layout (#timestamp [ns],raw AX,mitigated AX,flagged)");
  ImuAxisRecord record;
  ImuAxis clean_axis = ImuAxis::kAz, mitigated_axis = ImuAxis::kAz;
  if (!AxisOfColumn(reader.header_column(1), "raw", &record.axis) ||
      (with_clean &&
       (!AxisOfColumn(reader.header_column(2), "clean", &clean_axis) || clean_axis != record.axis)) ||
      !AxisOfColumn(reader.header_column(columns - 2), "mitigated", &mitigated_axis) ||
      mitigated_axis != record.axis || reader.header_column(columns - 1) != "flagged")
    reader.Fail("header: expected timestamp [ns],raw AX,[clean AX,]mitigated AX,flagged of one IMU axis AX");
  while (reader.Next()) {
    const int64_t t = reader.Int(0), f = reader.Int(columns - 1);
    if (f != 0 && f != 1) reader.Fail("flagged: must be 0 or 1");
    if (!record.t_ns.empty() && t <= record.t_ns.back()) reader.Fail("timestamp: must increase strictly");
    record.t_ns.push_back(t);
    record.raw.push_back(reader.Double(1));
    if (with_clean) record.clean.push_back(reader.Double(2));
    record.mitigated.push_back(reader.Double(columns - 2));
    record.flagged.push_back(static_cast<uint8_t>(f));
  }
  return record;
}

}  // namespace vigil::experiments
