#include "core/csv.h"

#include "core/error.h"
#include "core/format.h"

namespace vigil {

CsvReader::CsvReader(std::string path, std::size_t num_columns, std::string what)
    : path_(std::move(path)), num_columns_(num_columns), in_(path_) {
  if (!in_) throw InputError(path_ + ": cannot open for reading");
  std::string header;
  if (!std::getline(in_, header)) throw InputError(Located(path_, 1, "empty file (expected a '#' header)"));
  line_ = 1;
  if (!header.empty() && header.back() == '\r') header.pop_back();
  if (header.empty() || header[0] != '#') Fail("expected a header line starting with '#' (" + what + ")");
  const std::string names = header.substr(1);
  std::vector<std::string_view> cols;
  Split(names, &cols);
  if (cols.size() != num_columns_) {
    Fail("header has " + std::to_string(cols.size()) + " columns, expected " + std::to_string(num_columns_) +
         " (" + what + ")");
  }
  for (auto c : cols) header_.emplace_back(c);
}

void CsvReader::Split(const std::string& row, std::vector<std::string_view>* out) const {
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
  while (std::getline(in_, row_)) {
    ++line_;
    if (!row_.empty() && row_.back() == '\r') row_.pop_back();
    if (row_.find_first_not_of(" \t") == std::string::npos) continue;
    Split(row_, &fields_);
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

CsvWriter::CsvWriter(const std::string& header) : text_("#" + header + "\n") {}

void CsvWriter::Sep() {
  if (row_started_) text_ += ',';
  row_started_ = true;
}

CsvWriter& CsvWriter::operator<<(double v) {
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
  row_started_ = false;
}

}  // namespace vigil
