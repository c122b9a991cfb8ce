// Reading and writing vigil's CSV files (EuRoC style: one '#' header line, comma separated, '.' decimal).
//
// CsvReader checks the shape of every row and turns every problem into an InputError "file:line: reason".
// CsvWriter formats doubles in shortest round-trip form (core/format.h), so files are exact and reproducible.
#pragma once

#include <cstdint>
#include <fstream>
#include <string>
#include <string_view>
#include <vector>

namespace vigil {

class CsvReader {
 public:
  // Opens `path` and reads its header; the header must start with '#' and have `num_columns` columns.
  // `what` names the expected layout in errors (e.g. "EuRoC imu0 layout").
  CsvReader(std::string path, std::size_t num_columns, std::string what);

  // Reads the next non-empty row; false at the end of the file. Rows must have `num_columns` fields.
  bool Next();

  double Double(std::size_t column) const;   // a finite number
  int64_t Int(std::size_t column) const;     // an integer
  std::string_view Text(std::size_t column) const { return fields_[column]; }
  const std::string& header_column(std::size_t column) const { return header_[column]; }

  int line() const { return line_; }
  const std::string& path() const { return path_; }
  [[noreturn]] void Fail(const std::string& reason) const;

 private:
  void Split(const std::string& row, std::vector<std::string_view>* out) const;

  std::string path_;
  std::size_t num_columns_;
  std::ifstream in_;
  std::vector<std::string> header_;
  std::string row_;
  std::vector<std::string_view> fields_;
  int line_ = 0;
};

// Accumulates rows in memory; written in one piece by WriteFileAtomic (core/output.h) or Str().
class CsvWriter {
 public:
  explicit CsvWriter(const std::string& header);  // header without the leading '#'
  CsvWriter& operator<<(double v);
  CsvWriter& operator<<(int64_t v);
  CsvWriter& operator<<(int v) { return *this << static_cast<int64_t>(v); }
  CsvWriter& operator<<(std::string_view text);
  void EndRow();
  const std::string& Str() const { return text_; }

 private:
  void Sep();
  std::string text_;
  bool row_started_ = false;
};

}  // namespace vigil
