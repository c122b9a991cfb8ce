// A small numeric table (row labels x column labels) and its Markdown, CSV and LaTeX (booktabs) forms.
#pragma once

#include <string>
#include <vector>

namespace vigil::report {

struct ResultTable {
  std::string title;   // caption (LaTeX) / heading (Markdown)
  std::string corner;  // header of the row-label column (CSV: after '#')
  std::vector<std::string> columns, rows;
  std::vector<std::vector<double>> values;  // rows x columns; NaN prints as "n/a"
  int decimals = 2;
};

// A value with `decimals` fixed decimals, or "n/a" when it is not finite (every table cell is written this
// way).
std::string FormatCell(double value, int decimals = 3);

std::string TableMarkdown(const ResultTable& table);  // a pipe table preceded by "**title**"
std::string TableCsv(const ResultTable& table);       // "#corner,col,..." then one line per row
std::string TableLatex(const ResultTable& table);     // table environment with booktabs rules

// Markdown of two tables of the same shape cell by cell: "ours (reference)"; a missing reference cell
// (label not in `reference`) shows ours only.
std::string SideBySideMarkdown(const ResultTable& ours, const ResultTable& reference);

// The value at (row, column) by their labels; NaN when either label is absent.
double TableValue(const ResultTable& table, const std::string& row, const std::string& column);

}  // namespace vigil::report
