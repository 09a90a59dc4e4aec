// SPDX-License-Identifier: GPL-3.0-or-later
/// @file table.hpp
/// @brief Tables: tab-separated data tables for build/data, and LaTeX tabulars for build/tables.
#pragma once

#include <string>
#include <variant>
#include <vector>

namespace dfchaos::kit {

/// A table cell: number (%.17g in TSV), integer, or text.
using Cell = std::variant<double, long long, std::string>;

/// A tab-separated table: one header line of column names, then rows; doubles in %.17g.
class Table {
 public:
  explicit Table(std::vector<std::string> columns);  ///< a table with these column names
  /// Appends a row. @throws std::logic_error if the number of cells differs from the columns.
  Table& row(std::vector<Cell> cells);
  std::size_t rows() const { return rows_.size(); }  ///< number of rows so far
  std::string render() const;                        ///< header line and rows, tab-separated
  /// The table with `comments` ('#' lines, each ending in a newline) between the column line and
  /// the rows: the layout of every data file (docs/architecture.md, "Data files"), which
  /// `pandas.read_csv(f, sep="\t", comment="#")` and `numpy.genfromtxt(f, names=True,
  /// delimiter="\t", comments="#", dtype=None, encoding=None)` both read in one call (the latter
  /// takes its names from the first line).
  std::string render(const std::string& comments) const;

 private:
  std::vector<std::string> columns_;
  std::vector<std::vector<Cell>> rows_;
};

/// A booktabs LaTeX tabular whose cells are LaTeX already (format numbers with format_significant
/// or latex_number first): `\begin{tabular}{spec} \toprule header \midrule rows \bottomrule \end{tabular}`.
class LatexTable {
 public:
  /// @param spec     the column specification, e.g. "rrrr"
  /// @param header   the header cells (LaTeX)
  LatexTable(std::string spec, std::vector<std::string> header);
  /// Appends a row of LaTeX cells; a cell that is a number in exponent notation ("8.7e-05") is typeset
  /// as one (latex_number). @throws std::logic_error if the number of cells differs from the header.
  LatexTable& row(const std::vector<std::string>& cells);
  /// Appends a \midrule before the next row.
  LatexTable& rule();
  std::size_t rows() const { return rows_; }  ///< number of rows so far
  /// The tabular, ending in a newline.
  std::string render() const;

 private:
  std::string spec_;
  std::size_t columns_;
  std::string head_, body_;
  std::size_t rows_ = 0;
};

}  // namespace dfchaos::kit
