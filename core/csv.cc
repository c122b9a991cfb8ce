#include "core/csv.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "core/format.h"
#include "core/output.h"

namespace vigil {

CsvReader::CsvReader(const std::string& path, std::size_t num_columns, const std::string& what)
    : CsvReader(ReadTextFile(path), num_columns, what) {}  // only a regular file: a FIFO would block

CsvReader::CsvReader(TextFile file, std::size_t num_columns, const std::string& what)
    : path_(std::move(file.path)), text_(std::move(file.text)), num_columns_(num_columns) {
  std::string_view header;
  if (!NextLine(&header)) throw InputError(Located(path_, 1, "empty file (expected a '#' header)"));
  line_ = 1;
  if (header.empty() || header[0] != '#') Fail("expected a header line starting with '#' (" + what + ")");
  std::vector<std::string_view> cols;
  Split(header.substr(1), &cols);
  if (cols.size() != num_columns_) {
    Fail("header has " + std::to_string(cols.size()) + " columns, expected " + std::to_string(num_columns_) +
         " (" + what + ")");
  }
  for (auto c : cols) header_.emplace_back(c);
}

bool CsvReader::NextLine(std::string_view* line) {
  if (pos_ >= text_.size()) return false;
  const std::size_t end = std::min(text_.find('\n', pos_), text_.size());
  *line = std::string_view(text_).substr(pos_, end - pos_);
  pos_ = end + 1;
  if (!line->empty() && line->back() == '\r') line->remove_suffix(1);
  return true;
}

void CsvReader::Split(std::string_view row, std::vector<std::string_view>* out) const {
  out->clear();
  std::string_view rest(row);
  while (true) {
    const auto comma = rest.find(',');
    std::string_view f = rest.substr(0, comma);
    while (!f.empty() && (f.front() == ' ' || f.front() == '\t')) f.remove_prefix(1);
    while (!f.empty() && (f.back() == ' ' || f.back() == '\t' || f.back() == '\r')) f.remove_suffix(1);
    out->push_back(f);
    if (comma == std::string_view::npos) break;
    rest.remove_prefix(comma + 1);
  }
}

bool CsvReader::Next() {
  std::string_view row;
  while (NextLine(&row)) {
    ++line_;
    if (row.find_first_not_of(" \t") == std::string_view::npos) continue;
    Split(row, &fields_);
    if (fields_.size() != num_columns_) {
      Fail("expected " + std::to_string(num_columns_) + " columns, found " + std::to_string(fields_.size()));
    }
    return true;
  }
  return false;
}

double CsvReader::Double(std::size_t column) const {
  double v = 0.0;
  if (!ParseDouble(fields_[column], &v)) {
    Fail(header_[column] + ": expected a finite number, got '" + std::string(fields_[column]) + "'");
  }
  return v;
}

int64_t CsvReader::Int(std::size_t column) const {
  int64_t v = 0;
  if (!ParseInt64(fields_[column], &v)) {
    Fail(header_[column] + ": expected an integer, got '" + std::string(fields_[column]) + "'");
  }
  return v;
}

void CsvReader::Fail(const std::string& reason) const { throw InputError(Located(path_, line_, reason)); }

CsvWriter::CsvWriter(const std::string& header, std::string file)
    : file_(std::move(file)), text_("#" + header + "\n") {
  std::size_t start = 0;
  for (std::size_t comma; (comma = header.find(',', start)) != std::string::npos; start = comma + 1)
    columns_.push_back(header.substr(start, comma - start));
  columns_.push_back(header.substr(start));
}

void CsvWriter::Sep() {
  if (column_ > 0) text_ += ',';
  ++column_;
}

CsvWriter& CsvWriter::operator<<(double v) {
  if (!std::isfinite(v)) {
    const std::string column =
        column_ < columns_.size() ? columns_[column_] : "column " + std::to_string(column_ + 1);
    throw InputError(
        Located(file_, static_cast<int>(rows_) + 2,
                column + ": cannot write the non-finite value " + FormatDouble(v) +
                    " (vigil never writes inf or nan): an input value or setting is out of range"));
  }
  Sep();
  text_ += FormatDouble(v);
  return *this;
}

CsvWriter& CsvWriter::operator<<(int64_t v) {
  Sep();
  text_ += std::to_string(v);
  return *this;
}

CsvWriter& CsvWriter::operator<<(std::string_view text) {
  Sep();
  text_ += text;
  return *this;
}

void CsvWriter::EndRow() {
  text_ += '\n';
  ++rows_;
  column_ = 0;
}

}  // namespace vigil
