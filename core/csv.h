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

#include "core/output.h"

namespace vigil {

class CsvReader {
 public:
  // Reads `path` (a regular file, core/output.h ReadFile) and its header; the header must start with '#' and
  // have `num_columns` columns. `what` names the expected layout in errors (e.g. "EuRoC imu0 layout").
  CsvReader(const std::string& path, std::size_t num_columns, const std::string& what);
  // The same on a file already in memory.
  CsvReader(TextFile file, std::size_t num_columns, const std::string& what);

  // Reads the next non-empty row; false at the end of the file. Rows must have `num_columns` fields.
  bool Next();

  double Double(std::size_t column) const;  // a finite number
  int64_t Int(std::size_t column) const;    // an integer
  std::string_view Text(std::size_t column) const { return fields_[column]; }
  const std::string& header_column(std::size_t column) const { return header_[column]; }

  int line() const { return line_; }
  const std::string& path() const { return path_; }
  [[noreturn]] void Fail(const std::string& reason) const;

 private:
  void Split(std::string_view row, std::vector<std::string_view>* out) const;
  bool NextLine(std::string_view* line);  // without its "\n" / "\r\n"; false at the end

  std::string path_;
  std::string text_;
  std::size_t pos_ = 0;
  std::size_t num_columns_;
  std::vector<std::string> header_;
  std::vector<std::string_view> fields_;
  int line_ = 0;
};

// Accumulates rows in memory; written in one piece by WriteFileAtomic (core/output.h) or Str().
class CsvWriter {
 public:
  // `header` without the leading '#'; `file` names the file being written in errors.
  CsvWriter(const std::string& header, std::string file);
  // inf / nan are never written: InputError "file:line: column: cannot write the non-finite value ...".
  CsvWriter& operator<<(double v);
  CsvWriter& operator<<(int64_t v);
  CsvWriter& operator<<(int v) { return *this << static_cast<int64_t>(v); }
  CsvWriter& operator<<(std::string_view text);
  void EndRow();
  const std::string& Str() const { return text_; }

 private:
  void Sep();
  std::vector<std::string> columns_;
  std::string file_;
  std::string text_;
  std::size_t rows_ = 0;
  std::size_t column_ = 0;  // fields written in the current row
};

}  // namespace vigil
